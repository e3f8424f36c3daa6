/* The renderer tests' room scene (render_room.h). */
#include "render_room.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void add_quad(test_scene *t, size_t *nv, size_t *ni, const float o[3], const float du[3], const float dv[3])
{
    float n[3] = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
    float l = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    uint32_t b = (uint32_t)*nv;
    for (int i = 0; i < 4; i++) {
        float a = (float)(i == 1 || i == 2), c = (float)(i >= 2);
        tl_vertex *x = &t->v[(*nv)++];
        memset(x, 0, sizeof *x);
        for (int k = 0; k < 3; k++) {
            x->position[k] = o[k] + a * du[k] + c * dv[k];
            x->normal[k] = n[k] / l;
        }
        x->uv[0] = a;
        x->uv[1] = c;
    }
    const uint32_t q[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 6; i++) t->idx[(*ni)++] = b + q[i];
}

/* Room [-10,10] x [0,10] x [-10,10] seen from inside, plus a box [-1,1] x [0,2] x [-1,1]. */
void build_room(test_scene *t)
{
    memset(t, 0, sizeof *t);
    size_t nv = 0, ni = 0;
    const float S = 10.0f, H = 10.0f;
    /* faces wound so that their normals point into the room */
    add_quad(t, &nv, &ni, (float[3]){-S, 0, S}, (float[3]){2 * S, 0, 0}, (float[3]){0, 0, -2 * S}); /* floor, +Y */
    add_quad(t, &nv, &ni, (float[3]){-S, H, -S}, (float[3]){2 * S, 0, 0}, (float[3]){0, 0, 2 * S}); /* ceiling, -Y */
    add_quad(t, &nv, &ni, (float[3]){-S, 0, -S}, (float[3]){2 * S, 0, 0}, (float[3]){0, H, 0});     /* back, +Z */
    add_quad(t, &nv, &ni, (float[3]){S, 0, S}, (float[3]){-2 * S, 0, 0}, (float[3]){0, H, 0});      /* front, -Z */
    add_quad(t, &nv, &ni, (float[3]){-S, 0, S}, (float[3]){0, 0, -2 * S}, (float[3]){0, H, 0});     /* left, +X */
    add_quad(t, &nv, &ni, (float[3]){S, 0, -S}, (float[3]){0, 0, 2 * S}, (float[3]){0, H, 0});      /* right, -X */
    size_t room_indices = ni;
    /* box: outward faces */
    const float B = 1.0f, BH = 2.0f;
    add_quad(t, &nv, &ni, (float[3]){-B, BH, B}, (float[3]){2 * B, 0, 0}, (float[3]){0, 0, -2 * B}); /* top */
    add_quad(t, &nv, &ni, (float[3]){-B, 0, B}, (float[3]){2 * B, 0, 0}, (float[3]){0, BH, 0});      /* +Z */
    add_quad(t, &nv, &ni, (float[3]){B, 0, -B}, (float[3]){-2 * B, 0, 0}, (float[3]){0, BH, 0});     /* -Z */
    add_quad(t, &nv, &ni, (float[3]){B, 0, B}, (float[3]){0, 0, -2 * B}, (float[3]){0, BH, 0});      /* +X */
    add_quad(t, &nv, &ni, (float[3]){-B, 0, -B}, (float[3]){0, 0, 2 * B}, (float[3]){0, BH, 0});     /* -X */
    const float id[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    t->obj[0] = (tl_object){0, (uint32_t)room_indices, 0, {0}, {-S, 0, -S}, {S, H, S}, TL_PRIMITIVE_TRIANGLES};
    t->obj[1] = (tl_object){(uint32_t)room_indices, (uint32_t)(ni - room_indices), 1, {0}, {-B, 0, -B}, {B, BH, B}, TL_PRIMITIVE_TRIANGLES};
    memcpy(t->obj[0].transform, id, sizeof id);
    memcpy(t->obj[1].transform, id, sizeof id);
    const tl_material plain = {.alpha = 1.0f};
    t->mat[0] = plain;
    t->mat[1] = plain;
    t->mat[0].albedo[0] = t->mat[0].albedo[1] = t->mat[0].albedo[2] = 0.7f;
    t->mat[0].specular[0] = t->mat[0].specular[1] = t->mat[0].specular[2] = 0.04f;
    t->mat[0].gloss = 0.25f;
    snprintf(t->mat[0].name, sizeof t->mat[0].name, "wall");
    t->mat[1].albedo[0] = 0.8f;
    t->mat[1].albedo[1] = 0.2f;
    t->mat[1].albedo[2] = 0.1f;
    t->mat[1].specular[0] = t->mat[1].specular[1] = t->mat[1].specular[2] = 0.05f;
    t->mat[1].gloss = 0.8f;
    snprintf(t->mat[1].name, sizeof t->mat[1].name, "box");
    t->s.vertices = t->v;
    t->s.vertex_count = nv;
    t->s.indices = t->idx;
    t->s.index_count = ni;
    t->s.objects = t->obj;
    t->s.object_count = 2;
    t->s.materials = t->mat;
    t->s.material_count = 2;
    t->s.lights = t->lights;
    t->s.camera = (tl_camera){{0, 3, 8}, {0, 1.5f, 0}, {0, 1, 0}, 1.0f, 0.1f, 100.0f};
}
