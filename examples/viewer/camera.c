/* The viewer's camera: orbit around a point (drag), fly (WASD + mouse), zoom (scroll). Yaw and
 * pitch give the direction the camera looks in; Y is up. */
#include <math.h>

#include "viewer.h"

static const float vw_pitch_limit = 1.55f; /* just short of straight up or down */

static void vw_direction(const vw_camera *c, float d[3])
{
    d[0] = cosf(c->pitch) * sinf(c->yaw);
    d[1] = sinf(c->pitch);
    d[2] = -cosf(c->pitch) * cosf(c->yaw);
}

static float vw_clampf(float v, float lo, float hi) { return v < lo ? lo : v > hi ? hi : v; }

void vw_camera_from_scene(vw_camera *c, const tl_camera *s, float extent)
{
    float d[3] = {s->target[0] - s->position[0], s->target[1] - s->position[1], s->target[2] - s->position[2]};
    float len = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(len > 1e-6f)) { d[0] = 0; d[1] = 0; d[2] = -1; len = 1; }
    c->mode = VW_CAMERA_ORBIT;
    c->scene = *s;
    c->moved = 0;
    c->distance = len;
    c->pitch = vw_clampf(asinf(vw_clampf(d[1] / len, -1, 1)), -vw_pitch_limit, vw_pitch_limit);
    c->yaw = atan2f(d[0], -d[2]);
    for (int i = 0; i < 3; i++) { c->target[i] = s->target[i]; c->eye[i] = s->position[i]; }
    c->speed = extent > 0 ? extent * 0.15f : 2.0f;
    c->fov_y = s->fov_y;
    c->near_z = s->near_z;
    c->far_z = s->far_z;
}

void vw_camera_get(vw_camera *c, tl_camera *out)
{
    if (!c->moved) { /* bit for bit the scene's view, as thinlight-render renders it */
        *out = c->scene;
        return;
    }
    float d[3];
    vw_direction(c, d);
    if (c->mode == VW_CAMERA_ORBIT)
        for (int i = 0; i < 3; i++) c->eye[i] = c->target[i] - d[i] * c->distance;
    for (int i = 0; i < 3; i++) {
        out->position[i] = c->eye[i];
        out->target[i] = c->eye[i] + d[i];
        out->up[i] = i == 1 ? 1.0f : 0.0f;
    }
    out->fov_y = c->fov_y;
    out->near_z = c->near_z;
    out->far_z = c->far_z;
}

/* Dragging right turns the view around the centre to the right; up lifts the eye. */
void vw_camera_orbit(vw_camera *c, float dx, float dy)
{
    c->moved = 1;
    c->yaw -= dx * 0.008f;
    c->pitch = vw_clampf(c->pitch - dy * 0.008f, -vw_pitch_limit, vw_pitch_limit);
}

void vw_camera_look(vw_camera *c, float dx, float dy)
{
    c->moved = 1;
    c->yaw += dx * 0.004f;
    c->pitch = vw_clampf(c->pitch - dy * 0.004f, -vw_pitch_limit, vw_pitch_limit);
}

void vw_camera_zoom(vw_camera *c, float steps)
{
    c->moved = 1;
    if (c->mode == VW_CAMERA_ORBIT) {
        c->distance = vw_clampf(c->distance * powf(0.85f, steps), 0.05f, 1e5f);
        return;
    }
    float d[3];
    vw_direction(c, d);
    for (int i = 0; i < 3; i++) c->eye[i] += d[i] * steps * c->speed * 0.25f;
}

/* move: right, up, forward in [-1, 1]. */
void vw_camera_fly(vw_camera *c, const float move[3], float dt)
{
    c->moved = 1;
    float d[3], right[3];
    vw_direction(c, d);
    float h = sqrtf(d[0] * d[0] + d[2] * d[2]);
    right[0] = h > 0 ? -d[2] / h : 1;
    right[1] = 0;
    right[2] = h > 0 ? d[0] / h : 0;
    for (int i = 0; i < 3; i++)
        c->eye[i] += (right[i] * move[0] + (i == 1) * move[1] + d[i] * move[2]) * c->speed * dt;
}

/* Keeps the eye where it is: flying starts from the orbit's eye, orbiting goes round the point
 * the camera looked at, as far away as before. */
void vw_camera_set_mode(vw_camera *c, vw_camera_mode mode)
{
    if (mode == c->mode) return;
    tl_camera now;
    vw_camera_get(c, &now);
    if (mode == VW_CAMERA_ORBIT) {
        float d[3];
        vw_direction(c, d);
        for (int i = 0; i < 3; i++) c->target[i] = c->eye[i] + d[i] * c->distance;
    }
    c->mode = mode;
}
