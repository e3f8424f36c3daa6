/* What the sweep found, three ways: a one-screen table on stdout, the JSON records (docs/tools.md) and the generated section of docs/bandwidth.md. The summary lines are made once and
 * shared by the table and the doc. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "bench_shadows.h"
#include "thinlight/version.h"
#include "tool_util.h"

#define BENCH__STR2(x) #x
#define BENCH__STR(x) BENCH__STR2(x)
#define BENCH__LINE 2048

/* The summary's lines, as many as the sizes and configurations make (a fixed count once dropped
 * the last size's lines without a word); `lost` counts lines an allocation failure left out. */
typedef struct bench__summary {
    char (*lines)[BENCH__LINE];
    size_t count, capacity, lost;
} bench__summary;

static void bench__say(bench__summary *s, const char *fmt, ...) TL_TOOL_PRINTF(2, 3);
static void bench__say(bench__summary *s, const char *fmt, ...)
{
    if (s->count == s->capacity) {
        size_t cap = s->capacity ? 2 * s->capacity : 32;
        char(*grown)[BENCH__LINE] = realloc(s->lines, cap * sizeof *grown);
        if (!grown) {
            s->lost++;
            return;
        }
        s->lines = grown;
        s->capacity = cap;
    }
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(s->lines[s->count++], BENCH__LINE, fmt, ap);
    va_end(ap);
}

static void bench__summary_free(bench__summary *s)
{
    free(s->lines);
    *s = (bench__summary){0};
}

/* Appends to a line being built; a line that would not fit ends in "..." instead of being cut
 * without a sign. */
static void bench__add(char *line, const char *fmt, ...) TL_TOOL_PRINTF(2, 3);
static void bench__add(char *line, const char *fmt, ...)
{
    size_t n = strlen(line);
    if (n + 4 >= BENCH__LINE) return;
    va_list ap;
    va_start(ap, fmt);
    int w = vsnprintf(line + n, BENCH__LINE - n, fmt, ap);
    va_end(ap);
    if (w >= 0 && n + (size_t)w >= BENCH__LINE) memcpy(line + BENCH__LINE - 4, "...", 4);
}

/* The configuration the summary speaks for: thin-lpp when measured, else the first other mode;
 * tiled when measured, else the last strategy asked for. */
static bench_config bench__subject(const bench_options *opt)
{
    tl_render_mode mode = BENCH_REFERENCE;
    if (bench_mode_requested(opt, TL_MODE_THIN_LPP)) mode = TL_MODE_THIN_LPP;
    for (size_t i = 0; mode == BENCH_REFERENCE && i < opt->mode_count; i++)
        if (opt->modes[i] != BENCH_REFERENCE) mode = opt->modes[i];
    tl_light_strategy strategy = opt->strategies[opt->strategy_count - 1];
    for (size_t i = 0; i < opt->strategy_count; i++)
        if (opt->strategies[i] == TL_LIGHT_STRATEGY_TILED) strategy = TL_LIGHT_STRATEGY_TILED;
    return bench_config_make(mode, strategy);
}

static uint32_t bench__gbuffer_only_bpp(const bench_record *r)
{
    return r->gbuffer_bytes_per_pixel - bench_light_buffer_bpp(r);
}

/* "<subject> speed-up over <other>" at every count >= 64 (the largest alone when there is none);
 * `light_pass`: the ratio of the light passes (cull + shading) rather than of the frames. */
static void bench__speedup_line(const bench_run *run, bench__summary *s, const char *at, bench_size size,
                                bench_config subject, bench_config other, int light_pass)
{
    const bench_options *opt = &run->opt;
    uint32_t largest = opt->lights[opt->light_count - 1];
    char line[BENCH__LINE];
    if (light_pass)
        snprintf(line, sizeof line, "%s%s light pass (cull + shading) speed-up over %s's, ns per pixel-light pair in "
                 "brackets:", at, bench_config_name(subject), bench_config_name(other));
    else
        snprintf(line, sizeof line, "%s%s speed-up over %s (its frame time / %s's, median over frames):", at,
                 bench_config_name(subject), bench_config_name(other), bench_config_name(subject));
    int any = 0;
    for (size_t li = 0; li < opt->light_count; li++) {
        uint32_t n = opt->lights[li];
        if (n < 64 && n != largest) continue;
        const bench_record *a = bench_find(run, subject, n, size), *b = bench_find(run, other, n, size);
        if (!a || !b || !(a->ms_median > 0.0)) continue;
        if (!light_pass) {
            bench__add(line, "%s %.2fx at %u", any ? "," : "", bench_speedup(a, b), n);
        } else if (a->lighting_ms > 0.0) {
            bench__add(line, "%s %.2fx at %u (%.1f vs %.1f)", any ? "," : "", b->lighting_ms / a->lighting_ms, n,
                       bench_ns_per_pair(a), bench_ns_per_pair(b));
        } else {
            continue;
        }
        any = 1;
    }
    if (any) bench__say(s, "%s lights", line);
}

/* The fastest thin (thin-lpp, thin-deferred) and fat configurations at a light count. visibility
 * and forward are no thin G-buffer: they are set against these apart (bench__visibility_lines). */
static void bench__fastest(const bench_run *run, bench_size size, const bench_config *modes, size_t mode_count,
                           uint32_t n, const bench_record **thin, const bench_record **fat)
{
    *thin = *fat = NULL;
    for (size_t m = 0; m < mode_count; m++) {
        const bench_record *r = bench_find(run, modes[m], n, size);
        if (!r || !(r->ms_median > 0.0)) continue;
        int is_thin = r->mode == TL_MODE_THIN_LPP || r->mode == TL_MODE_THIN_DEFERRED;
        if (is_thin && (!*thin || r->ms_median < (*thin)->ms_median)) *thin = r;
        if (r->mode == TL_MODE_FAT && (!*fat || r->ms_median < (*fat)->ms_median)) *fat = r;
    }
}

/* The light passes' name in the summary: cull + shading (visibility's shading pass, vis-resolve,
 * also evaluates the materials, as forward's does). */
static const char *bench__light_pass_name(const bench_record *r)
{
    return r->mode == TL_MODE_VISIBILITY ? "light pass (light-cull + vis-resolve)" : "light pass (cull + shading)";
}

/* Which pass of a frame takes the most of it (the light passes, cull + shading, counted as one):
 * its name and share. */
static const char *bench__dominant_pass(const bench_record *r, double *share)
{
    const char *name = bench__light_pass_name(r);
    double most = r->lighting_ms;
    for (int p = 0; p < TL_PASS_COUNT; p++) {
        if (!(r->passes & BENCH_PASS_BIT(p)) || p == TL_PASS_LIGHT_CULL || p == TL_PASS_LIGHTS || p == TL_PASS_LIGHTS_TILED ||
            (r->mode == TL_MODE_FORWARD && p == TL_PASS_FORWARD) || (r->mode == TL_MODE_VISIBILITY && p == TL_PASS_VIS_RESOLVE))
            continue;
        if (r->pass_ms[p] > most) most = r->pass_ms[p], name = tl_pass_name((tl_pass)p);
    }
    *share = r->ms_median > 0.0 ? most / r->ms_median : NAN;
    return name;
}

/* The fastest thin configuration against the fastest fat one at every light count, then which pass
 * dominates the fastest thin frame at the largest count on this machine, and the light pass's
 * efficiency there (the roofline). */
static void bench__fastest_line(const bench_run *run, bench__summary *s, const char *at, bench_size size,
                                const bench_config *modes, size_t mode_count)
{
    const bench_options *opt = &run->opt;
    char line[BENCH__LINE];
    snprintf(line, sizeof line, "%sfastest thin configuration over the fastest fat one (frame time):", at);
    int any = 0;
    const bench_record *thin = NULL, *fat = NULL;
    for (size_t li = 0; li < opt->light_count; li++) {
        uint32_t n = opt->lights[li];
        bench__fastest(run, size, modes, mode_count, n, &thin, &fat);
        if (!thin || !fat) continue;
        bench__add(line, "%s %s over %s %.2fx at %u", any ? "," : "", bench_config_name(thin->config),
                   bench_config_name(fat->config), bench_speedup(thin, fat), n);
        any = 1;
    }
    if (!any) return;
    bench__say(s, "%s lights", line);
    if (!thin) return;
    double share, light_share = thin->ms_median > 0.0 ? thin->lighting_ms / thin->ms_median : NAN;
    char name[64];
    const char *pass = bench__dominant_pass(thin, &share);
    snprintf(name, sizeof name, "%s%s", pass, strstr(pass, "pass") ? "" : " pass");
    char light[48] = "";
    if (strcmp(pass, bench__light_pass_name(thin)) != 0)
        snprintf(light, sizeof light, "; the light pass %.0f %%", 100.0 * light_share);
    bench__say(s, "%sthe %s is %.0f %% of the fastest thin frame on this machine (%s, %u lights, %.2f ms%s)", at,
               name, 100.0 * share, bench_config_name(thin->config), thin->lights, thin->ms_median, light);
    if (fat && isfinite(thin->light_efficiency) && isfinite(fat->light_efficiency))
        bench__say(s,
                   "%slight efficiency (floor / light ms, the roofline table) at %u lights: %s %.2f, %s %.2f",
                   at, thin->lights, bench_config_name(thin->config), thin->light_efficiency,
                   bench_config_name(fat->config), fat->light_efficiency);
}

