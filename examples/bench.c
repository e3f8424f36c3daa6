/* thinlight-bench: the memory and bandwidth comparison of the four render modes (DESIGN.md
 * section 6). This file holds the command line and the order of the work; see bench.h. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "tool_effects.h"
#include "tool_util.h"

static const char usage_text[] =
    "usage: " BENCH_TOOL " [--scene default|FILE.gltf] [--size WxH[,WxH...]] [--lights N,N,...]\n"
    "                       [--modes MODE,...] [--strategies S,...] [--light-formats F,...]\n"
    "                       [--frames N] [--warmup N] [--json OUT.json] [--out DIR] [--quick]\n"
    "                       [--doc FILE.md] [--seed S] [--lighting M] [--fresnel F] [--no-plot]\n"
    "                       [--effects E,...] [--effects-doc FILE.md] [effect options]\n"
    "                       [--context C] [--device N]\n"
    "                       [--list-devices] [--help]\n"
    "\n"
    "Renders the same frames in every mode and compares what they store (bytes per pixel of the\n"
    "targets each plan allocates), move (the renderer's bytes-moved estimate), cost (GPU time) and\n"
    "lose (error of the final and HDR images against the fat G-buffer's, the precision reference).\n"
    "\n"
    "  --scene S        'default' (the built-in crypt, default) or a glTF file\n"
    "  --size LIST      image sizes, e.g. 1280x720,1920x1080 (default 1280x720; 1..16384 per side)\n"
    "  --lights LIST    local lights per frame, point + spot with 1 in 8 a spot light, plus the scene's\n"
    "                   directional light (default 8,16,32,64,128,256,512,1024; 0..65536)\n"
    "  --modes LIST     thin-lpp, thin-deferred, fat, forward (default all four); fat is rendered\n"
    "                   as the error reference even when not listed\n"
    "  --frames N       timed frames per measurement (default 7; medians and p90 over them)\n"
    "  --warmup N       untimed frames before them (default 2)\n"
    "  --strategies LIST light strategies, each mode rendered with each: volumes, tiled, auto\n"
    "                   (default volumes,tiled). forward with volumes is per-object light lists\n"
    "                   (\"forward\"), with tiled Forward+ (\"forward+\"); fat of the same strategy\n"
    "                   is each one's error reference\n"
    "  --light-formats LIST rgba16f (always) and r11g11b10f: thin-lpp/tiled also with the\n"
    "                   R11G11B10F light buffer (default rgba16f,r11g11b10f)\n"
    "  --json FILE      write one record per (mode, strategy, lights, size)\n"
    "  --out DIR        write final images, heat maps of |mode - fat| (at the largest light count)\n"
    "                   and the plots (gnuplot) into DIR (PNG: needs a build with THINLIGHT_WITH_IO)\n"
    "  --quick          a short sweep: 640x360, lights 8,64,256, 3 frames after 1 warm-up\n"
    "                   (options given explicitly still apply)\n"
    "  --doc FILE       replace the text between " BENCH_DOC_BEGIN " and " BENCH_DOC_END "\n"
    "                   in FILE with the tables, and copy the plots to img/ beside it (needs --out\n"
    "                   unless --no-plot)\n"
    "  --seed S         seed of the light layout (default 1)\n"
    "  --lighting M     auto (default: ggx for glTF materials, else blinn-phong), blinn-phong or ggx\n"
    "  --fresnel F      thin-lpp with GGX: two-sums (default, exact) or nv (Schlick with n.v per pixel);\n"
    "                   without it, a GGX-lit sweep also measures thin-lpp/tiled/nv beside the exact layout\n"
    "  --no-plot        do not run gnuplot\n"
    "  --effects LIST   none (default), ssao, fog, dof, bloom, ssr: at the first size and light count,\n"
    "                   every configuration of the first strategy also renders with each effect (ssr:\n"
    "                   not forward, which has no reflections), taking turns with frames without it:\n"
    "                   the effect's cost (its passes' GPU time) and its error against fat with the\n"
    "                   same effect (SSAO: also the AO target's) join the table, the JSON (\"effects\")\n"
    "                   and the error-vs-time plot. --ssao, --fog, --dof, --bloom, --ssr add one;\n"
    "                   their parameter options set it up:\n"
    ;
static const char usage_tail[] =
    "  --effects-doc FILE replace the text between " BENCH_EFFECTS_DOC_BEGIN " and\n"
    "                   " BENCH_EFFECTS_DOC_END " in FILE with the effects' table\n"
    TL_TOOL_CONTEXT_HELP
    "  --help           this text\n"
    "\n"
    "The context used (back end, platform, GL renderer and version) is printed on stderr and kept in\n"
    "the JSON. A build without THINLIGHT_WITH_IO (docs/gpu-servers.md) reads no glTF and writes no\n"
    "image: --scene FILE and --out fail with one line; the table, --json and --doc work.\n"
    "\n"
    "Exit status: 0 success, 1 bad input (an unreadable scene, an unwritable path), 2 bad usage.\n";

static const uint32_t bench__default_lights[] = {8, 16, 32, 64, 128, 256, 512, 1024};
static const uint32_t bench__quick_lights[] = {8, 64, 256};

static int bench__usage(const char *fmt, const char *arg)
{
    fprintf(stderr, BENCH_TOOL ": ");
    fprintf(stderr, fmt, arg);
    fputs(" (see --help)\n", stderr);
    return BENCH_EXIT_BAD_USAGE;
}

static int bench__parse_u64(const char *s, uint64_t max, uint64_t *out)
{
    char *end;
    if (!s || *s < '0' || *s > '9') return 0;
    errno = 0;
    unsigned long long v = strtoull(s, &end, 10);
    if (errno || *end || v > max) return 0;
    *out = v;
    return 1;
}

static int bench__cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* Copies `arg` into buf and splits it at commas into items (at most max); 0 after a usage line
 * for an empty item, too many items or too long a list. */
