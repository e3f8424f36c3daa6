/* The light pass: instanced light volumes (docs/frame.md). One instanced draw per light type
 * and side: volumes the camera is outside of by their front faces (depth LEQUAL: lights hidden
 * behind the scene cost nothing), those that contain it or may cross the near plane by their back
 * faces (GEQUAL), both with depth clamp so the far plane cuts nothing; directional lights as a
 * full-screen triangle. What the shader does with the light (accumulate into the light buffer,
 * shade into HDR) is the mode table's. */
#include <stdio.h>

#include "gl/gl.h"
#include "lights.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

/* The light buffer (thin-lpp): R11G11B10F keeps each value to 6 or 5 mantissa bits in 4 bytes.
 * With MSAA's per-sample edges it has the G-buffer's samples (pass_msaa.c): an edge pixel's light
 * per sample, every other pixel's in all its samples. */
static uint32_t tl__light_format(const tl_renderer_options *o)
{
    return o->light_format == TL_LIGHT_FORMAT_R11G11B10F ? GL_R11F_G11F_B10F : GL_RGBA16F;
}

static const tl__target_def tl__target_light_diffuse = {TL__TARGET(LIGHT_DIFFUSE, "light.diffuse"),
                                                        .format_of = tl__light_format, .samples_of = tl__gbuffer_samples,
                                                        .store = TL__STORE_LIGHT};
static const tl__target_def tl__target_light_specular = {TL__TARGET(LIGHT_SPECULAR, "light.specular"),
                                                         .format_of = tl__light_format, .samples_of = tl__gbuffer_samples,
                                                         .store = TL__STORE_LIGHT};
static const tl__target_def tl__target_light_fresnel = {TL__TARGET(LIGHT_FRESNEL, "light.fresnel"),
                                                        .format_of = tl__light_format, .samples_of = tl__gbuffer_samples,
                                                        .store = TL__STORE_LIGHT};
/* The light scale: the light pass writes these at the light buffer's size, and light-upsample
 * (pass_light_upsample.c) makes the full-size light buffer above of them for the material pass. */
static const tl__target_def tl__target_light_reduced_diffuse = {TL__TARGET(LIGHT_REDUCED_DIFFUSE, "light.reduced.diffuse"),
                                                                .format_of = tl__light_format, .shift_of = tl__light_shift,
                                                                .store = TL__STORE_LIGHT};
static const tl__target_def tl__target_light_reduced_specular = {TL__TARGET(LIGHT_REDUCED_SPECULAR, "light.reduced.specular"),
                                                                 .format_of = tl__light_format, .shift_of = tl__light_shift,
                                                                 .store = TL__STORE_LIGHT};
static const tl__target_def tl__target_light_reduced_fresnel = {TL__TARGET(LIGHT_REDUCED_FRESNEL, "light.reduced.fresnel"),
                                                                .format_of = tl__light_format, .shift_of = tl__light_shift,
                                                                .store = TL__STORE_LIGHT};
/* TL_CLEARCOAT_SUMS: the coat's specular sum (coat_sums.glsl), in the light buffer's format. */
static const tl__target_def tl__target_light_coat = {TL__TARGET(LIGHT_COAT, "light.coat"),
                                                     .format_of = tl__light_format, .store = TL__STORE_LIGHT};

