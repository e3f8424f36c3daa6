/* Bloom (docs/effects.md): one pass over the bloom target's mip levels. The first draw takes HDR
 * through the soft threshold and Jimenez's 13-tap downsample into level 0 (half size); each next
 * draw downsamples the level above into the next; then from the smallest level back up, a 3x3 tent
 * upsample of the coarser level is blended over the finer one with weight `scatter` (Jimenez,
 * "Next generation post processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014; the blend
 * is Unity URP's). Level 0 then holds the bloom image, which the tone-map pass adds to HDR. Every
 * filter's weights sum to 1 and both resamplings keep the image's mean, so the chain conserves
 * energy. Each draw samples a one-level view of the level it reads, never the level it writes. */
#include <stdio.h>

#include "renderer_internal.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

static void tl__bloom_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->d.options.bloom.enabled) return;
    d->reads = d->samples = TL__B(HDR);
    d->writes = TL__B(BLOOM);
    d->state = tl__pipeline_fullscreen;
}

static void tl__bloom_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)in;
    (void)d;
    static const char *const steps[3] = {"TL_BLOOM_PREFILTER", "TL_BLOOM_DOWN", "TL_BLOOM_UP"};
    for (int k = 0; k < 3; k++) {
        out->used[k] = 1;
        snprintf(out->slot[k], sizeof out->slot[k], "%s", steps[k]);
    }
}

/* One full-screen draw of `program` into `level`, sampling `source` (0: what the pass bound). */
static void tl__bloom_draw(tl_renderer *r, const tl__pass_ctx *ctx, GLuint program, uint32_t level, GLuint source)
{
    const GladGLContext *gl = &r->gl;
    const tl__target *t = &r->targets[TL_TARGET_BLOOM];
    uint32_t w = t->width >> level, h = t->height >> level;
    tl__state_framebuffer(gl, &r->state, level ? ctx->cp->level_fbos[level] : ctx->cp->fbo);
    tl__state_viewport(gl, &r->state, 0, 0, (GLsizei)(w ? w : 1u), (GLsizei)(h ? h : 1u));
    if (source) gl->BindTextureUnit(TL_TARGET_BLOOM, source);
    tl__state_program(gl, &r->state, program);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    ctx->rec->st.draw_calls++;
}

static void tl__bloom_execute(tl_renderer *r, const tl__pass_ctx *ctx)
{
    const GladGLContext *gl = &r->gl;
    const tl__compiled_pass *cp = ctx->cp;
    const tl__target *lv = r->levels[TL_TARGET_BLOOM];
    uint32_t n = cp->level_count ? cp->level_count : 1u;
    tl__state_vertex_array(gl, &r->state, r->vao_empty);
    gl->BindSampler(TL_TARGET_HDR, r->sampler_linear); /* the 13 taps fall between texels */
    tl__bloom_draw(r, ctx, cp->programs[0], 0, 0);
    gl->BindSampler(TL_TARGET_HDR, 0);
    for (uint32_t k = 1; k < n; k++) tl__bloom_draw(r, ctx, cp->programs[1], k, lv[k - 1].texture);
    tl__pipeline blend = cp->decl->state;
    blend.blend = TL__BLEND_ALPHA; /* finer = scatter * tent(coarser) + (1 - scatter) * finer */
    tl__state_apply(gl, &r->state, &blend);
    for (uint32_t k = n - 1; k-- > 0;) tl__bloom_draw(r, ctx, cp->programs[2], k, lv[k + 1].texture);
}

const tl__pass_def tl__pass_bloom = {
    .id = TL_PASS_BLOOM,
    .name = "bloom",
    .programs = {{"bloom.prefilter", "fullscreen.vert.glsl", "bloom.frag.glsl"},
                 {"bloom.down", "fullscreen.vert.glsl", "bloom.frag.glsl"},
                 {"bloom.up", "fullscreen.vert.glsl", "bloom.frag.glsl"}},
    .declare = tl__bloom_declare,
    .permute = tl__bloom_permute,
    .execute = tl__bloom_execute,
};
