/* The scenes of the shadow tests and thinlight-shadows-report (shadow_scenes.h). */
#include "shadow_scenes.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


typedef struct tl__builder {
    tl_vertex *v;
    uint32_t *ix;
    size_t nv, ni;
} tl__builder;

/* A quad (two triangles) from corner o along edges a and b, normal a x b. */
static void tl__quad(tl__builder *b, const float o[3], const float a[3], const float e[3])
{
    float n[3] = {a[1] * e[2] - a[2] * e[1], a[2] * e[0] - a[0] * e[2], a[0] * e[1] - a[1] * e[0]};
    float l = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; k++) n[k] /= l;
    uint32_t base = (uint32_t)b->nv;
    for (int c = 0; c < 4; c++) {
        tl_vertex *v = &b->v[b->nv++];
        memset(v, 0, sizeof *v);
        for (int k = 0; k < 3; k++) {
            v->position[k] = o[k] + ((c & 1) ? a[k] : 0.0f) + ((c & 2) ? e[k] : 0.0f);
            v->normal[k] = n[k];
        }
    }
    const uint32_t t[6] = {0, 1, 3, 0, 3, 2};
    for (int k = 0; k < 6; k++) b->ix[b->ni++] = base + t[k];
}

/* An axis-aligned box from lo to hi, faces outwards. */
static void tl__box(tl__builder *b, const float lo[3], const float hi[3])
{
    float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
    tl__quad(b, (float[3]){lo[0], lo[1], hi[2]}, (float[3]){dx, 0, 0}, (float[3]){0, dy, 0});  /* +z */
    tl__quad(b, (float[3]){hi[0], lo[1], lo[2]}, (float[3]){-dx, 0, 0}, (float[3]){0, dy, 0}); /* -z */
    tl__quad(b, (float[3]){hi[0], lo[1], hi[2]}, (float[3]){0, 0, -dz}, (float[3]){0, dy, 0}); /* +x */
    tl__quad(b, (float[3]){lo[0], lo[1], lo[2]}, (float[3]){0, 0, dz}, (float[3]){0, dy, 0});  /* -x */
    tl__quad(b, (float[3]){lo[0], hi[1], hi[2]}, (float[3]){dx, 0, 0}, (float[3]){0, 0, -dz}); /* +y */
    tl__quad(b, (float[3]){lo[0], lo[1], lo[2]}, (float[3]){dx, 0, 0}, (float[3]){0, 0, dz});  /* -y */
}

int tl_shadow_stiff_case(tl_shadow_case *c)
{
    memset(c, 0, sizeof *c);
    tl_scene *s = calloc(1, sizeof *s);
    tl__builder b = {calloc(64, sizeof(tl_vertex)), calloc(96, sizeof(uint32_t)), 0, 0};
    tl_object *objects = calloc(3, sizeof *objects);
    if (!s || !b.v || !b.ix || !objects) return 0;
    /* the plane: 40 m wide, 4 km long, to the horizon from 1.6 m above it */
    tl__quad(&b, (float[3]){-20, 0, 10}, (float[3]){40, 0, 0}, (float[3]){0, 0, -4000});
    objects[0] = (tl_object){.first_index = 0, .index_count = 6};
    tl__box(&b, (float[3]){-0.02f, 0, -6.02f}, (float[3]){0.02f, 3.0f, -5.98f}); /* the thin pole: 4 cm */
    objects[1] = (tl_object){.first_index = 6, .index_count = 36};
    tl__box(&b, (float[3]){1.0f, 0, -9.0f}, (float[3]){2.0f, 1.0f, -8.0f}); /* a box resting on the plane */
    objects[2] = (tl_object){.first_index = 42, .index_count = 36};
    s->vertices = b.v, s->vertex_count = b.nv, s->indices = b.ix, s->index_count = b.ni;
    s->objects = objects, s->object_count = 3;
    s->camera = (tl_camera){.position = {3.0f, 1.6f, 6.0f}, .target = {0.0f, 0.0f, -8.0f}, .fov_y = 1.0f,
                            .near_z = 0.01f, .far_z = 1e4f};
    c->scene = s;
    c->built = 1;
    /* a low sun (10 degrees above the plane) across the view, and a point light 1 cm above it */
    c->lights[0] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {0.5f, -0.1763f, 0.85f}, .color = {3, 3, 3},
                              .shadow = 1};
    c->lights[1] = (tl_light){.type = TL_LIGHT_POINT, .position = {0.4f, 0.01f, -7.0f}, .color = {20, 20, 20},
                              .radius = 30.0f, .shadow = 1};
    c->light_names[0] = "directional 10 deg";
    c->light_names[1] = "point 1 cm above the plane";
    c->light_count = 2;
    return tl_scene_compute_bounds(s) == TL_OK;
}

