/* The shadow views (docs/viewer.md, docs/shadows.md "Debug views"): the atlas's depth read back
 * with tl_renderer_read_shadow_atlas, and the shadow-debug pass's target (tl_renderer_options.
 * shadow_debug, which vw_options turns on for these views): the cascade of each pixel and the
 * shadow-only term. Every value shown is the renderer's; this file only colours it. */
#include <stdio.h>
#include <stdlib.h>

#include "viewer.h"

static void vw_px(uint8_t *p, float r, float g, float b)
{
    float c[3] = {r, g, b};
    for (int k = 0; k < 3; k++) p[k] = (uint8_t)(c[k] <= 0.0f ? 0 : c[k] >= 1.0f ? 255 : (int)(c[k] * 255.0f + 0.5f));
    p[3] = 255;
}

int vw_shadow_debug_wanted(const vw_app *app)
{
    return app->grid || app->view == VW_VIEW_SHADOW_CASCADES || app->view == VW_VIEW_SHADOW_ONLY;
}

/* The shadow-debug target into app->scratch[0], or NULL with the reason in the view's note. */
static const float *vw_shadow_debug(vw_app *app, tl_renderer *r)
{
    size_t size = (size_t)app->width * app->height * 16;
    if (!app->plan.shadow_lights) {
        snprintf(app->view_note, sizeof app->view_note, "no casting light (the crypt casts with --shadows)");
        return NULL;
    }
    if (!(app->plan.targets & TL_TARGET_BIT(TL_TARGET_SHADOW_DEBUG)) ||
        tl_renderer_read_target(r, TL_TARGET_SHADOW_DEBUG, app->scratch[0], &size) != TL_OK) {
        snprintf(app->view_note, sizeof app->view_note, "no shadow-debug pass (not built with multisampled G-buffers)");
        return NULL;
    }
    return app->scratch[0];
}

/* ---- shadow-only ---------------------------------------------------------------------------- */

/* R grey (black: shadowed, white: lit); dark blue where no casting light reaches (G = 0); black sky. */
int vw_shadow_only(vw_app *app, tl_renderer *r, uint8_t *out)
{
    const float *d = vw_shadow_debug(app, r);
    if (!d) return 1;
    for (size_t i = 0, n = (size_t)app->width * app->height; i < n; i++) {
        const float *p = d + 4 * i;
        if (p[3] < 0.5f) vw_px(out + 4 * i, 0, 0, 0);
        else if (p[1] <= 0.0f) vw_px(out + 4 * i, 0.05f, 0.05f, 0.3f);
        else vw_px(out + 4 * i, p[0], p[0], p[0]);
    }
    return 0;
}

/* ---- shadow-cascades ------------------------------------------------------------------------ */

static const float vw_cascade_colours[4][3] = {{1.0f, 0.25f, 0.2f}, {0.25f, 0.9f, 0.3f}, {0.3f, 0.45f, 1.0f},
                                               {1.0f, 0.85f, 0.2f}};

/* Cascade coordinate c (index + blend towards the next) at pixel (x, y): its cascade's colour, and
 * where it blends, diagonal stripes of the next cascade's colour as wide as the blend weight. */
static const float *vw_cascade_colour(float c, uint32_t x, uint32_t y)
{
    int i = c >= 3.0f ? 3 : (int)c;
    float f = c - (float)i;
    return vw_cascade_colours[i < 3 && (float)((x + y) % 8u) < 8.0f * f ? i + 1 : i];
}

/* Each surface pixel in its cascade's colour shaded by the final image's luma (in out); grey
 * beyond the last cascade or without a casting directional light; black sky. */
int vw_shadow_cascades(vw_app *app, tl_renderer *r, uint8_t *out)
{
    static const float grey[3] = {0.4f, 0.4f, 0.4f};
    const float *d = vw_shadow_debug(app, r);
    if (!d) return 1;
    for (uint32_t y = 0; y < app->height; y++)
        for (uint32_t x = 0; x < app->width; x++) {
            size_t i = (size_t)y * app->width + x;
            const float *p = d + 4 * i, *rgb = p[2] >= 0.0f ? vw_cascade_colour(p[2], x, y) : grey;
            uint8_t *o = out + 4 * i;
            float shade = p[3] < 0.5f ? 0.0f : 0.35f + 0.65f * (0.2126f * o[0] + 0.7152f * o[1] + 0.0722f * o[2]) / 255.0f;
            vw_px(o, rgb[0] * shade, rgb[1] * shade, rgb[2] * shade);
        }
    return 0;
}

