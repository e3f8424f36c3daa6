/* Tests of the built-in crypt scene (pure C, no GL): counts, determinism, geometric validity,
 * light placement, limits, allocator use and the feature summary. */
#include <float.h>
#include <stdint.h>

#include "thinlight/scene.h"
#include "tl_test.h"

/* ---- helpers ------------------------------------------------------------------------------- */

static tl_scene *make(const tl_default_scene_desc *d)
{
    tl_scene *s = NULL;
    tl_result r = tl_scene_create_default(d, &s);
    TL_CHECK_EQ_U(r, TL_OK);
    TL_CHECK(r != TL_OK || s != NULL);
    return s;
}

static size_t count_type(const tl_scene *s, tl_light_type t)
{
    size_t n = 0;
    for (size_t i = 0; i < s->light_count; i++) n += s->lights[i].type == t;
    return n;
}

static double len3(const float v[3]) { return sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]); }

static void cross3(double o[3], const double a[3], const double b[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* Hall plan (default_scene.c): x in [-7.5, 7.5], z in [-20, 20] plus the apse to z = -22.5,
 * floor 0, vault crown 7.5; columns at x = +-2.5, z = -15 .. 15 step 5. */
#define HALL_X 7.5
#define HALL_Z0 -20.0
#define HALL_Z1 20.0
#define CROWN 7.5

static int near_column(double x, double z, double clear)
{
    for (int side = -1; side <= 1; side += 2)
        for (int k = 1; k < 8; k++)
            if (fabs(x - side * 2.5) < clear && fabs(z - (-20.0 + 5.0 * k)) < clear) return 1;
    return 0;
}

/* A counting allocator: every block carries its size; can be told to fail the Nth call. */
typedef struct counting {
    size_t calls, live, live_bytes, peak_bytes;
    size_t fail_at; /* SIZE_MAX: never */
    int foreign_free;
} counting;

static void *c_alloc(size_t size, void *user)
{
    counting *c = user;
    size_t call = c->calls++;
    if (call == c->fail_at) return NULL;
    size_t *p = malloc(size + 16);
    if (!p) return NULL;
    p[0] = size;
    p[1] = 0x5ce9e5ce9e5ce9e5ull & SIZE_MAX;
    c->live++;
    c->live_bytes += size;
    if (c->live_bytes > c->peak_bytes) c->peak_bytes = c->live_bytes;
    return (char *)p + 16;
}

static void c_free(void *ptr, void *user)
{
    counting *c = user;
    if (!ptr) return;
    size_t *p = (size_t *)((char *)ptr - 16);
    if (p[1] != (0x5ce9e5ce9e5ce9e5ull & SIZE_MAX)) {
        c->foreign_free++;
        return;
    }
    p[1] = 0;
    c->live--;
    c->live_bytes -= p[0];
    free(p);
}

/* ---- cases --------------------------------------------------------------------------------- */

TL_TEST(scene_default_counts)
{
    tl_scene *s = make(NULL);
    if (!s) return;
    size_t tris = s->index_count / 3;
    printf("default: %zu triangles, %zu vertices, %zu objects, %zu materials, %zu textures, %zu lights\n",
           tris, s->vertex_count, s->object_count, s->material_count, s->texture_count, s->light_count);
    TL_CHECK(tris >= 100000);
    TL_CHECK(s->object_count >= 100);
    TL_CHECK_EQ_U(s->index_count % 3, 0);
    TL_CHECK_EQ_U(count_type(s, TL_LIGHT_POINT), 64);
    TL_CHECK_EQ_U(count_type(s, TL_LIGHT_SPOT), 8);
    TL_CHECK_EQ_U(count_type(s, TL_LIGHT_DIRECTIONAL), 1);
    TL_CHECK_EQ_U(s->light_count, 73);
    TL_CHECK(s->material_count >= 8);
    TL_CHECK(s->texture_count >= 4);
    tl_scene_destroy(s);

    tl_scene *t = make(&(tl_default_scene_desc){.point_lights = 1000, .spot_lights = 3, .no_directional = 1});
    if (!t) return;
    TL_CHECK_EQ_U(count_type(t, TL_LIGHT_POINT), 1000);
    TL_CHECK_EQ_U(count_type(t, TL_LIGHT_SPOT), 3);
    TL_CHECK_EQ_U(count_type(t, TL_LIGHT_DIRECTIONAL), 0);
    TL_CHECK_EQ_U(t->light_count, 1003);
    tl_scene_destroy(t);

    /* spot lights default to an eighth of the point lights */
    tl_scene *u = make(&(tl_default_scene_desc){.point_lights = 4096, .detail = 1});
    if (!u) return;
    TL_CHECK_EQ_U(count_type(u, TL_LIGHT_SPOT), 512);
    tl_scene_destroy(u);
}

TL_TEST(scene_default_detail_levels)
{
    size_t prev_tris = 0, objects = 0;
    for (uint32_t detail = 1; detail <= 8; detail++) {
        tl_scene *s = make(&(tl_default_scene_desc){.detail = detail});
        if (!s) return;
        size_t tris = s->index_count / 3;
        printf("detail %u: %zu triangles, %zu vertices, %zu objects\n", detail, tris, s->vertex_count,
               s->object_count);
        TL_CHECK(tris > prev_tris);
        if (detail == 1) objects = s->object_count;
        TL_CHECK_EQ_U(s->object_count, objects); /* detail changes tessellation, not the layout */
        if (detail == 4) TL_CHECK(tris >= 100000);
        prev_tris = tris;
        tl_scene_destroy(s);
    }
    tl_scene *s = NULL;
    TL_CHECK_EQ_U(tl_scene_create_default(&(tl_default_scene_desc){.detail = 9}, &s), TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(s == NULL);
    /* detail 0 is the default, 4 */
    tl_scene *a = make(&(tl_default_scene_desc){.detail = 0});
    tl_scene *b = make(&(tl_default_scene_desc){.detail = 4});
    if (a && b) TL_CHECK_EQ_U(a->index_count, b->index_count);
    tl_scene_destroy(a);
    tl_scene_destroy(b);
}

TL_TEST(scene_default_deterministic)
{
    tl_scene *a = make(&(tl_default_scene_desc){.seed = 7, .point_lights = 200});
    tl_scene *b = make(&(tl_default_scene_desc){.seed = 7, .point_lights = 200});
    tl_scene *c = make(&(tl_default_scene_desc){.seed = 8, .point_lights = 200});
    if (!a || !b || !c) goto done;
    TL_CHECK_EQ_U(a->vertex_count, b->vertex_count);
    TL_CHECK_EQ_U(a->index_count, b->index_count);
    TL_CHECK_EQ_U(a->light_count, b->light_count);
    TL_CHECK(memcmp(a->vertices, b->vertices, a->vertex_count * sizeof(tl_vertex)) == 0);
    TL_CHECK(memcmp(a->indices, b->indices, a->index_count * sizeof(uint32_t)) == 0);
    TL_CHECK(memcmp(a->objects, b->objects, a->object_count * sizeof(tl_object)) == 0);
    TL_CHECK(memcmp(a->materials, b->materials, a->material_count * sizeof(tl_material)) == 0);
    TL_CHECK(memcmp(a->lights, b->lights, a->light_count * sizeof(tl_light)) == 0);
    for (size_t t = 0; t < a->texture_count; t++)
        TL_CHECK(memcmp(a->textures[t].rgba, b->textures[t].rgba,
                        (size_t)a->textures[t].width * a->textures[t].height * 4) == 0);
    /* another seed moves the lights, not the geometry */
    TL_CHECK_EQ_U(a->vertex_count, c->vertex_count);
    TL_CHECK(memcmp(a->vertices, c->vertices, a->vertex_count * sizeof(tl_vertex)) == 0);
    TL_CHECK_EQ_U(a->light_count, c->light_count);
    TL_CHECK(memcmp(a->lights, c->lights, a->light_count * sizeof(tl_light)) != 0);
    size_t moved = 0;
    for (size_t i = 0; i < a->light_count; i++)
        moved += memcmp(a->lights[i].position, c->lights[i].position, sizeof(float) * 3) != 0;
    TL_CHECK(moved > a->light_count / 2);
    /* seed 0 is the default, 1 */
    {
        tl_scene *d0 = make(&(tl_default_scene_desc){.seed = 0, .detail = 1});
        tl_scene *d1 = make(&(tl_default_scene_desc){.seed = 1, .detail = 1});
        if (d0 && d1) TL_CHECK(memcmp(d0->lights, d1->lights, d0->light_count * sizeof(tl_light)) == 0);
        tl_scene_destroy(d0);
        tl_scene_destroy(d1);
    }
done:
    tl_scene_destroy(a);
    tl_scene_destroy(b);
    tl_scene_destroy(c);
}

static void check_geometry(const tl_scene *s)
{
    size_t bad_index = 0, bad_normal = 0, bad_tangent = 0, nonfinite = 0, degenerate = 0, winding = 0;
    for (size_t v = 0; v < s->vertex_count; v++) {
        const tl_vertex *x = &s->vertices[v];
        const float *f = (const float *)x;
        for (size_t k = 0; k < sizeof(tl_vertex) / sizeof(float); k++) nonfinite += !isfinite(f[k]);
        if (fabs(len3(x->normal) - 1.0) > 1e-4) bad_normal++;
        if (fabs(len3(x->tangent) - 1.0) > 1e-4 || fabs(fabs(x->tangent[3]) - 1.0) > 0) bad_tangent++;
        double tn = x->tangent[0] * x->normal[0] + x->tangent[1] * x->normal[1] + x->tangent[2] * x->normal[2];
        if (fabs(tn) > 1e-3) bad_tangent++;
        for (int k = 0; k < 3; k++) {
            if (x->position[k] < s->bounds_min[k] || x->position[k] > s->bounds_max[k]) bad_index++;
        }
    }
    for (size_t i = 0; i + 2 < s->index_count; i += 3) {
        uint32_t i0 = s->indices[i], i1 = s->indices[i + 1], i2 = s->indices[i + 2];
        if (i0 >= s->vertex_count || i1 >= s->vertex_count || i2 >= s->vertex_count) {
            bad_index++;
            continue;
        }
        const tl_vertex *a = &s->vertices[i0], *b = &s->vertices[i1], *c = &s->vertices[i2];
        double e1[3], e2[3], n[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = (double)b->position[k] - a->position[k];
            e2[k] = (double)c->position[k] - a->position[k];
        }
        cross3(n, e1, e2);
        double area2 = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (!(area2 > 1e-10)) {
            degenerate++;
            continue;
        }
        /* counter-clockwise seen from the side the vertex normals point to */
        double d = 0.0;
        for (int k = 0; k < 3; k++) d += n[k] * ((double)a->normal[k] + b->normal[k] + c->normal[k]);
        if (!(d > 0.0)) winding++;
    }
    TL_CHECK_EQ_U(nonfinite, 0);
    TL_CHECK_EQ_U(bad_index, 0);
    TL_CHECK_EQ_U(bad_normal, 0);
    TL_CHECK_EQ_U(bad_tangent, 0);
    TL_CHECK_EQ_U(degenerate, 0);
    TL_CHECK_EQ_U(winding, 0);

    /* objects: consecutive index ranges covering the whole buffer, identity transforms, valid
     * materials, every referenced vertex inside tight bounds */
    size_t next = 0, outside = 0, loose = 0;
    for (size_t o = 0; o < s->object_count; o++) {
        const tl_object *ob = &s->objects[o];
        TL_CHECK_EQ_U(ob->first_index, next);
        TL_CHECK(ob->index_count > 0 && ob->index_count % 3 == 0);
        TL_CHECK(ob->material < s->material_count);
        next = (size_t)ob->first_index + ob->index_count;
        for (int k = 0; k < 16; k++) TL_CHECK(ob->transform[k] == ((k % 5 == 0) ? 1.0f : 0.0f));
        float lo[3] = {FLT_MAX, FLT_MAX, FLT_MAX}, hi[3] = {-FLT_MAX, -FLT_MAX, -FLT_MAX};
        for (size_t i = ob->first_index; i < next && i < s->index_count; i++) {
            const float *p = s->vertices[s->indices[i] < s->vertex_count ? s->indices[i] : 0].position;
            for (int k = 0; k < 3; k++) {
                if (p[k] < ob->bounds_min[k] || p[k] > ob->bounds_max[k]) outside++;
                if (p[k] < lo[k]) lo[k] = p[k];
                if (p[k] > hi[k]) hi[k] = p[k];
            }
        }
        for (int k = 0; k < 3; k++)
            if (lo[k] != ob->bounds_min[k] || hi[k] != ob->bounds_max[k]) loose++;
        for (int k = 0; k < 3; k++)
            TL_CHECK(ob->bounds_min[k] >= s->bounds_min[k] && ob->bounds_max[k] <= s->bounds_max[k]);
    }
    TL_CHECK_EQ_U(next, s->index_count);
    TL_CHECK_EQ_U(outside, 0);
    TL_CHECK_EQ_U(loose, 0);
}

TL_TEST(scene_default_geometry_valid)
{
    static const uint32_t details[] = {1, 4, 8};
    for (size_t i = 0; i < sizeof details / sizeof details[0]; i++) {
        tl_scene *s = make(&(tl_default_scene_desc){.detail = details[i]});
        if (!s) return;
        check_geometry(s);
        /* the hall is about 15 x 40 x 7.5 m */
        TL_CHECK(s->bounds_min[1] > -0.2f && s->bounds_min[1] < 0.0f + 1e-6f);
        TL_CHECK(s->bounds_max[1] > 7.4f && s->bounds_max[1] < 8.0f);
        TL_CHECK(s->bounds_min[0] < -7.5f && s->bounds_min[0] > -9.0f);
        TL_CHECK(s->bounds_max[0] > 7.5f && s->bounds_max[0] < 9.0f);
        TL_CHECK(s->bounds_min[2] < -22.0f && s->bounds_max[2] > 20.0f);
        tl_scene_destroy(s);
    }
}

/* Closed convex props (single boxes and spheres): every face looks away from the centre. */
TL_TEST(scene_default_convex_props_outward)
{
    tl_scene *s = make(NULL);
    if (!s) return;
    size_t checked = 0, inward = 0, spheres = 0;
    for (size_t o = 0; o < s->object_count; o++) {
        const tl_object *ob = &s->objects[o];
        double c[3], ext[3];
        for (int k = 0; k < 3; k++) {
            c[k] = 0.5 * ((double)ob->bounds_min[k] + ob->bounds_max[k]);
            ext[k] = (double)ob->bounds_max[k] - ob->bounds_min[k];
        }
        int is_box = ob->index_count == 36;
        int is_sphere = fabs(ext[0] - ext[1]) < 1e-4 && fabs(ext[1] - ext[2]) < 1e-4 && ob->index_count > 36;
        if (is_sphere) {
            double r = 0.5 * ext[0];
            for (size_t i = ob->first_index; i < (size_t)ob->first_index + ob->index_count; i++) {
                const float *p = s->vertices[s->indices[i]].position;
                double d = sqrt((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) +
                                (p[2] - c[2]) * (p[2] - c[2]));
                if (fabs(d - r) > 1e-4) is_sphere = 0;
            }
            spheres += is_sphere;
        }
        if (!is_box && !is_sphere) continue;
        for (size_t i = ob->first_index; i < (size_t)ob->first_index + ob->index_count; i += 3) {
            const float *a = s->vertices[s->indices[i]].position, *b = s->vertices[s->indices[i + 1]].position,
                        *cc = s->vertices[s->indices[i + 2]].position;
            double e1[3], e2[3], n[3], d = 0;
            for (int k = 0; k < 3; k++) {
                e1[k] = (double)b[k] - a[k];
                e2[k] = (double)cc[k] - a[k];
            }
            cross3(n, e1, e2);
            for (int k = 0; k < 3; k++) d += n[k] * ((a[k] + b[k] + cc[k]) / 3.0 - c[k]);
            if (!(d > 0)) inward++;
            checked++;
        }
    }
    TL_CHECK(spheres >= 8);
    TL_CHECK(checked > 1000);
    TL_CHECK_EQ_U(inward, 0);
    tl_scene_destroy(s);
}

/* Everything stands in the hall, or in a recess (niche, apse) that opens onto it: an object
 * wholly behind the walls must lie inside the bounds of one that reaches the hall. */
TL_TEST(scene_default_objects_reachable)
{
    tl_scene *s = make(NULL);
    if (!s) return;
    const float lo[3] = {-(float)HALL_X, -1.0f, (float)HALL_Z0}, hi[3] = {(float)HALL_X, 10.0f, (float)HALL_Z1};
    size_t hidden = 0, recessed = 0;
    for (size_t o = 0; o < s->object_count; o++) {
        const tl_object *a = &s->objects[o];
        int touches = 1;
        for (int k = 0; k < 3; k++) touches &= a->bounds_max[k] >= lo[k] && a->bounds_min[k] <= hi[k];
        /* touching the boundary plane from outside only counts for the recess itself */
        if (touches) continue;
        recessed++;
        int held = 0;
        for (size_t q = 0; q < s->object_count && !held; q++) {
            const tl_object *b = &s->objects[q];
            if (q == o) continue;
            int b_touches = 1, contains = 1;
            for (int k = 0; k < 3; k++) {
                b_touches &= b->bounds_max[k] >= lo[k] && b->bounds_min[k] <= hi[k];
                contains &= a->bounds_min[k] >= b->bounds_min[k] - 0.05f && a->bounds_max[k] <= b->bounds_max[k] + 0.05f;
            }
            held = b_touches && contains;
        }
        if (!held) {
            fprintf(stderr, "object %zu (material %s) is walled in: [%g %g %g] - [%g %g %g]\n", o,
                    s->materials[a->material].name, a->bounds_min[0], a->bounds_min[1], a->bounds_min[2],
                    a->bounds_max[0], a->bounds_max[1], a->bounds_max[2]);
            hidden++;
        }
    }
    TL_CHECK(recessed >= 9); /* the urns in the niches and the altar in the apse */
    TL_CHECK_EQ_U(hidden, 0);
    tl_scene_destroy(s);
}

static void check_lights(const tl_scene *s)
{
    size_t bad = 0, in_column = 0;
    for (size_t i = 0; i < s->light_count; i++) {
        const tl_light *l = &s->lights[i];
        TL_CHECK_FINITE3(l->color);
        if (!(l->color[0] > 0 && l->color[1] > 0 && l->color[2] > 0)) bad++;
        if (l->type == TL_LIGHT_DIRECTIONAL) {
            if (fabs(len3(l->direction) - 1.0) > 1e-4 || !(l->direction[1] < 0)) bad++;
            continue;
        }
        TL_CHECK_FINITE3(l->position);
        const float *p = l->position;
        if (!(fabs(p[0]) < HALL_X && p[2] > HALL_Z0 && p[2] < HALL_Z1)) bad++;
        if (!(p[1] >= 0.3f - 1e-6f && p[1] <= CROWN - 0.5 + 1e-6)) bad++;
        if (near_column(p[0], p[2], 0.5)) in_column++;
        if (!(l->radius > 0.0f) || !isfinite(l->radius)) bad++;
        if (l->type == TL_LIGHT_SPOT) {
            if (fabs(len3(l->direction) - 1.0) > 1e-4) bad++;
            if (!(l->direction[1] < -0.85f)) bad++; /* mostly downward */
            if (!(l->cos_outer > 0.0f && l->cos_outer < l->cos_inner && l->cos_inner <= 1.0f)) bad++;
        } else if (l->type != TL_LIGHT_POINT) {
            bad++;
        }
    }
    TL_CHECK_EQ_U(bad, 0);
    TL_CHECK_EQ_U(in_column, 0);
}

TL_TEST(scene_default_lights_inside)
{
    static const uint32_t counts[] = {8, 64, 1024, 4096};
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++) {
        for (uint64_t seed = 1; seed <= 3; seed++) {
            tl_scene *s = make(&(tl_default_scene_desc){.point_lights = counts[i], .seed = seed, .detail = 1});
            if (!s) return;
            check_lights(s);
            /* the lights cover the whole hall, not one corner */
            double zmin = 1e9, zmax = -1e9, xmin = 1e9, xmax = -1e9, rsum = 0;
            size_t np = 0;
            for (size_t k = 0; k < s->light_count; k++) {
                const tl_light *l = &s->lights[k];
                if (l->type != TL_LIGHT_POINT) continue;
                zmin = fmin(zmin, l->position[2]);
                zmax = fmax(zmax, l->position[2]);
                xmin = fmin(xmin, l->position[0]);
                xmax = fmax(xmax, l->position[0]);
                rsum += l->radius;
                np++;
            }
            TL_CHECK(zmax - zmin > 25.0 && xmax - xmin > 8.0);
            double rmean = rsum / (double)np;
            TL_CHECK(rmean >= 1.5 && rmean <= 7.0);
            if (counts[i] == 4096) TL_CHECK(rmean < 3.5); /* 4096 lights must not all cover the screen */
            tl_scene_destroy(s);
        }
    }
}

TL_TEST(scene_light_count_limit)
{
    counting c = {.fail_at = SIZE_MAX};
    tl_allocator a = {c_alloc, c_free, &c};
    tl_scene *s = (tl_scene *)(uintptr_t)1;
    TL_CHECK_EQ_U(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 65537, .allocator = a}, &s),
                  TL_ERROR_LIMIT);
    TL_CHECK(s == NULL);
    TL_CHECK_EQ_U(tl_scene_create_default(&(tl_default_scene_desc){.spot_lights = 65537, .allocator = a}, &s),
                  TL_ERROR_LIMIT);
    TL_CHECK_EQ_U(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = UINT32_MAX, .allocator = a}, &s),
                  TL_ERROR_LIMIT);
    TL_CHECK_EQ_U(c.calls, 0);
    TL_CHECK_EQ_U(c.live, 0);

    /* the largest count is accepted */
    s = make(&(tl_default_scene_desc){.point_lights = 65536, .detail = 1, .allocator = a});
    if (s) {
        TL_CHECK_EQ_U(count_type(s, TL_LIGHT_POINT), 65536);
        TL_CHECK_EQ_U(count_type(s, TL_LIGHT_SPOT), 8192);
        check_lights(s);
        tl_scene_destroy(s);
    }
    TL_CHECK_EQ_U(c.live, 0);

    /* zero means the default */
    s = make(&(tl_default_scene_desc){.point_lights = 0, .detail = 1});
    if (s) {
        TL_CHECK_EQ_U(count_type(s, TL_LIGHT_POINT), 64);
        TL_CHECK_EQ_U(count_type(s, TL_LIGHT_SPOT), 8);
        tl_scene_destroy(s);
    }
    s = make(&(tl_default_scene_desc){.point_lights = 1, .detail = 1});
    if (s) {
        TL_CHECK_EQ_U(count_type(s, TL_LIGHT_POINT), 1);
        TL_CHECK_EQ_U(count_type(s, TL_LIGHT_SPOT), 0);
        tl_scene_destroy(s);
    }
}

