/* The viewer's command line and --help (which lists every key). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "tool_options.h"

#define VW_TOOL "thinlight-viewer"

static const char vw_usage[] =
    "usage: thinlight-viewer [SCENE.gltf|SCENE.glb|crypt|showcase] [options]\n"
    "Opens a window on the built-in crypt (default) or a glTF 2.0 file.\n"
    "  --size WxH            window size (default 1280x720; 16..8192 per side)\n"
    "  --lights N            crypt: point lights (default 64); glTF: seeded point lights added (0..65536)\n"
    "  --view V              final (default), normals, gloss, luma, chroma, albedo, depth, position,\n"
    "                        light-diffuse, light-specular, tile-lights, hdr, before-fxaa, diff-fat,\n"
    "                        ao-raw, ao (with --ssao), dof-coc (with --dof), ssr (with --ssr),\n"
    "                        bloom (with --bloom), msaa-edges, material-model, shadow-atlas,\n"
    "                        shadow-cascades, shadow-only (with casting lights: --shadows), vis-id,\n"
    "                        vis-normals (--mode visibility)\n"
    "  --shadows             the crypt's moonlight and braziers cast shadows (docs/shadows.md); a glTF\n"
    "                        file's directional lights and brightest other lights, up to 8 (docs/gltf.md,\n"
    "                        \"Shadows\"; its lights' thinlight_shadow flags are honoured without it too)\n"
    "  --grid                every view as thumbnails\n"
    "  --split MODE          left half in --mode, right half in MODE\n"
    "  --animate             move the lights\n"
    "  --no-panel            hide the panel\n"
    "  --screenshot FILE     write the view (without the panel) as PNG after --frames and exit\n"
    "  --screenshot-window FILE  the same with the panel, as the window shows it\n"
    "  --frames N            frames to render before the screenshot (default 3; 1..100000); alone: exit\n"
    "                        after N\n"
    "  --resize WxH          resize the window after the first frames (tests)\n"
    "  --print-targets       print the targets' size and bytes whenever they are (re)allocated\n"
    "  --dynamic-light-scale thin-lpp: lower the light scale while the camera moves (to 1/2, or 1/4 when\n"
    "                        the last frame took longer than --light-budget-ms), back to --light-scale\n"
    "                        after 0.25 s (and 3 frames) without motion\n"
    "  --light-budget-ms MS  the dynamic light scale's frame-time budget (default 33.3; 0.001..1e6)\n"
    "  --move-camera F,N     orbit the camera a step a frame for N frames from frame F (scripted motion,\n"
    "                        for tests; with --frames)\n"
    "  --print-frames        print one line per frame: its light scale, camera motion and GPU time\n"
    "  --list-options        list every option and the values it takes, then exit\n"
    "  --help                this text\n";
static const char vw_usage_options[] =
    "Renderer options (as thinlight-render; the panel changes them live):\n";
static const char vw_usage_budgets[] =
    "Memory budgets (as thinlight-render):\n";
static const char vw_usage_tail[] =
    "The glTF loader's and the renderers' warnings go to stderr, each once.\n"
    "Exit status: 0 success, 1 bad input (an unreadable scene, no window), 2 bad usage (an unknown\n"
    "option, a malformed or out-of-range value).\n";

static const char vw_keys[] =
    "Keys (when the panel does not have the keyboard):\n"
    "  left drag             orbit (orbit camera) or look around (fly camera)\n"
    "  right drag            look around\n"
    "  W A S D, Q E          fly forward, left, back, right, down, up (switches to the fly camera)\n"
    "  Shift                 fly 4x faster\n"
    "  scroll                zoom (orbit) or move forward (fly)\n"
    "  F                     toggle fly / orbit camera\n"
    "  C                     back to the scene's camera\n"
    "  1 2 3 4 5             mode: thin-lpp, thin-deferred, fat, forward, visibility\n"
    "  T                     light strategy: auto, volumes, tiled\n"
    "  V / Shift+V           next / previous debug view\n"
    "  0                     the final view\n"
    "  G                     grid of every view\n"
    "  X                     split view (left: the mode, right: fat, or the mode chosen in the panel)\n"
    "  + / -                 light count x2 / /2\n"
    "  L                     animate the lights on / off\n"
    "  [ / ]                 exposure /1.25 / x1.25\n"
    "  R                     light scale (thin-lpp): 1, 1/2, 1/4\n"
    "  Shift+R               dynamic light scale on / off (lower while the camera moves)\n"
    "  M                     antialiasing: none, FXAA, MSAA 2x, 4x, 8x (MSAA: thin-lpp and forward)\n"
    "  H or F1               hide / show the panel\n"
    "  P or F12              screenshot (viewer-N.png in the current directory)\n"
    "  Escape                quit\n";

/* The renderer options' flags (tool_options.h): every field of the registry. */
static tl_tool_options vw_flags;

