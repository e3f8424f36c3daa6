/* The lighting models in rendered frames (issue 13): ambient as a parameter, GGX in every mode
 * and light strategy against the double-precision reference (tests/common/reference) pixel by
 * pixel, the light pre-pass's two specular layouts against fat, and extreme cases. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ggx_scene.h"
#include "render_fixture.h"
#include "tl_test.h"

#define W 160
#define H 120

typedef struct frame {
    float *hdr, *pos; /* W x H x 4; pos only when asked (fat) */
} frame;

/* Every renderer here: W x H without FXAA, every target and the frame's statistics readable. */
static tl_renderer *make(tl_renderer_desc d)
{
    d.width = W;
    d.height = H;
    d.options.fxaa = TL_FXAA_OFF;
    return tl_test_renderer(&(tl_test_renderer_desc){.renderer = d, .readable = true});
}

static float *read_target(tl_renderer *r, tl_target_id t)
{
    size_t size = (size_t)W * H * 4 * sizeof(float);
    float *buf = malloc(size);
    if (buf && tl_renderer_read_target(r, t, buf, &size) != TL_OK) {
        free(buf);
        buf = NULL;
    }
    return buf;
}

/* Renders the scene once; 0 after a failed check. */
static int render(tl_renderer_desc d, const tl_scene *s, frame *f)
{
    memset(f, 0, sizeof *f);
    tl_renderer *r = make(d);
    TL_CHECK(r != NULL);
    if (!r) return 0;
    int ok = tl_renderer_set_scene(r, s) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK &&
             tl_renderer_wait(r, NULL) == TL_OK;
    TL_CHECK(ok);
    if (ok) {
        f->hdr = read_target(r, TL_TARGET_HDR);
        if (d.options.mode == TL_MODE_FAT) f->pos = read_target(r, TL_TARGET_FAT_POSITION);
    }
    tl_renderer_destroy(r);
    TL_CHECK(f->hdr != NULL);
    return ok && f->hdr;
}

static void frame_free(frame *f)
{
    free(f->hdr);
    free(f->pos);
}

/* ---- ambient as a parameter ------------------------------------------------------------------ */

/* No lights, no emission: HDR is albedo * ambient exactly (to FP16), the scene's ambient by
 * default, the descriptor's when set, and exactly 0 when asked for with negative components. */
TL_TEST(ambient_parameter_scene_default_override_and_zero)
{
    ggx_scene *g = malloc(sizeof *g);
    ggx_scene_build(g);
    g->s.light_count = 0;
    const float asked[3][3] = {{0, 0, 0}, {0.25f, 0.5f, 1.0f}, {-1, -1, -1}};
    const double expect[3][3] = {{0.03, 0.03, 0.03}, {0.25, 0.5, 1.0}, {0, 0, 0}};
    for (int m = TL_MODE_THIN_LPP; m < TL_MODE_COUNT_; m++)
        for (int c = 0; c < 3; c++) {
            tl_renderer_desc d = {.options.mode = (tl_render_mode)m};
            memcpy(d.options.ambient, asked[c], sizeof d.options.ambient);
            frame f;
            if (!render(d, &g->s, &f)) continue;
            /* the plane's pixel in the bottom row centre: albedo 0.5 */
            const float *px = &f.hdr[(size_t)(2 * W + W / 2) * 4];
            for (int k = 0; k < 3; k++) {
                double want = 0.5 * expect[c][k];
                TL_CHECK_LE(fabs(px[k] - want), want * TL_HALF_REL_STEP * 2 + 1e-7);
            }
            frame_free(&f);
        }
    free(g);
}