void vw_cascade_legend_colour(float t, uint8_t rgb[3])
{
    const float *c = vw_cascade_colours[t >= 1.0f ? 3 : (int)(t * 4.0f)];
    for (int k = 0; k < 3; k++) rgb[k] = (uint8_t)(c[k] * 255.0f + 0.5f);
}

/* ---- shadow-atlas --------------------------------------------------------------------------- */

/* The view whose tile holds texel (x, y), or -1. */
static long vw_atlas_view(const tl_shadow_view_info *v, size_t n, uint32_t x, uint32_t y)
{
    for (size_t i = 0; i < n; i++)
        if (x >= v[i].x && x < v[i].x + v[i].size && y >= v[i].y && y < v[i].y + v[i].size) return (long)i;
    return -1;
}

/* A texel's grey: t = (z - near) / (far - near) along its view's axis, 1 - 0.85 t (white nearest);
 * dark blue where nothing was drawn (the far value). docs/viewer.md has the formula. */
void vw_atlas_texel(const tl_shadow_view_info *v, float d, uint8_t *px)
{
    float n = v->near_z, f = v->far_z, z;
    if (d == 0.0f) { /* reversed depth (tl_renderer_read_shadow_atlas): the far value */
        vw_px(px, 0.0f, 0.0f, 0.3f);
        return;
    }
    z = v->perspective ? n * f / (n + d * (f - n)) : f - d * (f - n);
    float t = (z - n) / (f - n);
    vw_px(px, 1.0f - 0.85f * t, 1.0f - 0.85f * t, 1.0f - 0.85f * t);
}

/* The whole atlas in a square of side min(width, height) at the right, nearest texel; tile edges in
 * the light type's colour (yellow directional, cyan point, magenta spot); black where no view lies. */
static void vw_atlas_draw(vw_app *app, const float *atlas, uint32_t side, const tl_shadow_view_info *v, size_t n,
                          uint8_t *out)
{
    static const float edge[4][3] = {{1, 1, 1}, {0, 1, 1}, {1, 0, 1}, {1, 1, 0}}; /* by tl_light_type */
    /* at the right (the legend is at the bottom left) */
    uint32_t s = app->width < app->height ? app->width : app->height, x0 = app->width - s, y0 = (app->height - s) / 2;
    for (uint32_t y = 0; y < app->height; y++)
        for (uint32_t x = 0; x < app->width; x++) {
            uint8_t *px = out + 4 * ((size_t)y * app->width + x);
            vw_px(px, 0, 0, 0);
            if (x < x0 || y < y0 || x >= x0 + s || y >= y0 + s) continue;
            uint32_t tx = (uint32_t)(((uint64_t)(x - x0) * side) / s), ty = (uint32_t)(((uint64_t)(y - y0) * side) / s);
            long k = vw_atlas_view(v, n, tx, ty);
            if (k < 0) continue;
            uint32_t ex = (uint32_t)(((uint64_t)(x - x0 + 1) * side) / s);
            uint32_t ey = (uint32_t)(((uint64_t)(y - y0 + 1) * side) / s);
            const tl_shadow_view_info *w = &v[k];
            if (tx == w->x || ty == w->y || ex >= w->x + w->size || ey >= w->y + w->size) {
                const float *c = edge[w->type < 4 ? w->type : 0];
                vw_px(px, c[0], c[1], c[2]);
            } else {
                vw_atlas_texel(w, atlas[(size_t)ty * side + tx], px);
            }
        }
}

int vw_shadow_atlas(vw_app *app, tl_renderer *r, uint8_t *out)
{
    size_t n = 0, bytes = 0;
    uint32_t side = 0;
    if (tl_renderer_get_shadow_views(r, NULL, &n, &side) != TL_OK || !n || !side) {
        snprintf(app->view_note, sizeof app->view_note, "no shadow atlas (the crypt casts with --shadows)");
        return 1;
    }
    tl_shadow_view_info *v = malloc(n * sizeof *v);
    float *atlas = NULL;
    int bad = !v || tl_renderer_get_shadow_views(r, v, &n, NULL) != TL_OK ||
              tl_renderer_read_shadow_atlas(r, NULL, &bytes) != TL_OK || !(atlas = malloc(bytes)) ||
              tl_renderer_read_shadow_atlas(r, atlas, &bytes) != TL_OK;
    if (!bad) vw_atlas_draw(app, atlas, side, v, n, out);
    else snprintf(app->view_note, sizeof app->view_note, "the shadow atlas could not be read");
    free(v);
    free(atlas);
    return bad;
}
