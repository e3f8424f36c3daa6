/* The lit plane and sphere of the lighting-model tests (ggx_scene.h). */
#include "ggx_scene.h"

#include <math.h>
#include <string.h>

static void add_plane(ggx_scene *g, size_t *nv, size_t *ni)
{
    const float s = 6.0f, xz[4][2] = {{-s, s}, {s, s}, {s, -s}, {-s, -s}};
    for (int i = 0; i < 4; i++) {
        tl_vertex *x = &g->v[(*nv)++];
        memset(x, 0, sizeof *x);
        x->position[0] = xz[i][0];
        x->position[2] = xz[i][1];
        x->normal[1] = 1.0f;
    }
    const uint32_t q[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 6; i++) g->idx[(*ni)++] = q[i];
}

static void add_sphere(ggx_scene *g, size_t *nv, size_t *ni)
{
    const double pi = TL_REF_PI;
    uint32_t base = (uint32_t)*nv;
    for (int r = 0; r <= GGX_SPHERE_RINGS; r++)
        for (int s = 0; s <= GGX_SPHERE_SEGMENTS; s++) {
            double th = pi * r / GGX_SPHERE_RINGS, ph = 2.0 * pi * s / GGX_SPHERE_SEGMENTS;
            double n[3] = {sin(th) * cos(ph), cos(th), -sin(th) * sin(ph)};
            tl_vertex *x = &g->v[(*nv)++];
            memset(x, 0, sizeof *x);
            for (int k = 0; k < 3; k++) {
                x->position[k] = (float)(g->centre[k] + g->radius * n[k]);
                /* exactly (position - centre) / radius in float, so interpolation keeps the identity */
                x->normal[k] = (float)(((double)x->position[k] - g->centre[k]) / g->radius);
            }
        }
    for (int r = 0; r < GGX_SPHERE_RINGS; r++)
        for (int s = 0; s < GGX_SPHERE_SEGMENTS; s++) {
            uint32_t a = base + (uint32_t)(r * (GGX_SPHERE_SEGMENTS + 1) + s), b = a + GGX_SPHERE_SEGMENTS + 1;
            const uint32_t q[6] = {a, b, a + 1, a + 1, b, b + 1};
            for (int i = 0; i < 6; i++) g->idx[(*ni)++] = q[i];
        }
}

void ggx_scene_build(ggx_scene *g)
{
    memset(g, 0, sizeof *g);
    g->centre[1] = 1.3;
    g->radius = 1.0;
    size_t nv = 0, ni = 0;
    add_plane(g, &nv, &ni);
    add_sphere(g, &nv, &ni);
    const float id[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    g->obj[0] = (tl_object){0, 6, 0, {0}, {-6, 0, -6}, {6, 0, 6}, TL_PRIMITIVE_TRIANGLES};
    g->obj[1] = (tl_object){6, (uint32_t)(ni - 6), 1, {0}, {-1, 0.3f, -1}, {1, 2.3f, 1}, TL_PRIMITIVE_TRIANGLES};
    memcpy(g->obj[0].transform, id, sizeof id);
    memcpy(g->obj[1].transform, id, sizeof id);
    const tl_material none = {.alpha = 1.0f};
    g->mat[0] = none;
    g->mat[0].albedo[0] = g->mat[0].albedo[1] = g->mat[0].albedo[2] = 0.5f;
    g->mat[0].specular[0] = g->mat[0].specular[1] = g->mat[0].specular[2] = 0.04f;
    g->mat[0].gloss = 51.0f / 255.0f; /* roughness 0.8 */
    g->mat[1] = none; /* gold metal, converted as the glTF loader converts constant factors */
    g->mat[1].flags = TL_MATERIAL_MICROFACET;
    g->mat[1].specular[0] = 1.0f;
    g->mat[1].specular[1] = 0.766f;
    g->mat[1].specular[2] = 0.336f;
    g->mat[1].gloss = 102.0f / 255.0f; /* roughness 0.6 */
    g->lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {1.6f, 2.8f, 2.2f}, .color = {24, 22, 20},
                              .radius = 9.0f};
    g->lights[1] = (tl_light){.type = TL_LIGHT_SPOT, .position = {-2.0f, 3.5f, 1.0f},
                              .direction = {0.5f, -0.8f, -0.2f}, .color = {30, 26, 40}, .radius = 8.0f,
                              .cos_inner = 0.93f, .cos_outer = 0.8f};
    float *d = g->lights[1].direction, l = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int k = 0; k < 3; k++) d[k] /= l;
    g->lights[2] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {-0.3f, -0.8f, -0.52f},
                              .color = {0.8f, 0.85f, 1.0f}};
    d = g->lights[2].direction, l = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int k = 0; k < 3; k++) d[k] /= l;
    g->s.vertices = g->v;
    g->s.vertex_count = nv;
    g->s.indices = g->idx;
    g->s.index_count = ni;
    g->s.objects = g->obj;
    g->s.object_count = 2;
    g->s.materials = g->mat;
    g->s.material_count = 2;
    g->s.lights = g->lights;
    g->s.light_count = 3;
    g->s.ambient[0] = g->s.ambient[1] = g->s.ambient[2] = 0.03f;
    g->s.camera = (tl_camera){{0, 2.6f, 5.2f}, {0, 0.9f, 0}, {0, 1, 0}, 0.9f, 0.1f, 100.0f};
}

