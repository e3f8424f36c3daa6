/* light_scale below 1 (docs/frame.md, "Light at reduced resolution"): a full-screen pass at the
 * light buffer's size that keeps, per block of the frame, the nearest depth sample, that
 * sample's RT0 texel and where in the block it lies (light_reduce.frag.glsl says why the nearest). The light pass then depth-tests
 * its volumes against the reduced depth and reads the reduced RT0. Its targets are the frame's
 * depth and RT0 formats at the light buffer's size. */
#include <stdio.h>

#include "gl/gl.h"
#include "lights.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

static const tl__target_def tl__target_light_depth = {TL__TARGET(LIGHT_DEPTH, "light.depth"),
                                                      .format_of = tl__depth_format, .shift_of = tl__light_shift,
                                                      .store = TL__STORE_GBUFFER, .depth = 1};
static const tl__target_def tl__target_light_rt0 = {TL__TARGET(LIGHT_RT0, "light.rt0"), .format_of = tl__rt0_format,
                                                    .shift_of = tl__light_shift, .store = TL__STORE_GBUFFER,
                                                    .read_rt0 = 1};

/* Where in its block the kept sample is: the light pass lights that very pixel's position. */
static const tl__target_def tl__target_light_offset = {TL__TARGET(LIGHT_OFFSET, "light.offset"), .format = GL_R8,
                                                       .shift_of = tl__light_shift, .store = TL__STORE_GBUFFER};

static void tl__reduce_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->light_shift || !in->lights) return;
    d->reads = d->samples = TL__B(DEPTH) | TL__B(RT0);
    d->writes = TL__B(LIGHT_DEPTH) | TL__B(LIGHT_RT0) | TL__B(LIGHT_OFFSET);
    d->clears = TL__B(LIGHT_DEPTH); /* to the far value: every fragment's depth then passes */
    d->attach_depth = 1;
    d->depth_target = TL_TARGET_LIGHT_DEPTH;
    d->state = tl__pipeline_fullscreen;
    d->state.depth_test = TL__DEPTH_LEQUAL; /* depth is written only with the test on */
}

static void tl__reduce_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    out->used[0] = 1;
    tl__perm_value(&out->slot[0], TL__V_LIGHT_SHIFT, in->light_shift);
    tl__perm_flag(&out->slot[0], in->rt0_flag);
}

const tl__pass_def tl__pass_light_reduce = {
    .id = TL_PASS_LIGHT_REDUCE,
    .name = "light-reduce",
    .programs = {{"light-reduce", "fullscreen.vert.glsl", "light_reduce.frag.glsl"}},
    .targets = {&tl__target_light_depth, &tl__target_light_rt0, &tl__target_light_offset},
    .declare = tl__reduce_declare,
    .permute = tl__reduce_permute,
    .execute = tl__draw_fullscreen,
};