TL_TEST(scene_allocator_honoured)
{
    counting c = {.fail_at = SIZE_MAX};
    tl_allocator a = {c_alloc, c_free, &c};
    tl_scene *s = make(&(tl_default_scene_desc){.detail = 1, .allocator = a});
    size_t allocations = c.calls;
    TL_CHECK(allocations >= 5);
    TL_CHECK(c.live == allocations);
    if (s) {
        TL_CHECK(s->allocator.alloc == c_alloc && s->allocator.user == &c);
        tl_scene_destroy(s);
    }
    TL_CHECK_EQ_U(c.live, 0);
    TL_CHECK_EQ_U(c.live_bytes, 0);
    TL_CHECK_EQ_U(c.foreign_free, 0);

    /* fail each allocation in turn: out of memory, nothing leaked, no output */
    for (size_t n = 0; n < allocations; n++) {
        counting f = {.fail_at = n};
        tl_allocator fa = {c_alloc, c_free, &f};
        tl_scene *t = (tl_scene *)(uintptr_t)1;
        tl_result r = tl_scene_create_default(&(tl_default_scene_desc){.detail = 1, .allocator = fa}, &t);
        TL_CHECK_EQ_U(r, TL_ERROR_OUT_OF_MEMORY);
        TL_CHECK(t == NULL);
        TL_CHECK_EQ_U(f.live, 0);
        TL_CHECK_EQ_U(f.foreign_free, 0);
        if (r == TL_OK) tl_scene_destroy(t);
    }

    /* an allocator with only one of its functions is a usage error */
    tl_scene *t = NULL;
    TL_CHECK_EQ_U(tl_scene_create_default(&(tl_default_scene_desc){.allocator = {c_alloc, NULL, &c}}, &t),
                  TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK_EQ_U(tl_scene_create_default(&(tl_default_scene_desc){.allocator = {NULL, c_free, &c}}, &t),
                  TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(t == NULL);
}

TL_TEST(scene_bad_arguments)
{
    TL_CHECK_EQ_U(tl_scene_create_default(NULL, NULL), TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK_EQ_U(tl_scene_create_default(&(tl_default_scene_desc){0}, NULL), TL_ERROR_INVALID_ARGUMENT);
    tl_scene_destroy(NULL);
    tl_scene_features(NULL, NULL);
    tl_scene_feature_set f;
    memset(&f, 0xff, sizeof f);
    tl_scene_features(NULL, &f);
    TL_CHECK(f.point_lights == 0 && f.triangle_count == 0 && f.has_textures == 0 && f.object_count == 0);
}

TL_TEST(scene_features)
{
    tl_scene *s = make(NULL);
    if (!s) return;
    tl_scene_feature_set f;
    tl_scene_features(s, &f);
    TL_CHECK_EQ_U(f.point_lights, 64);
    TL_CHECK_EQ_U(f.spot_lights, 8);
    TL_CHECK_EQ_U(f.directional_lights, 1);
    TL_CHECK(f.has_specular == 1);
    TL_CHECK(f.has_textures == 1);
    TL_CHECK(f.has_normal_maps == 0);
    TL_CHECK(f.has_emissive == 1);
    TL_CHECK(f.has_alpha_mask == 0);
    TL_CHECK(f.has_alpha_blend == 0);
    TL_CHECK_EQ_U(f.triangle_count, s->index_count / 3);
    TL_CHECK_EQ_U(f.object_count, s->object_count);
    tl_scene_destroy(s);

    s = make(&(tl_default_scene_desc){.no_directional = 1, .point_lights = 16, .spot_lights = 5, .detail = 1});
    if (!s) return;
    tl_scene_features(s, &f);
    TL_CHECK_EQ_U(f.point_lights, 16);
    TL_CHECK_EQ_U(f.spot_lights, 5);
    TL_CHECK_EQ_U(f.directional_lights, 0);
    tl_scene_destroy(s);

    /* a hand-made scene: only materials that objects draw with count; a map past the array is no
     * texture; TL_LIGHT_DEFAULT is a point light */
    tl_material mats[2] = {{.albedo = {1, 1, 1}, .albedo_map = TL_TEXTURE_MAP(5), .flags = TL_MATERIAL_ALPHA_MASK},
                           {.specular = {0.5f, 0.5f, 0.5f}, .emissive = {1, 0, 0}, .flags = TL_MATERIAL_ALPHA_BLEND}};
    tl_object objs[1] = {{.first_index = 0, .index_count = 3, .material = 0}};
    uint32_t idx[3] = {0, 0, 0};
    tl_light lights[2] = {{.type = TL_LIGHT_DEFAULT, .radius = 1}, {.type = TL_LIGHT_SPOT, .radius = 1}};
    tl_scene hand = {.indices = idx, .index_count = 3, .objects = objs, .object_count = 1, .materials = mats,
                     .material_count = 2, .lights = lights, .light_count = 2};
    tl_scene_features(&hand, &f);
    TL_CHECK_EQ_U(f.point_lights, 1);
    TL_CHECK_EQ_U(f.spot_lights, 1);
    TL_CHECK(f.has_textures == 0 && f.has_alpha_mask == 1 && f.has_alpha_blend == 0);
    TL_CHECK(f.has_specular == 0 && f.has_emissive == 0);
    TL_CHECK_EQ_U(f.triangle_count, 1);
}

TL_TEST(scene_materials_textures_valid)
{
    tl_scene *s = make(NULL);
    if (!s) return;
    int glossy = 0, matte = 0, coloured_specular = 0, textured = 0, emissive = 0;
    for (size_t m = 0; m < s->material_count; m++) {
        const tl_material *mt = &s->materials[m];
        TL_CHECK(mt->name[0] != '\0');
        TL_CHECK(memchr(mt->name, 0, sizeof mt->name) != NULL);
        for (int k = 0; k < 3; k++) {
            TL_CHECK(mt->albedo[k] >= 0.0f && mt->albedo[k] <= 1.0f);
            TL_CHECK(mt->specular[k] >= 0.0f && mt->specular[k] <= 1.0f);
            TL_CHECK(mt->emissive[k] >= 0.0f && isfinite(mt->emissive[k]));
        }
        TL_CHECK(mt->gloss >= 0.0f && mt->gloss <= 1.0f);
        TL_CHECK_EQ_U(mt->flags, 0); /* all opaque, single-sided */
        TL_CHECK(mt->albedo_map == 0 || mt->albedo_map - 1 < s->texture_count);
        TL_CHECK(mt->normal_map == 0 && mt->metallic_roughness_map == 0);
        TL_CHECK(mt->emissive_map == 0 && mt->occlusion_map == 0);
        glossy += mt->gloss >= 0.75f && mt->specular[0] >= 0.04f && mt->specular[0] <= 0.08f;
        matte += mt->gloss <= 0.25f && mt->specular[0] <= 0.03f;
        coloured_specular += mt->specular[0] != mt->specular[2];
        textured += mt->albedo_map != 0;
        emissive += mt->emissive[0] > 0.0f;
    }
    TL_CHECK(glossy >= 1 && matte >= 2 && coloured_specular >= 1 && textured >= 4 && emissive >= 1);
    for (size_t t = 0; t < s->texture_count; t++) {
        const tl_texture *tx = &s->textures[t];
        TL_CHECK(tx->width >= 64 && tx->height >= 64 && tx->rgba != NULL);
        TL_CHECK(tx->name[0] != '\0');
        if (!tx->rgba) continue;
        /* opaque, and not flat: a real pattern */
        size_t n = (size_t)tx->width * tx->height, opaque = 0;
        double mean = 0, var = 0;
        for (size_t i = 0; i < n; i++) {
            opaque += tx->rgba[4 * i + 3] == 255;
            mean += tx->rgba[4 * i + 1];
        }
        mean /= (double)n;
        for (size_t i = 0; i < n; i++) var += (tx->rgba[4 * i + 1] - mean) * (tx->rgba[4 * i + 1] - mean);
        var /= (double)n;
        TL_CHECK_EQ_U(opaque, n);
        TL_CHECK(mean > 40 && mean < 230);
        TL_CHECK(var > 25.0);
    }
    tl_scene_destroy(s);
}

TL_TEST(scene_camera_inside)
{
    tl_scene *s = make(NULL);
    if (!s) return;
    const tl_camera *c = &s->camera;
    TL_CHECK(fabs(c->position[0]) < HALL_X && c->position[2] > HALL_Z0 && c->position[2] < HALL_Z1);
    TL_CHECK(c->position[1] > 0.5f && c->position[1] < 5.0f);
    TL_CHECK(fabs(c->target[0]) < HALL_X && c->target[2] > HALL_Z0 && c->target[2] < HALL_Z1);
    TL_CHECK(!near_column(c->position[0], c->position[2], 1.0));
    float f[3] = {c->target[0] - c->position[0], c->target[1] - c->position[1], c->target[2] - c->position[2]};
    double fl = len3(f);
    TL_CHECK(fl > 1.0);
    /* down the nave (towards -z), tilted slightly down */
    TL_CHECK(f[2] / fl < -0.95);
    TL_CHECK(f[1] / fl < 0.0 && f[1] / fl > -0.2);
    TL_CHECK(fabs(len3(c->up) - 1.0) < 1e-6 && c->up[1] == 1.0f);
    TL_CHECK(c->fov_y > 0.8f && c->fov_y < 1.3f);
    TL_CHECK(c->near_z > 0.0f && c->far_z > c->near_z);
    TL_CHECK(c->far_z >= 50.0f);
    TL_CHECK(s->ambient[0] > 0.0f && s->ambient[0] < 0.1f);
    /* the camera is in no object's solid */
    size_t inside = 0;
    for (size_t o = 0; o < s->object_count; o++) {
        const tl_object *ob = &s->objects[o];
        int in = 1;
        for (int k = 0; k < 3; k++) in &= c->position[k] > ob->bounds_min[k] && c->position[k] < ob->bounds_max[k];
        /* vaults and arches have open bounds below them; anything whose box holds the camera
         * must reach above the springing line */
        if (in && ob->bounds_min[1] < 4.0f) inside++;
    }
    TL_CHECK_EQ_U(inside, 0);
    tl_scene_destroy(s);
}

/* ---- bounds (tl_object_compute_bounds, tl_scene_compute_bounds) ------------------------------- */

/* The smallest box around every vertex an object's indices name, through its transform: each
 * vertex (transformed here in double, per vertex, with the zero transform taken as the identity)
 * lies inside the computed box, and every face of the box is touched by a vertex, both within
 * float's rounding of the coordinate (2^-24 relative, half a step each way). */
static void check_box_brute_force(const tl_scene *s, const tl_object *o, const float lo[3], const float hi[3],
                                  double *worst)
{
    int zero = 1;
    for (int k = 0; k < 16; k++) zero &= o->transform[k] == 0.0f;
    double seen_lo[3] = {INFINITY, INFINITY, INFINITY}, seen_hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (uint32_t i = 0; i < o->index_count; i++) {
        const float *p = s->vertices[s->indices[o->first_index + i]].position;
        for (int r = 0; r < 3; r++) {
            double w = p[r];
            if (!zero)
                w = (double)o->transform[r] * p[0] + (double)o->transform[4 + r] * p[1] +
                    (double)o->transform[8 + r] * p[2] + (double)o->transform[12 + r];
            seen_lo[r] = fmin(seen_lo[r], w);
            seen_hi[r] = fmax(seen_hi[r], w);
        }
    }
    for (int r = 0; r < 3; r++) {
        double tol_lo = fabs(seen_lo[r]) * 0x1.0p-24, tol_hi = fabs(seen_hi[r]) * 0x1.0p-24;
        TL_CHECK_LE(fabs((double)lo[r] - seen_lo[r]), tol_lo); /* inside and touching, within rounding */
        TL_CHECK_LE(fabs((double)hi[r] - seen_hi[r]), tol_hi);
        *worst = fmax(*worst, fmax(fabs((double)lo[r] - seen_lo[r]), fabs((double)hi[r] - seen_hi[r])));
    }
}

/* Every object of the crypt (identity transforms), then the same objects under seeded rotations,
 * scales and translations, and under the zero transform: the helper against the brute force; the
 * crypt's own bounds (over each object's vertex range) contain the helper's. */
TL_TEST(object_bounds_match_brute_force)
{
    tl_scene *s = make(&(tl_default_scene_desc){.detail = 1, .point_lights = 8});
    if (!s) return;
    double worst = 0.0;
    size_t checked = 0;
    tl_rng rng = {7};
    for (int pass = 0; pass < 3; pass++) {
        for (size_t i = 0; i < s->object_count; i++) {
            tl_object o = s->objects[i];
            if (pass == 1) { /* rotation about a random axis, scale 0.1 .. 10, translation up to 1000 */
                double a = tl_rng_unit(&rng) * 6.283185307179586, c = cos(a), sn = sin(a);
                double sc = pow(10.0, 2.0 * tl_rng_unit(&rng) - 1.0);
                double ax[3] = {tl_rng_unit(&rng) - 0.5, tl_rng_unit(&rng) - 0.5, tl_rng_unit(&rng) - 0.5};
                double l = sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
                for (int k = 0; k < 3; k++) ax[k] /= l;
                const double cross[3][3] = {{0, -ax[2], ax[1]}, {ax[2], 0, -ax[0]}, {-ax[1], ax[0], 0}};
                for (int col = 0; col < 3; col++) /* Rodrigues: c I + s [a]x + (1 - c) a a^T */
                    for (int row = 0; row < 3; row++)
                        o.transform[col * 4 + row] = (float)(sc * ((row == col ? c : 0.0) + sn * cross[row][col] +
                                                                  (1.0 - c) * ax[row] * ax[col]));
                o.transform[15] = 1.0f;
                for (int k = 0; k < 3; k++) o.transform[12 + k] = (float)(2000.0 * tl_rng_unit(&rng) - 1000.0);
            }
            if (pass == 2) memset(o.transform, 0, sizeof o.transform);
            float lo[3] = {7, 7, 7}, hi[3] = {7, 7, 7};
            TL_CHECK(tl_object_compute_bounds(s, &o, lo, hi) == TL_OK);
            check_box_brute_force(s, &o, lo, hi, &worst);
            checked++;
            if (pass == 0 && o.index_count)
                for (int k = 0; k < 3; k++)
                    TL_CHECK(lo[k] >= s->objects[i].bounds_min[k] && hi[k] <= s->objects[i].bounds_max[k]);
        }
    }
    printf("  %zu objects, largest distance from the brute force's box: %g\n", checked, worst);

    /* tl_scene_compute_bounds: each object as tl_object_compute_bounds, the scene as their union */
    float scene_lo[3], scene_hi[3];
    memcpy(scene_lo, s->bounds_min, sizeof scene_lo);
    memcpy(scene_hi, s->bounds_max, sizeof scene_hi);
    for (size_t i = 0; i < s->object_count; i++) memset(s->objects[i].bounds_min, 0, 6 * sizeof(float));
    TL_CHECK(tl_scene_compute_bounds(s) == TL_OK);
    float u_lo[3] = {INFINITY, INFINITY, INFINITY}, u_hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < s->object_count; i++) {
        float lo[3], hi[3];
        TL_CHECK(tl_object_compute_bounds(s, &s->objects[i], lo, hi) == TL_OK);
        TL_CHECK(memcmp(lo, s->objects[i].bounds_min, sizeof lo) == 0);
        TL_CHECK(memcmp(hi, s->objects[i].bounds_max, sizeof hi) == 0);
        for (int k = 0; k < 3 && s->objects[i].index_count; k++) {
            u_lo[k] = fminf(u_lo[k], lo[k]);
            u_hi[k] = fmaxf(u_hi[k], hi[k]);
        }
    }
    TL_CHECK(memcmp(u_lo, s->bounds_min, sizeof u_lo) == 0 && memcmp(u_hi, s->bounds_max, sizeof u_hi) == 0);
    for (int k = 0; k < 3; k++) TL_CHECK(s->bounds_min[k] >= scene_lo[k] && s->bounds_max[k] <= scene_hi[k]);
    tl_scene_destroy(s);
}

/* What the helpers refuse, leaving their outputs and the scene as they were. */
TL_TEST(object_bounds_bad_arguments)
{
    tl_vertex v[3] = {{.position = {1, 2, 3}}, {.position = {4, 5, 6}}, {.position = {7, 8, NAN}}};
    uint32_t idx[6] = {0, 1, 0, 0, 1, 5};
    tl_object objs[2] = {{.index_count = 3, .bounds_max = {9, 9, 9}}, {.first_index = 3, .index_count = 3}};
    tl_scene s = {.vertices = v, .vertex_count = 3, .indices = idx, .index_count = 6, .objects = objs,
                  .object_count = 2};
    float lo[3] = {7, 7, 7}, hi[3] = {7, 7, 7};
    TL_CHECK(tl_object_compute_bounds(NULL, &objs[0], lo, hi) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_object_compute_bounds(&s, NULL, lo, hi) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_object_compute_bounds(&s, &objs[0], NULL, hi) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_object_compute_bounds(&s, &objs[1], lo, hi) == TL_ERROR_INVALID_ARGUMENT); /* index 5 of 3 vertices */
    tl_object past = {.first_index = 4, .index_count = 3};
    TL_CHECK(tl_object_compute_bounds(&s, &past, lo, hi) == TL_ERROR_INVALID_ARGUMENT); /* indices 4..7 of 6 */
    idx[2] = 2;
    TL_CHECK(tl_object_compute_bounds(&s, &objs[0], lo, hi) == TL_ERROR_INVALID_ARGUMENT); /* a NaN position */
    tl_object nan_transform = {.index_count = 2};
    nan_transform.transform[5] = NAN;
    TL_CHECK(tl_object_compute_bounds(&s, &nan_transform, lo, hi) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(lo[0] == 7 && hi[2] == 7);
    TL_CHECK(tl_scene_compute_bounds(NULL) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_scene_compute_bounds(&s) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(objs[0].bounds_max[0] == 9 && objs[0].bounds_min[0] == 0); /* unchanged */
    /* an empty object has zero bounds; a scene of empty objects zero bounds too */
    idx[2] = 0;
    objs[1].index_count = 0;
    TL_CHECK(tl_scene_compute_bounds(&s) == TL_OK);
    TL_CHECK(objs[0].bounds_min[0] == 1 && objs[0].bounds_max[2] == 6 && objs[1].bounds_max[0] == 0);
    TL_CHECK(s.bounds_min[0] == 1 && s.bounds_max[1] == 5);
    objs[0].index_count = 0;
    TL_CHECK(tl_scene_compute_bounds(&s) == TL_OK);
    TL_CHECK(s.bounds_min[0] == 0 && s.bounds_max[1] == 0 && objs[0].bounds_max[2] == 0);
}
