/* Bloom (docs/effects.md): one pass over the bloom target's mip levels. The first draw takes HDR
 * through the soft threshold and Jimenez's 13-tap downsample into level 0 (half size); each next
 * draw downsamples the level above into the next; then from the smallest level back up, a 3x3 tent
 * upsample of the coarser level is blended over the finer one with weight `scatter` (Jimenez,
 * "Next generation post processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014; the blend
 * is Unity URP's). Level 0 then holds the bloom image, which the tone-map pass adds to HDR. Every
 * filter's weights sum to 1 and both resamplings keep the image's mean, so the chain conserves
 * energy. Each draw samples a one-level view of the level it reads, never the level it writes. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gl/gl.h"
#include "pass.h"
#include "view.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

static uint32_t tl__bloom_levels(const tl_renderer_options *o) { return o->bloom.levels; }

/* Half size, its levels from the options; sampled bilinearly by the tone map (the 2x upsample). */
static const tl__target_def tl__target_bloom = {TL__TARGET(BLOOM, "bloom"), .format = GL_RGBA16F,
                                                .levels_of = tl__bloom_levels, .shift = 1, .linear = 1};

/* tl_bloom_desc in the option registry (docs/effects.md). */
static const tl_option_info tl__bloom_rows[] = {
    TL__OPT_BOOL(bloom.enabled, "bloom"),
    TL__OPT_FLOAT(bloom.threshold, TL__OPT_ABOVE_0 | TL_OPTION_NEGATIVE_ZERO, 1, NULL, "HDR",
                  "bloom: brightness (largest channel) where it starts"),
    TL__OPT_FLOAT(bloom.knee, 0.0, 1.0, TL_OPTION_MIN_OPEN | TL_OPTION_NEGATIVE_ZERO, 0.5, NULL, "of the threshold",
                  "bloom: soft knee"),
    TL__OPT_FLOAT(bloom.intensity, TL__OPT_ABOVE_0, 0.5, NULL, "", "bloom: weight of the bloom image added to HDR"),
    TL__OPT_FLOAT(bloom.scatter, 0.0, 1.0, TL_OPTION_MIN_OPEN, 0.7, NULL, "",
                  "bloom: weight of each coarser level (larger: wider glow)"),
    TL__OPT_UINT(bloom.levels, 1, TL__MAX_LEVELS, 0, 6, "levels", "bloom: mip levels of the chain, the first at half size"),
};

static void tl__bloom_resolve(void *options)
{
    tl_bloom_desc *b = (tl_bloom_desc *)options;
    if (!b->enabled) memset(b, 0, sizeof *b);
}

/* std140 block tl_bloom_block of shaders/bloom.frag.glsl: threshold, knee (absolute), intensity, scatter. */
static void tl__bloom_params(const tl_renderer_options *o, const tl__view *v, void *block)
{
    (void)v;
    const tl_bloom_desc *d = &o->bloom;
    float *b = (float *)block;
    b[0] = d->threshold;
    b[1] = d->knee * d->threshold;
    b[2] = d->intensity;
    b[3] = d->scatter;
}

static void tl__bloom_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->o->bloom.enabled) return;
    d->reads = d->samples = TL__B(HDR);
    d->writes = TL__B(BLOOM);
    d->state = tl__pipeline_fullscreen;
}

static void tl__bloom_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)in;
    (void)d;
    static const unsigned steps[3] = {TL__F_BLOOM_PREFILTER, TL__F_BLOOM_DOWN, TL__F_BLOOM_UP};
    for (int k = 0; k < 3; k++) {
        out->used[k] = 1;
        tl__perm_flag(&out->slot[k], steps[k]);
    }
}

/* One full-screen draw of `program` into `level`, sampling `source` (0: what the pass bound). */
static void tl__bloom_draw(const tl__pass_ctx *ctx, GLuint program, uint32_t level, GLuint source)
{
    const GladGLContext *gl = ctx->gl;
    uint32_t w = ctx->level_width >> level, h = ctx->level_height >> level;
    tl__state_framebuffer(gl, ctx->state, level ? ctx->level_fbos[level] : ctx->fbo);
    tl__state_viewport(gl, ctx->state, 0, 0, (GLsizei)(w ? w : 1u), (GLsizei)(h ? h : 1u));
    if (source) gl->BindTextureUnit(ctx->unit_of[TL_TARGET_BLOOM], source);
    tl__state_program(gl, ctx->state, program);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    ctx->out->draw_calls++;
}

static void tl__bloom_execute(const tl__pass_ctx *ctx)
{
    const GladGLContext *gl = ctx->gl;
    const GLuint *lv = ctx->level_textures;
    uint32_t n = ctx->level_count ? ctx->level_count : 1u;
    tl__state_vertex_array(gl, ctx->state, ctx->fullscreen_vao);
    gl->BindSampler(ctx->unit_of[TL_TARGET_HDR], ctx->linear_sampler); /* the 13 taps fall between texels */
    tl__bloom_draw(ctx, ctx->programs[0], 0, 0);
    gl->BindSampler(ctx->unit_of[TL_TARGET_HDR], 0);
    for (uint32_t k = 1; k < n; k++) tl__bloom_draw(ctx, ctx->programs[1], k, lv[k - 1]);
    tl__pipeline blend = *ctx->pipeline;
    blend.blend = TL__BLEND_ALPHA; /* finer = scatter * tent(coarser) + (1 - scatter) * finer */
    tl__state_apply(gl, ctx->state, &blend);
    for (uint32_t k = n - 1; k-- > 0;) tl__bloom_draw(ctx, ctx->programs[2], k, lv[k + 1]);
}

static int tl__bloom_wanted(const tl_renderer_options *o) { return o->bloom.enabled; }

const tl__pass_def tl__pass_bloom = {
    .id = TL_PASS_BLOOM,
    .name = "bloom",
    .programs = {{"bloom.prefilter", "fullscreen.vert.glsl", "bloom.frag.glsl"},
                 {"bloom.down", "fullscreen.vert.glsl", "bloom.frag.glsl"},
                 {"bloom.up", "fullscreen.vert.glsl", "bloom.frag.glsl"}},
    .targets = {&tl__target_bloom},
    TL__OPTIONS(bloom, tl__bloom_rows),
    .resolve = tl__bloom_resolve,
    .params_size = 4 * sizeof(float),
    .params = tl__bloom_params,
    .declare = tl__bloom_declare,
    .permute = tl__bloom_permute,
    .execute = tl__bloom_execute,
    .wanted = tl__bloom_wanted,
    .refuses = TL__REFUSES_MSAA,
    .refuses_why = {"bloom reads a one-sample HDR", NULL},
};