int tl_shadow_penumbra_case(tl_shadow_case *c)
{
    memset(c, 0, sizeof *c);
    tl_scene *s = calloc(1, sizeof *s);
    tl__builder b = {calloc(112, sizeof(tl_vertex)), calloc(168, sizeof(uint32_t)), 0, 0};
    tl_object *objects = calloc(4, sizeof *objects);
    if (!s || !b.v || !b.ix || !objects) return 0;
    tl__quad(&b, (float[3]){-8, 0, 8}, (float[3]){16, 0, 0}, (float[3]){0, 0, -16}); /* the floor */
    objects[0] = (tl_object){.first_index = 0, .index_count = 6};
    tl__box(&b, (float[3]){-1.6f, 0, -0.6f}, (float[3]){-0.6f, 1.0f, 0.4f}); /* a box resting on it */
    objects[1] = (tl_object){.first_index = 6, .index_count = 36};
    tl__box(&b, (float[3]){0.8f, 0, -0.1f}, (float[3]){1.0f, 1.8f, 0.1f}); /* a pole 20 cm thick, 1.8 m tall */
    objects[2] = (tl_object){.first_index = 42, .index_count = 36};
    tl__box(&b, (float[3]){-0.5f, 1.3f, 1.0f}, (float[3]){0.3f, 1.4f, 1.8f}); /* a plate floating 1.3 m up */
    objects[3] = (tl_object){.first_index = 78, .index_count = 36};
    s->vertices = b.v, s->vertex_count = b.nv, s->indices = b.ix, s->index_count = b.ni;
    s->objects = objects, s->object_count = 4;
    s->camera = (tl_camera){.position = {0.3f, 3.6f, 5.2f}, .target = {0.0f, 0.2f, 0.6f}, .fov_y = 0.9f,
                            .near_z = 0.05f, .far_z = 100.0f};
    c->scene = s;
    c->built = 1;
    /* a spot light 4 m up looking down and a point light, each a sphere 0.25 m in radius */
    c->lights[0] = (tl_light){.type = TL_LIGHT_SPOT, .position = {0.2f, 4.0f, 0.8f}, .direction = {0, -1, 0},
                              .color = {20, 20, 20}, .radius = 14.0f, .cos_inner = 0.707f, .cos_outer = 0.574f,
                              .source_radius = 0.25f, .shadow = 1};
    c->lights[1] = (tl_light){.type = TL_LIGHT_POINT, .position = {1.2f, 3.2f, 2.0f}, .color = {20, 20, 20},
                              .radius = 14.0f, .source_radius = 0.25f, .shadow = 1};
    c->light_names[0] = "spot 0.25 m";
    c->light_names[1] = "point 0.25 m";
    c->light_count = 2;
    return tl_scene_compute_bounds(s) == TL_OK;
}

