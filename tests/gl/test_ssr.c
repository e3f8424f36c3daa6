/* Screen-space reflections (docs/effects.md): off plans nothing and changes no byte; a mirror
 * floor (gloss 1, black) under an emissive quad reflects it exactly where the mirrored quad
 * projects (computed in double) with the weight of Schlick's Fresnel of the stored normal, every
 * pixel within one FP16 step, and nothing elsewhere;
 * rays that leave the screen or meet the background add nothing, and nothing is NaN or Inf on
 * 1x1 and 7x3 targets, with reversed D32F at 1:10^7 and an infinite far plane. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_fixture.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"
#include "tl_test.h"

enum { W = 320, H = 180 };

/* the modes that plan SSR (forward does not); visibility's G-buffer pass writes RT0 for it */
static const tl_render_mode modes[] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_VISIBILITY};
static const tl_depth_format depths[] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};

/* A floor y = 0 (object 0, black mirror) and an emissive quad x in [-2, 2], y in [1, 3] at
 * z = -8 facing +z (object 1). One point light far below the floor reaches nothing
 * (ssr_and_ssao_without_lights_in_every_mode drops it). */
typedef struct mirror_scene {
    tl_vertex v[8];
    uint32_t idx[12];
    tl_object obj[2];
    tl_material mat[2];
    tl_light light;
    tl_scene s;
} mirror_scene;

static const float EMISSIVE = 4.0f;

static void quad(mirror_scene *m, int q, const float o[3], const float du[3], const float dv[3])
{
    float n[3] = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
    float l = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int i = 0; i < 4; i++) {
        float a = (float)(i == 1 || i == 2), c = (float)(i >= 2);
        tl_vertex *x = &m->v[4 * q + i];
        memset(x, 0, sizeof *x);
        for (int k = 0; k < 3; k++) {
            x->position[k] = o[k] + a * du[k] + c * dv[k];
            x->normal[k] = n[k] / l;
        }
    }
    const uint32_t t[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 6; i++) m->idx[6 * q + i] = (uint32_t)(4 * q) + t[i];
    const float id[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    m->obj[q] = (tl_object){(uint32_t)(6 * q), 6, (uint32_t)q, {0}, {-100, -100, -100}, {100, 100, 100}, TL_PRIMITIVE_TRIANGLES};
    memcpy(m->obj[q].transform, id, sizeof id);
    m->mat[q] = (tl_material){.alpha = 1.0f};
}

static void mirror(mirror_scene *m, float cam_y)
{
    memset(m, 0, sizeof *m);
    quad(m, 0, (float[3]){-20, 0, 10}, (float[3]){40, 0, 0}, (float[3]){0, 0, -20});
    quad(m, 1, (float[3]){-2, 1, -8}, (float[3]){4, 0, 0}, (float[3]){0, 2, 0});
    m->mat[0].gloss = 1.0f;
    m->mat[0].specular[0] = m->mat[0].specular[1] = m->mat[0].specular[2] = 0.04f;
    m->mat[1].emissive[0] = m->mat[1].emissive[1] = m->mat[1].emissive[2] = EMISSIVE;
    m->s = (tl_scene){.vertices = m->v, .vertex_count = 8, .indices = m->idx, .index_count = 12, .objects = m->obj,
                      .object_count = 2, .materials = m->mat, .material_count = 2, .lights = &m->light,
                      .light_count = 1};
    m->light = (tl_light){.type = TL_LIGHT_POINT, .position = {0, -50, 0}, .color = {1, 1, 1}, .radius = 1};
    m->s.ambient[0] = m->s.ambient[1] = m->s.ambient[2] = -1.0f; /* none: the floor is black */
    m->s.camera = (tl_camera){{0, cam_y, 4}, {0, 0.5f, -8}, {0, 1, 0}, 1.0f, 0.1f, 0.0f};
}



/* The camera's basis and the pixel of a world point, as the renderer projects it (double). */
typedef struct basis {
    double eye[3], f[3], s[3], u[3], t, aspect;
} basis;

static basis camera_basis(const tl_camera *c, uint32_t w, uint32_t h)
{
    basis b;
    for (int k = 0; k < 3; k++) b.eye[k] = c->position[k], b.f[k] = (double)c->target[k] - c->position[k];
    double fl = sqrt(b.f[0] * b.f[0] + b.f[1] * b.f[1] + b.f[2] * b.f[2]);
    for (int k = 0; k < 3; k++) b.f[k] /= fl;
    b.s[0] = -b.f[2], b.s[1] = 0.0, b.s[2] = b.f[0]; /* f x (0, 1, 0) */
    double sl = sqrt(b.s[0] * b.s[0] + b.s[2] * b.s[2]);
    b.s[0] /= sl, b.s[2] /= sl;
    b.u[0] = b.s[1] * b.f[2] - b.s[2] * b.f[1], b.u[1] = b.s[2] * b.f[0] - b.s[0] * b.f[2];
    b.u[2] = b.s[0] * b.f[1] - b.s[1] * b.f[0];
    b.t = tan(0.5 * c->fov_y);
    b.aspect = (double)w / h;
    return b;
}

