/* Vignette: one pass in two draws. The first writes the vignette factor of every pixel into its own
 * target, 1 - strength * smoothstep(radius, radius + softness, d), d the distance from the centre
 * as a fraction of the half-diagonal; the second darkens HDR by it (blended: HDR * factor). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gl/gl.h"
#include "pass.h"
#include "view.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

static const tl__target_def tl__target_vignette = {TL__TARGET(VIGNETTE, "vignette"), .format = GL_R16F};

/* tl_vignette_desc in the option registry. */
static const tl_option_info tl__vignette_rows[] = {
    TL__OPT_BOOL(vignette.enabled, "vignette: HDR darkened towards the corners"),
    TL__OPT_FLOAT(vignette.strength, 0.0, 1.0, TL_OPTION_MIN_OPEN, 0.5, NULL, "", "vignette: darkening at full fall-off"),
    TL__OPT_FLOAT(vignette.radius, TL__OPT_ABOVE_0, 0.5, NULL, "of the half-diagonal", "vignette: where the fall-off starts"),
    TL__OPT_FLOAT(vignette.softness, TL__OPT_ABOVE_0, 0.5, NULL, "of the half-diagonal", "vignette: the fall-off's width"),
};

static void tl__vignette_resolve(void *options)
{
    tl_vignette_desc *v = (tl_vignette_desc *)options;
    if (!v->enabled) memset(v, 0, sizeof *v);
}

/* std140 block tl_vignette_block of shaders/vignette.frag.glsl: strength, radius, softness, 0. */
static void tl__vignette_params(const tl_renderer_options *o, const tl__view *v, void *block)
{
    (void)v;
    float *b = (float *)block;
    b[0] = o->vignette.strength;
    b[1] = o->vignette.radius;
    b[2] = o->vignette.softness;
    b[3] = 0.0f;
}

static void tl__vignette_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->o->vignette.enabled) return;
    d->reads = TL__B(HDR); /* blended onto */
    d->writes = TL__B(HDR) | TL__B(VIGNETTE);
    d->split_writes = 1;
    d->state = tl__pipeline_fullscreen;
}

static void tl__vignette_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)in;
    (void)d;
    out->used[0] = out->used[1] = 1;
    tl__perm_flag(&out->slot[0], TL__F_VIGNETTE_FACTOR);
}

/* The factor into its target, then HDR darkened by it: write_fbos[0] holds HDR, [1] the factor. */
static void tl__vignette_execute(const tl__pass_ctx *ctx)
{
    const GladGLContext *gl = ctx->gl;
    tl__state_vertex_array(gl, ctx->state, ctx->fullscreen_vao);
    tl__state_framebuffer(gl, ctx->state, ctx->write_fbos[1]);
    tl__state_program(gl, ctx->state, ctx->programs[0]);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    tl__pipeline blend = *ctx->pipeline;
    blend.blend = TL__BLEND_ALPHA; /* HDR (1 - a) with a = 1 - factor */
    tl__state_apply(gl, ctx->state, &blend);
    tl__state_framebuffer(gl, ctx->state, ctx->write_fbos[0]);
    gl->BindTextureUnit(ctx->unit_of[TL_TARGET_VIGNETTE], ctx->write_textures[1]);
    tl__state_program(gl, ctx->state, ctx->programs[1]);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    ctx->out->draw_calls += 2;
}

static int tl__vignette_wanted(const tl_renderer_options *o) { return o->vignette.enabled; }

const tl__pass_def tl__pass_vignette = {
    .id = TL_PASS_VIGNETTE,
    .name = "vignette",
    .programs = {{"vignette.factor", "fullscreen.vert.glsl", "vignette.frag.glsl"},
                 {"vignette.apply", "fullscreen.vert.glsl", "vignette.frag.glsl"}},
    .targets = {&tl__target_vignette},
    TL__OPTIONS(vignette, tl__vignette_rows),
    .resolve = tl__vignette_resolve,
    .params_size = 4 * sizeof(float),
    .params = tl__vignette_params,
    .declare = tl__vignette_declare,
    .permute = tl__vignette_permute,
    .execute = tl__vignette_execute,
    .wanted = tl__vignette_wanted,
    .refuses = TL__REFUSES_MSAA,
    .refuses_why = {"the vignette blends over a one-sample HDR", NULL},
};
