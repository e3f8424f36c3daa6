/* Reading targets back. Every readback takes its buffer size in bytes; a NULL buffer asks for the
 * size (tl__size_check, which fxaa_apply.c shares). */
#include <stdio.h>
#include <string.h>

#include "renderer_internal.h"

/* The size protocol shared by every readback: *size gets `need`; a NULL buffer only asks, a buffer
 * smaller than `need` is TL_ERROR_LIMIT. Returns 1 when the caller should go on and read. */
int tl__size_check(tl_renderer *rr, const void *dst, size_t *size, size_t need, const char *what, tl_result *res)
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
tl_result tl__read_output(tl_renderer *r, uint8_t *rgba, size_t size)
{
    char msg[256];
    tl_result res = tl__target_read(&r->dev.gl, &r->graph.targets[tl__target_frame_output()], GL_RGBA,
                                    GL_UNSIGNED_BYTE, rgba, size, msg, sizeof msg);
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

/* Visibility's id split on the CPU: (object slot, triangle within it, 1, 1), or (-1, -1, 0, 1) where
 * nothing was drawn; both fields are below 2^24, exact as floats. */
static tl_result tl__read_vis_id(tl_renderer *r, tl_target_id id, float *rgba, size_t n, char *msg, size_t msg_size)
{
    unsigned char *ids = (unsigned char *)(rgba + n * 3); /* the upper quarter, spread out in order */
    tl_result res = tl__target_read(&r->dev.gl, &r->graph.targets[id], GL_RED_INTEGER, GL_UNSIGNED_INT, ids,
                                    n * sizeof(uint32_t), msg, msg_size);
    for (size_t i = 0; res == TL_OK && i < n; i++) {
        uint32_t v;
        memcpy(&v, ids + 4 * i, sizeof v);
        int drawn = v != 0u;
        rgba[4 * i + 0] = drawn ? (float)((v >> TL__VIS_TRIANGLE_BITS) - 1u) : -1.0f;
        rgba[4 * i + 1] = drawn ? (float)(v & ((1u << TL__VIS_TRIANGLE_BITS) - 1u)) : -1.0f;
        rgba[4 * i + 2] = (float)drawn;
        rgba[4 * i + 3] = 1.0f;
    }
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
    else if (r->graph.plan.targets[id]->read_rt0) res = tl__read_rt0(r, id, rgba, n, msg, sizeof msg);
    else if (r->graph.plan.targets[id]->read_vis_id) res = tl__read_vis_id(r, id, rgba, n, msg, sizeof msg);
    else res = tl__target_read(&r->dev.gl, t, GL_RGBA, GL_FLOAT, rgba, *size, msg, sizeof msg);
    if (res != TL_OK) return tl__fail(&r->dev, res, "renderer: reading %s: %s", tl_target_name(id), msg);
    return TL_OK;
}
