/* thinlight-bench: the memory and bandwidth comparison of the four render modes (docs/tools.md). This file holds the order of the work and the checks before it (the command line:
 * bench_args.c); see bench.h. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "bench_shadows.h"
#include "tool_util.h"

/* Everything that can fail for bad input is checked before the sweep; nothing is created unless
 * every check passes. */
/* A doc the run will rewrite: a regular file (checked first: a FIFO is never opened), readable,
 * with both markers. */
static int bench__check_doc(const char *path, const char *begin, const char *end, char **text)
{
    if (tl_tool_check_output(BENCH_TOOL, path)) return 1;
    *text = tl_tool_read_file(path, NULL);
    if (!*text) {
        tl_tool_fail(BENCH_TOOL, "cannot read '%s': %s", path, strerror(errno));
        return 1;
    }
    size_t head;
    const char *tail;
    return tl_tool_doc_split(BENCH_TOOL, path, *text, begin, end, &head, &tail);
}

static int bench__check_outputs(bench_options *o, char **doc_text, char **effects_text, char **aa_text,
                                char **shadows_text)
{
    int e;
    if (o->out && !tl_tool_have_io()) {
        tl_tool_fail(BENCH_TOOL, "--out %s: %s (--json and the table need nothing)", o->out, tl_tool_no_io_images);
        return 1;
    }
    if (o->json) { /* like --out, the JSON's directory is created when missing */
        char *dir = tl_tool_dir_of(o->json);
        e = dir ? tl_tool_make_dirs(dir) : ENOMEM;
        free(dir);
        if (e) {
            tl_tool_fail(BENCH_TOOL, "cannot write '%s': %s", o->json, strerror(e));
            return 1;
        }
    }
    if (o->json && tl_tool_check_output(BENCH_TOOL, o->json)) return 1;
    if (o->doc && bench__check_doc(o->doc, BENCH_DOC_BEGIN, BENCH_DOC_END, doc_text)) return 1;
    if (o->effects_doc && bench__check_doc(o->effects_doc, BENCH_EFFECTS_DOC_BEGIN, BENCH_EFFECTS_DOC_END, effects_text))
        return 1;
    char aa_begin[128], aa_end[128];
    bench_aa_doc_markers(o, aa_begin, aa_end, sizeof aa_begin);
    if (o->aa_doc && bench__check_doc(o->aa_doc, aa_begin, aa_end, aa_text)) return 1;
    if (o->shadows_doc &&
        bench__check_doc(o->shadows_doc, BENCH_SHADOWS_DOC_BEGIN, BENCH_SHADOWS_DOC_END, shadows_text))
        return 1;
    if (o->out && !o->no_plot && !tl_tool_have_gnuplot()) {
        fprintf(stderr, BENCH_TOOL ": warning: gnuplot not found on PATH, no plots (install gnuplot-nox)\n");
        o->no_plot = 1;
    }
    if (o->out) {
        if ((e = tl_tool_make_dirs(o->out)) != 0) {
            tl_tool_fail(BENCH_TOOL, "cannot create output directory '%s': %s", o->out, strerror(e));
            return 1;
        }
        char *probe = tl_tool_strf("%s/bench_probe.png", o->out);
        e = probe ? tl_tool_check_output(BENCH_TOOL, probe) : 1;
        if (!probe) tl_tool_fail(BENCH_TOOL, "out of memory");
        free(probe);
        if (e) return 1;
    }
    if (o->doc && !o->no_plot) {
        char *dir = tl_tool_dir_of(o->doc), *img = dir ? tl_tool_strf("%s/img", dir) : NULL;
        e = img ? tl_tool_make_dirs(img) : ENOMEM;
        if (e) tl_tool_fail(BENCH_TOOL, "cannot create image directory '%s': %s", img ? img : "img", strerror(e));
        free(dir);
        free(img);
        if (e) return 1;
    }
    return 0;
}

/* With GGX lighting (asked, or the planner's choice for the scene) and no --fresnel, thin-lpp/tiled
 * is also measured with the cheaper Fresnel layout, so the report shows both. */
static void bench__fresnel_variant(bench_options *o, bench_scene *scene)
{
    tl_scene_feature_set features;
    tl_frame_plan plan;
    tl_scene_features(bench_scene_get(scene), &features);
    tl_renderer_desc desc = bench_config_desc(o, bench_config_make(TL_MODE_THIN_LPP, TL_LIGHT_STRATEGY_DEFAULT), 64, 64);
    o->fresnel_nv_variant = o->base.fresnel == TL_FRESNEL_DEFAULT && tl_frame_plan_build(&desc, &features, &plan) == TL_OK &&
                            plan.lighting == TL_LIGHTING_GGX;
}

int main(int argc, char **argv)
{
    bench_run *run = calloc(1, sizeof *run);
    if (!run) {
        tl_tool_fail(BENCH_TOOL, "out of memory");
        return BENCH_EXIT_BAD_INPUT;
    }
    run->log.tool = BENCH_TOOL;
    int rc = bench_parse_args(argc, argv, &run->opt);
    if (rc || run->opt.context_args.list_devices) {
        if (!rc) rc = tl_tool_list_devices(BENCH_TOOL);
        free(run);
        return rc < 0 ? 0 : rc;
    }
    bench_options *opt = &run->opt;
    char *doc_text = NULL, *effects_text = NULL, *aa_text = NULL, *shadows_text = NULL;
    bench_scene *scene = NULL;
    rc = BENCH_EXIT_BAD_INPUT;
    if (tl_tool_environment_read(BENCH_TOOL, &opt->env) || bench_scene_open(opt, &scene, run) ||
        bench__check_outputs(opt, &doc_text, &effects_text, &aa_text, &shadows_text) ||
        bench_aa_check_budget(run, scene))
        goto done;
    bench__fresnel_variant(opt, scene);
    tl_tool_machine(run->cpu, sizeof run->cpu, &run->cores);
    /* the plans first: the sweep times each planned mode against its renderer with planning off */
    if (bench_planning_compare(run, scene) || bench_sweep(run, scene)) goto done;
    int plot_failed = opt->out && !opt->no_plot && (bench_plots(run) || bench_aa_plot(run) || bench_shadows_plot(run));
    bench_print_table(run);
    bench_effects_print_table(run);
    bench_aa_print_table(run);
    bench_shadows_print_table(run);
    if (opt->json && bench_write_json(run, opt->json)) goto done;
    if (opt->doc && bench_update_doc(run, doc_text)) goto done;
    if (opt->effects_doc && bench_effects_update_doc(run, effects_text)) goto done;
    if (opt->aa_doc && bench_aa_update_doc(run, aa_text)) goto done;
    if (opt->shadows_doc && bench_shadows_update_doc(run, shadows_text)) goto done;
    rc = plot_failed ? BENCH_EXIT_BAD_INPUT : 0;
done:
    tl_tool_environment_free(&opt->env);
    bench_scene_close(scene);
    free(doc_text);
    free(effects_text);
    free(aa_text);
    free(shadows_text);
    free(run->shadows);
    free(run->effects);
    bench_aa_free(run);
    for (size_t i = 0; i < run->record_count; i++) free(run->records[i].frame_ms);
    free(run->records);
    free(run->images);
    free(run);
    return rc;
}
