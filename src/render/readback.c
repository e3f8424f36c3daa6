/* Reading targets back, and FXAA on a caller's image through the frame's own passes (the luma
 * pass, then the compiled FXAA pass). Every readback takes its buffer size in bytes; a NULL buffer
 * asks for the size. */
#include <stdio.h>
#include <string.h>

#include "renderer_internal.h"

/* The size protocol shared by every readback: *size gets `need`; a NULL buffer only asks, a buffer
 * smaller than `need` is TL_ERROR_LIMIT. Returns 1 when the caller should go on and read. */
static int tl__size_check(tl_renderer *rr, const void *dst, size_t *size, size_t need, const char *what,
                          tl_result *res)
{
    tl__device *r = &rr->dev;
    *res = TL_OK;
    if (!size) {
        *res = tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: reading %s needs a size", what);
        return 0;
    }
    size_t have = *size;
    *size = need;
    if (!dst) return 0;
    if (have < need) {
        *res = tl__fail(r, TL_ERROR_LIMIT, "renderer: reading %s needs %zu bytes, the buffer has %zu", what, need, have);
        return 0;
    }
    return 1;
}

/* A target that shares its memory with one written later in the frame holds that one's pixels. */
static tl_result tl__readable(tl_renderer *r, tl_target_id id)
{
    if ((unsigned)id >= TL_TARGET_COUNT || !r->graph.targets[id].texture)
        return tl__fail(&r->dev, TL_ERROR_INVALID_ARGUMENT, "renderer: target %s is not in the plan", tl_target_name(id));
    if (r->graph.plan.shared & TL_TARGET_BIT(id))
        return tl__fail(&r->dev, TL_ERROR_INVALID_ARGUMENT,
                        "renderer: target %s shares its memory with a target written later in the frame; list it in "
                        "tl_renderer_options.keep_targets to read it",
                        tl_target_name(id));
    return TL_OK;
}

/* The output target as it is (apply_fxaa has just written it outside a frame). */
static tl_result tl__read_output(tl_renderer *r, uint8_t *rgba, size_t size)
{
    char msg[256];
    tl_result res = tl__target_read(&r->dev.gl, &r->graph.targets[TL_TARGET_OUTPUT], GL_RGBA, GL_UNSIGNED_BYTE, rgba,
                                    size, msg, sizeof msg);
    if (res != TL_OK) return tl__fail(&r->dev, res, "renderer: reading the output: %s", msg);
    return TL_OK;
}

tl_result tl_renderer_read_output(tl_renderer *r, uint8_t *rgba, size_t *size)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res;
    if (!tl__size_check(r, rgba, size, (size_t)r->desc.width * r->desc.height * 4, "the output", &res)) return res;
    if ((res = tl__need_context(&r->dev, "tl_renderer_read_output")) != TL_OK) return res;
    /* the target's memory before a frame is whatever GL gave it: not an image */
    if (!r->output_drawn)
        return tl__fail(&r->dev, TL_ERROR_INVALID_ARGUMENT,
                        "renderer: tl_renderer_read_output: no frame was rendered into the output at %ux%u (call "
                        "tl_renderer_render first; render_to draws into the caller's framebuffer instead)",
                        r->desc.width, r->desc.height);
    return tl__read_output(r, rgba, *size);
}

/* Depth into the upper quarter of the buffer, then spread out as (window depth, distance, 0, 1). */
static tl_result tl__read_depth(tl_renderer *r, tl_target_id id, float *rgba, size_t n, char *msg, size_t msg_size)
{
    float *d = rgba + n * 3;
    tl_result res = tl__target_read(&r->dev.gl, &r->graph.targets[id], GL_DEPTH_COMPONENT, GL_FLOAT, d,
                                    n * sizeof(float), msg, msg_size);
    if (res != TL_OK) return res;
    tl_projection pr; /* of the camera the depth was rendered with (set_scene: the scene's) */
    const tl__camera_view *c = &r->scene.frame_camera;
    res = tl_projection_perspective(r->desc.options.depth_format, c->fov_y, (float)r->desc.width / (float)r->desc.height,
                                    c->near_z, c->far_z, &pr);
    if (res != TL_OK) {
        snprintf(msg, msg_size, "no camera has been resolved yet");
        return res;
    }
    for (size_t i = 0; i < n; i++) {
        float dv = d[i];
        rgba[4 * i + 0] = dv;
        rgba[4 * i + 1] = -tl_depth_linearize(&pr, dv);
        rgba[4 * i + 2] = 0.0f;
        rgba[4 * i + 3] = 1.0f;
    }
    return TL_OK;
}

