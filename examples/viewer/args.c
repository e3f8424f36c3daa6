/* The viewer's command line and --help (which lists every key). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "tool_effects.h"

static const char vw_usage[] =
    "usage: thinlight-viewer [SCENE.gltf|SCENE.glb|crypt] [options]\n"
    "Opens a window on the built-in crypt (default) or a glTF 2.0 file.\n"
    "  --size WxH            window size (default 1280x720)\n"
    "  --mode MODE           thin-lpp (default), thin-deferred, fat or forward\n"
    "  --light-strategy S    auto (default), volumes or tiled\n"
    "  --depth FMT           d24 (default) or d32f-reversed\n"
    "  --rt0 FMT             rgba8 (default) or rgb10a2\n"
    "  --light-buffer L      exact (default) or compact\n"
    "  --fxaa P              off, 12, 29 (default) or 39\n"
    "  --exposure E          exposure before tone mapping (default 1)\n"
    "  --lights N            crypt: point lights (default 64); glTF: seeded point lights added\n"
    "  --view V              final (default), normals, gloss, luma, chroma, albedo, depth, position,\n"
    "                        light-diffuse, light-specular, tile-lights, hdr, before-fxaa, diff-fat,\n"
    "                        ao-raw, ao (with --ssao), dof-coc (with --dof), ssr (with --ssr),\n"
    "                        bloom (with --bloom)\n"
    "  --grid                every view as thumbnails\n"
    "  --split MODE          left half in --mode, right half in MODE\n"
    "  --animate             move the lights\n"
    "  --no-panel            hide the panel\n"
    "  --screenshot FILE     write the view (without the panel) as PNG after --frames and exit\n"
    "  --screenshot-window FILE  the same with the panel, as the window shows it\n"
    "  --frames N            frames to render before the screenshot (default 3); alone: exit after N\n"
    "  --resize WxH          resize the window after the first frames (tests)\n"
    "  --print-targets       print the targets' size and bytes whenever they are (re)allocated\n"
    "  --help                this text\n"
    "Screen-space effects (as thinlight-render; the panel's Effects section changes them live):\n";

static const char vw_keys[] =
    "Keys (when the panel does not have the keyboard):\n"
    "  left drag             orbit (orbit camera) or look around (fly camera)\n"
    "  right drag            look around\n"
    "  W A S D, Q E          fly forward, left, back, right, down, up (switches to the fly camera)\n"
    "  Shift                 fly 4x faster\n"
    "  scroll                zoom (orbit) or move forward (fly)\n"
    "  F                     toggle fly / orbit camera\n"
    "  C                     back to the scene's camera\n"
    "  1 2 3 4               mode: thin-lpp, thin-deferred, fat, forward\n"
    "  T                     light strategy: auto, volumes, tiled\n"
    "  V / Shift+V           next / previous debug view\n"
    "  0                     the final view\n"
    "  G                     grid of every view\n"
    "  X                     split view (left: the mode, right: fat, or the mode chosen in the panel)\n"
    "  + / -                 light count x2 / /2\n"
    "  L                     animate the lights on / off\n"
    "  [ / ]                 exposure /1.25 / x1.25\n"
    "  H or F1               hide / show the panel\n"
    "  P or F12              screenshot (viewer-N.png in the current directory)\n"
    "  Escape                quit\n";

void vw_print_usage(FILE *f)
{
    fputs(vw_usage, f);
    fputs(tl_tool_effects_help, f);
    fputs(vw_keys, f);
}

static int vw_bad(const char *what, const char *value)
{
    fprintf(stderr, "thinlight-viewer: %s%s%s (see --help)\n", what, value ? ": " : "", value ? value : "");
    return 2;
}

static int vw_parse_u32(const char *s, uint32_t *out, uint32_t max)
{
    char *end;
    unsigned long v = strtoul(s, &end, 10);
    if (!*s || *end || s[0] == '-' || v > max) return 0;
    *out = (uint32_t)v;
    return 1;
}

static int vw_parse_size(const char *s, uint32_t *w, uint32_t *h)
{
    unsigned a, b;
    char extra;
    if (sscanf(s, "%ux%u%c", &a, &b, &extra) != 2 || a < 16 || b < 16 || a > 8192 || b > 8192) return 0;
    *w = a;
    *h = b;
    return 1;
}

/* The renderer settings: 1 when `opt` was one of them, -1 for a bad value. */
static int vw_parse_setting(vw_args *a, const char *opt, const char *v)
{
    tl_renderer_desc *d = &a->desc;
    if (!strcmp(opt, "--mode")) return tl_render_mode_from_name(v, &d->mode) == TL_OK ? 1 : -1;
    if (!strcmp(opt, "--light-strategy")) return tl_light_strategy_from_name(v, &d->light_strategy) == TL_OK ? 1 : -1;
    if (!strcmp(opt, "--depth")) {
        if (!strcmp(v, "d24")) d->depth_format = TL_DEPTH_FORMAT_D24;
        else if (!strcmp(v, "d32f-reversed")) d->depth_format = TL_DEPTH_FORMAT_D32F_REVERSED;
        else return -1;
    } else if (!strcmp(opt, "--rt0")) {
        if (!strcmp(v, "rgba8")) d->rt0 = TL_RT0_RGBA8;
        else if (!strcmp(v, "rgb10a2")) d->rt0 = TL_RT0_RGB10A2;
        else return -1;
    } else if (!strcmp(opt, "--light-buffer")) {
        if (!strcmp(v, "exact")) d->light_buffer = TL_LIGHT_BUFFER_EXACT;
        else if (!strcmp(v, "compact")) d->light_buffer = TL_LIGHT_BUFFER_COMPACT;
        else return -1;
    } else if (!strcmp(opt, "--fxaa")) {
        static const char *names[] = {"off", "12", "29", "39"};
        int found = 0;
        for (int i = 0; i < 4; i++)
            if (!strcmp(v, names[i])) { d->fxaa = (tl_fxaa_preset)(TL_FXAA_OFF + i); found = 1; }
        if (!found) return -1;
    } else if (!strcmp(opt, "--exposure")) {
        char *end;
        d->exposure = strtof(v, &end);
        if (*end || !(d->exposure > 0.0f) || d->exposure > 1e6f) return -1;
    } else {
        return 0;
    }
    return 1;
}

