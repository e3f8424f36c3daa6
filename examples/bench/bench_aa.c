/* The antialiasing measurements (--aa, docs/antialiasing.md): at the first size and for every light
 * count, the truth first (fat at BENCH_AA_TRUTH_SCALE times the width and the height with FXAA
 * off, its HDR target tone-mapped per sample on the CPU and averaged per pixel, bench_aa_truth.c;
 * the edge pixels from its depth and normals, bench_edges.c), then every requested mode of the
 * first strategy with every method asked that its plan applies, one renderer each, the renderers
 * taking turns frame by frame (a mode's methods side by side; at most bench_renderers_at_once at a
 * time). Each record: the median frame time, its ratio to the same mode's FXAA frames, the error
 * of the final image against the truth over the frame and over the edge pixels, the bytes its
 * targets take and, thin-lpp with MSAA, the re-lit fraction. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "tool_log.h"

const char *const bench_aa_names[BENCH_AAS + 1] = {"none",  "fxaa",   "msaa2",  "msaa4", "msaa8",
                                                   "msaa2e", "msaa4e", "msaa8e", NULL};
static const uint32_t bench__aa_sample_counts[BENCH_AAS] = {1, 1, 2, 4, 8, 2, 4, 8};

tl_msaa_lighting bench_aa_lighting(bench_aa a)
{
    if (a >= BENCH_AA_MSAA2E && a < BENCH_AAS) return TL_MSAA_LIGHTING_SAMPLE_EDGES;
    return a >= BENCH_AA_MSAA2 && a < BENCH_AAS ? TL_MSAA_LIGHTING_MATERIAL_PASS : TL_MSAA_LIGHTING_DEFAULT;
}

const char *bench_aa_name(bench_aa a) { return (unsigned)a < BENCH_AAS ? bench_aa_names[a] : "truth"; }
uint32_t bench_aa_samples(bench_aa a) { return (unsigned)a < BENCH_AAS ? bench__aa_sample_counts[a] : 1; }

/* One renderer of the measurement: a mode (with the first strategy) and a method. */
typedef struct bench__aa_item {
    bench_config config;
    bench_aa aa;
} bench__aa_item;

static tl_renderer_desc bench__aa_desc(const bench_options *opt, bench_config c, bench_aa aa)
{
    tl_renderer_desc d = bench_config_desc(opt, c, opt->sizes[0].width, opt->sizes[0].height);
    d.options.fxaa = aa == BENCH_AA_FXAA ? TL_FXAA_DEFAULT : TL_FXAA_OFF;
    d.options.msaa = bench_aa_samples(aa);
    d.options.msaa_lighting = bench_aa_lighting(aa);
    tl_tool_budget_renderer(&opt->budgets, &d);
    return d;
}

/* The truth's renderer: fat, the first strategy, FXAA off, the targets it reads back kept. */
static tl_renderer_desc bench__truth_desc(const bench_options *opt)
{
    tl_renderer_desc d = bench__aa_desc(opt, bench_config_make(TL_MODE_FAT, opt->strategies[0]), BENCH_AA_NONE);
    d.width *= BENCH_AA_TRUTH_SCALE;
    d.height *= BENCH_AA_TRUTH_SCALE;
    d.options.keep_targets = TL_TARGET_BIT(TL_TARGET_HDR) | TL_TARGET_BIT(TL_TARGET_DEPTH) |
                             TL_TARGET_BIT(TL_TARGET_FAT_NORMAL);
    return d;
}

/* Whether the plan applies method aa in configuration c: MSAA with as many samples as asked, and
 * no more than the context allows (max_samples; 0: not known). Otherwise why not, in `why`. */
static int bench__aa_applies(const bench_options *opt, const tl_scene_feature_set *features, bench_config c,
                             bench_aa aa, uint32_t max_samples, char *why, size_t size)
{
    uint32_t n = bench_aa_samples(aa);
    tl_renderer_desc d = bench__aa_desc(opt, c, aa);
    tl_frame_plan plan;
    if (n == 1) return 1;
    if (tl_frame_plan_build(&d, features, &plan) != TL_OK) {
        snprintf(why, size, "no plan");
        return 0;
    }
    if (plan.msaa != n) {
        snprintf(why, size, "%s", plan.msaa_reason[0] ? plan.msaa_reason : "the plan has no MSAA");
        return 0;
    }
    if (max_samples && n > max_samples) {
        snprintf(why, size, "the context allows %u samples (GL_MAX_SAMPLES)", max_samples);
        return 0;
    }
    return 1;
}

