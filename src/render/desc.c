/* Renderer options with their defaults resolved (the one place a zeroed field becomes a value):
 * the options of the frame as a whole here, each pass's own options (its slice of
 * tl_renderer_options) by its pass (tl__pass_def.resolve). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "plan_internal.h"
#include "shadows.h"

/* The general options' defaults. */
static void tl__general_defaults(tl_renderer_options *o)
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
}

/* The general options: their defaults, and the first one out of range named in `why` with its
 * value and range. */
static int tl__general_resolve(tl_renderer_options *o, tl__why *why)
{
    tl__general_defaults(o);
    const float *am = o->ambient;
    const tl__option_range rows[] = {
        TL__RANGE_ENUM("mode", o->mode, TL_MODE_COUNT_, "tl_render_mode"),
        TL__RANGE_ENUM("depth_format", o->depth_format, TL_DEPTH_FORMAT_COUNT_, "tl_depth_format"),
        TL__RANGE_ENUM("rt0", o->rt0, TL_RT0_COUNT_, "tl_rt0_packing"),
        TL__RANGE_ENUM("light_buffer", o->light_buffer, TL_LIGHT_BUFFER_COUNT_, "tl_light_buffer"),
        TL__RANGE_ENUM("fxaa", o->fxaa, TL_FXAA_COUNT_, "tl_fxaa_preset"),
        TL__RANGE_ENUM("light_format", o->light_format, TL_LIGHT_FORMAT_COUNT_, "tl_light_format"),
        TL__RANGE_ENUM("light_strategy", o->light_strategy, TL_LIGHT_STRATEGY_COUNT_, "tl_light_strategy"),
        TL__RANGE_ENUM("tiled_shading", o->tiled_shading, TL_TILED_SHADING_COUNT_, "tl_tiled_shading"),
        TL__RANGE_ENUM("lighting", o->lighting, TL_LIGHTING_COUNT_, "tl_lighting_model"),
        TL__RANGE_ENUM("fresnel", o->fresnel, TL_FRESNEL_COUNT_, "tl_fresnel_layout"),
        TL__RANGE_ENUM("transparency", o->transparency, TL_TRANSPARENCY_COUNT_, "tl_transparency"),
        TL__RANGE_FLOAT(!isfinite(am[0]), "ambient[0]", am[0], "finite"),
        TL__RANGE_FLOAT(!isfinite(am[1]), "ambient[1]", am[1], "finite"),
        TL__RANGE_FLOAT(!isfinite(am[2]), "ambient[2]", am[2], "finite"),
        TL__RANGE_FLOAT(!isfinite(o->fxaa_edge_threshold), "fxaa_edge_threshold", o->fxaa_edge_threshold,
                        "finite; <= 0: 0.166"),
        TL__RANGE_FLOAT(!isfinite(o->fxaa_edge_threshold_min), "fxaa_edge_threshold_min", o->fxaa_edge_threshold_min,
                        "finite; <= 0: 0.0833"),
        TL__RANGE_FLOAT(!isfinite(o->fxaa_subpix), "fxaa_subpix", o->fxaa_subpix, "finite; 0: 0.75, < 0: 0"),
        TL__RANGE_FLOAT(!isfinite(o->exposure), "exposure", o->exposure, "finite; <= 0: 1"),
        TL__RANGE_INT(o->tile_size != 8 && o->tile_size != 16 && o->tile_size != 32, "tile_size", o->tile_size,
                      "8, 16 or 32; 0: 16"),
        TL__RANGE_FLOAT(o->light_scale != 1.0f && o->light_scale != 0.5f && o->light_scale != 0.25f, "light_scale",
                        o->light_scale, "1, 0.5 or 0.25; 0: 1"),
        TL__RANGE_INT(o->msaa != 1 && o->msaa != 2 && o->msaa != 4 && o->msaa != 8, "msaa", o->msaa,
                      "0, 1, 2, 4 or 8 samples"),
        TL__RANGE_ENUM("msaa_lighting", o->msaa_lighting, TL_MSAA_LIGHTING_COUNT_, "tl_msaa_lighting"),
        TL__RANGE_ENUM("clearcoat", o->clearcoat, TL_CLEARCOAT_COUNT_, "tl_clearcoat_lighting"),
    };
    if (!tl__option_ranges(rows, sizeof rows / sizeof rows[0], "options", why)) return 0;
    if (!tl__shadow_desc_check(&o->shadows, "options.shadows", why)) return 0;
    /* R11G11B10F has no alpha for the compact layout's specular luminance */
    if (o->light_format == TL_LIGHT_FORMAT_R11G11B10F && o->light_buffer != TL_LIGHT_BUFFER_EXACT)
        return tl__why_say(why, "options.light_format = %d (R11G11B10F) needs options.light_buffer = %d (EXACT), not %d",
                           (int)o->light_format, (int)TL_LIGHT_BUFFER_EXACT, (int)o->light_buffer);
    return 1;
}

tl_result tl__options_resolve(const tl_renderer_options *in, tl_renderer_options *out, tl__why *why)
{
    *out = *in;
    if (!tl__general_resolve(out, why)) return TL_ERROR_INVALID_ARGUMENT;
    for (int i = 0; i < TL_PASS_COUNT; i++) {
        const tl__pass_def *def = tl__pass_table[i];
        char prefix[64];
        snprintf(prefix, sizeof prefix, "options.%s", def->options_name ? def->options_name : "");
        if (def->resolve && !def->resolve((char *)out + def->options_offset, prefix, why))
            return TL_ERROR_INVALID_ARGUMENT;
    }
    return TL_OK;
}

tl_result tl__renderer_desc_resolve(const tl_renderer_desc *in, tl_renderer_desc *d, tl__why *why)
{
    tl_renderer_desc r = *in;
    if (!r.width) r.width = 1280;
    if (!r.height) r.height = 720;
    tl_result res = tl__options_resolve(&in->options, &r.options, why);
    *d = r;
    if (res != TL_OK) return res;
    if (r.width > TL__MAX_SIZE || r.height > TL__MAX_SIZE) {
        tl__why_say(why, "size %ux%u is over %u per side", r.width, r.height, TL__MAX_SIZE);
        return TL_ERROR_LIMIT;
    }
    return TL_OK;
}
