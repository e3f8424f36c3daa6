/* The renderer's shadow term of one light (shadow_term.h), on the tests' context. */
#include <math.h>
#include <stdlib.h>

#include "render_fixture.h"
#include "shadow_term.h"

static float *tl__hdr_luma(tl_renderer *r, size_t n)
{
    float *p = tl_test_read_target(r, TL_TARGET_HDR, n);
    if (!p) return NULL;
    for (size_t i = 0; i < n; i++) p[i] = p[4 * i] + p[4 * i + 1] + p[4 * i + 2];
    return p;
}

float *tl_shadow_ratio(const tl_shadow_case *c, const tl_light *light, tl_renderer_options o, uint32_t w, uint32_t h,
                       tl_frame_stats *stats, tl_shadow_view_info *views, size_t *view_count)
{
    tl_scene s = *c->scene;
    tl_light l = *light;
    l.shadow = 1;
    s.lights = &l;
    s.light_count = 1;
    o.ambient[0] = o.ambient[1] = o.ambient[2] = -1.0f;
    o.synchronous_stats = 1;
    tl_renderer *r = tl_test_render_once(&s, (tl_renderer_desc){.width = w, .height = h, .options = o});
    if (!r) return NULL;
    size_t n = (size_t)w * h;
    if (stats) tl_renderer_render(r, NULL, stats);
    if (views && tl_renderer_get_shadow_views(r, views, view_count, NULL) != TL_OK) *view_count = 0;
    float *on = tl__hdr_luma(r, n), *off = NULL;
    l.shadow = 0;
    if (on && tl_renderer_set_lights(r, &l, 1) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK &&
        tl_renderer_wait(r, NULL) == TL_OK)
        off = tl__hdr_luma(r, n);
    tl_renderer_destroy(r);
    if (!on || !off) {
        free(on);
        free(off);
        return NULL;
    }
    float peak = 0.0f;
    for (size_t i = 0; i < n; i++) peak = fmaxf(peak, off[i]);
    /* a light that adds less than 2^-12 (the FP16 targets hold 11 bits) is not measured */
    float floor = fmaxf(1e-6f * peak, 2.44e-4f);
    for (size_t i = 0; i < n; i++) on[i] = off[i] > floor ? on[i] / off[i] : -1.0f;
    free(off);
    return on;
}

float *tl_shadow_term(const tl_shadow_case *c, const tl_light *light, tl_renderer_options o, uint32_t w, uint32_t h,
                      tl_frame_stats *stats)
{
    float *t = tl_shadow_ratio(c, light, o, w, h, stats, NULL, NULL);
    for (size_t i = 0; t && i < (size_t)w * h; i++) t[i] = fminf(t[i], 1.0f);
    return t;
}
