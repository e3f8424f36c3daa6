/* Stability cases, stiff geometry (stability.h): slivers under a pixel wide, triangles crossing the
 * near plane (vertices behind the camera), a scene at 1e5 units from the origin, and a mesh of more
 * than 2^20 triangles. Every case runs in every mode of `stiff_modes`, reads every target the plan
 * allocated and finds no NaN or Inf, and checks a computed expectation: the slivers' image against
 * a plain quad's, the floor's visible pixels (a CPU ray per pixel) covered and lit and the frame
 * against fat's, the translated frame against the untranslated one. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "stability.h"
#include "thinlight/metrics.h"

/* The modes the stiff geometry cases run in, by registry name (tl_render_mode_from_name), with what
 * their tolerances depend on. Adding a mode is one line here; the visibility mode's would be
 *     {"visibility", 0.0, 0, 1u << 20},
 * (albedo evaluated at full precision in the resolve, positions from the triangle's vertices, at
 * most 2^20 triangles: its ids). */
static const struct stiff_mode {
    const char *name;
    /* relative error of the albedo the mode stores, beyond the FP16 steps every mode has:
     * thin-deferred rebuilds chroma from its neighbours, one 8-bit chroma step of RT1, 2 % in
     * linear colour (as stability_1x1_target allows) */
    double albedo_rel;
    /* 1: the light pass rebuilds positions from the depth buffer (the thin modes); 0: from
     * interpolated positions (fat's position target, forward's varyings). Far from the origin the
     * depth's rounding grows by z / near along the view ray (stiff_geometry_coordinates_at_1e5_*). */
    int positions_from_depth;
    /* the most triangles the mode takes in one scene; 0: no limit of its own. A mode with a limit
     * refuses limit + 1 with a message that names the triangles, and draws `limit`. */
    size_t max_triangles;
} stiff_modes[] = {
    {"thin-lpp", 0.0, 1, 0},
    {"thin-deferred", 0.02, 1, 0},
    {"fat", 0.0, 0, 0},
    {"forward", 0.0, 0, 0},
    {"visibility", 0.0, 0, 1u << 20}, /* the id's 20 triangle bits (pass_visibility.c) */
};
#define STIFF_MODE_COUNT (sizeof stiff_modes / sizeof stiff_modes[0])

#define SW 320
#define SH 180
#define FOV 1.0471976f /* 60 degrees */

/* ---- scenes of any size, on the heap --------------------------------------------------------- */

typedef struct stiff_scene {
    tl_vertex *v;
    uint32_t *idx;
    size_t nv, ni;
    tl_object obj[4];
    tl_material mat[2];
    tl_texture tex;
    uint8_t texels[8 * 8 * 4];
    tl_light light[4];
    tl_scene s;
} stiff_scene;

/* The rectangle the sliver and budget cases cover: the plane z = -RECT_Z facing the camera at the
 * origin (mini_init's view: world = view space), x in [RECT_X0, RECT_X1], y in [RECT_Y0, RECT_Y1]. */
#define RECT_Z 3.0f
#define RECT_X0 (-1.0f)
#define RECT_X1 0.75f
#define RECT_Y0 (-0.5f)
#define RECT_Y1 0.625f

/* A scene with room for nv vertices and ni indices, lit by a point light, a directional light and
 * ambient, drawing material 0: albedo 0.8 x an 8 x 8 texture of seeded colours (magnified: smooth),
 * specular 0.2, gloss 0.5. 0 (a failed check) when the memory is not there. */
static int stiff_scene_init(stiff_scene *m, size_t nv, size_t ni)
{
    memset(m, 0, sizeof *m);
    m->v = malloc(nv * sizeof *m->v);
    m->idx = malloc(ni * sizeof *m->idx);
    TL_CHECK(m->v && m->idx);
    if (!m->v || !m->idx) {
        free(m->v);
        free(m->idx);
        m->v = NULL;
        m->idx = NULL;
        return 0;
    }
    tl_rng rng = {7};
    for (int i = 0; i < 8 * 8; i++) {
        for (int k = 0; k < 3; k++) m->texels[4 * i + k] = (uint8_t)(64 + (tl_rng_u64(&rng) % 192));
        m->texels[4 * i + 3] = 255;
    }
    m->tex = (tl_texture){.width = 8, .height = 8, .rgba = m->texels, .name = "stiff.colours"};
    m->mat[0] = plain_material(0.8f, 0.2f, 0.5f);
    m->mat[0].albedo_map = TL_TEXTURE_MAP(0);
    m->light[0] = point_light(0.3f, 0.4f, -1.5f, 10.0f, 2.0f, 1.8f, 1.5f);
    m->light[1] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {-0.3f, -0.2f, -1.0f},
                             .color = {0.4f, 0.45f, 0.5f}};
    m->s = (tl_scene){.materials = m->mat, .material_count = 1, .textures = &m->tex, .texture_count = 1,
                      .lights = m->light, .light_count = 2, .ambient = {0.05f, 0.05f, 0.05f}, .objects = m->obj,
                      .camera = {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, FOV, 0.1f, 100.0f}};
    return 1;
}

