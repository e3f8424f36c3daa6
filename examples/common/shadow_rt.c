/* Ray-traced shadow truth with Embree 3 (shadow_rt.h). */
#include "shadow_rt.h"

#include <embree3/rtcore.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct tl_shadow_rt {
    RTCDevice device;
    RTCScene scene;
    float extent; /* largest coordinate magnitude: the shadow ray's offset scale */
    uint32_t *prim_object; /* per triangle: its object + 1 */
};

static void tl__xform(const float *m, const float p[3], float out[3])
{
    int identity = 1;
    for (int i = 0; i < 16; i++) identity &= m[i] == 0.0f;
    for (int k = 0; k < 3; k++)
        out[k] = identity ? p[k] : m[k] * p[0] + m[4 + k] * p[1] + m[8 + k] * p[2] + m[12 + k];
}

/* One Embree geometry of every opaque triangle object, in world space. */
static int tl__rt_geometry(tl_shadow_rt *rt, const tl_scene *s)
{
    size_t tris = 0;
    for (size_t o = 0; o < s->object_count; o++) {
        const tl_object *ob = &s->objects[o];
        const tl_material *m = s->material_count ? &s->materials[ob->material] : NULL;
        if (ob->primitive == TL_PRIMITIVE_TRIANGLES && !(m && (m->flags & TL_MATERIAL_ALPHA_BLEND)))
            tris += ob->index_count / 3;
    }
    if (!tris) return 1;
    RTCGeometry g = rtcNewGeometry(rt->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), tris * 3);
    unsigned *ix = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris);
    rt->prim_object = malloc(tris * sizeof *rt->prim_object);
    if (!v || !ix || !rt->prim_object) return 0;
    size_t n = 0;
    for (size_t o = 0; o < s->object_count; o++) {
        const tl_object *ob = &s->objects[o];
        const tl_material *m = s->material_count ? &s->materials[ob->material] : NULL;
        if (ob->primitive != TL_PRIMITIVE_TRIANGLES || (m && (m->flags & TL_MATERIAL_ALPHA_BLEND))) continue;
        for (uint32_t i = 0; i + 2 < ob->index_count; i += 3, rt->prim_object[n] = (uint32_t)o + 1u, n++)
            for (int k = 0; k < 3; k++) {
                tl__xform(ob->transform, s->vertices[s->indices[ob->first_index + i + (uint32_t)k]].position,
                          &v[(n * 3 + (size_t)k) * 3]);
                for (int a = 0; a < 3; a++) rt->extent = fmaxf(rt->extent, fabsf(v[(n * 3 + (size_t)k) * 3 + (size_t)a]));
                ix[n * 3 + (size_t)k] = (unsigned)(n * 3 + (size_t)k);
            }
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(rt->scene, g);
    rtcReleaseGeometry(g);
    return 1;
}

tl_shadow_rt *tl_shadow_rt_create(const tl_scene *s)
{
    tl_shadow_rt *rt = calloc(1, sizeof *rt);
    if (!rt) return NULL;
    rt->device = rtcNewDevice("threads=1");
    if (!rt->device) {
        fprintf(stderr, "shadow_rt: rtcNewDevice failed\n");
        free(rt);
        return NULL;
    }
    rt->scene = rtcNewScene(rt->device);
    rtcSetSceneBuildQuality(rt->scene, RTC_BUILD_QUALITY_HIGH);
    if (!tl__rt_geometry(rt, s)) {
        fprintf(stderr, "shadow_rt: no geometry buffers\n");
        tl_shadow_rt_destroy(rt);
        return NULL;
    }
    rtcCommitScene(rt->scene);
    return rt;
}

void tl_shadow_rt_destroy(tl_shadow_rt *rt)
{
    if (!rt) return;
    if (rt->scene) rtcReleaseScene(rt->scene);
    if (rt->device) rtcReleaseDevice(rt->device);
    free(rt->prim_object);
    free(rt);
}

static void tl__norm(float v[3])
{
    float l = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0.0f) v[0] /= l, v[1] /= l, v[2] /= l;
}

