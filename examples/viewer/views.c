/* The debug views: each reads the frame's targets back through the public API
 * (tl_renderer_read_target, which decodes RT0 and linearises depth and splits visibility's id;
 * tl_albedo_reconstruct for RT1's chroma; an application pass for the tiled light lists, and in
 * visibility one whose read keeps RT0) and turns them into RGBA8, rows bottom to top. The grid puts
 * every view in one image; the split view two modes side by side. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "legend.h"
#include "thinlight/codec.h"
#include "viewer.h"

typedef int (*vw_view_fn)(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out);
/* A view that maps a scalar to colours fills its legend (title, end values, colour map). */
typedef void (*vw_legend_fn)(const vw_app *app, vw_legend *l);

typedef struct vw_view_def {
    const char *name;
    const char *help;
    vw_view_fn build;
    vw_legend_fn legend; /* NULL: the view shows colours, not a scale */
} vw_view_def;

/* GL beyond 1.1, for the light lists' storage buffer. */
typedef void (*vw_barrier_fn)(unsigned int);
typedef void (*vw_buffer_read_fn)(unsigned int, intptr_t, intptr_t, void *);
typedef struct vw_gl {
    vw_barrier_fn memory_barrier;
    vw_buffer_read_fn get_named_buffer_sub_data;
} vw_gl;
#define VW_GL_BUFFER_UPDATE_BARRIER_BIT 0x00000200u

static size_t vw_pixels(const vw_app *app) { return (size_t)app->width * app->height; }

static uint8_t vw_u8(float v) { return (uint8_t)(v <= 0.0f ? 0 : v >= 1.0f ? 255 : (int)(v * 255.0f + 0.5f)); }

static void vw_put(uint8_t *px, float r, float g, float b)
{
    px[0] = vw_u8(r);
    px[1] = vw_u8(g);
    px[2] = vw_u8(b);
    px[3] = 255;
}

static void vw_put_srgb(uint8_t *px, float r, float g, float b)
{
    vw_put(px, tl_linear_to_srgb(r), tl_linear_to_srgb(g), tl_linear_to_srgb(b));
}

void vw_heat(float t, uint8_t rgb[3])
{
    static const float stops[6][3] = {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}, {1, 1, 1}};
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    float f = t * 5.0f;
    int i = f >= 5.0f ? 4 : (int)f;
    float a = f - (float)i;
    for (int c = 0; c < 3; c++) rgb[c] = vw_u8(stops[i][c] * (1 - a) + stops[i + 1][c] * a);
}

/* A target as 4 floats a pixel into scratch[slot]; 0 when the plan has none. */
static const float *vw_read(vw_app *app, tl_renderer *r, tl_target_id t, int slot)
{
    size_t size = vw_pixels(app) * 16;
    if (r == app->r && !(app->plan.targets & TL_TARGET_BIT(t))) return NULL; /* not in this mode */
    if (tl_renderer_read_target(r, t, app->scratch[slot], &size) != TL_OK) return NULL;
    return app->scratch[slot];
}

static int vw_is_background(const vw_app *app, const float *depth, size_t i)
{
    float clear = app->desc.options.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED ? 0.0f : 1.0f;
    return depth[4 * i] == clear;
}

static int vw_unavailable(vw_app *app, const char *why)
{
    snprintf(app->view_note, sizeof app->view_note, "%s", why);
    return 1;
}

static int vw_fat(const vw_app *app) { return app->desc.options.mode == TL_MODE_FAT; }

/* ---- the views ------------------------------------------------------------------------------ */

static int vw_view_final(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    size_t size = vw_pixels(app) * 4;
    return tl_renderer_read_output(r, out, &size) != TL_OK ? vw_unavailable(app, "no output") : 0;
}

static int vw_view_normals_gloss(vw_app *app, tl_renderer *r, uint8_t *out, int gloss)
{
    /* visibility writes RT0 when something reads it: here the viewer's own pass (vw_views_app_passes) */
    const float *ng = vw_read(app, r, vw_fat(app) ? TL_TARGET_FAT_NORMAL : TL_TARGET_RT0, 0);
    const float *d = vw_read(app, r, TL_TARGET_DEPTH, 1);
    if (!ng || !d) return vw_unavailable(app, "no G-buffer normals in this mode");
    for (size_t i = 0, n = vw_pixels(app); i < n; i++) {
        const float *p = ng + 4 * i;
        if (vw_is_background(app, d, i)) vw_put(out + 4 * i, 0, 0, 0);
        else if (gloss) vw_put(out + 4 * i, p[3], p[3], p[3]);
        else vw_put(out + 4 * i, p[0] * 0.5f + 0.5f, p[1] * 0.5f + 0.5f, p[2] * 0.5f + 0.5f);
    }
    return 0;
}

static int vw_view_normals(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    return vw_view_normals_gloss(app, r, out, 0);
}

static int vw_view_gloss(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    return vw_view_normals_gloss(app, r, out, 1);
}

/* RT1: channel 0 luma, 1 the pixel's own chroma (Cb where x + y is even, Cr where odd). */
static int vw_view_rt1(vw_app *app, tl_renderer *r, uint8_t *out, int chroma)
{
    const float *t = vw_read(app, r, TL_TARGET_RT1, 0);
    const float *d = vw_read(app, r, TL_TARGET_DEPTH, 1);
    if (!t || !d) return vw_unavailable(app, "RT1 (luma, chroma) exists in thin-deferred only");
    for (uint32_t y = 0; y < app->height; y++)
        for (uint32_t x = 0; x < app->width; x++) {
            size_t i = (size_t)y * app->width + x;
            float v = t[4 * i], c = t[4 * i + 1], rgb[3];
            if (vw_is_background(app, d, i)) { vw_put(out + 4 * i, 0, 0, 0); continue; }
            if (!chroma) { vw_put(out + 4 * i, v, v, v); continue; }
            float ycc[3] = {0.5f, 0.5f, 0.5f};
            ycc[1 + tl_chroma_parity(x, y)] = c;
            tl_luma_chroma_to_rgb(TL_COLOR_SPACE_YCBCR, ycc, rgb);
            vw_put(out + 4 * i, rgb[0], rgb[1], rgb[2]);
        }
    return 0;
}

