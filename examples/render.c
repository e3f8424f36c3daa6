/* thinlight-render: renders the built-in scene or a glTF file headless and writes the
 * final image (PNG) or the HDR image (EXR); optionally every intermediate target. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "thinlight/context.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"
#include "tool_effects.h"
#include "tool_gl.h"
#include "tool_log.h"
#include "tool_util.h"

static const char *const usage =
    "usage: thinlight-render SCENE.gltf|SCENE.glb|default -o OUT.png|OUT.exr [options]\n"
    "       thinlight-render SCENE.gltf|SCENE.glb|default --stats|--print-plan [options]\n"
    "       thinlight-render --list-devices\n"
    "  --size WxH            image size (default 1280x720)\n"
    "  --mode MODE           thin-lpp (default), thin-deferred, fat or forward\n"
    "  --no-depth-prepass    forward mode without its depth pre-pass\n"
    "  --lights N            point lights of the built-in scene (default 64); for a glTF\n"
    "                        file, N seeded point lights added within its bounds\n"
    "  --spots N             spot lights (default lights/8)\n"
    "  --no-directional      leave out the directional light\n"
    "  --seed S              scene seed (default 1)\n"
    "  --depth FMT           d24 (default) or d32f-reversed\n"
    "  --rt0 FMT             rgba8 (default: oct 2x12 + gloss 8) or rgb10a2\n"
    "  --light-buffer L      exact (default: diffuse + specular RGBA16F) or compact (one RGBA16F)\n"
    "  --light-format F      rgba16f (default) or r11g11b10f (light buffer storage; exact layout)\n"
    "  --lighting M          auto (default: ggx for glTF materials, else blinn-phong), blinn-phong\n"
    "                        or ggx\n"
    "  --fresnel F           thin-lpp with GGX: two-sums (default: exact, light.fresnel target) or\n"
    "                        nv (one specular sum, Schlick with n.v per pixel)\n"
    "  --ambient A           ambient radiance replacing the scene's (0 turns it off)\n"
    "  --light-strategy S    auto (default), volumes or tiled\n"
    "  --tile-size T         tiled: 8, 16 (default) or 32 pixels\n"
    "  --tiled-shading K     tiled: fragment (default) or compute\n"
    "  --fxaa P              off, 12, 29 (default) or 39\n"
    "  --exposure E          exposure before tone mapping (default 1)\n"
    "  --frames N            render N frames and report the last (default 1)\n"
    "  --stats               print per-pass GPU times and target bytes\n"
    "  --print-plan          print the frame plan: passes, inputs, outputs, targets, programs\n"
    "  --dump-targets DIR    write every intermediate target as EXR into DIR\n"
    "%s"
    TL_TOOL_CONTEXT_HELP
    "  --help                this text\n"
    "An .exr output holds the HDR image before tone mapping; .png the final image. The context used\n"
    "is printed on stderr. A build without THINLIGHT_WITH_IO (docs/gpu-servers.md) reads no glTF and\n"
    "writes no image: -o, --dump-targets and a glTF scene fail with one line; --stats and\n"
    "--print-plan work.\n";

static int bad_usage(const char *msg, const char *arg)
{
    fprintf(stderr, "thinlight-render: %s%s%s\n", msg, arg ? ": " : "", arg ? arg : "");
    fprintf(stderr, usage, tl_tool_effects_help);
    return 2;
}

static int parse_u32(const char *s, uint32_t *out)
{
    char *end;
    errno = 0;
    unsigned long v = strtoul(s, &end, 10);
    if (errno || end == s || *end || v > 0xFFFFFFFFul || s[0] == '-') return 0;
    *out = (uint32_t)v;
    return 1;
}

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
    static const char *const names[TL_TARGET_COUNT] = {
        "depth",        "rt0_normal_gloss", "rt1_albedo", "light_diffuse", "light_specular", "fat_position",
        "fat_normal",   "fat_albedo",       "fat_material", "hdr",         "ldr",            "output", NULL,
        "ao_raw",       "ao",               "dof",          "light_fresnel", "bloom"};
    tl_frame_plan plan;
    if (tl_renderer_get_plan(r, &plan) != TL_OK) memset(&plan, 0, sizeof plan);
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        size_t size = n * sizeof *buf;
        uint32_t tw = plan.target_info[t].width ? plan.target_info[t].width : w; /* bloom: half size */
        uint32_t th = plan.target_info[t].height ? plan.target_info[t].height : h;
        if (!names[t]) continue; /* a storage buffer */
        if (tl_renderer_read_target(r, (tl_target_id)t, buf, &size) != TL_OK) continue; /* not allocated */
        char path[4096];
        snprintf(path, sizeof path, "%s/%s.exr", dir, names[t]);
        tl_image_desc id = {.width = tw, .height = th, .channels = 4, .type = TL_PIXEL_F32, .bottom_up = 1};
        if (tl_tool_write_image("thinlight-render", path, &id, buf)) {
            free(buf);
            return 1;
        }
        fprintf(stderr, "wrote %s\n", path);
    }
    free(buf);
    return 0;
}