static void stiff_scene_free(stiff_scene *m)
{
    free(m->v);
    free(m->idx);
    memset(m, 0, sizeof *m);
}

/* A vertex of the rectangle's plane at (x, y): normal +Z, uv across the rectangle (v downward). */
static uint32_t rect_vertex(stiff_scene *m, float x, float y)
{
    tl_vertex *v = &m->v[m->nv];
    *v = (tl_vertex){.position = {x, y, -RECT_Z}, .normal = {0, 0, 1},
                     .uv = {(x - RECT_X0) / (RECT_X1 - RECT_X0), (RECT_Y1 - y) / (RECT_Y1 - RECT_Y0)}};
    return (uint32_t)m->nv++;
}

static void triangle(stiff_scene *m, uint32_t a, uint32_t b, uint32_t c)
{
    m->idx[m->ni++] = a;
    m->idx[m->ni++] = b;
    m->idx[m->ni++] = c;
}

/* Makes everything added so far one object of material 0 (bounds computed by set_scene). */
static void stiff_scene_one_object(stiff_scene *m)
{
    m->obj[0] = (tl_object){.index_count = (uint32_t)m->ni};
    m->s.object_count = 1;
    m->s.vertices = m->v;
    m->s.vertex_count = m->nv;
    m->s.indices = m->idx;
    m->s.index_count = m->ni;
}

/* The rectangle as two triangles: what the other meshes of it are compared with. */
static int rect_plain(stiff_scene *m)
{
    if (!stiff_scene_init(m, 4, 6)) return 0;
    uint32_t a = rect_vertex(m, RECT_X0, RECT_Y0), b = rect_vertex(m, RECT_X1, RECT_Y0),
             c = rect_vertex(m, RECT_X1, RECT_Y1), d = rect_vertex(m, RECT_X0, RECT_Y1);
    triangle(m, a, b, c);
    triangle(m, a, c, d);
    stiff_scene_one_object(m);
    return 1;
}

/* The rectangle as `cols` columns of two slivers each, the full height tall and (cols = 256 at
 * 320 x 180) 0.35 pixels wide: aspect about 1:160. Counter-clockwise seen from the camera. */
static int rect_strip(stiff_scene *m, uint32_t cols)
{
    if (!stiff_scene_init(m, 2 * ((size_t)cols + 1), 6 * (size_t)cols)) return 0;
    for (uint32_t i = 0; i <= cols; i++) {
        float x = RECT_X0 + (RECT_X1 - RECT_X0) * (float)i / (float)cols;
        rect_vertex(m, x, RECT_Y0);
        rect_vertex(m, x, RECT_Y1);
    }
    for (uint32_t i = 0; i < cols; i++) {
        uint32_t b0 = 2 * i, t0 = b0 + 1, b1 = b0 + 2, t1 = b0 + 3;
        triangle(m, b0, b1, t1);
        triangle(m, b0, t1, t0);
    }
    stiff_scene_one_object(m);
    return 1;
}

/* The rectangle as a fan of `per_side` x 4 triangles around an off-centre point, each under a
 * pixel wide at the rim (per_side = 256 at 320 x 180: 0.35 and 0.23 pixels) and far thinner
 * towards the centre, where they meet at one vertex. */
