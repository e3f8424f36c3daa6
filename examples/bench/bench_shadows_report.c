/* The shadows' figures (--shadows) as a table on stdout, a member of the JSON and a Markdown
 * section between the markers of --shadows-doc (docs/shadows.md), with the plot copied beside it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_shadows.h"

static const char *const bench__depth_names[BENCH_SHADOW_DEPTHS] = {"D24", "D32F-rev"};

/* "0.1234 %" or the dash when there is no figure. */
static const char *bench__pct(char *buf, size_t size, double v)
{
    if (isfinite(v)) snprintf(buf, size, "%.4f %%", 100.0 * v);
    else snprintf(buf, size, "–");
    return buf;
}

static double bench__share(const bench_shadow_record *r) { return 1.0 - r->frame_ms_off / r->frame_ms; }

void bench_shadows_print_table(const bench_run *run)
{
    if (!run->shadow_count) return;
    const bench_shadow_record *r0 = &run->shadows[0];
    printf("\nshadows at %ux%u, %u lights, %u casting (%u timed frames; ms: %s, medians; wrong: shadow term of %s "
           "against the ray-traced truth, outside the penumbra)\n",
           r0->width, r0->height, r0->lights, r0->casting_lights, r0->frames,
           run->timers_ok ? "GPU timers" : "wall clock", run->shadow_truth_light[0] ? run->shadow_truth_light : "-");
    if (run->shadow_truth_why[0]) printf("no truth: %s\n", run->shadow_truth_why);
    printf("%-18s %9s %9s %7s %9s %9s %9s %9s %9s %8s %5s %9s %11s %11s %18s %11s\n", "mode", "off ms", "on ms", "share",
           "no-cache", "maps ms", "nc maps", "light ms", "lookup", "atlas MiB", "maps", "kept", "D24 wrong",
           "D32F wrong", "acne/leaks/counted", "vs fat");
    for (size_t i = 0; i < run->shadow_count; i++) {
        const bench_shadow_record *r = &run->shadows[i];
        char w24[24], w32[24], vf[24], acne[48];
        const bench_shadow_error *e = &r->truth[1];
        if (e->measured)
            snprintf(acne, sizeof acne, "%llu/%llu/%llu", (unsigned long long)e->acne, (unsigned long long)e->leaks,
                     (unsigned long long)e->counted);
        else snprintf(acne, sizeof acne, "–");
        printf("%-18s %9.1f %9.1f %6.1f%% %9.1f %9.1f %9.1f %9.1f %9.1f %8.1f %5u %9u %11s %11s %18s %11s\n",
               bench_config_name(r->config), r->frame_ms_off, r->frame_ms, 100.0 * bench__share(r), r->frame_ms_nocache,
               r->shadow_ms, r->shadow_ms_nocache, r->light_ms, r->lookup_ms, (double)r->atlas_bytes / 1048576.0,
               r->maps_rendered, r->maps_cached, bench__pct(w24, sizeof w24, r->truth[0].wrong),
               bench__pct(w32, sizeof w32, e->wrong), acne, bench__pct(vf, sizeof vf, e->vs_fat));
    }
}

static void bench__json_error(tl_tool_json *j, const char *key, const bench_shadow_error *e)
{
    tl_tool_json_object(j, key, 1);
    tl_tool_json_bool(j, "measured", e->measured);
    tl_tool_json_num(j, "counted", e->measured ? (double)e->counted : NAN);
    tl_tool_json_num(j, "acne", e->measured ? (double)e->acne : NAN);
    tl_tool_json_num(j, "leaks", e->measured ? (double)e->leaks : NAN);
    tl_tool_json_num(j, "wrong", e->wrong);
    tl_tool_json_num(j, "vs_fat", e->vs_fat);
    tl_tool_json_close(j, '}');
}

