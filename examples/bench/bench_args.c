/* thinlight-bench's command line: its options (a table for the tools' one parser, tool_args.h),
 * their defaults and --help. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "bench_shadows.h"
#include "tool_budget.h"
#include "tool_options.h"

static const char usage_head[] =
    "usage: " BENCH_TOOL " [--scene default|FILE.gltf] [--size WxH[,WxH...]] [--lights N,N,...]\n"
    "                       [--modes MODE,...] [--strategies S,...] [--light-formats F,...]\n"
    "                       [--frames N] [--warmup N] [--json OUT.json] [--out DIR] [--quick]\n"
    "                       [--doc FILE.md] [--seed S] [--no-plot] [renderer options]\n"
    "                       [--effects E,...] [--effects-doc FILE.md]\n"
    "                       [--aa M,...] [--aa-doc FILE.md] [--aa-doc-section NAME]\n"
    "                       [--shadows off,on] [--shadows-doc FILE.md]\n"
    "                       [--context C] [--device N] [memory budgets]\n"
    "                       [--list-devices] [--list-options] [--help]\n"
    "\n"
    "Renders the same frames in every mode and compares what they store (bytes per pixel of the\n"
    "targets each plan allocates), move (the renderer's bytes-moved estimate), cost (GPU time) and\n"
    "lose (error of the final and HDR images against the fat G-buffer's, the precision reference).\n"
    "\n"
    "  --scene S        'default' (the built-in crypt, default) or a glTF file\n"
    "  --size LIST      image sizes, e.g. 1280x720,1920x1080 (default 1280x720; 1..16384 per side)\n"
    "  --lights LIST    local lights per frame, point + spot with 1 in 8 a spot light, plus the scene's\n"
    "                   directional light (default 8,16,32,64,128,256,512,1024; 0..65536)\n"
    "  --modes LIST     thin-lpp, thin-deferred, fat, forward, visibility (default all five); fat is\n"
    "                   rendered as the error reference even when not listed; visibility, which\n"
    "                   always lights with tiles, once: \"visibility/tiled\" (fat/tiled its reference)\n"
    "  --frames N       timed frames per measurement (default 7; 1..1000; medians and p90 over them)\n"
    "  --warmup N       untimed frames before them (default 2; 0..1000)\n"
    "  --strategies LIST light strategies, each mode rendered with each: volumes, tiled, auto\n"
    "                   (default tiled,volumes: the light scales take the first). forward with\n"
    "                   volumes is per-object light lists\n"
    "                   (\"forward\"), with tiled Forward+ (\"forward+\"); fat of the same strategy\n"
    "                   is each one's error reference\n"
    "  --light-formats LIST the light buffer's formats (options.light_format): the default (always)\n"
    "                   and the others: thin-lpp/tiled also with the R11G11B10F light buffer (default all)\n"
    "  --light-scales LIST options.light_scale: 1 (always) and the smaller scales: thin-lpp also with\n"
    "                   its light buffer at that scale per axis, with the first strategy (default all); a\n"
    "                   table of its own gives their error against fat and against thin-lpp at scale 1,\n"
    "                   over the frame and over the edge pixels (fat's depth steps and creases), their\n"
    "                   passes' times, bytes and re-lit fraction\n";
static const char usage_outputs[] =
    "  --json FILE      write one record per (mode, strategy, lights, size)\n"
    "  --out DIR        write final images, heat maps of |mode - fat| (at the largest light count;\n"
    "                   light-scale variants also against thin-lpp at scale 1), the edge pixels and\n"
    "                   the plots (gnuplot) into DIR (PNG: needs a build with THINLIGHT_WITH_IO)\n"
    "  --quick          a short sweep: 640x360, lights 8,64,256, 3 frames after 1 warm-up, every mode\n"
    "                   (options given explicitly still apply)\n"
    "  --doc FILE       replace the text between " BENCH_DOC_BEGIN " and " BENCH_DOC_END "\n"
    "                   in FILE with the tables, and copy the plots to img/ beside it (needs --out\n"
    "                   unless --no-plot)\n"
    "  --seed S         seed of the light layout (default 1)\n"
    "  --no-plot        do not run gnuplot\n"
    "  --effects LIST   none (default), ssao, fog, dof, bloom, ssr, vignette: at the first size and light count,\n"
    "                   every configuration of the first strategy also renders with each effect (ssr:\n"
    "                   not forward, which has no reflections), taking turns with frames without it:\n"
    "                   the effect's cost (its passes' GPU time) and its error against fat with the\n"
    "                   same effect (SSAO: also the AO target's) join the table, the JSON (\"effects\")\n"
    "                   and the error-vs-time plot. --ssao, --fog, --dof, --bloom, --ssr, --vignette\n"
    "                   add one; their parameter options (below) set it up\n";
static const char usage_middle[] =
    "  --effects-doc FILE replace the text between " BENCH_EFFECTS_DOC_BEGIN " and\n"
    "                   " BENCH_EFFECTS_DOC_END " in FILE with the effects' table\n"
    "  --aa LIST        antialiasing methods, none, fxaa, msaa2, msaa4, msaa8 (thin-lpp's material\n"
    "                   pass, forward), msaa2e, msaa4e, msaa8e (per-sample lighting on edges:\n"
    "                   thin-lpp, thin-deferred, fat) (default: not measured):\n"
    "                   at the first size and every light count, each requested mode of the first\n"
    "                   strategy with each method its plan applies (up to the context's\n"
    "                   GL_MAX_SAMPLES), the renderers taking turns frame by frame; the\n"
    "                   error of each final image against a truth (fat at 4x4 the pixels, tone-mapped\n"
    "                   per sample on the CPU, averaged) over the frame and over the edge pixels,\n"
    "                   its time against the same mode's FXAA and no AA, its bytes per pixel and the\n"
    "                   re-lit (thin-lpp MSAA) or per-sample (msaaNe) fraction: a table, the JSON\n"
    "                   (\"aa\"), a plot and images in --out\n"
    "  --aa-doc FILE    replace the text between " BENCH_AA_DOC_BEGIN " and " BENCH_AA_DOC_END "\n"
    "                   in FILE with the AA table, and copy the plot and crops to img/ beside it\n"
    "  --aa-doc-section NAME the section between <!-- bench-aa:NAME:begin --> and <!-- bench-aa:NAME:end -->\n"
    "                   instead, its plot and crops named bench_aa_NAME_* (letters, digits, '-')\n"
    "  --shadows LIST   off, on (default: not measured): with on, at the first size and light count,\n"
    "                   every configuration with the scene's lights without shadows, casting (cached)\n"
    "                   and casting without the cache, frames taking turns; the shadow maps' and the\n"
    "                   lookup's time, atlas bytes, maps rendered and kept, and the shadow terms of the\n"
    "                   casting point lights (one at a time) against the ray-traced truth (D24 and\n"
    "                   reversed D32F; a bench built with Embree 3, else no truth): a table, the JSON\n"
    "                   (\"shadows\") and a plot. The crypt's moonlight and braziers cast; a glTF file\n"
    "                   is loaded with the shadow rule (its directional lights and brightest seeded\n"
    "                   lights, up to 8, and its lights' thinlight_shadow flags: docs/gltf.md), which\n"
    "                   its sweeps then render too\n"
    "  --shadows-doc FILE replace the text between " BENCH_SHADOWS_DOC_BEGIN " and\n"
    "                   " BENCH_SHADOWS_DOC_END " in FILE with the shadows' table, copy the plot to img/\n";
static const char usage_options[] =
    "Renderer options, for every configuration (each effect's only where it is measured; the\n"
    "sweep sets mode, light_strategy, light_format and light_scale: --modes, --strategies,\n"
    "--light-formats, --light-scales). Without --fresnel a GGX-lit sweep also measures\n"
    "thin-lpp/tiled/nv beside the exact layout:\n";
static const char usage_tail[] =
    "  --list-options   list every option and the values it takes, then exit\n"
    "  --help           this text\n"
    "\n"
    "Each renderer gets the target-memory budget: a size whose targets need more is refused before the\n"
    "sweep. The renderers whose frames take turns hold a copy of the scene each: as many as fit in\n"
    "512 MiB of such copies are kept at once (all of them for the built-in crypt), otherwise fewer, down\n"
    "to one configuration at a time, so a scene with large textures is held once, not once per\n"
    "configuration (docs/bandwidth.md).\n"
    "The context used (back end, platform, GL renderer and version) is printed on stderr and kept in\n"
    "the JSON; the glTF loader's and the renderers' warnings are printed once each. A build without\n"
    "THINLIGHT_WITH_IO (docs/gpu-servers.md) reads no glTF and writes no image: --scene FILE and --out\n"
    "fail with one line; the table, --json and --doc work.\n"
    "\n"
    "Exit status: 0 success, 1 bad input (an unreadable scene, an unwritable path, a size over the\n"
    "target-memory budget), 2 bad usage (an unknown option, a malformed or out-of-range value).\n";

enum {
    B_HELP, B_LIST, B_QUICK, B_NO_PLOT, B_SCENE, B_SIZE, B_LIGHTS, B_MODES, B_STRATEGIES, B_FORMATS, B_SCALES, B_FRAMES,
    B_WARMUP, B_SEED, B_JSON, B_OUT, B_DOC, B_EFFECTS, B_EFFECTS_DOC, B_AA, B_AA_DOC, B_AA_SECTION, B_SHADOWS,
    B_SHADOWS_DOC
};

/* The renderer options the sweep sets itself, each through a list flag of its own
 * (bench_swept_flags), and the rest's flags (tool_options.h). */