static int rect_fan(stiff_scene *m, uint32_t per_side)
{
    uint32_t rim = 4 * per_side;
    if (!stiff_scene_init(m, (size_t)rim + 1, 3 * (size_t)rim)) return 0;
    uint32_t c = rect_vertex(m, RECT_X0 + 0.37f * (RECT_X1 - RECT_X0), RECT_Y0 + 0.61f * (RECT_Y1 - RECT_Y0));
    static const float corner[5][2] = {{RECT_X0, RECT_Y0}, {RECT_X1, RECT_Y0}, {RECT_X1, RECT_Y1}, {RECT_X0, RECT_Y1},
                                       {RECT_X0, RECT_Y0}};
    for (int side = 0; side < 4; side++) /* counter-clockwise around the rectangle */
        for (uint32_t i = 0; i < per_side; i++) {
            float t = (float)i / (float)per_side;
            /* on the side's line exactly: the coordinate the side keeps is the corner's */
            const float *p0 = corner[side], *p1 = corner[side + 1];
            float x = p0[0] == p1[0] ? p0[0] : p0[0] + t * (p1[0] - p0[0]);
            float y = p0[1] == p1[1] ? p0[1] : p0[1] + t * (p1[1] - p0[1]);
            rect_vertex(m, x, y);
        }
    for (uint32_t i = 0; i < rim; i++) triangle(m, c, 1 + i, 1 + (i + 1) % rim);
    stiff_scene_one_object(m);
    return 1;
}

/* ---- THE TRIANGLE BUDGET MESH ----------------------------------------------------------------
 * stiff_mesh_triangle_budget: `n` triangles (n >= 2) in one object, none degenerate, covering the
 * rectangle's middle band (x over the rectangle, y in [-0.0625, 0.0625]: about 91 x 6.5 pixels at
 * 320 x 180, the thin strip): a grid of cols x rows cells of two triangles each, plus one more
 * triangle below the band's left corner when n is odd. Vertices are shared (about n / 2 of them:
 * 25 MB and 12.6 MB of indices for 2^20 + 1 triangles), every triangle counter-clockwise from the
 * camera, cells about 1/1000 of a pixel in area (2048 x 256 cells for 2^20 + 1). Built in a few
 * milliseconds; the visibility mode's limit (its 2^20 triangle ids) is held with n = limit and
 * limit + 1. */
#define BUDGET_Y0 (-0.0625f)
#define BUDGET_Y1 0.0625f
static int stiff_mesh_triangle_budget(stiff_scene *m, size_t n)
{
    size_t cells = n / 2, rows = 1;
    while (rows * rows * 16 < cells && cells % (rows * 2) == 0) rows *= 2; /* cols = 16 x rows or so */
    size_t cols = cells / rows, extra = n - 2 * cols * rows; /* n = 2 cols rows + (0 or 1, or the rest) */
    TL_CHECK(cols * rows == cells && extra <= 1);
    if (cols * rows != cells || extra > 1) return 0;
    if (!stiff_scene_init(m, (cols + 1) * (rows + 1) + extra, 3 * n)) return 0;
    for (size_t j = 0; j <= rows; j++)
        for (size_t i = 0; i <= cols; i++)
            rect_vertex(m, RECT_X0 + (RECT_X1 - RECT_X0) * (float)((double)i / (double)cols),
                        BUDGET_Y0 + (BUDGET_Y1 - BUDGET_Y0) * (float)((double)j / (double)rows));
    for (size_t j = 0; j < rows; j++)
        for (size_t i = 0; i < cols; i++) {
            uint32_t a = (uint32_t)(j * (cols + 1) + i), b = a + 1, d = (uint32_t)(a + cols + 1), c = d + 1;
            triangle(m, a, b, c);
            triangle(m, a, c, d);
        }
    if (extra) /* below the band's first cell: its own third vertex */
        triangle(m, rect_vertex(m, RECT_X0, BUDGET_Y0 - (BUDGET_Y1 - BUDGET_Y0) / (float)rows), 1, 0);
    TL_CHECK_EQ_U(m->ni, 3 * n);
    stiff_scene_one_object(m);
    return 1;
}

/* The band alone as two triangles. */
static int budget_plain(stiff_scene *m)
{
    if (!stiff_scene_init(m, 4, 6)) return 0;
    uint32_t a = rect_vertex(m, RECT_X0, BUDGET_Y0), b = rect_vertex(m, RECT_X1, BUDGET_Y0),
             c = rect_vertex(m, RECT_X1, BUDGET_Y1), d = rect_vertex(m, RECT_X0, BUDGET_Y1);
    triangle(m, a, b, c);
    triangle(m, a, c, d);
    stiff_scene_one_object(m);
    return 1;
}

/* ---- rendering and comparing ------------------------------------------------------------------ */

/* run_scene in the mode named `name` at SW x SH (every target read, every one checked finite). */
static int stiff_run(run *u, const char *name, const tl_scene *s, const char *what)
{
    tl_render_mode mode;
    if (tl_render_mode_from_name(name, &mode) != TL_OK) {
        fprintf(stderr, "  mode \"%s\" is not in the registry\n", name);
        tl_test_failures++;
        return 0;
    }
    char label[96];
    snprintf(label, sizeof label, "%s, %s", what, name);
    if (!run_scene(u, (tl_renderer_desc){.options.mode = mode, .width = SW, .height = SH}, s, label)) return 0;
    check_all_targets_finite(u, label);
    return 1;
}

