/* thinlight-render's command line: its options (a table for the tools' one parser, tool_args.h)
 * and --help. */
#include <stdio.h>
#include <string.h>

#include "render.h"
#include "tool_options.h"

static const char usage_head[] =
    "usage: thinlight-render SCENE.gltf|SCENE.glb|default|showcase -o OUT.png|OUT.exr [options]\n"
    "       thinlight-render SCENE.gltf|SCENE.glb|default|showcase --stats|--print-plan [options]\n"
    "       thinlight-render --list-devices\n"
    "  --size WxH            image size (default 1280x720; 1..16384 per side)\n"
    "  --lights N            point lights of the built-in scene (default 64; 0..65536); for a glTF\n"
    "                        file, N seeded point lights added within its bounds\n"
    "  --spots N             spot lights (default lights/8; 0..65536)\n"
    "  --no-directional      leave out the directional light\n"
    "  --seed S              scene seed (default 1)\n"
    "  --glass N             the built-in scene with N alpha-blended glass panes (default 0; 0..8)\n"
    "  --shadows             the built-in scene's moonlight and braziers cast shadows (docs/shadows.md);\n"
    "                        a glTF file's directional lights and brightest other lights, up to\n"
    "                        --shadow-max (docs/gltf.md, \"Shadows\"; its lights' thinlight_shadow\n"
    "                        flags are honoured with or without it); the --shadow-* renderer options\n"
    "                        below set the atlas up\n"
    "  --shadow-move         every frame after the first, the first casting local light moves 1 cm\n"
    "                        (measures the shadow cache with one light moving)\n"
    "  --shadow-move-object  every frame after the first, the object nearest that light moves 1 cm\n"
    "  --frames N            render N frames and report the last (default 1; 1..100000)\n"
    "  --stats               print per-pass GPU times and target bytes\n"
    "  --print-plan          print the frame plan: passes, inputs, outputs, targets, programs\n"
    "  --dump-targets DIR    write every target of the plan as EXR into DIR (depth, decoded\n"
    "                        normals, visibility's id (vis_id.exr: object, triangle, drawn) and\n"
    "                        32-bit targets as 32-bit floats, the others as half)\n";
static const char usage_options[] = "Renderer options (docs/renderer.md, \"Options at run time\"):\n";
static const char usage_tail[] =
    "  --list-options        list every option and the values it takes, then exit\n"
    "  --help                this text\n"
    "An .exr output holds the HDR image before tone mapping; .png the final image. The context used\n"
    "is printed on stderr, and the glTF loader's and the renderer's warnings, each once. A build\n"
    "without THINLIGHT_WITH_IO (docs/gpu-servers.md) reads no glTF and writes no image: -o,\n"
    "--dump-targets and a glTF scene fail with one line; --stats and --print-plan work.\n"
    "Exit status: 0 success, 1 bad input (an unreadable scene, an unwritable output, a frame over\n"
    "the target-memory budget), 2 bad usage (an unknown option, a malformed or out-of-range value).\n";

enum { R_HELP, R_LIST, R_OUT, R_DUMP, R_SIZE, R_LIGHTS, R_SPOTS, R_NO_DIRECTIONAL, R_SEED, R_FRAMES, R_STATS, R_PLAN,
       R_GLASS, R_SHADOWS, R_SHADOW_MOVE, R_SHADOW_MOVE_OBJECT };

/* The renderer options' flags (tool_options.h): every field of the registry. */
static tl_tool_options render_flags;

static const tl_opt render_opts[] = {
    {"--help", TL_OPT_FLAG, .id = R_HELP},
    {"-h", TL_OPT_FLAG, .id = R_HELP},
    {"--list-options", TL_OPT_FLAG, .id = R_LIST},
    {"-o", TL_OPT_TEXT, .id = R_OUT},
    {"--dump-targets", TL_OPT_TEXT, .id = R_DUMP},
    {"--size", TL_OPT_SIZE, .id = R_SIZE, .lo = 1, .hi = 16384},
    {"--lights", TL_OPT_UINT, .id = R_LIGHTS, .lo = 0, .hi = 65536},
    {"--spots", TL_OPT_UINT, .id = R_SPOTS, .lo = 0, .hi = 65536},
    {"--no-directional", TL_OPT_FLAG, .id = R_NO_DIRECTIONAL},
    {"--seed", TL_OPT_UINT, .id = R_SEED, .lo = 0, .hi = UINT64_MAX},
    {"--frames", TL_OPT_UINT, .id = R_FRAMES, .lo = 1, .hi = 100000},
    {"--stats", TL_OPT_FLAG, .id = R_STATS},
    {"--print-plan", TL_OPT_FLAG, .id = R_PLAN},
    {"--glass", TL_OPT_UINT, .id = R_GLASS, .lo = 0, .hi = 8},
    {"--shadows", TL_OPT_FLAG, .id = R_SHADOWS},
    {"--shadow-move", TL_OPT_FLAG, .id = R_SHADOW_MOVE},
    {"--shadow-move-object", TL_OPT_FLAG, .id = R_SHADOW_MOVE_OBJECT},
};

