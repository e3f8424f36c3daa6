/* The material models' error and cost on the showcase scene (scene.h tl_scene_create_showcase):
 * each pixel's row (model) from an unlit rendering that codes it, and a frame's HDR against a
 * reference frame's over one row's pixels. Shared by thinlight-models-report and the material
 * model tests; not part of the library. */
#ifndef TL_MODELS_MEASURE_H
#define TL_MODELS_MEASURE_H

#include <stddef.h>
#include <stdint.h>

#include "thinlight/renderer.h"
#include "thinlight/scene.h"

#define TL_MM_NO_ROW 255u

/* One row's error: PSNR of HDR colour clamped to [0, 1] (the display range at exposure 1, peak 1),
 * the largest absolute HDR difference and that difference over the reference value there. */
typedef struct tl_mm_error {
    size_t pixels;
    double psnr_db, max_abs, max_rel;
    size_t nan_pixels;
} tl_mm_error;

/* A copy of the showcase with every material made standard (the one-model frame), sharing all but
 * its materials with `s`; NULL on failure. tl_mm_free frees such a copy. */
tl_scene *tl_mm_standard_only(const tl_scene *s);
void tl_mm_free(tl_scene *copy);
/* rows[w * h]: the showcase row (tl_material_model) each pixel shows, TL_MM_NO_ROW for the floor and
 * the sky. `d` carries the size and the GL loader. 0, or 1 after a line on stderr. */
int tl_mm_rows(const tl_scene *s, tl_renderer_desc d, uint8_t *rows);
/* Renders `frames` frames of `s` with `d` and reads HDR into hdr[w * h * 4] (NULL: not read); stats
 * of the last, with the material pass's time the least of the frames after the first. */
int tl_mm_render(const tl_scene *s, tl_renderer_desc d, uint32_t frames, float *hdr, tl_frame_stats *stats);
/* `a` against `ref` over the pixels of each row (out[TL_MATERIAL_MODEL_COUNT_]). */
void tl_mm_compare(const float *a, const float *ref, const uint8_t *rows, size_t n, tl_mm_error *out);

#endif