static int covered(const run *u, size_t px) { return u->f.depth[4 * px] != u->clear; }

/* A tessellation of a region against the region's plain quad, same mode: the pixels the quad covers
 * with all eight neighbours (its interior, where a boundary pixel's coverage is not in question)
 * are all covered (no crack) and each within `tol` of the quad's HDR, the mean over them within
 * TESS_MEAN_TOL; the pixel counts covered differ by at most the quad's boundary pixels. */
typedef struct tess_result {
    size_t interior, cracks, beyond, covered_mesh, covered_quad;
    double max_diff, mean_diff[3], mean_quad[3];
} tess_result;

static tess_result compare_tessellation(const run *mesh, const run *quad, double tol)
{
    tess_result t = {0};
    for (uint32_t y = 0; y < SH; y++)
        for (uint32_t x = 0; x < SW; x++) {
            size_t px = (size_t)y * SW + x;
            t.covered_mesh += covered(mesh, px);
            t.covered_quad += covered(quad, px);
            int inner = x > 0 && y > 0 && x + 1 < SW && y + 1 < SH;
            for (int dy = -1; inner && dy <= 1; dy++)
                for (int dx = -1; inner && dx <= 1; dx++) inner = covered(quad, px + (size_t)(dy * SW + dx));
            if (!inner) continue;
            t.interior++;
            if (!covered(mesh, px)) {
                t.cracks++;
                continue;
            }
            for (int ch = 0; ch < 3; ch++) {
                double a = mesh->f.hdr[4 * px + ch], b = quad->f.hdr[4 * px + ch], d = fabs(a - b);
                t.max_diff = fmax(t.max_diff, d / (fabs(b) > 0 ? fabs(b) : 1.0));
                t.beyond += d > tol * fabs(b);
                t.mean_diff[ch] += a - b;
                t.mean_quad[ch] += b;
            }
        }
    for (int ch = 0; ch < 3; ch++)
        if (t.interior) {
            t.mean_diff[ch] /= (double)t.interior;
            t.mean_quad[ch] /= (double)t.interior;
        }
    return t;
}

/* Relative tolerances of the tessellation comparisons: the same surface point shaded from another
 * triangle differs by the interpolation's float rounding (positions, uv: a few 2^-24), moved through
 * the texture's bilinear weights and the lighting, then stored: one FP16 step of HDR (2^-10, both
 * roundings), in thin-lpp the light buffer's FP16 step again. Four FP16 steps per value cover
 * that, plus the mode's albedo_rel (thin-deferred's chroma, rebuilt from neighbours whose luma
 * may differ by a step); the mean over the interior must agree to a quarter of one FP16 step, since
 * rounding differences do not all fall one way. */
#define TESS_TOL (4.0 * TL_HALF_REL_STEP)
#define TESS_MEAN_TOL (0.25 * TL_HALF_REL_STEP)

static void check_tessellation(const char *what, const char *mode, double tol, const tess_result *t)
{
    double worst_mean = 0.0;
    for (int ch = 0; ch < 3; ch++) worst_mean = fmax(worst_mean, fabs(t->mean_diff[ch]) / t->mean_quad[ch]);
    printf("  %s, %-14s %zu interior pixels, %zu cracks, %zu values beyond %.2g (worst %.3g relative), mean "
           "(%.5f %.5f %.5f) vs the quad's by %.3g relative; covered %zu vs %zu\n",
           what, mode, t->interior, t->cracks, t->beyond, tol, t->max_diff, t->mean_quad[0] + t->mean_diff[0],
           t->mean_quad[1] + t->mean_diff[1], t->mean_quad[2] + t->mean_diff[2], worst_mean, t->covered_mesh,
           t->covered_quad);
    TL_CHECK(t->interior > 100);
    TL_CHECK_EQ_U(t->cracks, 0);
    TL_CHECK_EQ_U(t->beyond, 0);
    TL_CHECK_LE(worst_mean, TESS_MEAN_TOL);
    size_t a = t->covered_mesh, b = t->covered_quad;
    TL_CHECK_LE(a > b ? a - b : b - a, b - t->interior);
}

/* ---- a. slivers ------------------------------------------------------------------------------- */

