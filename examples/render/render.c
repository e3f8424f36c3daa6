/* thinlight-render: renders the built-in scene or a glTF file headless and writes the
 * final image (PNG) or the HDR image (EXR); optionally every intermediate target. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "render.h"
#include "thinlight/context.h"
#include "tool_log.h"
#include "tool_util.h"

static const char *ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), m = strlen(suffix);
    return n >= m && strcmp(s + n - m, suffix) == 0 ? s + n - m : NULL;
}

static void print_plan(tl_renderer *r, const tl_frame_stats *st, const tl_scene *scene)
{
    tl_frame_plan plan;
    if (tl_renderer_get_plan(r, &plan) != TL_OK) return;
    size_t need = tl_frame_plan_format(&plan, NULL, 0);
    char *text = malloc(need + 1);
    if (!text) return;
    tl_frame_plan_format(&plan, text, need + 1);
    fputs(text, stdout);
    free(text);
    printf("light volumes drawn: %u point (spheres), %u spot (cones), %u directional (full screen)\n",
           st->lights_drawn[TL_LIGHT_POINT], st->lights_drawn[TL_LIGHT_SPOT], st->lights_drawn[TL_LIGHT_DIRECTIONAL]);
    printf("scene: %zu objects, %zu triangles, %zu lights\n", scene->object_count, scene->index_count / 3,
           scene->light_count);
}

static int dump_targets(tl_renderer *r, const char *dir, uint32_t w, uint32_t h)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "thinlight-render: cannot create %s: %s\n", dir, strerror(errno));
        return 1;
    }
    size_t n = (size_t)w * h * 4;
    float *buf = malloc(n * sizeof *buf);
    if (!buf) {
        fprintf(stderr, "thinlight-render: out of memory\n");
        return 1;
    }
    /* file names (the light lists and the fix-up list are storage buffers: no image) */
    static const char *const names[TL_TARGET_COUNT] = {
        [TL_TARGET_DEPTH] = "depth",           [TL_TARGET_RT0] = "rt0_normal_gloss",
        [TL_TARGET_RT1] = "rt1_albedo",        [TL_TARGET_LIGHT_DIFFUSE] = "light_diffuse",
        [TL_TARGET_LIGHT_SPECULAR] = "light_specular", [TL_TARGET_FAT_POSITION] = "fat_position",
        [TL_TARGET_FAT_NORMAL] = "fat_normal", [TL_TARGET_FAT_ALBEDO] = "fat_albedo",
        [TL_TARGET_FAT_MATERIAL] = "fat_material", [TL_TARGET_HDR] = "hdr",
        [TL_TARGET_LDR] = "ldr",               [TL_TARGET_OUTPUT] = "output",
        [TL_TARGET_AO_RAW] = "ao_raw",         [TL_TARGET_AO] = "ao",
        [TL_TARGET_DOF] = "dof",               [TL_TARGET_LIGHT_FRESNEL] = "light_fresnel",
        [TL_TARGET_BLOOM] = "bloom",           [TL_TARGET_SSR] = "ssr",
        [TL_TARGET_LIGHT_DEPTH] = "light_depth", [TL_TARGET_LIGHT_RT0] = "light_rt0_normal_gloss",
        [TL_TARGET_LIGHT_OFFSET] = "light_offset", [TL_TARGET_LIGHT_REDUCED_DIFFUSE] = "light_reduced_diffuse",
        [TL_TARGET_LIGHT_REDUCED_SPECULAR] = "light_reduced_specular",
        [TL_TARGET_LIGHT_REDUCED_FRESNEL] = "light_reduced_fresnel",
        [TL_TARGET_VIS_ID] = "vis_id"}; /* as read back: object slot, triangle, drawn, 1 (-1, -1, 0, 1: nothing) */
    tl_frame_plan plan;
    if (tl_renderer_get_plan(r, &plan) != TL_OK) memset(&plan, 0, sizeof plan);
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        size_t size = n * sizeof *buf;
        uint32_t tw = plan.target_info[t].width ? plan.target_info[t].width : w; /* bloom: half size */
        uint32_t th = plan.target_info[t].height ? plan.target_info[t].height : h;
        if (!names[t] || !(plan.targets & TL_TARGET_BIT(t))) continue; /* a storage buffer, or not planned */
        if (tl_renderer_read_target(r, (tl_target_id)t, buf, &size) != TL_OK) { /* the renderer logged why */
            free(buf);
            return 1;
        }
        char path[4096];
        snprintf(path, sizeof path, "%s/%s.exr", dir, names[t]);
        /* each at its own precision: half floats hold 16F targets and 8-bit channels exactly; depth
         * (24 or 32 bits, read as window depth and distance), the decoded RT0 normal (2 x 10 or 12
         * bits), visibility's id (triangles up to 2^20, past half's 2^11 integers) and 32-bit float
         * targets need full floats */
        int full = t == TL_TARGET_DEPTH || t == TL_TARGET_RT0 || t == TL_TARGET_LIGHT_DEPTH || t == TL_TARGET_LIGHT_RT0 ||
                   t == TL_TARGET_VIS_ID || plan.target_bytes_per_pixel[t] >= 16;
        tl_image_desc id = {.width = tw, .height = th, .channels = 4, .type = TL_PIXEL_F32, .bottom_up = 1,
                            .full_float = full};
        if (tl_tool_write_image("thinlight-render", path, &id, buf)) {
            free(buf);
            return 1;
        }
        fprintf(stderr, "wrote %s\n", path);
    }
    free(buf);
    return 0;
}

