/* Renderer options with their defaults resolved (the one place a zeroed field becomes a value):
 * the options of the frame as a whole here, each pass's own options (its slice of
 * tl_renderer_options) by its pass (tl__pass_def.resolve). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "plan_internal.h"
#include "shadows.h"

/* The general options: their defaults, and the first one out of range named in *bad. */
static int tl__general_resolve(tl_renderer_options *o, const char **bad)
{
    if (o->mode == TL_MODE_DEFAULT) o->mode = TL_MODE_THIN_LPP;
    if (o->depth_format == TL_DEPTH_FORMAT_DEFAULT) o->depth_format = TL_DEPTH_FORMAT_D24;
    if (o->rt0 == TL_RT0_DEFAULT) o->rt0 = TL_RT0_RGBA8;
    if (o->light_buffer == TL_LIGHT_BUFFER_DEFAULT) o->light_buffer = TL_LIGHT_BUFFER_EXACT;
    if (o->light_format == TL_LIGHT_FORMAT_DEFAULT) o->light_format = TL_LIGHT_FORMAT_RGBA16F;
    if (o->tiled_shading == TL_TILED_SHADING_DEFAULT) o->tiled_shading = TL_TILED_SHADING_FRAGMENT;
    if (o->fresnel == TL_FRESNEL_DEFAULT) o->fresnel = TL_FRESNEL_TWO_SUMS;
    if (!o->tile_size) o->tile_size = TL__TILE_SIZE_DEFAULT;
    if (o->fxaa == TL_FXAA_DEFAULT) o->fxaa = TL_FXAA_29;
    if (o->fxaa_edge_threshold <= 0.0f) o->fxaa_edge_threshold = 0.166f;
    if (o->fxaa_edge_threshold_min <= 0.0f) o->fxaa_edge_threshold_min = 0.0833f;
    if (o->fxaa_subpix == 0.0f) o->fxaa_subpix = 0.75f;
    if (o->fxaa_subpix < 0.0f) o->fxaa_subpix = 0.0f;
    if (!(o->exposure > 0.0f)) o->exposure = 1.0f;
    if (o->light_scale == 0.0f) o->light_scale = 1.0f;
    if (o->msaa == 0) o->msaa = 1;
    tl__shadow_desc_resolve(&o->shadows);
    const struct { int bad; const char *name; } checks[] = {
        {(unsigned)o->mode >= TL_MODE_COUNT_, "mode"},
        {(unsigned)o->depth_format >= TL_DEPTH_FORMAT_COUNT_, "depth_format"},
        {(unsigned)o->rt0 >= TL_RT0_COUNT_, "rt0"},
        {(unsigned)o->light_buffer >= TL_LIGHT_BUFFER_COUNT_, "light_buffer"},
        {(unsigned)o->fxaa >= TL_FXAA_COUNT_, "fxaa"},
        {(unsigned)o->light_format >= TL_LIGHT_FORMAT_COUNT_, "light_format"},
        {(unsigned)o->light_strategy >= TL_LIGHT_STRATEGY_COUNT_, "light_strategy"},
        {(unsigned)o->tiled_shading >= TL_TILED_SHADING_COUNT_, "tiled_shading"},
        {(unsigned)o->lighting >= TL_LIGHTING_COUNT_, "lighting"},
        {(unsigned)o->fresnel >= TL_FRESNEL_COUNT_, "fresnel"},
        {(unsigned)o->transparency >= TL_TRANSPARENCY_COUNT_, "transparency"},
        {!isfinite(o->ambient[0]) || !isfinite(o->ambient[1]) || !isfinite(o->ambient[2]), "ambient"},
        {o->tile_size != 8 && o->tile_size != 16 && o->tile_size != 32, "tile_size (8, 16 or 32)"},
        {o->light_scale != 1.0f && o->light_scale != 0.5f && o->light_scale != 0.25f, "light_scale (1, 0.5 or 0.25)"},
        {!tl__shadow_desc_valid(&o->shadows), "shadows (atlas_size a power of two in 1024..16384, max_lights 1..64, pcf_radius 0..3, filter PCF or PCSS, directional_angle 0..0.2)"},
        {o->msaa != 1 && o->msaa != 2 && o->msaa != 4 && o->msaa != 8, "msaa (0, 1, 2, 4 or 8 samples)"},
        {(unsigned)o->msaa_lighting >= TL_MSAA_LIGHTING_COUNT_, "msaa_lighting"},
        {(unsigned)o->clearcoat >= TL_CLEARCOAT_COUNT_, "clearcoat"},
        /* R11G11B10F has no alpha for the compact layout's specular luminance */
        {o->light_format == TL_LIGHT_FORMAT_R11G11B10F && o->light_buffer != TL_LIGHT_BUFFER_EXACT,
         "light_format (R11G11B10F needs the exact light buffer)"},
    };
    for (size_t i = 0; i < sizeof checks / sizeof checks[0]; i++)
        if (checks[i].bad) {
            *bad = checks[i].name;
            return 0;
        }
    return 1;
}

tl_result tl__options_resolve(const tl_renderer_options *in, tl_renderer_options *out, const char **bad)
{
    const char *unused;
    if (!bad) bad = &unused;
    *out = *in;
    if (!tl__general_resolve(out, bad)) return TL_ERROR_INVALID_ARGUMENT;
    for (int i = 0; i < TL_PASS_COUNT; i++) {
        const tl__pass_def *def = tl__pass_table[i];
        if (def->resolve && !def->resolve((char *)out + def->options_offset)) {
            *bad = def->options_name;
            return TL_ERROR_INVALID_ARGUMENT;
        }
    }
    return TL_OK;
}

tl_result tl__renderer_desc_resolve(const tl_renderer_desc *in, tl_renderer_desc *d, const char **bad)
{
    const char *unused;
    if (!bad) bad = &unused;
    *bad = "size";
    tl_renderer_desc r = *in;
    if (!r.width) r.width = 1280;
    if (!r.height) r.height = 720;
    tl_result res = tl__options_resolve(&in->options, &r.options, bad);
    *d = r;
    if (res != TL_OK) return res;
    if (r.width > TL__MAX_SIZE || r.height > TL__MAX_SIZE) {
        *bad = "size";
        return TL_ERROR_LIMIT;
    }
    return TL_OK;
}