/* A rectangle of slivers under a pixel wide (a strip of columns; a fan around one vertex) against
 * the same rectangle as two triangles, in every mode: no crack inside, each interior pixel and the
 * mean colour the quad's. */
TL_TEST(stiff_geometry_slivers_match_plain_quad)
{
    for (size_t mi = 0; mi < STIFF_MODE_COUNT; mi++) {
        const char *mode = stiff_modes[mi].name;
        stiff_scene plain;
        run q;
        if (!rect_plain(&plain)) return;
        if (!stiff_run(&q, mode, &plain.s, "plain quad")) {
            stiff_scene_free(&plain);
            continue;
        }
        for (int variant = 0; variant < 2; variant++) {
            stiff_scene sl;
            run u;
            const char *what = variant ? "fan of 1024 slivers" : "strip of 512 slivers";
            if (!(variant ? rect_fan(&sl, 256) : rect_strip(&sl, 256))) break;
            if (stiff_run(&u, mode, &sl.s, what)) {
                double tol = TESS_TOL + stiff_modes[mi].albedo_rel;
                tess_result t = compare_tessellation(&u, &q, tol);
                check_tessellation(what, mode, tol, &t);
                run_free(&u);
            }
            stiff_scene_free(&sl);
        }
        run_free(&q);
        stiff_scene_free(&plain);
    }
}

/* ---- b. triangles crossing the near plane ---------------------------------------------------- */

/* The floor y = -1, |x| <= 60, |z| <= 60 around the camera, and a big triangle standing on it at
 * x = -3 from z = 40 to z = -10: every triangle has vertices behind the camera (w < 0) and crosses
 * the near plane. The camera looks 15 degrees down. A pixel whose centre ray meets the floor 2 units
 * inside its edges (0.09 pixels inside the far edge, far above the rasteriser's rounding) and right
 * of x = -1 (not behind the standing triangle) must be covered and hold at least half the ambient
 * term (0.02 x 0.6); the frame must match fat's (LDR output) within the bound test_coplanar.c takes
 * for the encodings alone: 8 steps a value, 45 dB. */
#define FLOOR_HALF 60.0f
#define NEAR_AMBIENT 0.02f
#define NEAR_ALBEDO 0.6f
TL_TEST(stiff_geometry_triangles_crossing_near_plane)
{
    mini_scene m;
    mini_init(&m, FOV, 0.1f, 200.0f);
    m.mat[0] = plain_material(NEAR_ALBEDO, 0.3f, 0.6f);
    add_quad(&m, (float[3]){-FLOOR_HALF, -1, FLOOR_HALF}, (float[3]){2 * FLOOR_HALF, 0, 0},
             (float[3]){0, 0, -2 * FLOOR_HALF}, 0);
    add_quad(&m, (float[3]){-3, -1, 40}, (float[3]){0, 0, -50}, (float[3]){0, 6, 0}, 0);
    m.obj[1].index_count = 3; /* its first triangle: (-3, -1, 40) behind, the two others in front */
    m.light[0] = point_light(0.5f, 0.5f, -4.0f, 20.0f, 6.0f, 6.0f, 6.0f);
    m.light[1] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {0.2f, -1.0f, -0.3f},
                            .color = {0.3f, 0.3f, 0.3f}};
    m.s.light_count = 2;
    m.s.ambient[0] = m.s.ambient[1] = m.s.ambient[2] = NEAR_AMBIENT;
    m.s.camera.target[1] = -tanf(15.0f * 3.14159265f / 180.0f);
    uint8_t *floor_px = calloc((size_t)SW * SH, 1), *fat_out = malloc((size_t)SW * SH * 4);
    TL_CHECK(floor_px && fat_out);
    size_t floor_count = 0;
    for (uint32_t y = 0; floor_px && y < SH; y++)
        for (uint32_t x = 0; x < SW; x++) {
            double d[3];
            camera_ray(&m.s.camera, SW, SH, x + 0.5, y + 0.5, d);
            if (d[1] >= 0.0) continue;
            double t = -1.0 / d[1], px = t * d[0], pz = t * d[2];
            if (fabs(px) < FLOOR_HALF - 2 && fabs(pz) < FLOOR_HALF - 2 && px > -1.0) {
                floor_px[(size_t)y * SW + x] = 1;
                floor_count++;
            }
        }
    TL_CHECK(floor_count > (size_t)SW * SH / 4);
    run fat;
    int have_fat = floor_px && fat_out && stiff_run(&fat, "fat", &m.s, "near plane");
    if (have_fat) {
        TL_CHECK(tl_renderer_read_output(fat.r, fat_out, &(size_t){(size_t)SW * SH * 4}) == TL_OK);
        run_free(&fat);
    }
    for (size_t mi = 0; have_fat && mi < STIFF_MODE_COUNT; mi++) {
        const char *mode = stiff_modes[mi].name;
        run u;
        if (!stiff_run(&u, mode, &m.s, "near plane")) continue;
        size_t holes = 0, dark = 0;
        const float least = 0.5f * NEAR_AMBIENT * NEAR_ALBEDO;
        for (size_t px = 0; px < (size_t)SW * SH; px++) {
            if (!floor_px[px]) continue;
            holes += !covered(&u, px);
            dark += !(u.f.hdr[4 * px] >= least && u.f.hdr[4 * px + 1] >= least && u.f.hdr[4 * px + 2] >= least);
        }
        uint8_t *out = malloc((size_t)SW * SH * 4);
        tl_image_error e = {0};
        TL_CHECK(out && tl_renderer_read_output(u.r, out, &(size_t){(size_t)SW * SH * 4}) == TL_OK);
        TL_CHECK(out && tl_image_compare_u8(out, fat_out, (size_t)SW * SH * 4, &e) == TL_OK);
        printf("  near plane, %-14s %zu floor pixels, %zu uncovered, %zu below half the ambient term; vs fat "
               "%.2f dB, max %.0f steps\n", mode, floor_count, holes, dark, e.psnr_db, e.max_abs);
        TL_CHECK_EQ_U(holes, 0);
        TL_CHECK_EQ_U(dark, 0);
        TL_CHECK(e.psnr_db >= 45.0);
        TL_CHECK_LE(e.max_abs, 8.0);
        free(out);
        run_free(&u);
    }
    free(floor_px);
    free(fat_out);
}