static void bench__json_record(tl_tool_json *j, const bench_shadow_record *r)
{
    tl_tool_json_object(j, NULL, 0);
    tl_tool_json_str(j, "mode", bench_config_name(r->config));
    tl_tool_json_uint(j, "lights", r->lights);
    tl_tool_json_uint(j, "casting_lights", r->casting_lights);
    tl_tool_json_uint(j, "width", r->width);
    tl_tool_json_uint(j, "height", r->height);
    tl_tool_json_uint(j, "frames", r->frames);
    tl_tool_json_num(j, "frame_ms", r->frame_ms);
    tl_tool_json_num(j, "frame_ms_off", r->frame_ms_off);
    tl_tool_json_num(j, "frame_ms_no_cache", r->frame_ms_nocache);
    tl_tool_json_num(j, "frame_ratio", r->ratio);
    tl_tool_json_num(j, "shadow_share", bench__share(r));
    tl_tool_json_num(j, "shadow_ms", r->shadow_ms);
    tl_tool_json_num(j, "shadow_ms_no_cache", r->shadow_ms_nocache);
    tl_tool_json_num(j, "light_ms", r->light_ms);
    tl_tool_json_num(j, "light_ms_off", r->light_ms_off);
    tl_tool_json_num(j, "lookup_ms", r->lookup_ms);
    tl_tool_json_uint(j, "atlas_bytes", r->atlas_bytes);
    tl_tool_json_uint(j, "shadow_lights", r->shadow_lights);
    tl_tool_json_uint(j, "maps_rendered", r->maps_rendered);
    tl_tool_json_uint(j, "maps_cached", r->maps_cached);
    tl_tool_json_uint(j, "maps_rendered_no_cache", r->maps_nocache);
    tl_tool_json_object(j, "truth", 0);
    for (int d = 0; d < BENCH_SHADOW_DEPTHS; d++) bench__json_error(j, bench__depth_names[d], &r->truth[d]);
    tl_tool_json_close(j, '}');
    tl_tool_json_close(j, '}');
}

void bench_shadows_json(tl_tool_json *j, const bench_run *run)
{
    tl_tool_json_object(j, "shadows", 0);
    tl_tool_json_str(j, "truth_light", run->shadow_truth_light);
    if (run->shadow_truth_why[0]) tl_tool_json_str(j, "no_truth_reason", run->shadow_truth_why);
    else tl_tool_json_num(j, "no_truth_reason", NAN); /* null: measured */
    tl_tool_json_uint(j, "penumbra_band_px", BENCH_SHADOW_BAND);
    tl_tool_json_array(j, "records", 0);
    for (size_t i = 0; i < run->shadow_count; i++) bench__json_record(j, &run->shadows[i]);
    tl_tool_json_close(j, ']');
    tl_tool_json_close(j, '}');
}

typedef struct bench__shadows_doc {
    const bench_run *run;
    const char *text, *tail;
    size_t head;
    int plot;
} bench__shadows_doc;

static void bench__md_intro(FILE *f, const bench_run *run)
{
    const bench_shadow_record *r0 = &run->shadows[0];
    fprintf(f, "\n<!-- Generated by %s --shadows off,on; edit the tool, not this section. -->\n\n", BENCH_TOOL);
    fprintf(f, "%s at %ux%u, %u local lights (%s), %u of them casting (%s; at most 8 get a "
               "map); %u timed frames after %u warm-up per configuration, three renderers taking turns frame by frame: "
               "no shadows (\"off\"), shadows with the cache (nothing moves: the maps are kept) and shadows without "
               "it (every map every frame, \"no cache\"). GL: %s, %s, on %s (%zu cores; 1-minute load average %.1f "
               "before the run, %.1f after). Times: %s, medians; the frame's time includes the shadow maps' "
               "(tl_frame_stats.gpu_ms). Share: 1 - off / on. Lookup: the light pass (light-cull + lights, "
               "lights-tiled or forward) with shadows minus without. Wrong: the shadow terms of %s (each light "
               "alone, ambient and emission off) against the ray-traced truth (Embree), pixels in the wrong "
               "lit/shadowed state over the counted pixels (those more than %d pixels from a change of the truth's "
               "state or of the object hit), added up over the lights; acne: shadowed but lit in the truth, leaks "
               "the opposite; vs fat: pixels whose state differs from fat's term (same strategy and depth).\n\n",
            run->scene_name, r0->width, r0->height, r0->lights, run->light_definition, r0->casting_lights,
            run->shadow_casters, run->opt.frames, run->opt.warmup, run->gl_renderer, run->gl_version, run->cpu, run->cores, run->load_start,
            run->load_end, run->timers_ok ? "GPU timer queries" : "wall clock",
            run->shadow_truth_light[0] ? run->shadow_truth_light : "one light", BENCH_SHADOW_BAND);
    if (run->shadow_truth_why[0]) fprintf(f, "No truth in this run: %s.\n\n", run->shadow_truth_why);
}