/* What the light pass reads and writes in this mode, whatever the strategy (the tiled pass too). */
void tl__light_pass_targets(const tl__plan_input *in, tl__pass_decl *d)
{
    const tl__mode_def *m = in->mode;
    tl_target_set spec_targets = TL__B(LIGHT_SPECULAR) | TL__B(FAT_MATERIAL);
    int exact_spec = in->spec && in->o->light_buffer == TL_LIGHT_BUFFER_EXACT;
    d->writes = m->light_writes & (exact_spec ? ~0u : ~TL__B(LIGHT_SPECULAR));
    if (in->fresnel != TL_FRESNEL_TWO_SUMS) d->writes &= ~TL__B(LIGHT_FRESNEL); /* S2: GGX's two sums only */
    d->reads = m->light_reads & (in->spec ? ~0u : ~spec_targets);
    d->samples = m->light_samples & d->reads;
    d->neighbourhood = d->samples & TL__B(RT1); /* chroma from the four neighbours */
    if (d->writes & TL__B(HDR)) d->reads |= TL__B(HDR); /* shading adds to it */
    if (in->coat_sums && (d->writes & TL__B(LIGHT_DIFFUSE))) { /* the coat's own sum (coat_sums.glsl) */
        d->writes |= TL__B(LIGHT_COAT);
        d->reads |= TL__B(COAT_GLOSS);
        d->samples |= TL__B(COAT_GLOSS);
    }
    if (tl__msaa_sample_edges(in->o)) { /* which pixels each of the two light passes lights (pass_msaa.c) */
        d->reads |= TL__B(MSAA_EDGES);
        d->samples |= TL__B(MSAA_EDGES);
    }
    if (in->light_shift) { /* the light scale: the reduced depth and RT0 (pass_light_reduce.c) */
        tl_target_set full = TL__B(DEPTH) | TL__B(RT0), reduced = TL__B(LIGHT_DEPTH) | TL__B(LIGHT_RT0) | TL__B(LIGHT_OFFSET);
        d->reads = (d->reads & ~full) | reduced;
        d->samples = (d->samples & ~full) | reduced;
        d->depth_target = TL_TARGET_LIGHT_DEPTH;
        d->writes = tl__light_buffer_reduced(d->writes); /* light-upsample makes the full-size buffer */
    }
}

tl_target_set tl__light_buffer_reduced(tl_target_set full)
{
    static const tl_target_id pairs[3][2] = {{TL_TARGET_LIGHT_DIFFUSE, TL_TARGET_LIGHT_REDUCED_DIFFUSE},
                                             {TL_TARGET_LIGHT_SPECULAR, TL_TARGET_LIGHT_REDUCED_SPECULAR},
                                             {TL_TARGET_LIGHT_FRESNEL, TL_TARGET_LIGHT_REDUCED_FRESNEL}};
    tl_target_set out = full;
    for (int i = 0; i < 3; i++)
        if (full & TL_TARGET_BIT(pairs[i][0])) out = (out & ~TL_TARGET_BIT(pairs[i][0])) | TL_TARGET_BIT(pairs[i][1]);
    return out;
}

/* The shader switches of the light pass's reads, whatever the strategy: the RT0 encoding and the
 * light scale's shift. */
void tl__light_pass_defines(const tl__plan_input *in, const tl__pass_decl *d, tl__perm *k)
{
    if (d->reads & (TL__B(RT0) | TL__B(LIGHT_RT0))) tl__perm_flag(k, in->rt0_flag);
    if (in->light_shift) tl__perm_value(k, TL__V_LIGHT_SHIFT, in->light_shift);
    /* MSAA per-sample edges: a multisampled G-buffer (pass_msaa.c) */
    if (tl__msaa_sample_edges(in->o)) tl__perm_value(k, TL__V_GBUFFER_SAMPLES, in->msaa);
    /* fat, and thin-deferred where RT1.a is not SSAO's, shade each light under the pixel's material
     * model (fat_models.glsl) */
    int model_stored = (d->reads & TL__B(FAT_POSITION)) || ((d->reads & TL__B(RT1)) && tl__ssao_pass(in) != 2);
    if (model_stored && tl__plan_has_models(&in->f)) tl__perm_flag(k, TL__F_MATERIAL_MODELS);
    if (d->reads & TL__B(COAT_GLOSS)) tl__perm_flag(k, TL__F_COAT_SUMS);
}

static void tl__lights_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->lights || in->mode->forward || in->mode->visibility || in->strategy != TL_LIGHT_STRATEGY_VOLUMES) return;
    tl__light_pass_targets(in, d);
    if (!(d->writes & TL__B(HDR))) d->clears = d->writes;
    d->attach_depth = 1;
    d->light_data = TL__LIGHTS_INSTANCES;
    d->state = (tl__pipeline){.depth_write = 0, .color_write = 1, .blend = TL__BLEND_ADD,
                              .clip_zero_one = in->o->depth_format == TL_DEPTH_FORMAT_D32F_REVERSED};
}

static void tl__lights_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    const size_t counts[3] = {in->f.point_lights, in->f.spot_lights, in->f.directional_lights};
    for (int k = 0; k < 3; k++) {
        if (!counts[k]) continue;
        tl__perm *p = &out->slot[k];
        out->used[k] = 1;
        tl__perm_value(p, TL__V_LIGHT_TYPE, (uint32_t)(k + 1));
        tl__perm_flag(p, in->mode->light_flag);
        tl__light_pass_defines(in, d, p);
        tl__perm_merge(p, &in->spec_perm);
        if (k < 2 && in->o->fullscreen_lights) tl__perm_flag(p, TL__F_LIGHT_FULLSCREEN);
    }
}