/* visibility is no thin G-buffer: depth and a 32-bit triangle id per pixel, the materials and the
 * lights evaluated in vis-resolve from the rebuilt triangle (docs/frame.md, "Visibility buffer"), so
 * the "fastest thin" line leaves it out and it is set apart here: its frame against the fastest fat
 * and the fastest thin configuration of each light count (the median of per-frame ratios, as every
 * speed-up), the memory it allocates beside thin-lpp's and fat's of its strategy group, and where
 * its frame's time goes at the largest light count. */
static void bench__visibility_lines(const bench_run *run, bench__summary *s, const char *at, bench_size size,
                                    const bench_config *modes, size_t mode_count)
{
    const bench_options *opt = &run->opt;
    bench_config vis = bench_config_make(TL_MODE_VISIBILITY, TL_LIGHT_STRATEGY_TILED);
    tl_light_strategy group = opt->strategies[bench_visibility_group(opt)];
    const char *vname = bench_config_name(vis);
    char line[BENCH__LINE];
    snprintf(line, sizeof line,
             "%s%s (not a thin G-buffer: depth + a 32-bit triangle id, materials and lights in vis-resolve; "
             "compared apart) over the fastest fat and the fastest thin configuration (frame time):",
             at, vname);
    int any = 0;
    const bench_record *last = NULL;
    for (size_t li = 0; li < opt->light_count; li++) {
        uint32_t n = opt->lights[li];
        const bench_record *v = bench_find(run, vis, n, size), *thin, *fat;
        if (!v || !(v->ms_median > 0.0)) continue;
        last = v;
        bench__fastest(run, size, modes, mode_count, n, &thin, &fat);
        if (!thin && !fat) continue;
        bench__add(line, "%s", any ? ";" : "");
        if (fat) bench__add(line, " %.2fx over %s", bench_speedup(v, fat), bench_config_name(fat->config));
        if (thin) bench__add(line, "%s %.2fx over %s", fat ? "," : "", bench_speedup(v, thin), bench_config_name(thin->config));
        bench__add(line, " at %u", n);
        any = 1;
    }
    if (any) bench__say(s, "%s lights", line);
    if (!last) return;
    const bench_record *lpp = bench_find(run, bench_config_make(TL_MODE_THIN_LPP, group), last->lights, size),
                       *fat = bench_find(run, bench_config_make(BENCH_REFERENCE, group), last->lights, size);
    snprintf(line, sizeof line,
             "%s%s allocates %u B/px (sum %u; depth %u + vis.id %u, vis.tiles %u, light.lists %u)", at, vname,
             last->bytes_per_pixel, last->bytes_per_pixel_sum, last->target_bpp[TL_TARGET_DEPTH],
             last->target_bpp[TL_TARGET_VIS_ID], last->target_bpp[TL_TARGET_VIS_TILES],
             last->target_bpp[TL_TARGET_LIGHT_LISTS]);
    if (lpp)
        bench__add(line, " against %s's %u (depth %u + RT0 %u + light buffer %u)", bench_config_name(lpp->config),
                   lpp->bytes_per_pixel, lpp->target_bpp[TL_TARGET_DEPTH], lpp->target_bpp[TL_TARGET_RT0],
                   bench_light_buffer_bpp(lpp));
    if (fat)
        bench__add(line, "%s %s's %u (depth + G-buffer %u)", lpp ? " and" : " against", bench_config_name(fat->config),
                   fat->bytes_per_pixel, bench__gbuffer_only_bpp(fat));
    bench__add(line, "; it moves %.1f MiB a frame by the estimate", last->bytes_moved / 1048576.0);
    if (lpp) bench__add(line, " (%s %.1f)", bench_config_name(lpp->config), lpp->bytes_moved / 1048576.0);
    /* a library whose estimate counts bytes per fragment of a samples-passed query counts none for a
       compute pass: said rather than left to read as free */
    if ((last->passes & BENCH_PASS_BIT(TL_PASS_VIS_RESOLVE)) && last->pass_bytes[TL_PASS_VIS_RESOLVE] <= 0.0)
        bench__add(line, ", which counts nothing for its compute passes (vis-classify, vis-resolve)");
    bench__say(s, "%s", line);
    if (!(last->ms_median > 0.0)) return;
    snprintf(line, sizeof line, "%swhere %s's frame goes at %u lights (%.2f ms):", at, vname, last->lights,
             last->ms_median);
    static const tl_pass order[] = {TL_PASS_GBUFFER, TL_PASS_LIGHT_CULL, TL_PASS_VIS_CLASSIFY, TL_PASS_VIS_RESOLVE};
    double rest = last->ms_median;
    for (size_t k = 0; k < sizeof order / sizeof order[0]; k++) {
        if (!(last->passes & BENCH_PASS_BIT(order[k]))) continue;
        bench__add(line, "%s %s %.0f %%", k ? "," : "", tl_pass_name(order[k]), 100.0 * last->pass_ms[order[k]] / last->ms_median);
        rest -= last->pass_ms[order[k]];
    }
    bench__add(line, ", the other passes %.0f %%", 100.0 * (rest > 0.0 ? rest : 0.0) / last->ms_median);
    bench__say(s, "%s", line);
}

static void bench__scale_lines(const bench_run *run, bench__summary *s, const char *at, bench_size size);

static void bench__summarise(const bench_run *run, bench__summary *s)
{
    const bench_options *opt = &run->opt;
    bench_config subject = bench__subject(opt), ref = bench_reference_of(subject);
    const char *sname = bench_config_name(subject);
    uint32_t largest = opt->lights[opt->light_count - 1];
    bench_config modes[BENCH_CONFIGS];
    size_t mode_count = bench_render_modes(opt, modes);
    for (size_t si = 0; si < opt->size_count; si++) {
        bench_size size = opt->sizes[si];
        char at[32] = "";
        if (opt->size_count > 1) snprintf(at, sizeof at, "%ux%u: ", size.width, size.height);
        const bench_record *fat = bench_find(run, ref, largest, size);
        const bench_record *sub = bench_find(run, subject, largest, size);
        if (!fat || !sub) continue;
        if (subject != ref && fat->gbuffer_bytes_per_pixel)
            bench__say(s,
                       "%s%s stores %u B/px in depth + G-buffer + light buffer = %.0f%% of fat's %u B/px "
                       "(depth + G-buffer alone: %u vs %u B/px = %.0f%%); all targets allocate %u vs %u B/px "
                       "(sums %u vs %u: targets with disjoint lifetimes share memory)",
                       at, sname, sub->gbuffer_bytes_per_pixel,
                       100.0 * sub->gbuffer_bytes_per_pixel / fat->gbuffer_bytes_per_pixel,
                       fat->gbuffer_bytes_per_pixel, bench__gbuffer_only_bpp(sub), bench__gbuffer_only_bpp(fat),
                       bench__gbuffer_only_bpp(fat) ? 100.0 * bench__gbuffer_only_bpp(sub) / bench__gbuffer_only_bpp(fat) : 0.0,
                       sub->bytes_per_pixel, fat->bytes_per_pixel, sub->bytes_per_pixel_sum, fat->bytes_per_pixel_sum);
        /* against fat, forward, forward+ and the subject's mode with the other strategies (not in
         * --quick, whose few configurations would set the subject against fat's slowest strategy) */
        for (size_t m = 0; !opt->quick && subject != ref && m < mode_count; m++) {
            tl_render_mode om = bench_config_mode(modes[m]);
            if (modes[m] == subject || (om != BENCH_REFERENCE && om != TL_MODE_FORWARD && om != TL_MODE_VISIBILITY &&
                                        om != bench_config_mode(subject)))
                continue;
            bench__speedup_line(run, s, at, size, subject, modes[m], 0);
            if (om == bench_config_mode(subject)) bench__speedup_line(run, s, at, size, subject, modes[m], 1);
        }
        bench__fastest_line(run, s, at, size, modes, mode_count);
        bench__visibility_lines(run, s, at, size, modes, mode_count);
        bench__scale_lines(run, s, at, size);
        /* the worst image quality of each configuration */
        char line[BENCH__LINE];
        snprintf(line, sizeof line, "%slowest PSNR of the final image against fat (same strategy):", at);
        int any = 0;
        uint64_t nans = 0;
        for (size_t m = 0; m < mode_count; m++) {
            const bench_record *worst = NULL;
            for (size_t li = 0; li < opt->light_count; li++) {
                const bench_record *r = bench_find(run, modes[m], opt->lights[li], size);
                if (!r) continue;
                nans += r->nan_pixels;
                if (r->mode != BENCH_REFERENCE && (!worst || r->ldr.psnr_db < worst->ldr.psnr_db)) worst = r;
            }
            if (!worst) continue;
            bench__add(line, "%s %s %.1f dB (max error %.0f steps, at %u lights)", any ? ";" : "",
                       bench_config_name(modes[m]), worst->ldr.psnr_db, worst->ldr.max_abs, worst->lights);
            any = 1;
        }
        if (any) bench__say(s, "%s", line);
        bench__say(s, "%s%s", at, nans ? "NaN or Inf pixels in some HDR image: see the NaN column"
                                       : "no NaN or Inf in any mode's HDR image");
    }
}

