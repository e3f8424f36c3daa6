/* Renderer options with their defaults resolved (the one place a zeroed field becomes a value). */
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
    if (d->fxaa == TL_FXAA_DEFAULT) d->fxaa = TL_FXAA_29;
    if (d->fxaa_edge_threshold <= 0.0f) d->fxaa_edge_threshold = 0.166f;
    if (d->fxaa_edge_threshold_min <= 0.0f) d->fxaa_edge_threshold_min = 0.0833f;
    if (d->fxaa_subpix == 0.0f) d->fxaa_subpix = 0.75f;
    if (d->fxaa_subpix < 0.0f) d->fxaa_subpix = 0.0f;
    if (!(d->exposure > 0.0f)) d->exposure = 1.0f;
    if ((unsigned)d->mode >= TL_MODE_COUNT_ || (unsigned)d->depth_format >= TL_DEPTH_FORMAT_COUNT_ ||
        (unsigned)d->rt0 >= TL_RT0_COUNT_ || (unsigned)d->light_buffer >= TL_LIGHT_BUFFER_COUNT_ ||
        (unsigned)d->fxaa >= TL_FXAA_COUNT_)
        return TL_ERROR_INVALID_ARGUMENT;
    if (d->width > TL__MAX_SIZE || d->height > TL__MAX_SIZE) return TL_ERROR_LIMIT;
    return TL_OK;
}
