/* The view of a frame: the camera resolved against the scene, matrices, frustum planes and the
 * per-frame uniform block (frame.glsl). */
#include <math.h>
#include <string.h>

#include "scene_gpu.h"
#include "view.h"

static int tl__reversed(tl_depth_format f) { return f == TL_DEPTH_FORMAT_D32F_REVERSED; }

static void tl__view_info(const tl_renderer_desc *d, const tl__camera_view *cam, tl__view *v)
{
    tl_view_info *i = &v->info;
    memcpy(i->view, v->view.m, sizeof i->view);
    memcpy(i->projection, v->proj.m, sizeof i->projection);
    memcpy(i->view_projection, v->view_proj.m, sizeof i->view_projection);
    memcpy(i->eye, v->eye, sizeof i->eye);
    i->near_z = v->near_z;
    i->far_z = cam->far_z;
    i->reversed_z = tl__reversed(d->options.depth_format);
    i->width = d->width;
    i->height = d->height;
}

tl_result tl__camera_check(tl__device *dev, tl__scene_gpu *g, tl_depth_format depth, const tl_camera *c,
                           const char *what, tl__camera_view *out)
{
    char msg[TL__CHECK_MESSAGE_SIZE];
    if (g->bounds_dirty) tl__scene_bounds_refresh(g); /* objects moved since the last view */
    tl_result res = tl__camera_resolve(c, what, depth, g->has_bounds ? g->bounds_min : NULL,
                                       g->has_bounds ? g->bounds_max : NULL, out, msg, sizeof msg);
    if (res != TL_OK) return tl__fail(dev, res, "renderer: %s", msg);
    if (out->near_raised && !(g->warned & TL__WARNED_NEAR)) { /* once per scene: not every frame */
        g->warned |= TL__WARNED_NEAR;
        tl__log_message(&dev->log, TL_LOG_WARNING, "renderer: %s", msg);
    }
    return TL_OK;
}

tl_result tl__view_setup(tl__device *dev, tl__scene_gpu *g, const tl_renderer_desc *d, const tl_camera *c,
                         const char *what, uint64_t frame, tl__view *v)
{
    tl__camera_view cam;
    tl_depth_format depth = d->options.depth_format;
    tl_result res = tl__camera_check(dev, g, depth, c, what, &cam);
    if (res != TL_OK) return res;
    res = tl_projection_perspective(depth, cam.fov_y, (float)d->width / (float)d->height, cam.near_z, cam.far_z,
                                    &v->projection);
    if (res != TL_OK) /* the camera was resolved for this: a failure here is the renderer's bug */
        return tl__fail(dev, res, "renderer: no projection for fov %g, near %g, far %g", (double)cam.fov_y,
                        (double)cam.near_z, (double)cam.far_z);
    g->frame_camera = cam;
    tl__camera_view_matrix(&cam, v->view.m);
    memcpy(v->proj.m, v->projection.m, sizeof v->proj.m);
    v->view_proj = tl__mat4_mul(&v->proj, &v->view);
    tl__frustum_planes(&v->view_proj, v->planes);
    if (tl__reversed(depth)) { /* [0,1] clip: the near plane is w - z >= 0 */
        const float *m = v->view_proj.m;
        for (int i = 0; i < 4; i++) v->planes[4][i] = m[i * 4 + 3] - m[i * 4 + 2];
        float l = sqrtf(v->planes[4][0] * v->planes[4][0] + v->planes[4][1] * v->planes[4][1] +
                        v->planes[4][2] * v->planes[4][2]);
        for (int i = 0; i < 4; i++) v->planes[4][i] /= l;
    }
    v->clear_depth = tl__reversed(depth) ? 0.0f : 1.0f;
    memcpy(v->eye, c->position, sizeof v->eye);
    v->near_z = cam.near_z;
    v->target_distance = cam.target_distance;
    v->time = (float)(frame % 3600000u) / 60.0f; /* the frame counter at 60 Hz */
    tl__view_info(d, &cam, v);
    return TL_OK;
}

void tl__frame_ubo_post(const tl_renderer_desc *d, tl__frame_ubo *u)
{
    memset(u, 0, sizeof *u);
    u->inv_size[0] = 1.0f / (float)d->width;
    u->inv_size[1] = 1.0f / (float)d->height;
}

void tl__frame_ubo_fill(const tl_renderer_desc *d, const tl__view *v, const float ambient[3], const uint32_t tiles[4],
                        const uint32_t light_counts[3], tl__frame_ubo *u)
{
    tl__frame_ubo_post(d, u);
    memcpy(u->view, v->view.m, sizeof u->view);
    memcpy(u->proj, v->proj.m, sizeof u->proj);
    memcpy(u->view_proj, v->view_proj.m, sizeof u->view_proj);
    const float *m = v->projection.m;
    u->depth_params[0] = m[10];
    u->depth_params[1] = m[14];
    u->depth_params[2] = m[11];
    u->depth_params[3] = tl__reversed(d->options.depth_format) ? 1.0f : 0.0f;
    u->ray_params[0] = m[0];
    u->ray_params[1] = m[5];
    u->ray_params[2] = m[8];
    u->ray_params[3] = m[9];
    memcpy(u->ambient, ambient, sizeof u->ambient);
    u->clear_depth = v->clear_depth;
    memcpy(u->tiles, tiles, sizeof u->tiles);
    u->light_counts[0] = light_counts[0];
    u->light_counts[1] = light_counts[1];
    u->light_counts[2] = light_counts[2];
}
