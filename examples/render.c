/* thinlight-render: renders the built-in scene or a glTF file headless and writes the
 * final image (PNG) or the HDR image (EXR); optionally every intermediate target. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "thinlight/context.h"
#include "thinlight/io.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"
#include "tool_util.h"

#define TOOL "thinlight-render"

static const char *const usage =
    "usage: thinlight-render SCENE.gltf|SCENE.glb|default -o OUT.png|OUT.exr [options]\n"
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
    "  --fxaa P              off, 12, 29 (default) or 39\n"
    "  --exposure E          exposure before tone mapping (default 1)\n"
    "  --frames N            render N frames and report the last (default 1)\n"
    "  --stats               print per-pass GPU times and target bytes\n"
    "  --print-plan          print the frame plan: passes, inputs, outputs, targets, programs\n"
    "  --dump-targets DIR    write every intermediate target as EXR into DIR\n"
    "  --help                this text\n"
    "An .exr output holds the HDR image before tone mapping; .png the final image.\n";

static int bad_usage(const char *msg, const char *arg)
{
    fprintf(stderr, "thinlight-render: %s%s%s\n%s", msg, arg ? ": " : "", arg ? arg : "", usage);
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
        "fat_normal",   "fat_albedo",       "fat_material", "hdr",         "ldr",            "output"};
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        if (tl_renderer_read_target(r, (tl_target_id)t, buf, n) != TL_OK) continue; /* not allocated */
        char path[4096];
        snprintf(path, sizeof path, "%s/%s.exr", dir, names[t]);
        tl_image_desc id = {w, h, 4, TL_PIXEL_F32, 1, TL_TOOL_LOGGER(TOOL)};
        if (tl_image_write(path, &id, buf) != TL_OK) {
            free(buf);
            return 1;
        }
        fprintf(stderr, "wrote %s\n", path);
    }
    free(buf);
    return 0;
}

