/* The exact pixel-light pairs of the last frame (tl_renderer_count_light_pairs): the depth the light
 * pass read, read back, and the scene's local lights in the frame's view space, tested on the CPU
 * with the light passes' own range and cone tests (light_loop.glsl, tl_light_reaches), each light
 * over a conservative screen rectangle of its range. docs/bandwidth.md, "Reading the results". */
#include <math.h>
#include <string.h>

#include "renderer_internal.h"

/* The grid the light pass shades: each cell's view-space point (x, y, z; NaN x: no surface). */
typedef struct tl__pair_grid {
    float (*p)[3];
    uint32_t w, h;  /* the grid */
    uint32_t shift; /* light scale 2^-shift: a cell covers 2^shift pixels a side */
    uint32_t fw, fh; /* the frame */
    tl_projection pr;
} tl__pair_grid;

/* The depth the light pass reads (the reduced one below light scale 1), readable. */
static tl_result tl__pairs_source(tl_renderer *r, tl_target_id *depth, int *offset)
{
    *offset = r->graph.plan.pub.light_scale < 1.0f;
    *depth = *offset ? TL_TARGET_LIGHT_DEPTH : TL_TARGET_DEPTH;
    tl_target_id ids[2] = {*depth, TL_TARGET_LIGHT_OFFSET};
    for (int i = 0; i < 1 + *offset; i++) {
        if (!r->graph.targets[ids[i]].texture)
            return tl__fail(&r->dev, TL_ERROR_INVALID_ARGUMENT, "renderer: counting light pairs: the plan has no %s",
                            tl_target_name(ids[i]));
        if (r->graph.plan.shared & TL_TARGET_BIT(ids[i]))
            return tl__fail(&r->dev, TL_ERROR_INVALID_ARGUMENT,
                            "renderer: counting light pairs: %s shares its memory with a target written later in the "
                            "frame; list it in tl_renderer_options.keep_targets",
                            tl_target_name(ids[i]));
    }
    return TL_OK;
}

/* Each cell's point as the light pass reconstructs it (gbuffer_decode.glsl, tl_gbuffer_position):
 * the depth's linear distance along the ray through the pixel centre (below light scale 1: the
 * centre of the pixel the cell's depth came from, or of its block). */
static void tl__pairs_points(tl__pair_grid *g, const float *depth, const uint8_t *offset, float clear)
{
    float inv_w = 1.0f / (float)g->fw, inv_h = 1.0f / (float)g->fh, k = (float)(1u << g->shift);
    for (uint32_t y = 0; y < g->h; y++)
        for (uint32_t x = 0; x < g->w; x++) {
            size_t i = (size_t)y * g->w + x;
            if (depth[i] == clear) {
                g->p[i][0] = NAN;
                continue;
            }
            float cx = ((float)x + 0.5f) * k, cy = ((float)y + 0.5f) * k;
            if (offset) {
                unsigned o = offset[i] & 31u;
                if (o != 16u) {
                    cx = (float)(x * (1u << g->shift) + (o & 3u)) + 0.5f;
                    cy = (float)(y * (1u << g->shift) + (o >> 2)) + 0.5f;
                }
            }
            tl_view_position_from_depth(&g->pr, cx * inv_w * 2.0f - 1.0f, cy * inv_h * 2.0f - 1.0f, depth[i], g->p[i]);
        }
}

/* A conservative rectangle of grid cells [x0, x1) x [y0, y1) that the sphere (view space) may
 * cover: its bounding box's corners projected, widened by a cell; the whole grid when the sphere
 * reaches the eye's plane. */