static void normalize3(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; k++) v[k] /= l;
}

void ggx_view_matrix(const tl_camera *c, double m[16])
{
    double f[3], up[3] = {c->up[0], c->up[1], c->up[2]}, s[3], u[3];
    for (int k = 0; k < 3; k++) f[k] = (double)c->target[k] - c->position[k];
    normalize3(f);
    s[0] = f[1] * up[2] - f[2] * up[1];
    s[1] = f[2] * up[0] - f[0] * up[2];
    s[2] = f[0] * up[1] - f[1] * up[0];
    normalize3(s);
    u[0] = s[1] * f[2] - s[2] * f[1];
    u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    const double *e = (const double[3]){c->position[0], c->position[1], c->position[2]};
    const double r[16] = {s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0,
                          -(s[0] * e[0] + s[1] * e[1] + s[2] * e[2]), -(u[0] * e[0] + u[1] * e[1] + u[2] * e[2]),
                          f[0] * e[0] + f[1] * e[1] + f[2] * e[2], 1};
    memcpy(m, r, sizeof r);
}

static void xform(const double m[16], const double p[3], double w, double out[3])
{
    for (int i = 0; i < 3; i++) out[i] = m[i] * p[0] + m[4 + i] * p[1] + m[8 + i] * p[2] + m[12 + i] * w;
}

size_t ggx_ref_lights(const ggx_scene *g, const double view[16], tl_ref_light *out)
{
    for (size_t i = 0; i < g->s.light_count; i++) {
        const tl_light *l = &g->s.lights[i];
        tl_ref_light *o = &out[i];
        memset(o, 0, sizeof *o);
        o->type = (tl_ref_light_type)l->type;
        double p[3] = {l->position[0], l->position[1], l->position[2]}, d[3] = {l->direction[0], l->direction[1], l->direction[2]};
        xform(view, p, 1.0, o->position);
        xform(view, d, 0.0, o->direction);
        normalize3(o->direction);
        for (int k = 0; k < 3; k++) o->color[k] = l->color[k];
        o->range = l->radius;
        o->source_radius = l->type == TL_LIGHT_DIRECTIONAL ? 0.0 : l->source_radius;
        o->cos_inner = l->type == TL_LIGHT_SPOT ? l->cos_inner : 1.0;
        o->cos_outer = l->cos_outer;
    }
    return g->s.light_count;
}

int ggx_classify(const ggx_scene *g, const double view[16], const double p[3], double n_view[3])
{
    /* world = view^-1 p: the view matrix is a rotation R and translation t, so world = R^T (p - t) */
    double q[3] = {p[0] - view[12], p[1] - view[13], p[2] - view[14]}, w[3];
    for (int i = 0; i < 3; i++) w[i] = view[4 * i] * q[0] + view[4 * i + 1] * q[1] + view[4 * i + 2] * q[2];
    if (fabs(w[1]) < 1e-3) {
        xform(view, (const double[3]){0, 1, 0}, 0.0, n_view);
        return 0;
    }
    double c[3], d[3];
    xform(view, g->centre, 1.0, c);
    for (int k = 0; k < 3; k++) d[k] = p[k] - c[k];
    double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (fabs(len - g->radius) > 0.01 * g->radius) return -1;
    for (int k = 0; k < 3; k++) n_view[k] = d[k] / len;
    return 1;
}

void ggx_ref_surface(const tl_material *m, tl_render_mode mode, tl_ref_surface *out)
{
    memset(out, 0, sizeof *out);
    if (m->flags & TL_MATERIAL_METALLIC_ROUGHNESS) {
        const double base[3] = {m->albedo[0], m->albedo[1], m->albedo[2]};
        tl_ref_surface_metallic_roughness(base, m->metallic, m->roughness, out);
    } else {
        for (int k = 0; k < 3; k++) {
            out->albedo[k] = m->albedo[k];
            out->specular[k] = m->specular[k];
        }
        out->gloss = m->gloss;
        out->occlusion = 1.0;
    }
    if (mode == TL_MODE_THIN_LPP || mode == TL_MODE_THIN_DEFERRED) out->gloss = round(out->gloss * 255.0) / 255.0;
    if (mode == TL_MODE_THIN_DEFERRED) {
        double lum = 0.2126 * out->specular[0] + 0.7152 * out->specular[1] + 0.0722 * out->specular[2];
        double s = round(sqrt(lum) * 255.0) / 255.0;
        for (int k = 0; k < 3; k++) out->specular[k] = s * s;
    }
}