int main(int argc, char **argv)
{
    const char *scene_arg = NULL, *out = NULL, *dump = NULL;
    tl_renderer_desc rd = {0};
    tl_default_scene_desc sd = {0};
    uint32_t frames = 1;
    int stats = 0, plan = 0, zero_points = 0, zero_spots = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(usage, stdout);
            return 0;
        } else if (!strcmp(a, "--stats")) {
            stats = 1;
        } else if (!strcmp(a, "--print-plan")) {
            plan = 1;
        } else if (!strcmp(a, "--no-depth-prepass")) {
            rd.forward_no_depth_prepass = 1;
        } else if (!strcmp(a, "--no-directional")) {
            sd.no_directional = 1;
        } else if (a[0] == '-' && strcmp(a, "-") != 0) {
            if (!v) return bad_usage("missing value for", a);
            i++;
            if (!strcmp(a, "-o")) {
                out = v;
            } else if (!strcmp(a, "--size")) {
                unsigned w = 0, h = 0;
                char extra;
                if (sscanf(v, "%ux%u%c", &w, &h, &extra) != 2) return bad_usage("--size wants WxH", v);
                if (!w || !h || w > 16384 || h > 16384) {
                    fprintf(stderr, "thinlight-render: size %s is out of range (1..16384 per side)\n", v);
                    return 1;
                }
                rd.width = w;
                rd.height = h;
            } else if (!strcmp(a, "--mode")) {
                if (tl_render_mode_from_name(v, &rd.mode) != TL_OK)
                    return bad_usage("--mode wants thin-lpp, thin-deferred, fat or forward", v);
            } else if (!strcmp(a, "--lights")) {
                if (!parse_u32(v, &sd.point_lights)) return bad_usage("--lights wants a count", v);
                zero_points = sd.point_lights == 0;
            } else if (!strcmp(a, "--spots")) {
                if (!parse_u32(v, &sd.spot_lights)) return bad_usage("--spots wants a count", v);
                zero_spots = sd.spot_lights == 0;
            } else if (!strcmp(a, "--seed")) {
                uint32_t s;
                if (!parse_u32(v, &s)) return bad_usage("--seed wants a number", v);
                sd.seed = s;
            } else if (!strcmp(a, "--frames")) {
                if (!parse_u32(v, &frames) || !frames || frames > 100000) return bad_usage("--frames wants 1..100000", v);
            } else if (!strcmp(a, "--depth")) {
                if (!strcmp(v, "d24")) rd.depth_format = TL_DEPTH_FORMAT_D24;
                else if (!strcmp(v, "d32f-reversed")) rd.depth_format = TL_DEPTH_FORMAT_D32F_REVERSED;
                else return bad_usage("--depth wants d24 or d32f-reversed", v);
            } else if (!strcmp(a, "--rt0")) {
                if (!strcmp(v, "rgba8")) rd.rt0 = TL_RT0_RGBA8;
                else if (!strcmp(v, "rgb10a2")) rd.rt0 = TL_RT0_RGB10A2;
                else return bad_usage("--rt0 wants rgba8 or rgb10a2", v);
            } else if (!strcmp(a, "--light-buffer")) {
                if (!strcmp(v, "exact")) rd.light_buffer = TL_LIGHT_BUFFER_EXACT;
                else if (!strcmp(v, "compact")) rd.light_buffer = TL_LIGHT_BUFFER_COMPACT;
                else return bad_usage("--light-buffer wants exact or compact", v);
            } else if (!strcmp(a, "--fxaa")) {
                if (!strcmp(v, "off")) rd.fxaa = TL_FXAA_OFF;
                else if (!strcmp(v, "12")) rd.fxaa = TL_FXAA_12;
                else if (!strcmp(v, "29")) rd.fxaa = TL_FXAA_29;
                else if (!strcmp(v, "39")) rd.fxaa = TL_FXAA_39;
                else return bad_usage("--fxaa wants off, 12, 29 or 39", v);
            } else if (!strcmp(a, "--exposure")) {
                char *end;
                rd.exposure = strtof(v, &end);
                if (*end || !(rd.exposure > 0.0f) || rd.exposure > 1e6f) return bad_usage("--exposure wants a positive number", v);
            } else if (!strcmp(a, "--dump-targets")) {
                dump = v;
            } else {
                return bad_usage("unknown option", a);
            }
        } else if (!scene_arg) {
            scene_arg = a;
        } else {
            return bad_usage("unexpected argument", a);
        }
    }
    if (!scene_arg) return bad_usage("no scene given (use 'default' for the built-in one)", NULL);
    if (!out) return bad_usage("no output given (-o OUT.png or OUT.exr)", NULL);
    int hdr_out = ends_with(out, ".exr") != NULL;
    if (!hdr_out && !ends_with(out, ".png")) {
        fprintf(stderr, "thinlight-render: output %s must end in .png or .exr\n", out);
        return 1;
    }
    if (sd.point_lights > 65536 || sd.spot_lights > 65536) {
        fprintf(stderr, "thinlight-render: at most 65536 point and 65536 spot lights\n");
        return 1;
    }

    tl_scene *scene = NULL;
    tl_result res;
    if (strcmp(scene_arg, "default") != 0) {
        /* a glTF file: its own lights (or the default rig), plus --lights N seeded point lights */
        tl_gltf_options go = {.extra_lights = sd.point_lights, .seed = sd.seed, .logger = TL_TOOL_LOGGER(TOOL)};
        res = tl_scene_load_gltf(scene_arg, &go, &scene); /* its one error line is ours */
        if (res != TL_OK) return 1;
    } else {
        res = tl_scene_create_default(&sd, &scene);
        if (res != TL_OK) {
            fprintf(stderr, "thinlight-render: building the default scene: %s\n", tl_result_string(res));
            return 1;
        }
        /* In the scene descriptor zero means "default"; on the command line it means none. */
        if (zero_points && !zero_spots && sd.spot_lights == 0) zero_spots = 1;
        size_t kept = 0;
        for (size_t i = 0; i < scene->light_count; i++) {
            tl_light_type t = scene->lights[i].type == TL_LIGHT_DEFAULT ? TL_LIGHT_POINT : scene->lights[i].type;
            if ((t == TL_LIGHT_POINT && zero_points) || (t == TL_LIGHT_SPOT && zero_spots)) continue;
            scene->lights[kept++] = scene->lights[i];
        }
        scene->light_count = kept;
    }
    if (!rd.width) {
        rd.width = 1280;
        rd.height = 720;
    }
    tl_context *ctx = NULL;
    res = tl_context_create(&(tl_context_desc){.width = rd.width, .height = rd.height}, &ctx);
    if (res != TL_OK) {
        fprintf(stderr, "thinlight-render: no GL context: %s\n", tl_context_last_error(NULL));
        tl_scene_destroy(scene);
        return 1;
    }
    rd.get_proc_address = tl_context_proc_loader;
    rd.get_proc_address_user = ctx;
    tl_renderer *r = NULL;
    char err[4096];
    res = tl_renderer_create(&rd, &r, err, sizeof err);
    int rc = 0;
    if (res != TL_OK) {
        fprintf(stderr, "thinlight-render: %s\n", err);
        rc = 1;
    }
    if (!rc && (res = tl_renderer_set_scene(r, scene)) != TL_OK) {
        fprintf(stderr, "thinlight-render: %s\n", tl_renderer_last_error(r));
        rc = 1;
    }
    tl_frame_stats st;
    memset(&st, 0, sizeof st);
    for (uint32_t f = 0; !rc && f < frames; f++) {
        if (frames > 1 && f % 10 == 0) fprintf(stderr, "\rframe %u/%u", f + 1, frames);
        if ((res = tl_renderer_render(r, NULL, &st)) != TL_OK) {
            fprintf(stderr, "thinlight-render: %s\n", tl_renderer_last_error(r));
            rc = 1;
        }
    }
    if (frames > 1) fprintf(stderr, "\n");
    if (!rc && plan) print_plan(r, &st, scene);
    if (!rc && stats) {
        size_t px = (size_t)rd.width * rd.height;
        printf("%ux%u, %zu lights, %u objects drawn, %u draw calls\n", rd.width, rd.height, scene->light_count,
               st.objects_drawn, st.draw_calls);
        tl_frame_plan fp;
        if (tl_renderer_get_plan(r, &fp) == TL_OK)
            for (size_t i = 0; i < fp.pass_count; i++) {
                tl_pass p = fp.passes[i].pass;
                printf("  %-13s %8.2f ms %10llu fragments %8.2f MB moved (estimate)\n", tl_pass_name(p), st.pass_ms[p],
                       (unsigned long long)st.pass_fragments[p], st.pass_bytes[p] * 1e-6);
            }
        printf("  %-9s %8.2f ms GPU, %.2f ms wall\n", "frame", st.gpu_ms, st.cpu_ms);
        for (int t = 0; t < TL_TARGET_COUNT; t++)
            if (st.target_bytes[t])
                printf("  %-15s %5.1f B/px %8.2f MiB\n", tl_target_name((tl_target_id)t),
                       (double)st.target_bytes[t] / (double)px, (double)st.target_bytes[t] / 1048576.0);
        printf("  G-buffer %.1f B/px + light buffer %.1f B/px; all targets %.1f B/px\n",
               (double)st.gbuffer_bytes / (double)px, (double)st.light_buffer_bytes / (double)px,
               (double)st.total_target_bytes / (double)px);
    }
    if (!rc) {
        size_t n = (size_t)rd.width * rd.height * 4;
        void *pixels = hdr_out ? malloc(n * sizeof(float)) : malloc(n);
        tl_image_desc id = {rd.width, rd.height, 4, hdr_out ? TL_PIXEL_F32 : TL_PIXEL_U8, 1, TL_TOOL_LOGGER(TOOL)};
        if (!pixels) {
            fprintf(stderr, "thinlight-render: out of memory\n");
            rc = 1;
        } else if ((hdr_out ? tl_renderer_read_target(r, TL_TARGET_HDR, pixels, n)
                            : tl_renderer_read_output(r, pixels, n)) != TL_OK) {
            fprintf(stderr, "thinlight-render: %s\n", tl_renderer_last_error(r));
            rc = 1;
        } else if (tl_image_write(out, &id, pixels) != TL_OK) {
            rc = 1;
        }
        free(pixels);
    }
    if (!rc && dump) rc = dump_targets(r, dump, rd.width, rd.height);
    tl_renderer_destroy(r);
    tl_context_destroy(ctx);
    tl_scene_destroy(scene);
    return rc;
}
