/* MSAA with per-sample lighting on edges (docs/antialiasing.md; Lauritzen 2010, CryENGINE 3's
 * sample mask) for thin-lpp, thin-deferred and fat: the G-buffer pass draws into a multisampled
 * G-buffer (tl__gbuffer_samples, pass_geometry.c), msaa-classify marks the pixels whose samples
 * differ in depth, normal or (deferred modes) material in msaa.edges, the light pass (volumes or
 * the tiled fragment pass) lights every other pixel once from sample 0's surface, and
 * lights-samples runs the same light pass again with sample-rate shading on the edge pixels alone
 * (shaders/gbuffer_samples.glsl says which pixels a pass lights); the compute tiled pass does both
 * in one dispatch, an invocation per pixel and sample (lights_tiled.comp.glsl), and has no
 * lights-samples. thin-lpp's light buffer is
 * multisampled too, and its material pass (multisampled, depth EQUAL against the G-buffer's depth)
 * takes the light of the first sample it covers that holds its surface (light_msaa.glsl). The thin
 * G-buffer's checkerboard chroma is rebuilt per sample from the four neighbours' same sample index
 * (gbuffer_decode.glsl, tl_rt1_read). */
#include <stdio.h>
#include <string.h>

#include "gl/gl.h"
#include "lights.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

extern const tl__pass_def tl__pass_lights, tl__pass_lights_tiled;

/* visibility resolves every sample itself (pass_visibility.c): no edges to classify */
static int tl__sample_edges(const tl__plan_input *in)
{
    return in->lights && tl__msaa_sample_edges(in->o) && !in->mode->visibility;
}

/* One byte a pixel, one sample: 1 on an edge pixel. */
static const tl__target_def tl__target_msaa_edges = {TL__TARGET(MSAA_EDGES, "msaa.edges"), .format = GL_R8};

/* ---- msaa-classify ------------------------------------------------------------------------- */

static void tl__classify_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!tl__sample_edges(in)) return;
    tl__pass_decl light = {0}; /* it reads what the light pass reads of the G-buffer, and depth */
    tl__light_pass_targets(in, &light);
    d->writes = d->clears = TL__B(MSAA_EDGES);
    d->reads = d->samples = TL__B(DEPTH) | (light.samples & ~(TL__B(MSAA_EDGES) | TL__B(HDR)));
    d->state = (tl__pipeline){.color_write = 1};
}

static void tl__classify_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    tl__perm *k = &out->slot[0];
    out->used[0] = 1;
    tl__perm_value(k, TL__V_GBUFFER_SAMPLES, in->msaa);
    tl__perm_flag(k, in->rt0_flag);
    if (in->o->mode == TL_MODE_FAT) tl__perm_flag(k, TL__F_CLASSIFY_FAT);
    else if (d->samples & TL__B(RT1)) tl__perm_flag(k, TL__F_CLASSIFY_RT1);
}

/* It writes the edge pixels alone: its samples-passed count is theirs. */
static void tl__classify_collect(const uint64_t *results, uint64_t fragments, uint64_t pixels, double ms,
                               tl_frame_stats *st)
{
    (void)results;
    (void)ms;
    st->msaa_edge_pixels = fragments;
    st->msaa_edge_fraction = pixels ? (double)fragments / (double)pixels : 0.0;
}

const tl__pass_def tl__pass_msaa_classify = {
    .id = TL_PASS_MSAA_CLASSIFY,
    .name = "msaa-classify",
    .programs = {{"msaa-classify", "fullscreen.vert.glsl", "msaa_classify.frag.glsl"}},
    .targets = {&tl__target_msaa_edges},
    .declare = tl__classify_declare,
    .permute = tl__classify_permute,
    .execute = tl__draw_fullscreen,
    .collect = tl__classify_collect,
};

/* ---- lights-samples: the light pass again, per sample, on the edge pixels ---------------------- */

static void tl__samples_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    /* the compute tiled pass lights the edge pixels' samples in its own dispatch */
    int compute = in->tiled_compute;
    if (!tl__sample_edges(in) || (in->strategy == TL_LIGHT_STRATEGY_TILED && compute)) return;
    if (in->strategy == TL_LIGHT_STRATEGY_TILED)
        tl__pass_lights_tiled.declare(in, d);
    else
        tl__pass_lights.declare(in, d);
    d->clears = 0u; /* it adds to what the light pass wrote */
}

/* The light pass's programs with TL_MSAA_SAMPLE: volumes in slots 0-2 (point, spot, directional),
 * the tiled fragment pass in slot 3. */
static void tl__samples_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    tl__pass_defines light;
    memset(&light, 0, sizeof light);
    int tiled = in->strategy == TL_LIGHT_STRATEGY_TILED;
    (tiled ? &tl__pass_lights_tiled : &tl__pass_lights)->permute(in, d, &light);
    for (int k = 0; k < 3; k++) {
        if (!light.used[k]) continue;
        int slot = tiled ? 3 : k;
        out->used[slot] = 1;
        out->slot[slot] = light.slot[k];
        tl__perm_flag(&out->slot[slot], TL__F_MSAA_SAMPLE);
    }
}

static void tl__samples_execute(const tl__pass_ctx *ctx)
{
    const GladGLContext *gl = ctx->gl;
    if (!ctx->programs[3]) {
        tl__pass_lights.execute(ctx);
        return;
    }
    tl__state_program(gl, ctx->state, ctx->programs[3]);
    tl__state_vertex_array(gl, ctx->state, ctx->fullscreen_vao);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    ctx->out->draw_calls++;
}

const tl__pass_def tl__pass_lights_samples = {
    .id = TL_PASS_LIGHTS_SAMPLES,
    .name = "lights-samples",
    .programs = {{"lights-samples.point", "light.vert.glsl", "light.frag.glsl"},
                 {"lights-samples.spot", "light.vert.glsl", "light.frag.glsl"},
                 {"lights-samples.directional", "light.vert.glsl", "light.frag.glsl"},
                 {"lights-samples.tiled", "fullscreen.vert.glsl", "lights_tiled.frag.glsl"}},
    .declare = tl__samples_declare,
    .permute = tl__samples_permute,
    .execute = tl__samples_execute,
    .services = TL__PASS_LIGHTS,
};