TL_TEST(ambient_parameter_not_finite_is_refused)
{
    if (!ensure_context()) {
        TL_CHECK(0);
        return;
    }
    tl_renderer_desc d = {.width = 8, .height = 8, .get_proc_address = tl_context_proc_loader,
                          .get_proc_address_user = g_ctx, .options.ambient = {0, NAN, 0}};
    tl_renderer *r = (tl_renderer *)&d;
    TL_CHECK(tl_renderer_create(&d, &r) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(r == NULL);
}

/* ---- against the double reference ------------------------------------------------------------ */

/* How far a frame's HDR is from the reference, pixel by pixel over the points of the plane and the
 * sphere (silhouette pixels whose position lies on neither, within 1 %, are left out). The normal
 * a mode stores is off by up to `normal_error` radians (its format's bound), which moves radiance
 * by more than any tolerance near the terminator (n.l -> 0): the reference is therefore the range
 * [lo, hi] of the radiance over the normal tilted by that angle four ways, and the error is the
 * distance outside it relative to the untilted value plus `floor` (an absolute allowance for values
 * near zero). */
typedef struct ref_error {
    double max_rel, mean_rel;
    size_t compared, nonfinite;
    int worst_x, worst_y;
} ref_error;

typedef struct ref_setup {
    double view[16], ambient[3];
    tl_ref_light lights[GGX_MAX_LIGHTS];
    size_t light_count;
    tl_ref_surface surf[2];
    tl_ref_model model;
} ref_setup;

/* The reference's range over the tilted normals; centre[] the untilted value. */
static void ref_range(const ref_setup *rs, int obj, const double p[3], const double n[3], double normal_error,
                      double centre[3], double lo[3], double hi[3])
{
    tl_ref_shade(rs->model, &rs->surf[obj], p, n, rs->lights, rs->light_count, rs->ambient, centre);
    double a[3] = {fabs(n[0]) < 0.9 ? 1.0 : 0.0, fabs(n[0]) < 0.9 ? 0.0 : 1.0, 0.0}, t[2][3];
    t[0][0] = n[1] * a[2] - n[2] * a[1];
    t[0][1] = n[2] * a[0] - n[0] * a[2];
    t[0][2] = n[0] * a[1] - n[1] * a[0];
    double l = sqrt(t[0][0] * t[0][0] + t[0][1] * t[0][1] + t[0][2] * t[0][2]);
    for (int k = 0; k < 3; k++) t[0][k] /= l;
    t[1][0] = n[1] * t[0][2] - n[2] * t[0][1];
    t[1][1] = n[2] * t[0][0] - n[0] * t[0][2];
    t[1][2] = n[0] * t[0][1] - n[1] * t[0][0];
    for (int k = 0; k < 3; k++) lo[k] = hi[k] = centre[k];
    for (int j = 0; j < 4; j++) {
        double m[3], c[3], sgn = j & 1 ? -1.0 : 1.0, tn = tan(normal_error);
        for (int k = 0; k < 3; k++) m[k] = n[k] + sgn * tn * t[j >> 1][k];
        tl_ref_shade(rs->model, &rs->surf[obj], p, m, rs->lights, rs->light_count, rs->ambient, c);
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], c[k]);
            hi[k] = fmax(hi[k], c[k]);
        }
    }
}

/* A pixel with a 4-neighbour on another surface (or none). */
static int ggx_on_edge(signed char cls[H][W], int x, int y)
{
    const int dx[4] = {-1, 1, 0, 0}, dy[4] = {0, 0, -1, 1};
    for (int k = 0; k < 4; k++) {
        int u = x + dx[k], v = y + dy[k];
        if (u >= 0 && v >= 0 && u < W && v < H && cls[v][u] != cls[y][x]) return 1;
    }
    return 0;
}

/* skip_edges (thin-deferred): each pixel's missing chroma is rebuilt from its neighbours, which
 * across an object's edge is the codec's documented loss (docs/precision.md), not the lighting's;
 * and black albedo comes back one 8-bit sRGB step off (the same page), so the allowance grows by
 * that step, linear 1 / (255 x 12.92), times the pixel's diffuse irradiance. */
#define ALBEDO_BLACK_STEP (1.0 / (255.0 * 12.92))
static ref_error compare_reference(const ggx_scene *g, const frame *fat, const float *hdr, tl_render_mode mode,
                                   tl_ref_model model, double normal_error, double floor, int skip_edges)
{
    ref_error e = {0};
    ref_setup rs;
    rs.model = model;
    ggx_view_matrix(&g->s.camera, rs.view);
    rs.light_count = ggx_ref_lights(g, rs.view, rs.lights);
    for (int k = 0; k < 3; k++) rs.ambient[k] = g->s.ambient[k];
    for (int m = 0; m < 2; m++) ggx_ref_surface(&g->mat[m], mode, &rs.surf[m]);
    static signed char cls[H][W];
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            const float *q = &fat->pos[((size_t)y * W + x) * 4];
            double p[3] = {q[0], q[1], q[2]}, n[3];
            cls[y][x] = (signed char)(q[3] < 0.5f ? -2 : ggx_classify(g, rs.view, p, n));
        }
    double sum = 0.0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t i = ((size_t)y * W + x) * 4;
            for (int k = 0; k < 3; k++) e.nonfinite += !isfinite(hdr[i + k]);
            if (cls[y][x] < 0 || (skip_edges && ggx_on_edge(cls, x, y))) continue;
            double p[3] = {fat->pos[i], fat->pos[i + 1], fat->pos[i + 2]}, n[3], ref[3], lo[3], hi[3];
            int obj = ggx_classify(g, rs.view, p, n);
            ref_range(&rs, obj, p, n, normal_error, ref, lo, hi);
            double irradiance[3] = {0, 0, 0}; /* thin-deferred: diffuse light + ambient, for the albedo step */
            if (skip_edges) {
                tl_ref_surface white = {.albedo = {1, 1, 1}, .occlusion = 1, .gloss = rs.surf[obj].gloss};
                tl_ref_shade(rs.model, &white, p, n, rs.lights, rs.light_count, rs.ambient, irradiance);
            }
            for (int k = 0; k < 3; k++) {
                double v = hdr[i + k], out = v < lo[k] ? lo[k] - v : v > hi[k] ? v - hi[k] : 0.0;
                out = fmax(out - ALBEDO_BLACK_STEP * irradiance[k], 0.0);
                double rel = v != v ? INFINITY : out / (ref[k] + floor);
                sum += rel;
                e.compared++;
                if (rel > e.max_rel) {
                    e.max_rel = rel;
                    e.worst_x = x;
                    e.worst_y = y;
                }
            }
        }
    e.mean_rel = e.compared ? sum / (double)e.compared : 0.0;
    return e;
}

