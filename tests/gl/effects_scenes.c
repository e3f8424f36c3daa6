/* Scenes of quads for the screen-space effects' tests (effects_scenes.h). */
#include "effects_scenes.h"

#include <math.h>
#include <string.h>

/* A quad o + a du + b dv, a, b in [0, 1]; its normal du x dv faces the camera. */
static void quad(quads *q, const float o[3], const float du[3], const float dv[3])
{
    float n[3] = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
    float l = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    uint32_t b = (uint32_t)q->nv;
    for (int i = 0; i < 4; i++) {
        float a = (float)(i == 1 || i == 2), c = (float)(i >= 2);
        tl_vertex *x = &q->v[q->nv++];
        memset(x, 0, sizeof *x);
        for (int k = 0; k < 3; k++) {
            x->position[k] = o[k] + a * du[k] + c * dv[k];
            x->normal[k] = n[k] / l;
        }
    }
    const uint32_t t[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 6; i++) q->idx[q->ni++] = b + t[i];
}

static void quads_finish(quads *q, const tl_camera *cam)
{
    q->obj[0] = (tl_object){0, (uint32_t)q->ni, 0, {0}, {-1000, -1000, -1000}, {1000, 1000, 1000}, TL_PRIMITIVE_TRIANGLES};
    const float id[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    memcpy(q->obj[0].transform, id, sizeof id);
    q->mat[0] = (tl_material){.alpha = 1.0f, .albedo = {0.5f, 0.5f, 0.5f}};
    q->s.vertices = q->v;
    q->s.vertex_count = q->nv;
    q->s.indices = q->idx;
    q->s.index_count = q->ni;
    q->s.objects = q->obj;
    q->s.object_count = 1;
    q->s.materials = q->mat;
    q->s.material_count = 1;
    q->s.ambient[0] = q->s.ambient[1] = q->s.ambient[2] = 1.0f;
    q->s.camera = *cam;
}

void plane_scene(quads *q)
{
    memset(q, 0, sizeof *q);
    quad(q, (float[3]){-100, 0, 100}, (float[3]){200, 0, 0}, (float[3]){0, 0, -200});
    quads_finish(q, &(tl_camera){{0, 2, 6}, {0, 0, 0}, {0, 1, 0}, 1.0f, 0.1f, 0.0f});
}

void corner_scene(quads *q)
{
    memset(q, 0, sizeof *q);
    quad(q, (float[3]){-40, 0, 40}, (float[3]){80, 0, 0}, (float[3]){0, 0, -42});
    quad(q, (float[3]){-40, 0, -2}, (float[3]){80, 0, 0}, (float[3]){0, 40, 0});
    quads_finish(q, &(tl_camera){{0, 3, 6}, {0, 0, -2}, {0, 1, 0}, 1.0f, 0.1f, 0.0f});
}

void wall_scene(quads *q, float dist)
{
    memset(q, 0, sizeof *q);
    quad(q, (float[3]){-4 * dist, -4 * dist, -dist}, (float[3]){8 * dist, 0, 0}, (float[3]){0, 8 * dist, 0});
    quads_finish(q, &(tl_camera){{0, 0, 0}, {0, 0, -dist}, {0, 1, 0}, 1.0f, 0.1f, 0.0f});
}

int project(const tl_camera *c, uint32_t w, uint32_t h, const double p[3], int *x, int *y)
{
    double f[3], s[3], u[3], d[3];
    for (int k = 0; k < 3; k++) f[k] = (double)c->target[k] - c->position[k];
    double fl = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int k = 0; k < 3; k++) f[k] /= fl;
    s[0] = -f[2], s[1] = 0.0, s[2] = f[0]; /* f x (0, 1, 0) */
    double sl = sqrt(s[0] * s[0] + s[2] * s[2]);
    s[0] /= sl, s[2] /= sl;
    u[0] = s[1] * f[2] - s[2] * f[1], u[1] = s[2] * f[0] - s[0] * f[2], u[2] = s[0] * f[1] - s[1] * f[0];
    for (int k = 0; k < 3; k++) d[k] = p[k] - c->position[k];
    double vx = s[0] * d[0] + s[1] * d[1] + s[2] * d[2], vy = u[0] * d[0] + u[1] * d[1] + u[2] * d[2];
    double vz = f[0] * d[0] + f[1] * d[1] + f[2] * d[2]; /* distance along the view axis */
    double t = tan(0.5 * c->fov_y), aspect = (double)w / h;
    double nx = vx / (vz * t * aspect), ny = vy / (vz * t);
    *x = (int)floor((nx * 0.5 + 0.5) * w);
    *y = (int)floor((ny * 0.5 + 0.5) * h);
    return vz > 0.0 && *x >= 0 && *y >= 0 && *x < (int)w && *y < (int)h;
}