/* The options choosing target formats and FXAA. */
static int parse_format(tl_renderer_desc *rd, const char *opt, const char *v)
{
    if (!strcmp(opt, "--depth")) {
        if (!strcmp(v, "d24")) rd->depth_format = TL_DEPTH_FORMAT_D24;
        else if (!strcmp(v, "d32f-reversed")) rd->depth_format = TL_DEPTH_FORMAT_D32F_REVERSED;
        else return bad_usage("--depth wants d24 or d32f-reversed", v);
    } else if (!strcmp(opt, "--rt0")) {
        if (!strcmp(v, "rgba8")) rd->rt0 = TL_RT0_RGBA8;
        else if (!strcmp(v, "rgb10a2")) rd->rt0 = TL_RT0_RGB10A2;
        else return bad_usage("--rt0 wants rgba8 or rgb10a2", v);
    } else if (!strcmp(opt, "--light-buffer")) {
        if (!strcmp(v, "exact")) rd->light_buffer = TL_LIGHT_BUFFER_EXACT;
        else if (!strcmp(v, "compact")) rd->light_buffer = TL_LIGHT_BUFFER_COMPACT;
        else return bad_usage("--light-buffer wants exact or compact", v);
    } else if (!strcmp(opt, "--light-format")) {
        if (!strcmp(v, "rgba16f")) rd->light_format = TL_LIGHT_FORMAT_RGBA16F;
        else if (!strcmp(v, "r11g11b10f")) rd->light_format = TL_LIGHT_FORMAT_R11G11B10F;
        else return bad_usage("--light-format wants rgba16f or r11g11b10f", v);
    } else if (!strcmp(opt, "--lighting")) {
        if (tl_lighting_model_from_name(v, &rd->lighting) != TL_OK)
            return bad_usage("--lighting wants blinn-phong, ggx or auto", v);
    } else if (!strcmp(opt, "--fresnel")) {
        if (tl_fresnel_layout_from_name(v, &rd->fresnel) != TL_OK) return bad_usage("--fresnel wants two-sums or nv", v);
    } else if (!strcmp(opt, "--ambient")) {
        float a;
        char extra;
        if (sscanf(v, "%f%c", &a, &extra) != 1 || !(a >= 0.0f) || a > 65504.0f)
            return bad_usage("--ambient wants a radiance >= 0", v);
        rd->ambient[0] = rd->ambient[1] = rd->ambient[2] = a > 0.0f ? a : -1.0f; /* negative: exactly 0 */
    } else if (!strcmp(opt, "--light-strategy")) {
        if (tl_light_strategy_from_name(v, &rd->light_strategy) != TL_OK)
            return bad_usage("--light-strategy wants volumes, tiled or auto", v);
    } else if (!strcmp(opt, "--tile-size")) {
        if (!parse_u32(v, &rd->tile_size) || (rd->tile_size != 8 && rd->tile_size != 16 && rd->tile_size != 32))
            return bad_usage("--tile-size wants 8, 16 or 32", v);
    } else if (!strcmp(opt, "--tiled-shading")) {
        if (!strcmp(v, "fragment")) rd->tiled_shading = TL_TILED_SHADING_FRAGMENT;
        else if (!strcmp(v, "compute")) rd->tiled_shading = TL_TILED_SHADING_COMPUTE;
        else return bad_usage("--tiled-shading wants fragment or compute", v);
    } else if (!strcmp(opt, "--fxaa")) {
        if (!strcmp(v, "off")) rd->fxaa = TL_FXAA_OFF;
        else if (!strcmp(v, "12")) rd->fxaa = TL_FXAA_12;
        else if (!strcmp(v, "29")) rd->fxaa = TL_FXAA_29;
        else if (!strcmp(v, "39")) rd->fxaa = TL_FXAA_39;
        else return bad_usage("--fxaa wants off, 12, 29 or 39", v);
    } else {
        return bad_usage("unknown option", opt);
    }
    return 0;
}