/* The camera's basis: right, up, back (view +Z) as the renderer's look-at makes it. */
static void tl__camera_basis(const tl_camera *c, float r[3], float u[3], float b[3])
{
    float up[3] = {c->up[0], c->up[1], c->up[2]};
    if (up[0] == 0.0f && up[1] == 0.0f && up[2] == 0.0f) up[1] = 1.0f;
    for (int k = 0; k < 3; k++) b[k] = c->position[k] - c->target[k];
    tl__norm(b);
    r[0] = up[1] * b[2] - up[2] * b[1], r[1] = up[2] * b[0] - up[0] * b[2], r[2] = up[0] * b[1] - up[1] * b[0];
    tl__norm(r);
    u[0] = b[1] * r[2] - b[2] * r[1], u[1] = b[2] * r[0] - b[0] * r[2], u[2] = b[0] * r[1] - b[1] * r[0];
}

/* The state of the surface point p with geometric normal ng (facing the eye) for the light. */
static uint8_t tl__light_state(const tl_shadow_rt *rt, const float p[3], const float ng[3], const tl_light *l)
{
    float d[3], tfar = INFINITY;
    if (l->type == TL_LIGHT_DIRECTIONAL) {
        for (int k = 0; k < 3; k++) d[k] = -l->direction[k];
        tl__norm(d);
    } else {
        for (int k = 0; k < 3; k++) d[k] = l->position[k] - p[k];
        tfar = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        tl__norm(d);
    }
    if (d[0] * ng[0] + d[1] * ng[1] + d[2] * ng[2] <= 0.0f) return TL_RT_AWAY;
    float eps = 1e-5f * fmaxf(1.0f, rt->extent);
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    struct RTCRay ray = {0};
    ray.org_x = p[0] + ng[0] * eps, ray.org_y = p[1] + ng[1] * eps, ray.org_z = p[2] + ng[2] * eps;
    ray.dir_x = d[0], ray.dir_y = d[1], ray.dir_z = d[2];
    ray.tnear = 0.0f;
    ray.tfar = tfar;
    ray.mask = 0xFFFFFFFFu;
    rtcOccluded1(rt->scene, &ctx, &ray);
    return ray.tfar == -INFINITY ? TL_RT_SHADOWED : TL_RT_LIT;
}

/* The primary ray through pixel (x, y): the surface point p and its geometric normal ng (facing the
 * eye); the object hit + 1, 0 without a hit. */
static uint32_t tl__primary(const tl_shadow_rt *rt, const tl_camera *c, const float basis[9], float tx, float ty,
                            float sx, float sy, float p[3], float ng[3])
{
    float d[3];
    for (int k = 0; k < 3; k++) d[k] = basis[k] * sx * tx + basis[3 + k] * sy * ty - basis[6 + k];
    tl__norm(d);
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    struct RTCRayHit rh;
    memset(&rh, 0, sizeof rh);
    rh.ray.org_x = c->position[0], rh.ray.org_y = c->position[1], rh.ray.org_z = c->position[2];
    rh.ray.dir_x = d[0], rh.ray.dir_y = d[1], rh.ray.dir_z = d[2];
    rh.ray.tnear = c->near_z > 0.0f ? c->near_z : 0.0f;
    rh.ray.tfar = c->far_z > 0.0f ? c->far_z : INFINITY;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(rt->scene, &ctx, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return 0;
    ng[0] = rh.hit.Ng_x, ng[1] = rh.hit.Ng_y, ng[2] = rh.hit.Ng_z;
    tl__norm(ng);
    if (ng[0] * d[0] + ng[1] * d[1] + ng[2] * d[2] > 0.0f) ng[0] = -ng[0], ng[1] = -ng[1], ng[2] = -ng[2];
    for (int k = 0; k < 3; k++) p[k] = c->position[k] + d[k] * rh.ray.tfar;
    return rt->prim_object[rh.hit.primID];
}

/* Calls `shade` for every pixel with its primary hit (object 0: none). */
static void tl__pixels(const tl_shadow_rt *rt, const tl_camera *c, uint32_t w, uint32_t h,
                       void (*shade)(void *user, size_t i, uint32_t object, const float p[3], const float ng[3]),
                       void *user)
{
    float basis[9];
    tl__camera_basis(c, basis, basis + 3, basis + 6);
    float ty = tanf(0.5f * (c->fov_y > 0.0f ? c->fov_y : 1.04719755f)), tx = ty * (float)w / (float)h;
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            float sx = 2.0f * ((float)x + 0.5f) / (float)w - 1.0f, sy = 2.0f * ((float)y + 0.5f) / (float)h - 1.0f;
            float p[3] = {0, 0, 0}, ng[3] = {0, 0, 0};
            uint32_t object = tl__primary(rt, c, basis, tx, ty, sx, sy, p, ng);
            shade(user, (size_t)y * w + x, object, p, ng);
        }
}