static int vw_view_luma(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    return vw_view_rt1(app, r, out, 0);
}

static int vw_view_chroma(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    return vw_view_rt1(app, r, out, 1);
}

/* Thin: the codec's own reconstruction (edge-aware filter, YCbCr) of RT1's bytes, sRGB as stored. */
static int vw_view_albedo(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    size_t n = vw_pixels(app);
    const float *d = vw_read(app, r, TL_TARGET_DEPTH, 1);
    if (vw_fat(app)) {
        const float *a = vw_read(app, r, TL_TARGET_FAT_ALBEDO, 0);
        if (!a || !d) return vw_unavailable(app, "no albedo target");
        for (size_t i = 0; i < n; i++)
            if (vw_is_background(app, d, i)) vw_put(out + 4 * i, 0, 0, 0);
            else vw_put_srgb(out + 4 * i, a[4 * i], a[4 * i + 1], a[4 * i + 2]);
        return 0;
    }
    const float *t = vw_read(app, r, TL_TARGET_RT1, 0);
    if (!t || !d) return vw_unavailable(app, "albedo is stored in thin-deferred and fat only");
    uint8_t *yc = app->scratch8[1];
    for (size_t i = 0; i < n; i++) {
        yc[2 * i] = vw_u8(t[4 * i]);
        yc[2 * i + 1] = vw_u8(t[4 * i + 1]);
    }
    float *rgb = app->scratch[2];
    if (tl_albedo_reconstruct(TL_COLOR_SPACE_YCBCR, TL_CHROMA_FILTER_EDGE, yc, app->width, app->height, rgb) != TL_OK)
        return vw_unavailable(app, "albedo reconstruction failed");
    for (size_t i = 0; i < n; i++)
        if (vw_is_background(app, d, i)) vw_put(out + 4 * i, 0, 0, 0);
        else vw_put(out + 4 * i, rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]);
    return 0;
}

/* Log scale from the nearest covered pixel (white) to the farthest (black). */
static int vw_view_depth(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    const float *d = vw_read(app, r, TL_TARGET_DEPTH, 1);
    if (!d) return vw_unavailable(app, "no depth target");
    size_t n = vw_pixels(app);
    float near_z = 1e30f, far_z = 0;
    for (size_t i = 0; i < n; i++)
        if (!vw_is_background(app, d, i) && d[4 * i + 1] > 0) {
            if (d[4 * i + 1] < near_z) near_z = d[4 * i + 1];
            if (d[4 * i + 1] > far_z) far_z = d[4 * i + 1];
        }
    app->depth_range[0] = near_z;
    app->depth_range[1] = far_z;
    float scale = far_z > near_z * 1.0001f ? 1.0f / logf(far_z / near_z) : 0.0f;
    for (size_t i = 0; i < n; i++) {
        float z = d[4 * i + 1] > near_z ? d[4 * i + 1] : near_z;
        float v = vw_is_background(app, d, i) ? 0.0f : 1.0f - 0.9f * logf(z / near_z) * scale;
        vw_put(out + 4 * i, v, v, v);
    }
    return 0;
}

typedef struct vw_basis {
    float eye[3], right[3], up[3], fwd[3];
    float tan_x, tan_y;
} vw_basis;

static void vw_normalize(float v[3])
{
    float l = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0) for (int i = 0; i < 3; i++) v[i] /= l;
}