/* Options with a value; the step's status, or -1 to go on. */
static int vw_parse_valued(vw_args *a, const char *opt, const char *v)
{
    int s = vw_parse_setting(a, opt, v);
    if (s < 0) return vw_bad(opt, v);
    if (s > 0) return -1;
    if (!strcmp(opt, "--size")) { if (!vw_parse_size(v, &a->width, &a->height)) return vw_bad("--size wants WxH, 16..8192", v); }
    else if (!strcmp(opt, "--resize")) { if (!vw_parse_size(v, &a->resize_w, &a->resize_h)) return vw_bad("--resize wants WxH", v); }
    else if (!strcmp(opt, "--lights")) { if (!vw_parse_u32(v, &a->lights, 65536)) return vw_bad("--lights wants 0..65536", v); a->lights_set = 1; }
    else if (!strcmp(opt, "--frames")) { if (!vw_parse_u32(v, &a->frames, 100000) || !a->frames) return vw_bad("--frames wants 1..100000", v); }
    else if (!strcmp(opt, "--view")) { if (!vw_view_from_name(v, &a->view)) return vw_bad("unknown view", v); }
    else if (!strcmp(opt, "--split")) { if (tl_render_mode_from_name(v, &a->split_mode) != TL_OK) return vw_bad("--split wants a mode", v); a->split = 1; }
    else if (!strcmp(opt, "--screenshot")) a->screenshot = v;
    else if (!strcmp(opt, "--screenshot-window")) { a->screenshot = v; a->screenshot_window = 1; }
    else return vw_bad("unknown option", opt);
    return -1;
}

int vw_parse_args(int argc, char **argv, vw_args *a)
{
    memset(a, 0, sizeof *a);
    int fx;
    a->width = 1280;
    a->height = 720;
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i];
        if (!strcmp(o, "--help") || !strcmp(o, "-h")) { vw_print_usage(stdout); return 0; }
        if (!strcmp(o, "--grid")) a->grid = 1;
        else if (!strcmp(o, "--animate")) a->animate = 1;
        else if (!strcmp(o, "--no-panel")) a->no_panel = 1;
        else if (!strcmp(o, "--print-targets")) a->print_targets = 1;
        else if (o[0] == '-' && o[1] == '-' && (fx = tl_tool_effect_option("thinlight-viewer", &a->desc, o,
                                                                            i + 1 < argc ? argv[i + 1] : NULL)) != 0) {
            if (fx < 0) return 2; /* the line is printed */
            i += fx - 1;          /* 2: it took the value */
        } else if (o[0] == '-' && o[1] == '-') {
            if (i + 1 >= argc) return vw_bad("missing value for", o);
            int s = vw_parse_valued(a, o, argv[++i]);
            if (s >= 0) return s;
        } else if (!a->scene) a->scene = o;
        else return vw_bad("more than one scene", o);
    }
    if (a->scene && !strcmp(a->scene, "crypt")) a->scene = NULL;
    if (a->screenshot && !a->frames) a->frames = 3;
    return -1;
}
