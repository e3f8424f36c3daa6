/* The antialiasing figures (--aa) as a table on stdout, the JSON member "aa", a Markdown table
 * between the markers of --aa-doc (docs/antialiasing.md) and the edge-PSNR-against-time plot. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

static const char bench__truth_definition[] =
    "fat with the first strategy at 4x the width and 4x the height (16 samples per pixel), FXAA off; its HDR "
    "target tone-mapped per sample on the CPU as shaders/tonemap.frag.glsl does (clamp to [0, 65504], exposure 1, "
    "ACES fit clamped to [0, 1]), each 4x4 block averaged in that tone-mapped linear space, then sRGB-encoded and "
    "rounded to 8 bits";
static const char bench__edge_definition[] =
    "pixels with a sample of the truth's 4x4 on a depth discontinuity or normal crease of the truth's DEPTH and "
    "FAT_NORMAL targets (bench_edges_mask at the truth's resolution: within 2 of its pixels)";

static void bench__db(char *buf, size_t size, double db)
{
    if (db >= 999.0) snprintf(buf, size, "identical");
    else snprintf(buf, size, "%.2f dB", db);
}

static void bench__num(char *buf, size_t size, const char *fmt, double v)
{
    if (isfinite(v)) snprintf(buf, size, fmt, v);
    else snprintf(buf, size, "-");
}

void bench_aa_print_table(const bench_run *run)
{
    if (!run->aa_count) return;
    const bench_aa_record *r0 = &run->aa[0];
    printf("\nantialiasing at %ux%u, %s (%u timed frames; ms: %s, medians; errors: final image against the truth, fat "
           "at %ux supersampled)\n",
           r0->width, r0->height, tl_light_strategy_name(bench_config_strategy(r0->config)), r0->frames,
           run->timers_ok ? "GPU timers" : "wall clock", BENCH_AA_TRUTH_SCALE * BENCH_AA_TRUTH_SCALE);
    printf("%6s %-22s %-6s %9s %8s %8s %5s %10s %10s %5s %5s %7s %6s\n", "lights", "mode", "AA", "ms", "x FXAA",
           "x none", "B/px", "PSNR", "edge PSNR", "max", "edge", "re-lit", "edges");
    for (size_t i = 0; i < run->aa_count; i++) {
        const bench_aa_record *r = &run->aa[i];
        char psnr[24], edge[24], ratio[16], ratio_none[16], relit[16];
        bench__db(psnr, sizeof psnr, r->ldr.psnr_db);
        bench__db(edge, sizeof edge, r->edge_ldr.psnr_db);
        bench__num(ratio, sizeof ratio, "%.3f", r->ratio_vs_fxaa);
        bench__num(ratio_none, sizeof ratio_none, "%.3f", r->ratio_vs_none);
        bench__num(relit, sizeof relit, "%.4f", r->relit_fraction);
        printf("%6u %-22s %-6s %9.2f %8s %8s %5u %10s %10s %5.0f %5.0f %7s %5.1f%%\n", r->lights,
               bench_config_name(r->config), bench_aa_name(r->aa), r->ms_median, ratio, ratio_none, r->bytes_per_pixel,
               psnr, edge, r->ldr.max_abs, r->edge_ldr.max_abs, relit, 100.0 * r->edge_fraction);
    }
    for (size_t i = 0; i < run->aa_skipped_count; i++) printf("not measured: %s\n", run->aa_skipped[i]);
    fflush(stdout);
}

static void bench__json_record(tl_tool_json *j, const bench_aa_record *r)
{
    tl_tool_json_object(j, NULL, 1);
    tl_tool_json_str(j, "mode", tl_render_mode_name(bench_config_mode(r->config)));
    tl_tool_json_str(j, "config", bench_config_name(r->config));
    tl_tool_json_str(j, "strategy", tl_light_strategy_name(bench_config_strategy(r->config)));
    tl_tool_json_str(j, "aa", bench_aa_name(r->aa));
    tl_tool_json_uint(j, "samples", r->samples);
    tl_tool_json_uint(j, "lights", r->lights);
    tl_tool_json_uint(j, "width", r->width);
    tl_tool_json_uint(j, "height", r->height);
    tl_tool_json_uint(j, "frames", r->frames);
    tl_tool_json_num(j, "ms_median", r->ms_median);
    tl_tool_json_num(j, "ratio_vs_fxaa", r->ratio_vs_fxaa);
    tl_tool_json_num(j, "ratio_vs_none", r->ratio_vs_none);
    tl_tool_json_num(j, "psnr_db", r->ldr.psnr_db);
    tl_tool_json_num(j, "edge_psnr_db", r->edge_ldr.psnr_db);
    tl_tool_json_num(j, "max_abs_error", r->ldr.max_abs);
    tl_tool_json_num(j, "edge_max_abs_error", r->edge_ldr.max_abs);
    tl_tool_json_num(j, "mean_abs_error", r->ldr.mean_abs);
    tl_tool_json_num(j, "edge_mean_abs_error", r->edge_ldr.mean_abs);
    tl_tool_json_uint(j, "bytes_per_pixel", r->bytes_per_pixel);
    tl_tool_json_num(j, "relit_fraction", r->relit_fraction);
    tl_tool_json_num(j, "edge_fraction", r->edge_fraction);
    tl_tool_json_close(j, '}');
}

void bench_aa_json(tl_tool_json *j, const bench_run *run)
{
    tl_tool_json_array(j, "aa", 0);
    for (size_t i = 0; i < run->aa_count; i++) bench__json_record(j, &run->aa[i]);
    tl_tool_json_close(j, ']');
    if (!run->opt.aa) return;
    tl_tool_json_str(j, "aa_truth_definition", bench__truth_definition);
    tl_tool_json_str(j, "aa_edge_definition", bench__edge_definition);
    tl_tool_json_array(j, "aa_not_measured", 1);
    for (size_t i = 0; i < run->aa_skipped_count; i++) tl_tool_json_str(j, NULL, run->aa_skipped[i]);
    tl_tool_json_close(j, ']');
}

/* ---- the doc -------------------------------------------------------------------------------- */