void vw_print_usage(FILE *f)
{
    tl_tool_options_build(&vw_flags, NULL);
    fputs(vw_usage, f);
    fputs(tl_tool_environment_help, f);
    fputs(vw_usage_options, f);
    tl_tool_options_help(f, &vw_flags);
    fputs(vw_usage_budgets, f);
    fputs(tl_tool_budget_help, f);
    fputs(vw_usage_tail, f);
    fputs(vw_keys, f);
}

enum { V_HELP, V_LIST, V_SIZE, V_RESIZE, V_LIGHTS, V_FRAMES, V_VIEW, V_SPLIT, V_SCREENSHOT, V_SCREENSHOT_WINDOW,
       V_GRID, V_ANIMATE, V_NO_PANEL, V_PRINT_TARGETS, V_DYNAMIC, V_BUDGET, V_MOVE, V_PRINT_FRAMES,
       V_SHADOWS };

static const tl_opt vw_opts[] = {
    {"--help", TL_OPT_FLAG, .id = V_HELP},
    {"-h", TL_OPT_FLAG, .id = V_HELP},
    {"--list-options", TL_OPT_FLAG, .id = V_LIST},
    {"--size", TL_OPT_SIZE, .id = V_SIZE, .lo = 16, .hi = 8192},
    {"--resize", TL_OPT_SIZE, .id = V_RESIZE, .lo = 16, .hi = 8192},
    {"--lights", TL_OPT_UINT, .id = V_LIGHTS, .lo = 0, .hi = 65536},
    {"--frames", TL_OPT_UINT, .id = V_FRAMES, .lo = 1, .hi = 100000},
    {"--view", TL_OPT_TEXT, .id = V_VIEW},
    {"--split", TL_OPT_TEXT, .id = V_SPLIT},
    {"--screenshot", TL_OPT_TEXT, .id = V_SCREENSHOT},
    {"--screenshot-window", TL_OPT_TEXT, .id = V_SCREENSHOT_WINDOW},
    {"--grid", TL_OPT_FLAG, .id = V_GRID},
    {"--animate", TL_OPT_FLAG, .id = V_ANIMATE},
    {"--no-panel", TL_OPT_FLAG, .id = V_NO_PANEL},
    {"--print-targets", TL_OPT_FLAG, .id = V_PRINT_TARGETS},
    {"--dynamic-light-scale", TL_OPT_FLAG, .id = V_DYNAMIC},
    {"--light-budget-ms", TL_OPT_REAL, .id = V_BUDGET, .min = 0.001, .max = 1e6},
    {"--move-camera", TL_OPT_UINT_LIST, .id = V_MOVE, .lo = 0, .hi = 100000, .items = 2},
    {"--print-frames", TL_OPT_FLAG, .id = V_PRINT_FRAMES},
    {"--shadows", TL_OPT_FLAG, .id = V_SHADOWS},
};

