/* The measurements: for every size and every light count, warm-up frames, then timed frames of
 * every mode in turn (fat, the reference, first): interleaving the modes frame by frame makes
 * every mode see the same share of whatever else the machine is doing. Then medians of the GPU
 * timers and the wall clock, the plan's targets, the renderer's fragment and byte counts, and the
 * error of the final and HDR images against fat's images of the same frame. Last, what planning
 * saves in time: each mode planned against tl_renderer_options.planning off, on the same context. */
#define _DEFAULT_SOURCE /* sysconf(_SC_PHYS_PAGES) */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench.h"
#include "bench_shadows.h"
#include "thinlight/context.h"
#include "tool_log.h"
#include "tool_util.h"


/* TL_MODE_THIN_LPP .. TL_MODE_VISIBILITY (tl_render_mode order, DEFAULT left out): name, slug. Every
 * mode has its row: a mode without one was named "(null)" in the table and in file names.
 * visibility is always tiled (bench_config_make): its plan lights from the tile lists. */
static const char *const bench__names[BENCH_STRATEGIES][BENCH_MODES][2] = {
    {{"thin-lpp/auto", "thin-lpp-auto"}, {"thin-deferred/auto", "thin-deferred-auto"}, {"fat/auto", "fat-auto"},
     {"forward/auto", "forward-auto"}, {"visibility/tiled", "visibility-tiled"}},
    {{"thin-lpp/volumes", "thin-lpp-volumes"}, {"thin-deferred/volumes", "thin-deferred-volumes"},
     {"fat/volumes", "fat-volumes"}, {"forward", "forward"}, {"visibility/tiled", "visibility-tiled"}},
    {{"thin-lpp/tiled", "thin-lpp-tiled"}, {"thin-deferred/tiled", "thin-deferred-tiled"}, {"fat/tiled", "fat-tiled"},
     {"forward+", "forward-plus"}, {"visibility/tiled", "visibility-tiled"}}};
_Static_assert(BENCH_MODES == 5, "a new mode needs its names in bench__names (and its colour in the plots)");

static const char *bench__config_string(bench_config c, int slug)
{
    unsigned m = (unsigned)bench_config_mode(c), s = (unsigned)bench_config_strategy(c);
    if (m < 1 || m > BENCH_MODES || s >= BENCH_STRATEGIES) return "?";
    unsigned v = bench_config_variant_of(c);
    static const char *const scaled[2][BENCH_STRATEGIES][2] = {
        {{"thin-lpp/auto/light-1/2", "thin-lpp-auto-light-half"}, {"thin-lpp/volumes/light-1/2", "thin-lpp-volumes-light-half"},
         {"thin-lpp/tiled/light-1/2", "thin-lpp-tiled-light-half"}},
        {{"thin-lpp/auto/light-1/4", "thin-lpp-auto-light-quarter"},
         {"thin-lpp/volumes/light-1/4", "thin-lpp-volumes-light-quarter"},
         {"thin-lpp/tiled/light-1/4", "thin-lpp-tiled-light-quarter"}}};
    if ((v == BENCH_VARIANT_LIGHT_HALF || v == BENCH_VARIANT_LIGHT_QUARTER) && m == TL_MODE_THIN_LPP)
        return scaled[v - BENCH_VARIANT_LIGHT_HALF][s][slug];
    static const char *const compute[BENCH_MODES][2] = {{"thin-lpp/tiled-compute", "thin-lpp-tiled-compute"},
                                                         {"thin-deferred/tiled-compute", "thin-deferred-tiled-compute"},
                                                         {"fat/tiled-compute", "fat-tiled-compute"},
                                                         {"?", "?"}, {"?", "?"}};
    if (v == BENCH_VARIANT_TILED_COMPUTE) return s == TL_LIGHT_STRATEGY_TILED ? compute[m - 1][slug] : "?";
    if (v && (m != TL_MODE_THIN_LPP || s != TL_LIGHT_STRATEGY_TILED)) return "?";
    if (v == BENCH_VARIANT_R11G11B10F) return slug ? "thin-lpp-tiled-r11g11b10f" : "thin-lpp/tiled/r11g11b10f";
    if (v == BENCH_VARIANT_FRESNEL_NV) return slug ? "thin-lpp-tiled-nv" : "thin-lpp/tiled/nv";
    return bench__names[s][m - 1][slug];
}

const char *bench_config_name(bench_config c) { return bench__config_string(c, 0); }
const char *bench_config_slug(bench_config c) { return bench__config_string(c, 1); }

bench_config bench_reference_of(bench_config c) { return bench_config_make(BENCH_REFERENCE, bench_config_strategy(c)); }

/* The strategy group visibility is rendered in (once: it always lights with tiles): the tiled
 * strategy's, so fat/tiled is its error reference; without tiles asked, the first strategy's (its fat
 * the reference; the name stays visibility/tiled, what its plan does). */
size_t bench_visibility_group(const bench_options *opt)
{
    for (size_t s = 0; s < opt->strategy_count; s++)
        if (opt->strategies[s] == TL_LIGHT_STRATEGY_TILED) return s;
    return 0;
}