typedef struct bench__aa_doc {
    const bench_run *run;
    const char *text;
    size_t head;
    const char *tail;
    int plot;                      /* img/BENCH_AA_PLOT.png copied */
    int crops[2 * (BENCH_MODES * BENCH_AAS + 1)]; /* per aa_images entry: copied into img/ */
} bench__aa_doc;

/* An image's name in img/ beside the doc: the same for every run, so a new run replaces it. */
void bench_aa_doc_markers(const bench_options *o, char *begin, char *end, size_t size)
{
    if (!o->aa_section) {
        snprintf(begin, size, "%s", BENCH_AA_DOC_BEGIN);
        snprintf(end, size, "%s", BENCH_AA_DOC_END);
        return;
    }
    snprintf(begin, size, "<!-- bench-aa:%s:begin -->", o->aa_section);
    snprintf(end, size, "<!-- bench-aa:%s:end -->", o->aa_section);
}

/* An image's name in the doc's img/: bench_aa_[SECTION_]..., so that sections do not share files. */
static void bench__doc_name(const bench_options *o, const bench_aa_image *im, char *buf, size_t size)
{
    char prefix[80];
    snprintf(prefix, sizeof prefix, "bench_aa_%s%s", o->aa_section ? o->aa_section : "", o->aa_section ? "_" : "");
    if (im->aa == BENCH_AAS) snprintf(buf, size, "%struth.png", prefix);
    else snprintf(buf, size, "%s%s_%s.png", prefix, bench_config_slug(im->config), bench_aa_name(im->aa));
}

static void bench__plot_name(const bench_options *o, char *buf, size_t size)
{
    if (o->aa_section) snprintf(buf, size, "bench_aa_%s_error_vs_ms.png", o->aa_section);
    else snprintf(buf, size, "%s.png", BENCH_AA_PLOT);
}

static void bench__md_db(FILE *f, double db)
{
    if (db >= 999.0) fputs(" identical |", f);
    else fprintf(f, " %.2f |", db);
}

