/* Renderer options with their defaults resolved (the one place a zeroed field becomes a value). */
#include <math.h>

#include "plan_internal.h"

tl_result tl__renderer_desc_resolve(const tl_renderer_desc *in, tl_renderer_desc *d)
{
    *d = *in;
    if (d->mode == TL_MODE_DEFAULT) d->mode = TL_MODE_THIN_LPP;
    if (!d->width) d->width = 1280;
    if (!d->height) d->height = 720;
    if (d->depth_format == TL_DEPTH_FORMAT_DEFAULT) d->depth_format = TL_DEPTH_FORMAT_D24;
    if (d->rt0 == TL_RT0_DEFAULT) d->rt0 = TL_RT0_RGBA8;
    if (d->light_buffer == TL_LIGHT_BUFFER_DEFAULT) d->light_buffer = TL_LIGHT_BUFFER_EXACT;
    if (d->light_format == TL_LIGHT_FORMAT_DEFAULT) d->light_format = TL_LIGHT_FORMAT_RGBA16F;
    if (d->tiled_shading == TL_TILED_SHADING_DEFAULT) d->tiled_shading = TL_TILED_SHADING_FRAGMENT;
    if (d->fresnel == TL_FRESNEL_DEFAULT) d->fresnel = TL_FRESNEL_TWO_SUMS;
    if (!d->tile_size) d->tile_size = TL__TILE_SIZE_DEFAULT;
    if (d->fxaa == TL_FXAA_DEFAULT) d->fxaa = TL_FXAA_29;
    if (d->fxaa_edge_threshold <= 0.0f) d->fxaa_edge_threshold = 0.166f;
    if (d->fxaa_edge_threshold_min <= 0.0f) d->fxaa_edge_threshold_min = 0.0833f;
    if (d->fxaa_subpix == 0.0f) d->fxaa_subpix = 0.75f;
    if (d->fxaa_subpix < 0.0f) d->fxaa_subpix = 0.0f;
    if (!(d->exposure > 0.0f)) d->exposure = 1.0f;
    if ((unsigned)d->mode >= TL_MODE_COUNT_ || (unsigned)d->depth_format >= TL_DEPTH_FORMAT_COUNT_ ||
        (unsigned)d->rt0 >= TL_RT0_COUNT_ || (unsigned)d->light_buffer >= TL_LIGHT_BUFFER_COUNT_ ||
        (unsigned)d->fxaa >= TL_FXAA_COUNT_ || (unsigned)d->light_format >= TL_LIGHT_FORMAT_COUNT_ ||
        (unsigned)d->light_strategy >= TL_LIGHT_STRATEGY_COUNT_ || (unsigned)d->tiled_shading >= TL_TILED_SHADING_COUNT_ ||
        (unsigned)d->lighting >= TL_LIGHTING_COUNT_ || (unsigned)d->fresnel >= TL_FRESNEL_COUNT_)
        return TL_ERROR_INVALID_ARGUMENT;
    for (int k = 0; k < 3; k++)
        if (!isfinite(d->ambient[k])) return TL_ERROR_INVALID_ARGUMENT;
    if (d->tile_size != 8 && d->tile_size != 16 && d->tile_size != 32) return TL_ERROR_INVALID_ARGUMENT;
    /* R11G11B10F has no alpha for the compact layout's specular luminance */
    if (d->light_format == TL_LIGHT_FORMAT_R11G11B10F && d->light_buffer != TL_LIGHT_BUFFER_EXACT)
        return TL_ERROR_INVALID_ARGUMENT;
    if (d->width > TL__MAX_SIZE || d->height > TL__MAX_SIZE) return TL_ERROR_LIMIT;
    return TL_OK;
}