static size_t bench__list(const char *option, const char *what, const char *arg, char *buf, size_t size, char **items,
                          size_t max)
{
    size_t n = 0;
    if (strlen(arg) < size) {
        strcpy(buf, arg);
        for (char *s = buf;; s++) {
            char *comma = strchr(s, ',');
            if (comma) *comma = '\0';
            if (!*s || n == max) {
                n = 0;
                break;
            }
            items[n++] = s;
            if (!comma) break;
            s = comma;
        }
    }
    if (!n)
        fprintf(stderr, BENCH_TOOL ": %s wants up to %zu comma-separated %s, got '%s' (see --help)\n", option, max,
                what, arg);
    return n;
}

static int bench__parse_lights(const char *arg, bench_options *o)
{
    char buf[512], *items[BENCH_MAX_LIGHT_COUNTS];
    size_t n = bench__list("--lights", "counts", arg, buf, sizeof buf, items, BENCH_MAX_LIGHT_COUNTS);
    if (!n) return BENCH_EXIT_BAD_USAGE;
    for (size_t i = 0; i < n; i++) {
        uint64_t v;
        if (!bench__parse_u64(items[i], UINT32_MAX, &v)) return bench__usage("--lights: '%s' is not a count", items[i]);
        if (v > BENCH_MAX_LIGHTS) {
            fprintf(stderr, BENCH_TOOL ": --lights: %s lights is more than a sweep may use (at most %u)\n", items[i],
                    BENCH_MAX_LIGHTS);
            return BENCH_EXIT_BAD_USAGE;
        }
        o->lights[i] = (uint32_t)v;
    }
    qsort(o->lights, n, sizeof o->lights[0], bench__cmp_u32);
    o->light_count = 0;
    for (size_t i = 0; i < n; i++)
        if (!o->light_count || o->lights[o->light_count - 1] != o->lights[i]) o->lights[o->light_count++] = o->lights[i];
    return 0;
}

