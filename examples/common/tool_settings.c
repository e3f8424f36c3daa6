/* The renderer settings the tools share (tool_settings.h). */
#include "tool_settings.h"

const char tl_tool_settings_help[] =
    "  --mode MODE           thin-lpp (default), thin-deferred, fat or forward\n"
    "  --no-depth-prepass    forward mode without its depth pre-pass\n"
    "  --light-strategy S    auto (default), volumes or tiled\n"
    "  --light-scale K       thin-lpp: light buffer size per axis, 1 (default), 0.5 or 0.25\n"
    "  --transparency T      alpha-blended materials: auto (default: stipple where it applies),\n"
    "                        forward or stipple (thin-lpp: layers in the G-buffer's 2x2 stipple)\n"
    "  --depth FMT           d24 (default) or d32f-reversed\n"
    "  --rt0 FMT             rgba8 (default: oct 2x12 + gloss 8) or rgb10a2\n"
    "  --light-buffer L      exact (default: diffuse + specular RGBA16F) or compact (one RGBA16F)\n"
    "  --light-format F      rgba16f (default) or r11g11b10f (light buffer storage; exact layout)\n"
    "  --lighting M          auto (default: ggx for glTF materials, else blinn-phong), blinn-phong\n"
    "                        or ggx\n"
    "  --fresnel F           thin-lpp with GGX: two-sums (default: exact, light.fresnel target) or\n"
    "                        nv (one specular sum, Schlick with n.v per pixel)\n"
    "  --ambient A           ambient radiance replacing the scene's (0 turns it off; at most 65504)\n"
    "  --tile-size T         tiled: 8, 16 (default) or 32 pixels\n"
    "  --tiled-shading K     tiled: fragment (default) or compute\n"
    "  --fxaa P              off, 12, 29 (default) or 39\n"
    "  --msaa N              1 (default: off), 2, 4 or 8 samples: thin-lpp's material pass, or forward,\n"
    "                        multisampled (with --fxaa off for MSAA alone)\n"
    "  --msaa-lighting L     with --msaa: default (thin-lpp: material-pass; thin-deferred, fat:\n"
    "                        per-sample-edges), material-pass or per-sample-edges (thin-lpp too: a\n"
    "                        multisampled G-buffer, edge pixels lit per sample)\n"
    "  --clearcoat C         thin-lpp's clearcoat: auto (default: the coat's own sums where they apply),\n"
    "                        approx (the base's specular takes the coat's lobe) or sums\n"
    "  --exposure E          exposure before tone mapping (default 1; above 0, at most 1e6)\n";

enum { S_MODE, S_NO_PREPASS, S_STRATEGY, S_DEPTH, S_RT0, S_LIGHT_BUFFER, S_LIGHT_FORMAT, S_LIGHTING, S_FRESNEL,
       S_AMBIENT, S_TILE_SIZE, S_TILED_SHADING, S_FXAA, S_EXPOSURE, S_LIGHT_SCALE, S_TRANSPARENCY, S_MSAA,
       S_MSAA_LIGHTING, S_CLEARCOAT };

static const char *const depth_names[] = {"d24", "d32f-reversed", NULL};
static const int depth_values[] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};
static const char *const rt0_names[] = {"rgba8", "rgb10a2", NULL};
static const int rt0_values[] = {TL_RT0_RGBA8, TL_RT0_RGB10A2};
static const char *const light_buffer_names[] = {"exact", "compact", NULL};
static const int light_buffer_values[] = {TL_LIGHT_BUFFER_EXACT, TL_LIGHT_BUFFER_COMPACT};
static const char *const light_format_names[] = {"rgba16f", "r11g11b10f", NULL};
static const int light_format_values[] = {TL_LIGHT_FORMAT_RGBA16F, TL_LIGHT_FORMAT_R11G11B10F};
static const char *const tile_names[] = {"8", "16", "32", NULL};
static const int tile_values[] = {8, 16, 32};
static const char *const shading_names[] = {"fragment", "compute", NULL};
static const int shading_values[] = {TL_TILED_SHADING_FRAGMENT, TL_TILED_SHADING_COMPUTE};
static const char *const light_scale_names[] = {"1", "0.5", "0.25", NULL};
static const int light_scale_values[] = {1, 2, 4}; /* the divisor */
static const char *const transparency_names[] = {"auto", "forward", "stipple", NULL};
static const int transparency_values[] = {TL_TRANSPARENCY_DEFAULT, TL_TRANSPARENCY_FORWARD, TL_TRANSPARENCY_STIPPLE};
static const char *const msaa_names[] = {"1", "2", "4", "8", NULL};
static const int msaa_values[] = {1, 2, 4, 8};
static const char *const msaa_lighting_names[] = {"default", "material-pass", "per-sample-edges", NULL};
static const int msaa_lighting_values[] = {TL_MSAA_LIGHTING_DEFAULT, TL_MSAA_LIGHTING_MATERIAL_PASS,
                                           TL_MSAA_LIGHTING_SAMPLE_EDGES};
static const char *const clearcoat_names[] = {"auto", "approx", "sums", NULL};
static const int clearcoat_values[] = {TL_CLEARCOAT_DEFAULT, TL_CLEARCOAT_APPROXIMATE, TL_CLEARCOAT_SUMS};
static const char *const fxaa_names[] = {"off", "12", "29", "39", NULL};
static const int fxaa_values[] = {TL_FXAA_OFF, TL_FXAA_12, TL_FXAA_29, TL_FXAA_39};