static void report(const char *what, ref_error e)
{
    printf("%-44s max %.3f %% at (%d, %d), mean %.4f %% over %zu values\n", what, 100.0 * e.max_rel, e.worst_x,
           e.worst_y, 100.0 * e.mean_rel, e.compared);
}

/* The fat frame of the scene: positions for the reference, and HDR. */
static int fat_frame(const ggx_scene *g, tl_lighting_model model, frame *fat)
{
    return render((tl_renderer_desc){.options.mode = TL_MODE_FAT, .options.lighting = model}, &g->s, fat);
}

/* Absolute allowance: FP16's step at the dimmest lit values the scene has (ambient 0.015). */
#define REF_FLOOR 1e-4
/* The stored normals' angular error bounds: fat's RGBA16F components are within half an FP16 step,
 * 2^-11 relative, so the direction within about sqrt(3) 2^-11 rad; RT0's oct12-precise within
 * 0.0395 degrees (docs/precision.md). Forward shades the interpolated normal itself. */
#define FAT_NORMAL_ERROR (1.7320508 / 2048.0)
#define OCT12_NORMAL_ERROR (0.0395 * 3.14159265358979 / 180.0)

/* Renders `d` and checks its HDR against the reference within `tol`; most pixels compared. */
static void check_mode(const ggx_scene *g, const frame *fat, tl_renderer_desc d, double tol, const char *what)
{
    frame f;
    if (!render(d, &g->s, &f)) return;
    tl_ref_model model = d.options.lighting == TL_LIGHTING_BLINN_PHONG ? TL_REF_MODEL_BLINN_PHONG : TL_REF_MODEL_GGX;
    double normal_error = d.options.mode == TL_MODE_FAT       ? FAT_NORMAL_ERROR
                          : d.options.mode == TL_MODE_FORWARD ? 0.0
                                                              : OCT12_NORMAL_ERROR;
    ref_error e = compare_reference(g, fat, f.hdr, d.options.mode, model, normal_error, REF_FLOOR,
                                    d.options.mode == TL_MODE_THIN_DEFERRED);
    report(what, e);
    TL_CHECK(e.compared > (size_t)W * H * 3 / 2 * 9 / 10);
    TL_CHECK_EQ_U(e.nonfinite, 0);
    TL_CHECK_LE(e.max_rel, tol);
    frame_free(&f);
}

/* The bounds (docs/renderer.md, "Precision against the reference"), beyond the stored normal's
 * angular error, which the reference range already covers: fat and forward hold float data and
 * round HDR (and fat the light sums) to FP16, 2^-11 relative per rounding; thin-lpp adds D24
 * depth (relative position error below 1e-5 here) and FP16 light sums, and is held to the same
 * 0.5 %. Thin-deferred stores albedo as 8-bit sRGB YCbCr: half a step at linear 0.5 is 0.64 %,
 * and neutral greys come back one step off (docs/precision.md), so 2 %. */
#define FAT_TOL 0.005
#define THIN_LPP_TOL 0.005
#define THIN_DEFERRED_TOL 0.02

static const char *const strategy_names[] = {"", "volumes", "tiled"};

TL_TEST(ggx_fat_and_forward_match_reference_every_strategy)
{
    ggx_scene *g = malloc(sizeof *g);
    ggx_scene_build(g);
    frame fat;
    if (fat_frame(g, TL_LIGHTING_GGX, &fat)) {
        for (int s = TL_LIGHT_STRATEGY_VOLUMES; s <= TL_LIGHT_STRATEGY_TILED; s++) {
            char what[64];
            snprintf(what, sizeof what, "ggx fat %s", strategy_names[s]);
            check_mode(g, &fat, (tl_renderer_desc){.options.mode = TL_MODE_FAT, .options.lighting = TL_LIGHTING_GGX,
                                                   .options.light_strategy = (tl_light_strategy)s}, FAT_TOL, what);
            snprintf(what, sizeof what, "ggx forward %s", strategy_names[s]);
            check_mode(g, &fat, (tl_renderer_desc){.options.mode = TL_MODE_FORWARD, .options.lighting = TL_LIGHTING_GGX,
                                                   .options.light_strategy = (tl_light_strategy)s}, FAT_TOL, what);
        }
        frame_free(&fat);
    }
    free(g);
}