/* One option of vw_opts; -1 to go on, else the exit status (0 after --help or --list-options). */
static int vw_option(vw_args *a, const tl_opt_table *tables, size_t ntables, const tl_opt *o, const tl_opt_value *v)
{
    switch (o->id) {
    case V_HELP: vw_print_usage(stdout); return 0;
    case V_LIST: tl_opt_list(stdout, tables, ntables); return 0;
    case V_SIZE: a->width = v->w[0], a->height = v->h[0]; break;
    case V_RESIZE: a->resize_w = v->w[0], a->resize_h = v->h[0]; break;
    case V_LIGHTS: a->lights = (uint32_t)v->u[0], a->lights_set = 1; break;
    case V_FRAMES: a->frames = (uint32_t)v->u[0]; break;
    case V_VIEW:
        if (!vw_view_from_name(v->text, &a->view)) return tl_opt_usage(VW_TOOL, "--view '%s': unknown view", v->text);
        break;
    case V_SPLIT:
        if (tl_render_mode_from_name(v->text, &a->split_mode) != TL_OK)
            return tl_opt_usage(VW_TOOL, "--split '%s': wants thin-lpp, thin-deferred, fat or forward", v->text);
        a->split = 1;
        break;
    case V_SCREENSHOT: a->screenshot = v->text; break;
    case V_SCREENSHOT_WINDOW: a->screenshot = v->text, a->screenshot_window = 1; break;
    case V_GRID: a->grid = 1; break;
    case V_ANIMATE: a->animate = 1; break;
    case V_NO_PANEL: a->no_panel = 1; break;
    case V_PRINT_TARGETS: a->print_targets = 1; break;
    case V_DYNAMIC: a->dynamic_light_scale = 1; break;
    case V_BUDGET: a->light_budget_ms = v->f[0]; break;
    case V_MOVE:
        if (v->count != 2) return tl_opt_usage(VW_TOOL, "--move-camera wants FIRST,COUNT (two frame numbers)");
        a->move_first = (uint32_t)v->u[0], a->move_count = (uint32_t)v->u[1];
        break;
    case V_PRINT_FRAMES: a->print_frames = 1; break;
    case V_SHADOWS: a->shadows = 1; break;
    default: break;
    }
    return -1;
}

/* Any option of the tables; -1 to go on, else the exit status. */
static int vw_apply(vw_args *a, const tl_opt_table *tables, size_t ntables, const tl_opt *o, const tl_opt_value *v)
{
    int rc = tl_tool_options_apply(VW_TOOL, &vw_flags, &a->desc.options, o, v);
    if (rc) return rc == 1 ? -1 : rc;
    if (tl_tool_environment_apply(&a->env, o, v) || tl_tool_budget_option(&a->budgets, o, v)) return -1;
    return vw_option(a, tables, ntables, o, v);
}

int vw_parse_args(int argc, char **argv, vw_args *a)
{
    memset(a, 0, sizeof *a);
    a->width = 1280;
    a->height = 720;
    tl_tool_options_build(&vw_flags, NULL);
    const tl_opt_table tables[] = {TL_OPT_TABLE(vw_opts), tl_tool_options_table(&vw_flags), tl_tool_budget_option_table,
                                   tl_tool_environment_option_table};
    size_t ntables = sizeof tables / sizeof tables[0];
    tl_opt_parser p;
    tl_opt_begin(&p, VW_TOOL, argc, argv, tables, ntables);
    const tl_opt *o;
    tl_opt_value v;
    int rc;
    while ((rc = tl_opt_next(&p, &o, &v)) == 1) {
        if (!o) {
            if (a->scene) return tl_opt_usage(VW_TOOL, "more than one scene: '%s'", v.text);
            a->scene = v.text;
        } else if ((rc = vw_apply(a, tables, ntables, o, &v)) >= 0) {
            return rc;
        }
    }
    if (rc) return rc;
    if (a->scene && !strcmp(a->scene, "crypt")) a->scene = NULL;
    if (a->screenshot && !a->frames) a->frames = 3;
    if (!(a->light_budget_ms > 0.0)) a->light_budget_ms = 1000.0 / 30.0;
    return -1;
}
