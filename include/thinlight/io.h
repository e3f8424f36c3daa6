/* thinlight io: image files through OpenImageIO (C++ kept inside src/io behind this C API).
 * Writers go through a temporary file in the same directory and rename it into place, so a
 * failure never leaves a partial file behind. */
#ifndef THINLIGHT_IO_H
#define THINLIGHT_IO_H

#include "thinlight/base.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum tl_pixel_type {
    TL_PIXEL_DEFAULT = 0, /**< = TL_PIXEL_U8 */
    TL_PIXEL_U8,
    TL_PIXEL_F32,
    TL_PIXEL_TYPE_COUNT_
} tl_pixel_type;

typedef struct tl_image_desc {
    uint32_t width;
    uint32_t height;
    uint32_t channels;      /**< 1..4 */
    tl_pixel_type type;
    int bottom_up;          /**< 1 when the first row in memory is the bottom one (GL readback) */
} tl_image_desc;

/**
 * Writes an image; the file type follows the extension (.png, .exr, .tif, .jpg, ... as OIIO
 * supports). Float data written to an 8-bit format is clamped to [0,1] and rounded. On failure a
 * message naming the file and the reason is written to `error` (may be NULL).
 */
TL_API tl_result tl_image_write(const char *path, const tl_image_desc *desc, const void *pixels, char *error,
                                size_t error_size);

/**
 * Reads an image as RGBA8 (sRGB-encoded as stored). *rgba is allocated with malloc and freed with
 * tl_image_free. Images larger than max_pixels (0: 2^26) give TL_ERROR_LIMIT.
 */
TL_API tl_result tl_image_read_rgba8(const char *path, size_t max_pixels, uint32_t *width, uint32_t *height,
                                     uint8_t **rgba, char *error, size_t error_size);
TL_API void tl_image_free(void *pixels);

#ifdef __cplusplus
}
#endif
#endif