TL_TEST(ggx_thin_modes_match_reference_every_strategy)
{
    ggx_scene *g = malloc(sizeof *g);
    ggx_scene_build(g);
    frame fat;
    if (fat_frame(g, TL_LIGHTING_GGX, &fat)) {
        const tl_tiled_shading shading[] = {TL_TILED_SHADING_FRAGMENT, TL_TILED_SHADING_COMPUTE};
        for (int s = TL_LIGHT_STRATEGY_VOLUMES; s <= TL_LIGHT_STRATEGY_TILED; s++)
            for (int c = 0; c < (s == TL_LIGHT_STRATEGY_TILED ? 2 : 1); c++) {
                char what[64];
                tl_renderer_desc d = {.options.mode = TL_MODE_THIN_LPP, .options.lighting = TL_LIGHTING_GGX,
                                      .options.light_strategy = (tl_light_strategy)s,
                                      .options.tiled_shading = shading[c]};
                snprintf(what, sizeof what, "ggx thin-lpp two sums %s%s", strategy_names[s], c ? " compute" : "");
                check_mode(g, &fat, d, THIN_LPP_TOL, what);
                d.options.mode = TL_MODE_THIN_DEFERRED;
                snprintf(what, sizeof what, "ggx thin-deferred %s%s", strategy_names[s], c ? " compute" : "");
                check_mode(g, &fat, d, THIN_DEFERRED_TOL, what);
            }
        frame_free(&fat);
    }
    free(g);
}

/* The same scene under Blinn-Phong: the model switch changes nothing of today's model. */
TL_TEST(blinn_phong_fat_and_thin_lpp_match_reference)
{
    ggx_scene *g = malloc(sizeof *g);
    ggx_scene_build(g);
    frame fat;
    if (fat_frame(g, TL_LIGHTING_BLINN_PHONG, &fat)) {
        check_mode(g, &fat, (tl_renderer_desc){.options.mode = TL_MODE_FAT,
                                               .options.lighting = TL_LIGHTING_BLINN_PHONG},
                   FAT_TOL, "blinn-phong fat");
        check_mode(g, &fat, (tl_renderer_desc){.options.mode = TL_MODE_THIN_LPP,
                                               .options.lighting = TL_LIGHTING_BLINN_PHONG},
                   THIN_LPP_TOL, "blinn-phong thin-lpp");
        frame_free(&fat);
    }
    free(g);
}

/* ---- the light pre-pass's two Fresnel layouts ------------------------------------------------- */

/* The cheap layout's own model: one specular sum S = sum c w, times Schlick with n.v per pixel. */
static void ref_shade_nv(const tl_ref_surface *s, const double p[3], const double n[3], const tl_ref_light *lights,
                         size_t count, const double ambient[3], double out[3])
{
    double v[3] = {-p[0], -p[1], -p[2]}, lv = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; k++) v[k] /= lv;
    double diffuse[3] = {0}, spec[3] = {0}, alpha = tl_ref_ggx_alpha(s->gloss);
    for (size_t j = 0; j < count; j++) {
        double t[3];
        tl_ref_ggx_terms(&lights[j], p, n, v, alpha, t);
        for (int k = 0; k < 3; k++) {
            diffuse[k] += fmin(lights[j].color[k] * t[0], 65504.0);
            spec[k] += fmin(lights[j].color[k] * t[1], 65504.0) + fmin(lights[j].color[k] * t[2], 65504.0);
        }
    }
    double nv = fmin(fmax(n[0] * v[0] + n[1] * v[1] + n[2] * v[2], 0.0), 1.0);
    double w = tl_ref_fresnel_weight(nv);
    for (int k = 0; k < 3; k++)
        out[k] = s->albedo[k] * (diffuse[k] + ambient[k] * s->occlusion) + (s->specular[k] * (1.0 - w) + w) * spec[k];
}

/* PSNR of a against b over the covered pixels, with the peak of b (HDR has no fixed peak). */
static double hdr_psnr(const frame *fat, const float *a, const float *b)
{
    double se = 0.0, peak = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        if (fat->pos[i * 4 + 3] < 0.5f) continue;
        for (int k = 0; k < 3; k++) {
            double d = (double)a[i * 4 + k] - b[i * 4 + k];
            se += d * d;
            peak = fmax(peak, b[i * 4 + k]);
            n++;
        }
    }
    return se > 0.0 ? 10.0 * log10(peak * peak / (se / (double)n)) : INFINITY;
}

/* The n.v layout renders its own model (checked against ref_shade_nv within thin-lpp's bound); the
 * two-sums layout renders GGX exactly. Printed: how far n.v is from the exact model (the model's
 * error, not the renderer's). */
