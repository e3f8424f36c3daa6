/* What the frame planner saves (docs/frame.md, "The frame planner"): each mode's plan for the scene against the
 * plan the renderer makes with tl_renderer_options.planning off (every feature planned for, whatever
 * the scene uses). Pure: tl_frame_plan_build needs no GL; bench_sweep adds the frame times. */
#include <math.h>
#include <string.h>

#include "bench.h"
#include "tool_util.h"

int bench_planning_compare(bench_run *run, bench_scene *scene)
{
    const bench_options *opt = &run->opt;
    const tl_light *lights;
    size_t count;
    if (bench_scene_lights(scene, opt->lights[opt->light_count - 1], &lights, &count)) return 1;
    tl_scene lit = *bench_scene_get(scene); /* shallow: only the light array differs */
    lit.lights = (tl_light *)lights;
    lit.light_count = count;
    tl_scene_feature_set features;
    tl_scene_features(&lit, &features);
    tl_render_mode modes[BENCH_MODES]; /* fat first, then the requested modes (the planner's strategy) */
    size_t mode_count = 0;
    modes[mode_count++] = BENCH_REFERENCE;
    for (size_t i = 0; i < opt->mode_count; i++)
        if (opt->modes[i] != BENCH_REFERENCE) modes[mode_count++] = opt->modes[i];
    run->planning_count = 0;
    for (size_t m = 0; m < mode_count; m++) {
        tl_frame_plan plan, full;
        tl_renderer_desc desc = bench_config_desc(opt, bench_config_make(modes[m], TL_LIGHT_STRATEGY_DEFAULT),
                                                  opt->sizes[0].width, opt->sizes[0].height);
        tl_result a = tl_frame_plan_build(&desc, &features, &plan);
        desc.options.planning = TL_SWITCH_OFF;
        tl_result b = tl_frame_plan_build(&desc, &features, &full);
        if (a != TL_OK || b != TL_OK) {
            tl_tool_fail(BENCH_TOOL, "%s: tl_frame_plan_build: %s", tl_render_mode_name(modes[m]),
                         tl_result_string(a != TL_OK ? a : b));
            return 1;
        }
        run->planning[run->planning_count++] = (bench_planning){
            .mode = modes[m],
            .bytes_per_pixel = plan.bytes_per_pixel,
            .unplanned_bytes_per_pixel = full.bytes_per_pixel,
            .programs = plan.program_count,
            .unplanned_programs = full.program_count,
            .passes = plan.pass_count,
            .unplanned_passes = full.pass_count,
            .planned_ms = NAN,
            .unplanned_ms = NAN,
        };
    }
    return 0;
}