#define CHOICE(names) .choices = names##_names, .values = names##_values

static const tl_opt settings_opts[] = {
    {"--mode", TL_OPT_TEXT, .id = S_MODE},
    {"--no-depth-prepass", TL_OPT_FLAG, .id = S_NO_PREPASS},
    {"--light-strategy", TL_OPT_TEXT, .id = S_STRATEGY},
    {"--light-scale", TL_OPT_TEXT, .id = S_LIGHT_SCALE, CHOICE(light_scale)},
    {"--transparency", TL_OPT_TEXT, .id = S_TRANSPARENCY, CHOICE(transparency)},
    {"--depth", TL_OPT_TEXT, .id = S_DEPTH, CHOICE(depth)},
    {"--rt0", TL_OPT_TEXT, .id = S_RT0, CHOICE(rt0)},
    {"--light-buffer", TL_OPT_TEXT, .id = S_LIGHT_BUFFER, CHOICE(light_buffer)},
    {"--light-format", TL_OPT_TEXT, .id = S_LIGHT_FORMAT, CHOICE(light_format)},
    {"--lighting", TL_OPT_TEXT, .id = S_LIGHTING},
    {"--fresnel", TL_OPT_TEXT, .id = S_FRESNEL},
    {"--ambient", TL_OPT_REAL, .id = S_AMBIENT, .min = 0.0, .max = 65504.0},
    {"--tile-size", TL_OPT_TEXT, .id = S_TILE_SIZE, CHOICE(tile)},
    {"--tiled-shading", TL_OPT_TEXT, .id = S_TILED_SHADING, CHOICE(shading)},
    {"--fxaa", TL_OPT_TEXT, .id = S_FXAA, CHOICE(fxaa)},
    {"--msaa", TL_OPT_TEXT, .id = S_MSAA, CHOICE(msaa)},
    {"--msaa-lighting", TL_OPT_TEXT, .id = S_MSAA_LIGHTING, CHOICE(msaa_lighting)},
    {"--clearcoat", TL_OPT_TEXT, .id = S_CLEARCOAT, CHOICE(clearcoat)},
    {"--exposure", TL_OPT_REAL, .id = S_EXPOSURE, .min = 0.0, .max = 1e6, .flags = TL_OPT_MIN_OPEN},
};

const tl_opt_table tl_tool_settings_option_table = TL_OPT_TABLE(settings_opts);

/* The options whose names the library knows (tl_*_from_name): 1, or 2 after one line. */
static int tl__settings_named(const char *tool, tl_renderer_desc *d, int id, const char *v)
{
    if (id == S_MODE && tl_render_mode_from_name(v, &d->options.mode) != TL_OK)
        return tl_opt_usage(tool, "--mode '%s': wants thin-lpp, thin-deferred, fat or forward", v);
    if (id == S_STRATEGY && tl_light_strategy_from_name(v, &d->options.light_strategy) != TL_OK)
        return tl_opt_usage(tool, "--light-strategy '%s': wants volumes, tiled or auto", v);
    if (id == S_LIGHTING && tl_lighting_model_from_name(v, &d->options.lighting) != TL_OK)
        return tl_opt_usage(tool, "--lighting '%s': wants blinn-phong, ggx or auto", v);
    if (id == S_FRESNEL && tl_fresnel_layout_from_name(v, &d->options.fresnel) != TL_OK)
        return tl_opt_usage(tool, "--fresnel '%s': wants two-sums or nv", v);
    return 1;
}

int tl_tool_settings_apply(const char *tool, tl_renderer_desc *d, const tl_opt *o, const tl_opt_value *v)
{
    if (!tl_opt_in(o, tl_tool_settings_option_table)) return 0;
    int u = (int)v->u[0];
    switch (o->id) {
    case S_NO_PREPASS: d->options.forward_no_depth_prepass = 1; break;
    case S_DEPTH: d->options.depth_format = (tl_depth_format)u; break;
    case S_RT0: d->options.rt0 = (tl_rt0_packing)u; break;
    case S_LIGHT_BUFFER: d->options.light_buffer = (tl_light_buffer)u; break;
    case S_LIGHT_FORMAT: d->options.light_format = (tl_light_format)u; break;
    case S_AMBIENT: /* zero is "the scene's" in the descriptor; a negative value means exactly 0 */
        d->options.ambient[0] = d->options.ambient[1] = d->options.ambient[2] = v->f[0] > 0.0 ? (float)v->f[0] : -1.0f;
        break;
    case S_TILE_SIZE: d->options.tile_size = (uint32_t)u; break;
    case S_TILED_SHADING: d->options.tiled_shading = (tl_tiled_shading)u; break;
    case S_FXAA: d->options.fxaa = (tl_fxaa_preset)u; break;
    case S_EXPOSURE: d->options.exposure = (float)v->f[0]; break;
    case S_LIGHT_SCALE: d->options.light_scale = 1.0f / (float)u; break;
    case S_TRANSPARENCY: d->options.transparency = (tl_transparency)u; break;
    case S_MSAA: d->options.msaa = (uint32_t)u; break;
    case S_MSAA_LIGHTING: d->options.msaa_lighting = (tl_msaa_lighting)u; break;
    case S_CLEARCOAT: d->options.clearcoat = (tl_clearcoat_lighting)u; break;
    default: return tl__settings_named(tool, d, o->id, v->text);
    }
    return 1;
}