size_t bench_render_modes(const bench_options *opt, bench_config *modes)
{
    size_t n = 0;
    for (size_t s = 0; s < opt->strategy_count; s++) {
        modes[n++] = bench_config_make(BENCH_REFERENCE, opt->strategies[s]);
        for (size_t i = 0; i < opt->mode_count; i++)
            if (opt->modes[i] != BENCH_REFERENCE && (opt->modes[i] != TL_MODE_VISIBILITY || s == bench_visibility_group(opt)))
                modes[n++] = bench_config_make(opt->modes[i], opt->strategies[s]);
        bench_config lpp = bench_config_make(TL_MODE_THIN_LPP, opt->strategies[s]);
        if (s == 0 && bench_mode_requested(opt, TL_MODE_THIN_LPP)) { /* the light scales (they light with volumes) */
            if (opt->light_scales & 1u) modes[n++] = bench_config_variant(lpp, BENCH_VARIANT_LIGHT_HALF);
            if (opt->light_scales & 2u) modes[n++] = bench_config_variant(lpp, BENCH_VARIANT_LIGHT_QUARTER);
        }
        if (opt->strategies[s] == TL_LIGHT_STRATEGY_TILED && opt->base.tiled_shading == TL_TILED_SHADING_AUTO) {
            /* both tiled light passes, each a configuration: fat's first (the others' error reference
             * stays fat/tiled) */
            modes[n++] = bench_config_variant(bench_config_make(BENCH_REFERENCE, TL_LIGHT_STRATEGY_TILED),
                                              BENCH_VARIANT_TILED_COMPUTE);
            for (size_t i = 0; i < opt->mode_count; i++)
                if (opt->modes[i] != BENCH_REFERENCE && opt->modes[i] != TL_MODE_FORWARD &&
                    opt->modes[i] != TL_MODE_VISIBILITY) /* its resolve is compute already */
                    modes[n++] = bench_config_variant(bench_config_make(opt->modes[i], TL_LIGHT_STRATEGY_TILED),
                                                      BENCH_VARIANT_TILED_COMPUTE);
        }
        bench_config tiled = bench_config_make(TL_MODE_THIN_LPP, TL_LIGHT_STRATEGY_TILED);
        if (opt->strategies[s] != TL_LIGHT_STRATEGY_TILED || !bench_mode_requested(opt, TL_MODE_THIN_LPP)) continue;
        if (opt->small_light_buffer) modes[n++] = bench_config_variant(tiled, BENCH_VARIANT_R11G11B10F);
        if (opt->fresnel_nv_variant) modes[n++] = bench_config_variant(tiled, BENCH_VARIANT_FRESNEL_NV);
    }
    return n;
}

int bench_mode_requested(const bench_options *opt, tl_render_mode mode)
{
    for (size_t i = 0; i < opt->mode_count; i++)
        if (opt->modes[i] == mode) return 1;
    return 0;
}

const bench_record *bench_find(const bench_run *run, bench_config config, uint32_t lights, bench_size size)
{
    for (size_t i = 0; i < run->record_count; i++) {
        const bench_record *r = &run->records[i];
        if (r->config == config && r->lights == lights && r->width == size.width && r->height == size.height) return r;
    }
    return NULL;
}

double bench_speedup(const bench_record *a, const bench_record *b)
{
    double ratios[BENCH_MAX_FRAMES], unused, median;
    if (!a->frame_ms || !b->frame_ms || a->frames != b->frames || !a->frames) return b->ms_median / a->ms_median;
    for (uint32_t f = 0; f < a->frames; f++) ratios[f] = b->frame_ms[f] / a->frame_ms[f];
    bench_median_p90(ratios, a->frames, &median, &unused);
    return median;
}

double bench_light_pass_ms(tl_render_mode mode, const double *pass_ms)
{
    if (mode == TL_MODE_FORWARD) return pass_ms[TL_PASS_FORWARD];
    if (mode == TL_MODE_VISIBILITY) return pass_ms[TL_PASS_VIS_RESOLVE];
    return pass_ms[TL_PASS_LIGHTS] + pass_ms[TL_PASS_LIGHTS_TILED];
}

double bench_per_light_ms(const bench_record *r) { return r->lights ? r->lighting_ms / r->lights : NAN; }

double bench_ns_per_pair(const bench_record *r)
{
    return r->light_pairs ? r->lighting_ms * 1e6 / (double)r->light_pairs : NAN;
}

double bench_ms_per_mpixel_covered(const bench_record *r)
{
    return r->covered_pixels ? r->lighting_ms / ((double)r->covered_pixels * 1e-6) : NAN;
}

double bench_mib_at(const bench_record *r, uint32_t w, uint32_t h)
{
    return (double)r->bytes_per_pixel * (double)w * (double)h / 1048576.0;
}

uint32_t bench_light_buffer_bpp(const bench_record *r)
{
    return r->target_bpp[TL_TARGET_LIGHT_DIFFUSE] + r->target_bpp[TL_TARGET_LIGHT_SPECULAR] +
           r->target_bpp[TL_TARGET_LIGHT_FRESNEL];
}

/* ---- statistics over the timed frames ------------------------------------------------------- */

static int bench__cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

void bench_median_p90(double *v, size_t n, double *median, double *p90)
{
    qsort(v, n, sizeof *v, bench__cmp);
    *median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    size_t rank = (size_t)ceil(0.9 * (double)n);
    *p90 = v[rank ? rank - 1 : 0];
}

double bench_median(double *v, size_t n)
{
    double median, p90;
    bench_median_p90(v, n, &median, &p90);
    return median;
}

/* ---- one (mode, lights, size) ---------------------------------------------------------------- */

typedef struct bench__frame_buffers {
    size_t pixels;
    uint8_t *ldr, *ref_ldr;      /* RGB after compaction */
    float *hdr, *ref_hdr;        /* RGB after compaction */
    uint8_t *scale1_ldr;         /* thin-lpp at light scale 1, the light-scale variants' second reference */
    uint8_t *edge;               /* the size's edge mask (bench_edges.c), once edge_done */
    size_t edge_count;
    int edge_done;
} bench__frame_buffers;

/* One mode's timed frames: gpu[f], wall[f], pass[p * frames + f], and the last frame's stats. */
typedef struct bench__samples {
    double *gpu, *wall, *cpu, *pass;
    tl_frame_stats last;
} bench__samples;

/* RGBA to RGB in place. */
static void bench__rgb_u8(uint8_t *p, size_t n)
{
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) p[3 * i + c] = p[4 * i + c];
}

