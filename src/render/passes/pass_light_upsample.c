/* light_scale below 1 (docs/frame.md, "Light at reduced resolution"): light-upsample, a compute
 * pass between the light pass and the material pass. It makes the full-size light buffer
 * (LIGHT_DIFFUSE, _SPECULAR, _FRESNEL) of the reduced one the light pass wrote (LIGHT_REDUCED_*),
 * one invocation per quad of reduced texels, which it reads once for the frame pixels between their
 * centres, and re-lights from the tile lists the pixels no texel is credible for (counted in
 * light.fixup). The material pass is then scale 1's. */
#include "gl/gl.h"
#include "lights.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

static void tl__upsample_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->light_shift || !in->lights || !in->mode->material_pass) return;
    tl__pass_decl light = {0};
    tl__light_pass_targets(in, &light); /* the reduced buffer it wrote, the full one to make */
    tl_target_set reduced = light.writes & (TL__B(LIGHT_REDUCED_DIFFUSE) | TL__B(LIGHT_REDUCED_SPECULAR) |
                                            TL__B(LIGHT_REDUCED_FRESNEL));
    static const tl_target_id full[3] = {TL_TARGET_LIGHT_DIFFUSE, TL_TARGET_LIGHT_SPECULAR, TL_TARGET_LIGHT_FRESNEL};
    for (int i = 0; i < 3; i++)
        if (reduced & tl__light_buffer_reduced(TL_TARGET_BIT(full[i]))) d->images |= TL_TARGET_BIT(full[i]);
    d->samples = reduced | TL__B(LIGHT_DEPTH) | TL__B(LIGHT_RT0) | TL__B(LIGHT_OFFSET) | TL__B(DEPTH) | TL__B(RT0);
    d->reads = d->samples | TL__B(LIGHT_LISTS); /* the re-lit pixels' lights (light-cull, pass_tiled.c) */
    d->writes = d->images | TL__B(LIGHT_FIXUP);
    d->compute = 1;
    d->light_data = TL__LIGHTS_VIEW | TL__LIGHTS_TILES;
}

static void tl__upsample_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    tl__perm *k = &out->slot[0];
    out->used[0] = 1;
    tl__perm_value(k, TL__V_UPSAMPLE, in->light_shift);
    tl__perm_flag(k, in->rt0_flag);
    tl__perm_merge(k, &in->spec_perm);
    tl__perm_value(k, TL__V_LIGHT_IMAGE_FORMAT, in->o->light_format == TL_LIGHT_FORMAT_R11G11B10F
                                                    ? TL__IMAGE_FORMAT_R11G11B10F : TL__IMAGE_FORMAT_RGBA16F);
}

/* An invocation per quad of texels, from (-1, -1) to the last: (w + 1) x (h + 1) quads. */
static void tl__upsample_execute(const tl__pass_ctx *ctx)
{
    const GladGLContext *gl = ctx->gl;
    tl__fixup *f = &ctx->lights->fixup;
    uint32_t k = (1u << ctx->light_shift) - 1u;
    uint32_t w = ((ctx->width + k) >> ctx->light_shift) + 1u, h = ((ctx->height + k) >> ctx->light_shift) + 1u;
    tl__fixup_begin(gl, f);
    tl__state_program(gl, ctx->state, ctx->programs[0]);
    gl->DispatchCompute((w + 15) / 16, (h + 15) / 16, 1);
    gl->MemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    tl__fixup_end(gl, f, ctx->frame);
}

const tl__pass_def tl__pass_light_upsample = {
    .id = TL_PASS_LIGHT_UPSAMPLE,
    .name = "light-upsample",
    .programs = {{"light-upsample", NULL, NULL, "light_upsample.comp.glsl"}},
    .declare = tl__upsample_declare,
    .permute = tl__upsample_permute,
    .execute = tl__upsample_execute,
    .services = TL__PASS_LIGHTS,
};