const char *const bench_swept_fields[] = {"mode", "light_strategy", "light_format", "light_scale", NULL};
const char *const bench_swept_flags[] = {"--modes", "--strategies", "--light-formats", "--light-scales", NULL};
static bench_renderer_flags bench__flags;
static const char *const bench__shadow_names[] = {"off", "on", NULL};

static tl_opt bench__opts[] = {
    {"--help", TL_OPT_FLAG, .id = B_HELP},
    {"-h", TL_OPT_FLAG, .id = B_HELP},
    {"--list-options", TL_OPT_FLAG, .id = B_LIST},
    {"--quick", TL_OPT_FLAG, .id = B_QUICK},
    {"--no-plot", TL_OPT_FLAG, .id = B_NO_PLOT},
    {"--scene", TL_OPT_TEXT, .id = B_SCENE},
    {"--size", TL_OPT_SIZE_LIST, .id = B_SIZE, .lo = 1, .hi = BENCH_MAX_SIDE, .items = BENCH_MAX_SIZES},
    {"--lights", TL_OPT_UINT_LIST, .id = B_LIGHTS, .lo = 0, .hi = BENCH_MAX_LIGHTS, .items = BENCH_MAX_LIGHT_COUNTS},
    {"--modes", TL_OPT_TEXT_LIST, .id = B_MODES, .items = 2 * BENCH_MODES},
    {"--strategies", TL_OPT_TEXT_LIST, .id = B_STRATEGIES, .items = 2 * BENCH_STRATEGIES},
    {"--light-formats", TL_OPT_TEXT_LIST, .id = B_FORMATS, .items = 4},
    {"--light-scales", TL_OPT_TEXT_LIST, .id = B_SCALES, .items = 6},
    {"--frames", TL_OPT_UINT, .id = B_FRAMES, .lo = 1, .hi = BENCH_MAX_FRAMES},
    {"--warmup", TL_OPT_UINT, .id = B_WARMUP, .lo = 0, .hi = BENCH_MAX_FRAMES},
    {"--seed", TL_OPT_UINT, .id = B_SEED, .lo = 0, .hi = UINT64_MAX},
    {"--json", TL_OPT_TEXT, .id = B_JSON},
    {"--out", TL_OPT_TEXT, .id = B_OUT},
    {"--doc", TL_OPT_TEXT, .id = B_DOC},
    {"--effects", TL_OPT_TEXT_LIST, .id = B_EFFECTS, .items = 2 * BENCH_EFFECTS + 1, .choices = bench_effect_names},
    {"--effects-doc", TL_OPT_TEXT, .id = B_EFFECTS_DOC},
    {"--aa", TL_OPT_TEXT_LIST, .id = B_AA, .items = 2 * BENCH_AAS, .choices = bench_aa_names},
    {"--aa-doc", TL_OPT_TEXT, .id = B_AA_DOC},
    {"--aa-doc-section", TL_OPT_TEXT, .id = B_AA_SECTION},
    {"--shadows", TL_OPT_TEXT_LIST, .id = B_SHADOWS, .items = 2, .choices = bench__shadow_names},
    {"--shadows-doc", TL_OPT_TEXT, .id = B_SHADOWS_DOC},
};