int tl_shadow_spot_case(tl_shadow_case *c, int occluder)
{
    memset(c, 0, sizeof *c);
    tl_scene *s = calloc(1, sizeof *s);
    tl__builder b = {calloc(28, sizeof(tl_vertex)), calloc(42, sizeof(uint32_t)), 0, 0};
    tl_object *objects = calloc(2, sizeof *objects);
    if (!s || !b.v || !b.ix || !objects) return 0;
    tl__quad(&b, (float[3]){-30, 0, 30}, (float[3]){60, 0, 0}, (float[3]){0, 0, -60}); /* the floor, 60 m */
    objects[0] = (tl_object){.first_index = 0, .index_count = 6};
    tl__box(&b, (float[3]){-0.4f, 0, -2.8f}, (float[3]){0.4f, 0.3f, -2.0f}); /* a box in both pools */
    objects[1] = (tl_object){.first_index = 6, .index_count = 36};
    s->vertices = b.v, s->vertex_count = b.nv, s->indices = b.ix, s->index_count = b.ni;
    s->objects = objects, s->object_count = occluder ? 2 : 1;
    s->camera = (tl_camera){.position = {0.0f, 3.0f, 3.0f}, .target = {0.0f, 0.0f, -4.0f}, .fov_y = 1.1f,
                            .near_z = 0.05f, .far_z = 200.0f};
    c->scene = s;
    c->built = 1;
    /* a spot 0.6 m over the floor looking 14 degrees down, its 50-degree cone reaching from below
     * its foot to the horizon (the floor seen at grazing angles far off, at 26 degrees from the
     * vertical near the foot: far from the axis's angle), and a spot 2 m up tilted 45 degrees */
    c->lights[0] = (tl_light){.type = TL_LIGHT_SPOT, .position = {0.0f, 0.6f, 0.0f}, .direction = {0, -0.25f, -1},
                              .color = {20, 20, 20}, .radius = 40.0f, .cos_inner = 0.766f, .cos_outer = 0.643f,
                              .shadow = 1};
    c->lights[1] = (tl_light){.type = TL_LIGHT_SPOT, .position = {1.5f, 2.0f, -1.0f}, .direction = {-0.5f, -0.707f, -0.5f},
                              .color = {20, 20, 20}, .radius = 20.0f, .cos_inner = 0.866f, .cos_outer = 0.707f,
                              .shadow = 1};
    c->light_names[0] = "spot 0.6 m up, 14 deg down";
    c->light_names[1] = "spot 2 m up, 45 deg down";
    c->light_count = 2;
    return tl_scene_compute_bounds(s) == TL_OK;
}

int tl_shadow_crypt_case(tl_shadow_case *c, uint32_t detail)
{
    memset(c, 0, sizeof *c);
    if (tl_scene_create_default(&(tl_default_scene_desc){.shadows = 1, .detail = detail}, &c->scene) != TL_OK) return 0;
    tl_scene *s = c->scene;
    for (size_t i = 0; i < s->material_count; i++) memset(s->materials[i].emissive, 0, sizeof s->materials[i].emissive);
    /* the moonlight, the two braziers nearest the camera and its nearest lantern (a spot light,
     * made to cast here) */
    size_t best[3] = {SIZE_MAX, SIZE_MAX, SIZE_MAX};
    float best_d[3] = {INFINITY, INFINITY, INFINITY};
    for (size_t i = 0; i < s->light_count; i++) {
        const tl_light *l = &s->lights[i];
        if (l->type == TL_LIGHT_DIRECTIONAL && l->shadow) {
            c->light_names[c->light_count] = "moonlight";
            c->lights[c->light_count++] = *l;
            continue;
        }
        if (l->type == TL_LIGHT_POINT && !l->shadow) continue;
        float d = 0.0f;
        for (int k = 0; k < 3; k++) d += (l->position[k] - s->camera.position[k]) * (l->position[k] - s->camera.position[k]);
        int slot = l->type == TL_LIGHT_SPOT ? 2 : d < best_d[0] ? 0 : 1;
        if (slot == 0) best[1] = best[0], best_d[1] = best_d[0];
        if (d < best_d[slot]) best[slot] = i, best_d[slot] = d;
    }
    static const char *const names[3] = {"nearest brazier", "second brazier", "nearest lantern (spot)"};
    for (int k = 0; k < 3; k++) {
        if (best[k] == SIZE_MAX) continue;
        c->light_names[c->light_count] = names[k];
        c->lights[c->light_count++] = s->lights[best[k]];
    }
    return c->light_count > 0;
}

void tl_shadow_case_free(tl_shadow_case *c)
{
    if (!c->scene) return;
    if (c->built) {
        free(c->scene->vertices);
        free(c->scene->indices);
        free(c->scene->objects);
        free(c->scene);
    } else {
        tl_scene_destroy(c->scene);
    }
    c->scene = NULL;
}