/* The command line. */
typedef struct render_args {
    const char *scene, *out, *dump, *context, *device;
    tl_renderer_desc rd;
    tl_default_scene_desc sd;
    uint32_t frames;
    int stats, plan, zero_points, zero_spots, list_devices, hdr_out;
    tl_tool_context_options ctx;
} render_args;

/* One option that takes a value; 0, or 2 after the usage text. */
static int parse_value(render_args *a, const char *opt, const char *v)
{
    tl_renderer_desc *rd = &a->rd;
    if (!strcmp(opt, "-o")) a->out = v;
    else if (!strcmp(opt, "--dump-targets")) a->dump = v;
    else if (!strcmp(opt, "--context")) a->context = v;
    else if (!strcmp(opt, "--device")) a->device = v;
    else if (!strcmp(opt, "--size")) {
        unsigned w = 0, h = 0;
        char extra;
        if (sscanf(v, "%ux%u%c", &w, &h, &extra) != 2) return bad_usage("--size wants WxH", v);
        if (!w || !h || w > 16384 || h > 16384) {
            fprintf(stderr, "thinlight-render: size %s is out of range (1..16384 per side)\n", v);
            return 1;
        }
        rd->width = w;
        rd->height = h;
    } else if (!strcmp(opt, "--mode")) {
        if (tl_render_mode_from_name(v, &rd->mode) != TL_OK)
            return bad_usage("--mode wants thin-lpp, thin-deferred, fat or forward", v);
    } else if (!strcmp(opt, "--lights")) {
        if (!parse_u32(v, &a->sd.point_lights)) return bad_usage("--lights wants a count", v);
        a->zero_points = a->sd.point_lights == 0;
    } else if (!strcmp(opt, "--spots")) {
        if (!parse_u32(v, &a->sd.spot_lights)) return bad_usage("--spots wants a count", v);
        a->zero_spots = a->sd.spot_lights == 0;
    } else if (!strcmp(opt, "--seed")) {
        uint32_t seed;
        if (!parse_u32(v, &seed)) return bad_usage("--seed wants a number", v);
        a->sd.seed = seed;
    } else if (!strcmp(opt, "--frames")) {
        if (!parse_u32(v, &a->frames) || !a->frames || a->frames > 100000) return bad_usage("--frames wants 1..100000", v);
    } else if (!strcmp(opt, "--exposure")) {
        char *end;
        rd->exposure = strtof(v, &end);
        if (*end || !(rd->exposure > 0.0f) || rd->exposure > 1e6f) return bad_usage("--exposure wants a positive number", v);
    } else {
        return parse_format(rd, opt, v);
    }
    return 0;
}

