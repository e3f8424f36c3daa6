/* The light pass: instanced light volumes (DESIGN.md section 2). One instanced draw per light type
 * and side: volumes the camera is outside of by their front faces (depth LEQUAL: lights hidden
 * behind the scene cost nothing), those that contain it or may cross the near plane by their back
 * faces (GEQUAL), both with depth clamp so the far plane cuts nothing; directional lights as a
 * full-screen triangle. What the shader does with the light (accumulate into the light buffer,
 * shade into HDR) is the mode table's. */
#include <stdio.h>

#include "renderer_internal.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

/* What the light pass reads and writes in this mode, whatever the strategy (the tiled pass too). */
void tl__light_pass_targets(const tl__plan_input *in, tl__pass_decl *d)
{
    const tl__mode_def *m = in->mode;
    uint32_t spec_targets = TL__B(LIGHT_SPECULAR) | TL__B(FAT_MATERIAL);
    int exact_spec = in->spec && in->d.options.light_buffer == TL_LIGHT_BUFFER_EXACT;
    d->writes = m->light_writes & (exact_spec ? ~0u : ~TL__B(LIGHT_SPECULAR));
    if (in->fresnel != TL_FRESNEL_TWO_SUMS) d->writes &= ~TL__B(LIGHT_FRESNEL); /* S2: GGX's two sums only */
    d->reads = m->light_reads & (in->spec ? ~0u : ~spec_targets);
    d->samples = m->light_samples & d->reads;
    d->neighbourhood = d->samples & TL__B(RT1); /* chroma from the four neighbours */
    if (d->writes & TL__B(HDR)) d->reads |= TL__B(HDR); /* shading adds to it */
}

static void tl__lights_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->lights || in->mode->forward || in->strategy != TL_LIGHT_STRATEGY_VOLUMES) return;
    tl__light_pass_targets(in, d);
    if (!(d->writes & TL__B(HDR))) d->clears = d->writes;
    d->attach_depth = 1;
    d->state = (tl__pipeline){.depth_write = 0, .color_write = 1, .blend = TL__BLEND_ADD,
                              .clip_zero_one = in->d.options.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED};
}

static void tl__lights_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    const size_t counts[3] = {in->f.point_lights, in->f.spot_lights, in->f.directional_lights};
    const char *fullscreen = in->d.options.fullscreen_lights ? " TL_LIGHT_FULLSCREEN" : "";
    for (int k = 0; k < 3; k++) {
        if (!counts[k]) continue;
        out->used[k] = 1;
        snprintf(out->slot[k], sizeof out->slot[k], "TL_LIGHT_TYPE=%d %s%s%s %s%s", k + 1, in->mode->light_define,
                 (d->reads & TL__B(RT0)) ? " " : "", (d->reads & TL__B(RT0)) ? in->rt0_define : "", in->spec_define,
                 k < 2 ? fullscreen : "");
    }
}

/* One type's instances: outside volumes by front faces, inside ones by back faces. */
static void tl__draw_volumes(tl_renderer *r, int k, tl__frame_record *rec)
{
    const GladGLContext *gl = &r->gl;
    GLsizei nidx = (GLsizei)r->volume_index_count[k];
    size_t count = r->instance_count[k], outside = r->instance_outside[k];
    tl__pipeline p = {.depth_write = 0, .color_write = 1, .blend = TL__BLEND_ADD, .depth_clamp = 1,
                      .clip_zero_one = r->state.p.clip_zero_one};
    if (outside) {
        p.depth_test = TL__DEPTH_LEQUAL;
        p.cull = TL__CULL_BACK;
        tl__state_apply(gl, &r->state, &p);
        gl->DrawElementsInstancedBaseInstance(GL_TRIANGLES, nidx, GL_UNSIGNED_INT, NULL, (GLsizei)outside, 0);
        rec->st.draw_calls++;
    }
    if (count > outside) {
        p.depth_test = TL__DEPTH_GEQUAL;
        p.cull = TL__CULL_FRONT;
        tl__state_apply(gl, &r->state, &p);
        gl->DrawElementsInstancedBaseInstance(GL_TRIANGLES, nidx, GL_UNSIGNED_INT, NULL, (GLsizei)(count - outside),
                                              (GLuint)outside);
        rec->st.draw_calls++;
    }
}

static void tl__lights_execute(tl_renderer *r, const tl__pass_ctx *ctx)
{
    const GladGLContext *gl = &r->gl;
    const tl__pipeline base = r->state.p;
    for (int k = 0; k < TL__LIGHT_KINDS; k++) {
        GLuint p = ctx->cp->programs[k];
        if (ctx->queries) gl->BeginQuery(GL_SAMPLES_PASSED, ctx->queries[k]); /* every type's: read later */
        if (!r->instance_count[k] || !p) {
            if (ctx->queries) gl->EndQuery(GL_SAMPLES_PASSED);
            continue;
        }
        tl__state_program(gl, &r->state, p);
        tl__state_vertex_array(gl, &r->state, r->vao_light[k]);
        if (k == 2 || r->desc.options.fullscreen_lights) {
            tl__state_apply(gl, &r->state, &base); /* no depth test, no culling */
            gl->DrawArraysInstanced(GL_TRIANGLES, 0, 3, (GLsizei)r->instance_count[k]);
            ctx->rec->st.draw_calls++;
        } else {
            tl__draw_volumes(r, k, ctx->rec);
        }
        if (ctx->queries) gl->EndQuery(GL_SAMPLES_PASSED);
        ctx->rec->instances[ctx->index] += r->instance_count[k];
    }
}

static void tl__lights_collect(tl_renderer *r, const uint64_t *results, tl_frame_stats *st)
{
    (void)r;
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
    .declare = tl__lights_declare,
    .permute = tl__lights_permute,
    .prepare = tl__lights_prepare,
    .upload = tl__lights_upload,
    .execute = tl__lights_execute,
    .collect = tl__lights_collect,
    .query_count = TL__LIGHT_KINDS,
};