static void bench__planning(const bench_run *run, bench__summary *s)
{
    char line[BENCH__LINE];
    snprintf(line, sizeof line,
             "what planning saves (the plan against planning off, %u lights; ms: median frame at %ux%u):",
             run->opt.lights[run->opt.light_count - 1], run->opt.sizes[0].width, run->opt.sizes[0].height);
    for (size_t i = 0; i < run->planning_count; i++) {
        const bench_planning *p = &run->planning[i];
        bench__add(line, "%s %s %u of %u B/px, %zu of %zu programs", i ? ";" : "", tl_render_mode_name(p->mode),
                   p->bytes_per_pixel, p->unplanned_bytes_per_pixel, p->programs, p->unplanned_programs);
        if (isfinite(p->planned_ms) && isfinite(p->unplanned_ms))
            bench__add(line, ", %.1f of %.1f ms", p->planned_ms, p->unplanned_ms);
    }
    if (run->planning_count) bench__say(s, "%s", line);
}

static void bench__outputs(const bench_run *run, bench__summary *s)
{
    const bench_options *opt = &run->opt;
    if (opt->json) bench__say(s, "JSON records: %s", opt->json);
    if (opt->out) {
        size_t count[BENCH_IMAGE_KINDS] = {0};
        for (size_t i = 0; i < run->image_count; i++) count[run->images[i].kind]++;
        bench__say(s,
                   "images in %s: %zu final images, %zu heat maps of |mode - fat| and %zu of |light-scale variant - "
                   "thin-lpp at scale 1| at %u lights (bench_heat_*_vs_fat_*, bench_heat_*_vs_scale1_*: largest RGB "
                   "difference, 0 to %u 8-bit steps on a square-root ramp)",
                   opt->out, count[BENCH_IMAGE_FINAL], count[BENCH_IMAGE_HEAT], count[BENCH_IMAGE_HEAT_SCALE1],
                   opt->lights[opt->light_count - 1], BENCH_HEAT_SCALE);
        if (run->plots_made)
            bench__say(s, "plots: %s/{%s,%s,%s}.png", opt->out, bench_plot_names[0], bench_plot_names[1],
                       bench_plot_names[2]);
    }
}

/* ---- the light scales --------------------------------------------------------------------------- */

static void bench__fmt(char *buf, size_t size, const char *fmt, double v);

/* The configurations of the light-scale comparison: the first strategy's fat (the reference),
 * thin-lpp at scale 1 and its variants at 1/2 and 1/4, those measured; 0 when no variant is. */
static size_t bench__scale_configs(const bench_options *opt, bench_config *out)
{
    bench_config modes[BENCH_CONFIGS];
    size_t mode_count = bench_render_modes(opt, modes), n = 0, scaled = 0;
    bench_config lpp = bench_config_make(TL_MODE_THIN_LPP, opt->strategies[0]);
    for (size_t m = 0; m < mode_count; m++) {
        int is_scaled = bench_config_scaled(modes[m]);
        if (m == 0 || modes[m] == lpp || is_scaled) out[n++] = modes[m];
        scaled += is_scaled;
    }
    return scaled ? n : 0;
}

/* "46.1/104": PSNR and max error, or "-" when not measured (or the reference itself). */
static void bench__err_cell(char *buf, size_t size, const tl_image_error *e, int measured)
{
    if (!measured) snprintf(buf, size, "-");
    else snprintf(buf, size, "%.1f/%.0f", e->psnr_db, e->max_abs);
}

typedef struct bench__scale_cells {
    char fat[24], edge_fat[24], s1[24], edge_s1[24], relit[16], reduce[16], upsample[16], material[16];
} bench__scale_cells;

static void bench__scale_row(const bench_record *r, bench__scale_cells *c)
{
    int ref = r->mode == BENCH_REFERENCE, scaled = bench_config_scaled(r->config);
    bench__fmt(c->reduce, sizeof c->reduce, "%.2f",
               r->passes & BENCH_PASS_BIT(TL_PASS_LIGHT_REDUCE) ? r->pass_ms[TL_PASS_LIGHT_REDUCE] : NAN);
    bench__fmt(c->upsample, sizeof c->upsample, "%.2f",
               r->passes & BENCH_PASS_BIT(TL_PASS_LIGHT_UPSAMPLE) ? r->pass_ms[TL_PASS_LIGHT_UPSAMPLE] : NAN);
    bench__fmt(c->material, sizeof c->material, "%.2f",
               r->passes & BENCH_PASS_BIT(TL_PASS_MATERIAL) ? r->pass_ms[TL_PASS_MATERIAL] : NAN);
    bench__err_cell(c->fat, sizeof c->fat, &r->ldr, !ref);
    bench__err_cell(c->edge_fat, sizeof c->edge_fat, &r->edge_ldr, !ref && r->edge_pixels);
    bench__err_cell(c->s1, sizeof c->s1, &r->scale1_ldr, r->has_scale1);
    bench__err_cell(c->edge_s1, sizeof c->edge_s1, &r->edge_scale1_ldr, r->has_scale1 && r->edge_pixels);
    if (scaled) snprintf(c->relit, sizeof c->relit, "%.2f", 100.0 * r->relit_fraction);
    else snprintf(c->relit, sizeof c->relit, "-");
}

static const char bench__scale_caption[] =
    "error of the final image against fat at full resolution and against thin-lpp at light scale 1, over "
    "the whole frame and over the edge pixels alone (within " BENCH__STR(BENCH_EDGE_RADIUS) " pixels of a depth "
    "discontinuity or a normal crease of fat's frame), as PSNR dB / max error in 8-bit steps; ms: GPU time, "
    "median; reduce, light, upsample, material: those passes' ms (light: cull + lights; upsample: light-upsample, "
    "which also re-lights the edge pixels); re-lit %: tl_frame_stats.relit_fraction";

static void bench__print_scales(const bench_run *run, bench_size size)
{
    const bench_options *opt = &run->opt;
    bench_config cfg[BENCH_CONFIGS];
    size_t n = bench__scale_configs(opt, cfg);
    if (!n) return;
    const bench_record *any = bench_find(run, cfg[0], opt->lights[0], size);
    printf("\nlight scales at %ux%u (edge pixels: %.1f %% of the frame): %s\n", size.width, size.height,
           any && any->edge_pixels ? 100.0 * (double)any->edge_pixels / ((double)size.width * size.height) : 0.0,
           bench__scale_caption);
    printf("%-27s %6s %8s %7s %8s %8s %8s %5s %7s %11s %11s %11s %11s\n", "config", "lights", "ms med", "reduce",
           "light", "upsample", "material", "B/px", "re-lit%", "vs fat", "edge fat", "vs scale 1", "edge s1");
    for (size_t li = 0; li < opt->light_count; li++) {
        if (li) putchar('\n');
        for (size_t m = 0; m < n; m++) {
            const bench_record *r = bench_find(run, cfg[m], opt->lights[li], size);
            if (!r) continue;
            bench__scale_cells c;
            bench__scale_row(r, &c);
            printf("%-27s %6u %8.2f %7s %8.2f %8s %8s %5u %7s %11s %11s %11s %11s\n", bench_config_name(r->config),
                   r->lights, r->ms_median, c.reduce, r->lighting_ms, c.upsample, c.material, r->bytes_per_pixel,
                   c.relit, c.fat, c.edge_fat, c.s1, c.edge_s1);
        }
    }
}