static int bench__parse_sizes(const char *arg, bench_options *o)
{
    char buf[512], *items[BENCH_MAX_SIZES];
    size_t n = bench__list("--size", "WxH", arg, buf, sizeof buf, items, BENCH_MAX_SIZES);
    if (!n) return BENCH_EXIT_BAD_USAGE;
    for (size_t i = 0; i < n; i++) {
        char *x = strchr(items[i], 'x');
        uint64_t w, h;
        if (!x) return bench__usage("--size: '%s' is not WxH", items[i]);
        *x = '\0';
        int ok = bench__parse_u64(items[i], UINT32_MAX, &w) && bench__parse_u64(x + 1, UINT32_MAX, &h);
        *x = 'x';
        if (!ok) return bench__usage("--size: '%s' is not WxH", items[i]);
        if (!w || !h || w > BENCH_MAX_SIDE || h > BENCH_MAX_SIDE) {
            fprintf(stderr, BENCH_TOOL ": --size: %s is out of range (1..%u pixels per side)\n", items[i],
                    BENCH_MAX_SIDE);
            return BENCH_EXIT_BAD_USAGE;
        }
        o->sizes[i] = (bench_size){(uint32_t)w, (uint32_t)h};
    }
    o->size_count = n;
    return 0;
}

static int bench__parse_modes(const char *arg, bench_options *o)
{
    char buf[256], *items[2 * BENCH_MODES]; /* repeats are dropped */
    size_t n = bench__list("--modes", "modes", arg, buf, sizeof buf, items, 2 * BENCH_MODES);
    if (!n) return BENCH_EXIT_BAD_USAGE;
    o->mode_count = 0;
    for (size_t i = 0; i < n; i++) {
        tl_render_mode m;
        if (strcmp(items[i], "default") == 0 || tl_render_mode_from_name(items[i], &m) != TL_OK)
            return bench__usage("--modes: unknown mode '%s' (thin-lpp, thin-deferred, fat, forward)", items[i]);
        if (!bench_mode_requested(o, m)) o->modes[o->mode_count++] = m;
    }
    return 0;
}

static int bench__parse_strategies(const char *arg, bench_options *o)
{
    char buf[128], *items[2 * BENCH_STRATEGIES];
    size_t n = bench__list("--strategies", "strategies", arg, buf, sizeof buf, items, 2 * BENCH_STRATEGIES);
    if (!n) return BENCH_EXIT_BAD_USAGE;
    o->strategy_count = 0;
    for (size_t i = 0; i < n; i++) {
        tl_light_strategy s;
        if (tl_light_strategy_from_name(items[i], &s) != TL_OK)
            return bench__usage("--strategies: unknown light strategy '%s' (volumes, tiled, auto)", items[i]);
        int seen = 0;
        for (size_t k = 0; k < o->strategy_count; k++) seen |= o->strategies[k] == s;
        if (!seen) o->strategies[o->strategy_count++] = s;
    }
    return 0;
}

static int bench__parse_light_formats(const char *arg, bench_options *o)
{
    char buf[128], *items[2 * TL_LIGHT_FORMAT_COUNT_];
    size_t n = bench__list("--light-formats", "formats", arg, buf, sizeof buf, items, 2 * TL_LIGHT_FORMAT_COUNT_);
    if (!n) return BENCH_EXIT_BAD_USAGE;
    o->small_light_buffer = 0;
    for (size_t i = 0; i < n; i++) {
        if (!strcmp(items[i], "r11g11b10f")) o->small_light_buffer = 1;
        else if (strcmp(items[i], "rgba16f"))
            return bench__usage("--light-formats: unknown light buffer format '%s' (rgba16f, r11g11b10f)", items[i]);
    }
    return 0;
}

static int bench__parse_effects(const char *arg, bench_options *o)
{
    char buf[128], *items[2 * BENCH_EFFECTS + 1];
    size_t n = bench__list("--effects", "effects", arg, buf, sizeof buf, items, 2 * BENCH_EFFECTS + 1);
    if (!n) return BENCH_EXIT_BAD_USAGE;
    for (size_t i = 0; i < n; i++) {
        int e = 0;
        while (e < BENCH_EFFECTS && strcmp(items[i], bench_effect_name((bench_effect)e))) e++;
        if (e < BENCH_EFFECTS) o->effects |= 1u << e;
        else if (strcmp(items[i], "none"))
            return bench__usage("--effects: unknown effect '%s' (none, ssao, fog, dof, bloom, ssr)", items[i]);
    }
    return 0;
}

