/* The stability cases' hand-made scenes, one rendered frame and reading its targets (stability.h). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "stability.h"

/* ---- renderer, small hand-made scenes --------------------------------------------------------- */

tl_material plain_material(float albedo, float specular, float gloss)
{
    tl_material m = {.alpha = 1.0f};
    for (int k = 0; k < 3; k++) {
        m.albedo[k] = albedo;
        m.specular[k] = specular;
    }
    m.gloss = gloss;
    return m;
}

/* Camera at the origin looking down -Z with +Y up: view space equals world space, so the lights
 * and surfaces below are given in view space directly. */
void mini_init(mini_scene *m, float fov_y, float near_z, float far_z)
{
    memset(m, 0, sizeof *m);
    m->mat[0] = plain_material(0.5f, 0.25f, 0.5f);
    m->s.vertices = m->v;
    m->s.indices = m->idx;
    m->s.objects = m->obj;
    m->s.materials = m->mat;
    m->s.material_count = 1;
    m->s.lights = m->light;
    m->s.camera = (tl_camera){{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, fov_y, near_z, far_z};
}

/* Adds a quad o, o+du, o+du+dv, o+dv (counter-clockwise seen from du x dv) as a new object. */
void add_quad(mini_scene *m, const float o[3], const float du[3], const float dv[3], uint32_t material)
{
    float n[3] = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
    float l = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    uint32_t b = (uint32_t)m->nv;
    tl_object *ob = &m->obj[m->s.object_count++];
    memcpy(ob->transform, identity, sizeof identity);
    ob->first_index = (uint32_t)m->ni;
    ob->index_count = 6;
    ob->material = material;
    for (int k = 0; k < 3; k++) ob->bounds_min[k] = FLT_MAX, ob->bounds_max[k] = -FLT_MAX;
    for (int i = 0; i < 4; i++) {
        float a = (float)(i == 1 || i == 2), c = (float)(i >= 2);
        tl_vertex *x = &m->v[m->nv++];
        memset(x, 0, sizeof *x);
        for (int k = 0; k < 3; k++) {
            x->position[k] = o[k] + a * du[k] + c * dv[k];
            x->normal[k] = l > 0.0f ? n[k] / l : 0.0f;
            ob->bounds_min[k] = fminf(ob->bounds_min[k], x->position[k]);
            ob->bounds_max[k] = fmaxf(ob->bounds_max[k], x->position[k]);
        }
        x->uv[0] = a;
        x->uv[1] = c;
    }
    static const uint32_t q[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 6; i++) m->idx[m->ni++] = b + q[i];
    m->s.vertex_count = m->nv;
    m->s.index_count = m->ni;
}

/* A wall facing the camera at distance `dist`, large enough to fill a 60-degree view. */
void add_wall(mini_scene *m, float dist, uint32_t material)
{
    float s = 2.0f * dist + 1.0f;
    add_quad(m, (float[3]){-s, -s, -dist}, (float[3]){2 * s, 0, 0}, (float[3]){0, 2 * s, 0}, material);
}

tl_light point_light(float x, float y, float z, float radius, float r, float g, float b)
{
    return (tl_light){.type = TL_LIGHT_POINT, .position = {x, y, z}, .direction = {0, -1, 0}, .color = {r, g, b},
                      .radius = radius};
}

/* ---- reading targets ---------------------------------------------------------------------- */

static void frame_free(frame *f)
{
    free(f->depth);
    free(f->rt0);
    free(f->diffuse);
    free(f->specular);
    free(f->hdr);
    memset(f, 0, sizeof *f);
}

/* Reads a target when the plan allocated it; NULL otherwise. */
float *read_target(tl_renderer *r, tl_target_id id)
{
    uint32_t w, h;
    tl_renderer_get_size(r, &w, &h);
    size_t n = (size_t)w * h * 4;
    float *buf = malloc(n * sizeof *buf);
    if (buf && tl_renderer_read_target(r, id, buf, &(size_t){n * sizeof *buf}) == TL_OK) return buf;
    free(buf);
    return NULL;
}

static void frame_read(tl_renderer *r, frame *f)
{
    memset(f, 0, sizeof *f);
    tl_renderer_get_size(r, &f->w, &f->h);
    f->depth = read_target(r, TL_TARGET_DEPTH);
    f->rt0 = read_target(r, TL_TARGET_RT0);
    f->diffuse = read_target(r, TL_TARGET_LIGHT_DIFFUSE);
    f->specular = read_target(r, TL_TARGET_LIGHT_SPECULAR);
    f->hdr = read_target(r, TL_TARGET_HDR);
}

/* Reads every target the plan allocated and counts non-finite values; returns the number of
 * targets read. Names the offending targets. */
size_t count_nonfinite_all_targets(tl_renderer *r, const char *label, size_t *bad_total)
{
    uint32_t w, h;
    tl_renderer_get_size(r, &w, &h);
    size_t n = (size_t)w * h * 4, targets = 0;
    float *buf = malloc(n * sizeof *buf);
    *bad_total = 0;
    for (int t = 0; buf && t < TL_TARGET_COUNT; t++) {
        if (tl_renderer_read_target(r, (tl_target_id)t, buf, &(size_t){n * sizeof *buf}) != TL_OK) continue;
        targets++;
        size_t bad = 0, first = 0;
        for (size_t i = 0; i < n; i++)
            if (!isfinite(buf[i])) {
                if (!bad) first = i;
                bad++;
            }
        if (bad)
            fprintf(stderr, "  %s: target %s holds %zu non-finite values (first at pixel %zu channel %zu: %g)\n",
                    label, tl_target_name((tl_target_id)t), bad, first / 4, first % 4, (double)buf[first]);
        *bad_total += bad;
    }
    free(buf);
    return targets;
}

/* ---- one rendered frame -------------------------------------------------------------------- */

/* The projection the renderer builds for the scene camera. */
static tl_projection projection_of(const tl_renderer_desc *d, const tl_camera *c, uint32_t w, uint32_t h)
{
    tl_projection p;
    tl_result res = tl_projection_perspective(d->options.depth_format, c->fov_y, (float)w / (float)h, c->near_z,
                                              c->far_z, &p);
    TL_CHECK(res == TL_OK);
    return p;
}

void run_free(run *u)
{
    frame_free(&u->f);
    tl_renderer_destroy(u->r);
    memset(u, 0, sizeof *u);
}

/* Creates a renderer, sets the scene, renders with the scene camera and reads the targets. */
int run_scene(run *u, tl_renderer_desc d, const tl_scene *s, const char *label)
{
    memset(u, 0, sizeof *u);
    if (!ensure_context()) {
        TL_CHECK(!"no GL context");
        return 0;
    }
    u->desc = d;
    if (!d.options.fxaa) d.options.fxaa = TL_FXAA_OFF;
    u->r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = d, .readable = true}); /* every target is read back */
    if (!u->r) return 0;
    tl_result res = tl_renderer_set_scene(u->r, s);
    if (res != TL_OK)
        fprintf(stderr, "  %s: set_scene: %s (%s)\n", label, tl_result_string(res), tl_renderer_last_error(u->r));
    TL_CHECK(res == TL_OK);
    if (res == TL_OK) {
        res = tl_renderer_render(u->r, NULL, &u->stats);
        if (res != TL_OK)
            fprintf(stderr, "  %s: render: %s (%s)\n", label, tl_result_string(res), tl_renderer_last_error(u->r));
        TL_CHECK(res == TL_OK);
    }
    if (res != TL_OK) {
        run_free(u);
        return 0;
    }
    frame_read(u->r, &u->f);
    TL_CHECK(u->f.depth && u->f.hdr); /* RT0 and the light buffer only when the plan has lights */
    u->pr = projection_of(&d, &s->camera, u->f.w, u->f.h);
    u->clear = d.options.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED ? 0.0f : 1.0f;
    return u->f.depth && u->f.hdr;
}

void check_all_targets_finite(run *u, const char *label)
{
    size_t bad = 0, n = count_nonfinite_all_targets(u->r, label, &bad);
    TL_CHECK(n >= 3); /* depth, HDR, output at least */
    TL_CHECK_EQ_U(bad, 0);
}