static void bench__md_scales(FILE *f, const bench_run *run, bench_size size)
{
    const bench_options *opt = &run->opt;
    bench_config cfg[BENCH_CONFIGS];
    size_t n = bench__scale_configs(opt, cfg);
    if (!n) return;
    fprintf(f, "\n#### Light scales, %ux%u\n\nThin-lpp with its light buffer at 1/2 and 1/4 per axis: %s.\n\n",
            size.width, size.height, bench__scale_caption);
    fputs("| config | lights | ms median | reduce ms | light ms | upsample ms | material ms | B/px | re-lit % | "
          "vs fat | edge vs fat | vs scale 1 | edge vs scale 1 |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
          "---:|---:|\n",
          f);
    for (size_t li = 0; li < opt->light_count; li++)
        for (size_t m = 0; m < n; m++) {
            const bench_record *r = bench_find(run, cfg[m], opt->lights[li], size);
            if (!r) continue;
            bench__scale_cells c;
            bench__scale_row(r, &c);
            fprintf(f, "| `%s` | %u | %.2f | %s | %.2f | %s | %s | %u | %s | %s | %s | %s | %s |\n",
                    bench_config_name(r->config), r->lights, r->ms_median, c.reduce, r->lighting_ms, c.upsample,
                    c.material, r->bytes_per_pixel, c.relit, c.fat, c.edge_fat, c.s1, c.edge_s1);
        }
}

/* Per light-scale variant: its speed-up over the fastest fat of the same light count and the "no
 * halo" check (its largest edge error against fat over twice thin-lpp's at scale 1). */
static void bench__scale_lines(const bench_run *run, bench__summary *s, const char *at, bench_size size)
{
    const bench_options *opt = &run->opt;
    bench_config cfg[BENCH_CONFIGS], modes[BENCH_CONFIGS];
    size_t n = bench__scale_configs(opt, cfg), mode_count = bench_render_modes(opt, modes);
    for (size_t k = 0; k < n; k++) {
        if (!bench_config_scaled(cfg[k])) continue;
        char line[BENCH__LINE];
        snprintf(line, sizeof line, "%s%s: over the fastest fat, PSNR against fat, edge max error against twice "
                 "scale 1's (no halo):", at, bench_config_name(cfg[k]));
        int any = 0;
        for (size_t li = 0; li < opt->light_count; li++) {
            uint32_t lights = opt->lights[li];
            const bench_record *r = bench_find(run, cfg[k], lights, size),
                               *one = bench_find(run, bench_config_scale1(cfg[k]), lights, size), *fat = NULL;
            for (size_t m = 0; m < mode_count; m++) {
                const bench_record *q = bench_find(run, modes[m], lights, size);
                if (q && q->mode == TL_MODE_FAT && q->ms_median > 0.0 && (!fat || q->ms_median < fat->ms_median)) fat = q;
            }
            if (!r || !one || !fat || !r->edge_pixels) continue;
            double bound = 2.0 * one->edge_ldr.max_abs;
            bench__add(line, "%s %.2fx, %.1f dB, %.0f %s %.0f at %u", any ? ";" : "", bench_speedup(r, fat),
                       r->ldr.psnr_db, r->edge_ldr.max_abs, r->edge_ldr.max_abs <= bound ? "<=" : ">", bound, lights);
            any = 1;
        }
        if (any) bench__say(s, "%s lights", line);
    }
}

/* ---- the roofline ------------------------------------------------------------------------------ */

static const char bench__roofline_caption[] =
    "local lights only, at the grid the light pass shades; exact: pixel-light pairs in range (and cone), "
    "counted on the CPU from the depth the light pass read; evaluated: the pairs the strategy evaluated "
    "(tiles: each list entry over the pixels of its blocks; volumes: fragments past the range test; forward's per-object "
    "lists: -), over exact in brackets; probe: the ALU probe's ns per pair on this device (the least of the "
    "run's probes at this size, light count and lighting model); floor = exact x "
    "probe; efficiency = floor / light ms; covered: pixels with a local light in range";

typedef struct bench__roofline_cells {
    char exact[16], evaluated[32], probe[16], floor[16], eff[16], covered[16];
} bench__roofline_cells;

static void bench__roofline_row(const bench_record *r, bench__roofline_cells *c)
{
    bench__fmt(c->exact, sizeof c->exact, "%.3f", r->pairs_counted ? (double)r->exact_pairs * 1e-6 : NAN);
    if (!r->evaluated_known) snprintf(c->evaluated, sizeof c->evaluated, "-");
    else if (r->pairs_counted && r->exact_pairs)
        snprintf(c->evaluated, sizeof c->evaluated, "%.3f (%.2fx)", (double)r->evaluated_pairs * 1e-6,
                 (double)r->evaluated_pairs / (double)r->exact_pairs);
    else snprintf(c->evaluated, sizeof c->evaluated, "%.3f", (double)r->evaluated_pairs * 1e-6);
    bench__fmt(c->probe, sizeof c->probe, "%.3f", r->probe_ns_per_pair);
    bench__fmt(c->floor, sizeof c->floor, "%.2f", r->floor_ms);
    bench__fmt(c->eff, sizeof c->eff, "%.3f", r->light_efficiency);
    bench__fmt(c->covered, sizeof c->covered, "%.0f", r->pairs_counted ? (double)r->covered_pixels : NAN);
}

static void bench__print_roofline(const bench_run *run, bench_size size)
{
    const bench_options *opt = &run->opt;
    bench_config modes[BENCH_CONFIGS];
    size_t mode_count = bench_render_modes(opt, modes);
    printf("\nroofline at %ux%u: %s\n", size.width, size.height, bench__roofline_caption);
    printf("%-27s %6s %8s %9s %16s %8s %8s %6s %9s\n", "config", "lights", "light ms", "exact M", "evaluated M",
           "probe ns", "floor ms", "eff", "covered");
    for (size_t m = 0; m < mode_count; m++) {
        if (m) putchar('\n');
        for (size_t li = 0; li < opt->light_count; li++) {
            const bench_record *r = bench_find(run, modes[m], opt->lights[li], size);
            if (!r) continue;
            bench__roofline_cells c;
            bench__roofline_row(r, &c);
            printf("%-27s %6u %8.2f %9s %16s %8s %8s %6s %9s\n", bench_config_name(r->config), r->lights, r->lighting_ms,
                   c.exact, c.evaluated, c.probe, c.floor, c.eff, c.covered);
        }
    }
}

static void bench__md_roofline(FILE *f, const bench_run *run, bench_size size)
{
    const bench_options *opt = &run->opt;
    bench_config modes[BENCH_CONFIGS];
    size_t mode_count = bench_render_modes(opt, modes);
    fprintf(f, "\n#### Roofline, %ux%u\n\nThe light pass against its floor: %s.\n\n", size.width, size.height,
            bench__roofline_caption);
    fputs("| config | lights | light ms | exact Mpairs | evaluated Mpairs (x exact) | probe ns / pair | floor ms | "
          "efficiency | covered px |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
          f);
    for (size_t m = 0; m < mode_count; m++)
        for (size_t li = 0; li < opt->light_count; li++) {
            const bench_record *r = bench_find(run, modes[m], opt->lights[li], size);
            if (!r) continue;
            bench__roofline_cells c;
            bench__roofline_row(r, &c);
            fprintf(f, "| `%s` | %u | %.2f | %s | %s | %s | %s | %s | %s |\n", bench_config_name(r->config), r->lights,
                    r->lighting_ms, c.exact, c.evaluated, c.probe, c.floor, c.eff, c.covered);
        }
}

/* ---- stdout --------------------------------------------------------------------------------- */

static void bench__fmt(char *buf, size_t size, const char *fmt, double v)
{
    if (isfinite(v)) snprintf(buf, size, fmt, v);
    else snprintf(buf, size, "-");
}

