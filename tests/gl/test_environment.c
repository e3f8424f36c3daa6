/* Background and environment (issue 30): the background colour through the tone map in every
 * mode, the sky drawn from the environment, image-based light on two rows of spheres of varying
 * roughness against a double-precision Monte Carlo reference of the same environment
 * (tests/common/reference/ibl_ref.c) and against fat, the plan without them, and bad input. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, getpid */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "ibl_ref.h"
#include "render_fixture.h"
#include "thinlight/io.h"
#include "tl_test.h"

#define W 260
#define H 120
#define SEG 64
#define RINGS 32
#define SPHERE_VERTICES ((SEG + 1) * (RINGS + 1))
#define SPHERE_INDICES (SEG * RINGS * 6)
#define PER_ROW 5
#define SPHERES (2 * PER_ROW)
#define ENV_W 256
#define ENV_H 128
#define CAM_Z 12.0
#define FOV_TAN 0.22 /* tan(fov_y / 2) */

static const tl_render_mode all_modes[] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_FORWARD,
                                           TL_MODE_VISIBILITY};
#define MODES ((int)(sizeof all_modes / sizeof all_modes[0]))

/* Two rows of five unit spheres (top: a grey dielectric, bottom: gold), perceptual roughness
 * 0, 0.25, 0.5, 0.75, 1 from left to right; no lights; the camera on +Z looking down -Z, so view
 * directions are world directions. */
typedef struct sphere_row {
    tl_vertex v[SPHERE_VERTICES];
    uint32_t idx[SPHERE_INDICES];
    tl_object obj[SPHERES];
    tl_material mat[SPHERES];
    tl_light light; /* black: it only puts fat's position target in the plan, for the tests to read */
    tl_scene s;
    double centre[SPHERES][3];
} sphere_row;

static const double row_albedo[2][3] = {{0.5, 0.5, 0.5}, {0.0, 0.0, 0.0}};
static const double row_f0[2][3] = {{0.04, 0.04, 0.04}, {1.0, 0.766, 0.336}};

static double sphere_roughness(int k)
{
    return (k % PER_ROW) / (double)(PER_ROW - 1);
}

static void sphere_mesh(sphere_row *g)
{
    const double pi = 3.14159265358979323846;
    for (int r = 0; r <= RINGS; r++)
        for (int s = 0; s <= SEG; s++) {
            double th = pi * r / RINGS, ph = 2.0 * pi * s / SEG;
            tl_vertex *x = &g->v[r * (SEG + 1) + s];
            x->position[0] = x->normal[0] = (float)(sin(th) * cos(ph));
            x->position[1] = x->normal[1] = (float)cos(th);
            x->position[2] = x->normal[2] = (float)(-sin(th) * sin(ph));
        }
    size_t n = 0;
    for (int r = 0; r < RINGS; r++)
        for (int s = 0; s < SEG; s++) {
            uint32_t a = (uint32_t)(r * (SEG + 1) + s), b = a + SEG + 1;
            const uint32_t q[6] = {a, b, a + 1, a + 1, b, b + 1};
            for (int i = 0; i < 6; i++) g->idx[n++] = q[i];
        }
}

static void sphere_row_build(sphere_row *g)
{
    memset(g, 0, sizeof *g);
    sphere_mesh(g);
    for (int k = 0; k < SPHERES; k++) {
        int row = k / PER_ROW;
        g->centre[k][0] = 2.2 * (k % PER_ROW - 2);
        g->centre[k][1] = row ? -1.1 : 1.1;
        tl_object *o = &g->obj[k];
        o->index_count = SPHERE_INDICES;
        o->material = (uint32_t)k;
        o->transform[0] = o->transform[5] = o->transform[10] = o->transform[15] = 1.0f;
        o->transform[12] = (float)g->centre[k][0];
        o->transform[13] = (float)g->centre[k][1];
        tl_material *m = &g->mat[k];
        for (int c = 0; c < 3; c++) {
            m->albedo[c] = row ? -1.0f : (float)row_albedo[0][c];
            m->specular[c] = (float)row_f0[row][c];
        }
        m->gloss = (float)(1.0 - sphere_roughness(k));
        m->flags = TL_MATERIAL_MICROFACET;
    }
    g->s = (tl_scene){.vertices = g->v, .vertex_count = SPHERE_VERTICES, .indices = g->idx,
                      .index_count = SPHERE_INDICES, .objects = g->obj, .object_count = SPHERES,
                      .materials = g->mat, .material_count = SPHERES, .lights = &g->light, .light_count = 1};
    g->light = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {0, -1, 0}};
    g->s.camera = (tl_camera){.position = {0, 0, (float)CAM_Z}, .fov_y = (float)(2.0 * atan(FOV_TAN)),
                              .near_z = 1.0f, .far_z = 100.0f};
}

/* Every renderer here: W x H without FXAA and ambient light, every target kept. */
static tl_renderer *make(tl_renderer_options o)
{
    tl_renderer_desc d = {.width = W, .height = H, .options = o};
    d.options.fxaa = TL_FXAA_OFF;
    d.options.keep_targets = TL_TARGETS_ALL;
    d.options.ambient[0] = d.options.ambient[1] = d.options.ambient[2] = -1.0f;
    return tl_test_renderer(&(tl_test_renderer_desc){.renderer = d});
}