/* One option of render_opts; 0, or -1 after --help or --list-options. */
static int render_option(render_args *a, const tl_opt_table *tables, size_t ntables, const tl_opt *o,
                         const tl_opt_value *v)
{
    switch (o->id) {
    case R_HELP:
        printf("%s%s%s", usage_head, tl_tool_environment_help, usage_options);
        tl_tool_options_help(stdout, &render_flags);
        printf("%s%s%s", TL_TOOL_CONTEXT_HELP, tl_tool_budget_help, usage_tail);
        return -1;
    case R_LIST: tl_opt_list(stdout, tables, ntables); return -1;
    case R_OUT: a->out = v->text; break;
    case R_DUMP: a->dump = v->text; break;
    case R_SIZE: a->rd.width = v->w[0], a->rd.height = v->h[0]; break;
    case R_LIGHTS: a->sd.point_lights = (uint32_t)v->u[0], a->zero_points = v->u[0] == 0; break;
    case R_SPOTS: a->sd.spot_lights = (uint32_t)v->u[0], a->zero_spots = v->u[0] == 0; break;
    case R_NO_DIRECTIONAL: a->sd.no_directional = 1; break;
    case R_SEED: a->sd.seed = v->u[0]; break;
    case R_FRAMES: a->frames = (uint32_t)v->u[0]; break;
    case R_STATS: a->stats = 1; break;
    case R_PLAN: a->plan = 1; break;
    case R_GLASS: a->sd.glass_panes = (uint32_t)v->u[0]; break;
    case R_SHADOWS: a->sd.shadows = 1; break;
    case R_SHADOW_MOVE: a->shadow_move = 1; break;
    case R_SHADOW_MOVE_OBJECT: a->shadow_move = 2; break;
    default: break;
    }
    return 0;
}

/* Any option of the tables; 0, -1 after --help or --list-options, or 2 after one line. */
static int render_apply(render_args *a, const tl_opt_table *tables, size_t ntables, const tl_opt *o,
                        const tl_opt_value *v)
{
    int rc = tl_tool_options_apply(RENDER_TOOL, &render_flags, &a->rd.options, o, v);
    if (rc) return rc == 1 ? 0 : rc;
    if (tl_tool_environment_apply(&a->env, o, v) || tl_tool_context_option(&a->context_args, o, v) ||
        tl_tool_budget_option(&a->budgets, o, v))
        return 0;
    return render_option(a, tables, ntables, o, v);
}

int render_parse_args(int argc, char **argv, render_args *a)
{
    memset(a, 0, sizeof *a);
    a->frames = 1;
    tl_tool_options_build(&render_flags, NULL);
    const tl_opt_table tables[] = {TL_OPT_TABLE(render_opts), tl_tool_options_table(&render_flags),
                                   tl_tool_context_option_table, tl_tool_budget_option_table,
                                   tl_tool_environment_option_table};
    size_t ntables = sizeof tables / sizeof tables[0];
    tl_opt_parser p;
    tl_opt_begin(&p, RENDER_TOOL, argc, argv, tables, ntables);
    const tl_opt *o;
    tl_opt_value v;
    int rc;
    while ((rc = tl_opt_next(&p, &o, &v)) == 1) {
        if (!o) {
            if (a->scene) return tl_opt_usage(RENDER_TOOL, "unexpected argument '%s'", v.text);
            a->scene = v.text;
        } else if ((rc = render_apply(a, tables, ntables, o, &v)) != 0) {
            return rc;
        }
    }
    if (rc) return rc;
    if (a->context_args.list_devices) return 0;
    if (!a->scene) return tl_opt_usage(RENDER_TOOL, "no scene given (use 'default' for the built-in one)");
    if (!a->out && !a->stats && !a->plan)
        return tl_opt_usage(RENDER_TOOL, "no output given (-o OUT.png or OUT.exr, or --stats or --print-plan)");
    return tl_tool_context_parse(RENDER_TOOL, &a->context_args, &a->ctx);
}
