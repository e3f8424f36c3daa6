/* The shadow term of one light (bench_shadows.h): the renderer's HDR image with the light alone
 * casting over the image with it alone not casting (docs/shadows.md, "Truth"). Public API only:
 * thinlight-shadows-report uses it too. */
#include <math.h>
#include <stdlib.h>

#include "bench_shadows.h"

static float *bench__hdr_sum(tl_renderer *r, size_t n)
{
    size_t size = n * 4 * sizeof(float);
    float *p = malloc(size);
    if (!p || tl_renderer_read_target(r, TL_TARGET_HDR, p, &size) != TL_OK) {
        free(p);
        return NULL;
    }
    for (size_t i = 0; i < n; i++) p[i] = p[4 * i] + p[4 * i + 1] + p[4 * i + 2];
    return p;
}

/* The light alone casting over the light alone not casting, per pixel; -1 where it adds less than
 * 2^-12 (the FP16 targets hold 11 bits) or 10^-6 of its peak. */
float *bench_shadow_term(tl_renderer *r, const tl_light *light, size_t n)
{
    tl_light l = *light;
    float *on = NULL, *off = NULL;
    l.shadow = 1;
    if (tl_renderer_set_lights(r, &l, 1) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK &&
        tl_renderer_wait(r, NULL) == TL_OK)
        on = bench__hdr_sum(r, n);
    l.shadow = 0;
    if (on && tl_renderer_set_lights(r, &l, 1) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK &&
        tl_renderer_wait(r, NULL) == TL_OK)
        off = bench__hdr_sum(r, n);
    if (!on || !off) {
        free(on);
        free(off);
        return NULL;
    }
    float peak = 0.0f;
    for (size_t i = 0; i < n; i++) peak = fmaxf(peak, off[i]);
    float floor = fmaxf(1e-6f * peak, 2.44e-4f);
    for (size_t i = 0; i < n; i++) on[i] = off[i] > floor ? fminf(on[i] / off[i], 1.0f) : -1.0f;
    free(off);
    return on;
}