/* Bad input found before any work (so that no context line precedes the one saying why); 0 or 1. */
static int check_inputs(render_args *a)
{
    if (a->out) {
        a->hdr_out = ends_with(a->out, ".exr") != NULL;
        if (!a->hdr_out && !ends_with(a->out, ".png")) {
            fprintf(stderr, "thinlight-render: output %s must end in .png or .exr\n", a->out);
            return 1;
        }
    }
    const char *image = a->out ? a->out : a->dump;
    if (image && !tl_tool_have_io()) {
        fprintf(stderr, "thinlight-render: %s %s: %s (--stats and --print-plan need nothing)\n",
                a->out ? "-o" : "--dump-targets", image, tl_tool_no_io_images);
        return 1;
    }
    return a->out ? tl_tool_check_output("thinlight-render", a->out) : 0;
}

/* The glTF file or the built-in crypt with the lights the command line asks for; 0 or 1. */
static int load_scene(render_args *a, tl_tool_log *log, tl_scene **out)
{
    tl_scene *scene = NULL;
    tl_result res;
    if (strcmp(a->scene, "showcase") == 0) { /* the material models' spheres (scene.h) */
        res = tl_scene_create_showcase(&(tl_showcase_scene_desc){.point_lights = a->sd.point_lights, .seed = a->sd.seed},
                                       out);
        if (res != TL_OK) fprintf(stderr, "thinlight-render: building the showcase scene: %s\n", tl_result_string(res));
        return res != TL_OK;
    }
    if (strcmp(a->scene, "default") != 0) {
        /* a glTF file: its own lights (or the default rig), plus --lights N seeded point lights;
         * with --shadows the loader's rule makes them cast up to the budget (docs/gltf.md) */
        char gerr[1024] = "";
        uint32_t budget = a->rd.options.shadows.max_lights ? a->rd.options.shadows.max_lights : TL_SHADOW_DEFAULT_MAX_LIGHTS;
        tl_gltf_options o = {.extra_lights = a->sd.point_lights, .seed = a->sd.seed,
                             .shadow_lights = a->sd.shadows ? budget : 0};
        tl_tool_budget_gltf(&a->budgets, &o);
        res = tl_tool_load_gltf(a->scene, &o, log, out, gerr, sizeof gerr);
        if (res != TL_OK) tl_tool_log_error(log, "%s", gerr[0] ? gerr : tl_result_string(res));
        return res != TL_OK;
    }
    res = tl_scene_create_default(&a->sd, &scene);
    if (res != TL_OK) {
        fprintf(stderr, "thinlight-render: building the default scene: %s\n", tl_result_string(res));
        return 1;
    }
    /* In the scene descriptor zero means "default"; on the command line it means none. */
    if (a->zero_points && !a->zero_spots && a->sd.spot_lights == 0) a->zero_spots = 1;
    size_t kept = 0;
    for (size_t i = 0; i < scene->light_count; i++) {
        tl_light_type t = scene->lights[i].type == TL_LIGHT_DEFAULT ? TL_LIGHT_POINT : scene->lights[i].type;
        if ((t == TL_LIGHT_POINT && a->zero_points) || (t == TL_LIGHT_SPOT && a->zero_spots)) continue;
        scene->lights[kept++] = scene->lights[i];
    }
    scene->light_count = kept;
    *out = scene;
    return 0;
}