void bench_print_table(const bench_run *run)
{
    const bench_options *opt = &run->opt;
    bench_config modes[BENCH_CONFIGS];
    size_t mode_count = bench_render_modes(opt, modes);
    char sizes[160] = "";
    for (size_t si = 0; si < opt->size_count; si++)
        snprintf(sizes + strlen(sizes), sizeof sizes - strlen(sizes), "%s%ux%u", si ? ", " : "", opt->sizes[si].width,
                 opt->sizes[si].height);
    printf("thinlight-bench %s: %s (%zu triangles, %zu objects) at %s, %u timed frames after %u warm-up, seed %llu\n",
           tl_version_string(), run->scene_name, run->scene_triangles, run->scene_objects, sizes, opt->frames,
           opt->warmup, (unsigned long long)opt->seed);
    printf("GL: %s, %s (context %s: %s); CPU: %s, %zu cores, load average %.1f before, %.1f after; sweep took "
           "%.0f s\n",
           run->gl_renderer, run->gl_version, run->context, run->context_platform, run->cpu, run->cores, run->load_start, run->load_end, run->seconds);
    printf("%s\n", run->light_definition);
    printf("ms = %s per frame (median, p90); light ms = the passes that apply the lights (light-cull + lights,\n"
           "lights-tiled, forward or vis-resolve); ns/pair = light ms per pixel-light pair shaded;\n"
           "B/px = memory the targets occupy (shared where lifetimes allow; sum = as if each had its own);\n"
           "MiB moved = the renderer's bytes-moved estimate per frame;\n"
           "PSNR and max err (8-bit steps) of the final image against fat of the same frame; NaN = HDR pixels\n",
           run->timers_ok ? "GPU time (timer queries)" : "wall clock (no GPU timers)");
    for (size_t si = 0; si < opt->size_count; si++) {
        bench_size size = opt->sizes[si];
        printf("\n%ux%u\n%-26s %6s %8s %8s %8s %7s %5s %4s %9s %9s %7s %7s %4s\n", size.width, size.height, "mode",
               "lights", "ms med", "ms p90", "light ms", "ns/pair", "B/px", "sum", "MiB@1080p", "MiB moved", "PSNR dB",
               "max err", "NaN");
        for (size_t m = 0; m < mode_count; m++) {
            if (m) putchar('\n');
            for (size_t li = 0; li < opt->light_count; li++) {
                const bench_record *r = bench_find(run, modes[m], opt->lights[li], size);
                if (!r) continue;
                char label[48], pl[16], cov[16], psnr[16], maxe[16];
                snprintf(label, sizeof label, "%s%s", bench_config_name(r->config),
                         r->mode == BENCH_REFERENCE ? " (ref)" : "");
                bench__fmt(pl, sizeof pl, "%.2f", r->lighting_ms);
                bench__fmt(cov, sizeof cov, "%.1f", bench_ns_per_pair(r));
                bench__fmt(psnr, sizeof psnr, "%.1f", r->mode == BENCH_REFERENCE ? NAN : r->ldr.psnr_db);
                bench__fmt(maxe, sizeof maxe, "%.0f", r->mode == BENCH_REFERENCE ? NAN : r->ldr.max_abs);
                printf("%-26s %6u %8.2f %8.2f %8s %7s %5u %4u %9.1f %9.1f %7s %7s %4llu\n", label, r->lights,
                       r->ms_median, r->ms_p90, pl, cov, r->bytes_per_pixel, r->bytes_per_pixel_sum,
                       bench_mib_at(r, 1920, 1080), r->bytes_moved / 1048576.0, psnr, maxe,
                       (unsigned long long)r->nan_pixels);
            }
        }
    }
    for (size_t si = 0; si < opt->size_count; si++) bench__print_roofline(run, opt->sizes[si]);
    for (size_t si = 0; si < opt->size_count; si++) bench__print_scales(run, opt->sizes[si]);
    bench__summary s = {0};
    bench__summarise(run, &s);
    bench__planning(run, &s);
    bench__outputs(run, &s);
    putchar('\n');
    for (size_t i = 0; i < s.count; i++) printf("%s\n", s.lines[i]);
    if (s.lost) printf("(%zu summary lines left out: out of memory)\n", s.lost);
    bench__summary_free(&s);
    fflush(stdout);
}

/* ---- JSON ----------------------------------------------------------------------------------- */

static const char bench__edge_definition[] =
    "pixels within " BENCH__STR(BENCH_EDGE_RADIUS) " pixels (a square) of a depth discontinuity or a normal crease of "
    "the fat reference's frame (its DEPTH and FAT_NORMAL targets read back): |d(x-1) + d(x+1) - 2 d(x)| over "
    BENCH__STR(BENCH_EDGE_DEPTH) " d(x) in linear view depth along x or y, or neighbouring normals more than "
    BENCH__STR(BENCH_EDGE_CREASE_DEG) " degrees apart";

static const char *bench__light_type_name(int t)
{
    return t == TL_LIGHT_POINT ? "point" : t == TL_LIGHT_SPOT ? "spot" : "directional";
}

/* An error member: {psnr_db, max_abs_error, mean_abs_error} (edge: with pixels and fraction, from
 * `edges`), or null when it was not measured. */
static void bench__json_error(tl_tool_json *j, const char *key, const tl_image_error *e, const bench_record *edges)
{
    if (!e) {
        tl_tool_json_num(j, key, NAN); /* null */
        return;
    }
    tl_tool_json_object(j, key, 1);
    if (edges) {
        tl_tool_json_uint(j, "pixels", edges->edge_pixels);
        tl_tool_json_num(j, "fraction", (double)edges->edge_pixels / ((double)edges->width * edges->height));
    }
    tl_tool_json_num(j, "psnr_db", e->psnr_db);
    tl_tool_json_num(j, "max_abs_error", e->max_abs);
    tl_tool_json_num(j, "mean_abs_error", e->mean_abs);
    tl_tool_json_close(j, '}');
}