/* RT0 decoded on the CPU with the codec: normal and gloss. */
static tl_result tl__read_rt0(tl_renderer *r, tl_target_id id, float *rgba, size_t n, char *msg, size_t msg_size)
{
    uint8_t *bytes = (uint8_t *)tl__alloc_array(&r->dev.alloc, n, 4);
    if (!bytes) return TL_ERROR_OUT_OF_MEMORY;
    int ten = r->desc.options.rt0 == TL_RT0_RGB10A2;
    tl_result res = tl__target_read(&r->dev.gl, &r->graph.targets[id], GL_RGBA,
                                    ten ? GL_UNSIGNED_INT_2_10_10_10_REV : GL_UNSIGNED_BYTE, bytes, n * 4, msg, msg_size);
    for (size_t i = 0; res == TL_OK && i < n; i++) {
        float nv[3], g;
        if (ten) {
            uint32_t t;
            memcpy(&t, bytes + 4 * i, 4);
            tl_rt0_decode_rgb10a2(t, nv, &g, NULL);
        } else {
            tl_rt0_decode_rgba8(bytes + 4 * i, nv, &g);
        }
        memcpy(&rgba[4 * i], nv, sizeof nv);
        rgba[4 * i + 3] = g;
    }
    tl__free(&r->dev.alloc, bytes);
    return res;
}

tl_result tl_renderer_read_target(tl_renderer *r, tl_target_id id, float *rgba, size_t *size)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__readable(r, id);
    if (res != TL_OK) return res;
    const tl__target *t = &r->graph.targets[id];
    size_t n = (size_t)t->width * t->height; /* a reduced target: its first level */
    if (!tl__size_check(r, rgba, size, n * 4 * sizeof(float), tl_target_name(id), &res)) return res;
    if ((res = tl__need_context(&r->dev, "tl_renderer_read_target")) != TL_OK) return res;
    char msg[256] = "";
    /* the light scale's reduced depth and RT0 read as the frame's */
    if (r->graph.plan.targets[id]->depth) res = tl__read_depth(r, id, rgba, n, msg, sizeof msg);
    else if (id == TL_TARGET_RT0 || id == TL_TARGET_LIGHT_RT0) res = tl__read_rt0(r, id, rgba, n, msg, sizeof msg);
    else res = tl__target_read(&r->dev.gl, t, GL_RGBA, GL_FLOAT, rgba, *size, msg, sizeof msg);
    if (res != TL_OK) return tl__fail(&r->dev, res, "renderer: reading %s: %s", tl_target_name(id), msg);
    return TL_OK;
}

static const tl__compiled_pass *tl__fxaa_pass(const tl__graph *g, size_t *index)
{
    for (size_t i = 0; i < g->pass_count; i++)
        if (g->passes[i].def && g->passes[i].def->id == TL_PASS_FXAA) {
            *index = i;
            return &g->passes[i];
        }
    return NULL;
}

