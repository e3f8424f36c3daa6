/* The material-model showcase (scene.h tl_scene_create_showcase): a row of spheres per material
 * model, roughness rising along each row, over a grey floor, lit by seeded point lights above. One
 * sphere mesh drawn by every sphere object through its transform. */
#include <math.h>
#include <string.h>

#include "core/alloc.h"
#include "core/log.h"
#include "scene_internal.h"

#define TL__SC_PI 3.14159265358979323846
#define TL__SC_COLUMNS 5u
#define TL__SC_ROWS ((uint32_t)TL_MATERIAL_MODEL_COUNT_)
#define TL__SC_SLICES 48u /* around */
#define TL__SC_STACKS 24u /* pole to pole */
#define TL__SC_MAX_LIGHTS 65536u

/* The sphere (radius 0.4 at the origin) and the floor quad: vertices, then indices. */
static void tl__sc_sphere(tl_vertex *v, uint32_t *idx)
{
    size_t n = 0, k = 0;
    for (uint32_t j = 0; j <= TL__SC_STACKS; j++) {
        double th = TL__SC_PI * j / TL__SC_STACKS;
        for (uint32_t i = 0; i <= TL__SC_SLICES; i++, n++) {
            double ph = 2.0 * TL__SC_PI * i / TL__SC_SLICES;
            float nx = (float)(sin(th) * cos(ph)), ny = (float)cos(th), nz = (float)(-sin(th) * sin(ph));
            v[n] = (tl_vertex){.position = {0.4f * nx, 0.4f * ny, 0.4f * nz},
                               .normal = {nx, ny, nz},
                               .uv = {(float)i / TL__SC_SLICES, (float)j / TL__SC_STACKS},
                               .tangent = {(float)-sin(ph), 0.0f, (float)-cos(ph), 1.0f}};
        }
    }
    for (uint32_t j = 0; j < TL__SC_STACKS; j++)
        for (uint32_t i = 0; i < TL__SC_SLICES; i++) {
            uint32_t a = j * (TL__SC_SLICES + 1) + i, b = a + TL__SC_SLICES + 1;
            uint32_t q[6] = {a, b, a + 1, a + 1, b, b + 1};
            for (int t = 0; t < 6; t++) idx[k++] = q[t];
        }
}

static void tl__sc_floor(tl_vertex *v, uint32_t *idx, uint32_t base)
{
    const float c[4][2] = {{-4.0f, -3.0f}, {-4.0f, 4.0f}, {4.0f, 4.0f}, {4.0f, -3.0f}};
    for (int i = 0; i < 4; i++)
        v[i] = (tl_vertex){.position = {c[i][0], 0.0f, c[i][1]}, .normal = {0, 1, 0}, .tangent = {1, 0, 0, 1}};
    const uint32_t q[6] = {0, 1, 2, 0, 2, 3};
    for (int t = 0; t < 6; t++) idx[t] = base + q[t];
}

/* Row r's model and colour, column c's roughness. */
static void tl__sc_material(uint32_t r, uint32_t c, tl_material *m)
{
    static const float colours[TL__SC_ROWS][3] = {{0.80f, 0.20f, 0.15f}, {0.95f, 0.75f, 0.20f}, {0.10f, 0.25f, 0.70f},
                                                  {0.35f, 0.05f, 0.30f}, {0.85f, 0.55f, 0.45f}, {0.20f, 0.65f, 0.30f}};
    float rough = 0.1f + 0.8f * (float)c / (float)(TL__SC_COLUMNS - 1);
    *m = (tl_material){.model = r, .gloss = 1.0f - rough, .flags = TL_MATERIAL_MICROFACET};
    memcpy(m->albedo, colours[r], sizeof m->albedo);
    for (int k = 0; k < 3; k++) m->specular[k] = 0.04f;
    m->clearcoat = 1.0f;
    m->clearcoat_roughness = 0.1f;
    for (int k = 0; k < 3; k++) m->sheen_color[k] = 0.8f;
    m->sheen_roughness = 0.5f;
    m->wrap = 0.5f;
    m->toon_steps = 4;
}

static void tl__sc_lights(tl_scene *s, uint32_t count, uint64_t seed)
{
    tl__rng rng = {seed};
    float scale = 8.0f / (float)count; /* the same light in all at any count */
    for (uint32_t i = 0; i < count; i++) {
        tl_light *l = &s->lights[i];
        *l = (tl_light){.type = TL_LIGHT_POINT, .radius = 6.0f};
        l->position[0] = tl__rng_range(&rng, -3.5f, 3.5f);
        l->position[1] = tl__rng_range(&rng, 0.8f, 3.0f);
        l->position[2] = tl__rng_range(&rng, -2.5f, 3.5f);
        for (int k = 0; k < 3; k++) l->color[k] = scale * 3.0f * tl__rng_range(&rng, 0.4f, 1.0f);
    }
}

