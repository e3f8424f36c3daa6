/* Extreme and stiff cases of docs/stability.md in rendered frames (OSMesa/llvmpipe): lighting
 * limits (gloss 0 and 1, grazing N.L and N.V, a light at the shaded point, radius 0 and huge,
 * 10^4 lights on one pixel, intensities at the FP16 maximum) and scene limits (no lights, no
 * geometry, 1x1 and the largest target, degenerate triangles, NaN/Inf vertices, missing
 * textures, positions at the near and far plane and along grazing rays).
 *
 * References are computed on the CPU in double from the lighting model of docs/renderer.md,
 * evaluated at the G-buffer's own decoded normal, gloss and reconstructed position, so that the
 * tolerances only have to cover the shader's float arithmetic, one depth read step and the FP16
 * store (one FP16 step per store: llvmpipe rounds FP16 render-target stores toward zero, hardware
 * usually to nearest; both are faithful). Position checks compare against analytic ray-plane
 * intersections with tolerances in depth-format steps. The key cases (FP16 limits, 10^4 lights,
 * 1x1, empty scene) run in every mode of tl_render_mode (see `modes`); the others check the
 * light buffer, which only thin-lpp has. docs/stability.md lists every case with its figures.
 *
 * This header is what the case files share: stability_frame.c (hand-made scenes, one rendered
 * frame and its targets) and stability_model.c (the CPU reference of the lighting model, FP16
 * rounding); the cases are in stability_lighting.c, stability_fp16.c, stability_scene_limits.c
 * and stability_depth.c. */
#ifndef TL_STABILITY_H
#define TL_STABILITY_H

#include <stddef.h>
#include <stdint.h>

#include "render_fixture.h"
#include "thinlight/codec.h"
#include "thinlight/context.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"
#include "tl_test.h"

/* The render modes the key cases (FP16 limits, 10^4 lights, 1x1, empty scene) run in; the other
 * cases check the thin light buffer, which only thin-lpp has. */
static const tl_render_mode modes[] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_FORWARD,
                                       TL_MODE_VISIBILITY};
#define MODE_COUNT (sizeof modes / sizeof modes[0])

/* ---- small hand-made scenes (stability_frame.c) -------------------------------------------- */

#define MAX_V 256
#define MAX_I 512
#define MAX_O 8

typedef struct mini_scene {
    tl_vertex v[MAX_V];
    uint32_t idx[MAX_I];
    tl_object obj[MAX_O];
    tl_material mat[4];
    tl_texture tex[2];
    tl_light light[8];
    size_t nv, ni;
    tl_scene s;
} mini_scene;

static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

tl_material plain_material(float albedo, float specular, float gloss);
/* Camera at the origin looking down -Z with +Y up: view space equals world space, so the lights
 * and surfaces are given in view space directly. */
void mini_init(mini_scene *m, float fov_y, float near_z, float far_z);
/* Adds a quad o, o+du, o+du+dv, o+dv (counter-clockwise seen from du x dv) as a new object. */
void add_quad(mini_scene *m, const float o[3], const float du[3], const float dv[3], uint32_t material);
/* A wall facing the camera at distance `dist`, large enough to fill a 60-degree view. */
void add_wall(mini_scene *m, float dist, uint32_t material);
tl_light point_light(float x, float y, float z, float radius, float r, float g, float b);

/* ---- one rendered frame and its targets (stability_frame.c) --------------------------------- */

typedef struct frame {
    uint32_t w, h;
    float *depth, *rt0, *diffuse, *specular, *hdr;
} frame;

typedef struct run {
    tl_renderer *r;
    tl_renderer_desc desc;
    tl_frame_stats stats;
    frame f;
    tl_projection pr;
    float clear; /* window depth of the background */
} run;

/* Reads a target when the plan allocated it; NULL otherwise. */
float *read_target(tl_renderer *r, tl_target_id id);
/* Reads every target the plan allocated and counts non-finite values; returns the number of
 * targets read. Names the offending targets. */
size_t count_nonfinite_all_targets(tl_renderer *r, const char *label, size_t *bad_total);
void run_free(run *u);
/* Creates a renderer, sets the scene, renders with the scene camera and reads the targets. */
int run_scene(run *u, tl_renderer_desc d, const tl_scene *s, const char *label);
void check_all_targets_finite(run *u, const char *label);

/* ---- CPU reference of the lighting model (stability_model.c) -------------------------------- */

/* NDC of a pixel centre, computed as the light pass computes it (float). */
void pixel_ndc(uint32_t x, uint32_t y, uint32_t w, uint32_t h, float ndc[2]);
/* The world-space direction (not unit) of the ray from c->position through window position (x, y)
 * of a w x h frame (pixels, rows bottom-up: a pixel's centre is at x + 0.5, y + 0.5), in double,
 * through the renderer's look-at (forward to the target, right = forward x up, up zero: +Y) and
 * perspective (c->fov_y, aspect w / h). */
void camera_ray(const tl_camera *c, uint32_t w, uint32_t h, double x, double y, double dir[3]);
/* The nearest of `s`'s triangles (objects with an identity or zero transform, triangle primitives)
 * the ray origin + t dir (t > 0) meets, in double: the object's index, or -1 when none; *t_hit its
 * t. For the hand-made scenes' expectations (a few thousand triangles at most). */
long scene_ray_object(const tl_scene *s, const double origin[3], const double dir[3], double *t_hit);
/* The G-buffer sample the light pass sees at a pixel: position reconstructed from the stored
 * depth (the DEPTH target's linear distance), decoded normal and gloss; 0 for background.
 * The light pass fetches the same depth through a texture, which may convert it to float
 * differently from the read-back (llvmpipe: by one float ULP, i.e. about one D24 code near 1), so
 * p_lo and p_hi hold the positions one such step nearer and farther. */
typedef struct gsample {
    double p[3], n[3], gloss;
    double p_lo[3], p_hi[3];
} gsample;

int gbuffer_sample(const frame *f, const tl_projection *pr, float clear_depth, uint32_t x, uint32_t y, gsample *g);
/* One light's (diffuse weight, specular weight) at p with normal n, in double, and an absolute
 * error allowance for the shader's float evaluation. */
void model_terms(const tl_light *l, const double p[3], const double n[3], double gloss, double out[2], double err[2]);
/* The model at a G-buffer sample; `err` adds how far the terms move when the position moves by
 * one depth read step (p_lo, p_hi). */
void light_terms(const tl_light *l, const gsample *g, double out[2], double err[2]);
/* Float -> FP16 -> float, round to nearest even / toward zero (llvmpipe's render-target store). */
double half_rn(double v);
double half_rz(double v);
/* The spacing of FP16 values at |v|, at least the smallest subnormal. */
double half_ulp(double v);

typedef struct light_check {
    size_t lit;         /* pixels with a reference above 1e-3 */
    size_t bad;         /* values beyond tolerance */
    size_t rn, rz, n;   /* single light: values equal to the reference rounded to nearest / toward zero */
    double max_ratio;   /* max |gpu - ref| / tolerance */
    double max_value;   /* largest reference value */
} light_check;

/* Compares the light buffer (diffuse RGB, specular RGB) with the sum over `lights` evaluated at
 * the G-buffer's own samples. */
light_check check_light_buffer(const frame *f, const tl_projection *pr, float clear_depth, const tl_light *lights,
                               size_t count, const char *label);

#endif