static void vw_cross(const float a[3], const float b[3], float o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static void vw_camera_basis(const vw_app *app, const tl_camera *cam, vw_basis *b)
{
    float up[3] = {cam->up[0], cam->up[1], cam->up[2]};
    if (up[0] == 0 && up[1] == 0 && up[2] == 0) up[1] = 1;
    for (int i = 0; i < 3; i++) { b->eye[i] = cam->position[i]; b->fwd[i] = cam->target[i] - cam->position[i]; }
    vw_normalize(b->fwd);
    vw_cross(b->fwd, up, b->right);
    vw_normalize(b->right);
    vw_cross(b->right, b->fwd, b->up);
    float fov = cam->fov_y > 0 ? cam->fov_y : 1.04719755f;
    b->tan_y = tanf(fov * 0.5f);
    b->tan_x = b->tan_y * (float)app->width / (float)app->height;
}

/* World position rebuilt from linear depth along the pixel's ray (fat: its view-space position
 * target), shown as (p - scene min) / (scene max - scene min). */
static int vw_view_position(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    const float *d = vw_read(app, r, TL_TARGET_DEPTH, 1);
    const float *fp = vw_fat(app) ? vw_read(app, r, TL_TARGET_FAT_POSITION, 0) : NULL;
    if (!d || (vw_fat(app) && !fp)) return vw_unavailable(app, "no depth target");
    vw_basis b;
    vw_camera_basis(app, cam, &b);
    const float *lo = app->scene->bounds_min, *hi = app->scene->bounds_max;
    for (uint32_t y = 0; y < app->height; y++)
        for (uint32_t x = 0; x < app->width; x++) {
            size_t i = (size_t)y * app->width + x;
            if (vw_is_background(app, d, i)) { vw_put(out + 4 * i, 0, 0, 0); continue; }
            float z = d[4 * i + 1];
            float vx = ((2.0f * ((float)x + 0.5f) / (float)app->width) - 1.0f) * b.tan_x * z;
            float vy = ((2.0f * ((float)y + 0.5f) / (float)app->height) - 1.0f) * b.tan_y * z;
            if (fp) { vx = fp[4 * i]; vy = fp[4 * i + 1]; z = -fp[4 * i + 2]; }
            float c[3];
            for (int k = 0; k < 3; k++) {
                float w = b.eye[k] + b.right[k] * vx + b.up[k] * vy + b.fwd[k] * z;
                c[k] = hi[k] > lo[k] ? (w - lo[k]) / (hi[k] - lo[k]) : 0.5f;
            }
            vw_put(out + 4 * i, c[0], c[1], c[2]);
        }
    return 0;
}

/* Radiance-like values: times exposure, Reinhard x / (1 + x), sRGB. */
static void vw_put_hdr(uint8_t *px, float e, float r, float g, float b, int reinhard)
{
    r *= e; g *= e; b *= e;
    if (reinhard) { r /= 1 + r; g /= 1 + g; b /= 1 + b; }
    vw_put_srgb(px, r, g, b);
}

static int vw_view_light(vw_app *app, tl_renderer *r, uint8_t *out, int specular)
{
    const float *dif = vw_read(app, r, TL_TARGET_LIGHT_DIFFUSE, 0);
    const float *spec = specular ? vw_read(app, r, TL_TARGET_LIGHT_SPECULAR, 2) : NULL;
    if (!dif) return vw_unavailable(app, "the light buffer exists in thin-lpp only");
    int compact = specular && !spec;
    if (compact && app->desc.options.light_buffer != TL_LIGHT_BUFFER_COMPACT)
        return vw_unavailable(app, "no specular light buffer (no specular material)");
    float e = app->desc.options.exposure > 0 ? app->desc.options.exposure : 1.0f;
    for (size_t i = 0, n = vw_pixels(app); i < n; i++) {
        const float *p = spec ? spec + 4 * i : dif + 4 * i;
        if (compact) vw_put_hdr(out + 4 * i, e, p[3], p[3], p[3], 1);
        else vw_put_hdr(out + 4 * i, e, p[0], p[1], p[2], 1);
    }
    return 0;
}

static int vw_view_light_diffuse(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    return vw_view_light(app, r, out, 0);
}

static int vw_view_light_specular(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    return vw_view_light(app, r, out, 1);
}

/* Tiles from the bottom left, as the light lists store them; overflowed tiles in magenta. */
static int vw_view_tile_lights(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    const tl_frame_plan *p = &app->plan;
    if (p->light_strategy != TL_LIGHT_STRATEGY_TILED || !p->tile_size)
        return vw_unavailable(app, "lights per tile: the tiled light strategy only");
    if (vw_view_final(app, r, cam, out)) return 1;
    size_t tiles = (size_t)p->tiles_x * p->tiles_y;
    uint32_t most = 1;
    for (size_t t = 0; t < tiles && t < app->tile_capacity; t++)
        if (app->tile_counts[t] != UINT32_MAX && app->tile_counts[t] > most) most = app->tile_counts[t];
    app->tile_max = most;
    for (uint32_t y = 0; y < app->height; y++)
        for (uint32_t x = 0; x < app->width; x++) {
            size_t i = (size_t)y * app->width + x, t = (size_t)(y / p->tile_size) * p->tiles_x + x / p->tile_size;
            uint8_t *px = out + 4 * i, h[3] = {255, 0, 255};
            uint32_t c = t < app->tile_capacity ? app->tile_counts[t] : 0;
            if (c != UINT32_MAX) vw_heat((float)c / (float)most, h);
            int edge = x % p->tile_size == 0 || y % p->tile_size == 0;
            float grey = (px[0] + px[1] + px[2]) / 3.0f;
            for (int k = 0; k < 3; k++) px[k] = edge ? 40 : (uint8_t)(0.3f * grey + 0.7f * h[k]);
        }
    return 0;
}

static int vw_view_hdr(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    const float *h = vw_read(app, r, TL_TARGET_HDR, 0);
    if (!h) return vw_unavailable(app, "no HDR target");
    float e = app->desc.options.exposure > 0 ? app->desc.options.exposure : 1.0f;
    for (size_t i = 0, n = vw_pixels(app); i < n; i++) vw_put_hdr(out + 4 * i, e, h[4 * i], h[4 * i + 1], h[4 * i + 2], 0);
    return 0;
}

static int vw_view_before_fxaa(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    const float *l = vw_read(app, r, TL_TARGET_LDR, 0);
    if (!l) return vw_unavailable(app, "FXAA is off: the tone-mapped image is the output");
    for (size_t i = 0, n = vw_pixels(app); i < n; i++) vw_put(out + 4 * i, l[4 * i], l[4 * i + 1], l[4 * i + 2]);
    return 0;
}

/* MSAA: the pixels the method treats as edges, red over the darkened image. thin-lpp's material
 * pass writes HDR alpha 0.5 where a sample's light texel was another surface's and it was re-lit
 * from the lists (the resolved alpha is below 1 there); per-sample edges (thin-deferred, fat) mark
 * the pixels lit per sample in msaa.edges. */
static int vw_view_msaa_edges(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    int per_sample = (app->plan.targets & TL_TARGET_BIT(TL_TARGET_MSAA_EDGES)) != 0;
    if (app->plan.msaa <= 1 || (app->desc.options.mode != TL_MODE_THIN_LPP && !per_sample))
        return vw_unavailable(app, "MSAA is off, or lit in neither the material pass nor per sample on edges");
    const float *h = vw_read(app, r, per_sample ? TL_TARGET_MSAA_EDGES : TL_TARGET_HDR, 0);
    if (!h || vw_view_final(app, r, cam, out)) return vw_unavailable(app, "no HDR target or edge mask");
    for (size_t i = 0, n = vw_pixels(app); i < n; i++) {
        uint8_t *p = out + 4 * i;
        if (per_sample ? h[4 * i] > 0.5f : h[4 * i + 3] < 1.0f) p[0] = 255, p[1] = p[2] = 0;
        else p[0] = (uint8_t)(p[0] / 3), p[1] = (uint8_t)(p[1] / 3), p[2] = (uint8_t)(p[2] / 3);
    }
    return 0;
}

/* Each pixel's material model (material_ids.c; legend in docs/viewer.md). */
static int vw_view_material_model(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    if (vw_view_final(app, r, cam, out) || vw_material_ids(app, cam, app->scratch[2], out))
        return vw_unavailable(app, "no scene to draw");
    return 0;
}

/* Largest channel difference of the two outputs, times diff_scale, on the heat scale. */
static int vw_view_diff_fat(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    if (!app->fat) return vw_unavailable(app, "no fat renderer");
    uint8_t *ref = app->scratch8[0] + vw_pixels(app) * 4; /* the second half of the grid scratch */
    size_t size = vw_pixels(app) * 4;
    if (vw_view_final(app, r, cam, out) || tl_renderer_read_output(app->fat, ref, &size) != TL_OK)
        return vw_unavailable(app, "no output to compare");
    for (size_t i = 0, n = vw_pixels(app); i < n; i++) {
        int m = 0;
        for (int k = 0; k < 3; k++) {
            int dd = abs((int)out[4 * i + k] - (int)ref[4 * i + k]);
            if (dd > m) m = dd;
        }
        vw_heat((float)m / 255.0f * app->diff_scale, out + 4 * i);
        out[4 * i + 3] = 255;
    }
    return 0;
}

/* SSAO's targets: AO as grey, black 0 (occluded) to white 1 (open). */
static int vw_view_ao_target(vw_app *app, tl_renderer *r, uint8_t *out, tl_target_id t)
{
    if (!app->desc.options.ssao.enabled)
        return vw_unavailable(app, "SSAO is off (--ssao, or the Effects panel)");
    const float *ao = vw_read(app, r, t, 0);
    const float *d = vw_read(app, r, TL_TARGET_DEPTH, 1);
    if (!ao || !d) return vw_unavailable(app, "no AO target in this plan");
    for (size_t i = 0, n = vw_pixels(app); i < n; i++) {
        float v = vw_is_background(app, d, i) ? 1.0f : ao[4 * i];
        vw_put(out + 4 * i, v, v, v);
    }
    return 0;
}

static int vw_view_ao_raw(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    return vw_view_ao_target(app, r, out, TL_TARGET_AO_RAW);
}

static int vw_view_ao(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    return vw_view_ao_target(app, r, out, TL_TARGET_AO);
}

/* The largest circle of confusion, in pixels (tl_dof_desc's defaults resolved). */
static float vw_coc_max(const vw_app *app)
{
    const tl_dof_desc *f = &app->desc.options.dof;
    float aperture = f->aperture > 0 ? f->aperture : 0.01f;
    return (f->max_radius > 0 ? f->max_radius : 2.0f * aperture) * (float)app->height;
}

/* The dof target's alpha: the radius the gather used at each pixel, 0 to the largest. */
static int vw_view_dof_coc(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    if (!app->desc.options.dof.enabled) return vw_unavailable(app,
                                                              "depth of field is off (--dof, or the Effects panel)");
    const float *f = vw_read(app, r, TL_TARGET_DOF, 0);
    if (!f) return vw_unavailable(app, "no dof target in this plan");
    float most = vw_coc_max(app);
    for (size_t i = 0, n = vw_pixels(app); i < n; i++) {
        vw_heat(most > 0 ? f[4 * i + 3] / most : 0.0f, out + 4 * i);
        out[4 * i + 3] = 255;
    }
    return 0;
}

/* The reflection term SSR adds to HDR, times exposure, x / (1 + x). */
static int vw_view_ssr(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    if (!app->desc.options.ssr.enabled) return vw_unavailable(app, "reflections are off (--ssr, or the Effects panel)");
    const float *t = vw_read(app, r, TL_TARGET_SSR, 0);
    if (!t) return vw_unavailable(app, "no ssr target (forward mode plans no reflections)");
    float e = app->desc.options.exposure > 0 ? app->desc.options.exposure : 1.0f;
    for (size_t i = 0, n = vw_pixels(app); i < n; i++) vw_put_hdr(out + 4 * i, e, t[4 * i], t[4 * i + 1], t[4 * i + 2], 1);
    return 0;
}

/* img (w x h RGBA floats, rows bottom to top) at texel coordinates (u, v), bilinear with edges
 * clamped, as GL's linear filter samples it. */
static void vw_bilinear(const float *img, uint32_t w, uint32_t h, float u, float v, float c[3])
{
    int x0 = (int)floorf(u), y0 = (int)floorf(v);
    float fx = u - (float)x0, fy = v - (float)y0;
    int xs[2] = {x0 < 0 ? 0 : x0, x0 + 1 > (int)w - 1 ? (int)w - 1 : x0 + 1};
    int ys[2] = {y0 < 0 ? 0 : y0, y0 + 1 > (int)h - 1 ? (int)h - 1 : y0 + 1};
    for (int i = 0; i < 3; i++) {
        float row[2];
        for (int j = 0; j < 2; j++) {
            const float *p = img + 4 * (size_t)ys[j] * w + i;
            row[j] = p[4 * xs[0]] * (1 - fx) + p[4 * xs[1]] * fx;
        }
        c[i] = row[0] * (1 - fy) + row[1] * fy;
    }
}

/* The bloom the tone-map pass adds to HDR: the chain's first level (half size) sampled at each
 * pixel's centre as that pass's textureLod does, times intensity and exposure, x / (1 + x). */
static int vw_view_bloom(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    if (!app->desc.options.bloom.enabled) return vw_unavailable(app, "bloom is off (--bloom, or the Effects panel)");
    const float *b = vw_read(app, r, TL_TARGET_BLOOM, 0);
    if (!b) return vw_unavailable(app, "no bloom target in this plan");
    const tl_plan_target *t = &app->plan.target_info[TL_TARGET_BLOOM];
    const tl_renderer_options *o = &app->desc.options;
    float k = o->bloom.intensity > 0 ? o->bloom.intensity : 0.5f; /* tl_bloom_desc's default */
    k *= o->exposure > 0 ? o->exposure : 1.0f;
    float sx = (float)t->width / (float)app->width, sy = (float)t->height / (float)app->height;
    for (uint32_t y = 0; y < app->height; y++)
        for (uint32_t x = 0; x < app->width; x++) {
            float c[3];
            vw_bilinear(b, t->width, t->height, ((float)x + 0.5f) * sx - 0.5f, ((float)y + 0.5f) * sy - 0.5f, c);
            vw_put_hdr(out + 4 * ((size_t)y * app->width + x), k, c[0], c[1], c[2], 1);
        }
    return 0;
}

/* The shadow views (shadow_views.c); cascades over the final image. */
static int vw_view_shadow_atlas(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    return vw_shadow_atlas(app, r, out);
}

static int vw_view_shadow_cascades(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    return vw_view_final(app, r, cam, out) || vw_shadow_cascades(app, r, out);
}

static int vw_view_shadow_only(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    return vw_shadow_only(app, r, out);
}

/* ---- visibility's id buffer ------------------------------------------------------------------ */

/* The id as the G-buffer pass stores it ((object slot + 1) << 20 | triangle, renderer.h) from what
 * tl_renderer_read_target gives (object, triangle, drawn); 0 where nothing was drawn. */
static uint32_t vw_vis_id(const float *p)
{
    if (p[2] < 0.5f || p[0] < 0.0f || p[1] < 0.0f) return 0;
    return (((uint32_t)p[0] + 1u) << 20) | (uint32_t)p[1];
}

/* The id's colour (docs/viewer.md, "vis-id"): a 32-bit integer hash (Wellons' lowbias32) of the id,
 * its three low bytes b as 64 + 3 b / 4 per channel, so that no triangle is near black, which is
 * where nothing was drawn. */
static void vw_vis_colour(uint32_t id, uint8_t *px)
{
    uint32_t h = id;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    for (int k = 0; k < 3; k++) px[k] = id ? (uint8_t)(64u + ((h >> (8 * k)) & 255u) * 3u / 4u) : 0;
    px[3] = 255;
}

static int vw_view_vis_id(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    (void)cam;
    const float *v = vw_read(app, r, TL_TARGET_VIS_ID, 0);
    if (!v) return vw_unavailable(app, "the id buffer exists in visibility only");
    for (size_t i = 0, n = vw_pixels(app); i < n; i++) vw_vis_colour(vw_vis_id(v + 4 * i), out + 4 * i);
    return 0;
}

static float vw_dot(const float a[3], const float b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* An object's transform (column-major, all zero: the identity) applied to a point. */
static void vw_object_point(const float *m, int identity, const float p[3], float o[3])
{
    for (int k = 0; k < 3; k++)
        o[k] = identity ? p[k] : m[k] * p[0] + m[4 + k] * p[1] + m[8 + k] * p[2] + m[12 + k];
}

/* The rebuilt normal of one pixel, in world space: its triangle's vertices placed by the object's
 * transform, the barycentrics of the pixel's view ray (from the eye along d) against the triangle's
 * plane (perspective-correct: vis_rebuild.glsl's window-space weights, formulated as its fallback
 * for triangles crossing the eye's plane is), held to the triangle as vis_rebuild.glsl holds them, the vertex normals interpolated and
 * turned by the inverse transpose of the transform. 0 when the id names no triangle of the scene. */
static int vw_rebuild_normal(const tl_scene *s, uint32_t object, uint32_t triangle, const float eye[3],
                             const float d[3], float n[3])
{
    if (object >= s->object_count) return 0;
    const tl_object *o = &s->objects[object];
    if ((uint64_t)triangle * 3u + 3u > o->index_count || o->primitive != 0) return 0;
    int identity = 1;
    for (int k = 0; k < 16; k++) identity &= o->transform[k] == 0.0f;
    const tl_vertex *v[3];
    float p[3][3];
    for (int k = 0; k < 3; k++) {
        uint64_t at = (uint64_t)o->first_index + 3u * triangle + (uint64_t)k;
        if (at >= s->index_count || s->indices[at] >= s->vertex_count) return 0;
        v[k] = &s->vertices[s->indices[at]];
        vw_object_point(o->transform, identity, v[k]->position, p[k]);
        for (int c = 0; c < 3; c++) p[k][c] -= eye[c];
    }
    float e1[3], e2[3], pv[3], q[3], t[3] = {-p[0][0], -p[0][1], -p[0][2]}, b[3];
    for (int c = 0; c < 3; c++) e1[c] = p[1][c] - p[0][c], e2[c] = p[2][c] - p[0][c];
    vw_cross(d, e2, pv);
    float inv = 1.0f / vw_dot(e1, pv);
    vw_cross(t, e1, q);
    b[1] = vw_dot(t, pv) * inv;
    b[2] = vw_dot(d, q) * inv;
    b[0] = 1.0f - b[1] - b[2];
    if (!isfinite(b[0]) || !isfinite(b[1]) || !isfinite(b[2])) b[0] = b[1] = b[2] = 1.0f / 3.0f;
    float sum = 0.0f;
    for (int k = 0; k < 3; k++) sum += b[k] = b[k] < 0.0f ? 0.0f : b[k] > 1.0f ? 1.0f : b[k];
    float m[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++)
        for (int c = 0; c < 3; c++) m[c] += v[k]->normal[c] * b[k] / (sum > 1e-30f ? sum : 1e-30f);
    if (identity) {
        memcpy(n, m, sizeof m);
    } else { /* the inverse transpose's columns: the cross products of the transform's, over its determinant */
        const float *a = o->transform, a0[3] = {a[0], a[1], a[2]}, a1[3] = {a[4], a[5], a[6]}, a2[3] = {a[8], a[9], a[10]};
        float c0[3], c1[3], c2[3];
        vw_cross(a1, a2, c0);
        vw_cross(a2, a0, c1);
        vw_cross(a0, a1, c2);
        float det = vw_dot(a0, c0), sign = det < 0.0f ? -1.0f : 1.0f;
        for (int c = 0; c < 3; c++) n[c] = sign * (c0[c] * m[0] + c1[c] * m[1] + c2[c] * m[2]);
    }
    vw_normalize(n);
    return 1;
}

/* Each pixel's normal rebuilt on the CPU from the id buffer and the scene, as vis-resolve rebuilds
 * it (vis_rebuild.glsl) before the material's normal map: view space, n / 2 + 1/2 (the normals
 * view's mapping); black where nothing was drawn, magenta where the id names no triangle. */
static int vw_view_vis_normals(vw_app *app, tl_renderer *r, const tl_camera *cam, uint8_t *out)
{
    const float *v = vw_read(app, r, TL_TARGET_VIS_ID, 0);
    if (!v) return vw_unavailable(app, "the id buffer exists in visibility only");
    vw_basis b;
    vw_camera_basis(app, cam, &b);
    for (uint32_t y = 0; y < app->height; y++)
        for (uint32_t x = 0; x < app->width; x++) {
            size_t i = (size_t)y * app->width + x;
            const float *p = v + 4 * i;
            if (!vw_vis_id(p)) { vw_put(out + 4 * i, 0, 0, 0); continue; }
            float sx = ((2.0f * ((float)x + 0.5f) / (float)app->width) - 1.0f) * b.tan_x;
            float sy = ((2.0f * ((float)y + 0.5f) / (float)app->height) - 1.0f) * b.tan_y, d[3], n[3];
            for (int k = 0; k < 3; k++) d[k] = b.fwd[k] + b.right[k] * sx + b.up[k] * sy;
            if (!vw_rebuild_normal(app->scene, (uint32_t)p[0], (uint32_t)p[1], b.eye, d, n)) {
                vw_put(out + 4 * i, 1, 0, 1);
                continue;
            }
            float nx = vw_dot(n, b.right), ny = vw_dot(n, b.up), nz = -vw_dot(n, b.fwd);
            vw_put(out + 4 * i, nx * 0.5f + 0.5f, ny * 0.5f + 0.5f, nz * 0.5f + 0.5f);
        }
    return 0;
}

/* ---- legends -------------------------------------------------------------------------------- */

static void vw_grey(float t, uint8_t rgb[3]) { rgb[0] = rgb[1] = rgb[2] = vw_u8(t); }
/* The depth view: white at the nearest pixel (t = 0) to 0.1 at the farthest (t = 1), log scale. */
static void vw_depth_grey(float t, uint8_t rgb[3]) { vw_grey(1.0f - 0.9f * t, rgb); }

static void vw_legend_unit(const vw_app *app, vw_legend *l)
{
    (void)app;
    l->colour = vw_grey;
    snprintf(l->low, sizeof l->low, "0");
    snprintf(l->high, sizeof l->high, "1");
}

static void vw_legend_gloss(const vw_app *app, vw_legend *l)
{
    vw_legend_unit(app, l);
    l->title = "GLOSS";
}

static void vw_legend_ao_raw(const vw_app *app, vw_legend *l)
{
    vw_legend_unit(app, l);
    l->title = "AO BEFORE BLUR (1 = OPEN)";
}

static void vw_legend_ao(const vw_app *app, vw_legend *l)
{
    vw_legend_unit(app, l);
    l->title = "AO (1 = OPEN)";
}

static void vw_legend_depth(const vw_app *app, vw_legend *l)
{
    l->title = "LINEAR DEPTH (LOG)";
    l->colour = vw_depth_grey;
    snprintf(l->low, sizeof l->low, "%.3g M", app->depth_range[0]);
    snprintf(l->high, sizeof l->high, "%.3g M", app->depth_range[1]);
}

static void vw_legend_tiles(const vw_app *app, vw_legend *l)
{
    l->title = "LIGHTS PER TILE";
    l->colour = vw_heat;
    snprintf(l->low, sizeof l->low, "0");
    snprintf(l->high, sizeof l->high, "%u", app->tile_max);
}

static void vw_legend_diff(const vw_app *app, vw_legend *l)
{
    l->title = "MAX CHANNEL DIFF. FROM FAT";
    l->colour = vw_heat;
    snprintf(l->low, sizeof l->low, "0");
    snprintf(l->high, sizeof l->high, "%.1f/255", 255.0 / app->diff_scale);
}

static void vw_legend_coc(const vw_app *app, vw_legend *l)
{
    l->title = "DOF COC RADIUS (PX)";
    l->colour = vw_heat;
    snprintf(l->low, sizeof l->low, "0");
    snprintf(l->high, sizeof l->high, "%.1f", vw_coc_max(app));
}

static void vw_legend_shadow_atlas(const vw_app *app, vw_legend *l)
{
    (void)app;
    l->title = "SHADOW ATLAS DEPTH, EACH VIEW";
    l->colour = vw_depth_grey;
    snprintf(l->low, sizeof l->low, "NEAR");
    snprintf(l->high, sizeof l->high, "FAR");
}

static void vw_legend_shadow_cascades(const vw_app *app, vw_legend *l)
{
    (void)app;
    l->title = "DIRECTIONAL CASCADE (STRIPES: BLEND)";
    l->colour = vw_cascade_legend_colour;
    snprintf(l->low, sizeof l->low, "0");
    snprintf(l->high, sizeof l->high, "3");
}

static void vw_legend_shadow_only(const vw_app *app, vw_legend *l)
{
    vw_legend_unit(app, l);
    l->title = "SHADOW ONLY (1 = LIT)";
}

static const vw_view_def vw_view_table[VW_VIEW_COUNT] = {
    [VW_VIEW_FINAL] = {"final", "the output image (after FXAA)", vw_view_final, NULL},
    [VW_VIEW_NORMALS] = {"normals", "decoded view-space normals, n * 0.5 + 0.5", vw_view_normals, NULL},
    [VW_VIEW_GLOSS] = {"gloss", "gloss, black 0 to white 1", vw_view_gloss, vw_legend_gloss},
    [VW_VIEW_LUMA] = {"luma", "RT1 luma (thin-deferred)", vw_view_luma, NULL},
    [VW_VIEW_CHROMA] = {"chroma", "RT1 raw chroma: Cb on even pixels, Cr on odd (thin-deferred)", vw_view_chroma, NULL},
    [VW_VIEW_ALBEDO] = {"albedo", "albedo, missing chroma rebuilt (thin-deferred, fat)", vw_view_albedo, NULL},
    [VW_VIEW_DEPTH] = {"depth", "linear depth, log scale: white nearest, dark grey farthest, black background",
                       vw_view_depth, vw_legend_depth},
    [VW_VIEW_POSITION] = {"position", "world position from depth over the scene bounds", vw_view_position, NULL},
    [VW_VIEW_LIGHT_DIFFUSE] = {"light-diffuse", "light buffer diffuse (thin-lpp), x/(1+x)", vw_view_light_diffuse, NULL},
    [VW_VIEW_LIGHT_SPECULAR] = {"light-specular", "light buffer specular (thin-lpp), x/(1+x)", vw_view_light_specular,
                                NULL},
    [VW_VIEW_TILE_LIGHTS] = {"tile-lights", "local lights per tile (tiled), heat scale", vw_view_tile_lights,
                             vw_legend_tiles},
    [VW_VIEW_HDR] = {"hdr", "HDR times exposure before tone mapping, clipped at 1", vw_view_hdr, NULL},
    [VW_VIEW_BEFORE_FXAA] = {"before-fxaa", "the tone-mapped image before FXAA", vw_view_before_fxaa, NULL},
    [VW_VIEW_DIFF_FAT] = {"diff-fat", "heat map of |output - fat output| x scale", vw_view_diff_fat, vw_legend_diff},
    [VW_VIEW_AO_RAW] = {"ao-raw", "SSAO before the blur (ao.raw), black 0 to white 1 (open)", vw_view_ao_raw,
                        vw_legend_ao_raw},
    [VW_VIEW_AO] = {"ao", "SSAO after the depth-aware blur (ao), as applied", vw_view_ao, vw_legend_ao},
    [VW_VIEW_DOF_COC] = {"dof-coc", "depth of field: circle of confusion radius in pixels, heat scale",
                         vw_view_dof_coc, vw_legend_coc},
    [VW_VIEW_SSR] = {"ssr", "screen-space reflections: the term added to HDR, x/(1+x)", vw_view_ssr, NULL},
    [VW_VIEW_BLOOM] = {"bloom", "bloom: the glow added to HDR (first level, upsampled) times intensity, x/(1+x)",
                       vw_view_bloom, NULL},
    [VW_VIEW_MSAA_EDGES] = {"msaa-edges", "MSAA: red where thin-lpp's material pass re-lit a sample from the light lists, "
                            "or where per-sample edges lit a pixel per sample; the image darkened", vw_view_msaa_edges, NULL},
    [VW_VIEW_MATERIAL_MODEL] = {"material-model", "material model: grey standard, yellow unlit, blue clearcoat, "
                                "magenta sheen, orange wrap, green toon; shaded by the image's luma", vw_view_material_model, NULL},
    [VW_VIEW_SHADOW_ATLAS] = {"shadow-atlas", "the shadow atlas: each view's depth, white near to dark far; tile edges yellow "
                              "(sun), cyan (point), magenta (spot); blue: nothing drawn", vw_view_shadow_atlas,
                              vw_legend_shadow_atlas},
    [VW_VIEW_SHADOW_CASCADES] = {"shadow-cascades", "the casting directional light's cascade per pixel: red 0, green 1, blue 2, "
                                 "yellow 3, stripes of the next where two blend; grey beyond; shaded by the image's luma", vw_view_shadow_cascades,
                                 vw_legend_shadow_cascades},
    [VW_VIEW_SHADOW_ONLY] = {"shadow-only", "shadow term alone: the casting lights' visibility weighted by their diffuse "
                             "light, black shadowed to white lit; blue: no casting light reaches", vw_view_shadow_only,
                             vw_legend_shadow_only},
    [VW_VIEW_VIS_ID] = {"vis-id", "visibility: the id buffer, each object and triangle a hashed colour; black: nothing drawn",
                        vw_view_vis_id, NULL},
    [VW_VIEW_VIS_NORMALS] = {"vis-normals", "visibility: the normal rebuilt on the CPU from each pixel's id and the scene's "
                             "triangle, as vis-resolve does, n * 0.5 + 0.5", vw_view_vis_normals, NULL},
};

const char *vw_view_name(vw_view v) { return v < VW_VIEW_COUNT ? vw_view_table[v].name : "unknown"; }
const char *vw_view_help(vw_view v) { return v < VW_VIEW_COUNT ? vw_view_table[v].help : ""; }

int vw_view_from_name(const char *name, vw_view *v)
{
    for (int i = 0; i < VW_VIEW_COUNT; i++)
        if (!strcmp(name, vw_view_table[i].name)) { *v = (vw_view)i; return 1; }
    return 0;
}

/* ---- building the shown image --------------------------------------------------------------- */

/* One view into out; an unavailable one becomes a dark checkerboard. */
static void vw_build_one(vw_app *app, vw_view v, const tl_camera *cam, uint8_t *out)
{
    app->view_note[0] = 0;
    if (!vw_view_table[v].build(app, app->r, cam, out)) return;
    for (uint32_t y = 0; y < app->height; y++)
        for (uint32_t x = 0; x < app->width; x++) {
            uint8_t g = ((x / 16 + y / 16) & 1) ? 48 : 32;
            uint8_t *px = out + 4 * ((size_t)y * app->width + x);
            px[0] = px[1] = px[2] = g;
            px[3] = 255;
        }
}

/* Every view shrunk (nearest) into a grid, first view top left (no legends: thumbnails). */
static void vw_build_grid(vw_app *app, const tl_camera *cam)
{
    const uint32_t cols = VW_GRID_COLS, rows = VW_GRID_ROWS, cw = app->width / cols, ch = app->height / rows;
    for (size_t i = 0, n = vw_pixels(app); i < n; i++) memcpy(app->image + 4 * i, "\0\0\0\377", 4); /* opaque black */
    for (int v = 0; v < VW_VIEW_COUNT; v++) {
        uint8_t *full = app->scratch8[0];
        vw_build_one(app, (vw_view)v, cam, full);
        uint32_t cx = (uint32_t)v % cols, cy = rows - 1 - (uint32_t)v / cols;
        for (uint32_t y = 1; y + 1 < ch; y++)
            for (uint32_t x = 1; x + 1 < cw; x++) {
                size_t sx = (size_t)x * app->width / cw, sy = (size_t)y * app->height / ch;
                memcpy(app->image + 4 * ((size_t)(cy * ch + y) * app->width + cx * cw + x),
                       full + 4 * (sy * app->width + sx), 4);
            }
    }
    app->view_note[0] = 0;
}

/* Left half: this renderer's output; right half: the split renderer's; a white line between. */
static void vw_build_split(vw_app *app, const tl_camera *cam)
{
    uint8_t *right = app->scratch8[0];
    size_t size = vw_pixels(app) * 4;
    vw_build_one(app, VW_VIEW_FINAL, cam, app->image);
    if (!app->split || tl_renderer_read_output(app->split, right, &size) != TL_OK) return;
    uint32_t half = app->width / 2;
    for (uint32_t y = 0; y < app->height; y++) {
        size_t row = (size_t)y * app->width;
        memcpy(app->image + 4 * (row + half), right + 4 * (row + half), 4 * (size_t)(app->width - half));
        memset(app->image + 4 * (row + half), 255, 4);
    }
}

static int vw_ensure_buffers(vw_app *app)
{
    size_t n = vw_pixels(app);
    if (app->image && app->image_pixels == n) return 0;
    free(app->image);
    for (int i = 0; i < 3; i++) free(app->scratch[i]);
    for (int i = 0; i < 2; i++) free(app->scratch8[i]);
    app->image = malloc(n * 4);
    for (int i = 0; i < 3; i++) app->scratch[i] = malloc(n * 16);
    app->scratch8[0] = malloc(n * 8);
    app->scratch8[1] = malloc(n * 2);
    app->image_pixels = n;
    return app->image && app->scratch[0] && app->scratch[1] && app->scratch[2] && app->scratch8[0] && app->scratch8[1]
               ? 0
               : -1;
}

int vw_views_build(vw_app *app, const tl_camera *cam)
{
    if (vw_ensure_buffers(app)) return -1;
    if (app->split_on) vw_build_split(app, cam);
    else if (app->grid) vw_build_grid(app, cam);
    else {
        vw_build_one(app, app->view, cam, app->image);
        vw_legend l = {0};
        if (!app->view_note[0] && vw_view_table[app->view].legend) {
            vw_view_table[app->view].legend(app, &l);
            vw_draw_legend(app->image, app->width, app->height, &l);
        }
    }
    return 0;
}

/* ---- the light lists, read inside the frame ------------------------------------------------- */

static void vw_tile_pass(void *user, const tl_app_pass_context *ctx)
{
    vw_app *app = (vw_app *)user;
    const vw_gl *gl = (const vw_gl *)app->gl;
    uint32_t name = ctx->textures[TL_TARGET_LIGHT_LISTS], ts = app->plan.tile_size;
    if (!name || !ts || !gl->get_named_buffer_sub_data) return;
    size_t tiles = (size_t)((ctx->view->width + ts - 1) / ts) * ((ctx->view->height + ts - 1) / ts);
    if (tiles > app->tile_capacity) {
        uint32_t *t = realloc(app->tile_counts, tiles * 2 * sizeof *t + 16);
        if (!t) return;
        app->tile_counts = t;
        app->tile_capacity = tiles;
    }
    /* headers: 4 counters, then (first, count) per tile; read in place, then compacted */
    uint32_t *h = app->tile_counts;
    gl->memory_barrier(VW_GL_BUFFER_UPDATE_BARRIER_BIT);
    gl->get_named_buffer_sub_data(name, 0, (intptr_t)(16 + 8 * tiles), h);
    for (size_t t = 0; t < tiles; t++) h[t] = h[4 + 2 * t] == UINT32_MAX ? UINT32_MAX : h[4 + 2 * t + 1];
}

/* Does nothing: its declared read of RT0 is what it is for (visibility's G-buffer pass writes RT0
 * only when a later pass reads it, as SSAO does; keep_targets keeps memory, not writes). */
static void vw_rt0_pass(void *user, const tl_app_pass_context *ctx)
{
    (void)user;
    (void)ctx;
}

/* Adds the application pass `d` when wanted and missing, removes it when there and not wanted. */
static void vw_app_pass(tl_renderer *r, const tl_frame_plan *p, const tl_app_pass_desc *d, int want)
{
    int has = 0;
    for (size_t i = 0; i < p->pass_count; i++) has |= !strcmp(p->passes[i].name, d->name);
    if (has && !want) tl_renderer_remove_pass(r, d->name);
    if (!has && want) tl_renderer_add_pass(r, d);
}

void vw_views_app_passes(vw_app *app, tl_renderer *r)
{
    tl_app_pass_desc tiles = {.name = "viewer.tiles", .before = "tonemap",
                              .reads = TL_TARGET_BIT(TL_TARGET_LIGHT_LISTS), .writes = TL_TARGET_BIT(TL_TARGET_HDR),
                              .execute = vw_tile_pass, .user = app};
    tl_app_pass_desc rt0 = {.name = "viewer.rt0", .before = "tonemap", .reads = TL_TARGET_BIT(TL_TARGET_RT0),
                            .writes = TL_TARGET_BIT(TL_TARGET_HDR), .execute = vw_rt0_pass, .user = app};
    tl_frame_plan *p = &app->plan;
    if (tl_renderer_get_plan(r, p) != TL_OK) return;
    vw_app_pass(r, p, &tiles, (app->view == VW_VIEW_TILE_LIGHTS || app->grid) && p->light_strategy == TL_LIGHT_STRATEGY_TILED);
    if (tl_renderer_get_plan(r, p) != TL_OK) return;
    vw_app_pass(r, p, &rt0, app->desc.options.mode == TL_MODE_VISIBILITY &&
                                (app->grid || (!app->split_on && (app->view == VW_VIEW_NORMALS || app->view == VW_VIEW_GLOSS))));
    tl_renderer_get_plan(r, p);
}

int vw_views_init(vw_app *app, void *(*loader)(const char *))
{
    vw_gl *gl = calloc(1, sizeof *gl);
    if (!gl) return -1;
    gl->memory_barrier = (vw_barrier_fn)(uintptr_t)loader("glMemoryBarrier");
    gl->get_named_buffer_sub_data = (vw_buffer_read_fn)(uintptr_t)loader("glGetNamedBufferSubData");
    app->gl = gl;
    return gl->memory_barrier && gl->get_named_buffer_sub_data ? 0 : -1;
}

void vw_views_free(vw_app *app)
{
    vw_material_ids_free(app);
    free(app->gl);
    free(app->image);
    for (int i = 0; i < 3; i++) free(app->scratch[i]);
    for (int i = 0; i < 2; i++) free(app->scratch8[i]);
    free(app->tile_counts);
}