/* RGBA to RGB in place; the pixels with a non-finite channel, and in *marked those whose alpha is
 * the material pass's mark of a pixel the edge fix-up re-lit (0.5; 1 elsewhere). */
static uint64_t bench__rgb_f32(float *p, size_t n, uint64_t *marked)
{
    uint64_t bad = 0;
    *marked = 0;
    for (size_t i = 0; i < n; i++) {
        *marked += p[4 * i + 3] > 0.25f && p[4 * i + 3] < 0.75f;
        bad += !(isfinite(p[4 * i]) && isfinite(p[4 * i + 1]) && isfinite(p[4 * i + 2]) && isfinite(p[4 * i + 3]));
        for (int c = 0; c < 3; c++) p[3 * i + c] = p[4 * i + c];
    }
    return bad;
}

static double bench__peak(const float *rgb, size_t count)
{
    double peak = 0.0;
    for (size_t i = 0; i < count; i++)
        if (isfinite(rgb[i]) && rgb[i] > peak) peak = rgb[i];
    return peak > 0.0 ? peak : 1.0;
}

/* Plan figures: targets from what the renderer allocated, passes and the technique's bytes from
 * the plan (when the renderer can give it). */
static void bench__plan_figures(tl_tool_log *log, tl_renderer *r, const tl_frame_stats *st, size_t pixels,
                                bench_record *rec)
{
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        rec->target_bpp[t] = (uint32_t)((st->target_bytes[t] + pixels / 2) / pixels);
        rec->bytes_per_pixel_sum += rec->target_bpp[t];
    }
    rec->bytes_per_pixel = (uint32_t)((st->allocated_target_bytes + pixels / 2) / pixels);
    tl_frame_plan plan;
    if (tl_renderer_get_plan(r, &plan) == TL_OK) {
        for (size_t i = 0; i < plan.pass_count && i < TL_PASS_COUNT; i++) rec->passes |= BENCH_PASS_BIT(plan.passes[i].pass);
        rec->gbuffer_bytes_per_pixel = plan.gbuffer_bytes_per_pixel;
        rec->strategy = plan.light_strategy;
        rec->lighting = plan.lighting;
        rec->fresnel = plan.fresnel;
        for (int t = 0; t < TL_TARGET_COUNT; t++)
            if (plan.target_bytes_per_pixel[t] != rec->target_bpp[t]) { /* once, not per light count */
                char line[256];
                snprintf(line, sizeof line, "%s %s: the plan says %u B/px, the renderer allocated %u B/px",
                         bench_config_name(rec->config), tl_target_name((tl_target_id)t),
                         plan.target_bytes_per_pixel[t], rec->target_bpp[t]);
                tl_tool_log_message(log, TL_LOG_WARNING, line);
            }
    } else {
        for (int p = 0; p < TL_PASS_COUNT; p++)
            if (st->pass_ms[p] > 0.0) rec->passes |= BENCH_PASS_BIT(p);
        rec->gbuffer_bytes_per_pixel = (uint32_t)((st->gbuffer_bytes + st->light_buffer_bytes + pixels / 2) / pixels);
    }
}

/* Frame f of a mode (f < warmup: not timed). */
static int bench__frame(bench_run *run, tl_renderer *r, const bench_record *rec, bench__samples *smp, uint32_t f)
{
    const bench_options *opt = &run->opt;
    tl_frame_stats *st = &smp->last;
    if (tl_renderer_render(r, NULL, st) != TL_OK) {
        tl_tool_fail(BENCH_TOOL, "%s at %ux%u with %u lights: %s", bench_config_name(rec->config), rec->width,
                     rec->height, rec->lights, tl_renderer_last_error(r));
        return 1;
    }
    if (f < opt->warmup) return 0;
    uint32_t k = f - opt->warmup, frames = opt->frames;
    int timed = st->gpu_ms > 0.0;
    if (!timed) run->timers_ok = 0;
    smp->gpu[k] = timed ? st->gpu_ms : st->wall_ms;
    smp->wall[k] = st->wall_ms;
    smp->cpu[k] = st->cpu_ms;
    for (int p = 0; p < TL_PASS_COUNT; p++) smp->pass[p * frames + k] = st->pass_ms[p] > 0.0 ? st->pass_ms[p] : 0.0;
    return 0;
}

/* Medians over the timed frames; counts, byte estimates and sizes from the last frame (they do not
 * change from frame to frame). */
static void bench__summarise_frames(bench_run *run, tl_renderer *r, bench__samples *smp, size_t pixels,
                                    bench_record *rec)
{
    const bench_options *opt = &run->opt;
    uint32_t frames = opt->frames;
    const tl_frame_stats *st = &smp->last;
    rec->frame_ms = malloc(frames * sizeof *rec->frame_ms);
    if (rec->frame_ms) memcpy(rec->frame_ms, smp->gpu, frames * sizeof *rec->frame_ms);
    bench_median_p90(smp->gpu, frames, &rec->ms_median, &rec->ms_p90);
    bench_median_p90(smp->wall, frames, &rec->wall_ms_median, &rec->wall_ms_p90);
    double unused;
    bench_median_p90(smp->cpu, frames, &rec->cpu_ms_median, &unused);
    for (int p = 0; p < TL_PASS_COUNT; p++) bench_median_p90(smp->pass + p * frames, frames, &rec->pass_ms[p], &unused);
    for (int p = 0; p < TL_PASS_COUNT; p++) {
        rec->pass_bytes[p] = st->pass_bytes[p];
        rec->pass_fragments[p] = st->pass_fragments[p];
    }
    rec->bytes_moved = st->bytes_moved;
    for (int t = 0; t < TL_LIGHT_TYPE_COUNT_; t++) {
        rec->light_fragments[t] = st->light_fragments[t];
        rec->light_fragment_sum += st->light_fragments[t];
        rec->lights_drawn[t] = st->lights_drawn[t];
    }
    rec->forward_light_pairs = st->forward_light_pairs;
    rec->light_pairs = st->light_pairs;
    rec->draw_calls = st->draw_calls;
    rec->objects_drawn = st->objects_drawn;
    rec->relit_pixels = st->relit_pixels;
    rec->relit_fraction = st->relit_fraction;
    bench__plan_figures(&run->log, r, st, pixels, rec);
    rec->lighting_ms = rec->pass_ms[TL_PASS_LIGHT_CULL] + bench_light_pass_ms(rec->mode, rec->pass_ms);
}