void bench_renderer_flags_build(bench_renderer_flags *f)
{
    static const char *const none[] = {NULL};
    tl_tool_options_build(&f->flags, bench_swept_fields);
    /* the swept fields' own rows give their lists' names: build those alone, keep their choices */
    const char *others[TL_TOOL_OPTIONS_MAX + 1];
    size_t n = 0;
    for (size_t i = 0; i < tl_option_count() && n < TL_TOOL_OPTIONS_MAX; i++) {
        const char *name = tl_option_at(i)->name;
        int swept = 0;
        for (size_t k = 0; bench_swept_fields[k]; k++) swept |= strcmp(bench_swept_fields[k], name) == 0;
        if (!swept) others[n++] = name;
    }
    others[n] = NULL;
    tl_tool_options_build(&f->swept, others);
    for (size_t i = 0; i < sizeof bench__opts / sizeof bench__opts[0]; i++)
        for (size_t k = 0; bench_swept_flags[k]; k++) {
            if (strcmp(bench__opts[i].name, bench_swept_flags[k]) != 0) continue;
            const tl_opt *own = NULL;
            for (size_t j = 0; j < f->swept.count; j++)
                if (strcmp(f->swept.field[j]->name, bench_swept_fields[k]) == 0 && !f->swept.spec[j].fixed) own = &f->swept.opts[j];
            bench__opts[i].choices = own ? own->choices : none;
            bench__opts[i].values = own ? own->values : NULL;
        }
}