static void project(const basis *b, const double p[3], uint32_t w, uint32_t h, double *x, double *y)
{
    double d[3] = {p[0] - b->eye[0], p[1] - b->eye[1], p[2] - b->eye[2]};
    double vx = b->s[0] * d[0] + b->s[1] * d[1] + b->s[2] * d[2], vy = b->u[0] * d[0] + b->u[1] * d[1] + b->u[2] * d[2];
    double vz = b->f[0] * d[0] + b->f[1] * d[1] + b->f[2] * d[2];
    *x = (vx / (vz * b->t * b->aspect) * 0.5 + 0.5) * w;
    *y = (vy / (vz * b->t) * 0.5 + 0.5) * h;
}

/* Schlick's Fresnel (F0 = 0.04) of the floor at pixel (x, y) as the SSR pass weights it: with the
 * normal the G-buffer stored (n, view space, read back: RT0 decoded by the codec, or fat's FP16
 * normal) and the pixel's view ray (its centre, through the projection's ray parameters). Also
 * d F / d cos, for the tolerance. */
static double fresnel_at(const basis *b, const float *n, double x, double y, double *slope)
{
    double nx = (x + 0.5) / W * 2.0 - 1.0, ny = (y + 0.5) / H * 2.0 - 1.0;
    double v[3] = {nx * b->t * b->aspect, ny * b->t, -1.0}, vl = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    double nl = sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]);
    double c = -(n[0] * v[0] + n[1] * v[1] + n[2] * v[2]) / (vl * nl);
    *slope = 5.0 * 0.96 * pow(1.0 - c, 4.0);
    return 0.04 + 0.96 * pow(1.0 - c, 5.0);
}

/* The mirror image of the quad, (x, -y, z), projects to a trapezoid: its top edge (y = -1) at
 * row yt with half-width wt, its bottom edge (y = -2... -3) at row yb with half-width wb; pixels
 * 2 pixels inside its edges must hold E F, pixels 2 pixels outside nothing. */
static double half_width(const basis *b, double y, double yt, double wt, double yb, double wb)
{
    (void)b;
    return wb + (wt - wb) * (y - yb) / (yt - yb);
}

/* Inside the mirrored quad every pixel holds E F (gloss 1, no edge or distance fade there), F from
 * the stored normal: within one FP16 step of the SSR target's store (llvmpipe rounds toward zero;
 * E = 4 is exact in HDR), 16 float ulps for the shader's pow, and F's slope times 16 float roundings
 * of the cosine. The 2-pixel margins keep the trapezoid's rasterised edges (and the bisection's last
 * step onto them) out. */
static double ssr_tolerance(double f, double slope) { return f * (TL_HALF_REL_STEP + 16.0 * 0x1.0p-23) + slope * 16.0 * 0x1.0p-24; }