static void tl__sc_objects(tl_scene *s, uint32_t sphere_indices)
{
    for (uint32_t r = 0; r < TL__SC_ROWS; r++)
        for (uint32_t c = 0; c < TL__SC_COLUMNS; c++) {
            uint32_t i = r * TL__SC_COLUMNS + c;
            tl_object *o = &s->objects[i];
            *o = (tl_object){.index_count = sphere_indices, .material = i};
            o->transform[0] = o->transform[5] = o->transform[10] = o->transform[15] = 1.0f;
            o->transform[12] = -2.0f + 1.0f * (float)c;
            o->transform[13] = 0.4f;
            o->transform[14] = 2.5f - 1.0f * (float)r;
            tl__sc_material(r, c, &s->materials[i]);
        }
    uint32_t f = TL__SC_ROWS * TL__SC_COLUMNS;
    s->objects[f] = (tl_object){.first_index = sphere_indices, .index_count = 6, .material = f};
    s->materials[f] = (tl_material){.albedo = {0.5f, 0.5f, 0.5f}};
}

tl_result tl_scene_create_showcase(const tl_showcase_scene_desc *desc, tl_scene **out)
{
    tl_showcase_scene_desc d = desc ? *desc : (tl_showcase_scene_desc){0};
    const tl_logger *log = &d.logger;
    if (!out) return tl__logger_fail(log, TL_ERROR_INVALID_ARGUMENT, "showcase scene: no place for the scene (out is NULL)");
    *out = NULL;
    if ((d.allocator.alloc == NULL) != (d.allocator.free == NULL))
        return tl__logger_fail(log, TL_ERROR_INVALID_ARGUMENT, "showcase scene: the allocator needs both alloc and free");
    if (d.point_lights > TL__SC_MAX_LIGHTS)
        return tl__logger_fail(log, TL_ERROR_LIMIT, "showcase scene: point_lights = %u: over the limit of %u",
                               d.point_lights, TL__SC_MAX_LIGHTS);
    uint32_t lights = d.point_lights ? d.point_lights : 8u;
    size_t sv = (TL__SC_STACKS + 1) * (TL__SC_SLICES + 1), si = (size_t)TL__SC_STACKS * TL__SC_SLICES * 6;
    size_t objects = TL__SC_ROWS * TL__SC_COLUMNS + 1;
    const tl_allocator *a = &d.allocator;
    tl_scene *s = tl__alloc_array(a, 1, sizeof *s);
    if (!s) return tl__logger_fail(log, TL_ERROR_OUT_OF_MEMORY, "showcase scene: out of memory");
    memset(s, 0, sizeof *s);
    s->allocator = *a;
    s->vertices = tl__alloc_array(a, sv + 4, sizeof(tl_vertex));
    s->indices = tl__alloc_array(a, si + 6, sizeof(uint32_t));
    s->objects = tl__alloc_array(a, objects, sizeof(tl_object));
    s->materials = tl__alloc_array(a, objects, sizeof(tl_material));
    s->lights = tl__alloc_array(a, lights, sizeof(tl_light));
    if (!s->vertices || !s->indices || !s->objects || !s->materials || !s->lights) {
        tl_scene_destroy(s);
        return tl__logger_fail(log, TL_ERROR_OUT_OF_MEMORY, "showcase scene: out of memory");
    }
    tl__sc_sphere(s->vertices, s->indices);
    tl__sc_floor(s->vertices + sv, s->indices + si, (uint32_t)sv);
    s->vertex_count = sv + 4;
    s->index_count = si + 6;
    s->object_count = s->material_count = objects;
    tl__sc_objects(s, (uint32_t)si);
    s->light_count = lights;
    tl__sc_lights(s, lights, d.seed ? d.seed : 1u);
    s->ambient[0] = s->ambient[1] = s->ambient[2] = 0.02f;
    s->camera = (tl_camera){.position = {0.0f, 3.4f, 5.0f}, .target = {0.0f, 0.1f, 0.3f}, .up = {0.0f, 1.0f, 0.0f},
                            .fov_y = (float)(TL__SC_PI / 3.0), .near_z = 0.1f, .far_z = 50.0f};
    tl_result res = tl_scene_compute_bounds(s);
    if (res != TL_OK) {
        tl_scene_destroy(s);
        return tl__logger_fail(log, res, "showcase scene: its bounds could not be computed");
    }
    *out = s;
    return TL_OK;
}