TL_TEST(ggx_fresnel_layouts_render_their_models)
{
    ggx_scene *g = malloc(sizeof *g);
    ggx_scene_build(g);
    frame fat, sums, nv;
    if (fat_frame(g, TL_LIGHTING_GGX, &fat)) {
        tl_renderer_desc d = {.options.mode = TL_MODE_THIN_LPP, .options.lighting = TL_LIGHTING_GGX,
                              .options.fresnel = TL_FRESNEL_TWO_SUMS};
        int ok = render(d, &g->s, &sums);
        d.options.fresnel = TL_FRESNEL_NV;
        ok = render(d, &g->s, &nv) && ok;
        if (ok) {
            ref_setup rs = {.model = TL_REF_MODEL_GGX};
            for (int k = 0; k < 3; k++) rs.ambient[k] = g->s.ambient[k];
            ggx_view_matrix(&g->s.camera, rs.view);
            rs.light_count = ggx_ref_lights(g, rs.view, rs.lights);
            for (int m = 0; m < 2; m++) ggx_ref_surface(&g->mat[m], TL_MODE_THIN_LPP, &rs.surf[m]);
            double worst = 0.0, amb[3] = {g->s.ambient[0], g->s.ambient[1], g->s.ambient[2]};
            for (size_t i = 0; i < (size_t)W * H; i++) {
                double p[3] = {fat.pos[i * 4], fat.pos[i * 4 + 1], fat.pos[i * 4 + 2]}, n[3], ref[3], c[3], lo[3], hi[3];
                int obj = fat.pos[i * 4 + 3] < 0.5f ? -1 : ggx_classify(g, rs.view, p, n);
                if (obj < 0) continue;
                ref_shade_nv(&rs.surf[obj], p, n, rs.lights, rs.light_count, amb, ref);
                /* the normal's range, as for the exact model: scaled from the exact reference's */
                ref_range(&rs, obj, p, n, OCT12_NORMAL_ERROR, c, lo, hi);
                for (int k = 0; k < 3; k++) {
                    double slack = (hi[k] - lo[k]) * (ref[k] + REF_FLOOR) / (lo[k] + REF_FLOOR);
                    double rel = fmax(fabs(nv.hdr[i * 4 + k] - ref[k]) - slack, 0.0) / (ref[k] + REF_FLOOR);
                    worst = fmax(worst, rel);
                }
            }
            printf("n.v layout against its own model: max %.3f %%\n", 100.0 * worst);
            TL_CHECK_LE(worst, THIN_LPP_TOL);
            double p_sums = hdr_psnr(&fat, sums.hdr, fat.hdr), p_nv = hdr_psnr(&fat, nv.hdr, fat.hdr);
            printf("HDR PSNR against fat: two sums %.2f dB, n.v %.2f dB\n", p_sums, p_nv);
            TL_CHECK(p_sums >= p_nv);
        }
        frame_free(&sums);
        frame_free(&nv);
        frame_free(&fat);
    }
    free(g);
}

/* F0 = 1 makes Schlick's F 1 whatever the angle: both layouts then render the same image (to the
 * FP16 rounding of their sums: S1 + S2 once against S1 and S2 apart). */
TL_TEST(ggx_fresnel_layouts_agree_for_white_metal)
{
    ggx_scene *g = malloc(sizeof *g);
    ggx_scene_build(g);
    for (int m = 0; m < 2; m++) {
        g->mat[m].albedo[0] = g->mat[m].albedo[1] = g->mat[m].albedo[2] = 0.0f;
        g->mat[m].specular[0] = g->mat[m].specular[1] = g->mat[m].specular[2] = 1.0f;
    }
    frame a, b;
    tl_renderer_desc d = {.options.mode = TL_MODE_THIN_LPP, .options.lighting = TL_LIGHTING_GGX,
                          .options.fresnel = TL_FRESNEL_TWO_SUMS};
    int ok = render(d, &g->s, &a);
    d.options.fresnel = TL_FRESNEL_NV;
    ok = render(d, &g->s, &b) && ok;
    if (ok) {
        double worst = 0.0;
        for (size_t i = 0; i < (size_t)W * H * 4; i++)
            if (i % 4 != 3) worst = fmax(worst, fabs(a.hdr[i] - b.hdr[i]) / (fabs(a.hdr[i]) + REF_FLOOR));
        printf("white metal: layouts differ by at most %.4f %%\n", 100.0 * worst);
        TL_CHECK_LE(worst, 4.0 * TL_HALF_REL_STEP);
    }
    frame_free(&a);
    frame_free(&b);
    free(g);
}

/* ---- extreme cases (docs/stability.md) under GGX ------------------------------------------- */

/* Every target of every mode, strategy and layout stays finite and non-negative: roughness 0 (the
 * smoothest lobe, gloss 1) and 1 (gloss 0), a grazing camera and a grazing directional light,
 * point lights inside the sphere, just below the plane and on its surface. */