static void bench__json_record(tl_tool_json *j, const bench_record *r)
{
    tl_tool_json_object(j, NULL, 0);
    tl_tool_json_str(j, "mode", tl_render_mode_name(r->mode));
    tl_tool_json_str(j, "config", bench_config_name(r->config));
    tl_tool_json_str(j, "strategy_asked", tl_light_strategy_name(bench_config_strategy(r->config)));
    tl_tool_json_str(j, "strategy", tl_light_strategy_name(r->strategy));
    tl_tool_json_str(j, "light_format", bench_config_light_format(r->config) == TL_LIGHT_FORMAT_R11G11B10F
                                            ? "r11g11b10f" : "rgba16f");
    static const char *const variants[] = {"", "r11g11b10f", "fresnel-nv", "light-scale-0.5", "light-scale-0.25",
                                           "tiled-compute"};
    tl_tool_json_str(j, "variant", variants[bench_config_variant_of(r->config) % 6u]);
    tl_tool_json_num(j, "light_scale", bench_config_light_scale(r->config) > 0.0f ? bench_config_light_scale(r->config) : 1.0);
    tl_tool_json_bool(j, "reference", r->mode == BENCH_REFERENCE);
    tl_tool_json_str(j, "lighting", tl_lighting_model_name(r->lighting));
    tl_tool_json_str(j, "fresnel", r->fresnel == TL_FRESNEL_DEFAULT ? "none" : tl_fresnel_layout_name(r->fresnel));
    tl_tool_json_uint(j, "lights", r->lights);
    tl_tool_json_uint(j, "point_lights", r->point_lights);
    tl_tool_json_uint(j, "spot_lights", r->spot_lights);
    tl_tool_json_uint(j, "directional_lights", r->directional_lights);
    tl_tool_json_uint(j, "width", r->width);
    tl_tool_json_uint(j, "height", r->height);
    tl_tool_json_uint(j, "frames", r->frames);
    tl_tool_json_num(j, "ms_median", r->ms_median);
    tl_tool_json_num(j, "ms_p90", r->ms_p90);
    tl_tool_json_array(j, "frame_ms", 1);
    for (uint32_t f = 0; r->frame_ms && f < r->frames; f++) tl_tool_json_num(j, NULL, r->frame_ms[f]);
    tl_tool_json_close(j, ']');
    tl_tool_json_num(j, "wall_ms_median", r->wall_ms_median);
    tl_tool_json_num(j, "wall_ms_p90", r->wall_ms_p90);
    tl_tool_json_object(j, "pass_ms", 1);
    for (int p = 0; p < TL_PASS_COUNT; p++)
        if (r->passes & BENCH_PASS_BIT(p)) tl_tool_json_num(j, tl_pass_name((tl_pass)p), r->pass_ms[p]);
    tl_tool_json_close(j, '}');
    tl_tool_json_object(j, "pass_bytes", 1);
    for (int p = 0; p < TL_PASS_COUNT; p++)
        if (r->passes & BENCH_PASS_BIT(p)) tl_tool_json_num(j, tl_pass_name((tl_pass)p), r->pass_bytes[p]);
    tl_tool_json_close(j, '}');
    tl_tool_json_object(j, "pass_fragments", 1);
    for (int p = 0; p < TL_PASS_COUNT; p++)
        if (r->passes & BENCH_PASS_BIT(p)) tl_tool_json_uint(j, tl_pass_name((tl_pass)p), r->pass_fragments[p]);
    tl_tool_json_close(j, '}');
    tl_tool_json_uint(j, "bytes_per_pixel", r->bytes_per_pixel);
    tl_tool_json_uint(j, "bytes_per_pixel_sum", r->bytes_per_pixel_sum);
    tl_tool_json_num(j, "cpu_ms_median", r->cpu_ms_median);
    tl_tool_json_object(j, "targets", 1);
    for (int t = 0; t < TL_TARGET_COUNT; t++)
        if (r->target_bpp[t]) tl_tool_json_uint(j, tl_target_name((tl_target_id)t), r->target_bpp[t]);
    tl_tool_json_close(j, '}');
    tl_tool_json_uint(j, "gbuffer_bytes_per_pixel", r->gbuffer_bytes_per_pixel);
    tl_tool_json_uint(j, "light_buffer_bytes_per_pixel", bench_light_buffer_bpp(r));
    tl_tool_json_object(j, "mib_at", 1);
    static const uint32_t at[3][2] = {{1280, 720}, {1920, 1080}, {3840, 2160}};
    for (int i = 0; i < 3; i++) {
        char key[24];
        snprintf(key, sizeof key, "%ux%u", at[i][0], at[i][1]);
        tl_tool_json_num(j, key, bench_mib_at(r, at[i][0], at[i][1]));
    }
    tl_tool_json_close(j, '}');
    tl_tool_json_num(j, "bytes_per_frame_estimate", r->bytes_moved);
    if (r->pairs_counted) tl_tool_json_uint(j, "covered_pixels", r->covered_pixels);
    else tl_tool_json_num(j, "covered_pixels", NAN);
    tl_tool_json_uint(j, "light_fragment_sum", r->light_fragment_sum);
    tl_tool_json_object(j, "light_fragments", 1);
    for (int t = TL_LIGHT_POINT; t < TL_LIGHT_TYPE_COUNT_; t++)
        tl_tool_json_uint(j, bench__light_type_name(t), r->light_fragments[t]);
    tl_tool_json_close(j, '}');
    tl_tool_json_object(j, "lights_drawn", 1);
    for (int t = TL_LIGHT_POINT; t < TL_LIGHT_TYPE_COUNT_; t++)
        tl_tool_json_uint(j, bench__light_type_name(t), r->lights_drawn[t]);
    tl_tool_json_close(j, '}');
    tl_tool_json_num(j, "lighting_ms", r->lighting_ms);
    tl_tool_json_num(j, "per_light_ms", bench_per_light_ms(r));
    tl_tool_json_num(j, "ms_per_mpixel_covered", bench_ms_per_mpixel_covered(r));
    tl_tool_json_uint(j, "forward_light_pairs", r->forward_light_pairs);
    tl_tool_json_uint(j, "light_pairs", r->light_pairs);
    tl_tool_json_num(j, "light_ns_per_pair", bench_ns_per_pair(r));
    if (r->pairs_counted) tl_tool_json_uint(j, "exact_pairs", r->exact_pairs);
    else tl_tool_json_num(j, "exact_pairs", NAN);
    if (r->evaluated_known) tl_tool_json_uint(j, "evaluated_pairs", r->evaluated_pairs);
    else tl_tool_json_num(j, "evaluated_pairs", NAN);
    tl_tool_json_num(j, "probe_ns_per_pair", r->probe_ns_per_pair);
    tl_tool_json_num(j, "floor_ms", r->floor_ms);
    tl_tool_json_num(j, "light_efficiency", r->light_efficiency);
    tl_tool_json_uint(j, "draw_calls", r->draw_calls);
    tl_tool_json_uint(j, "objects_drawn", r->objects_drawn);
    tl_tool_json_num(j, "psnr_db", r->ldr.psnr_db);
    tl_tool_json_num(j, "max_abs_error", r->ldr.max_abs);
    tl_tool_json_num(j, "mean_abs_error", r->ldr.mean_abs);
    tl_tool_json_num(j, "hdr_psnr_db", r->hdr.psnr_db);
    tl_tool_json_num(j, "hdr_max_abs_error", r->hdr.max_abs);
    tl_tool_json_num(j, "hdr_mean_abs_error", r->hdr.mean_abs);
    tl_tool_json_num(j, "hdr_peak", r->hdr_peak);
    tl_tool_json_uint(j, "nan_pixels", r->nan_pixels);
    bench__json_error(j, "edge", r->edge_pixels ? &r->edge_ldr : NULL, r);
    bench__json_error(j, "error_vs_scale1", r->has_scale1 ? &r->scale1_ldr : NULL, NULL);
    bench__json_error(j, "edge_error_vs_scale1", r->has_scale1 && r->edge_pixels ? &r->edge_scale1_ldr : NULL, r);
    tl_tool_json_uint(j, "relit_pixels", r->relit_pixels);
    tl_tool_json_num(j, "relit_fraction", r->relit_fraction);
    tl_tool_json_num(j, "relit_fraction_marked", r->relit_fraction_marked);
    tl_tool_json_close(j, '}');
}

