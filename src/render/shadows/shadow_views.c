/* The shadow atlas's views for a frame (docs/shadows.md), on the CPU: which casting lights get a
 * map (by screen coverage times intensity, within the budget; a light gaining or losing its map
 * fades over TL__SHADOW_FADE_FRAMES frames), where their tiles lie (a buddy grid of power-of-two
 * squares, halved when the atlas is full), their matrices (spot: perspective; point: six cube
 * faces; directional: four sphere-fitted, texel-snapped cascades) and the bias coefficients the
 * lookup derives from the texel size and the depth formats. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <string.h>

#include "shadows.h"

/* ---- matrices ----------------------------------------------------------------------------------- */

static float tl__dot3(const float a[3], const float b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static float tl__norm3(const float a[3]) { return sqrtf(tl__dot3(a, a)); }

static void tl__cross3(const float a[3], const float b[3], float out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* World to a light's view looking along `f` (unit) from `eye`. */
static tl__mat4 tl__look(const float eye[3], const float f[3])
{
    float up[3] = {0.0f, 1.0f, 0.0f}, s[3], u[3];
    if (fabsf(f[1]) > 0.99f) up[1] = 0.0f, up[2] = 1.0f;
    tl__cross3(f, up, s);
    tl__vec3_normalize(s);
    tl__cross3(s, f, u);
    tl__mat4 m = {{0}};
    for (int k = 0; k < 3; k++) {
        m.m[k * 4 + 0] = s[k];
        m.m[k * 4 + 1] = u[k];
        m.m[k * 4 + 2] = -f[k];
    }
    m.m[12] = -tl__dot3(s, eye);
    m.m[13] = -tl__dot3(u, eye);
    m.m[14] = tl__dot3(f, eye);
    m.m[15] = 1.0f;
    return m;
}

/* Perspective (w = -z) with reversed depth, near 1 and far 0 (clip control [0, 1]): the atlas's one
 * convention whatever the frame's depth format. Standard GL depth would hold the light distance w
 * only to w^2 / n of a float step near 1, and the reference computed from camera-space positions
 * (terms of the camera's distances, not w) would err by float's step times those distances times
 * w / n: for a point light (n = radius / 1024) a thousand times the reversed map's error. */
static tl__mat4 tl__perspective(float tan_half, float n, float f)
{
    tl__mat4 m = {{0}};
    m.m[0] = m.m[5] = 1.0f / tan_half;
    m.m[11] = -1.0f;
    m.m[10] = n / (f - n);
    m.m[14] = n * f / (f - n);
    return m;
}

/* Orthographic over x, y in [-h, h] around (cx, cy) (light view), depth n..f reversed (1 to 0). */
static tl__mat4 tl__ortho(float cx, float cy, float h, float n, float f)
{
    tl__mat4 m = {{0}};
    m.m[0] = m.m[5] = 1.0f / h;
    m.m[12] = -cx / h;
    m.m[13] = -cy / h;
    m.m[10] = 1.0f / (f - n);
    m.m[14] = f / (f - n);
    m.m[15] = 1.0f;
    return m;
}

/* The inverse of a rigid view matrix (rotation and translation). */
static tl__mat4 tl__rigid_inverse(const tl__mat4 *v)
{
    tl__mat4 r = {{0}};
    const float *m = v->m;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r.m[j * 4 + i] = m[i * 4 + j];
    for (int i = 0; i < 3; i++) r.m[12 + i] = -(r.m[i] * m[12] + r.m[4 + i] * m[13] + r.m[8 + i] * m[14]);
    r.m[15] = 1.0f;
    return r;
}

/* ---- the atlas's tiles: a grid of cells (atlas / 32), power-of-two squares at aligned places ---- */

enum { TL__ATLAS_CELLS = 32 };

typedef struct tl__atlas_grid {
    uint8_t used[TL__ATLAS_CELLS][TL__ATLAS_CELLS];
    uint32_t cell; /* texels a cell */
} tl__atlas_grid;

static int tl__atlas_alloc(tl__atlas_grid *g, uint32_t size, uint32_t *x, uint32_t *y)
{
    uint32_t c = size / g->cell;
    for (uint32_t cy = 0; cy + c <= TL__ATLAS_CELLS; cy += c)
        for (uint32_t cx = 0; cx + c <= TL__ATLAS_CELLS; cx += c) {
            int free_block = 1;
            for (uint32_t j = 0; j < c && free_block; j++)
                for (uint32_t i = 0; i < c && free_block; i++) free_block = !g->used[cy + j][cx + i];
            if (!free_block) continue;
            for (uint32_t j = 0; j < c; j++) memset(&g->used[cy + j][cx], 1, c);
            *x = cx * g->cell;
            *y = cy * g->cell;
            return 1;
        }
    return 0;
}

static uint32_t tl__kind_views(int kind)
{
    return kind == TL_LIGHT_POINT ? 6u : kind == TL_LIGHT_SPOT ? 1u : (uint32_t)TL__SHADOW_CASCADES;
}

/* Tile sides, in cells, of the lights that get a map (in rank order, `kinds`): each light takes the
 * largest side its kind allows (directional 8 cells, a quarter of the atlas; spot and point 4, an
 * eighth) whose views leave every later light room at one cell (1/32 of the atlas): the budget's
 * 64 point lights need 384 of the 1024 cells, so every light in it gets a map. */
static void tl__tile_sides(const int *kinds, size_t n, uint32_t *sides)
{
    uint32_t reserve = 0, left = TL__ATLAS_CELLS * TL__ATLAS_CELLS;
    for (size_t j = 0; j < n; j++) reserve += tl__kind_views(kinds[j]);
    for (size_t j = 0; j < n; j++) {
        uint32_t views = tl__kind_views(kinds[j]), c = kinds[j] == TL_LIGHT_DIRECTIONAL ? 8u : 4u;
        reserve -= views;
        while (c > 1 && views * c * c > left - reserve) c /= 2;
        sides[j] = c;
        left -= views * c * c;
    }
}

/* Places the tiles, largest first (then by rank): aligned power-of-two squares placed in falling
 * size each find a free aligned square while their area fits, so none fails. xy: 2 x 6 per light. */
static void tl__tile_place(const int *kinds, const uint32_t *sides, size_t n, uint32_t cell, uint32_t (*xy)[12])
{
    tl__atlas_grid grid;
    memset(&grid, 0, sizeof grid);
    grid.cell = cell;
    for (uint32_t c = 8; c >= 1; c /= 2)
        for (size_t j = 0; j < n; j++)
            for (uint32_t v = 0; sides[j] == c && v < tl__kind_views(kinds[j]); v++)
                tl__atlas_alloc(&grid, c * cell, &xy[j][2 * v], &xy[j][2 * v + 1]);
}

/* ---- selection ------------------------------------------------------------------------------ */

static tl_result tl__shadow_arrays(tl__device *dev, tl__shadows *s, size_t count)
{
    if (count <= s->light_capacity) return TL_OK;
    float *slots = (float *)tl__calloc(&dev->alloc, count, sizeof *slots);
    float *fade = (float *)tl__calloc(&dev->alloc, count, sizeof *fade);
    float *score = (float *)tl__calloc(&dev->alloc, count, sizeof *score);
    uint32_t *order = (uint32_t *)tl__calloc(&dev->alloc, count, sizeof *order);
    if (!slots || !fade || !score || !order) {
        void *a[] = {slots, fade, score, order};
        for (int i = 0; i < 4; i++) tl__free(&dev->alloc, a[i]);
        return tl__fail(dev, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for %zu lights' shadows", count);
    }
    if (s->light_capacity) memcpy(fade, s->fade, s->light_capacity * sizeof *fade);
    void *old[] = {s->slots, s->fade, s->score, s->order};
    for (int i = 0; i < 4; i++) tl__free(&dev->alloc, old[i]);
    s->slots = slots;
    s->fade = fade;
    s->score = score;
    s->order = order;
    s->light_capacity = count;
    return TL_OK;
}

static int tl__light_kind(const tl_light *l) { return l->type == TL_LIGHT_DEFAULT ? TL_LIGHT_POINT : (int)l->type; }

/* A casting light's priority: directional lights first, then the light's solid angle on screen
 * (its range over its distance, 1 when the camera is inside it) times its brightest channel; 0
 * when it cannot reach the view. */
static float tl__shadow_score(const tl_light *l, const tl__view *v)
{
    float c = fmaxf(l->color[0], fmaxf(l->color[1], l->color[2]));
    if (tl__light_kind(l) == TL_LIGHT_DIRECTIONAL) return FLT_MAX;
    if (c <= 0.0f || !tl__sphere_visible((float(*)[4])v->planes, l->position, l->radius)) return 0.0f;
    float d2 = 0.0f;
    for (int k = 0; k < 3; k++) d2 += (l->position[k] - v->eye[k]) * (l->position[k] - v->eye[k]);
    float cover = d2 > l->radius * l->radius ? l->radius * l->radius / d2 : 1.0f;
    return cover * c;
}

/* Casting lights with a score, by score (insertion sort: casting lights are few); returns their count. */
static size_t tl__shadow_order(tl__shadows *s, const tl__lights *l, const tl__view *v)
{
    size_t n = 0;
    for (size_t i = 0; i < l->count; i++) {
        s->slots[i] = 0.0f;
        s->score[i] = l->lights[i].shadow ? tl__shadow_score(&l->lights[i], v) : 0.0f;
        if (s->score[i] <= 0.0f && s->fade[i] <= 0.0f) continue;
        size_t j = n++;
        for (; j > 0 && s->score[s->order[j - 1]] < s->score[i]; j--) s->order[j] = s->order[j - 1];
        s->order[j] = (uint32_t)i;
    }
    return n;
}

/* ---- views ---------------------------------------------------------------------------------- */

/* What building a light's views needs. */
typedef struct tl__view_ctx {
    const tl__view *v;
    tl__mat4 view_inv;   /* camera view to world */
    uint32_t atlas;      /* side in texels */
    uint32_t pcf;        /* kernel radius (PCSS: its largest) */
    float light_size;    /* PCSS: the light's radius (world) or its disc's angular radius's tangent */
    float camera;        /* the camera's distance from the world's origin */
    const tl__scene_gpu *g;
} tl__view_ctx;

static uint64_t tl__fnv(uint64_t h, const void *data, size_t n)
{
    const uint8_t *p = (const uint8_t *)data;
    for (size_t i = 0; i < n; i++) h = (h ^ p[i]) * 1099511628211ull;
    return h;
}

/* Inside the clip volume's sides (and in front of a perspective view): the four side planes and w. */
static int tl__box_in_clip(const tl__mat4 *m, const float lo[3], const float hi[3])
{
    const float *a = m->m;
    for (int p = 0; p < 5; p++) {
        float pl[4];
        for (int i = 0; i < 4; i++) {
            float row3 = a[i * 4 + 3], row = p < 4 ? a[i * 4 + (p >> 1)] : 0.0f;
            pl[i] = p == 4 ? row3 : (p & 1) ? row3 - row : row3 + row;
        }
        float x = pl[0] >= 0 ? hi[0] : lo[0], y = pl[1] >= 0 ? hi[1] : lo[1], z = pl[2] >= 0 ? hi[2] : lo[2];
        if (pl[0] * x + pl[1] * y + pl[2] * z + pl[3] < 0) return 0;
    }
    return 1;
}

uint64_t tl__shadow_casters(const tl__scene_gpu *g, const tl__mat4 *world_clip,
                            void (*draw)(void *user, uint32_t object), void *user)
{
    uint64_t h = 14695981039346656037ull;
    for (size_t i = 0; i < g->object_count; i++) {
        const tl_object *o = &g->objects[i];
        if (!o->index_count || g->object_state[i] || o->primitive != TL_PRIMITIVE_TRIANGLES) continue;
        if (g->materials[o->material].flags & TL_MATERIAL_ALPHA_BLEND) continue;
        if (!tl__box_in_clip(world_clip, o->bounds_min, o->bounds_max)) continue;
        uint32_t id = (uint32_t)i;
        h = tl__fnv(h, &id, sizeof id);
        h = tl__fnv(h, o->transform, sizeof o->transform);
        if (draw) draw(user, id);
    }
    return h;
}

/* PCSS: the stored depth d to the light-space distance z (perspective: 1/z = x d + y, from clip
 * z = P22 z_view + P23 and w = -z_view; orthographic: z = x d + y) and the light's size in texels
 * (a radius R at the light: R / texel per w; a disc of angular radius a: tan a / texel). */
static void tl__view_depth(tl__shadow_view_gpu *gv, const tl__mat4 *proj, float texel_per_w, float size, int persp)
{
    float a = proj->m[10], b = proj->m[14];
    gv->depth[0] = persp ? 1.0f / b : -1.0f / a;
    gv->depth[1] = persp ? a / b : b / a;
    gv->depth[2] = size / texel_per_w;
    gv->depth[3] = (float)persp;
}

/* One view: its matrices for rendering and lookup, its tile, the bias coefficients. `persp`: a
 * perspective view (else orthographic); n and f its depth range; `eye` its eye's distance from the
 * world's origin. */
static void tl__view_add(tl__shadows *s, const tl__view_ctx *c, const tl__mat4 *proj, const tl__mat4 *look,
                         float texel_per_w, float n, float f, int persp, float eye, uint32_t x, uint32_t y, uint32_t size)
{
    size_t i = s->view_count++;
    tl__shadow_view *sv = &s->views[i];
    tl__shadow_view_gpu *gv = &s->views_gpu[i];
    sv->world_clip = tl__mat4_mul(proj, look);
    sv->x = x, sv->y = y, sv->size = size;
    sv->near_z = n, sv->far_z = f, sv->perspective = persp;
    tl__mat4 m = tl__mat4_mul(&sv->world_clip, &c->view_inv);
    memcpy(gv->m, m.m, sizeof gv->m);
    float a = (float)c->atlas;
    gv->rect[0] = (float)x / a, gv->rect[1] = (float)y / a, gv->rect[2] = gv->rect[3] = (float)size / a;
    gv->texel[0] = texel_per_w;
    /* the atlas depth's quantum along the light, two float32 steps (the stored value's rounding
     * and the reference's arithmetic): reversed perspective, d = n (f - z) / (z (f - n)) steps d
     * 2^-23, z 2^-23 in z; orthographic, depth is linear over f - n */
    gv->texel[1] = persp ? 0.0f : 2.0f * ldexpf(1.0f, -24) * (f - n);
    gv->texel[2] = persp ? 2.0f * ldexpf(1.0f, -23) : 0.0f;
    /* the light distance both sides compute from coordinates of other origins (the lookup from
     * camera space, the shadow pass from object and world space) errs by float's step times those
     * coordinates' sizes (shadow.glsl's e_arith): here their part that does not depend on the point,
     * 2 |eye| + 3 |camera| (world; a cascade's eye is the origin) */
    gv->texel[3] = 2.0f * eye + 3.0f * c->camera;
    tl__view_depth(gv, proj, texel_per_w, c->light_size, persp);
    uint64_t h = tl__fnv(14695981039346656037ull, sv->world_clip.m, sizeof sv->world_clip.m);
    uint32_t tile[3] = {x, y, size};
    h = tl__fnv(h, tile, sizeof tile);
    sv->signature = h ^ tl__shadow_casters(c->g, &sv->world_clip, NULL, NULL);
    if (!sv->signature) sv->signature = 1;
}

/* The tangent of a view's half angle that keeps the kernel and the bias's reach inside its tile
 * for points within `tan_half` (shadow.glsl's margin). */
static float tl__tan_margin(float tan_half, uint32_t pcf, uint32_t size)
{
    return tan_half / (1.0f - 2.0f * ((float)pcf + 2.0f) / (float)size);
}

static void tl__spot_views(tl__shadows *s, const tl__view_ctx *c, const tl_light *l, const uint32_t *xy, uint32_t size)
{
    float dir[3] = {l->direction[0], l->direction[1], l->direction[2]};
    tl__vec3_normalize(dir);
    float co = fmaxf(l->cos_outer, 0.17f); /* at most 80 degrees off the axis: wider cones lose the rest */
    float tan_half = tl__tan_margin(sqrtf(1.0f - co * co) / co, c->pcf, size);
    float n = l->radius / 1024.0f, f = l->radius;
    tl__mat4 look = tl__look(l->position, dir), proj = tl__perspective(tan_half, n, f);
    tl__view_add(s, c, &proj, &look, 2.0f * tan_half / (float)size, n, f, 1, tl__norm3(l->position), xy[0], xy[1], size);
}

static void tl__point_views(tl__shadows *s, const tl__view_ctx *c, const tl_light *l, const uint32_t *xy, uint32_t size)
{
    static const float dirs[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    float tan_half = tl__tan_margin(1.0f, c->pcf, size);
    float n = l->radius / 1024.0f, f = l->radius;
    tl__mat4 proj = tl__perspective(tan_half, n, f);
    for (int k = 0; k < 6; k++) {
        tl__mat4 look = tl__look(l->position, dirs[k]);
        tl__view_add(s, c, &proj, &look, 2.0f * tan_half / (float)size, n, f, 1, tl__norm3(l->position), xy[2 * k],
                     xy[2 * k + 1], size);
    }
}

/* The camera's distance range the cascades cover: near plane to the farthest scene corner (or far). */
static float tl__cascade_far(const tl__view_ctx *c)
{
    const tl__scene_gpu *g = c->g;
    float far = c->v->info.far_z > 0.0f ? c->v->info.far_z : FLT_MAX, d = 0.0f;
    if (!g->has_bounds) return fminf(far, c->v->near_z * 1000.0f);
    for (int k = 0; k < 8; k++) {
        float p[3] = {(k & 1) ? g->bounds_max[0] : g->bounds_min[0], (k & 2) ? g->bounds_max[1] : g->bounds_min[1],
                      (k & 4) ? g->bounds_max[2] : g->bounds_min[2]};
        float e = 0.0f;
        for (int a = 0; a < 3; a++) e += (p[a] - c->v->eye[a]) * (p[a] - c->v->eye[a]);
        d = fmaxf(d, sqrtf(e));
    }
    return fminf(far, fmaxf(d, c->v->near_z * 2.0f));
}

/* The light's depth range over the scene's bounds and the cascade's sphere (light view `look`). */
static void tl__cascade_depth(const tl__view_ctx *c, const tl__mat4 *look, const float centre[3], float radius,
                              float *n, float *f)
{
    const tl__scene_gpu *g = c->g;
    *n = -centre[2] - radius;
    *f = -centre[2] + radius;
    for (int k = 0; g->has_bounds && k < 8; k++) {
        float p[3] = {(k & 1) ? g->bounds_max[0] : g->bounds_min[0], (k & 2) ? g->bounds_max[1] : g->bounds_min[1],
                      (k & 4) ? g->bounds_max[2] : g->bounds_min[2]};
        const float *m = look->m;
        float z = m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14];
        *n = fminf(*n, -z);
        *f = fmaxf(*f, -z);
    }
    float pad = (*f - *n) * 0.01f + radius * 0.01f;
    *n -= pad;
    *f += pad;
}

/* Four cascades: the camera's distance range split logarithmically, each slice's bounding
 * sphere (its radius depends only on the slice and the field of view, so it does not change when the
 * camera turns) and its centre snapped to whole texels in the light's view (no shimmer when it moves). */
static void tl__cascade_views(tl__shadows *s, const tl__view_ctx *c, const tl_light *l, const uint32_t *xy,
                              uint32_t size, float splits[4])
{
    float dir[3] = {l->direction[0], l->direction[1], l->direction[2]}, origin[3] = {0, 0, 0};
    tl__vec3_normalize(dir);
    tl__mat4 look = tl__look(origin, dir);
    float tx = 1.0f / c->v->proj.m[0], ty = 1.0f / c->v->proj.m[5], k2 = tx * tx + ty * ty;
    /* logarithmic splits from far / 1000 (a near plane far closer than that would spend the first
     * cascades on centimetres), the first cascade reaching down to the near plane */
    float far = tl__cascade_far(c), near = fmaxf(c->v->near_z, far * 1e-3f);
    for (int i = 0; i < TL__SHADOW_CASCADES; i++) {
        float t0 = (float)i / TL__SHADOW_CASCADES, t1 = (float)(i + 1) / TL__SHADOW_CASCADES;
        float a = i ? near * powf(far / near, t0) : c->v->near_z, b = near * powf(far / near, t1);
        splits[i] = b;
        float zc = 0.5f * (a + b) * (1.0f + k2), r;
        if (zc >= b) zc = b, r = b * sqrtf(k2);
        else r = sqrtf((zc - a) * (zc - a) + a * a * k2);
        r = tl__tan_margin(r, c->pcf, size); /* the kernel's reach stays inside the tile */
        float w[3], cl[3];
        for (int k = 0; k < 3; k++) w[k] = c->view_inv.m[8 + k] * -zc + c->view_inv.m[12 + k];
        for (int k = 0; k < 3; k++) cl[k] = look.m[k] * w[0] + look.m[4 + k] * w[1] + look.m[8 + k] * w[2] + look.m[12 + k];
        float texel = 2.0f * r / (float)size;
        cl[0] = floorf(cl[0] / texel) * texel;
        cl[1] = floorf(cl[1] / texel) * texel;
        float n, f;
        tl__cascade_depth(c, &look, cl, r, &n, &f);
        tl__mat4 proj = tl__ortho(cl[0], cl[1], r, n, f);
        tl__view_add(s, c, &proj, &look, texel, n, f, 0, 0.0f, xy[2 * i], xy[2 * i + 1], size);
    }
}

/* ---- the frame ------------------------------------------------------------------------------ */

/* Fades: a light in the budget gains its shadow at once when it takes a free place (nothing is
 * displaced: the first frame, fewer casting lights than the budget) and over
 * TL__SHADOW_FADE_FRAMES frames when it displaces another; a light leaving the budget keeps its map
 * while its shadow fades out. */
static void tl__shadow_fades(tl__shadows *s, size_t casting, uint32_t budget)
{
    size_t selected = 0;
    int displacing = s->light_count >= budget;
    for (size_t j = 0; j < casting; j++) {
        uint32_t i = s->order[j];
        float step = 1.0f / TL__SHADOW_FADE_FRAMES;
        if (s->score[i] > 0.0f && selected < budget) {
            selected++;
            s->fade[i] = displacing ? fminf(1.0f, s->fade[i] + step) : 1.0f;
        } else {
            s->fade[i] = fmaxf(0.0f, s->fade[i] - step);
        }
    }
}

/* The angular error bound (radians) of the normal the lighting passes read: RT0's octahedral code
 * rounds each of its two coordinates by half a cell c = 2 / (2^bits - 1), which moves the unnormalised
 * point (u, v, 1 - |u| - |v|) by at most c sqrt(3/2), and normalising (|point| >= 1/sqrt(3)) turns
 * that into at most c sqrt(3/2) sqrt(3) = 2.12 c radians; fat's half floats round each component by
 * 2^-11 relative; forward interpolates float normals (2^-22 for the interpolation and normalising). */
static float tl__normal_error(const tl_renderer_options *o)
{
    if (o->mode == TL_MODE_FAT) return ldexpf(1.0f, -11);
    if (o->mode == TL_MODE_FORWARD) return ldexpf(1.0f, -22);
    float cells = o->rt0 == TL_RT0_RGB10A2 ? 1023.0f : 4095.0f; /* 2 x 10 or 2 x 12 bits */
    return 2.0f / cells * sqrtf(1.5f) * sqrtf(3.0f);
}

/* The lookup's constants; `reversed`: the frame's depth format (the G-buffer's position error). */
static void tl__shadow_block_params(tl__shadows *s, const tl__view *v, const tl_renderer_options *o, int reversed)
{
    s->block.params[0] = 1.0f / (float)o->shadows.atlas_size;
    s->block.params[1] = (float)o->shadows.pcf_radius;
    /* the position rebuilt from the G-buffer's depth: reversed D32F keeps z to 2^-23 relative, two
     * steps (the stored value's rounding and the reconstruction's arithmetic); D24 steps 2^-24 in
     * window depth, z^2 (f - n) / (f n) 2^-24 in z, four steps: the vertex's projection, the
     * rasterizer's float interpolation (one float ulp below 1 is one D24 step), the conversion to
     * 24 bits (rounded or truncated) and the read back with the reconstruction's rounded m[10] */
    float n = v->near_z, f = v->info.far_z;
    s->block.params[2] = reversed ? ldexpf(1.0f, -22) : 0.0f;
    s->block.params[3] = reversed ? 0.0f : ldexpf(1.0f, -22) * (f > 0.0f ? (f - n) / (f * n) : 1.0f / n);
    s->block.flags[1] = o->shadows.filter == TL_SHADOW_FILTER_PCSS ? TL__SHADOW_PCSS_RADIUS : 0u;
    s->block.bias[0] = tl__normal_error(o);
}

/* One mapped light's record and views; its slot is the record + 1. */
static void tl__shadow_light_record(tl__shadows *s, tl__view_ctx *c, const tl_light *li, uint32_t i, int kind,
                                    const uint32_t *xy, uint32_t size, float angle)
{
    tl__shadow_light_gpu *rec = &s->block.lights[s->light_count];
    c->light_size = kind == TL_LIGHT_DIRECTIONAL ? tanf(angle) : li->source_radius;
    rec->info[0] = (uint32_t)s->view_count;
    if (kind == TL_LIGHT_SPOT) tl__spot_views(s, c, li, xy, size);
    else if (kind == TL_LIGHT_POINT) tl__point_views(s, c, li, xy, size);
    else tl__cascade_views(s, c, li, xy, size, rec->splits);
    rec->info[1] = (uint32_t)s->view_count - rec->info[0];
    for (uint32_t k = rec->info[0]; k < s->view_count; k++) {
        s->views[k].light = i, s->views[k].index = k - rec->info[0];
        s->views[k].split = kind == TL_LIGHT_DIRECTIONAL ? rec->splits[k - rec->info[0]] : 0.0f;
    }
    rec->info[2] = (uint32_t)kind;
    rec->fade[0] = s->fade[i];
    rec->fade[1] = (float)size;
    s->slots[i] = (float)(++s->light_count);
}

/* The frame's figures, and once per new largest count a warning naming the casting lights in view
 * left without a map and why (the budget: the lookup holds at most TL__SHADOW_MAX_LIGHTS). */
static void tl__shadow_stats(tl__device *dev, tl__shadows *s, size_t casting, const tl_renderer_options *o,
                             tl_frame_stats *st)
{
    uint32_t in_view = 0, mapped = 0, fading = 0;
    for (size_t j = 0; j < casting; j++) {
        uint32_t i = s->order[j];
        in_view += s->score[i] > 0.0f;
        mapped += s->score[i] > 0.0f && s->slots[i] > 0.0f;
        fading += s->slots[i] > 0.0f && s->fade[i] < 1.0f;
    }
    st->shadow_lights = (uint32_t)s->light_count;
    st->shadow_lights_fading = fading;
    st->shadow_lights_unmapped = in_view - mapped;
    st->shadow_atlas_bytes = (size_t)o->shadows.atlas_size * o->shadows.atlas_size * 4u;
    if (in_view - mapped <= s->unmapped_logged) return;
    s->unmapped_logged = in_view - mapped;
    tl__log_message(&dev->log, TL_LOG_WARNING,
                    "renderer: %u of %u casting lights in view have no shadow map: shadows.max_lights = %u "
                    "(the most lights given a map per frame, 1..%d; the brightest and nearest first)",
                    in_view - mapped, in_view, o->shadows.max_lights, TL__SHADOW_MAX_LIGHTS);
}

tl_result tl__shadows_prepare(tl__device *dev, tl__shadows *s, const tl__lights *l, const tl__scene_gpu *g,
                              const tl__view *v, const tl_renderer_options *o, tl_frame_stats *st)
{
    static const tl__program_src src = {"shadow.depth", "shadow_depth.vert.glsl", "shadow_depth.frag.glsl", NULL};
    tl_result res = tl__shadow_arrays(dev, s, l->count ? l->count : 1);
    if (res == TL_OK && !s->program) res = tl__program_get(dev, "shadow.depth", &src, NULL, NULL, &s->program);
    if (res != TL_OK) return res;
    /* the views hold the largest kernel: the PCF radius, or PCSS's largest */
    uint32_t reach = o->shadows.filter == TL_SHADOW_FILTER_PCSS ? TL__SHADOW_PCSS_RADIUS : o->shadows.pcf_radius;
    tl__view_ctx c = {v, tl__rigid_inverse(&v->view), o->shadows.atlas_size, reach, 0.0f, tl__norm3(v->eye), g};
    size_t casting = tl__shadow_order(s, l, v);
    tl__shadow_fades(s, casting, o->shadows.max_lights);
    /* every light with a shadow strength gets a map, in rank order, as many as the lookup holds */
    uint32_t mapped[TL__SHADOW_MAX_LIGHTS], sides[TL__SHADOW_MAX_LIGHTS], xy[TL__SHADOW_MAX_LIGHTS][12];
    int kinds[TL__SHADOW_MAX_LIGHTS];
    size_t n = 0;
    for (size_t j = 0; j < casting && n < TL__SHADOW_MAX_LIGHTS; j++)
        if (s->fade[s->order[j]] > 0.0f) mapped[n] = s->order[j], kinds[n] = tl__light_kind(&l->lights[mapped[n]]), n++;
    uint32_t cell = o->shadows.atlas_size / TL__ATLAS_CELLS;
    tl__tile_sides(kinds, n, sides);
    tl__tile_place(kinds, sides, n, cell, xy);
    s->view_count = s->light_count = 0;
    memset(s->block.lights, 0, sizeof s->block.lights);
    for (size_t j = 0; j < n; j++)
        tl__shadow_light_record(s, &c, &l->lights[mapped[j]], mapped[j], kinds[j], xy[j], sides[j] * cell,
                         o->shadows.directional_angle);
    tl__shadow_block_params(s, v, o, o->depth_format == TL_DEPTH_FORMAT_D32F_REVERSED);
    for (size_t i = 0; i < s->view_count; i++)
        s->views[i].render = o->shadows.cache == TL_SWITCH_OFF || i >= s->kept_count || s->kept[i] != s->views[i].signature;
    tl__shadow_stats(dev, s, casting, o, st);
    return TL_OK;
}