/* The roofline of the last frame: its exact pairs counted, what the strategy evaluated, the ALU
 * probe's cost per pair on this device (the floor and the efficiency follow once every record has
 * probed: bench__roofline_finish). A figure that cannot be had is absent (NaN, null in the JSON)
 * after a warning, never guessed. */
static void bench__roofline(bench_run *run, tl_renderer *r, const tl_frame_stats *st, bench_record *rec)
{
    rec->evaluated_known = rec->strategy == TL_LIGHT_STRATEGY_TILED || rec->mode != TL_MODE_FORWARD;
    rec->evaluated_pairs = rec->strategy == TL_LIGHT_STRATEGY_TILED
                               ? st->light_pairs
                               : st->light_fragments[TL_LIGHT_POINT] + st->light_fragments[TL_LIGHT_SPOT];
    if (!rec->evaluated_known) rec->evaluated_pairs = 0;
    rec->probe_ns_own = rec->probe_ns_per_pair = rec->floor_ms = rec->light_efficiency = NAN;
    tl_light_pair_count count;
    tl_light_probe_result probe;
    char line[512];
    if (tl_renderer_count_light_pairs(r, &count) == TL_OK) {
        rec->pairs_counted = 1;
        rec->exact_pairs = count.exact_pairs;
        rec->covered_pixels = count.covered_pixels;
    } else {
        snprintf(line, sizeof line, "%s: no exact pairs: %s", bench_config_name(rec->config), tl_renderer_last_error(r));
        tl_tool_log_message(&run->log, TL_LOG_WARNING, line);
    }
    if (tl_renderer_light_probe(r, &probe) == TL_OK) {
        rec->probe_ns_own = probe.ns_per_pair;
    } else {
        snprintf(line, sizeof line, "%s: no light probe: %s", bench_config_name(rec->config), tl_renderer_last_error(r));
        tl_tool_log_message(&run->log, TL_LOG_WARNING, line);
    }
}

/* The probe's cost per pair of a record: the least of the run's probes at its size, light count and
 * lighting model (one per configuration's renderer; a busy machine only adds time, so the least is
 * the floor's best estimate), then the floor and the efficiency. */
static void bench__roofline_finish(bench_run *run)
{
    for (size_t i = 0; i < run->record_count; i++) {
        bench_record *rec = &run->records[i];
        double least = INFINITY;
        for (size_t k = 0; k < run->record_count; k++) {
            const bench_record *o = &run->records[k];
            if (o->lights == rec->lights && o->width == rec->width && o->height == rec->height &&
                o->lighting == rec->lighting && o->probe_ns_own < least)
                least = o->probe_ns_own;
        }
        rec->probe_ns_per_pair = isfinite(least) ? least : NAN;
        if (rec->pairs_counted && isfinite(rec->probe_ns_per_pair))
            rec->floor_ms = (double)rec->exact_pairs * rec->probe_ns_per_pair * 1e-6;
        if (rec->lighting_ms > 0.0 && isfinite(rec->floor_ms)) rec->light_efficiency = rec->floor_ms / rec->lighting_ms;
    }
}

/* Reads the frame's images (into the reference buffers for fat) and measures the error. */
static int bench__images(tl_renderer *r, bench_record *rec, bench__frame_buffers *fb)
{
    int ref = rec->mode == BENCH_REFERENCE;
    uint8_t *ldr = ref ? fb->ref_ldr : fb->ldr;
    float *hdr = ref ? fb->ref_hdr : fb->hdr;
    size_t n = fb->pixels;
    if (tl_renderer_read_output(r, ldr, &(size_t){n * 4}) != TL_OK ||
        tl_renderer_read_target(r, TL_TARGET_HDR, hdr, &(size_t){n * 4 * sizeof(float)}) != TL_OK) {
        tl_tool_fail(BENCH_TOOL, "%s: reading the images: %s", bench_config_name(rec->config),
                     tl_renderer_last_error(r));
        return 1;
    }
    bench__rgb_u8(ldr, n);
    uint64_t marked;
    rec->nan_pixels = bench__rgb_f32(hdr, n, &marked);
    rec->relit_fraction_marked = bench_config_scaled(rec->config) ? (double)marked / (double)n : 0.0;
    rec->hdr_peak = bench__peak(fb->ref_hdr, n * 3);
    tl_image_compare_u8(ldr, fb->ref_ldr, n * 3, &rec->ldr);
    tl_image_compare(hdr, fb->ref_hdr, n * 3, rec->hdr_peak, &rec->hdr);
    if (fb->edge_done) {
        rec->edge_pixels = fb->edge_count;
        bench_edges_compare(ldr, fb->ref_ldr, fb->edge, n, &rec->edge_ldr);
    }
    if (bench_config_scaled(rec->config)) { /* thin-lpp at scale 1 of the strategy came before it */
        rec->has_scale1 = 1;
        tl_image_compare_u8(ldr, fb->scale1_ldr, n * 3, &rec->scale1_ldr);
        if (fb->edge_done) bench_edges_compare(ldr, fb->scale1_ldr, fb->edge, n, &rec->edge_scale1_ldr);
    } else if (rec->mode == TL_MODE_THIN_LPP && !bench_config_variant_of(rec->config)) {
        memcpy(fb->scale1_ldr, ldr, n * 3);
    }
    return 0;
}

