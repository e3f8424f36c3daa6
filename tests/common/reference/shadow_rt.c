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

void tl_shadow_rt_truth(const tl_shadow_rt *rt, const tl_camera *c, uint32_t w, uint32_t h, const tl_light *light,
                        uint8_t *state, uint32_t *object)
{
    float r[3], u[3], b[3];
    tl__camera_basis(c, r, u, b);
    float ty = tanf(0.5f * (c->fov_y > 0.0f ? c->fov_y : 1.04719755f)), tx = ty * (float)w / (float)h;
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            float sx = (2.0f * ((float)x + 0.5f) / (float)w - 1.0f) * tx, sy = (2.0f * ((float)y + 0.5f) / (float)h - 1.0f) * ty;
            float d[3];
            for (int k = 0; k < 3; k++) d[k] = r[k] * sx + u[k] * sy - b[k];
            tl__norm(d);
            struct RTCRayHit rh;
            memset(&rh, 0, sizeof rh);
            rh.ray.org_x = c->position[0], rh.ray.org_y = c->position[1], rh.ray.org_z = c->position[2];
            rh.ray.dir_x = d[0], rh.ray.dir_y = d[1], rh.ray.dir_z = d[2];
            rh.ray.tnear = c->near_z > 0.0f ? c->near_z : 0.0f;
            rh.ray.tfar = c->far_z > 0.0f ? c->far_z : INFINITY;
            rh.ray.mask = 0xFFFFFFFFu;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(rt->scene, &ctx, &rh);
            state[i] = TL_RT_NONE;
            object[i] = 0;
            if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
            float p[3], ng[3] = {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
            tl__norm(ng);
            if (ng[0] * d[0] + ng[1] * d[1] + ng[2] * d[2] > 0.0f) ng[0] = -ng[0], ng[1] = -ng[1], ng[2] = -ng[2];
            for (int k = 0; k < 3; k++) p[k] = c->position[k] + d[k] * rh.ray.tfar;
            object[i] = rt->prim_object[rh.hit.primID];
            state[i] = tl__light_state(rt, p, ng, light);
        }
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