/* One type's instances: outside volumes by front faces, inside ones by back faces. */
static void tl__draw_volumes(const tl__pass_ctx *ctx, int k)
{
    const GladGLContext *gl = ctx->gl;
    const tl__lights *l = ctx->lights;
    GLsizei nidx = (GLsizei)l->volume_index_count[k];
    size_t count = l->instance_count[k], outside = l->instance_outside[k];
    tl__pipeline p = {.depth_write = 0, .color_write = 1, .blend = TL__BLEND_ADD, .depth_clamp = 1,
                      .clip_zero_one = ctx->pipeline->clip_zero_one};
    if (outside) {
        p.depth_test = TL__DEPTH_LEQUAL;
        p.cull = TL__CULL_BACK;
        tl__state_apply(gl, ctx->state, &p);
        gl->DrawElementsInstancedBaseInstance(GL_TRIANGLES, nidx, GL_UNSIGNED_INT, NULL, (GLsizei)outside, 0);
        ctx->out->draw_calls++;
    }
    if (count > outside) {
        p.depth_test = TL__DEPTH_GEQUAL;
        p.cull = TL__CULL_FRONT;
        tl__state_apply(gl, ctx->state, &p);
        gl->DrawElementsInstancedBaseInstance(GL_TRIANGLES, nidx, GL_UNSIGNED_INT, NULL, (GLsizei)(count - outside),
                                              (GLuint)outside);
        ctx->out->draw_calls++;
    }
}

static void tl__lights_execute(const tl__pass_ctx *ctx)
{
    const GladGLContext *gl = ctx->gl;
    const tl__lights *l = ctx->lights;
    for (int k = 0; k < TL__LIGHT_KINDS; k++) {
        GLuint p = ctx->programs[k];
        if (ctx->queries) gl->BeginQuery(GL_SAMPLES_PASSED, ctx->queries[k]); /* every type's: read later */
        if (!l->instance_count[k] || !p) {
            if (ctx->queries) gl->EndQuery(GL_SAMPLES_PASSED);
            continue;
        }
        tl__state_program(gl, ctx->state, p);
        tl__state_vertex_array(gl, ctx->state, l->vao[k]);
        if (k == 2 || l->fullscreen) {
            tl__state_apply(gl, ctx->state, ctx->pipeline); /* no depth test, no culling */
            gl->DrawArraysInstanced(GL_TRIANGLES, 0, 3, (GLsizei)l->instance_count[k]);
            ctx->out->draw_calls++;
        } else {
            tl__draw_volumes(ctx, k);
        }
        if (ctx->queries) gl->EndQuery(GL_SAMPLES_PASSED);
        ctx->out->instances += l->instance_count[k];
    }
}

static void tl__lights_collect(const uint64_t *results, uint64_t fragments, uint64_t pixels, double ms,
                               tl_frame_stats *st)
{
    (void)fragments;
    (void)pixels;
    (void)ms;
    for (int k = 0; k < TL__LIGHT_KINDS; k++) {
        st->light_fragments[k + 1] = results[k];
        st->light_pairs += results[k];
    }
}

const tl__pass_def tl__pass_lights = {
    .id = TL_PASS_LIGHTS,
    .name = "lights",
    .programs = {{"lights.point", "light.vert.glsl", "light.frag.glsl"},
                 {"lights.spot", "light.vert.glsl", "light.frag.glsl"},
                 {"lights.directional", "light.vert.glsl", "light.frag.glsl"}},
    .targets = {&tl__target_light_diffuse, &tl__target_light_specular, &tl__target_light_fresnel, &tl__target_light_coat,
                &tl__target_light_reduced_diffuse, &tl__target_light_reduced_specular, &tl__target_light_reduced_fresnel},
    .declare = tl__lights_declare,
    .permute = tl__lights_permute,
    .execute = tl__lights_execute,
    .collect = tl__lights_collect,
    .query_count = TL__LIGHT_KINDS,
    .services = TL__PASS_LIGHTS,
};