static void print_stats(tl_renderer *r, const tl_frame_stats *st, const tl_scene *scene, uint32_t w, uint32_t h)
{
    size_t px = (size_t)w * h;
    printf("%ux%u, %zu lights, %u objects drawn, %u draw calls\n", w, h, scene->light_count, st->objects_drawn,
           st->draw_calls);
    tl_frame_plan fp;
    if (tl_renderer_get_plan(r, &fp) == TL_OK)
        for (size_t i = 0; i < fp.pass_count; i++) {
            tl_pass p = fp.passes[i].pass;
            printf("  %-13s %8.2f ms %10llu fragments %8.2f MB moved (estimate)\n", tl_pass_name(p), st->pass_ms[p],
                   (unsigned long long)st->pass_fragments[p], st->pass_bytes[p] * 1e-6);
        }
    printf("  %-9s %8.2f ms GPU, %.2f ms wall (%.2f ms issuing commands)\n", "frame", st->gpu_ms, st->wall_ms,
           st->cpu_ms);
    for (int t = 0; t < TL_TARGET_COUNT; t++)
        if (st->target_bytes[t])
            printf("  %-15s %5.1f B/px %8.2f MiB\n", tl_target_name((tl_target_id)t),
                   (double)st->target_bytes[t] / (double)px, (double)st->target_bytes[t] / 1048576.0);
    printf("  G-buffer %.1f B/px + light buffer %.1f B/px; all targets %.1f B/px, allocated %.1f B/px "
           "(targets with disjoint lifetimes share memory)\n",
           (double)st->gbuffer_bytes / (double)px, (double)st->light_buffer_bytes / (double)px,
           (double)st->total_target_bytes / (double)px, (double)st->allocated_target_bytes / (double)px);
    if (st->light_pairs)
        printf("  %llu pixel-light pairs shaded%s\n", (unsigned long long)st->light_pairs,
               st->tile_overflows ? " (some tiles overflowed their lists and looped over every light)" : "");
    if (st->relit_pixels)
        printf("  %llu pixels re-lit at full resolution by the light scale's edge fix-up (%.2f %% of the frame)\n",
               (unsigned long long)st->relit_pixels, 100.0 * st->relit_fraction);
    if (st->shadow_atlas_bytes)
        printf("  shadows: %u lights with a map (%u fading, %u in view without one: over --shadow-max), %u maps "
               "rendered, %u kept, atlas %.1f MiB, shadow maps %.2f ms GPU (part of the frame's)\n", st->shadow_lights,
               st->shadow_lights_fading, st->shadow_lights_unmapped,
               st->shadow_maps_rendered, st->shadow_maps_cached, (double)st->shadow_atlas_bytes / 1048576.0,
               st->shadow_ms);
}

/* -o: the final image (PNG) or the HDR target (EXR); 0 or 1. */
static int write_output(tl_renderer *r, const render_args *a, tl_tool_log *log)
{
    size_t n = (size_t)a->rd.width * a->rd.height * 4;
    void *pixels = a->hdr_out ? malloc(n * sizeof(float)) : malloc(n);
    tl_image_desc id = {.width = a->rd.width, .height = a->rd.height, .channels = 4,
                        .type = a->hdr_out ? TL_PIXEL_F32 : TL_PIXEL_U8, .bottom_up = 1};
    int rc = 0;
    if (!pixels) {
        fprintf(stderr, "thinlight-render: out of memory\n");
        rc = 1;
    } else if ((a->hdr_out ? tl_renderer_read_target(r, TL_TARGET_HDR, pixels, &(size_t){n * sizeof(float)})
                           : tl_renderer_read_output(r, pixels, &(size_t){n})) != TL_OK) {
        tl_tool_log_error(log, "%s", tl_renderer_last_error(r)); /* once: the logger may have said it */
        rc = 1;
    } else {
        rc = tl_tool_write_image("thinlight-render", a->out, &id, pixels);
    }
    free(pixels);
    return rc;
}

/* --shadow-move: the first casting local light (or, for an object, the object whose origin is
 * nearest it) moves 1 cm along x each frame after the first, so the shadow cache keeps every map
 * but that light's (or those whose frusta hold the object). */
static tl_result move_for_shadows(tl_renderer *r, const tl_scene *scene, tl_light *lights, int what, uint32_t f)
{
    size_t li = 0;
    while (li < scene->light_count && (!lights[li].shadow || lights[li].type == TL_LIGHT_DIRECTIONAL)) li++;
    if (li == scene->light_count || f == 0) return TL_OK;
    if (what == 1) {
        lights[li].position[0] += 0.01f;
        return tl_renderer_set_lights(r, lights, scene->light_count);
    }
    size_t best = 0;
    float best_d = INFINITY;
    for (size_t i = 0; i < scene->object_count; i++) {
        const float *m = scene->objects[i].transform, *p = lights[li].position;
        float d = (m[12] - p[0]) * (m[12] - p[0]) + (m[13] - p[1]) * (m[13] - p[1]) + (m[14] - p[2]) * (m[14] - p[2]);
        if (d < best_d) best_d = d, best = i;
    }
    float m[16];
    memcpy(m, scene->objects[best].transform, sizeof m);
    if (m[15] == 0.0f) m[0] = m[5] = m[10] = m[15] = 1.0f; /* all zero: the identity */
    m[12] += 0.01f * (float)f;
    return tl_renderer_set_object_transform(r, (uint32_t)best, m);
}