static void bench__md_row(FILE *f, const bench_shadow_record *r)
{
    char a[24], b[24], c[24];
    fprintf(f, "| %s | %.1f | %.1f | %.1f %% | %.1f | %.1f | %.1f | %.1f | %.1f | %u / %u | %.0f |",
            bench_config_name(r->config), r->frame_ms_off, r->frame_ms, 100.0 * bench__share(r), r->frame_ms_nocache,
            r->shadow_ms, r->shadow_ms_nocache, r->light_ms, r->lookup_ms, r->maps_rendered, r->maps_cached,
            (double)r->atlas_bytes / 1048576.0);
    for (int d = 0; d < BENCH_SHADOW_DEPTHS; d++) {
        const bench_shadow_error *e = &r->truth[d];
        if (e->measured)
            fprintf(f, " %s (%llu / %llu of %llu) | %s |", bench__pct(a, sizeof a, e->wrong),
                    (unsigned long long)e->acne, (unsigned long long)e->leaks, (unsigned long long)e->counted,
                    bench__pct(b, sizeof b, e->vs_fat));
        else fprintf(f, " %s | %s |", bench__pct(a, sizeof a, NAN), bench__pct(c, sizeof c, NAN));
    }
    fputc('\n', f);
}

static int bench__write_doc(FILE *f, const void *ctx)
{
    const bench__shadows_doc *d = ctx;
    const bench_run *run = d->run;
    fwrite(d->text, 1, d->head, f);
    bench__md_intro(f, run);
    fputs("| mode | off ms | on ms | share | no cache ms | maps ms | maps ms, no cache | light pass ms | lookup ms | "
          "maps rendered / kept | atlas MiB | D24 wrong (acne / leaks of counted) | D24 vs fat | "
          "D32F-rev wrong (acne / leaks of counted) | D32F-rev vs fat |\n"
          "|------|-------:|------:|------:|------------:|--------:|------------------:|--------------:|----------:|"
          "---------------------:|----------:|------------------------:|-----------:|-----------------------------:|"
          "----------------:|\n", f);
    for (size_t i = 0; i < run->shadow_count; i++) bench__md_row(f, &run->shadows[i]);
    if (d->plot) fputs("\n![Shadow error against frame time](img/" BENCH_SHADOWS_PLOT ".png)\n", f);
    else fputs("\n(The plot was not regenerated: the run had no --out, --no-plot or no gnuplot.)\n", f);
    fputc('\n', f);
    fputs(d->tail, f);
    return 0;
}

int bench_shadows_update_doc(const bench_run *run, const char *doc_text)
{
    const char *path = run->opt.shadows_doc;
    bench__shadows_doc d = {.run = run, .text = doc_text};
    if (!run->shadow_count) {
        fprintf(stderr, BENCH_TOOL ": warning: --shadows-doc %s: no shadow record was measured, the file is "
                        "unchanged\n", path);
        return 0;
    }
    if (tl_tool_doc_split(BENCH_TOOL, path, doc_text, BENCH_SHADOWS_DOC_BEGIN, BENCH_SHADOWS_DOC_END, &d.head, &d.tail))
        return 1;
    int err = 0;
    if (run->shadow_plot_made) {
        char *dir = tl_tool_dir_of(path), *img = dir ? tl_tool_strf("%s/img", dir) : NULL;
        char *src = tl_tool_strf("%s/%s.png", run->opt.out, BENCH_SHADOWS_PLOT);
        char *dst = img ? tl_tool_strf("%s/%s.png", img, BENCH_SHADOWS_PLOT) : NULL;
        err = !src || !dst || tl_tool_make_dirs(img) || tl_tool_copy_file(BENCH_TOOL, src, dst);
        if (err && (!src || !dst)) tl_tool_fail(BENCH_TOOL, "out of memory");
        else if (err && !tl_tool_is_dir(img)) tl_tool_fail(BENCH_TOOL, "cannot create '%s'", img);
        d.plot = !err;
        free(dir), free(img), free(src), free(dst);
    }
    return err || tl_tool_write_atomic(BENCH_TOOL, path, bench__write_doc, &d);
}