static void tl__pairs_rect(const tl__pair_grid *g, const float c[3], float rad, uint32_t rect[4])
{
    rect[0] = rect[1] = 0;
    rect[2] = g->w;
    rect[3] = g->h;
    if (!(c[2] + rad < -1.0e-4f * (1.0f + fabsf(c[2])))) return;
    const float *m = g->pr.m;
    double lo[2] = {1e30, 1e30}, hi[2] = {-1e30, -1e30};
    for (int i = 0; i < 8; i++) {
        double p[3] = {c[0] + ((i & 1) ? rad : -rad), c[1] + ((i & 2) ? rad : -rad), c[2] + ((i & 4) ? rad : -rad)};
        double w = -p[2];
        double nx = (m[0] * p[0] + m[8] * p[2]) / w, ny = (m[5] * p[1] + m[9] * p[2]) / w;
        lo[0] = nx < lo[0] ? nx : lo[0], hi[0] = nx > hi[0] ? nx : hi[0];
        lo[1] = ny < lo[1] ? ny : lo[1], hi[1] = ny > hi[1] ? ny : hi[1];
    }
    double size[2] = {g->fw, g->fh}, cells[2] = {g->w, g->h}, k = (double)(1u << g->shift);
    for (int a = 0; a < 2; a++) {
        double p0 = floor((lo[a] + 1.0) * 0.5 * size[a] / k) - 1.0, p1 = ceil((hi[a] + 1.0) * 0.5 * size[a] / k) + 1.0;
        p0 = p0 < 0.0 ? 0.0 : p0 > cells[a] ? cells[a] : p0;
        p1 = p1 < 0.0 ? 0.0 : p1 > cells[a] ? cells[a] : p1;
        rect[a] = (uint32_t)p0;
        rect[2 + a] = (uint32_t)p1;
    }
}

/* One light's pairs over its rectangle, marking the cells it reaches. The tests of light_loop.glsl's
 * tl_light_reaches in float: outside when d2 >= r^2; a spot also when dot(-to_light, axis) <= cos_outer sqrt(d2). */
static uint64_t tl__pairs_light(const tl__pair_grid *g, const tl__light_record *l, const uint32_t rect[4],
                                uint8_t *covered)
{
    const float *lp = l->position_radius, *dir = l->direction_cos_outer;
    float r2 = lp[3] * lp[3];
    int spot = (int)l->color_type[3] == TL_LIGHT_SPOT;
    uint64_t n = 0;
    for (uint32_t y = rect[1]; y < rect[3]; y++)
        for (uint32_t x = rect[0]; x < rect[2]; x++) {
            size_t i = (size_t)y * g->w + x;
            const float *p = g->p[i];
            if (isnan(p[0])) continue;
            float t[3] = {lp[0] - p[0], lp[1] - p[1], lp[2] - p[2]};
            float d2 = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
            if (d2 >= r2) continue;
            if (spot && d2 > 0.0f && -(t[0] * dir[0] + t[1] * dir[1] + t[2] * dir[2]) <= dir[3] * sqrtf(d2)) continue;
            n++;
            covered[i] = 1;
        }
    return n;
}

/* Every local light of the renderer, in the frame's view space. */
static void tl__pairs_count(tl_renderer *r, const tl__pair_grid *g, const float view[16], uint8_t *covered,
                            tl_light_pair_count *out)
{
    for (size_t i = 0; i < r->lights.count; i++) {
        const tl_light *l = &r->lights.lights[i];
        if (l->type == TL_LIGHT_DIRECTIONAL) {
            out->directional_lights++;
            continue;
        }
        out->local_lights++;
        tl__light_record rec;
        tl__light_record_fill(l, view, 0.0f, &rec);
        float c[3], rad, cv[3];
        tl__light_sphere(l, c, &rad);
        for (int k = 0; k < 3; k++) cv[k] = view[k] * c[0] + view[4 + k] * c[1] + view[8 + k] * c[2] + view[12 + k];
        uint32_t rect[4];
        tl__pairs_rect(g, cv, rad * 1.0001f + 1e-6f, rect);
        out->exact_pairs += tl__pairs_light(g, &rec, rect, covered);
    }
}