static int bench__write_json(FILE *f, const void *ctx)
{
    const bench_run *run = ctx;
    const bench_options *opt = &run->opt;
    tl_tool_json j;
    tl_tool_json_begin(&j, f);
    tl_tool_json_object(&j, NULL, 0);
    tl_tool_json_str(&j, "tool", BENCH_TOOL);
    tl_tool_json_str(&j, "version", tl_version_string());
    tl_tool_json_str(&j, "scene", opt->scene);
    tl_tool_json_str(&j, "scene_name", run->scene_name);
    tl_tool_json_uint(&j, "scene_triangles", run->scene_triangles);
    tl_tool_json_uint(&j, "scene_objects", run->scene_objects);
    tl_tool_json_str(&j, "lights_definition", run->light_definition);
    tl_tool_json_str(&j, "gl_renderer", run->gl_renderer);
    tl_tool_json_str(&j, "gl_version", run->gl_version);
    tl_tool_json_str(&j, "context", run->context);
    tl_tool_json_str(&j, "context_platform", run->context_platform);
    char machine[192];
    snprintf(machine, sizeof machine, "%s, %zu cores", run->cpu, run->cores);
    tl_tool_json_str(&j, "machine", machine);
    tl_tool_json_uint(&j, "cores", run->cores);
    tl_tool_json_uint(&j, "frames", opt->frames);
    tl_tool_json_uint(&j, "warmup", opt->warmup);
    tl_tool_json_uint(&j, "seed", opt->seed);
    tl_tool_json_bool(&j, "quick", opt->quick);
    tl_tool_json_str(&j, "timing", run->timers_ok ? "gpu timer queries" : "wall clock");
    tl_tool_json_str(&j, "error_reference", tl_render_mode_name(BENCH_REFERENCE));
    tl_tool_json_str(&j, "error_units",
                     "psnr_db, max_abs_error, mean_abs_error: final image, RGB, 8-bit steps (peak 255); hdr_*: HDR "
                     "target, RGB, linear radiance, PSNR relative to hdr_peak (the reference's largest value); "
                     "999 dB = identical; edge: the same over the edge pixels alone (edge_definition); "
                     "error_vs_scale1, edge_error_vs_scale1: light-scale variants against thin-lpp at light scale 1 "
                     "(same strategy and frame), null elsewhere");
    tl_tool_json_str(&j, "edge_definition", bench__edge_definition);
    tl_tool_json_str(&j, "relit_definition",
                     "relit_fraction: tl_frame_stats.relit_fraction (pixels the edge fix-up re-lit at full resolution "
                     "over the frame's pixels; 0 from a library that does not count them); relit_fraction_marked: "
                     "HDR pixels whose alpha is the material pass's re-lit mark (0.5), light-scale variants only "
                     "(0 from a library whose light-upsample pass re-lights them: its material pass marks none)");
    tl_tool_json_num(&j, "seconds", run->seconds);
    tl_tool_json_array(&j, "load_average", 1);
    tl_tool_json_num(&j, NULL, run->load_start);
    tl_tool_json_num(&j, NULL, run->load_end);
    tl_tool_json_close(&j, ']');
    tl_tool_json_array(&j, "sizes", 1);
    for (size_t i = 0; i < opt->size_count; i++) {
        tl_tool_json_array(&j, NULL, 1);
        tl_tool_json_uint(&j, NULL, opt->sizes[i].width);
        tl_tool_json_uint(&j, NULL, opt->sizes[i].height);
        tl_tool_json_close(&j, ']');
    }
    tl_tool_json_close(&j, ']');
    tl_tool_json_array(&j, "light_counts", 1);
    for (size_t i = 0; i < opt->light_count; i++) tl_tool_json_uint(&j, NULL, opt->lights[i]);
    tl_tool_json_close(&j, ']');
    tl_tool_json_array(&j, "modes", 1);
    for (size_t i = 0; i < opt->mode_count; i++) tl_tool_json_str(&j, NULL, tl_render_mode_name(opt->modes[i]));
    tl_tool_json_close(&j, ']');
    for (int requested = 1; requested >= 0; requested--) {
        tl_tool_json_array(&j, requested ? "records" : "reference_records", 0);
        for (size_t i = 0; i < run->record_count; i++)
            if (run->records[i].requested == requested) bench__json_record(&j, &run->records[i]);
        tl_tool_json_close(&j, ']');
    }
    tl_tool_json_array(&j, "planning", 0);
    for (size_t i = 0; i < run->planning_count; i++) {
        const bench_planning *p = &run->planning[i];
        tl_tool_json_object(&j, NULL, 1);
        tl_tool_json_str(&j, "mode", tl_render_mode_name(p->mode));
        tl_tool_json_uint(&j, "bytes_per_pixel", p->bytes_per_pixel);
        tl_tool_json_uint(&j, "unplanned_bytes_per_pixel", p->unplanned_bytes_per_pixel);
        tl_tool_json_uint(&j, "programs", p->programs);
        tl_tool_json_uint(&j, "unplanned_programs", p->unplanned_programs);
        tl_tool_json_uint(&j, "passes", p->passes);
        tl_tool_json_uint(&j, "unplanned_passes", p->unplanned_passes);
        tl_tool_json_num(&j, "planned_ms", p->planned_ms);
        tl_tool_json_num(&j, "unplanned_ms", p->unplanned_ms);
        tl_tool_json_close(&j, '}');
    }
    tl_tool_json_close(&j, ']');
    bench_effects_json(&j, run);
    bench_aa_json(&j, run);
    if (run->shadow_count) bench_shadows_json(&j, run);
    tl_tool_json_array(&j, "images", 0);
    for (size_t i = 0; i < run->image_count; i++) {
        const bench_image_file *im = &run->images[i];
        tl_tool_json_object(&j, NULL, 1);
        tl_tool_json_str(&j, "path", im->path);
        tl_tool_json_str(&j, "kind", bench_image_kind_names[im->kind]);
        tl_tool_json_str(&j, "mode", bench_config_slug(im->config));
        tl_tool_json_uint(&j, "lights", im->lights);
        tl_tool_json_close(&j, '}');
    }
    tl_tool_json_close(&j, ']');
    tl_tool_json_close(&j, '}');
    tl_tool_json_end(&j);
    return 0;
}

int bench_write_json(const bench_run *run, const char *path)
{
    return tl_tool_write_atomic(BENCH_TOOL, path, bench__write_json, run);
}

/* ---- docs/bandwidth.md ---------------------------------------------------------------------- */

typedef struct bench__doc {
    const bench_run *run;
    const char *text;
    size_t head;
    const char *tail;
    bench_config heat[BENCH_CONFIGS]; /* heat maps copied to img/bench_heat_<slug>.png */
    size_t heat_count;
    bench_config heat1[BENCH_CONFIGS]; /* and img/bench_heat_<slug>_vs_scale1.png */
    size_t heat1_count;
    int edges;                        /* img/bench_edges.png */
} bench__doc;

static void bench__md_number(FILE *f, const char *fmt, double v)
{
    fputs(" | ", f);
    if (isfinite(v)) fprintf(f, fmt, v);
    else fputs("–", f);
}

static void bench__md_table(FILE *f, const bench_run *run, bench_size size)
{
    const bench_options *opt = &run->opt;
    bench_config modes[BENCH_CONFIGS];
    size_t mode_count = bench_render_modes(opt, modes);
    fprintf(f, "\n#### %ux%u\n\n", size.width, size.height);
    fputs("| mode | lights | ms median | ms p90 | light ms | ns / pair | B/px (sum) | MiB @1080p | MiB moved / frame | "
          "PSNR dB | max err | NaN |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
          f);
    for (size_t m = 0; m < mode_count; m++)
        for (size_t li = 0; li < opt->light_count; li++) {
            const bench_record *r = bench_find(run, modes[m], opt->lights[li], size);
            if (!r) continue;
            int ref = r->mode == BENCH_REFERENCE;
            fprintf(f, "| `%s`%s | %u", bench_config_name(r->config), ref ? " (reference)" : "", r->lights);
            bench__md_number(f, "%.2f", r->ms_median);
            bench__md_number(f, "%.2f", r->ms_p90);
            bench__md_number(f, "%.2f", r->lighting_ms);
            bench__md_number(f, "%.1f", bench_ns_per_pair(r));
            fprintf(f, " | %u (%u)", r->bytes_per_pixel, r->bytes_per_pixel_sum);
            bench__md_number(f, "%.1f", bench_mib_at(r, 1920, 1080));
            bench__md_number(f, "%.1f", r->bytes_moved / 1048576.0);
            bench__md_number(f, "%.1f", ref ? NAN : r->ldr.psnr_db);
            bench__md_number(f, "%.0f", ref ? NAN : r->ldr.max_abs);
            fprintf(f, " | %llu |\n", (unsigned long long)r->nan_pixels);
        }
}

/* Targets per mode (largest light count, first size): what the bytes per pixel are made of. */
static void bench__md_targets(FILE *f, const bench_run *run)
{
    const bench_options *opt = &run->opt;
    bench_config modes[BENCH_CONFIGS];
    size_t mode_count = bench_render_modes(opt, modes);
    fputs("\nTargets each mode's plan allocates, bytes per pixel:\n\n| mode |", f);
    tl_target_set used = 0;
    for (size_t m = 0; m < mode_count; m++) {
        const bench_record *r = bench_find(run, modes[m], opt->lights[opt->light_count - 1], opt->sizes[0]);
        for (int t = 0; r && t < TL_TARGET_COUNT; t++)
            if (r->target_bpp[t]) used |= TL_TARGET_BIT(t);
    }
    for (int t = 0; t < TL_TARGET_COUNT; t++)
        if (used & TL_TARGET_BIT(t)) fprintf(f, " %s |", tl_target_name((tl_target_id)t));
    fputs(" sum | allocated | depth + G-buffer + light buffer |\n|---|", f);
    for (int t = 0; t < TL_TARGET_COUNT; t++)
        if (used & TL_TARGET_BIT(t)) fputs("---:|", f);
    fputs("---:|---:|---:|\n", f);
    for (size_t m = 0; m < mode_count; m++) {
        const bench_record *r = bench_find(run, modes[m], opt->lights[opt->light_count - 1], opt->sizes[0]);
        if (!r) continue;
        fprintf(f, "| `%s` |", bench_config_name(r->config));
        for (int t = 0; t < TL_TARGET_COUNT; t++)
            if (used & TL_TARGET_BIT(t)) r->target_bpp[t] ? fprintf(f, " %u |", r->target_bpp[t]) : fputs(" |", f);
        fprintf(f, " %u | %u | %u |\n", r->bytes_per_pixel_sum, r->bytes_per_pixel, r->gbuffer_bytes_per_pixel);
    }
}