/* Renders the frames and writes what was asked for; 0 or 1. A failed call's message goes through
 * the log, which printed it already when the renderer's logger did. */
static int render(render_args *a, tl_renderer *r, const tl_scene *scene, tl_tool_log *log)
{
    tl_frame_stats st;
    memset(&st, 0, sizeof st);
    if (tl_renderer_set_scene(r, scene) != TL_OK) {
        tl_tool_log_error(log, "%s", tl_renderer_last_error(r));
        return 1;
    }
    if (tl_tool_environment_set(RENDER_TOOL, &a->env, r)) return 1;
    tl_light *lights = a->shadow_move ? malloc(scene->light_count * sizeof *lights + 1) : NULL;
    if (lights) memcpy(lights, scene->lights, scene->light_count * sizeof *lights);
    for (uint32_t f = 0; f < a->frames; f++) {
        if (a->frames > 1 && f % 10 == 0) fprintf(stderr, "\rframe %u/%u", f + 1, a->frames);
        if ((lights && move_for_shadows(r, scene, lights, a->shadow_move, f) != TL_OK) ||
            tl_renderer_render(r, NULL, &st) != TL_OK) {
            free(lights);
            if (a->frames > 1) fputc('\n', stderr);
            tl_tool_log_error(log, "%s", tl_renderer_last_error(r));
            return 1;
        }
    }
    free(lights);
    if (a->frames > 1) fprintf(stderr, "\n");
    if (a->plan) print_plan(r, &st, scene);
    if (a->stats) print_stats(r, &st, scene, a->rd.width, a->rd.height);
    if (a->out && write_output(r, a, log)) return 1;
    if (a->dump && dump_targets(r, a->dump, a->rd.width, a->rd.height)) return 1;
    return 0;
}

/* The renderer's descriptor but for the context; 0, or 1 when its targets are over the budget
 * (checked from the plan before a context is made: one line, nothing allocated). */
static int describe_renderer(render_args *a, const tl_scene *scene, tl_tool_log *log)
{
    if (!a->rd.width) {
        a->rd.width = 1280;
        a->rd.height = 720;
    }
    a->rd.logger = tl_tool_log_logger(log);
    a->rd.options.synchronous_stats = a->stats || a->plan; /* their figures describe the frame just rendered */
    if (a->dump) a->rd.options.keep_targets = TL_TARGETS_ALL;
    if (a->hdr_out) a->rd.options.keep_targets |= TL_TARGET_BIT(TL_TARGET_HDR);
    tl_tool_budget_renderer(&a->budgets, &a->rd);
    return tl_tool_budget_check(RENDER_TOOL, NULL, &a->rd, scene);
}

int main(int argc, char **argv)
{
    static render_args a;
    static tl_tool_log log = {.tool = RENDER_TOOL};
    int rc = render_parse_args(argc, argv, &a);
    if (rc) return rc < 0 ? 0 : rc;
    if (a.context_args.list_devices) return tl_tool_list_devices(RENDER_TOOL);
    if (check_inputs(&a)) return 1;
    tl_scene *scene = NULL;
    if (tl_tool_environment_read(RENDER_TOOL, &a.env)) return 1; /* a bad file: one line, before any context */
    if (load_scene(&a, &log, &scene)) {
        tl_tool_environment_free(&a.env);
        return 1;
    }
    tl_context *ctx = NULL;
    if (describe_renderer(&a, scene, &log) ||
        tl_tool_context_open(RENDER_TOOL, &a.ctx, a.rd.width, a.rd.height, &ctx)) {
        tl_scene_destroy(scene);
        tl_tool_environment_free(&a.env);
        return 1;
    }
    a.rd.get_proc_address = tl_context_proc_loader;
    a.rd.get_proc_address_user = ctx;
    tl_renderer *r = NULL;
    if (tl_renderer_create(&a.rd, &r) != TL_OK) rc = 1; /* the logger said why */
    if (!rc) rc = render(&a, r, scene, &log);
    tl_renderer_destroy(r);
    tl_context_destroy(ctx);
    tl_scene_destroy(scene);
    tl_tool_environment_free(&a.env);
    return rc;
}