static bench_record *bench__append(bench_run *run)
{
    if (run->record_count == run->record_capacity) {
        size_t cap = run->record_capacity ? 2 * run->record_capacity : 64;
        bench_record *grown = realloc(run->records, cap * sizeof *grown);
        if (!grown) return NULL;
        run->records = grown;
        run->record_capacity = cap;
    }
    bench_record *rec = &run->records[run->record_count++];
    memset(rec, 0, sizeof *rec);
    return rec;
}

/* ---- the sweep ------------------------------------------------------------------------------ */

void bench_renderer_desc(bench_run *run, tl_context *ctx, tl_renderer_desc *d)
{
    d->get_proc_address = tl_context_proc_loader;
    d->get_proc_address_user = ctx;
    d->logger = tl_tool_log_logger(&run->log);
    tl_tool_budget_renderer(&run->opt.budgets, d);
}

tl_renderer *bench_renderer(bench_run *run, tl_context *ctx, size_t slot, tl_renderer_desc d, const tl_scene *scene)
{
    tl_renderer **r = &run->renderers[slot];
    if (!*r) {
        bench_renderer_desc(run, ctx, &d);
        if (tl_renderer_create(&d, r) != TL_OK) return NULL; /* the logger said why */
        if (tl_renderer_set_scene(*r, scene) == TL_OK) {
            if (!tl_tool_environment_set(BENCH_TOOL, &run->opt.env, *r)) return *r;
            tl_renderer_destroy(*r); /* the line is said */
            *r = NULL;
            return NULL;
        }
    } else if (tl_renderer_set_options(*r, &d.options) == TL_OK && tl_renderer_resize(*r, d.width, d.height) == TL_OK) {
        return *r;
    }
    tl_tool_log_error(&run->log, "%s", tl_renderer_last_error(*r));
    tl_renderer_destroy(*r);
    *r = NULL;
    return NULL;
}

void bench_renderers_close(bench_run *run)
{
    for (size_t i = 0; i < sizeof run->renderers / sizeof run->renderers[0]; i++) {
        tl_renderer_destroy(run->renderers[i]);
        run->renderers[i] = NULL;
    }
}

tl_renderer_desc bench_config_desc(const bench_options *o, bench_config c, uint32_t w, uint32_t h)
{
    tl_renderer_desc d = {.width = w, .height = h, .options = o->base};
    const tl_option_info *f;
    for (size_t i = 0; (f = tl_option_at(i)) != NULL; i++) /* the effects: measured one at a time */
        if (f->type == TL_OPTION_BOOL && strstr(f->name, ".enabled")) memset((char *)&d.options + f->offset, 0, f->size);
    d.options.mode = bench_config_mode(c);
    d.options.light_strategy = bench_config_strategy(c);
    d.options.light_format = bench_config_light_format(c);
    d.options.light_scale = bench_config_light_scale(c);
    d.options.fresnel = bench_config_fresnel(c, o->base.fresnel);
    d.options.tiled_shading = bench_config_tiled_shading(c, o->base.tiled_shading);
    d.options.synchronous_stats = 1;
    return d;
}

/* A configuration's renderer descriptor at one size, its HDR kept (without the context). */
static tl_renderer_desc bench__config_desc(const bench_run *run, bench_config c, bench_size size)
{
    tl_renderer_desc d = bench_config_desc(&run->opt, c, size.width, size.height);
    d.options.keep_targets |= TL_TARGET_BIT(TL_TARGET_HDR);
    tl_tool_budget_renderer(&run->opt.budgets, &d);
    return d;
}

/* The edge mask of a size (bench_edges.c) from the first fat configuration's renderer: one more
 * frame with its DEPTH and FAT_NORMAL targets kept, read back, then the renderer's own options
 * again, so the timed frames and the bytes it allocates are those of the plain configuration. */
static int bench__edge_probe(bench_run *run, tl_renderer *r, bench_config c, bench_size size,
                             bench__frame_buffers *fb)
{
    tl_renderer_desc d = bench__config_desc(run, c, size);
    tl_renderer_options o = d.options;
    o.keep_targets |= TL_TARGET_BIT(TL_TARGET_DEPTH) | TL_TARGET_BIT(TL_TARGET_FAT_NORMAL);
    size_t bytes = fb->pixels * 4 * sizeof(float);
    float *depth = malloc(bytes), *normal = malloc(bytes);
    int err = !depth || !normal;
    if (err) tl_tool_fail(BENCH_TOOL, "out of memory for the edge mask at %ux%u", size.width, size.height);
    else if (tl_renderer_set_options(r, &o) != TL_OK || tl_renderer_render(r, NULL, NULL) != TL_OK ||
             tl_renderer_read_target(r, TL_TARGET_DEPTH, depth, &(size_t){bytes}) != TL_OK ||
             tl_renderer_read_target(r, TL_TARGET_FAT_NORMAL, normal, &(size_t){bytes}) != TL_OK ||
             tl_renderer_set_options(r, &d.options) != TL_OK) {
        tl_tool_fail(BENCH_TOOL, "%s: the edge mask's depth and normals: %s", bench_config_name(c),
                     tl_renderer_last_error(r));
        err = 1;
    }
    if (!err) {
        fb->edge_count = bench_edges_mask(depth, normal, size.width, size.height, fb->edge);
        fb->edge_done = 1;
    }
    free(depth);
    free(normal);
    return err;
}

/* A size's renderers (those of the configurations held at once: a batch), its images and samples.
 * The fat images of a strategy are the references of the configurations after it: with every
 * configuration in one batch one slot serves each light count in turn; with several batches each
 * light count keeps its own. */
typedef struct bench__size_state {
    tl_renderer *renderers[BENCH_CONFIGS];
    bench__samples samples[BENCH_CONFIGS];
    double *sample_memory;
    bench__frame_buffers fb; /* ref_ldr, ref_hdr: `slots` images each */
    size_t slots;
} bench__size_state;