/* The renderers measured, mode by mode in the order asked, methods in bench_aa order; the methods
 * the plan does not apply are left out, each said once in run->aa_skipped when `run` is given. */
static size_t bench__aa_items(bench_run *run, const bench_options *opt, const bench_scene *scene, uint32_t max_samples,
                              bench__aa_item *out)
{
    tl_scene_feature_set features;
    tl_scene_features(bench_scene_get(scene), &features);
    size_t n = 0;
    for (size_t m = 0; m < opt->mode_count; m++) {
        bench_config c = bench_config_make(opt->modes[m], opt->strategies[0]);
        for (int a = 0; a < BENCH_AAS; a++) {
            char why[128] = "";
            if (!(opt->aa & (1u << a))) continue;
            if (bench__aa_applies(opt, &features, c, (bench_aa)a, max_samples, why, sizeof why)) {
                out[n++] = (bench__aa_item){c, (bench_aa)a};
            } else if (run && run->aa_skipped_count < BENCH_MODES * BENCH_AAS) {
                char *line = run->aa_skipped[run->aa_skipped_count++];
                snprintf(line, sizeof run->aa_skipped[0], "%s %s: %s", bench_config_name(c), bench_aa_names[a], why);
                fprintf(stderr, BENCH_TOOL ": --aa: no record of %s\n", line);
            }
        }
    }
    return n;
}

uint64_t bench_aa_frames(const bench_run *run, const bench_scene *scene)
{
    const bench_options *opt = &run->opt;
    bench__aa_item items[BENCH_MODES * BENCH_AAS];
    if (!opt->aa) return 0;
    size_t n = bench__aa_items(NULL, opt, scene, 0, items);
    return (uint64_t)opt->light_count * (n * (opt->warmup + opt->frames) + 1);
}

int bench_aa_check_budget(const bench_run *run, const bench_scene *scene)
{
    if (!run->opt.aa) return 0;
    tl_renderer_desc d = bench__truth_desc(&run->opt);
    return tl_tool_budget_check(BENCH_TOOL, "--aa, the truth", &d, bench_scene_get(scene));
}

/* GL_MAX_SAMPLES of the context (0 when it cannot be asked). */
static uint32_t bench__max_samples(tl_context *ctx)
{
    typedef void (*get_integer_fn)(unsigned, int *);
    tl_gl_proc proc = tl_context_proc_loader(ctx, "glGetIntegerv");
    int value = 0;
    if (proc) ((get_integer_fn)proc)(0x8D57u /* GL_MAX_SAMPLES */, &value);
    return value > 0 ? (uint32_t)value : 0;
}

/* One target of the truth's renderer, read back (w x h RGBA floats); NULL after a line saying why. */
static float *bench__read(tl_renderer *r, tl_target_id t, size_t pixels)
{
    size_t bytes = pixels * 4 * sizeof(float);
    float *p = malloc(bytes);
    if (!p) tl_tool_fail(BENCH_TOOL, "out of memory for the AA truth's %s", tl_target_name(t));
    else if (tl_renderer_read_target(r, t, p, &bytes) != TL_OK) {
        tl_tool_fail(BENCH_TOOL, "--aa, the truth's %s: %s", tl_target_name(t), tl_renderer_last_error(r));
        free(p);
        p = NULL;
    }
    return p;
}

/* The truth's edge pixels: bench_edges_mask on its depth and normals, a pixel an edge pixel when
 * any of its samples is. */
static int bench__truth_edges(tl_renderer *r, bench_aa_truth *t)
{
    const uint32_t k = BENCH_AA_TRUTH_SCALE;
    size_t fine = (size_t)t->width * k * t->height * k;
    float *depth = bench__read(r, TL_TARGET_DEPTH, fine), *normal = depth ? bench__read(r, TL_TARGET_FAT_NORMAL, fine) : NULL;
    uint8_t *mask = normal ? malloc(fine) : NULL;
    if (normal && !mask) tl_tool_fail(BENCH_TOOL, "out of memory for the AA truth's edges");
    if (mask) {
        bench_edges_mask(depth, normal, t->width * k, t->height * k, mask);
        t->edge_pixels = bench_aa_reduce_mask(mask, t->width, t->height, k, t->edge);
    }
    free(depth);
    free(normal);
    free(mask);
    return !mask;
}

