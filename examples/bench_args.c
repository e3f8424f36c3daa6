/* thinlight-bench's command line: its options (a table for the tools' one parser, tool_args.h),
 * their defaults and --help. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "bench_shadows.h"
#include "tool_budget.h"
#include "tool_effects.h"

static const char usage_head[] =
    "usage: " BENCH_TOOL " [--scene default|FILE.gltf] [--size WxH[,WxH...]] [--lights N,N,...]\n"
    "                       [--modes MODE,...] [--strategies S,...] [--light-formats F,...]\n"
    "                       [--frames N] [--warmup N] [--json OUT.json] [--out DIR] [--quick]\n"
    "                       [--doc FILE.md] [--seed S] [--lighting M] [--fresnel F] [--no-plot]\n"
    "                       [--effects E,...] [--effects-doc FILE.md] [effect options]\n"
    "                       [--aa M,...] [--aa-doc FILE.md] [--aa-doc-section NAME]\n"
    "                       [--tiled-shading fragment|compute] [--shadows off,on] [--shadows-doc FILE.md]\n"
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
    "  --modes LIST     thin-lpp, thin-deferred, fat, forward (default all four); fat is rendered\n"
    "                   as the error reference even when not listed\n"
    "  --frames N       timed frames per measurement (default 7; 1..1000; medians and p90 over them)\n"
    "  --warmup N       untimed frames before them (default 2; 0..1000)\n"
    "  --strategies LIST light strategies, each mode rendered with each: volumes, tiled, auto\n"
    "                   (default volumes,tiled). forward with volumes is per-object light lists\n"
    "                   (\"forward\"), with tiled Forward+ (\"forward+\"); fat of the same strategy\n"
    "                   is each one's error reference\n"
    "  --light-formats LIST rgba16f (always) and r11g11b10f: thin-lpp/tiled also with the\n"
    "                   R11G11B10F light buffer (default rgba16f,r11g11b10f)\n"
    "  --light-scales LIST 1 (always), 0.5, 0.25: thin-lpp also with its light buffer at that\n"
    "                   scale per axis, with the first strategy (default 1,0.5,0.25); a table of its own\n"
    "                   gives their error against fat and against thin-lpp at scale 1, over the frame\n"
    "                   and over the edge pixels (fat's depth steps and creases), their passes' times,\n"
    "                   bytes and re-lit fraction\n"
    "  --tiled-shading K the tiled strategy's light pass: fragment (default) or compute\n";
static const char usage_outputs[] =
    "  --json FILE      write one record per (mode, strategy, lights, size)\n"
    "  --out DIR        write final images, heat maps of |mode - fat| (at the largest light count;\n"
    "                   light-scale variants also against thin-lpp at scale 1), the edge pixels and\n"
    "                   the plots (gnuplot) into DIR (PNG: needs a build with THINLIGHT_WITH_IO)\n"
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
    "                   their parameter options set it up:\n";
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
    B_WARMUP, B_SEED, B_LIGHTING, B_FRESNEL, B_JSON, B_OUT, B_DOC, B_EFFECTS, B_EFFECTS_DOC, B_AA, B_AA_DOC,
    B_AA_SECTION, B_TILED_SHADING, B_SHADOWS, B_SHADOWS_DOC
};

static const char *const bench__format_names[] = {"rgba16f", "r11g11b10f", NULL};
static const char *const bench__scale_names[] = {"1", "0.5", "0.25", NULL};
static const char *const bench__shading_names[] = {"fragment", "compute", NULL};
static const char *const bench__shadow_names[] = {"off", "on", NULL};

static const tl_opt bench__opts[] = {
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
    {"--light-formats", TL_OPT_TEXT_LIST, .id = B_FORMATS, .items = 4, .choices = bench__format_names},
    {"--light-scales", TL_OPT_TEXT_LIST, .id = B_SCALES, .items = 6, .choices = bench__scale_names},
    {"--frames", TL_OPT_UINT, .id = B_FRAMES, .lo = 1, .hi = BENCH_MAX_FRAMES},
    {"--warmup", TL_OPT_UINT, .id = B_WARMUP, .lo = 0, .hi = BENCH_MAX_FRAMES},
    {"--seed", TL_OPT_UINT, .id = B_SEED, .lo = 0, .hi = UINT64_MAX},
    {"--lighting", TL_OPT_TEXT, .id = B_LIGHTING},
    {"--fresnel", TL_OPT_TEXT, .id = B_FRESNEL},
    {"--json", TL_OPT_TEXT, .id = B_JSON},
    {"--out", TL_OPT_TEXT, .id = B_OUT},
    {"--doc", TL_OPT_TEXT, .id = B_DOC},
    {"--effects", TL_OPT_TEXT_LIST, .id = B_EFFECTS, .items = 2 * BENCH_EFFECTS + 1, .choices = bench_effect_names},
    {"--effects-doc", TL_OPT_TEXT, .id = B_EFFECTS_DOC},
    {"--aa", TL_OPT_TEXT_LIST, .id = B_AA, .items = 2 * BENCH_AAS, .choices = bench_aa_names},
    {"--aa-doc", TL_OPT_TEXT, .id = B_AA_DOC},
    {"--aa-doc-section", TL_OPT_TEXT, .id = B_AA_SECTION},
    {"--tiled-shading", TL_OPT_TEXT, .id = B_TILED_SHADING, .choices = bench__shading_names},
    {"--shadows", TL_OPT_TEXT_LIST, .id = B_SHADOWS, .items = 2, .choices = bench__shadow_names},
    {"--shadows-doc", TL_OPT_TEXT, .id = B_SHADOWS_DOC},
};

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

/* --modes and --strategies name the library's modes and strategies (repeats are dropped); 0 or 2. */
static int bench__modes(bench_options *o, const tl_opt_value *v)
{
    o->mode_count = 0;
    for (size_t i = 0; i < v->count; i++) {
        tl_render_mode m;
        if (strcmp(v->item[i], "default") == 0 || tl_render_mode_from_name(v->item[i], &m) != TL_OK)
            return tl_opt_usage(BENCH_TOOL, "--modes: unknown mode '%s' (thin-lpp, thin-deferred, fat, forward)",
                                v->item[i]);
        if (!bench_mode_requested(o, m)) o->modes[o->mode_count++] = m;
    }
    return 0;
}