/* The batch's renderers stay the run's (bench_renderer): the next batch gives them its options. */
static void bench__batch_close(bench__size_state *s, size_t first, size_t count)
{
    for (size_t m = first; m < first + count; m++) s->renderers[m] = NULL;
}

static void bench__size_release(bench__size_state *s, size_t modes)
{
    bench__batch_close(s, 0, modes);
    free(s->fb.ldr);
    free(s->fb.ref_ldr);
    free(s->fb.hdr);
    free(s->fb.ref_hdr);
    free(s->fb.scale1_ldr);
    free(s->fb.edge);
    free(s->sample_memory);
    memset(s, 0, sizeof *s);
}

static int bench__size_setup(bench_run *run, bench_size size, size_t mode_count, size_t slots, bench__size_state *s)
{
    memset(s, 0, sizeof *s);
    size_t n = (size_t)size.width * size.height;
    s->slots = slots;
    s->fb.pixels = n;
    s->fb.ldr = malloc(n * 4);
    s->fb.ref_ldr = malloc(slots * n * 4);
    s->fb.hdr = malloc(n * 4 * sizeof(float));
    s->fb.ref_hdr = malloc(slots * n * 4 * sizeof(float));
    s->fb.scale1_ldr = malloc(slots * n * 4);
    s->fb.edge = malloc(n);
    size_t per_mode = (3 + TL_PASS_COUNT) * (size_t)run->opt.frames;
    s->sample_memory = malloc(mode_count * per_mode * sizeof(double));
    for (size_t m = 0; s->sample_memory && m < mode_count; m++) {
        bench__samples *smp = &s->samples[m];
        smp->gpu = s->sample_memory + m * per_mode;
        smp->wall = smp->gpu + run->opt.frames;
        smp->cpu = smp->wall + run->opt.frames;
        smp->pass = smp->cpu + run->opt.frames;
    }
    if (!s->fb.ldr || !s->fb.ref_ldr || !s->fb.hdr || !s->fb.ref_hdr || !s->fb.scale1_ldr || !s->fb.edge ||
        !s->sample_memory) {
        tl_tool_fail(BENCH_TOOL, "out of memory for %ux%u images", size.width, size.height);
        return 1;
    }
    return 0;
}

/* The renderers of modes[first, first + count): the run's first `count` renderers with these
 * configurations' options (made, with the scene, the first time). */
static int bench__batch_open(bench_run *run, tl_context *ctx, const tl_scene *scene, bench_size size,
                             const bench_config *modes, size_t first, size_t count, bench__size_state *s)
{
    for (size_t m = first; m < first + count; m++)
        if (!(s->renderers[m] = bench_renderer(run, ctx, m - first, bench__config_desc(run, modes[m], size), scene)))
            return 1;
    return 0;
}

static void bench__count_types(const tl_light *lights, size_t count, bench_record *rec)
{
    for (size_t i = 0; i < count; i++) {
        tl_light_type t = lights[i].type == TL_LIGHT_DEFAULT ? TL_LIGHT_POINT : lights[i].type;
        rec->point_lights += t == TL_LIGHT_POINT;
        rec->spot_lights += t == TL_LIGHT_SPOT;
        rec->directional_lights += t == TL_LIGHT_DIRECTIONAL;
    }
}

/* Where one light count's frames go: the records of every configuration at that count (in the
 * configurations' order) and the reference slot of the count. */
typedef struct bench__lights_job {
    bench_size size;
    uint32_t lights;
    size_t slot;
    bench_record *recs;
} bench__lights_job;

/* One light count at one size for the batch modes[first, first + count): their frames taking turns,
 * then each one's record. */
static int bench__sweep_lights(bench_run *run, bench__size_state *s, const bench_config *modes, size_t first,
                               size_t count, const bench__lights_job *job, bench_scene *scene,
                               tl_tool_progress *progress, uint64_t *done)
{
    const bench_options *opt = &run->opt;
    const tl_light *lights;
    size_t light_count;
    if (bench_scene_lights(scene, job->lights, &lights, &light_count)) return 1;
    for (size_t m = first; m < first + count; m++) {
        bench_record *rec = &job->recs[m];
        memset(rec, 0, sizeof *rec);
        rec->config = modes[m];
        rec->mode = bench_config_mode(modes[m]);
        rec->strategy = bench_config_strategy(modes[m]);
        rec->requested = bench_mode_requested(opt, rec->mode);
        rec->lights = job->lights;
        rec->width = job->size.width;
        rec->height = job->size.height;
        rec->frames = opt->frames;
        bench__count_types(lights, light_count, rec);
        if (tl_renderer_set_lights(s->renderers[m], lights, light_count) != TL_OK) {
            tl_tool_log_error(&run->log, "%s", tl_renderer_last_error(s->renderers[m]));
            return 1;
        }
    }
    uint32_t total = opt->warmup + opt->frames;
    char label[128];
    for (uint32_t f = 0; f < total; f++) {
        snprintf(label, sizeof label, "%ux%u, %u lights, frame %u/%u of %zu configuration%s", job->size.width,
                 job->size.height, job->lights, f + 1, total, count, count == 1 ? "" : "s");
        tl_tool_progress_update(progress, *done, label, f == 0);
        for (size_t m = first; m < first + count; m++, ++*done)
            if (bench__frame(run, s->renderers[m], &job->recs[m], &s->samples[m], f)) return 1;
    }
    bench__frame_buffers fb = s->fb; /* the reference images of this light count */
    fb.ref_ldr += job->slot * fb.pixels * 4;
    fb.ref_hdr += job->slot * fb.pixels * 4;
    fb.scale1_ldr += job->slot * fb.pixels * 4;
    for (size_t m = first; m < first + count; m++) {
        bench_record *rec = &job->recs[m];
        bench__summarise_frames(run, s->renderers[m], &s->samples[m], fb.pixels, rec);
        bench__roofline(run, s->renderers[m], &s->samples[m].last, rec);
        if (bench__images(s->renderers[m], rec, &fb)) return 1;
        if (m == 0 && !s->fb.edge_done) { /* the first fat: the size's edge mask, then its own edge error */
            if (bench__edge_probe(run, s->renderers[m], modes[m], job->size, &s->fb)) return 1;
            fb.edge_done = 1;
            fb.edge_count = s->fb.edge_count;
            rec->edge_pixels = fb.edge_count;
            bench_edges_compare(fb.ref_ldr, fb.ref_ldr, fb.edge, fb.pixels, &rec->edge_ldr);
            if (opt->out && bench_images_write_edges(run, rec, fb.ref_ldr, fb.edge)) return 1;
        }
        if (opt->out && job->lights == opt->lights[opt->light_count - 1] &&
            bench_images_write(run, rec, rec->mode == BENCH_REFERENCE ? fb.ref_ldr : fb.ldr, fb.ref_ldr,
                               rec->has_scale1 ? fb.scale1_ldr : NULL, 1, rec->mode != BENCH_REFERENCE))
            return 1;
    }
    return 0;
}