TL_TEST(ggx_extremes_stay_finite_every_mode)
{
    ggx_scene *g = malloc(sizeof *g);
    ggx_scene_build(g);
    g->mat[0].gloss = 0.0f;
    g->mat[1].gloss = 1.0f;
    g->s.camera.position[1] = 0.02f; /* n.v -> 0 on the plane */
    g->s.camera.target[1] = 0.02f;
    g->lights[2].direction[0] = 1.0f; /* n.l -> 0 on the plane */
    g->lights[2].direction[1] = -1e-4f;
    g->lights[2].direction[2] = 0.0f;
    g->lights[0].position[0] = 0.0f; /* inside the sphere */
    g->lights[0].position[1] = 1.3f;
    g->lights[0].position[2] = 0.0f;
    g->lights[3] = (tl_light){.type = TL_LIGHT_POINT, .position = {1.5f, 0.0f, 1.0f}, .color = {50, 50, 50},
                              .radius = 3.0f}; /* on the plane */
    g->s.light_count = 4;
    const tl_target_id ids[] = {TL_TARGET_HDR, TL_TARGET_LIGHT_DIFFUSE, TL_TARGET_LIGHT_SPECULAR, TL_TARGET_LIGHT_FRESNEL};
    for (int pass = 0; pass < 2; pass++) {
        if (pass) g->lights[3].position[1] = -1e-3f; /* just below it */
        for (int m = TL_MODE_THIN_LPP; m < TL_MODE_COUNT_; m++)
            for (int s = TL_LIGHT_STRATEGY_VOLUMES; s <= TL_LIGHT_STRATEGY_TILED; s++)
                for (int f = TL_FRESNEL_TWO_SUMS; f <= (m == TL_MODE_THIN_LPP ? TL_FRESNEL_NV : TL_FRESNEL_TWO_SUMS); f++) {
                    tl_renderer *r = make((tl_renderer_desc){.options.mode = (tl_render_mode)m,
                                                             .options.lighting = TL_LIGHTING_GGX,
                                                             .options.light_strategy = (tl_light_strategy)s,
                                                             .options.fresnel = (tl_fresnel_layout)f});
                    TL_CHECK(r != NULL);
                    if (!r) continue;
                    TL_CHECK(tl_renderer_set_scene(r, &g->s) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK &&
                             tl_renderer_wait(r, NULL) == TL_OK);
                    tl_frame_plan *plan = malloc(sizeof *plan);
                    TL_CHECK(plan && tl_renderer_get_plan(r, plan) == TL_OK);
                    for (size_t t = 0; plan && t < sizeof ids / sizeof ids[0]; t++) {
                        if (!(plan->targets & TL_TARGET_BIT(ids[t]))) continue;
                        float *buf = read_target(r, ids[t]);
                        TL_CHECK(buf != NULL);
                        if (!buf) continue;
                        size_t bad = 0;
                        for (size_t i = 0; i < (size_t)W * H * 4; i++) bad += !(isfinite(buf[i]) && buf[i] >= 0.0f);
                        if (bad)
                            fprintf(stderr, "%s %s fresnel %d pass %d: %zu bad values in %s\n",
                                    tl_render_mode_name((tl_render_mode)m), strategy_names[s], f, pass, bad,
                                    tl_target_name(ids[t]));
                        TL_CHECK_EQ_U(bad, 0);
                        free(buf);
                    }
                    free(plan);
                    tl_renderer_destroy(r);
                }
    }
    free(g);
}

/* ---- the planner (pure) ---------------------------------------------------------------------- */

/* The model follows the materials unless forced; light.fresnel exists exactly for thin-lpp with GGX,
 * specular materials, the exact light buffer and the two-sums layout, in the light format's size. */