static float *environment_image(void)
{
    float *rgb = malloc((size_t)ENV_W * ENV_H * 3 * sizeof *rgb);
    if (rgb) ibl_ref_sky_image(ENV_W, ENV_H, rgb);
    return rgb;
}

/* One frame of the sphere rows with `o` (and the environment when env is not NULL): its HDR and,
 * when pos is not NULL, fat's positions (o must be fat then); 0 after a failed check. */
static int render_rows(const sphere_row *g, tl_renderer_options o, const float *env, float **hdr, float **pos,
                       uint8_t **out)
{
    tl_renderer *r = make(o);
    TL_CHECK(r != NULL);
    if (!r) return 0;
    tl_environment_desc e = {.rgb = env, .width = ENV_W, .height = ENV_H};
    int ok = tl_renderer_set_scene(r, &g->s) == TL_OK && (!env || tl_renderer_set_environment(r, &e) == TL_OK) &&
             tl_renderer_render(r, NULL, NULL) == TL_OK && tl_renderer_wait(r, NULL) == TL_OK;
    TL_CHECK(ok);
    if (ok && hdr) ok = (*hdr = tl_test_read_target(r, TL_TARGET_HDR, (size_t)W * H)) != NULL;
    if (ok && pos) ok = (*pos = tl_test_read_target(r, TL_TARGET_FAT_POSITION, (size_t)W * H)) != NULL;
    if (ok && out) {
        size_t size = (size_t)W * H * 4;
        *out = malloc(size);
        ok = *out && tl_renderer_read_output(r, *out, &size) == TL_OK;
    }
    TL_CHECK(ok);
    tl_renderer_destroy(r);
    return ok;
}

/* ---- the plan ---------------------------------------------------------------------------------- */

static int plan_has(const tl_frame_plan *p, tl_pass pass, const char *define)
{
    for (size_t i = 0; i < p->pass_count; i++)
        if (p->passes[i].pass == pass && !define) return 1;
    for (size_t i = 0; define && i < p->program_count; i++)
        if (strstr(p->programs[i].defines, define)) return 1;
    return 0;
}

/* No background and no environment: no sky pass, no TL_IBL, in every mode; a background adds the
 * sky pass alone; an environment adds it and TL_IBL; removing the environment gives back the
 * first plan exactly. */
TL_TEST(environment_plan_only_when_asked)
{
    sphere_row *g = malloc(sizeof *g);
    float *env = environment_image();
    sphere_row_build(g);
    for (int m = 0; m < MODES; m++) {
        tl_renderer *r = make((tl_renderer_options){.mode = all_modes[m]});
        TL_CHECK(r && tl_renderer_set_scene(r, &g->s) == TL_OK);
        if (!r) continue;
        tl_frame_plan p0, p1, p2;
        tl_renderer_get_plan(r, &p0);
        TL_CHECK(!plan_has(&p0, TL_PASS_SKY, NULL) && !plan_has(&p0, TL_PASS_COUNT, "TL_IBL"));
        tl_environment_desc e = {.rgb = env, .width = ENV_W, .height = ENV_H};
        TL_CHECK(tl_renderer_set_environment(r, &e) == TL_OK);
        tl_renderer_get_plan(r, &p1);
        TL_CHECK(plan_has(&p1, TL_PASS_SKY, NULL) && plan_has(&p1, TL_PASS_COUNT, "TL_IBL"));
        TL_CHECK(plan_has(&p1, TL_PASS_COUNT, "TL_SKY_ENV"));
        TL_CHECK(tl_renderer_set_environment(r, NULL) == TL_OK);
        tl_renderer_get_plan(r, &p2);
        TL_CHECK(memcmp(&p0, &p2, sizeof p0) == 0);
        tl_renderer_options o;
        tl_renderer_get_options(r, &o);
        o.environment.background[2] = 0.5f;
        TL_CHECK(tl_renderer_set_options(r, &o) == TL_OK);
        tl_renderer_get_plan(r, &p2);
        TL_CHECK(plan_has(&p2, TL_PASS_SKY, NULL) && !plan_has(&p2, TL_PASS_COUNT, "TL_IBL"));
        TL_CHECK(!plan_has(&p2, TL_PASS_COUNT, "TL_SKY_ENV"));
        tl_renderer_destroy(r);
    }
    free(env);
    free(g);
}

/* An environment set and removed leaves no trace: the frame's output bytes equal those of a
 * renderer that never had one, in every mode. */
TL_TEST_FULL(environment_removed_renders_todays_bytes)
{
    sphere_row *g = malloc(sizeof *g);
    float *env = environment_image();
    sphere_row_build(g);
    for (int m = 0; m < MODES; m++) {
        uint8_t *a = NULL, *b = NULL;
        tl_renderer_options o = {.mode = all_modes[m]};
        render_rows(g, o, NULL, NULL, NULL, &a);
        tl_renderer *r = make(o);
        tl_environment_desc e = {.rgb = env, .width = ENV_W, .height = ENV_H};
        size_t size = (size_t)W * H * 4;
        b = malloc(size);
        int ok = r && tl_renderer_set_scene(r, &g->s) == TL_OK && tl_renderer_set_environment(r, &e) == TL_OK &&
                 tl_renderer_render(r, NULL, NULL) == TL_OK && tl_renderer_set_environment(r, NULL) == TL_OK &&
                 tl_renderer_render(r, NULL, NULL) == TL_OK && tl_renderer_read_output(r, b, &size) == TL_OK;
        TL_CHECK(ok);
        TL_CHECK(a && b && memcmp(a, b, size) == 0);
        tl_renderer_destroy(r);
        free(a);
        free(b);
    }
    free(env);
    free(g);
}