typedef struct tl__hard {
    const tl_shadow_rt *rt;
    const tl_light *light;
    uint8_t *state;
    uint32_t *object;
} tl__hard;

static void tl__hard_pixel(void *user, size_t i, uint32_t object, const float p[3], const float ng[3])
{
    tl__hard *t = (tl__hard *)user;
    t->object[i] = object;
    t->state[i] = object ? tl__light_state(t->rt, p, ng, t->light) : TL_RT_NONE;
}

void tl_shadow_rt_truth(const tl_shadow_rt *rt, const tl_camera *c, uint32_t w, uint32_t h, const tl_light *light,
                        uint8_t *state, uint32_t *object)
{
    tl__hard t = {rt, light, state, object};
    tl__pixels(rt, c, w, h, tl__hard_pixel, &t);
}

typedef struct tl__surface {
    float *position, *normal;
} tl__surface;

static void tl__surface_pixel(void *user, size_t i, uint32_t object, const float p[3], const float ng[3])
{
    tl__surface *t = (tl__surface *)user;
    (void)object;
    memcpy(&t->position[3 * i], p, 3 * sizeof(float));
    memcpy(&t->normal[3 * i], ng, 3 * sizeof(float));
}

void tl_shadow_rt_surface(const tl_shadow_rt *rt, const tl_camera *c, uint32_t w, uint32_t h, float *position,
                          float *normal)
{
    tl__surface t = {position, normal};
    tl__pixels(rt, c, w, h, tl__surface_pixel, &t);
}

/* An orthonormal pair perpendicular to unit a. */
static void tl__perpendicular(const float a[3], float e1[3], float e2[3])
{
    float t[3] = {0, 0, 0};
    t[fabsf(a[0]) < 0.6f ? 0 : fabsf(a[1]) < 0.6f ? 1 : 2] = 1.0f;
    e1[0] = a[1] * t[2] - a[2] * t[1], e1[1] = a[2] * t[0] - a[0] * t[2], e1[2] = a[0] * t[1] - a[1] * t[0];
    tl__norm(e1);
    e2[0] = a[1] * e1[2] - a[2] * e1[1], e2[1] = a[2] * e1[0] - a[0] * e1[2], e2[2] = a[0] * e1[1] - a[1] * e1[0];
}

typedef struct tl__area {
    const tl_shadow_rt *rt;
    const tl_light *light;
    float tan_angle;
    uint32_t strata;
    float *visibility;
    uint32_t *object;
} tl__area;

/* Whether the ray from o along unit d reaches tfar unoccluded. */
static int tl__unoccluded(const tl_shadow_rt *rt, const float o[3], const float d[3], float tfar)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    struct RTCRay ray = {0};
    ray.org_x = o[0], ray.org_y = o[1], ray.org_z = o[2];
    ray.dir_x = d[0], ray.dir_y = d[1], ray.dir_z = d[2];
    ray.tfar = tfar;
    ray.mask = 0xFFFFFFFFu;
    rtcOccluded1(rt->scene, &ctx, &ray);
    return ray.tfar != -INFINITY;
}

/* The fraction of the emitter seen from p: strata^2 shadow rays, one per equal-area cell (radius
 * sqrt(u), angle 2 pi v) of the disc facing p, the angles turned per pixel (a hash of its index) so
 * that the strata's pattern does not repeat from pixel to pixel. */
