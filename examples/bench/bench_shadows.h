/* thinlight-bench --shadows (docs/shadows.md, "Bench"): each configuration with the crypt's casting
 * lights off and on, their frames taking turns, and the shadow term against ray-traced truth
 * (Embree, where the bench was built with it). bench_shadows.c measures, bench_shadows_truth.c
 * compares with the truth, bench_shadows_report.c writes the table, JSON, doc section and plot. */
#ifndef TL_BENCH_SHADOWS_H
#define TL_BENCH_SHADOWS_H

#include "bench.h"

#define BENCH_SHADOWS_DOC_BEGIN "<!-- bench-shadows:begin -->"
#define BENCH_SHADOWS_DOC_END "<!-- bench-shadows:end -->"
#define BENCH_SHADOWS_PLOT "bench_shadows_error_vs_ms"
#define BENCH_SHADOW_DEPTHS 2 /* the truth with D24 [0] and reversed D32F [1] */
#define BENCH_SHADOW_BAND 2   /* pixels beside a change of the truth's state left out (the penumbra) */

/* One depth format's shadow term against the truth, outside the penumbra. */
typedef struct bench_shadow_error {
    int measured;              /* 0: no truth (run->shadow_truth_why says why) */
    uint64_t counted, acne, leaks;
    double wrong;              /* (acne + leaks) / counted */
    double vs_fat;             /* pixels whose state differs from fat's term (same strategy, depth); NaN: fat */
    uint64_t fat_counted, fat_differ; /* the counts behind vs_fat */
} bench_shadow_error;

/* One configuration at the first size and the first light count. */
typedef struct bench_shadow_record {
    bench_config config;
    uint32_t lights, width, height, frames;
    uint32_t casting_lights;   /* lights with tl_light.shadow */
    double frame_ms, frame_ms_off, frame_ms_nocache; /* medians: cached, no shadows, every map every frame */
    double ratio;              /* median over the frames of (with the cache / without shadows, side by side) */
    double shadow_ms, shadow_ms_nocache; /* tl_frame_stats.shadow_ms, medians */
    double light_ms, light_ms_off, lookup_ms; /* the light pass (light-cull + lights/lights-tiled/forward),
                                                 medians; lookup_ms = light_ms - light_ms_off */
    uint64_t atlas_bytes;      /* tl_frame_stats.shadow_atlas_bytes */
    uint32_t shadow_lights;    /* lights with a map (tl_frame_stats.shadow_lights) */
    uint32_t maps_rendered, maps_cached, maps_nocache; /* the last frame's, cached and without the cache */
    bench_shadow_error truth[BENCH_SHADOW_DEPTHS];
} bench_shadow_record;

/* bench_shadows.c */
int bench_shadows_measure(bench_run *run, tl_context *ctx, bench_scene *scene, tl_tool_progress *progress,
                          uint64_t *done);
uint64_t bench_shadows_frames(const bench_options *opt);

/* bench_shadows_truth.c: the truth of one light over the scene's camera at w x h; NULL with *why set
 * when the bench has no Embree or it failed. */
typedef struct bench_shadow_truth bench_shadow_truth;
bench_shadow_truth *bench_shadow_truth_make(const tl_scene *scene, const tl_light *light, uint32_t w, uint32_t h,
                                            char *why, size_t why_size);
void bench_shadow_truth_free(bench_shadow_truth *t);
/* Adds term's counts (0..1, < 0 where the light adds nothing) against the truth to `out`, and
 * against fat's term when fat is not NULL; then wrong and vs_fat are the fractions so far. */
void bench_shadow_truth_compare(const bench_shadow_truth *t, const float *term, const float *fat,
                                bench_shadow_error *out);
#define BENCH_SHADOW_TRUTH_LIGHTS 16 /* the casting point lights measured, one at a time, at most */

/* bench_shadows_term.c: the shadow term of `light` alone in r (whose scene and options the caller
 * set: ambient off, no emission, the HDR target kept), n pixels: the HDR sum of RGB with the light
 * casting over it not casting, 1 at most, -1 where the light adds less than 2^-12 (the FP16
 * targets hold 11 bits) or 10^-6 of its peak; malloc'd, rows bottom up; NULL when a call failed
 * (tl_renderer_last_error says why). Leaves r with `light` not casting. */
float *bench_shadow_term(tl_renderer *r, const tl_light *light, size_t n);

/* bench_shadows_report.c */
void bench_shadows_print_table(const bench_run *run);
void bench_shadows_json(tl_tool_json *j, const bench_run *run);
int bench_shadows_update_doc(const bench_run *run, const char *doc_text);
/* bench_shadows_plot.c */
int bench_shadows_plot(bench_run *run);

#endif