/* ---- the background colour --------------------------------------------------------------------- */

static double aces(double x)
{
    double t = x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
    return t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
}

static double srgb(double c)
{
    return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

/* Whether pixel (x, y) and its 8 neighbours are background (fat's position w is 0 there): with
 * MSAA a pixel beside a surface may hold some of its samples. */
static int background_inside(const float *pos, size_t x, size_t y)
{
    if (x == 0 || y == 0 || x + 1 == W || y + 1 == H) return 0;
    for (size_t yy = y - 1; yy <= y + 1; yy++)
        for (size_t xx = x - 1; xx <= x + 1; xx++)
            if (pos[(yy * W + xx) * 4 + 3] != 0.0f) return 0;
    return 1;
}

/* The background's pixels (fat's position w is 0 there) hold the colour through exposure, the
 * tone curve and sRGB within one 8-bit step, in every mode and with MSAA. */
TL_TEST(background_colour_through_tone_map_every_mode)
{
    sphere_row *g = malloc(sizeof *g);
    sphere_row_build(g);
    const float bg[3] = {0.2f, 0.5f, 1.5f};
    float *pos = NULL;
    render_rows(g, (tl_renderer_options){.mode = TL_MODE_FAT}, NULL, NULL, &pos, NULL);
    TL_CHECK(pos != NULL);
    for (int m = 0; m < MODES + 1 && pos; m++) { /* every mode, then thin-lpp with MSAA */
        tl_renderer_options o = {.mode = all_modes[m % MODES], .exposure = 1.3f, .msaa = m == MODES ? 4u : 0u};
        memcpy(o.environment.background, bg, sizeof bg);
        uint8_t *out = NULL;
        render_rows(g, o, NULL, NULL, NULL, &out);
        TL_CHECK(out != NULL);
        size_t n = 0, bad = 0;
        for (size_t i = 0; out && i < (size_t)W * H; i++) {
            size_t x = i % W, y = i / W;
            if (!background_inside(pos, x, y)) continue;
            n++;
            for (int c = 0; c < 3; c++) /* the output's rows are bottom-up, as the targets' */
                if (fabs(out[i * 4 + c] - 255.0 * srgb(aces(bg[c] * 1.3))) > 1.0) bad++;
        }
        TL_CHECK(n > (size_t)W * H / 3);
        TL_CHECK_EQ_U(bad, 0);
        free(out);
    }
    free(pos);
    free(g);
}

/* ---- the sky ------------------------------------------------------------------------------------ */

/* The world direction of pixel (x, y) (y up) of the sphere rows' camera (looking down -Z), or of
 * the same camera turned to look down -X (seam: the image's wrap at u = 0 is in view). */
static void pixel_ray(size_t x, size_t y, int seam, double d[3])
{
    double nx = (x + 0.5) / W * 2.0 - 1.0, ny = (y + 0.5) / H * 2.0 - 1.0;
    double vx = nx * FOV_TAN * W / H, vy = ny * FOV_TAN, l = sqrt(vx * vx + vy * vy + 1.0);
    d[0] = (seam ? -1.0 : vx) / l; /* looking down -X, right is -Z */
    d[1] = vy / l;
    d[2] = (seam ? -vx : -1.0) / l;
}

/* HDR's background pixels hold the environment's bilinear radiance in their view ray times the
 * intensity, in every mode, looking at the image's middle and at its wrap (no seam): within 1 %
 * (FP16 storage and llvmpipe's 8-bit filter weights). */
TL_TEST_FULL(environment_sky_is_the_image_every_mode)
{
    sphere_row *g = malloc(sizeof *g);
    float *env = environment_image(), *pos = NULL;
    sphere_row_build(g);
    ibl_ref_env e = {env, ENV_W, ENV_H};
    render_rows(g, (tl_renderer_options){.mode = TL_MODE_FAT}, NULL, NULL, &pos, NULL);
    for (int m = 0; m < 2 * MODES && pos; m++) {
        int seam = m >= MODES;
        g->s.camera.target[0] = seam ? -10.0f : 0.0f;
        g->s.camera.target[2] = seam ? (float)CAM_Z : 0.0f;
        float *hdr = NULL;
        tl_renderer_options o = {.mode = all_modes[m % MODES]};
        o.environment.intensity = 0.75f;
        render_rows(g, o, env, &hdr, NULL, NULL);
        double worst = 0.0;
        size_t n = 0;
        for (size_t i = 0; hdr && i < (size_t)W * H; i++) {
            if (!seam && pos[i * 4 + 3] != 0.0f) continue; /* looking down -X no sphere is in view */
            double d[3], c[3];
            pixel_ray(i % W, i / W, seam, d);
            ibl_ref_radiance(&e, d, c);
            n++;
            for (int k = 0; k < 3; k++) {
                double err = fabs(hdr[i * 4 + k] - 0.75 * c[k]) / (0.75 * c[k] + 1e-3);
                if (err > worst) worst = err;
            }
        }
        printf("sky, %s%s: %zu pixels, largest relative error %.4f %%\n", tl_render_mode_name(all_modes[m % MODES]),
               seam ? " (looking at the wrap)" : "", n, 100.0 * worst);
        TL_CHECK(hdr != NULL && n > (size_t)W * H / 3);
        TL_CHECK_LE(worst, 0.01);
        free(hdr);
    }
    free(pos);
    free(env);
    free(g);
}

/* No NaN, Inf or negative value reaches HDR with an environment, in every mode (and MSAA, a light
 * scale of 1/2); with TL_TEST_IMAGE_DIR set, the thin-lpp output is written there to look at. */
TL_TEST_FULL(environment_finite_every_mode)
{
    sphere_row *g = malloc(sizeof *g);
    float *env = environment_image();
    sphere_row_build(g);
    env[5] = NAN; /* bad pixels are taken as 0 */
    env[7] = -1.0f;
    env[9] = INFINITY;
    for (int m = 0; m < MODES + 2; m++) { /* every mode, then thin-lpp with MSAA and with a light scale */
        float *hdr = NULL;
        uint8_t *out = NULL;
        tl_renderer_options o = {.mode = all_modes[m % MODES], .msaa = m == MODES ? 4u : 0u,
                                 .light_scale = m == MODES + 1 ? 0.5f : 0.0f};
        render_rows(g, o, env, &hdr, NULL, &out);
        size_t bad = 0;
        for (size_t i = 0; hdr && i < (size_t)W * H * 4; i++) bad += !(hdr[i] >= 0.0f && hdr[i] <= 65504.0f);
        TL_CHECK(hdr && out);
        TL_CHECK_EQ_U(bad, 0);
#if TL_TEST_WITH_IO
        const char *dir = getenv("TL_TEST_IMAGE_DIR");
        if (dir && out && m == 0) {
            char path[512];
            snprintf(path, sizeof path, "%s/environment_spheres.png", dir);
            tl_image_desc d = {.width = W, .height = H, .channels = 4, .type = TL_PIXEL_U8, .bottom_up = 1};
            TL_CHECK(tl_image_write(path, &d, out) == TL_OK);
        }
#endif
        free(hdr);
        free(out);
    }
    free(env);
    free(g);
}

/* An unlit material takes no light, so none from the environment either: in every mode its pixels
 * are the same float (its albedo) with and without the environment. Forward once added the
 * environment's light to them. */
TL_TEST_FULL(environment_leaves_unlit_materials_alone_every_mode)
{
    sphere_row *g = malloc(sizeof *g);
    float *env = environment_image();
    sphere_row_build(g);
    for (int k = 0; k < SPHERES; k++) {
        g->mat[k].model = TL_MATERIAL_MODEL_UNLIT;
        for (int c = 0; c < 3; c++) g->mat[k].albedo[c] = 0.5f;
    }
    for (int m = 0; m < MODES; m++) {
        float *with = NULL, *without = NULL;
        render_rows(g, (tl_renderer_options){.mode = all_modes[m]}, env, &with, NULL, NULL);
        render_rows(g, (tl_renderer_options){.mode = all_modes[m]}, NULL, &without, NULL, NULL);
        TL_CHECK(with && without);
        size_t surface = 0, differ = 0;
        for (size_t i = 0; with && without && i < (size_t)W * H; i++) {
            if (!(without[i * 4] > 0.0f)) continue; /* the background: black without the environment */
            surface++;
            for (int c = 0; c < 3; c++) differ += with[i * 4 + c] != without[i * 4 + c];
        }
        printf("%s: %zu unlit pixels, %zu channels changed by the environment\n", tl_render_mode_name(all_modes[m]),
               surface, differ);
        TL_CHECK(surface > (size_t)W * H / 10);
        TL_CHECK_EQ_U(differ, 0);
        free(with);
        free(without);
    }
    free(env);
    free(g);
}

/* ---- image-based light against the Monte Carlo reference ---------------------------------------- */

typedef struct ibl_stats {
    double sum, max, sum_all, count, count_all;
} ibl_stats;

/* Which sphere a view-space point lies on (-1: none), and its world normal. */
static int sphere_of(const sphere_row *g, const float *p, double n[3])
{
    for (int k = 0; k < SPHERES; k++) {
        double d[3] = {p[0] - g->centre[k][0], p[1] - g->centre[k][1], p[2] + CAM_Z - g->centre[k][2]};
        double l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (fabs(l - 1.0) > 0.01) continue;
        for (int c = 0; c < 3; c++) n[c] = d[c] / l;
        return k;
    }
    return -1;
}

static double rel_l1(const float *a, const double b[3])
{
    return (fabs(a[0] - b[0]) + fabs(a[1] - b[1]) + fabs(a[2] - b[2])) / (b[0] + b[1] + b[2] + 1e-6);
}

/* One pixel's reference against `hdr`, into its sphere's statistics (every other pixel each way). */
static void ibl_compare_pixel(const sphere_row *g, const ibl_ref_env *e, const float *pos, size_t i, const float *hdr,
                              ibl_stats *st)
{
    double n[3], v[3], ref[3];
    int k = sphere_of(g, pos + i * 4, n);
    if (k < 0) return;
    double pl = sqrt(pos[i * 4] * pos[i * 4] + pos[i * 4 + 1] * pos[i * 4 + 1] + pos[i * 4 + 2] * pos[i * 4 + 2]);
    for (int c = 0; c < 3; c++) v[c] = -pos[i * 4 + c] / pl;
    double nv = n[0] * v[0] + n[1] * v[1] + n[2] * v[2], r = sphere_roughness(k);
    if (nv < 0.05) return; /* the silhouette: partly covered pixels */
    double alpha = tl_gloss_to_ggx_alpha((float)(1.0 - r));
    ibl_ref_shade(e, n, v, row_albedo[k / PER_ROW], row_f0[k / PER_ROW], alpha, 40, 1000 + i, ref);
    double err = rel_l1(hdr + i * 4, ref);
    st[k].sum_all += err;
    st[k].count_all += 1.0;
    if (nv < 0.25) return;
    st[k].sum += err;
    st[k].count += 1.0;
    if (err > st[k].max) st[k].max = err;
}

/* The largest relative difference of `a` from fat's HDR over the spheres' pixels. */
static double against_fat(const sphere_row *g, const float *pos, const float *fat, const float *a)
{
    double worst = 0.0, n[3];
    for (size_t i = 0; i < (size_t)W * H; i++) {
        if (sphere_of(g, pos + i * 4, n) < 0) continue;
        double f[3] = {fat[i * 4], fat[i * 4 + 1], fat[i * 4 + 2]}, d = rel_l1(a + i * 4, f);
        if (d > worst) worst = d;
    }
    return worst;
}

/* thin-lpp, thin-deferred, forward and visibility shade the environment's light as fat does (every
 * mode evaluates it with the material's own data: in a geometry pass, visibility in its resolve from
 * the rebuilt attributes): within 0.1 %. */
TL_TEST(environment_every_mode_matches_fat)
{
    sphere_row *g = malloc(sizeof *g);
    float *env = environment_image(), *pos = NULL, *fat = NULL;
    sphere_row_build(g);
    render_rows(g, (tl_renderer_options){.mode = TL_MODE_FAT}, env, &fat, &pos, NULL);
    TL_CHECK(pos && fat);
    for (int m = 0; m < MODES && pos && fat; m++) {
        if (all_modes[m] == TL_MODE_FAT) continue;
        float *hdr = NULL;
        render_rows(g, (tl_renderer_options){.mode = all_modes[m]}, env, &hdr, NULL, NULL);
        TL_CHECK(hdr != NULL);
        if (!hdr) continue;
        double d = against_fat(g, pos, fat, hdr);
        printf("%s against fat: largest relative difference %.4f %%\n", tl_render_mode_name(all_modes[m]), 100.0 * d);
        TL_CHECK_LE(d, 0.001);
        free(hdr);
    }
    free(pos);
    free(fat);
    free(env);
    free(g);
}

/* Bounds of the error against the Monte Carlo integral, per row (dielectric, gold): the mean over
 * n.v >= 0.25 and the largest. Measured (docs/lighting.md): means at most 3.0 % and 6.1 %, largest
 * 29.2 % and 68.0 % (gold: at n.v 0.25 to 0.5 with the sun 20 to 30 degrees off the mirror
 * direction, where the lobe prefiltered head-on is wider than the real one). */
static const double mc_mean_bound[2] = {0.04, 0.08}, mc_max_bound[2] = {0.35, 0.75};

/* Thin-lpp and fat against the Monte Carlo integral of the same image (n.v >= 0.25: mean and
 * largest relative error; all pixels but the silhouette: mean). The error is the split sum's
 * (docs/lighting.md): the lobe prefiltered with n = v = r around its dominant direction, the
 * prefiltered levels' roughness interpolated, the irradiance's 9 SH terms. */
TL_TEST_FULL(environment_spheres_against_monte_carlo)
{
    sphere_row *g = malloc(sizeof *g);
    float *env = environment_image(), *pos = NULL, *fat = NULL, *thin = NULL;
    sphere_row_build(g);
    ibl_ref_env e = {env, ENV_W, ENV_H};
    render_rows(g, (tl_renderer_options){.mode = TL_MODE_FAT}, env, &fat, &pos, NULL);
    render_rows(g, (tl_renderer_options){.mode = TL_MODE_THIN_LPP}, env, &thin, NULL, NULL);
    TL_CHECK(pos && fat && thin);
    ibl_stats st[2][SPHERES];
    memset(st, 0, sizeof st);
    for (size_t i = 0; pos && fat && thin && i < (size_t)W * H; i++) {
        size_t x = i % W, y = i / W;
        if ((x + y) % 2 || y % 2) continue;
        ibl_compare_pixel(g, &e, pos, i, fat, st[0]);
        ibl_compare_pixel(g, &e, pos, i, thin, st[1]);
    }
    printf("| material | roughness | fat mean | fat max | fat mean (all) | thin-lpp mean | thin-lpp max | thin-lpp mean (all) |\n");
    for (int k = 0; k < SPHERES; k++) {
        const ibl_stats *a = &st[0][k], *b = &st[1][k];
        int row = k / PER_ROW;
        printf("| %s | %.2f | %.2f %% | %.2f %% | %.2f %% | %.2f %% | %.2f %% | %.2f %% |\n", row ? "gold" : "dielectric",
               sphere_roughness(k), 100 * a->sum / a->count, 100 * a->max, 100 * a->sum_all / a->count_all,
               100 * b->sum / b->count, 100 * b->max, 100 * b->sum_all / b->count_all);
        TL_CHECK(a->count > 50 && b->count > 50);
        TL_CHECK_LE(a->sum / a->count, mc_mean_bound[row]);
        TL_CHECK_LE(b->sum / b->count, mc_mean_bound[row]);
        TL_CHECK_LE(a->max, mc_max_bound[row]);
        TL_CHECK_LE(b->max, mc_max_bound[row]);
    }
    free(pos);
    free(fat);
    free(thin);
    free(env);
    free(g);
}

/* ---- bad input and files ------------------------------------------------------------------------ */

/* Wrong shapes and NULL pixels are refused with a message naming the problem, and the environment
 * set before stays (the plan still has it). */
TL_TEST(environment_bad_input_refused)
{
    sphere_row *g = malloc(sizeof *g);
    float *env = environment_image();
    sphere_row_build(g);
    tl_renderer *r = make((tl_renderer_options){0});
    TL_CHECK(r && tl_renderer_set_scene(r, &g->s) == TL_OK);
    tl_environment_desc ok = {.rgb = env, .width = ENV_W, .height = ENV_H};
    TL_CHECK(r && tl_renderer_set_environment(r, &ok) == TL_OK);
    const tl_environment_desc bad[] = {{.rgb = NULL, .width = ENV_W, .height = ENV_H},
                                       {.rgb = env, .width = ENV_W, .height = ENV_W},
                                       {.rgb = env, .width = 2, .height = 1},
                                       {.rgb = env, .width = 0, .height = 0},
                                       {.rgb = env, .width = 32768, .height = 16384}};
    for (size_t i = 0; r && i < sizeof bad / sizeof bad[0]; i++) {
        TL_CHECK(tl_renderer_set_environment(r, &bad[i]) != TL_OK);
        TL_CHECK(strstr(tl_renderer_last_error(r), "environment") != NULL);
        tl_frame_plan p;
        tl_renderer_get_plan(r, &p);
        TL_CHECK(plan_has(&p, TL_PASS_SKY, NULL) && plan_has(&p, TL_PASS_COUNT, "TL_IBL"));
    }
    TL_CHECK(tl_renderer_set_environment(NULL, &ok) == TL_ERROR_INVALID_ARGUMENT);
    tl_renderer_options o = {0};
    o.environment.intensity = -1.0f;
    TL_CHECK(r && tl_renderer_set_options(r, &o) == TL_ERROR_INVALID_ARGUMENT);
    o.environment.intensity = 0.0f;
    o.environment.background[1] = NAN;
    TL_CHECK(r && tl_renderer_set_options(r, &o) == TL_ERROR_INVALID_ARGUMENT);
    tl_renderer_destroy(r);
    free(env);
    free(g);
}

/* ---- cube environments (tl_renderer_set_environment_cube) --------------------------------------- */

#define CUBE_N (ENV_H / 2) /* the faces' size whose equirectangular image is ENV_W x ENV_H */

/* The direction through texel (x, y) of face f, GL's cube-map convention (renderer.h). */
static void cube_direction(int f, uint32_t x, uint32_t y, double d[3])
{
    double sc = 2.0 * ((double)x + 0.5) / CUBE_N - 1.0, tc = 2.0 * ((double)y + 0.5) / CUBE_N - 1.0;
    const double dirs[6][3] = {{1, -tc, -sc}, {-1, -tc, sc}, {sc, 1, tc}, {sc, -1, -tc}, {sc, -tc, 1}, {-sc, -tc, -1}};
    double l = sqrt(dirs[f][0] * dirs[f][0] + dirs[f][1] * dirs[f][1] + dirs[f][2] * dirs[f][2]);
    for (int k = 0; k < 3; k++) d[k] = dirs[f][k] / l;
}

/* A cube made by sampling the equirectangular `env` (bilinear, as GL samples it) at each face texel. */
static float *cube_from_equirect(const float *env, tl_environment_cube_desc *c)
{
    float *faces = malloc((size_t)6 * CUBE_N * CUBE_N * 3 * sizeof *faces);
    ibl_ref_env e = {env, ENV_W, ENV_H};
    for (int f = 0; faces && f < 6; f++) {
        c->faces[f] = (tl_environment_face){.rgb = faces + (size_t)f * CUBE_N * CUBE_N * 3, .width = CUBE_N, .height = CUBE_N};
        for (uint32_t y = 0; y < CUBE_N; y++)
            for (uint32_t x = 0; x < CUBE_N; x++) {
                double d[3], rgb[3];
                cube_direction(f, x, y, d);
                ibl_ref_radiance(&e, d, rgb);
                for (int k = 0; k < 3; k++) faces[((size_t)f * CUBE_N * CUBE_N + y * CUBE_N + x) * 3 + k] = (float)rgb[k];
            }
    }
    return faces;
}

/* The 9-term irradiance kernel's L1 norm over the sphere, ∫ |sum_l A_l (2l+1) / (4 pi) P_l(t)| / pi:
 * how much a radiance difference bounded by 1 can move the diffuse term E / pi (midpoint rule). */
static double sh_kernel_l1(void)
{
    double sum = 0.0;
    const int n = 100000;
    for (int i = 0; i < n; i++) {
        double t = -1.0 + 2.0 * (i + 0.5) / n;
        double k = (0.25 + 0.5 * t + (5.0 / 32.0) * (3.0 * t * t - 1.0)) / 3.14159265358979323846;
        sum += fabs(k) * 2.0 / n;
    }
    return 2.0 * 3.14159265358979323846 * sum;
}

/* A cube sampled from the test sky renders as that sky given as equirectangular, within what the
 * resampling moves: the cube goes back to an equirectangular image E' (tl_environment_cube_to_equirect)
 * that differs from E by at most dmax per texel. The sky pass interpolates texels (a convex
 * combination): |sky' - sky| <= dmax. The bake is linear in the image: the prefiltered chain is made
 * of convex combinations (<= dmax) times F0 A + B <= 1; the diffuse E / pi moves by at most dmax
 * times the SH kernel's L1 norm K, times the albedo (0.5 at most here). Each HDR value is FP16 in
 * both frames: 2 x 2^-11 of the value more. */
TL_TEST(environment_cube_matches_equirect)
{
    sphere_row *g = malloc(sizeof *g);
    float *env = environment_image(), *back = malloc((size_t)ENV_W * ENV_H * 3 * sizeof(float)), *pos = NULL, *ref = NULL;
    tl_environment_cube_desc c;
    float *faces = env ? cube_from_equirect(env, &c) : NULL;
    TL_CHECK(g && env && back && faces);
    if (!g || !env || !back || !faces) return;
    sphere_row_build(g);
    tl_environment_cube_to_equirect(&c, back);
    double dmax = 0.0, k_sh = sh_kernel_l1();
    for (size_t i = 0; i < (size_t)ENV_W * ENV_H * 3; i++) dmax = fmax(dmax, fabs((double)back[i] - env[i]));
    render_rows(g, (tl_renderer_options){.mode = TL_MODE_FAT}, env, &ref, &pos, NULL);
    tl_renderer *r = make((tl_renderer_options){.mode = TL_MODE_FAT});
    float *hdr = NULL;
    int ok = r && tl_renderer_set_scene(r, &g->s) == TL_OK && tl_renderer_set_environment_cube(r, &c) == TL_OK &&
             tl_renderer_render(r, NULL, NULL) == TL_OK && tl_renderer_wait(r, NULL) == TL_OK &&
             (hdr = tl_test_read_target(r, TL_TARGET_HDR, (size_t)W * H)) != NULL;
    TL_CHECK(ok && ref && pos);
    size_t sky = 0, lit = 0, over = 0;
    double sky_max = 0.0, sphere_max = 0.0, sphere_sum = 0.0;
    for (size_t y = 0; ok && ref && pos && y < H; y++)
        for (size_t x = 0; x < W; x++) {
            size_t i = y * W + x;
            double n[3];
            int background = background_inside(pos, x, y), sphere = pos[i * 4 + 3] != 0.0f && sphere_of(g, pos + i * 4, n) >= 0;
            if (!background && !sphere) continue;
            double bound = background ? dmax : dmax * (1.0 + 0.5 * k_sh);
            for (int k = 0; k < 3; k++) {
                double d = fabs((double)hdr[i * 4 + k] - ref[i * 4 + k]), b = bound + 2.0 * ldexp(fabs(ref[i * 4 + k]), -11);
                over += d > b;
                if (background) sky_max = fmax(sky_max, d);
                else sphere_max = fmax(sphere_max, d), sphere_sum += d;
            }
            sky += background, lit += sphere;
        }
    printf("  cube %ux%u: round trip max |E' - E| %.4g (K %.4f); sky %zu px, max diff %.4g; spheres %zu px, max diff "
           "%.4g, mean %.4g; %zu values over the bound\n",
           CUBE_N, CUBE_N, dmax, k_sh, sky, sky_max, lit, sphere_max, lit ? sphere_sum / (3.0 * lit) : 0.0, over);
    TL_CHECK_LE(W * H / 4, sky);
    TL_CHECK_LE(W * H / 20, lit);
    TL_CHECK_EQ_U(over, 0);
    tl_renderer_destroy(r);
    free(hdr);
    free(ref);
    free(pos);
    free(faces);
    free(back);
    free(env);
    free(g);
}

/* A bad cube is refused with TL_ERROR_INVALID_ARGUMENT and one line naming the face and the problem. */
TL_TEST(environment_cube_bad_input_refused)
{
    float *env = environment_image();
    tl_environment_cube_desc good;
    float *faces = env ? cube_from_equirect(env, &good) : NULL;
    tl_renderer *r = make((tl_renderer_options){0});
    TL_CHECK(r && faces && tl_renderer_set_environment_cube(r, &good) == TL_OK);
    if (!r || !faces) return;
    float *nan_face = malloc((size_t)CUBE_N * CUBE_N * 3 * sizeof(float));
    memcpy(nan_face, good.faces[3].rgb, (size_t)CUBE_N * CUBE_N * 3 * sizeof(float));
    nan_face[(5 * CUBE_N + 7) * 3 + 1] = NAN;
    const char *want[5] = {"face -X is 64x32, not square", "face +Y is 32x32, face +X 64x64", "face -Y has a NaN at pixel (7, 5)",
                           "face +Z has no pixels", "face +X is 0x0, not square"};
    for (int k = 0; k < 5; k++) {
        tl_environment_cube_desc bad = good;
        if (k == 0) bad.faces[1].height = CUBE_N / 2;
        if (k == 1) bad.faces[2].width = bad.faces[2].height = CUBE_N / 2;
        if (k == 2) bad.faces[3].rgb = nan_face;
        if (k == 3) bad.faces[4].rgb = NULL;
        if (k == 4) bad.faces[0].width = bad.faces[0].height = 0;
        TL_CHECK(tl_renderer_set_environment_cube(r, &bad) == TL_ERROR_INVALID_ARGUMENT);
        printf("  %s\n", tl_renderer_last_error(r));
        TL_CHECK(strstr(tl_renderer_last_error(r), want[k]) != NULL);
    }
    TL_CHECK(tl_renderer_set_environment_cube(NULL, &good) == TL_ERROR_INVALID_ARGUMENT);
    tl_renderer_destroy(r);
    free(nan_face);
    free(faces);
    free(env);
}

#if TL_TEST_WITH_IO
/* An environment written as OpenEXR (full float) reads back as the same floats; a missing file is
 * TL_ERROR_IO and a file that is no image TL_ERROR_PARSE, never a crash. */
TL_TEST(environment_file_read_and_bad_files)
{
    float *env = environment_image();
    char path[64], junk[64];
    snprintf(path, sizeof path, "environment_%d.exr", (int)getpid());
    snprintf(junk, sizeof junk, "environment_%d.hdr", (int)getpid());
    tl_image_desc d = {.width = ENV_W, .height = ENV_H, .channels = 3, .type = TL_PIXEL_F32, .full_float = 1};
    TL_CHECK(tl_image_write(path, &d, env) == TL_OK);
    tl_float_image img;
    TL_CHECK(tl_image_read_rgb_float(path, NULL, &img) == TL_OK);
    TL_CHECK(img.width == ENV_W && img.height == ENV_H && img.rgb);
    TL_CHECK(img.rgb && memcmp(img.rgb, env, (size_t)ENV_W * ENV_H * 3 * sizeof(float)) == 0);
    tl_float_image_free(&img);
    TL_CHECK(img.rgb == NULL);
    FILE *f = fopen(junk, "wb");
    if (f) {
        fputs("#?RADIANCE\nnot really\n", f);
        fclose(f);
    }
    TL_CHECK(tl_image_read_rgb_float(junk, NULL, &img) == TL_ERROR_PARSE && img.rgb == NULL);
    TL_CHECK(tl_image_read_rgb_float("no/such/environment.hdr", NULL, &img) == TL_ERROR_IO);
    TL_CHECK(tl_image_read_rgb_float(NULL, NULL, &img) == TL_ERROR_INVALID_ARGUMENT);
    remove(path);
    remove(junk);
    free(env);
}
#endif

/* What setting an environment costs on the CPU (SH projection, the prefiltered chain, the BRDF
 * table, the upload), printed for docs/renderer.md; checks that each size is accepted and that
 * setting the same size again keeps the plan (no re-plan, no new programs). */
TL_TEST_FULL(environment_set_cost_printed)
{
    sphere_row *g = malloc(sizeof *g);
    sphere_row_build(g);
    tl_renderer *r = make((tl_renderer_options){0});
    TL_CHECK(r && tl_renderer_set_scene(r, &g->s) == TL_OK);
    static const uint32_t widths[] = {256, 1024};
    for (size_t i = 0; r && i < sizeof widths / sizeof widths[0]; i++) {
        uint32_t w = widths[i], h = w / 2;
        float *rgb = malloc((size_t)w * h * 3 * sizeof *rgb);
        TL_CHECK(rgb != NULL);
        if (!rgb) continue;
        ibl_ref_sky_image(w, h, rgb);
        tl_environment_desc e = {.rgb = rgb, .width = w, .height = h};
        struct timespec t0, t1;
        double ms[2];
        for (int k = 0; k < 2; k++) {
            tl_frame_plan before, after;
            tl_renderer_get_plan(r, &before);
            clock_gettime(CLOCK_MONOTONIC, &t0);
            TL_CHECK(tl_renderer_set_environment(r, &e) == TL_OK);
            clock_gettime(CLOCK_MONOTONIC, &t1);
            tl_renderer_get_plan(r, &after);
            if (i || k) TL_CHECK(memcmp(&before, &after, sizeof before) == 0);
            ms[k] = (t1.tv_sec - t0.tv_sec) * 1e3 + (t1.tv_nsec - t0.tv_nsec) * 1e-6;
        }
        printf("tl_renderer_set_environment %ux%u: %.1f ms%s, %.1f ms replacing it\n", (unsigned)w, (unsigned)h, ms[0],
               i ? "" : " (the first: with the BRDF table)", ms[1]);
        free(rgb);
    }
    tl_renderer_destroy(r);
    free(g);
}