TL_TEST(ggx_plan_model_and_fresnel_target)
{
    tl_scene_feature_set f = {.point_lights = 2, .directional_lights = 1, .has_specular = 1};
    tl_frame_plan *p = malloc(sizeof *p);
    tl_renderer_desc d = {.width = 64, .height = 64};
    TL_CHECK(tl_frame_plan_build(&d, &f, p) == TL_OK);
    TL_CHECK(p->lighting == TL_LIGHTING_BLINN_PHONG && p->fresnel == TL_FRESNEL_DEFAULT);
    TL_CHECK(!(p->targets & TL_TARGET_BIT(TL_TARGET_LIGHT_FRESNEL)));
    f.has_microfacet = 1;
    TL_CHECK(tl_frame_plan_build(&d, &f, p) == TL_OK);
    TL_CHECK(p->lighting == TL_LIGHTING_GGX && p->fresnel == TL_FRESNEL_TWO_SUMS);
    TL_CHECK_EQ_U(p->target_bytes_per_pixel[TL_TARGET_LIGHT_FRESNEL], 8);
    TL_CHECK(strstr(p->lighting_reason, "auto") != NULL);
    d.options.light_format = TL_LIGHT_FORMAT_R11G11B10F;
    TL_CHECK(tl_frame_plan_build(&d, &f, p) == TL_OK);
    TL_CHECK_EQ_U(p->target_bytes_per_pixel[TL_TARGET_LIGHT_FRESNEL], 4);
    d.options.light_format = TL_LIGHT_FORMAT_DEFAULT;
    const struct { tl_renderer_desc d; } off[] = {
        {{.width = 64, .height = 64, .options.fresnel = TL_FRESNEL_NV}},
        {{.width = 64, .height = 64, .options.light_buffer = TL_LIGHT_BUFFER_COMPACT}},
        {{.width = 64, .height = 64, .options.lighting = TL_LIGHTING_BLINN_PHONG}},
        {{.width = 64, .height = 64, .options.mode = TL_MODE_FAT}},
        {{.width = 64, .height = 64, .options.mode = TL_MODE_FORWARD}},
    };
    for (size_t i = 0; i < sizeof off / sizeof off[0]; i++) {
        TL_CHECK(tl_frame_plan_build(&off[i].d, &f, p) == TL_OK);
        TL_CHECK(!(p->targets & TL_TARGET_BIT(TL_TARGET_LIGHT_FRESNEL)));
    }
    f.has_specular = 0; /* nothing to apply Fresnel to */
    TL_CHECK(tl_frame_plan_build(&d, &f, p) == TL_OK);
    TL_CHECK(!(p->targets & TL_TARGET_BIT(TL_TARGET_LIGHT_FRESNEL)) && p->fresnel == TL_FRESNEL_DEFAULT);
    d.options.lighting = TL_LIGHTING_COUNT_;
    TL_CHECK(tl_frame_plan_build(&d, &f, p) == TL_ERROR_INVALID_ARGUMENT);
    d.options.lighting = TL_LIGHTING_DEFAULT;
    d.options.fresnel = TL_FRESNEL_COUNT_;
    TL_CHECK(tl_frame_plan_build(&d, &f, p) == TL_ERROR_INVALID_ARGUMENT);
    free(p);
    tl_lighting_model m;
    tl_fresnel_layout fl;
    TL_CHECK(tl_lighting_model_from_name("ggx", &m) == TL_OK && m == TL_LIGHTING_GGX);
    TL_CHECK(tl_lighting_model_from_name("GGX", &m) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_fresnel_layout_from_name("nv", &fl) == TL_OK && fl == TL_FRESNEL_NV);
    TL_CHECK(strcmp(tl_fresnel_layout_name(TL_FRESNEL_DEFAULT), "two-sums") == 0);
}

/* ---- spherical area lights -------------------------------------------------------------------- */

/* Sphere lights (a point light of radius 0.4 m at 2.6 m of the sphere, a spot of 0.25 m) against
 * the reference's sphere lights (irradiance of the sphere, Karis' representative point with its
 * normalisation), within the same bounds as punctual lights, every strategy. */
TL_TEST(ggx_sphere_lights_match_reference_every_strategy)
{
    ggx_scene *g = malloc(sizeof *g);
    ggx_scene_build(g);
    g->lights[0].source_radius = 0.4f;
    g->lights[1].source_radius = 0.25f;
    frame fat;
    if (fat_frame(g, TL_LIGHTING_GGX, &fat)) {
        for (int s = TL_LIGHT_STRATEGY_VOLUMES; s <= TL_LIGHT_STRATEGY_TILED; s++) {
            const struct { tl_render_mode mode; double tol; const char *name; } modes[] = {
                {TL_MODE_FAT, FAT_TOL, "fat"}, {TL_MODE_FORWARD, FAT_TOL, "forward"},
                {TL_MODE_THIN_LPP, THIN_LPP_TOL, "thin-lpp"}, {TL_MODE_THIN_DEFERRED, THIN_DEFERRED_TOL, "thin-deferred"}};
            for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
                char what[64];
                snprintf(what, sizeof what, "ggx sphere lights %s %s", modes[m].name, strategy_names[s]);
                check_mode(g, &fat, (tl_renderer_desc){.options.mode = modes[m].mode,
                                                       .options.lighting = TL_LIGHTING_GGX,
                                                       .options.light_strategy = (tl_light_strategy)s}, modes[m].tol,
                                                       what);
            }
        }
        frame_free(&fat);
    }
    free(g);
}

/* The range still bounds a sphere light (window and cone measured from its centre): volumes lose
 * nothing against the same lights shaded over the whole screen, and tiles nothing against volumes
 * beyond the order of FP16 sums; a sphere light makes a difference under GGX and none under
 * Blinn-Phong, whose lights are punctual. */