size_t bench_renderers_at_once(const bench_scene *scene)
{
    size_t bytes = bench_scene_bytes(scene), n = bytes ? BENCH_SCENE_COPIES_BYTES / bytes : BENCH_CONFIGS;
    return n ? n : 1;
}

/* Every configuration at one size, a batch of them at a time (bench_renderers_at_once), every light
 * count for each batch; the records land size-major, then lights, then configurations. */
static int bench__sweep_size(bench_run *run, tl_context *ctx, bench_scene *scene, bench_size size,
                             tl_tool_progress *progress, uint64_t *done)
{
    const bench_options *opt = &run->opt;
    bench_config modes[BENCH_CONFIGS];
    size_t mode_count = bench_render_modes(opt, modes), at_once = bench_renderers_at_once(scene);
    if (at_once > mode_count) at_once = mode_count;
    size_t first_record = run->record_count;
    for (size_t k = 0; k < opt->light_count * mode_count; k++)
        if (!bench__append(run)) {
            tl_tool_fail(BENCH_TOOL, "out of memory");
            return 1;
        }
    bench__size_state s;
    int err = bench__size_setup(run, size, mode_count, at_once == mode_count ? 1 : opt->light_count, &s);
    for (size_t first = 0; !err && first < mode_count; first += at_once) {
        size_t count = mode_count - first < at_once ? mode_count - first : at_once;
        err = bench__batch_open(run, ctx, bench_scene_get(scene), size, modes, first, count, &s);
        for (size_t li = 0; !err && li < opt->light_count; li++) {
            bench__lights_job job = {size, opt->lights[li], s.slots == 1 ? 0 : li,
                                     &run->records[first_record + li * mode_count]};
            err = bench__sweep_lights(run, &s, modes, first, count, &job, scene, progress, done);
        }
        bench__batch_close(&s, first, count);
    }
    bench__size_release(&s, mode_count);
    return err;
}

/* Refuses, before any GL work, a size whose targets are over the target-memory budget in some
 * configuration (one line naming both), and one whose renderers held at once and images would not
 * fit in this machine's memory (rather than being killed halfway): the plans of the largest batch,
 * the bench's own images (20 B/px, and 33 for the edge mask), and the references it keeps (24 B/px
 * each). */
static int bench__check_memory(const bench_run *run, const bench_scene *bs)
{
    const bench_options *opt = &run->opt;
    const tl_scene *scene = bench_scene_get(bs);
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    double available = pages > 0 && page > 0 ? (double)pages * (double)page * 0.75 : INFINITY;
    tl_scene_feature_set features;
    tl_scene_features(scene, &features);
    bench_config modes[BENCH_CONFIGS];
    size_t mode_count = bench_render_modes(opt, modes), at_once = bench_renderers_at_once(bs);
    if (at_once > mode_count) at_once = mode_count;
    size_t slots = at_once == mode_count ? 1 : opt->light_count;
    for (size_t si = 0; si < opt->size_count; si++) {
        bench_size size = opt->sizes[si];
        double batch = 0.0, largest = 0.0;
        for (size_t m = 0; m < mode_count; m++) {
            tl_frame_plan plan;
            tl_renderer_desc desc = bench__config_desc(run, modes[m], size);
            char what[64];
            snprintf(what, sizeof what, "%ux%u, %s", size.width, size.height, bench_config_name(modes[m]));
            if (tl_tool_budget_check(BENCH_TOOL, what, &desc, scene)) return 1;
            if (m % at_once == 0) batch = 0.0;
            if (tl_frame_plan_build(&desc, &features, &plan) == TL_OK) batch += plan.allocated_bytes_per_pixel;
            if (batch > largest) largest = batch;
        }
        /* the images 20 B/px, the edge mask 1 and, while it is made, fat's depth and normals 32; per
           reference slot fat's images 20 and thin-lpp's at scale 1 4 */
        double need = (largest + 20.0 + 1.0 + 32.0 + 24.0 * (double)slots) * size.width * size.height;
        if (need > available) {
            tl_tool_fail(BENCH_TOOL, "%ux%u needs about %.1f GiB for %zu renderers and the images, more than 3/4 of "
                                     "this machine's %.1f GiB",
                         size.width, size.height, need / 1073741824.0, at_once, available / 0.75 / 1073741824.0);
            return 1;
        }
    }
    return 0;
}

/* The frames of the renderers r[0..count) taking turns (which goes first alternates), after the
 * warm-up: ms[k * frames + f] (GPU timers, else the wall clock). */