TL_TEST(ssr_mirror_floor_reflects_quad_at_mirrored_position)
{
    mirror_scene m;
    mirror(&m, 1.5f);
    basis b = camera_basis(&m.s.camera, W, H);
    double top[3] = {2, -1, -8}, bottom[3] = {2, -3, -8}, xt, yt, xb, yb;
    project(&b, top, W, H, &xt, &yt);
    project(&b, bottom, W, H, &xb, &yb);
    double wt = xt - W / 2.0, wb = xb - W / 2.0;
    printf("  mirrored quad: rows %.1f..%.1f, half-widths %.1f (top) %.1f (bottom) px\n", yb, yt, wt, wb);
    for (size_t md = 0; md < sizeof modes / sizeof modes[0]; md++)
        for (size_t z = 0; z < 2; z++) {
            tl_renderer_desc d = {.width = W, .height = H, .options.mode = modes[md], .options.depth_format = depths[z],
                                  .options.ssr = {.enabled = 1, .steps = 64, .max_distance = 20.0f, .thickness = 0.5f}};
            tl_renderer *r = tl_test_render_once(&m.s, d);
            float *t = r ? tl_test_read_target(r, TL_TARGET_SSR, (size_t)W * H) : NULL;
            float *nrm = r ? tl_test_read_target(r, modes[md] == TL_MODE_FAT ? TL_TARGET_FAT_NORMAL : TL_TARGET_RT0, (size_t)W * H) : NULL;
            TL_CHECK(t != NULL && nrm != NULL);
            size_t inside = 0, hit = 0, outside = 0, stray = 0;
            double worst = 0.0, worst_rel = 0.0;
            for (int y = 0; t && nrm && y < H; y++)
                for (int x = 0; x < W; x++) {
                    const float *p = t + 4 * ((size_t)y * W + x);
                    double cx = fabs(x + 0.5 - W / 2.0), cy = y + 0.5, hw = half_width(&b, cy, yt, wt, yb, wb);
                    int in = cx < hw - 2.0 && cy > yb + 2.0 && cy < yt - 2.0;
                    int out = cx > hw + 2.0 || cy < yb - 2.0 || cy > yt + 2.0;
                    if (in) {
                        double slope, f = fresnel_at(&b, nrm + 4 * ((size_t)y * W + x), x, y, &slope);
                        double want = EMISSIVE * f, e = fabs(p[0] - want) / (EMISSIVE * ssr_tolerance(f, slope));
                        if (e > 1.0 && hit == inside) printf("    at %d,%d: %.7g, want %.7g\n", x, y, (double)p[0], want);
                        inside++;
                        hit += e <= 1.0;
                        worst = fmax(worst, e);
                        worst_rel = fmax(worst_rel, fabs(p[0] - want) / want);
                    } else if (out) {
                        outside++;
                        int s1 = p[0] != 0.0f || p[1] != 0.0f || p[2] != 0.0f || p[3] != 0.0f;
                        if (s1 && stray < 3) printf("    stray at %d,%d: %g %g\n", x, y, p[0], p[3]);
                        stray += s1;
                    }
                }
            printf("  %s, %s: %zu of %zu pixels inside the mirrored quad hold E F (worst %.3f of the tolerance, "
                   "relative %.2g), %zu of %zu outside not zero\n",
                   tl_render_mode_name(modes[md]), z ? "d32f-reversed" : "d24", hit, inside, worst, worst_rel, stray,
                   outside);
            TL_CHECK(inside > 100);
            TL_CHECK_EQ_U(hit, inside);
            TL_CHECK(outside > 1000 && stray == 0);
            free(t);
            free(nrm);
            tl_renderer_destroy(r);
        }
}

/* SSR off (enabled 0, whatever its other fields): the plan has no ssr pass, target or program and
 * equals the plan without the field; the output does not differ by one byte. Forward mode plans
 * no SSR even when it is on. */
TL_TEST(ssr_off_plans_nothing_and_changes_no_byte)
{
    mirror_scene m;
    mirror(&m, 1.5f);
    tl_scene_feature_set f = {.point_lights = 2, .has_specular = 1};
    const tl_render_mode all[] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_FORWARD,
                                  TL_MODE_VISIBILITY};
    for (size_t md = 0; md < sizeof all / sizeof all[0]; md++) {
        tl_renderer_desc plain = {.width = 64, .height = 36, .options.mode = all[md]}, off = plain, on = plain;
        off.options.ssr = (tl_ssr_desc){.enabled = 0, .steps = 9, .thickness = 3.0f, .intensity = 2.0f};
        on.options.ssr.enabled = 1;
        tl_frame_plan a, b, c;
        TL_CHECK(tl_frame_plan_build(&plain, &f, &a) == TL_OK && tl_frame_plan_build(&off, &f, &b) == TL_OK &&
                 tl_frame_plan_build(&on, &f, &c) == TL_OK);
        TL_CHECK(memcmp(&a, &b, sizeof a) == 0);
        int has_a = 0, has_c = 0;
        for (size_t i = 0; i < a.pass_count; i++) has_a |= a.passes[i].pass == TL_PASS_SSR || a.passes[i].pass == TL_PASS_SSR_APPLY;
        for (size_t i = 0; i < c.pass_count; i++) has_c |= c.passes[i].pass == TL_PASS_SSR || c.passes[i].pass == TL_PASS_SSR_APPLY;
        TL_CHECK(!has_a && !(a.targets & TL_TARGET_BIT(TL_TARGET_SSR)));
        TL_CHECK(has_c == (all[md] != TL_MODE_FORWARD));
        tl_renderer *r0 = tl_test_render_once(&m.s, plain), *r1 = tl_test_render_once(&m.s, off);
        uint8_t o0[64 * 36 * 4], o1[64 * 36 * 4];
        size_t s0 = sizeof o0, s1 = sizeof o1;
        TL_CHECK(r0 && r1 && tl_renderer_read_output(r0, o0, &s0) == TL_OK && tl_renderer_read_output(r1, o1, &s1) == TL_OK);
        TL_CHECK(memcmp(o0, o1, sizeof o0) == 0);
        tl_renderer_destroy(r0);
        tl_renderer_destroy(r1);
    }
}