/* An effect option (tool_effects.h): 0 not one, 1 a flag, 2 it took the next argument, -1 bad. */
static int bench__effect_option(bench_options *o, const char *a, const char *next)
{
    int rc = tl_tool_effect_option(BENCH_TOOL, &o->effect_desc, a, next);
    static const char *const flags[BENCH_EFFECTS] = {"--ssao", "--fog", "--dof", "--bloom", "--ssr"};
    for (int e = 0; rc == 1 && e < BENCH_EFFECTS; e++)
        if (!strcmp(a, flags[e])) o->effects |= 1u << e;
    return rc;
}

static int bench__parse_args(int argc, char **argv, bench_options *o)
{
    memset(o, 0, sizeof *o);
    o->scene = "default";
    const char *sizes = NULL, *lights = NULL, *modes = NULL, *strategies = NULL, *formats = NULL, *frames = NULL, *warmup = NULL, *seed = NULL;
    const char *context = NULL, *device = NULL, *lighting = NULL, *fresnel = NULL, *effects = NULL;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char **value = NULL;
        int erc = bench__effect_option(o, a, i + 1 < argc ? argv[i + 1] : NULL);
        if (erc < 0) return BENCH_EXIT_BAD_USAGE; /* it printed the line */
        if (erc == 2) i++;
        if (erc) continue;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) o->help = 1;
        else if (!strcmp(a, "--quick")) o->quick = 1;
        else if (!strcmp(a, "--no-plot")) o->no_plot = 1;
        else if (!strcmp(a, "--list-devices")) o->list_devices = 1;
        else if (!strcmp(a, "--context")) value = &context;
        else if (!strcmp(a, "--device")) value = &device;
        else if (!strcmp(a, "--scene")) value = &o->scene;
        else if (!strcmp(a, "--size")) value = &sizes;
        else if (!strcmp(a, "--lights")) value = &lights;
        else if (!strcmp(a, "--modes")) value = &modes;
        else if (!strcmp(a, "--strategies")) value = &strategies;
        else if (!strcmp(a, "--light-formats")) value = &formats;
        else if (!strcmp(a, "--frames")) value = &frames;
        else if (!strcmp(a, "--warmup")) value = &warmup;
        else if (!strcmp(a, "--seed")) value = &seed;
        else if (!strcmp(a, "--lighting")) value = &lighting;
        else if (!strcmp(a, "--fresnel")) value = &fresnel;
        else if (!strcmp(a, "--json")) value = &o->json;
        else if (!strcmp(a, "--out")) value = &o->out;
        else if (!strcmp(a, "--doc")) value = &o->doc;
        else if (!strcmp(a, "--effects")) value = &effects;
        else if (!strcmp(a, "--effects-doc")) value = &o->effects_doc;
        else return bench__usage(a[0] == '-' ? "unknown option '%s'" : "unexpected argument '%s'", a);
        if (value) {
            if (i + 1 >= argc || argv[i + 1][0] == '\0') return bench__usage("%s needs a value", a);
            *value = argv[++i];
        }
    }
    if (o->help || o->list_devices) return 0;
    int rc;
    if ((rc = tl_tool_context_parse(BENCH_TOOL, context, device, &o->context))) return rc;
    if ((rc = bench__parse_sizes(sizes ? sizes : o->quick ? "640x360" : "1280x720", o))) return rc;
    if (lights) {
        if ((rc = bench__parse_lights(lights, o))) return rc;
    } else {
        const uint32_t *l = o->quick ? bench__quick_lights : bench__default_lights;
        o->light_count = o->quick ? 3 : 8;
        memcpy(o->lights, l, o->light_count * sizeof *l);
    }
    if ((rc = bench__parse_modes(modes ? modes : "thin-lpp,thin-deferred,fat,forward", o))) return rc;
    if ((rc = bench__parse_strategies(strategies ? strategies : "volumes,tiled", o))) return rc;
    if ((rc = bench__parse_light_formats(formats ? formats : "rgba16f,r11g11b10f", o))) return rc;
    uint64_t v;
    if (frames && (!bench__parse_u64(frames, BENCH_MAX_FRAMES, &v) || v == 0))
        return bench__usage("--frames wants 1..1000, got '%s'", frames);
    o->frames = frames ? (uint32_t)v : o->quick ? 3 : 7;
    if (warmup && !bench__parse_u64(warmup, BENCH_MAX_FRAMES, &v))
        return bench__usage("--warmup wants 0..1000, got '%s'", warmup);
    o->warmup = warmup ? (uint32_t)v : o->quick ? 1 : 2;
    if (seed && !bench__parse_u64(seed, UINT64_MAX, &o->seed)) return bench__usage("--seed wants a number, got '%s'", seed);
    if (!seed) o->seed = 1;
    if (lighting && tl_lighting_model_from_name(lighting, &o->lighting) != TL_OK)
        return bench__usage("--lighting wants auto, blinn-phong or ggx, got '%s'", lighting);
    if (fresnel && tl_fresnel_layout_from_name(fresnel, &o->fresnel) != TL_OK)
        return bench__usage("--fresnel wants two-sums or nv, got '%s'", fresnel);
    if (effects && (rc = bench__parse_effects(effects, o))) return rc;
    if (o->doc && !o->out && !o->no_plot) return bench__usage("--doc %s needs --out DIR for the plots (or --no-plot)", o->doc);
    return 0;
}

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