/* ---- c. coordinates at 1e5 ------------------------------------------------------------------- */

/* A floor and a box lit by a point and a directional light, seen from 4 units; then the same scene
 * translated by (1e5, 0, 1e5), camera and lights with it. Every coordinate is a multiple of 1/128,
 * so the translated scene is exact in float (the float spacing at 1e5 is 2^-7 = 0.0078): what
 * differs is the renderer's own arithmetic at 1e5. */
static void far_scene(mini_scene *m, float ox, float oz)
{
    mini_init(m, FOV, 0.1f, 100.0f);
    m->mat[0] = plain_material(0.6f, 0.25f, 0.5f);
    m->mat[1] = plain_material(0.3f, 0.5f, 0.7f);
    m->mat[1].albedo[0] = 0.7f;
    m->s.material_count = 2;
    add_quad(m, (float[3]){ox - 2, 0, oz + 2}, (float[3]){4, 0, 0}, (float[3]){0, 0, -4}, 0);       /* floor */
    add_quad(m, (float[3]){ox - 0.5f, 0, oz + 0.5f}, (float[3]){1, 0, 0}, (float[3]){0, 1, 0}, 1);  /* front */
    add_quad(m, (float[3]){ox + 0.5f, 0, oz + 0.5f}, (float[3]){0, 0, -1}, (float[3]){0, 1, 0}, 1); /* right */
    add_quad(m, (float[3]){ox - 0.5f, 1, oz + 0.5f}, (float[3]){1, 0, 0}, (float[3]){0, 0, -1}, 1); /* top */
    m->light[0] = point_light(ox + 1.0f, 2.0f, oz + 2.0f, 8.0f, 5.0f, 4.5f, 4.0f);
    m->light[1] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {-0.25f, -1.0f, -0.5f},
                             .color = {0.3f, 0.3f, 0.35f}};
    m->s.light_count = 2;
    m->s.ambient[0] = m->s.ambient[1] = m->s.ambient[2] = 0.03f;
    m->s.camera = (tl_camera){{ox + 1.5f, 2.0f, oz + 3.5f}, {ox, 0.5f, oz}, {0, 1, 0}, FOV, 0.1f, 100.0f};
}

/* Pixels whose centre and the 8 points `margin` pixels around it all see the same object of `s`
 * (CPU rays): where no edge reaches when the geometry moves by less than `margin`. */