/* The truth of `lights` (slot 0's renderer, which the records then take over). */
static int bench__truth(bench_run *run, tl_context *ctx, bench_scene *scene, const tl_light *lights, size_t count,
                        bench_aa_truth *t)
{
    tl_renderer_desc d = bench__truth_desc(&run->opt);
    tl_frame_stats st;
    tl_renderer *r = bench_renderer(run, ctx, 0, d, bench_scene_get(scene));
    if (!r) return 1;
    if (tl_renderer_set_lights(r, lights, count) != TL_OK || tl_renderer_render(r, NULL, &st) != TL_OK) {
        tl_tool_fail(BENCH_TOOL, "--aa, the truth at %ux%u: %s", d.width, d.height, tl_renderer_last_error(r));
        return 1;
    }
    t->ms = st.gpu_ms > 0.0 ? st.gpu_ms : st.wall_ms;
    float *hdr = bench__read(r, TL_TARGET_HDR, (size_t)d.width * d.height);
    if (!hdr) return 1;
    bench_aa_resolve(hdr, t->width, t->height, BENCH_AA_TRUTH_SCALE, 1.0f, t->rgb);
    free(hdr);
    return bench__truth_edges(r, t);
}


/* A group of renderers taking turns: the items [first, first + count) and their frames. */
typedef struct bench__aa_group {
    const bench__aa_item *items;
    size_t first, count;
    tl_renderer *r[BENCH_MODES * BENCH_AAS];
    tl_frame_stats last[BENCH_MODES * BENCH_AAS]; /* each one's last frame */
    double *ms;                                   /* ms[k * frames + f] */
} bench__aa_group;

static int bench__group_open(bench_run *run, tl_context *ctx, bench_scene *scene, const tl_light *lights, size_t count,
                             bench__aa_group *g)
{
    for (size_t k = 0; k < g->count; k++) {
        const bench__aa_item *it = &g->items[g->first + k];
        g->r[k] = bench_renderer(run, ctx, k, bench__aa_desc(&run->opt, it->config, it->aa), bench_scene_get(scene));
        if (!g->r[k]) return 1;
        tl_frame_plan plan; /* the renderer's own plan applies what the pure plan promised */
        if (tl_renderer_get_plan(g->r[k], &plan) == TL_OK && plan.msaa != bench_aa_samples(it->aa)) {
            tl_tool_fail(BENCH_TOOL, "--aa, %s %s: the renderer planned %u samples (%s)", bench_config_name(it->config),
                         bench_aa_name(it->aa), plan.msaa, plan.msaa_reason);
            return 1;
        }
        if (tl_renderer_set_lights(g->r[k], lights, count) != TL_OK) {
            tl_tool_log_error(&run->log, "%s", tl_renderer_last_error(g->r[k]));
            return 1;
        }
    }
    return 0;
}

static int bench__group_frames(bench_run *run, bench__aa_group *g, uint32_t lights, tl_tool_progress *progress,
                               uint64_t *done)
{
    const bench_options *opt = &run->opt;
    uint32_t total = opt->warmup + opt->frames;
    char label[96];
    for (uint32_t f = 0; f < total; f++) {
        snprintf(label, sizeof label, "aa: %u lights, %zu renderers, frame %u/%u", lights, g->count, f + 1, total);
        tl_tool_progress_update(progress, *done, label, f == 0);
        for (size_t j = 0; j < g->count; j++, ++*done) {
            size_t k = (f + j) % g->count;
            tl_frame_stats *st = &g->last[k];
            if (tl_renderer_render(g->r[k], NULL, st) != TL_OK) {
                const bench__aa_item *it = &g->items[g->first + k];
                tl_tool_fail(BENCH_TOOL, "--aa, %s %s: %s", bench_config_name(it->config), bench_aa_name(it->aa),
                             tl_renderer_last_error(g->r[k]));
                return 1;
            }
            if (f < opt->warmup) continue;
            if (!(st->gpu_ms > 0.0)) run->timers_ok = 0;
            g->ms[k * opt->frames + (f - opt->warmup)] = st->gpu_ms > 0.0 ? st->gpu_ms : st->wall_ms;
        }
    }
    return 0;
}