static int bench__check_outputs(bench_options *o, char **doc_text, char **effects_text)
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
    tl_renderer_desc desc = {.mode = TL_MODE_THIN_LPP, .lighting = o->lighting, .width = 64, .height = 64};
    o->fresnel_nv_variant = o->fresnel == TL_FRESNEL_DEFAULT && tl_frame_plan_build(&desc, &features, &plan) == TL_OK &&
                            plan.lighting == TL_LIGHTING_GGX;
}

int main(int argc, char **argv)
{
    bench_run *run = calloc(1, sizeof *run);
    if (!run) {
        tl_tool_fail(BENCH_TOOL, "out of memory");
        return BENCH_EXIT_BAD_INPUT;
    }
    int rc = bench__parse_args(argc, argv, &run->opt);
    if (rc || run->opt.help || run->opt.list_devices) {
        if (!rc && run->opt.help) printf("%s%s%s", usage_text, tl_tool_effects_help, usage_tail);
        else if (!rc) rc = tl_tool_list_devices(BENCH_TOOL);
        free(run);
        return rc;
    }
    bench_options *opt = &run->opt;
    char *doc_text = NULL, *effects_text = NULL;
    bench_scene *scene = NULL;
    rc = BENCH_EXIT_BAD_INPUT;
    if (bench_scene_open(opt, &scene, run) || bench__check_outputs(opt, &doc_text, &effects_text)) goto done;
    bench__fresnel_variant(opt, scene);
    tl_tool_machine(run->cpu, sizeof run->cpu, &run->cores);
    /* the plans first: the sweep times each planned mode against its no_planning renderer */
    if (bench_planning_compare(run, scene) || bench_sweep(run, scene)) goto done;
    int plot_failed = opt->out && !opt->no_plot && bench_plots(run);
    bench_print_table(run);
    bench_effects_print_table(run);
    if (opt->json && bench_write_json(run, opt->json)) goto done;
    if (opt->doc && bench_update_doc(run, doc_text)) goto done;
    if (opt->effects_doc && bench_effects_update_doc(run, effects_text)) goto done;
    rc = plot_failed ? BENCH_EXIT_BAD_INPUT : 0;
done:
    bench_scene_close(scene);
    free(doc_text);
    free(effects_text);
    free(run->effects);
    for (size_t i = 0; i < run->record_count; i++) free(run->records[i].frame_ms);
    free(run->records);
    free(run->images);
    free(run);
    return rc;
}