/* The depth (and below light scale 1 the offsets) into the grid's points. */
static tl_result tl__pairs_read(tl_renderer *r, tl_target_id depth_id, int with_offset, tl__pair_grid *g)
{
    size_t n = (size_t)g->w * g->h;
    float *depth = (float *)tl__alloc_array(&r->dev.alloc, n, sizeof(float));
    uint8_t *offset = with_offset ? (uint8_t *)tl__alloc_array(&r->dev.alloc, n, 1) : NULL;
    char msg[256] = "";
    tl_result res = depth && (offset || !with_offset) ? TL_OK : TL_ERROR_OUT_OF_MEMORY;
    if (res == TL_OK)
        res = tl__target_read(&r->dev.gl, &r->graph.targets[depth_id], GL_DEPTH_COMPONENT, GL_FLOAT, depth,
                              n * sizeof(float), msg, sizeof msg);
    if (res == TL_OK && offset)
        res = tl__target_read(&r->dev.gl, &r->graph.targets[TL_TARGET_LIGHT_OFFSET], GL_RED, GL_UNSIGNED_BYTE, offset,
                              n, msg, sizeof msg);
    if (res == TL_OK)
        tl__pairs_points(g, depth, offset, r->desc.options.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED ? 0.0f : 1.0f);
    tl__free(&r->dev.alloc, depth);
    tl__free(&r->dev.alloc, offset);
    if (res != TL_OK) return tl__fail(&r->dev, res, "renderer: counting light pairs: reading the depth: %s", msg);
    return TL_OK;
}

tl_result tl_renderer_count_light_pairs(tl_renderer *r, tl_light_pair_count *out)
{
    if (!r || !out) return r ? tl__fail(&r->dev, TL_ERROR_INVALID_ARGUMENT, "renderer: counting light pairs: NULL output")
                             : TL_ERROR_INVALID_ARGUMENT;
    memset(out, 0, sizeof *out);
    tl_result res = tl__need_context(&r->dev, "tl_renderer_count_light_pairs");
    if (res != TL_OK) return res;
    if (r->frame_index == 0)
        return tl__fail(&r->dev, TL_ERROR_INVALID_ARGUMENT, "renderer: counting light pairs: no frame was rendered yet");
    tl_target_id depth_id;
    int with_offset;
    if ((res = tl__pairs_source(r, &depth_id, &with_offset)) != TL_OK) return res;
    const tl__camera_view *cam = &r->scene.frame_camera;
    tl__pair_grid g = {.w = r->graph.targets[depth_id].width, .h = r->graph.targets[depth_id].height,
                       .fw = r->desc.width, .fh = r->desc.height};
    for (float scale = r->graph.plan.pub.light_scale; scale > 0.0f && scale < 1.0f && g.shift < 4; scale *= 2.0f)
        g.shift++;
    res = tl_projection_perspective(r->desc.options.depth_format, cam->fov_y, (float)g.fw / (float)g.fh, cam->near_z,
                                    cam->far_z, &g.pr);
    if (res != TL_OK) return tl__fail(&r->dev, res, "renderer: counting light pairs: no camera was resolved yet");
    size_t n = (size_t)g.w * g.h;
    g.p = (float(*)[3])tl__alloc_array(&r->dev.alloc, n, sizeof *g.p);
    uint8_t *covered = (uint8_t *)tl__alloc_array(&r->dev.alloc, n, 1);
    if (!g.p || !covered) res = tl__fail(&r->dev, TL_ERROR_OUT_OF_MEMORY, "renderer: counting light pairs: %zu cells", n);
    if (res == TL_OK) res = tl__pairs_read(r, depth_id, with_offset, &g);
    if (res == TL_OK) {
        float view[16];
        tl__camera_view_matrix(cam, view);
        memset(covered, 0, n);
        tl__pairs_count(r, &g, view, covered, out);
        for (size_t i = 0; i < n; i++) {
            out->covered_pixels += covered[i];
            out->surface_pixels += !isnan(g.p[i][0]);
        }
        out->directional_pairs = out->surface_pixels * out->directional_lights;
        out->width = g.w;
        out->height = g.h;
    }
    tl__free(&r->dev.alloc, g.p);
    tl__free(&r->dev.alloc, covered);
    return res;
}