/* The final image of renderer k (RGB into rgb) against the truth, into its record. */
static int bench__group_record(bench_run *run, bench__aa_group *g, size_t k, const bench_aa_truth *t, uint8_t *rgb,
                               bench_aa_record *rec)
{
    const bench__aa_item *it = &g->items[g->first + k];
    size_t n = (size_t)t->width * t->height;
    double ms[BENCH_MAX_FRAMES];
    memcpy(ms, g->ms + k * run->opt.frames, run->opt.frames * sizeof *ms);
    *rec = (bench_aa_record){.aa = it->aa, .config = it->config, .samples = bench_aa_samples(it->aa),
                             .lights = t->lights, .width = t->width, .height = t->height, .frames = run->opt.frames,
                             .ms_median = bench_median(ms, run->opt.frames), .ratio_vs_fxaa = NAN, .ratio_vs_none = NAN,
                             .edge_fraction = (double)t->edge_pixels / (double)n, .relit_fraction = NAN};
    if (tl_renderer_read_output(g->r[k], rgb, &(size_t){n * 4}) != TL_OK) {
        tl_tool_fail(BENCH_TOOL, "--aa, %s %s: %s", bench_config_name(it->config), bench_aa_name(it->aa),
                     tl_renderer_last_error(g->r[k]));
        return 1;
    }
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) rgb[3 * i + c] = rgb[4 * i + c];
    tl_image_compare_u8(rgb, t->rgb, n * 3, &rec->ldr);
    bench_edges_compare(rgb, t->rgb, t->edge, n, &rec->edge_ldr);
    rec->bytes_per_pixel = (uint32_t)((g->last[k].allocated_target_bytes + n / 2) / n);
    if (bench_aa_lighting(it->aa) == TL_MSAA_LIGHTING_SAMPLE_EDGES)
        rec->relit_fraction = g->last[k].msaa_edge_fraction;
    else if (bench_config_mode(it->config) == TL_MODE_THIN_LPP && rec->samples > 1)
        rec->relit_fraction = g->last[k].relit_fraction;
    if (run->opt.out && t->lights == run->opt.lights[run->opt.light_count - 1])
        return bench_aa_images(run, t, rec, rgb);
    return 0;
}

/* The ratio of item k's frames to those of the same mode's method `base` rendered beside them
 * (the group's), NaN when the group has no such item. */
static double bench__group_ratio(const bench_run *run, const bench__aa_group *g, size_t k, bench_aa base)
{
    uint32_t frames = run->opt.frames;
    for (size_t x = 0; x < g->count; x++) {
        const bench__aa_item *a = &g->items[g->first + k], *b = &g->items[g->first + x];
        if (b->aa != base || b->config != a->config) continue;
        double ratios[BENCH_MAX_FRAMES];
        for (uint32_t f = 0; f < frames; f++) ratios[f] = g->ms[k * frames + f] / g->ms[x * frames + f];
        return bench_median(ratios, frames);
    }
    return NAN;
}

/* The ratios to the same mode's FXAA and no-AA frames rendered beside them. */
static void bench__group_ratios(const bench_run *run, const bench__aa_group *g, bench_aa_record *recs)
{
    for (size_t k = 0; k < g->count; k++) {
        recs[k].ratio_vs_fxaa = bench__group_ratio(run, g, k, BENCH_AA_FXAA);
        recs[k].ratio_vs_none = bench__group_ratio(run, g, k, BENCH_AA_NONE);
    }
}

/* How many items from `first` the next group takes: whole modes while they fit in at_once. */
static size_t bench__group_size(const bench__aa_item *items, size_t n, size_t first, size_t at_once)
{
    size_t end = first;
    while (end < n && end - first < at_once) {
        size_t mode_end = end;
        while (mode_end < n && items[mode_end].config == items[end].config) mode_end++;
        if (mode_end - first > at_once && end > first) break;
        end = mode_end - first > at_once ? first + at_once : mode_end;
    }
    return end - first;
}