static const uint32_t bench__default_lights[] = {8, 16, 32, 64, 128, 256, 512, 1024};
static const uint32_t bench__quick_lights[] = {8, 64, 256};

static int bench__cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* Ascending, without repeats. */
static void bench__set_lights(bench_options *o, const uint32_t *lights, size_t n)
{
    uint32_t sorted[BENCH_MAX_LIGHT_COUNTS];
    memcpy(sorted, lights, n * sizeof *lights);
    qsort(sorted, n, sizeof sorted[0], bench__cmp_u32);
    o->light_count = 0;
    for (size_t i = 0; i < n; i++)
        if (!o->light_count || o->lights[o->light_count - 1] != sorted[i]) o->lights[o->light_count++] = sorted[i];
}

/* --modes and --strategies: the library's modes and strategies by name (repeats are dropped). */
static int bench__modes(bench_options *o, const tl_opt_value *v)
{
    o->mode_count = 0;
    for (size_t i = 0; i < v->count; i++)
        if (!bench_mode_requested(o, (tl_render_mode)v->u[i])) o->modes[o->mode_count++] = (tl_render_mode)v->u[i];
    return 0;
}

static int bench__strategies(bench_options *o, const tl_opt_value *v)
{
    o->strategy_count = 0;
    for (size_t i = 0; i < v->count; i++) {
        int seen = 0;
        for (size_t k = 0; k < o->strategy_count; k++) seen |= o->strategies[k] == (tl_light_strategy)v->u[i];
        if (!seen) o->strategies[o->strategy_count++] = (tl_light_strategy)v->u[i];
    }
    return 0;
}

