/* The shadow module's debug reads (tl_renderer_get_shadow_views, tl_renderer_read_shadow_atlas). */
#include "renderer_internal.h"

tl_result tl_renderer_get_shadow_views(tl_renderer *r, tl_shadow_view_info *views, size_t *count, uint32_t *atlas_size)
{
    if (!r || !count) return TL_ERROR_INVALID_ARGUMENT;
    if (atlas_size) *atlas_size = r->shadows.atlas ? r->shadows.atlas_size : 0;
    if (!r->graph.plan.pub.shadow_lights) { /* the views of an earlier plan are gone with it */
        *count = 0;
        return TL_OK;
    }
    size_t have = *count;
    tl_result res = tl__shadows_views(&r->shadows, r->lights.lights, r->lights.count, views, count);
    if (res != TL_OK)
        return tl__fail(&r->dev, res, "renderer: %zu shadow views, the buffer holds %zu", *count, have);
    return TL_OK;
}

tl_result tl_renderer_read_shadow_atlas(tl_renderer *r, float *depth, size_t *size)
{
    if (!r || !size) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = depth ? tl__need_context(&r->dev, "tl_renderer_read_shadow_atlas") : TL_OK;
    if (res != TL_OK) return res;
    return tl__shadows_read_atlas(&r->dev, &r->shadows, depth, size);
}