/* The rest of the ratios: against the medians where a mode's methods were not side by side. */
static void bench__median_ratios(bench_aa_record *recs, size_t n)
{
    for (size_t k = 0; k < n; k++)
        for (size_t x = 0; x < n; x++) {
            if (recs[x].config != recs[k].config) continue;
            if (recs[x].aa == BENCH_AA_FXAA && isnan(recs[k].ratio_vs_fxaa))
                recs[k].ratio_vs_fxaa = recs[k].ms_median / recs[x].ms_median;
            if (recs[x].aa == BENCH_AA_NONE && isnan(recs[k].ratio_vs_none))
                recs[k].ratio_vs_none = recs[k].ms_median / recs[x].ms_median;
        }
}

/* Every item at one light count, a group at a time; records at recs[0..n). */
static int bench__aa_lights(bench_run *run, tl_context *ctx, bench_scene *scene, const bench__aa_item *items, size_t n,
                            const bench_aa_truth *t, bench_aa_record *recs, tl_tool_progress *progress, uint64_t *done)
{
    const tl_light *lights;
    size_t count, at_once = bench_renderers_at_once(scene);
    if (bench_scene_lights(scene, t->lights, &lights, &count)) return 1;
    double *ms = malloc(n * run->opt.frames * sizeof *ms);
    uint8_t *rgb = malloc((size_t)t->width * t->height * 4);
    int err = !ms || !rgb;
    if (err) tl_tool_fail(BENCH_TOOL, "out of memory for the AA records");
    for (size_t first = 0; !err && first < n;) {
        bench__aa_group g = {.items = items, .first = first, .count = bench__group_size(items, n, first, at_once), .ms = ms};
        err = bench__group_open(run, ctx, scene, lights, count, &g) || bench__group_frames(run, &g, t->lights, progress, done);
        for (size_t k = 0; !err && k < g.count; k++) err = bench__group_record(run, &g, k, t, rgb, &recs[first + k]);
        if (!err) bench__group_ratios(run, &g, recs + first);
        first += g.count;
    }
    if (!err) bench__median_ratios(recs, n);
    free(ms);
    free(rgb);
    return err;
}

/* The truth of light count `lights` and its records. */
static int bench__aa_count(bench_run *run, tl_context *ctx, bench_scene *scene, const bench__aa_item *items, size_t n,
                           bench_aa_truth *t, tl_tool_progress *progress, uint64_t *done)
{
    const tl_light *lights;
    size_t count;
    char label[96];
    snprintf(label, sizeof label, "aa: the truth of %u lights at %ux%u", t->lights, t->width * BENCH_AA_TRUTH_SCALE,
             t->height * BENCH_AA_TRUTH_SCALE);
    tl_tool_progress_update(progress, *done, label, 1);
    if (bench_scene_lights(scene, t->lights, &lights, &count) || bench__truth(run, ctx, scene, lights, count, t)) return 1;
    ++*done;
    if (run->opt.out && t->lights == run->opt.lights[run->opt.light_count - 1] && bench_aa_images(run, t, NULL, t->rgb))
        return 1;
    int err = bench__aa_lights(run, ctx, scene, items, n, t, run->aa + run->aa_count, progress, done);
    if (!err) run->aa_count += n;
    return err;
}

int bench_aa_measure(bench_run *run, tl_context *ctx, bench_scene *scene, tl_tool_progress *progress, uint64_t *done)
{
    const bench_options *opt = &run->opt;
    bench__aa_item items[BENCH_MODES * BENCH_AAS];
    if (!opt->aa) return 0;
    size_t n = bench__aa_items(run, opt, scene, bench__max_samples(ctx), items);
    if (!n) return 0;
    bench_aa_truth t = {.width = opt->sizes[0].width, .height = opt->sizes[0].height};
    size_t pixels = (size_t)t.width * t.height;
    run->aa = calloc(n * opt->light_count, sizeof *run->aa);
    t.rgb = malloc(pixels * 3);
    t.edge = malloc(pixels);
    int err = !run->aa || !t.rgb || !t.edge;
    if (err) tl_tool_fail(BENCH_TOOL, "out of memory for the AA measurement");
    for (size_t li = 0; !err && li < opt->light_count; li++) {
        t.lights = opt->lights[li];
        err = bench__aa_count(run, ctx, scene, items, n, &t, progress, done);
    }
    free(t.rgb);
    free(t.edge);
    return err;
}

void bench_aa_free(bench_run *run)
{
    free(run->aa);
    free(run->aa_images);
    run->aa = NULL;
    run->aa_images = NULL;
}