static int bench__planning_frames(bench_run *run, tl_renderer **r, const char *name, size_t count, uint32_t n,
                                  double *ms, tl_tool_progress *progress, uint64_t *done)
{
    const bench_options *opt = &run->opt;
    uint32_t total = opt->warmup + opt->frames;
    char label[96];
    for (uint32_t f = 0; f < total; f++) {
        snprintf(label, sizeof label, "planning: %s, %u lights, frame %u/%u", name, n, f + 1, total);
        tl_tool_progress_update(progress, *done, label, f == 0);
        for (size_t j = 0; j < count; j++, ++*done) {
            size_t k = (f + j) % count;
            tl_frame_stats st;
            if (tl_renderer_render(r[k], NULL, &st) != TL_OK) {
                tl_tool_log_error(&run->log, "%s", tl_renderer_last_error(r[k]));
                return 1;
            }
            if (f < opt->warmup) continue;
            if (!(st.gpu_ms > 0.0)) run->timers_ok = 0;
            ms[k * opt->frames + (f - opt->warmup)] = st.gpu_ms > 0.0 ? st.gpu_ms : st.wall_ms;
        }
    }
    return 0;
}

/* What planning saves in time: each mode of run->planning rendered at the first size with the
 * largest light count by a planned renderer and by one with tl_renderer_options.planning off, the two
 * taking turns frame by frame when both fit beside each other (bench_renderers_at_once), else one
 * after the other, after the same warm-up; medians of the frame time. */
static int bench__planning_times(bench_run *run, tl_context *ctx, bench_scene *scene, tl_tool_progress *progress,
                                 uint64_t *done)
{
    const bench_options *opt = &run->opt;
    bench_size size = opt->sizes[0];
    uint32_t n = opt->lights[opt->light_count - 1];
    const tl_light *lights;
    size_t count, together = bench_renderers_at_once(scene) >= 2 ? 2 : 1;
    if (!run->planning_count) return 0;
    if (bench_scene_lights(scene, n, &lights, &count)) return 1;
    double *ms = malloc(2 * (size_t)opt->frames * sizeof *ms); /* planned, then unplanned */
    if (!ms) {
        tl_tool_fail(BENCH_TOOL, "out of memory");
        return 1;
    }
    int err = 0;
    for (size_t i = 0; !err && i < run->planning_count; i++) {
        bench_planning *p = &run->planning[i];
        const char *name = tl_render_mode_name(p->mode);
        for (size_t first = 0; !err && first < 2; first += together) {
            tl_renderer *r[2] = {NULL, NULL};
            for (size_t k = 0; !err && k < together; k++) {
                tl_renderer_desc desc = bench_config_desc(&run->opt, bench_config_make(p->mode, TL_LIGHT_STRATEGY_DEFAULT),
                                                          size.width, size.height);
                desc.options.planning = first + k ? TL_SWITCH_OFF : TL_SWITCH_DEFAULT;
                r[k] = bench_renderer(run, ctx, k, desc, bench_scene_get(scene));
                if (!r[k]) err = 1;
                else if (tl_renderer_set_lights(r[k], lights, count) != TL_OK) {
                    tl_tool_log_error(&run->log, "%s", tl_renderer_last_error(r[k]));
                    err = 1;
                }
            }
            if (!err) err = bench__planning_frames(run, r, name, together, n, ms + first * opt->frames, progress, done);
        }
        if (!err) {
            double unused;
            bench_median_p90(ms, opt->frames, &p->planned_ms, &unused);
            bench_median_p90(ms + opt->frames, opt->frames, &p->unplanned_ms, &unused);
        }
    }
    free(ms);
    return err;
}

int bench_sweep(bench_run *run, bench_scene *scene)
{
    const bench_options *opt = &run->opt;
    if (bench__check_memory(run, scene)) return 1;
    tl_context *ctx = NULL;
    if (tl_tool_context_open(BENCH_TOOL, &opt->context, 64, 64, &ctx)) return 1;
    snprintf(run->gl_renderer, sizeof run->gl_renderer, "%s", tl_context_renderer_string(ctx));
    snprintf(run->gl_version, sizeof run->gl_version, "%s", tl_context_version_string(ctx));
    snprintf(run->context, sizeof run->context, "%s", tl_context_backend_name(tl_context_get_backend(ctx)));
    snprintf(run->context_platform, sizeof run->context_platform, "%s", tl_context_platform_string(ctx));
    bench_config modes[BENCH_CONFIGS];
    uint64_t total = (uint64_t)opt->size_count * opt->light_count * bench_render_modes(opt, modes) *
                     (opt->warmup + opt->frames) +
                     (uint64_t)run->planning_count * 2 * (opt->warmup + opt->frames) + bench_effects_frames(opt) +
                     bench_aa_frames(run, scene) + bench_shadows_frames(opt);
    tl_tool_progress progress;
    tl_tool_progress_begin(&progress, total);
    run->timers_ok = 1;
    uint64_t done = 0;
    int err = 0;
    double t0 = tl_tool_now_ms();
    run->load_start = tl_tool_load_average();
    for (size_t si = 0; !err && si < opt->size_count; si++)
        err = bench__sweep_size(run, ctx, scene, opt->sizes[si], &progress, &done);
    if (!err) bench__roofline_finish(run);
    if (!err) err = bench__planning_times(run, ctx, scene, &progress, &done);
    if (!err) err = bench_effects_measure(run, ctx, scene, &progress, &done);
    if (!err) err = bench_aa_measure(run, ctx, scene, &progress, &done);
    if (!err) err = bench_shadows_measure(run, ctx, scene, &progress, &done);
    run->seconds = (tl_tool_now_ms() - t0) * 1e-3;
    run->load_end = tl_tool_load_average();
    tl_tool_progress_end(&progress);
    bench_renderers_close(run);
    tl_context_destroy(ctx);
    return err;
}