/* Where each mode's time goes at the largest light count (first size). */
static void bench__md_passes(FILE *f, const bench_run *run)
{
    const bench_options *opt = &run->opt;
    bench_config modes[BENCH_CONFIGS];
    size_t mode_count = bench_render_modes(opt, modes);
    uint32_t n = opt->lights[opt->light_count - 1];
    uint64_t used = 0;
    for (size_t m = 0; m < mode_count; m++) {
        const bench_record *r = bench_find(run, modes[m], n, opt->sizes[0]);
        if (r) used |= r->passes;
    }
    fprintf(f, "\nGPU time per pass at %u lights, ms (median; MiB moved by the estimate in brackets):\n\n| mode |", n);
    for (int p = 0; p < TL_PASS_COUNT; p++)
        if (used & BENCH_PASS_BIT(p)) fprintf(f, " %s |", tl_pass_name((tl_pass)p));
    fputs(" frame |\n|---|", f);
    for (int p = 0; p < TL_PASS_COUNT; p++)
        if (used & BENCH_PASS_BIT(p)) fputs("---:|", f);
    fputs("---:|\n", f);
    for (size_t m = 0; m < mode_count; m++) {
        const bench_record *r = bench_find(run, modes[m], n, opt->sizes[0]);
        if (!r) continue;
        fprintf(f, "| `%s` |", bench_config_name(r->config));
        for (int p = 0; p < TL_PASS_COUNT; p++) {
            if (!(used & BENCH_PASS_BIT(p))) continue;
            if (r->passes & BENCH_PASS_BIT(p)) fprintf(f, " %.1f (%.0f) |", r->pass_ms[p], r->pass_bytes[p] / 1048576.0);
            else fputs(" |", f);
        }
        fprintf(f, " %.1f (%.0f) |\n", r->ms_median, r->bytes_moved / 1048576.0);
    }
}

static int bench__write_doc(FILE *f, const void *ctx)
{
    const bench__doc *d = ctx;
    const bench_run *run = d->run;
    const bench_options *opt = &run->opt;
    fwrite(d->text, 1, d->head, f);
    fprintf(f, "\n<!-- Generated by %s; edit the tool, not this section. -->\n\n", BENCH_TOOL);
    fprintf(f, "Scene: %s (%zu triangles, %zu objects); %u timed frames after %u warm-up, seed %llu%s. ",
            run->scene_name, run->scene_triangles, run->scene_objects, opt->frames, opt->warmup,
            (unsigned long long)opt->seed, opt->quick ? " (--quick)" : "");
    fprintf(f, "GL: %s, %s (context %s: %s), on %s (%zu cores; 1-minute load average %.1f before the sweep, %.1f "
               "after); the sweep took %.0f s. ",
            run->gl_renderer, run->gl_version, run->context, run->context_platform, run->cpu, run->cores, run->load_start, run->load_end, run->seconds);
    fprintf(f, "Times are %s. %s. PSNR and max err (8-bit steps) compare the final image with fat's.\n",
            run->timers_ok ? "GPU timer queries summed over the passes" : "wall clock (GPU timers unavailable)",
            run->light_definition);
    for (size_t si = 0; si < opt->size_count; si++) bench__md_table(f, run, opt->sizes[si]);
    for (size_t si = 0; si < opt->size_count; si++) bench__md_roofline(f, run, opt->sizes[si]);
    for (size_t si = 0; si < opt->size_count; si++) bench__md_scales(f, run, opt->sizes[si]);
    bench__md_passes(f, run);
    bench__md_targets(f, run);
    bench__summary s = {0};
    bench__summarise(run, &s);
    bench__planning(run, &s);
    fputs("\n", f);
    for (size_t i = 0; i < s.count; i++) fprintf(f, "- %s\n", s.lines[i]);
    if (s.lost) fprintf(f, "- (%zu summary lines left out: out of memory)\n", s.lost);
    bench__summary_free(&s);
    if (d->heat_count) {
        fprintf(f, "\nHeat maps of |mode - fat| at %ux%u with %u lights: the largest RGB difference in 8-bit steps "
                   "(black: none; the legend strip runs from 0 to %u steps, ticks every step), the largest of each "
                   "%ux%u block%s.\n\n",
                opt->sizes[0].width, opt->sizes[0].height, opt->lights[opt->light_count - 1], BENCH_HEAT_SCALE,
                (opt->sizes[0].width + 639) / 640, (opt->sizes[0].width + 639) / 640,
                opt->sizes[0].width > 640 ? " of pixels" : " (full size)");
        for (size_t i = 0; i < d->heat_count; i++)
            fprintf(f, "![%s against fat](img/bench_heat_%s.png)\n", bench_config_name(d->heat[i]),
                    bench_config_slug(d->heat[i]));
    }
    if (d->heat1_count) {
        fputs("\nThe light-scale variants against thin-lpp at light scale 1 (same scale and legend):\n\n", f);
        for (size_t i = 0; i < d->heat1_count; i++)
            fprintf(f, "![%s against thin-lpp at scale 1](img/bench_heat_%s_vs_scale1.png)\n",
                    bench_config_name(d->heat1[i]), bench_config_slug(d->heat1[i]));
    }
    if (d->edges)
        fputs("\nThe edge pixels of the light-scale tables (white; fat's image darkened beneath):\n\n"
              "![edge pixels](img/bench_edges.png)\n", f);
    if (run->plots_made) {
        fputs("\n", f);
        for (int i = 0; i < BENCH_PLOT_COUNT; i++) fprintf(f, "![%s](img/%s.png)\n", bench_plot_names[i], bench_plot_names[i]);
    } else {
        fputs("\n(The plots were not regenerated: the run had --no-plot or no gnuplot.)\n", f);
    }
    fputc('\n', f);
    fputs(d->tail, f);
    return 0;
}

/* Copies the doc-sized heat maps of the first size into img/ (those within the size limit). */
static int bench__doc_heat_maps(const bench_run *run, const char *dir, bench__doc *d)
{
    for (size_t i = 0; i < run->image_count; i++) {
        const bench_image_file *im = &run->images[i];
        int scale1 = im->kind == BENCH_IMAGE_HEAT_SCALE1_DOC, edges = im->kind == BENCH_IMAGE_EDGES;
        if ((im->kind != BENCH_IMAGE_HEAT_DOC && !scale1 && !edges) || im->width != run->opt.sizes[0].width ||
            im->height != run->opt.sizes[0].height || d->heat_count == BENCH_CONFIGS || d->heat1_count == BENCH_CONFIGS)
            continue;
        size_t size = 0;
        char *data = tl_tool_read_file(im->path, &size);
        free(data);
        if (size > BENCH_PNG_MAX_BYTES) {
            fprintf(stderr, BENCH_TOOL ": warning: %s is %zu KiB, over %u KiB: left out of the doc\n", im->path,
                    size / 1024, BENCH_PNG_MAX_BYTES / 1024);
            continue;
        }
        char *dst = edges ? tl_tool_strf("%s/img/bench_edges.png", dir)
                          : tl_tool_strf("%s/img/bench_heat_%s%s.png", dir, bench_config_slug(im->config),
                                         scale1 ? "_vs_scale1" : "");
        int err = !dst || tl_tool_copy_file(BENCH_TOOL, im->path, dst);
        free(dst);
        if (err) return 1;
        if (edges) d->edges = 1;
        else if (scale1) d->heat1[d->heat1_count++] = im->config;
        else d->heat[d->heat_count++] = im->config;
    }
    return 0;
}

int bench_update_doc(const bench_run *run, const char *doc_text)
{
    const char *path = run->opt.doc;
    bench__doc d = {run, doc_text, 0, NULL, {0}, 0, {0}, 0, 0};
    if (tl_tool_doc_split(BENCH_TOOL, path, doc_text, BENCH_DOC_BEGIN, BENCH_DOC_END, &d.head, &d.tail)) return 1;
    char *dir = tl_tool_dir_of(path);
    int err = !dir;
    for (int i = 0; !err && run->plots_made && i < BENCH_PLOT_COUNT; i++) {
        char *src = tl_tool_strf("%s/%s.png", run->opt.out, bench_plot_names[i]);
        char *dst = tl_tool_strf("%s/img/%s.png", dir, bench_plot_names[i]);
        err = src && dst ? tl_tool_copy_file(BENCH_TOOL, src, dst) : 1;
        free(src);
        free(dst);
    }
    if (!err && run->image_count) {
        char *img = tl_tool_strf("%s/img", dir);
        int e = img ? tl_tool_make_dirs(img) : 1;
        if (e) tl_tool_fail(BENCH_TOOL, "cannot create '%s'", img ? img : "img");
        free(img);
        err = e || bench__doc_heat_maps(run, dir, &d);
    }
    free(dir);
    return err || tl_tool_write_atomic(BENCH_TOOL, path, bench__write_doc, &d);
}