TL_TEST(ggx_sphere_lights_volumes_tiles_and_fullscreen_agree)
{
    ggx_scene *g = malloc(sizeof *g);
    ggx_scene_build(g);
    g->lights[0].source_radius = 0.8f;
    g->lights[1].source_radius = 0.5f;
    frame vol, full, tiled, punctual;
    tl_renderer_desc d = {.options.mode = TL_MODE_THIN_LPP, .options.lighting = TL_LIGHTING_GGX,
                          .options.light_strategy = TL_LIGHT_STRATEGY_VOLUMES};
    int ok = render(d, &g->s, &vol);
    d.options.fullscreen_lights = 1;
    ok = render(d, &g->s, &full) && ok;
    d.options.fullscreen_lights = 0;
    d.options.light_strategy = TL_LIGHT_STRATEGY_TILED;
    ok = render(d, &g->s, &tiled) && ok;
    if (ok) {
        double worst_full = 0.0, worst_tiled = 0.0;
        for (size_t i = 0; i < (size_t)W * H * 4; i++) {
            worst_full = fmax(worst_full, fabs(vol.hdr[i] - full.hdr[i]) / (fabs(full.hdr[i]) + REF_FLOOR));
            worst_tiled = fmax(worst_tiled, fabs(vol.hdr[i] - tiled.hdr[i]) / (fabs(vol.hdr[i]) + REF_FLOOR));
        }
        printf("sphere lights: volumes against full screen %.4f %%, tiles against volumes %.4f %%\n",
               100.0 * worst_full, 100.0 * worst_tiled);
        TL_CHECK_LE(worst_full, 4.0 * TL_HALF_REL_STEP);
        TL_CHECK_LE(worst_tiled, 4.0 * TL_HALF_REL_STEP);
    }
    /* GGX sees the radius; Blinn-Phong does not */
    g->lights[0].source_radius = g->lights[1].source_radius = 0.0f;
    d = (tl_renderer_desc){.options.mode = TL_MODE_THIN_LPP, .options.lighting = TL_LIGHTING_GGX};
    if (ok && render(d, &g->s, &punctual)) {
        TL_CHECK(memcmp(punctual.hdr, vol.hdr, (size_t)W * H * 4 * sizeof(float)) != 0);
        frame_free(&punctual);
    }
    d.options.lighting = TL_LIGHTING_BLINN_PHONG;
    frame bp0, bp1;
    if (render(d, &g->s, &bp0)) {
        g->lights[0].source_radius = 0.8f;
        if (render(d, &g->s, &bp1)) {
            TL_CHECK(memcmp(bp0.hdr, bp1.hdr, (size_t)W * H * 4 * sizeof(float)) == 0);
            frame_free(&bp1);
        }
        frame_free(&bp0);
    }
    frame_free(&vol);
    frame_free(&full);
    frame_free(&tiled);
    free(g);
}

/* A source radius larger than the distance to the lit surface (the plane and the sphere inside
 * the emitter), and larger than the light's range: finite everywhere; a negative or non-finite
 * radius is refused. */
TL_TEST(ggx_sphere_light_extremes)
{
    ggx_scene *g = malloc(sizeof *g);
    ggx_scene_build(g);
    g->lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {0.5f, 0.4f, 1.0f}, .color = {30, 30, 30},
                              .radius = 6.0f, .source_radius = 2.0f};
    g->lights[1].source_radius = 20.0f; /* beyond its 8 m range */
    for (int m = TL_MODE_THIN_LPP; m < TL_MODE_COUNT_; m++)
        for (int s = TL_LIGHT_STRATEGY_VOLUMES; s <= TL_LIGHT_STRATEGY_TILED; s++) {
            frame f;
            if (!render((tl_renderer_desc){.options.mode = (tl_render_mode)m, .options.lighting = TL_LIGHTING_GGX,
                                           .options.light_strategy = (tl_light_strategy)s}, &g->s, &f))
                continue;
            size_t bad = 0;
            for (size_t i = 0; i < (size_t)W * H * 4; i++) bad += !(isfinite(f.hdr[i]) && f.hdr[i] >= 0.0f);
            TL_CHECK_EQ_U(bad, 0);
            frame_free(&f);
        }
    tl_renderer *r = make((tl_renderer_desc){.options.lighting = TL_LIGHTING_GGX});
    TL_CHECK(r != NULL);
    if (r) {
        const float bad[2] = {-0.1f, NAN};
        for (int k = 0; k < 2; k++) {
            g->lights[0].source_radius = bad[k];
            TL_CHECK(tl_renderer_set_scene(r, &g->s) == TL_ERROR_INVALID_ARGUMENT);
            TL_CHECK(tl_renderer_set_lights(r, g->lights, 3) == TL_ERROR_INVALID_ARGUMENT);
        }
        tl_renderer_destroy(r);
    }
    free(g);
}
