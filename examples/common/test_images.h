/* Generated test images for chroma reconstruction: shared by the precision tests and the codec
 * report so both measure the same inputs. Deterministic; sRGB-encoded RGB floats in [0,1]. */
#ifndef TL_TEST_IMAGES_H
#define TL_TEST_IMAGES_H

#include <stddef.h>
#include <stdint.h>

typedef enum tl_test_image {
    TL_TEST_IMAGE_GRADIENT,     /* smooth colour gradients, no edges */
    TL_TEST_IMAGE_HARD_EDGES,   /* overlapping flat saturated shapes */
    TL_TEST_IMAGE_SINGLE_PIXEL, /* isolated coloured pixels and 1-pixel lines on a dark field */
    TL_TEST_IMAGE_NOISY,        /* multi-octave value-noise texture with fine colour grain */
    TL_TEST_IMAGE_SCENE,        /* photo-like: shaded spheres and a textured floor, with edges */
    TL_TEST_IMAGE_COUNT
} tl_test_image;

/* Stable name ("gradient", "hard-edges", ...). */
const char *tl_test_image_name(tl_test_image image);
/* 1 when the image has hard edges (every image but the gradient). */
int tl_test_image_has_edges(tl_test_image image);
/* Fills w*h*3 floats. */
void tl_test_image_generate(tl_test_image image, uint32_t w, uint32_t h, float *rgb);

#endif