static void tl__area_pixel(void *user, size_t i, uint32_t object, const float p[3], const float ng[3])
{
    tl__area *t = (tl__area *)user;
    const tl_light *l = t->light;
    t->object[i] = object;
    t->visibility[i] = -1.0f;
    if (!object) return;
    int sun = l->type == TL_LIGHT_DIRECTIONAL;
    float a[3], e1[3], e2[3];
    for (int k = 0; k < 3; k++) a[k] = sun ? -l->direction[k] : l->position[k] - p[k];
    tl__norm(a);
    if (a[0] * ng[0] + a[1] * ng[1] + a[2] * ng[2] <= 0.0f) return; /* facing away: not measured */
    tl__perpendicular(a, e1, e2);
    float eps = 1e-5f * fmaxf(1.0f, t->rt->extent), o[3];
    for (int k = 0; k < 3; k++) o[k] = p[k] + ng[k] * eps;
    uint32_t hash = (uint32_t)i * 2654435761u, seen = 0, n = t->strata;
    float turn = (float)(hash >> 8) / 16777216.0f;
    for (uint32_t u = 0; u < n; u++)
        for (uint32_t v = 0; v < n; v++) {
            float r = sqrtf(((float)u + 0.5f) / (float)n), phi = 6.28318531f * (((float)v + 0.5f) / (float)n + turn);
            float x = r * cosf(phi), y = r * sinf(phi), d[3], tfar = INFINITY;
            for (int k = 0; k < 3; k++) {
                if (sun) d[k] = a[k] + t->tan_angle * (x * e1[k] + y * e2[k]);
                else d[k] = l->position[k] + l->source_radius * (x * e1[k] + y * e2[k]) - o[k];
            }
            if (!sun) tfar = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            tl__norm(d);
            seen += (uint32_t)tl__unoccluded(t->rt, o, d, sun ? INFINITY : tfar);
        }
    t->visibility[i] = (float)seen / (float)(n * n);
}

void tl_shadow_rt_area(const tl_shadow_rt *rt, const tl_camera *c, uint32_t w, uint32_t h, const tl_light *light,
                       float angle, uint32_t strata, float *visibility, uint32_t *object)
{
    tl__area t = {rt, light, tanf(angle), strata ? strata : 1u, visibility, object};
    tl__pixels(rt, c, w, h, tl__area_pixel, &t);
}

void tl_shadow_rt_area_state(const float *visibility, uint8_t *state, size_t n)
{
    for (size_t i = 0; i < n; i++)
        state[i] = visibility[i] < 0.0f   ? TL_RT_AWAY
                   : visibility[i] >= 1.0f ? TL_RT_LIT
                   : visibility[i] <= 0.0f ? TL_RT_SHADOWED
                                           : TL_RT_NONE;
}

/* Left out: no hit, or within `band` pixels of another state or of another object. */
static int tl__in_band(const uint8_t *state, const uint32_t *object, uint32_t w, uint32_t h, uint32_t x, uint32_t y,
                       int band)
{
    size_t i = (size_t)y * w + x;
    int lit = state[i] == TL_RT_LIT;
    for (int dy = -band; dy <= band; dy++)
        for (int dx = -band; dx <= band; dx++) {
            int xx = (int)x + dx, yy = (int)y + dy;
            if (xx < 0 || yy < 0 || xx >= (int)w || yy >= (int)h) continue;
            size_t j = (size_t)yy * w + (size_t)xx;
            if (state[j] == TL_RT_NONE || (state[j] == TL_RT_LIT) != lit) return 1;
            if (object[j] != object[i]) return 1;
        }
    return 0;
}

tl_shadow_error tl_shadow_rt_compare_terms(const uint8_t *state, const uint32_t *object, const float *a, const float *b,
                                           uint32_t w, uint32_t h, int band)
{
    tl_shadow_error e = {0};
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            if (state[i] != TL_RT_LIT && state[i] != TL_RT_SHADOWED) continue;
            if (a[i] < 0.0f || (b && b[i] < 0.0f) || tl__in_band(state, object, w, h, x, y, band)) continue;
            e.counted++;
            int lit_a = a[i] >= 0.5f;
            int lit_b = b ? b[i] >= 0.5f : state[i] == TL_RT_LIT;
            if (lit_a && !lit_b) e.leaks++;
            if (!lit_a && lit_b) e.acne++;
        }
    e.wrong = e.counted ? (double)(e.acne + e.leaks) / (double)e.counted : 0.0;
    return e;
}

tl_shadow_error tl_shadow_rt_compare(const uint8_t *state, const uint32_t *object, const float *term, uint32_t w,
                                     uint32_t h, int band)
{
    return tl_shadow_rt_compare_terms(state, object, term, NULL, w, h, band);
}