static void bench__md_row(FILE *f, const bench_aa_record *r)
{
    fprintf(f, "| %u | %s | %s | %.1f |", r->lights, bench_config_name(r->config), bench_aa_name(r->aa), r->ms_median);
    if (isfinite(r->ratio_vs_fxaa)) fprintf(f, " %.3f |", r->ratio_vs_fxaa);
    else fputs(" – |", f);
    if (isfinite(r->ratio_vs_none)) fprintf(f, " %.3f |", r->ratio_vs_none);
    else fputs(" – |", f);
    fprintf(f, " %u |", r->bytes_per_pixel);
    bench__md_db(f, r->ldr.psnr_db);
    bench__md_db(f, r->edge_ldr.psnr_db);
    fprintf(f, " %.0f | %.0f | %.3f | %.2f |", r->ldr.max_abs, r->edge_ldr.max_abs, r->ldr.mean_abs,
            r->edge_ldr.mean_abs);
    if (isfinite(r->relit_fraction)) fprintf(f, " %.4f |\n", r->relit_fraction);
    else fputs(" – |\n", f);
}

static void bench__md_intro(FILE *f, const bench_run *run)
{
    const bench_aa_record *r0 = &run->aa[0];
    fprintf(f, "\n<!-- Generated by %s --aa; edit the tool, not this section. -->\n\n", BENCH_TOOL);
    int compute = bench_config_strategy(r0->config) == TL_LIGHT_STRATEGY_TILED &&
                  run->opt.base.tiled_shading == TL_TILED_SHADING_COMPUTE;
    fprintf(f, "%s at %ux%u (%s), the %s light strategy%s; %u timed frames after %u warm-up per record, each "
               "mode's methods taking turns frame by frame. GL: %s, %s, on %s (%zu cores; 1-minute load average "
               "%.1f before the run, %.1f after). Time: %s, median; \"× FXAA\": the median over the frames of the "
               "frame time over the same mode's FXAA frame beside it, \"× none\" the same over its no-AA (1x) frame. Errors: the final image (8-bit sRGB, RGB) "
               "against the truth, over the frame and over the edge pixels alone (%.1f %% of the frame at %u "
               "lights). Re-lit: thin-lpp with MSAA (msaaN), the material-pass samples that found no matching "
               "light-buffer texel and were re-lit, over the frame's pixels (tl_frame_stats.relit_fraction); with "
               "per-sample edges (msaaNe), the pixels classified as edges and lit per sample, over the frame's "
               "pixels (tl_frame_stats.msaa_edge_fraction).\n\n",
            run->scene_name, r0->width, r0->height, run->light_definition,
            tl_light_strategy_name(bench_config_strategy(r0->config)), compute ? " with the compute light pass" : "",
            run->opt.frames, run->opt.warmup,
            run->gl_renderer, run->gl_version, run->cpu, run->cores, run->load_start, run->load_end,
            run->timers_ok ? "GPU timer queries" : "wall clock", 100.0 * r0->edge_fraction, r0->lights);
}

/* The crops of the last light count: the truth, then one row per mode with its methods. */
static void bench__md_crops(FILE *f, const bench__aa_doc *d)
{
    const bench_run *run = d->run;
    int any = 0;
    for (size_t i = 0; i < run->aa_image_count; i++) any |= d->crops[i];
    if (!any) return;
    fprintf(f, "\nAt %u lights, crops of %ux%u pixels around the most edge pixels, magnified %ux (nearest):\n\n",
            run->opt.lights[run->opt.light_count - 1], BENCH_AA_CROP_W, BENCH_AA_CROP_H, BENCH_AA_CROP_ZOOM);
    for (size_t i = 0; i < run->aa_image_count; i++) {
        const bench_aa_image *im = &run->aa_images[i];
        if (!d->crops[i]) continue;
        char name[128];
        bench__doc_name(&run->opt, im, name, sizeof name);
        if (im->aa == BENCH_AAS) fprintf(f, "truth:\n\n![truth](img/%s)\n\n", name);
        else fprintf(f, "%s, %s:\n\n![%s %s](img/%s)\n\n", bench_config_name(im->config), bench_aa_name(im->aa),
                     bench_config_name(im->config), bench_aa_name(im->aa), name);
    }
}