static uint8_t *same_object_mask(const tl_scene *s, double margin, size_t *count)
{
    uint8_t *mask = calloc((size_t)SW * SH, 1);
    TL_CHECK(mask != NULL);
    *count = 0;
    double o[3] = {s->camera.position[0], s->camera.position[1], s->camera.position[2]};
    for (uint32_t y = 0; mask && y < SH; y++)
        for (uint32_t x = 0; x < SW; x++) {
            long first = -2;
            int same = 1;
            for (int k = 0; same && k < 9; k++) {
                double d[3];
                camera_ray(&s->camera, SW, SH, x + 0.5 + margin * (k % 3 - 1), y + 0.5 + margin * (k / 3 - 1), d);
                long hit = scene_ray_object(s, o, d, NULL);
                if (first == -2) first = hit;
                same = hit >= 0 && hit == first;
            }
            if (same) {
                mask[(size_t)y * SW + x] = 1;
                (*count)++;
            }
        }
    return mask;
}

/* The error the translation may cost, and why. At 1e5 a view-space coordinate is computed from
 * terms up to ~1.4e5 (< 2^17), where floats are 2^-7 apart: at most four roundings of one spacing
 * each (three products and the translation of view_proj x world, or the CPU's view matrix),
 * FAR_EPS = 2^-5 = 0.031 units, in any direction. So the frame at 1e5 may differ from the origin's
 * by what moving the surface by FAR_EPS does: measured at the origin by moving the point light,
 * then the camera, by +-FAR_EPS along each axis (12 frames; the maximum change per value is the
 * envelope; the directional light does not care). A mode that rebuilds positions from depth gets
 * the depth's error along the view ray: its window depth is z_clip / w_clip, two sums with their
 * own rounding FAR_EPS, and ndc(z) = -a - b / z with |b| ~ 2 near, so the view depth moves by
 * FAR_EPS x z / near (0.55 units at z = 3.5 for this near plane of 0.1): its envelope is taken
 * (1 + z / near) times. Each interior value (same_object_mask, 2 pixels: the geometry moves by
 * FAR_EPS x 155.9 / 3 = 1.6 pixels at most at this size) must lie within its envelope plus two FP16
 * steps; outside the interior only NaN and Inf are refused, and the covered pixel counts may differ
 * by at most the pixels covered outside it. Measured (llvmpipe): the worst value at 0.31 (fat,
 * forward: 0.7 % relative) and 0.17 (thin modes: 14 % relative, on the point-lit box) of its
 * bound; with the envelope of a move by 2^-7 unscaled, the thin modes' worst is 20 times it, fat's
 * and forward's 1.0 times. */
#define FAR_EPS 0x1.0p-5
TL_TEST(stiff_geometry_coordinates_at_1e5_match_origin)
{
    static mini_scene origin, far, moved;
    far_scene(&origin, 0.0f, 0.0f);
    far_scene(&far, 1e5f, 1e5f);
    size_t interior = 0, np = (size_t)SW * SH;
    uint8_t *mask = same_object_mask(&origin.s, 2.0, &interior);
    float *env = malloc(np * 4 * sizeof *env);
    TL_CHECK(env && interior > np / 5);
    for (size_t mi = 0; mask && env && mi < STIFF_MODE_COUNT; mi++) {
        const char *mode = stiff_modes[mi].name;
        run a, b;
        if (!stiff_run(&a, mode, &origin.s, "at the origin")) continue;
        if (!stiff_run(&b, mode, &far.s, "at 1e5")) {
            run_free(&a);
            continue;
        }
        memset(env, 0, np * 4 * sizeof *env);
        for (int k = 0; k < 12; k++) { /* the light, then the camera, -+FAR_EPS along x, y, z */
            moved = origin;
            moved.s.vertices = moved.v;
            moved.s.indices = moved.idx;
            moved.s.objects = moved.obj;
            moved.s.materials = moved.mat;
            moved.s.lights = moved.light;
            float d = (float)((k & 1) ? FAR_EPS : -FAR_EPS);
            int axis = (k / 2) % 3;
            if (k < 6)
                moved.light[0].position[axis] += d;
            else {
                moved.s.camera.position[axis] += d;
                moved.s.camera.target[axis] += d;
            }
            run c;
            if (!stiff_run(&c, mode, &moved.s, "moved by FAR_EPS")) continue;
            for (size_t q = 0; q < np * 4; q++) env[q] = fmaxf(env[q], fabsf(c.f.hdr[q] - a.f.hdr[q]));
            run_free(&c);
        }
        size_t beyond = 0, cov_a = 0, cov_b = 0;
        double worst = 0.0, worst_rel = 0.0;
        for (size_t px = 0; px < np; px++) {
            cov_a += covered(&a, px);
            cov_b += covered(&b, px);
            if (!mask[px]) continue;
            double z = a.f.depth[4 * px + 1]; /* the DEPTH target's view distance */
            double scale = stiff_modes[mi].positions_from_depth ? 1.0 + z / origin.s.camera.near_z : 1.0;
            for (int ch = 0; ch < 3; ch++) {
                double va = a.f.hdr[4 * px + ch], vb = b.f.hdr[4 * px + ch];
                double bound = scale * env[4 * px + ch] + 2.0 * half_ulp(va), r = fabs(vb - va) / bound;
                worst = fmax(worst, r);
                worst_rel = fmax(worst_rel, fabs(vb - va) / va);
                beyond += !(r <= 1.0);
            }
        }
        size_t edge = cov_a - interior, cov_diff = cov_a > cov_b ? cov_a - cov_b : cov_b - cov_a;
        printf("  1e5, %-14s %zu interior pixels: worst value at %.3f of its bound (%.3g relative), %zu beyond; "
               "covered %zu vs %zu at the origin (%zu outside the interior)\n", mode, interior, worst, worst_rel,
               beyond, cov_b, cov_a, edge);
        TL_CHECK_EQ_U(beyond, 0);
        TL_CHECK_LE(cov_diff, edge);
        run_free(&a);
        run_free(&b);
    }
    free(env);
    free(mask);
}

