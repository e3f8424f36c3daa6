/* Transparency through the light buffer (Inferred Lighting's stipple; docs/frame.md, "2d.
 * Transparency through the light buffer"): planned instead of the forward transparent pass when
 * tl__plan_input.stipple (plan.c says when). Three passes:
 *   stipple-depth    the opaque depth copied to opaque.depth, before the layers overwrite DEPTH;
 *   stipple          the blended objects into DEPTH and RT0, each on the pixels of its layer (one of
 *                    every 2x2 quad, shaders/stipple.glsl), nearest first by the depth test; the
 *                    light pass then lights them with everything else;
 *   stipple-blend    the blended objects again, far to near, blended onto HDR, each fragment with
 *                    the light of its layer's own pixels (shaders/stipple_gather.glsl).
 * The material pass (pass_geometry.c) tests against opaque.depth and gathers, where a layer took an
 * opaque pixel, the light of its neighbours. */
#include <stdio.h>

#include "gl/gl.h"
#include "pass.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

static const tl__target_def tl__target_opaque_depth = {TL__TARGET(OPAQUE_DEPTH, "opaque.depth"),
                                                       .format_of = tl__depth_format, .store = TL__STORE_GBUFFER, .depth = 1};

static tl__pipeline tl__stipple_state(const tl__plan_input *in, int depth_write, tl__blend blend)
{
    tl__pipeline p = {.depth_test = TL__DEPTH_LEQUAL, .depth_write = (uint8_t)depth_write, .color_write = 1,
                      .cull = TL__CULL_BACK, .blend = (uint8_t)blend};
    p.clip_zero_one = in->o->depth_format == TL_DEPTH_FORMAT_D32F_REVERSED;
    return p;
}

/* ---- stipple-depth: the opaque surfaces' depth, kept ---------------------------------------- */

static void tl__stipple_depth_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->stipple) return;
    d->reads = d->samples = TL__B(DEPTH);
    d->writes = d->clears = TL__B(OPAQUE_DEPTH); /* cleared to the far value: every copy then passes */
    d->attach_depth = 1;
    d->depth_target = TL_TARGET_OPAQUE_DEPTH;
    d->state = tl__pipeline_fullscreen;
    d->state.color_write = 0;
    d->state.depth_test = TL__DEPTH_LEQUAL; /* depth is written only with the test on */
}

static void tl__stipple_depth_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    out->used[0] = 1;
    if (tl__depth_format(in->o) == GL_DEPTH24_STENCIL8) tl__perm_flag(&out->slot[0], TL__F_DEPTH_UNORM24);
}

const tl__pass_def tl__pass_stipple_depth = {
    .id = TL_PASS_STIPPLE_DEPTH,
    .name = "stipple-depth",
    .programs = {{"stipple-depth", "fullscreen.vert.glsl", "stipple_depth.frag.glsl"}},
    .targets = {&tl__target_opaque_depth},
    .declare = tl__stipple_depth_declare,
    .permute = tl__stipple_depth_permute,
    .execute = tl__draw_fullscreen,
};

/* ---- stipple: the layers into the G-buffer -------------------------------------------------- */

static void tl__stipple_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->stipple) return;
    d->reads = TL__B(DEPTH) | TL__B(RT0); /* written on some pixels, kept on the others */
    d->writes = TL__B(DEPTH) | TL__B(RT0);
    d->attach_depth = 1;
    d->state = tl__stipple_state(in, 1, TL__BLEND_OFF);
}

static void tl__stipple_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    out->used[0] = 1;
    tl__perm_flag(&out->slot[0], TL__F_STIPPLE);
    tl__perm_flag(&out->slot[0], in->rt0_flag);
    tl__perm_merge(&out->slot[0], &in->material);
}

const tl__pass_def tl__pass_stipple = {
    .id = TL_PASS_STIPPLE,
    .name = "stipple",
    .programs = {{"stipple", "gbuffer.vert.glsl", "gbuffer.frag.glsl"}},
    .declare = tl__stipple_declare,
    .permute = tl__stipple_permute,
    .execute = tl__draw_transparent,
    .services = TL__PASS_SCENE,
};

/* ---- stipple-blend: the layers blended onto HDR --------------------------------------------- */

static void tl__resolve_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->stipple) return;
    d->writes = TL__B(HDR);
    d->samples = TL__B(DEPTH) | TL__B(RT0) | TL__B(LIGHT_DIFFUSE) | TL__B(LIGHT_SPECULAR) | TL__B(LIGHT_FRESNEL);
    d->reads = d->samples | TL__B(HDR) | TL__B(OPAQUE_DEPTH); /* blended onto; depth-tested */
    d->attach_depth = 1;
    d->depth_target = TL_TARGET_OPAQUE_DEPTH;
    /* fragments with no credible sample of their own (a back face, an edge) are lit forward */
    d->light_data = TL__LIGHTS_VIEW | TL__LIGHTS_INDEX_BUFFER | TL__LIGHTS_OBJECT_LISTS;
    d->state = tl__stipple_state(in, 0, TL__BLEND_ALPHA);
}

static void tl__resolve_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    tl__perm *k = &out->slot[0];
    out->used[0] = 1;
    tl__perm_flag(k, TL__F_FORWARD);
    tl__perm_flag(k, TL__F_TRANSPARENT);
    tl__perm_flag(k, TL__F_STIPPLE);
    tl__perm_merge(k, &in->spec_perm);
    tl__perm_flag(k, in->rt0_flag);
    tl__perm_merge(k, &in->material);
}

const tl__pass_def tl__pass_stipple_resolve = {
    .id = TL_PASS_STIPPLE_RESOLVE,
    .name = "stipple-blend",
    .programs = {{"stipple-blend", "gbuffer.vert.glsl", "forward.frag.glsl"}},
    .declare = tl__resolve_declare,
    .permute = tl__resolve_permute,
    .execute = tl__draw_transparent,
    .services = TL__PASS_SCENE,
};