static int bench__write_doc(FILE *f, const void *ctx)
{
    const bench__aa_doc *d = ctx;
    const bench_run *run = d->run;
    fwrite(d->text, 1, d->head, f);
    bench__md_intro(f, run);
    fputs("| lights | mode | AA | ms | × FXAA | × none | B/px | PSNR | edge PSNR | max | edge max | mean | edge mean | "
          "re-lit |\n"
          "|-------:|------|----|---:|-------:|-------:|-----:|-----:|----------:|----:|---------:|-----:|----------:|"
          "-------:|\n",
          f);
    for (size_t i = 0; i < run->aa_count; i++) bench__md_row(f, &run->aa[i]);
    if (run->aa_skipped_count) fputs("\nNot measured (the plan does not apply it):\n\n", f);
    for (size_t i = 0; i < run->aa_skipped_count; i++) fprintf(f, "- %s\n", run->aa_skipped[i]);
    char plot[128];
    bench__plot_name(&run->opt, plot, sizeof plot);
    if (d->plot) fprintf(f, "\n![AA error against time](img/%s)\n", plot);
    else fputs("\n(The plot was not regenerated: the run had no --out, --no-plot or no gnuplot.)\n", f);
    bench__md_crops(f, d);
    fputc('\n', f);
    fputs(d->tail, f);
    return 0;
}

/* Copies src to img/<name> beside the doc when it is under BENCH_AA_PNG_MAX_BYTES; 1 when copied. */
static int bench__doc_copy(const char *dir, const char *src, const char *name, int *err)
{
    size_t size = 0;
    char *data = tl_tool_read_file(src, &size);
    free(data);
    if (!data || size > BENCH_AA_PNG_MAX_BYTES) {
        if (data) fprintf(stderr, BENCH_TOOL ": warning: %s is %zu KiB: left out of the AA doc\n", src, size / 1024);
        return 0;
    }
    char *dst = tl_tool_strf("%s/img/%s", dir, name);
    *err = !dst || tl_tool_copy_file(BENCH_TOOL, src, dst);
    free(dst);
    return !*err;
}

int bench_aa_update_doc(const bench_run *run, const char *doc_text)
{
    const char *path = run->opt.aa_doc;
    bench__aa_doc d = {.run = run, .text = doc_text};
    if (!run->aa_count) {
        fprintf(stderr, BENCH_TOOL ": warning: --aa-doc %s: no AA record was measured, the file is unchanged\n", path);
        return 0;
    }
    char begin[128], end[128], plot[128];
    bench_aa_doc_markers(&run->opt, begin, end, sizeof begin);
    bench__plot_name(&run->opt, plot, sizeof plot);
    if (tl_tool_doc_split(BENCH_TOOL, path, doc_text, begin, end, &d.head, &d.tail)) return 1;
    char *dir = tl_tool_dir_of(path), *img = dir ? tl_tool_strf("%s/img", dir) : NULL;
    int err = !img || (run->opt.out && tl_tool_make_dirs(img));
    if (err) tl_tool_fail(BENCH_TOOL, "cannot create '%s'", img ? img : "img");
    if (!err && run->aa_plot_made) {
        char *src = tl_tool_strf("%s/%s.png", run->opt.out, BENCH_AA_PLOT);
        d.plot = src && bench__doc_copy(dir, src, plot, &err);
        free(src);
    }
    for (size_t i = 0; !err && i < run->aa_image_count && i < sizeof d.crops / sizeof d.crops[0]; i++) {
        const bench_aa_image *im = &run->aa_images[i];
        char name[128];
        bench__doc_name(&run->opt, im, name, sizeof name);
        if (im->crop) d.crops[i] = bench__doc_copy(dir, im->path, name, &err);
    }
    free(dir);
    free(img);
    return err || tl_tool_write_atomic(BENCH_TOOL, path, bench__write_doc, &d);
}