static int bench__strategies(bench_options *o, const tl_opt_value *v)
{
    o->strategy_count = 0;
    for (size_t i = 0; i < v->count; i++) {
        tl_light_strategy s;
        if (tl_light_strategy_from_name(v->item[i], &s) != TL_OK)
            return tl_opt_usage(BENCH_TOOL, "--strategies: unknown light strategy '%s' (volumes, tiled, auto)",
                                v->item[i]);
        int seen = 0;
        for (size_t k = 0; k < o->strategy_count; k++) seen |= o->strategies[k] == s;
        if (!seen) o->strategies[o->strategy_count++] = s;
    }
    return 0;
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
        printf("%s%s%s%s%s%s%s%s", usage_head, usage_outputs, tl_tool_effects_help, tl_tool_environment_help, usage_middle,
               TL_TOOL_CONTEXT_HELP, tl_tool_budget_help, usage_tail);
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
    case B_FORMATS:
        o->small_light_buffer = 0;
        for (size_t i = 0; i < v->count; i++) o->small_light_buffer |= v->u[i] == 1;
        break;
    case B_SCALES: /* 1 is the configurations themselves */
        o->light_scales = 0;
        for (size_t i = 0; i < v->count; i++) o->light_scales |= v->u[i] == 1 ? 1u : v->u[i] == 2 ? 2u : 0u;
        break;
    case B_FRAMES: o->frames = (uint32_t)v->u[0], g->frames = 1; break;
    case B_WARMUP: o->warmup = (uint32_t)v->u[0], g->warmup = 1; break;
    case B_SEED: o->seed = v->u[0], g->seed = 1; break;
    case B_LIGHTING:
        if (tl_lighting_model_from_name(v->text, &o->lighting) != TL_OK)
            return tl_opt_usage(BENCH_TOOL, "--lighting wants auto, blinn-phong or ggx, got '%s'", v->text);
        break;
    case B_FRESNEL:
        if (tl_fresnel_layout_from_name(v->text, &o->fresnel) != TL_OK)
            return tl_opt_usage(BENCH_TOOL, "--fresnel wants two-sums or nv, got '%s'", v->text);
        break;
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
    case B_TILED_SHADING: o->tiled_shading = v->u[0] ? TL_TILED_SHADING_COMPUTE : TL_TILED_SHADING_FRAGMENT; break;
    case B_SHADOWS:
        o->shadows = 0;
        for (size_t i = 0; i < v->count; i++) o->shadows |= v->u[i] == 1;
        break;
    case B_SHADOWS_DOC: o->shadows_doc = v->text; break;
    default: break;
    }
    return 0;
}

/* An effect option (tool_effects.h): the flags also add their effect to the measured ones. */
static int bench__effect_option(bench_options *o, const tl_opt *opt, const tl_opt_value *v)
{
    if (!tl_tool_effect_apply(&o->effect_desc, opt, v)) return 0;
    for (int e = 0; opt->kind == TL_OPT_FLAG && e < BENCH_EFFECTS; e++)
        if (!strcmp(opt->name + 2, bench_effect_names[e])) o->effects |= 1u << e;
    return 1;
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
        o->strategies[0] = TL_LIGHT_STRATEGY_VOLUMES;
        o->strategies[1] = TL_LIGHT_STRATEGY_TILED;
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
    const tl_opt_table tables[] = {TL_OPT_TABLE(bench__opts), tl_tool_effect_options, tl_tool_context_option_table,
                                   tl_tool_budget_option_table, tl_tool_environment_option_table};
    size_t ntables = sizeof tables / sizeof tables[0];
    tl_opt_parser p;
    tl_opt_begin(&p, BENCH_TOOL, argc, argv, tables, ntables);
    const tl_opt *opt;
    tl_opt_value v;
    int rc;
    while ((rc = tl_opt_next(&p, &opt, &v)) == 1) {
        if (!opt) return tl_opt_usage(BENCH_TOOL, "unexpected argument '%s'", v.text);
        if (tl_tool_environment_apply(&o->env, &o->env_desc, opt, &v)) continue;
        if (!bench__effect_option(o, opt, &v) && !tl_tool_context_option(&o->context_args, opt, &v) &&
            !tl_tool_budget_option(&o->budgets, opt, &v) && (rc = bench__option(o, &given, tables, ntables, opt, &v)))
            return rc;
    }
    if (rc || o->context_args.list_devices) return rc;
    bench__defaults(o, &given);
    if (o->doc && !o->out && !o->no_plot)
        return tl_opt_usage(BENCH_TOOL, "--doc %s needs --out DIR for the plots (or --no-plot)", o->doc);
    return tl_tool_context_parse(BENCH_TOOL, &o->context_args, &o->context);
}