/* Rays that leave the screen or meet the background add nothing: seen from above, the quad's
 * mirror image is off the screen and the floor reflects only the sky; and on 1x1 and 7x3
 * targets, with reversed D32F at near 1e-3 / far 1e4 and an infinite far plane, the SSR target
 * and HDR are finite everywhere. */
TL_TEST(ssr_rays_off_screen_or_to_background_add_nothing_no_nan)
{
    mirror_scene m;
    mirror(&m, 1.5f);
    m.s.camera.target[1] = -6.0f; /* looking down: the emissive quad and its mirror image are off the screen */
    for (size_t md = 0; md < sizeof modes / sizeof modes[0]; md++) {
        tl_renderer *r = tl_test_render_once(&m.s, (tl_renderer_desc){.width = W, .height = H,
                                                                      .options.mode = modes[md],
                                                                      .options.ssr = {.enabled = 1}});
        float *t = r ? tl_test_read_target(r, TL_TARGET_SSR, (size_t)W * H) : NULL;
        TL_CHECK(t != NULL);
        size_t nonzero = 0;
        for (size_t i = 0; t && i < (size_t)W * H * 4; i++) nonzero += t[i] != 0.0f;
        printf("  %s, looking down: %zu non-zero SSR values\n", tl_render_mode_name(modes[md]), nonzero);
        TL_CHECK(nonzero == 0);
        free(t);
        tl_renderer_destroy(r);
    }
    mirror(&m, 1.5f);
    const uint32_t sizes[3][2] = {{1, 1}, {7, 3}, {160, 90}};
    const float fars[2] = {1e4f, 0.0f};
    for (size_t md = 0; md < sizeof modes / sizeof modes[0]; md++)
        for (int sz = 0; sz < 3; sz++)
            for (int fr = 0; fr < 2; fr++) {
                m.s.camera.near_z = 1e-3f;
                m.s.camera.far_z = fars[fr];
                tl_renderer_desc d = {.width = sizes[sz][0], .height = sizes[sz][1], .options.mode = modes[md],
                                      .options.depth_format = TL_DEPTH_FORMAT_D32F_REVERSED,
                                      .options.ssr = {.enabled = 1, .intensity = 1e4f}};
                tl_renderer *r = tl_test_render_once(&m.s, d);
                size_t n = (size_t)sizes[sz][0] * sizes[sz][1];
                float *t = r ? tl_test_read_target(r, TL_TARGET_SSR, n) : NULL, *h = r ? tl_test_read_target(r, TL_TARGET_HDR, n) : NULL;
                TL_CHECK(t && h);
                size_t bad = 0;
                for (size_t i = 0; t && h && i < n * 4; i++) bad += !isfinite(t[i]) || !isfinite(h[i]);
                TL_CHECK(bad == 0);
                free(t);
                free(h);
                tl_renderer_destroy(r);
            }
}

/* A scene without lights plans no light pass, so fat's G-buffer writes only the targets SSAO and
 * reflections read (position, normal) and not albedo: each output is declared on its own
 * (the program failed to compile when they were declared together). The quad's reflection is
 * still there: it comes from HDR (emissive), not from lights. */
TL_TEST(ssr_and_ssao_without_lights_in_every_mode)
{
    mirror_scene m;
    mirror(&m, 1.5f);
    m.s.light_count = 0;
    m.s.lights = NULL;
    for (size_t md = 0; md < sizeof modes / sizeof modes[0]; md++)
        for (int fx = 0; fx < 3; fx++) {
            tl_renderer_desc d = {.width = W, .height = H, .options.mode = modes[md]};
            if (fx != 1) d.options.ssr.enabled = 1;
            if (fx != 0) d.options.ssao.enabled = 1, d.options.ssao.method = TL_SSAO_HEMISPHERE;
            tl_renderer *r = tl_test_render_once(&m.s, d);
            TL_CHECK(r != NULL);
            float *t = r && d.options.ssr.enabled ? tl_test_read_target(r, TL_TARGET_SSR, (size_t)W * H) : NULL;
            size_t lit = 0;
            for (size_t i = 0; t && i < (size_t)W * H; i++) lit += t[4 * i] > 0.0f;
            printf("  %s, %s%s, no lights: %s, %zu reflecting pixels\n", tl_render_mode_name(modes[md]),
                   d.options.ssr.enabled ? "ssr " : "", d.options.ssao.enabled ? "ssao" : "", r ? "rendered" : "FAILED",
                   lit);
            if (d.options.ssr.enabled) TL_CHECK(lit > 100);
            free(t);
            tl_renderer_destroy(r);
        }
}