/* argv into `a`; -1 for --help (printed), 0, or the exit status after one line. */
static int parse_args(int argc, char **argv, render_args *a)
{
    memset(a, 0, sizeof *a);
    a->frames = 1;
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i];
        int rc = 0;
        if (!strcmp(o, "--help") || !strcmp(o, "-h")) {
            printf(usage, tl_tool_effects_help);
            return -1;
        } else if (!strcmp(o, "--stats")) a->stats = 1;
        else if (!strcmp(o, "--print-plan")) a->plan = 1;
        else if (!strcmp(o, "--list-devices")) a->list_devices = 1;
        else if (!strcmp(o, "--no-depth-prepass")) a->rd.forward_no_depth_prepass = 1;
        else if (!strcmp(o, "--no-directional")) a->sd.no_directional = 1;
        else if ((rc = tl_tool_effect_option("thinlight-render", &a->rd, o, i + 1 < argc ? argv[i + 1] : NULL)) != 0) {
            if (rc < 0) return 2;
            i += rc - 1;
            rc = 0;
        } else if (o[0] == '-' && strcmp(o, "-") != 0) {
            if (i + 1 >= argc) return bad_usage("missing value for", o);
            rc = parse_value(a, o, argv[++i]);
        } else if (!a->scene) a->scene = o;
        else return bad_usage("unexpected argument", o);
        if (rc) return rc;
    }
    if (a->list_devices) return 0;
    if (!a->scene) return bad_usage("no scene given (use 'default' for the built-in one)", NULL);
    if (!a->out && !a->stats && !a->plan)
        return bad_usage("no output given (-o OUT.png or OUT.exr, or --stats or --print-plan)", NULL);
    return tl_tool_context_parse("thinlight-render", a->context, a->device, &a->ctx);
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
    if (a->sd.point_lights > 65536 || a->sd.spot_lights > 65536) {
        fprintf(stderr, "thinlight-render: at most 65536 point and 65536 spot lights\n");
        return 1;
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
static int load_scene(render_args *a, tl_scene **out)
{
    tl_scene *scene = NULL;
    tl_result res;
    if (strcmp(a->scene, "default") != 0) {
        /* a glTF file: its own lights (or the default rig), plus --lights N seeded point lights */
        char gerr[1024] = "";
        res = tl_tool_load_gltf(a->scene, a->sd.point_lights, a->sd.seed, out, gerr, sizeof gerr);
        if (res != TL_OK) fprintf(stderr, "thinlight-render: %s\n", gerr[0] ? gerr : tl_result_string(res));
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
}

/* -o: the final image (PNG) or the HDR target (EXR); 0 or 1. */
static int write_output(tl_renderer *r, const render_args *a)
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
        fprintf(stderr, "thinlight-render: %s\n", tl_renderer_last_error(r));
        rc = 1;
    } else {
        rc = tl_tool_write_image("thinlight-render", a->out, &id, pixels);
    }
    free(pixels);
    return rc;
}

/* Renders the frames and writes what was asked for; 0 or 1. */
static int render(render_args *a, tl_renderer *r, const tl_scene *scene)
{
    tl_frame_stats st;
    memset(&st, 0, sizeof st);
    if (tl_renderer_set_scene(r, scene) != TL_OK) {
        fprintf(stderr, "thinlight-render: %s\n", tl_renderer_last_error(r));
        return 1;
    }
    for (uint32_t f = 0; f < a->frames; f++) {
        if (a->frames > 1 && f % 10 == 0) fprintf(stderr, "\rframe %u/%u", f + 1, a->frames);
        if (tl_renderer_render(r, NULL, &st) != TL_OK) {
            fprintf(stderr, "%sthinlight-render: %s\n", a->frames > 1 ? "\n" : "", tl_renderer_last_error(r));
            return 1;
        }
    }
    if (a->frames > 1) fprintf(stderr, "\n");
    if (a->plan) print_plan(r, &st, scene);
    if (a->stats) print_stats(r, &st, scene, a->rd.width, a->rd.height);
    if (a->out && write_output(r, a)) return 1;
    if (a->dump && dump_targets(r, a->dump, a->rd.width, a->rd.height)) return 1;
    return 0;
}

int main(int argc, char **argv)
{
    static render_args a;
    int rc = parse_args(argc, argv, &a);
    if (rc) return rc < 0 ? 0 : rc;
    if (a.list_devices) return tl_tool_list_devices("thinlight-render");
    if (check_inputs(&a)) return 1;
    tl_scene *scene = NULL;
    if (load_scene(&a, &scene)) return 1;
    if (!a.rd.width) {
        a.rd.width = 1280;
        a.rd.height = 720;
    }
    tl_context *ctx = NULL;
    if (tl_tool_context_open("thinlight-render", &a.ctx, a.rd.width, a.rd.height, &ctx)) {
        tl_scene_destroy(scene);
        return 1;
    }
    a.rd.get_proc_address = tl_context_proc_loader;
    a.rd.get_proc_address_user = ctx;
    a.rd.logger = tl_tool_logger("thinlight-render");
    a.rd.synchronous_stats = a.stats || a.plan; /* their figures describe the frame just rendered */
    if (a.dump) a.rd.keep_targets = TL_TARGETS_ALL;
    if (a.hdr_out) a.rd.keep_targets |= TL_TARGET_BIT(TL_TARGET_HDR);
    tl_renderer *r = NULL;
    if (tl_renderer_create(&a.rd, &r) != TL_OK) rc = 1; /* the logger said why */
    if (!rc) rc = render(&a, r, scene);
    tl_renderer_destroy(r);
    tl_context_destroy(ctx);
    tl_scene_destroy(scene);
    return rc;
}
