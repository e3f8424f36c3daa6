/* The render modes against the double-precision lighting reference, Blinn-Phong or GGX as the
 * frame's plan chose, on any opaque scene (modes_reference.c; test_modes.c). A mode's frame is compared with the reference
 * evaluated on its own G-buffer where it has one (fat: its full-float targets; thin-lpp: RT0's
 * decoded normal and gloss and the position rebuilt from depth), with fat's where it has none
 * (forward and visibility: fat's normal tilted by its FP16 error, since they shade the unrounded
 * normal; visibility's id is checked against the scene's triangles, rebuilt in double);
 * albedo and F0 from fat's targets; ambient and emission from fat's frame without lights. */
#ifndef TL_MODES_REFERENCE_H
#define TL_MODES_REFERENCE_H

#include <stddef.h>
#include <stdint.h>

#include "thinlight/renderer.h"
#include "thinlight/scene.h"

typedef struct modes_frame {
    uint32_t w, h;
    tl_render_mode mode;
    tl_depth_format depth_format;
    tl_frame_plan plan;
    float view[16], proj[16]; /* the frame's, captured by an application pass */
    float *hdr, *ldr, *depth; /* HDR, LDR (tone-mapped, before FXAA), DEPTH: 4 floats a pixel */
    uint8_t *out;             /* the output, RGBA8 */
    float *position, *normal, *albedo, *material; /* fat's targets; thin: normal holds RT0 decoded */
    float *vis_id; /* visibility: VIS_ID read back (object slot, triangle, drawn, 1) */
} modes_frame;

/* Renders `s` once with `d` (every target kept); 0 on failure (the renderer's message on stderr). */
int modes_render(const tl_scene *s, tl_renderer_desc d, modes_frame *f);
void modes_frame_free(modes_frame *f);

typedef struct modes_ref_result {
    size_t compared;   /* values (pixel, channel) on the same surface in fat and the mode */
    size_t silhouette; /* pixels whose surfaces differ (depth formats at silhouettes): not compared */
    size_t beyond;     /* values outside the reference's range by more than the tolerance */
    double worst;      /* largest miss in units of the tolerance */
    int worst_x, worst_y;
    double worst_got, worst_lo, worst_hi;
    double psnr_bound_db; /* LDR PSNR against fat over the compared values that the ranges allow */
    double psnr_hdr_bound_db; /* the same from the two frames' stored HDR values, 8-bit rounding only */
    double psnr_db;       /* LDR (before FXAA) PSNR against fat over the compared values */
    double tonemap_worst; /* largest |LDR x 255 - the double tone curve of its HDR value| */
    /* visibility: pixels whose centre lies outside the triangle VIS_ID names (in double), the
     * centre's largest distance outside it in pixels; and, for their values, how many (and how far)
     * the triangle's own clamped point would put beyond the tolerance (the resolve extrapolates as
     * the rasteriser does: they are compared at fat's point) */
    size_t vis_outside, vis_outside_values, vis_outside_clamped_beyond;
    size_t vis_bad_ids; /* compared pixels whose id names no triangle of the scene */
    double vis_outside_worst_px, vis_outside_clamped_worst;
} modes_ref_result;

/* Compares frame `m` of scene `s` with the reference made from `fat` (a fat frame of the same
 * scene) and `base` (a fat frame of it without lights). */
void modes_compare_reference(const tl_scene *s, const modes_frame *fat, const modes_frame *base, const modes_frame *m,
                             modes_ref_result *res);

#endif