/* --light-scales: choice k is the scale min 2^k of options.light_scale's row; bit j - 1 of
 * light_scales asks for the scale 2^-j (1 is the configurations themselves). */
static void bench__scales(bench_options *o, const tl_opt_value *v)
{
    const tl_option_info *f = tl_option_find("light_scale");
    o->light_scales = 0;
    for (size_t i = 0; f && i < v->count; i++) {
        long j = lround(-log2(ldexp(f->min, (int)v->u[i])));
        if (j > 0) o->light_scales |= 1u << (j - 1);
    }
}

/* What the command line gave (the rest takes its default, which --quick may change). */
typedef struct bench__given {
    int sizes, lights, modes, strategies, frames, warmup, seed;
} bench__given;

/* One option of bench__opts; 0, -1 after --help or --list-options, or 2 after one line. */
static int bench__option(bench_options *o, bench__given *g, const tl_opt_table *tables, size_t ntables,
                         const tl_opt *opt, const tl_opt_value *v)
{
    switch (opt->id) {
    case B_HELP:
        printf("%s%s%s%s%s", usage_head, usage_outputs, usage_middle, tl_tool_environment_help, usage_options);
        tl_tool_options_help(stdout, &bench__flags.flags);
        printf("%s%s%s", TL_TOOL_CONTEXT_HELP, tl_tool_budget_help, usage_tail);
        return -1;
    case B_LIST: tl_opt_list(stdout, tables, ntables); return -1;
    case B_QUICK: o->quick = 1; break;
    case B_NO_PLOT: o->no_plot = 1; break;
    case B_SCENE: o->scene = v->text; break;
    case B_SIZE:
        for (size_t i = 0; i < v->count; i++) o->sizes[i] = (bench_size){v->w[i], v->h[i]};
        o->size_count = v->count, g->sizes = 1;
        break;
    case B_LIGHTS: {
        uint32_t l[BENCH_MAX_LIGHT_COUNTS];
        for (size_t i = 0; i < v->count; i++) l[i] = (uint32_t)v->u[i];
        bench__set_lights(o, l, v->count);
        g->lights = 1;
        break;
    }
    case B_MODES: g->modes = 1; return bench__modes(o, v);
    case B_STRATEGIES: g->strategies = 1; return bench__strategies(o, v);
    case B_FORMATS: /* the default is the configurations themselves */
        o->small_light_buffer = 0;
        for (size_t i = 0; i < v->count; i++) o->small_light_buffer |= v->u[i] == TL_LIGHT_FORMAT_R11G11B10F;
        break;
    case B_SCALES: bench__scales(o, v); break;
    case B_FRAMES: o->frames = (uint32_t)v->u[0], g->frames = 1; break;
    case B_WARMUP: o->warmup = (uint32_t)v->u[0], g->warmup = 1; break;
    case B_SEED: o->seed = v->u[0], g->seed = 1; break;
    case B_JSON: o->json = v->text; break;
    case B_OUT: o->out = v->text; break;
    case B_DOC: o->doc = v->text; break;
    case B_EFFECTS:
        for (size_t i = 0; i < v->count; i++)
            if (v->u[i] < BENCH_EFFECTS) o->effects |= 1u << v->u[i];
        break;
    case B_EFFECTS_DOC: o->effects_doc = v->text; break;
    case B_AA:
        o->aa = 0;
        for (size_t i = 0; i < v->count; i++) o->aa |= 1u << v->u[i];
        break;
    case B_AA_DOC: o->aa_doc = v->text; break;
    case B_AA_SECTION:
        if (strspn(v->text, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-") != strlen(v->text))
            return tl_opt_usage(BENCH_TOOL, "--aa-doc-section wants letters, digits and '-', got '%s'", v->text);
        o->aa_section = v->text;
        break;
    case B_SHADOWS:
        o->shadows = 0;
        for (size_t i = 0; i < v->count; i++) o->shadows |= v->u[i] == 1;
        break;
    case B_SHADOWS_DOC: o->shadows_doc = v->text; break;
    default: break;
    }
    return 0;
}

/* The effects whose `enabled` the renderer options set (--ssao, ...): measured (bench_effects.c). */
static void bench__effects_enabled(bench_options *o)
{
    for (int e = 0; e < BENCH_EFFECTS; e++) {
        char name[48];
        snprintf(name, sizeof name, "%s.enabled", bench_effect_names[e]);
        const tl_option_info *f = tl_option_find(name);
        int on = 0;
        if (f) memcpy(&on, (const char *)&o->base + f->offset, sizeof on);
        if (on) o->effects |= 1u << e;
    }
}

/* Defaults for what the command line did not give. */
static void bench__defaults(bench_options *o, const bench__given *g)
{
    if (!g->sizes) {
        o->sizes[0] = o->quick ? (bench_size){640, 360} : (bench_size){1280, 720};
        o->size_count = 1;
    }
    if (!g->lights)
        bench__set_lights(o, o->quick ? bench__quick_lights : bench__default_lights, o->quick ? 3 : 8);
    if (!g->modes) {
        o->mode_count = BENCH_MODES;
        for (size_t m = 0; m < BENCH_MODES; m++) o->modes[m] = (tl_render_mode)(TL_MODE_THIN_LPP + m);
    }
    if (!g->strategies) {
        /* tiles first: the light-scale variants light with the first strategy, and with volumes a
         * reduced light buffer costs nearly a full one (each light's fragments are rasterised) */
        o->strategies[0] = TL_LIGHT_STRATEGY_TILED;
        o->strategies[1] = TL_LIGHT_STRATEGY_VOLUMES;
        o->strategy_count = 2;
    }
    if (!g->frames) o->frames = o->quick ? 3 : 7;
    if (!g->warmup) o->warmup = o->quick ? 1 : 2;
    if (!g->seed) o->seed = 1;
}

int bench_parse_args(int argc, char **argv, bench_options *o)
{
    memset(o, 0, sizeof *o);
    o->scene = "default";
    o->small_light_buffer = 1;
    o->light_scales = 3u;
    bench__given given = {0};
    bench_renderer_flags_build(&bench__flags);
    const tl_opt_table tables[] = {TL_OPT_TABLE(bench__opts), tl_tool_options_table(&bench__flags.flags),
                                   tl_tool_context_option_table, tl_tool_budget_option_table,
                                   tl_tool_environment_option_table};
    size_t ntables = sizeof tables / sizeof tables[0];
    tl_opt_parser p;
    tl_opt_begin(&p, BENCH_TOOL, argc, argv, tables, ntables);
    const tl_opt *opt;
    tl_opt_value v;
    int rc;
    while ((rc = tl_opt_next(&p, &opt, &v)) == 1) {
        if (!opt) return tl_opt_usage(BENCH_TOOL, "unexpected argument '%s'", v.text);
        if ((rc = tl_tool_options_apply(BENCH_TOOL, &bench__flags.flags, &o->base, opt, &v)) == 2) return rc;
        if (rc || tl_tool_environment_apply(&o->env, opt, &v)) continue;
        if (!tl_tool_context_option(&o->context_args, opt, &v) && !tl_tool_budget_option(&o->budgets, opt, &v) &&
            (rc = bench__option(o, &given, tables, ntables, opt, &v)))
            return rc;
        rc = 0;
    }
    if (rc || o->context_args.list_devices) return rc;
    bench__effects_enabled(o);
    bench__defaults(o, &given);
    if (o->doc && !o->out && !o->no_plot)
        return tl_opt_usage(BENCH_TOOL, "--doc %s needs --out DIR for the plots (or --no-plot)", o->doc);
    return tl_tool_context_parse(BENCH_TOOL, &o->context_args, &o->context);
}