/* ---- d. more triangles than a limit ---------------------------------------------------------- */

/* The mesh of stiff_mesh_triangle_budget with 2^20 + 1 triangles (the visibility mode's 2^20
 * triangle ids, plus one). A mode without a limit of its own draws it like the band as two
 * triangles (compare_tessellation: no crack, every interior pixel and the mean the quad's); a mode
 * with a limit (stiff_modes[].max_triangles) refuses limit + 1 triangles at set_scene or render,
 * with a message naming the triangles, and draws a mesh of exactly `limit`. On llvmpipe the 2^20
 * triangles cost about a second a mode (the host memory: 38 MB of scene, the renderer's copy). */
#define BUDGET_N (((size_t)1 << 20) + 1)

/* A renderer of mode `name` given the scene: 1 when set_scene and a frame succeeded, 0 when one of
 * them refused (its message in `msg`). */
static int budget_try(const char *name, const tl_scene *s, char *msg, size_t size)
{
    tl_render_mode mode;
    TL_CHECK(tl_render_mode_from_name(name, &mode) == TL_OK);
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = {.options.mode = mode, .width = SW,
                                                                            .height = SH}});
    if (!r) return -1;
    tl_result res = tl_renderer_set_scene(r, s);
    if (res == TL_OK) res = tl_renderer_render(r, NULL, NULL);
    snprintf(msg, size, "%s", res == TL_OK ? "" : tl_renderer_last_error(r));
    tl_renderer_destroy(r);
    return res == TL_OK;
}

TL_TEST(stiff_geometry_triangle_count_over_limit)
{
    for (size_t mi = 0; mi < STIFF_MODE_COUNT; mi++) {
        const char *mode = stiff_modes[mi].name;
        size_t limit = stiff_modes[mi].max_triangles;
        stiff_scene big;
        if (limit) { /* refused past the limit, by name; drawn at it */
            char msg[512];
            if (!stiff_mesh_triangle_budget(&big, limit + 1)) return;
            int drawn = budget_try(mode, &big.s, msg, sizeof msg);
            printf("  %s, %zu triangles (limit %zu): %s\n", mode, limit + 1, limit, drawn ? "drawn" : msg);
            TL_CHECK(drawn == 0);
            TL_CHECK(strstr(msg, "triangle") != NULL);
            stiff_scene_free(&big);
            if (!stiff_mesh_triangle_budget(&big, limit)) return;
            TL_CHECK(budget_try(mode, &big.s, msg, sizeof msg) == 1);
            stiff_scene_free(&big);
            continue;
        }
        stiff_scene band;
        run q, u;
        if (!budget_plain(&band)) return;
        if (stiff_run(&q, mode, &band.s, "band as two triangles")) {
            if (stiff_mesh_triangle_budget(&big, BUDGET_N)) {
                char what[64];
                snprintf(what, sizeof what, "band of %zu triangles", BUDGET_N);
                if (stiff_run(&u, mode, &big.s, what)) {
                    double tol = TESS_TOL + stiff_modes[mi].albedo_rel;
                    tess_result t = compare_tessellation(&u, &q, tol);
                    check_tessellation(what, mode, tol, &t);
                    run_free(&u);
                }
                stiff_scene_free(&big);
            }
            run_free(&q);
        }
        stiff_scene_free(&band);
    }
}