/* The luma pass's program, and the caller's image in the output target. */
static tl_result tl__fxaa_input(tl_renderer *r, const uint8_t *rgba)
{
    tl__device *dev = &r->dev;
    tl__graph *g = &r->graph;
    tl_result res = TL_OK;
    if (!g->programs_ready && (res = tl__graph_programs(dev, g)) != TL_OK) return res;
    if (!g->luma.programs[0] &&
        (res = tl__program_get(dev, "luma", &tl__pass_luma.programs[0], "TL_OUT_LDR=0",
                                    &(tl__program_units){g->luma_decl.samples, g->luma_decl.images}, &g->luma.programs[0])) != TL_OK)
        return res;
    tl__pixel_store saved;
    tl__pixel_store_enter(&dev->gl, 1, &saved);
    dev->gl.TextureSubImage2D(g->targets[TL_TARGET_OUTPUT].texture, 0, 0, 0, (GLsizei)r->desc.width,
                              (GLsizei)r->desc.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    tl__pixel_store_leave(&dev->gl, &saved);
    return TL_OK;
}

tl_result tl_renderer_apply_fxaa(tl_renderer *r, const uint8_t *rgba, uint8_t *out, size_t *size)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl__device *dev = &r->dev;
    tl_result res;
    if (!tl__size_check(r, out, size, (size_t)r->desc.width * r->desc.height * 4, "the FXAA image", &res)) return res;
    if (!rgba) return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: apply_fxaa needs an input image");
    if ((res = tl__need_context(dev, "tl_renderer_apply_fxaa")) != TL_OK) return res;
    size_t fxaa_index = 0;
    const tl__compiled_pass *fxaa = tl__fxaa_pass(&r->graph, &fxaa_index);
    if (!fxaa || !r->graph.luma.fbo)
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: FXAA is off in this renderer");
    if ((res = tl__fxaa_input(r, rgba)) != TL_OK) return res;
    const GladGLContext *gl = &dev->gl;
    size_t offset = 0;
    size_t need = sizeof(tl__frame_ubo) + dev->lim.ubo_align + tl__params_bytes(r, fxaa, 1);
    if (tl__stream_begin(gl, &dev->stream, need, "buffer.frame") != TL_OK)
        return tl__fail(dev, TL_ERROR_GL, "renderer: could not map the per-frame buffer");
    tl__frame_ubo *u = (tl__frame_ubo *)tl__stream_reserve(&dev->stream, sizeof *u, dev->lim.ubo_align, &offset);
    tl__frame_ubo_post(&r->desc, u);
    tl__stream_bind_range(gl, &dev->stream, GL_UNIFORM_BUFFER, TL__UBO_FRAME, offset, sizeof *u);
    tl__frame_record rec;
    memset(&rec, 0, sizeof rec);
    tl__state_enter(gl, &dev->state, TL__TEXTURE_UNITS_USED);
    tl__run_pass(r, &r->graph.luma, &rec, 0);
    tl__run_pass(r, fxaa, &rec, fxaa_index);
    tl__state_reset(gl, &dev->state, TL__TEXTURE_UNITS_USED, TL__BUFFER_BINDINGS_USED, TL__IMAGE_UNITS_USED);
    tl__stream_end(gl, &dev->stream);
    res = tl__read_output(r, out, *size);
    GLenum e = gl->GetError();
    if (res == TL_OK && e != GL_NO_ERROR)
        return tl__fail(dev, TL_ERROR_GL, "renderer: %s in FXAA", tl__gl_error_string(e));
    return res;
}

tl_result tl_renderer_get_shadow_views(tl_renderer *r, tl_shadow_view_info *views, size_t *count, uint32_t *atlas_size)
{
    if (!r || !count) return TL_ERROR_INVALID_ARGUMENT;
    if (atlas_size) *atlas_size = r->shadows.atlas ? r->shadows.atlas_size : 0;
    if (!r->graph.plan.pub.shadow_lights) { /* the views of an earlier plan are gone with it */
        *count = 0;
        return TL_OK;
    }
    size_t have = *count;
    tl_result res = tl__shadows_views(&r->shadows, r->lights.lights, r->lights.count, views, count);
    if (res != TL_OK)
        return tl__fail(&r->dev, res, "renderer: %zu shadow views, the buffer holds %zu", *count, have);
    return TL_OK;
}

tl_result tl_renderer_read_shadow_atlas(tl_renderer *r, float *depth, size_t *size)
{
    if (!r || !size) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = depth ? tl__need_context(&r->dev, "tl_renderer_read_shadow_atlas") : TL_OK;
    if (res != TL_OK) return res;
    return tl__shadows_read_atlas(&r->dev, &r->shadows, depth, size);
}
