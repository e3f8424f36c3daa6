/* Screen-space effects (issue 14, docs/effects.md): an effect that is off plans nothing; SSAO on an
 * open plane (AO = 1 within the normals' quantisation), at a 90-degree inner corner (darker, and
 * exactly open beyond k_b + k_d from the wall; ssao_reference.c has every pixel against the CPU
 * estimator), finite on 1x1 and 7x3 targets
 * and with reversed D32F at 1:10^7; fog at a known distance against exp(-density d) in double and
 * at an infinite far plane; depth of field leaving its focus plane bit for bit; the vignette against
 * its formula in double; SSAO, fog, depth of field and the vignette off with their other fields set
 * change no byte of the image. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effects_scenes.h"
#include "render_fixture.h"
#include "thinlight/codec.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"
#include "tl_test.h"

#define BIT(t) TL_TARGET_BIT(t)

static const tl_render_mode modes[] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_FORWARD,
                                        TL_MODE_VISIBILITY};
static const tl_depth_format depths[] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};

/* ---- planning ------------------------------------------------------------------------------------ */

static int plan_has_effects(const tl_frame_plan *p)
{
    for (size_t i = 0; i < p->pass_count; i++) {
        tl_pass id = p->passes[i].pass;
        if (id == TL_PASS_SSAO || id == TL_PASS_SSAO_BLUR || id == TL_PASS_SSAO_APPLY || id == TL_PASS_FOG ||
            id == TL_PASS_DOF || id == TL_PASS_DOF_APPLY || id == TL_PASS_VIGNETTE)
            return 1;
    }
    for (size_t k = 0; k < p->program_count; k++)
        if (strstr(p->programs[k].defines, "SSAO") || strstr(p->programs[k].defines, "TL_AO_STORE")) return 1;
    return (p->targets & (BIT(TL_TARGET_AO_RAW) | BIT(TL_TARGET_AO) | BIT(TL_TARGET_DOF) | BIT(TL_TARGET_VIGNETTE))) != 0;
}

/* Effects off: no pass, target or define, and the other fields of an effect that is off change
 * nothing; each effect on adds its passes and exactly its targets' bytes. */
TL_TEST(effects_off_plan_nothing_on_plan_their_passes)
{
    tl_scene_feature_set f = {.point_lights = 2, .directional_lights = 1, .has_specular = 1};
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        tl_renderer_desc d = {.width = 64, .height = 32, .options.mode = modes[m]};
        tl_frame_plan base, noise, on;
        TL_CHECK(tl_frame_plan_build(&d, &f, &base) == TL_OK);
        TL_CHECK(!plan_has_effects(&base));
        tl_renderer_desc n = d;
        n.options.ssao = (tl_ssao_desc){.samples = 9, .radius = 3, .exponent = 2};
        n.options.fog = (tl_fog_desc){.density = 1, .noise = 0.5f};
        n.options.dof = (tl_dof_desc){.aperture = 0.5f, .samples = 9};
        n.options.vignette = (tl_vignette_desc){.strength = 1, .radius = 0.1f, .softness = 0.2f};
        TL_CHECK(tl_frame_plan_build(&n, &f, &noise) == TL_OK);
        TL_CHECK(memcmp(&base, &noise, sizeof base) == 0);
        tl_renderer_desc e = d;
        e.options.ssao.enabled = 1, e.options.ssao.method = TL_SSAO_DISC;
        TL_CHECK(tl_frame_plan_build(&e, &f, &on) == TL_OK);
        TL_CHECK((on.targets & BIT(TL_TARGET_AO)) && (on.targets & BIT(TL_TARGET_AO_RAW)));
        /* visibility stores no normal unless an effect reads one: its G-buffer pass then writes RT0 */
        const int vis = modes[m] == TL_MODE_VISIBILITY;
        TL_CHECK(!vis || (!(base.targets & BIT(TL_TARGET_RT0)) && (on.targets & BIT(TL_TARGET_RT0))));
        TL_CHECK_EQ_U(on.bytes_per_pixel, base.bytes_per_pixel + 4u + /* ao.raw and ao, R16F */
                                              (vis ? on.target_bytes_per_pixel[TL_TARGET_RT0] : 0u));
        e = d;
        e.options.fog.enabled = 1, e.options.fog.mode = TL_FOG_HEIGHT;
        TL_CHECK(tl_frame_plan_build(&e, &f, &on) == TL_OK);
        TL_CHECK_EQ_U(on.bytes_per_pixel, base.bytes_per_pixel);
        TL_CHECK(plan_has_effects(&on));
        e = d;
        e.options.dof.enabled = 1;
        TL_CHECK(tl_frame_plan_build(&e, &f, &on) == TL_OK);
        TL_CHECK_EQ_U(on.bytes_per_pixel, base.bytes_per_pixel + 8u);
        e = d;
        e.options.vignette.enabled = 1;
        TL_CHECK(tl_frame_plan_build(&e, &f, &on) == TL_OK);
        TL_CHECK_EQ_U(on.bytes_per_pixel, base.bytes_per_pixel + 2u); /* its factor, R16F */
        /* forward without a depth pre-pass has no depth to estimate from: no SSAO */
        e = d;
        e.options.ssao.enabled = 1, e.options.ssao.method = TL_SSAO_DISC;
        e.options.forward_depth_prepass = TL_SWITCH_OFF;
        TL_CHECK(tl_frame_plan_build(&e, &f, &on) == TL_OK);
        if (modes[m] == TL_MODE_FORWARD) TL_CHECK(!(on.targets & BIT(TL_TARGET_AO)));
    }
    tl_renderer_desc bad = {.width = 8, .height = 8, .options.ssao = {.enabled = 1, .method = TL_SSAO_DISC, .samples = 65}};
    tl_frame_plan p;
    TL_CHECK(tl_frame_plan_build(&bad, &f, &p) == TL_ERROR_INVALID_ARGUMENT);
    bad = (tl_renderer_desc){.width = 8, .height = 8, .options.fog = {.enabled = 1, .mode = TL_FOG_DISTANCE, .noise = 2.0f}};
    TL_CHECK(tl_frame_plan_build(&bad, &f, &p) == TL_ERROR_INVALID_ARGUMENT);
    bad = (tl_renderer_desc){.width = 8, .height = 8, .options.vignette = {.enabled = 1, .strength = 1.5f}};
    TL_CHECK(tl_frame_plan_build(&bad, &f, &p) == TL_ERROR_INVALID_ARGUMENT);
}

/* The image side of the same claim: SSAO, fog and depth of field off with every other field set
 * render the bytes of the plain frame (output and HDR), in every mode and light strategy, with a
 * light so that the frame is not flat. */
TL_TEST(effects_off_change_no_byte)
{
    quads q;
    corner_scene(&q);
    q.light[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {0.5f, 1.5f, -1}, .color = {3, 2, 1}, .radius = 4};
    q.s.lights = q.light;
    q.s.light_count = 1;
    const uint32_t w = 64, h = 48;
    const size_t n = (size_t)w * h;
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++)
        for (int st = TL_LIGHT_STRATEGY_VOLUMES; st <= TL_LIGHT_STRATEGY_TILED; st++) {
            tl_renderer_desc plain = {.width = w, .height = h, .options.mode = modes[m],
                                      .options.light_strategy = (tl_light_strategy)st};
            tl_renderer_desc off = plain;
            off.options.ssao = (tl_ssao_desc){.samples = 9, .radius = 3, .bias = 0.1f, .falloff = 2, .exponent = 2,
                                      .blur_radius = 3, .diffuse = 1};
            off.options.fog = (tl_fog_desc){.color = {1, 0.5f, 0.25f}, .density = 1, .height = 1, .height_falloff = 2,
                                    .noise = 0.5f, .noise_scale = 2, .noise_speed = 1};
            off.options.dof = (tl_dof_desc){.focus_distance = 3, .aperture = 0.5f, .max_radius = 0.5f, .samples = 9};
            off.options.vignette = (tl_vignette_desc){.strength = 1, .radius = 0.1f, .softness = 0.2f};
            tl_renderer *a = tl_test_render_once(&q.s, plain), *b = tl_test_render_once(&q.s, off);
            TL_CHECK(a && b);
            uint8_t *oa = malloc(n * 4), *ob = malloc(n * 4);
            float *ha = a ? tl_test_read_target(a, TL_TARGET_HDR, n) : NULL;
            float *hb = b ? tl_test_read_target(b, TL_TARGET_HDR, n) : NULL;
            int read = a && b && oa && ob && ha && hb && tl_renderer_read_output(a, oa, &(size_t){n * 4}) == TL_OK &&
                       tl_renderer_read_output(b, ob, &(size_t){n * 4}) == TL_OK;
            TL_CHECK(read);
            size_t differ = 0;
            for (size_t i = 0; read && i < n * 4; i++)
                differ += (oa[i] != ob[i]) + (memcmp(&ha[i], &hb[i], sizeof ha[i]) != 0);
            if (differ)
                printf("  %s, %s: %zu values differ\n", tl_render_mode_name(modes[m]),
                       tl_light_strategy_name((tl_light_strategy)st), differ);
            TL_CHECK_EQ_U(differ, 0);
            free(oa);
            free(ob);
            free(ha);
            free(hb);
            tl_renderer_destroy(a);
            tl_renderer_destroy(b);
        }
}

/* ---- SSAO ---------------------------------------------------------------------------------------- */

#define W 160
#define H 90

/* The open plane: every AO value of a floor pixel is 1 within OPEN_TOL. Thin and forward normals
 * are off by up to about 2e-3 rad (12-bit octahedral, or cross products of D24 positions), so
 * B <= 2e-3 and (1 - B)^3 >= 0.994; the hemisphere's sample points sit at least 0.031 radius
 * above the plane, far above the depth and normal error. */
#define OPEN_TOL 0.01

TL_TEST(ssao_open_plane_is_one)
{
    quads q;
    plane_scene(&q);
    for (int method = TL_SSAO_DISC; method <= TL_SSAO_HEMISPHERE; method++)
        for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++)
            for (size_t z = 0; z < 2; z++) {
                tl_renderer_desc d = {.width = W, .height = H, .options.mode = modes[m],
                                      .options.depth_format = depths[z]};
                d.options.ssao.enabled = 1, d.options.ssao.method = (tl_ssao_method)method;
                tl_renderer *r = tl_test_render_once(&q.s, d);
                TL_CHECK(r);
                if (!r) continue;
                float *ao = tl_test_read_target(r, TL_TARGET_AO, (size_t)W * H), *raw = tl_test_read_target(r, TL_TARGET_AO_RAW, (size_t)W * H);
                TL_CHECK(ao && raw);
                double lo = 1.0;
                for (size_t i = 0; ao && raw && i < (size_t)W * H; i++) {
                    lo = fmin(lo, fmin(ao[i * 4], raw[i * 4]));
                    TL_CHECK(isfinite(ao[i * 4]) && ao[i * 4] <= 1.0f);
                }
                printf("  open plane, %s, %s, depth %d: lowest AO %.5f\n", method == TL_SSAO_DISC ? "disc" : "hemisphere",
                       tl_render_mode_name(modes[m]), (int)depths[z], lo);
                TL_CHECK(lo >= 1.0 - OPEN_TOL);
                free(ao);
                free(raw);
                tl_renderer_destroy(r);
            }
}

/* The corner: floor pixels at the foot of the wall are darker than the open plane (by how much,
 * pixel by pixel, ssao_matches_cpu_estimator_every_mode checks against the CPU estimator); floor
 * pixels farther from the wall than k_b + k_d (plus the blur's reach) see only neighbours with
 * A = 0 and stay open. */
TL_TEST(ssao_inner_corner_darkens_bounded)
{
    quads q;
    corner_scene(&q);
    const float radius = 0.5f;
    for (int method = TL_SSAO_DISC; method <= TL_SSAO_HEMISPHERE; method++)
        for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
            tl_renderer_desc d = {.width = W, .height = H, .options.mode = modes[m]};
            d.options.ssao = (tl_ssao_desc){.enabled = 1, .method = (tl_ssao_method)method, .radius = radius, .falloff = radius};
            tl_renderer *r = tl_test_render_once(&q.s, d);
            TL_CHECK(r);
            if (!r) continue;
            float *ao = tl_test_read_target(r, TL_TARGET_AO, (size_t)W * H);
            TL_CHECK(ao);
            double corner = 1.0, open = 1.0;
            for (int k = 0; ao && k <= 40; k++) {
                double dist = 0.02 + 0.1 * k, p[3] = {0.0, 0.0, -2.0 + dist};
                int x, y;
                if (!project(&q.s.camera, W, H, p, &x, &y)) continue;
                double a = ao[((size_t)y * W + x) * 4];
                if (dist < 0.1) corner = fmin(corner, a);
                if (dist > 2.0 * radius + 0.3) open = fmin(open, a);
            }
            printf("  corner, %s, %s: AO at the foot of the wall %.4f, beyond k_b + k_d %.5f\n",
                   method == TL_SSAO_DISC ? "disc" : "hemisphere", tl_render_mode_name(modes[m]), corner, open);
            TL_CHECK(corner < 1.0 - OPEN_TOL);
            TL_CHECK(open >= 1.0 - OPEN_TOL);
            free(ao);
            tl_renderer_destroy(r);
        }
}

/* Every effect on at once, on tiny targets and with reversed D32F at near 1e-3, far 1e4 (1:10^7)
 * and an infinite far plane: AO in [0, 1] and HDR finite everywhere. */
/* tl_frame_stats counts by what a target is: G-buffer bytes are depth, RT0, RT1, the fat targets and
 * visibility's id, light-buffer bytes the light targets; the effects' targets (AO, DOF, bloom, SSR),
 * the light lists and visibility's material buckets are neither, in every mode, with every effect on. */
TL_TEST_FULL(effects_stats_count_effect_targets_apart)
{
    quads q;
    corner_scene(&q);
    q.light[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {0, 2, 1}, .direction = {0, -1, 0},
                            .color = {4, 4, 4}, .radius = 10.0f};
    q.s.lights = q.light;
    q.s.light_count = 1;
    const tl_target_set gbuffer = BIT(TL_TARGET_DEPTH) | BIT(TL_TARGET_RT0) | BIT(TL_TARGET_RT1) |
                                  BIT(TL_TARGET_FAT_POSITION) | BIT(TL_TARGET_FAT_NORMAL) | BIT(TL_TARGET_FAT_ALBEDO) |
                                  BIT(TL_TARGET_FAT_MATERIAL) | BIT(TL_TARGET_VIS_ID);
    const tl_target_set light = BIT(TL_TARGET_LIGHT_DIFFUSE) | BIT(TL_TARGET_LIGHT_SPECULAR) | BIT(TL_TARGET_LIGHT_FRESNEL);
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        tl_renderer_desc d = {.width = 64, .height = 48, .options.mode = modes[m],
                              .options.light_strategy = TL_LIGHT_STRATEGY_TILED,
                              .options.synchronous_stats = 1, .options.lighting = TL_LIGHTING_GGX};
        d.options.ssao.enabled = 1, d.options.ssao.method = TL_SSAO_DISC;
        d.options.dof.enabled = 1;
        d.options.bloom.enabled = 1;
        d.options.ssr.enabled = 1;
        tl_renderer *r = tl_test_render_once(&q.s, d);
        TL_CHECK(r != NULL);
        if (!r) continue;
        tl_frame_stats st;
        TL_CHECK(tl_renderer_render(r, NULL, &st) == TL_OK);
        size_t want_g = 0, want_l = 0, effects = 0;
        for (int t = 0; t < TL_TARGET_COUNT; t++) {
            if (gbuffer & BIT(t)) want_g += st.target_bytes[t];
            else if (light & BIT(t)) want_l += st.target_bytes[t];
            else if (t != TL_TARGET_HDR && t != TL_TARGET_LDR && t != TL_TARGET_OUTPUT) effects += st.target_bytes[t];
        }
        TL_CHECK(effects > 0); /* the frame has targets of neither kind: the test sees the difference */
        TL_CHECK_EQ_U(st.gbuffer_bytes, want_g);
        TL_CHECK_EQ_U(st.light_buffer_bytes, want_l);
        tl_renderer_destroy(r);
    }
}

TL_TEST_FULL(effects_finite_tiny_targets_and_extreme_depth)
{
    quads q;
    corner_scene(&q);
    const uint32_t sizes[3][2] = {{1, 1}, {7, 3}, {W, H}};
    const float fars[2] = {1e4f, 0.0f};
    for (size_t s = 0; s < 3; s++)
        for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++)
            for (size_t fi = 0; fi < 2; fi++) {
                q.s.camera.near_z = 1e-3f;
                q.s.camera.far_z = fars[fi];
                tl_renderer_desc d = {.width = sizes[s][0], .height = sizes[s][1], .options.mode = modes[m],
                                      .options.depth_format = TL_DEPTH_FORMAT_D32F_REVERSED};
                d.options.ssao.enabled = 1, d.options.ssao.method = fi ? TL_SSAO_HEMISPHERE : TL_SSAO_DISC;
                d.options.fog = (tl_fog_desc){.mode = fi ? TL_FOG_HEIGHT : TL_FOG_DISTANCE, .noise = 0.5f,
                                              .color = {1, 1, 1}};
                d.options.dof.enabled = 1;
                tl_renderer *r = tl_test_render_once(&q.s, d);
                TL_CHECK(r);
                if (!r) continue;
                size_t n = (size_t)d.width * d.height, bad = 0;
                float *ao = tl_test_read_target(r, TL_TARGET_AO, n), *hdr = tl_test_read_target(r, TL_TARGET_HDR, n);
                TL_CHECK(ao && hdr);
                for (size_t i = 0; ao && hdr && i < n; i++) {
                    bad += !(ao[i * 4] >= 0.0f && ao[i * 4] <= 1.0f);
                    for (int c = 0; c < 4; c++) bad += !isfinite(hdr[i * 4 + c]);
                }
                if (bad) printf("  %ux%u %s far %g: %zu bad values\n", d.width, d.height, tl_render_mode_name(modes[m]),
                                (double)fars[fi], bad);
                TL_CHECK(bad == 0);
                free(ao);
                free(hdr);
                tl_renderer_destroy(r);
            }
}

/* ---- fog ----------------------------------------------------------------------------------------- */

/* A wall at distance 20 facing the camera, ambient only: with distance fog each pixel's HDR is
 * c T + fog (1 - T), T = exp(-density d), d the pixel centre's distance computed in double; within
 * FP16 rounding of the stored values (two stores) and the depth format's error. The background of
 * an infinite far plane is the fog colour (T = 0), finite. */
TL_TEST(fog_known_depth_matches_formula_infinite_far_finite)
{
    quads q;
    const float dist = 20.0f, fog[3] = {0.5f, 0.25f, 2.0f}, density = 0.05f;
    wall_scene(&q, dist);
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++)
        for (size_t z = 0; z < 2; z++) {
            tl_renderer_desc d = {.width = W, .height = H, .options.mode = modes[m], .options.depth_format = depths[z]};
            tl_renderer *plain = tl_test_render_once(&q.s, d);
            d.options.fog = (tl_fog_desc){.enabled = 1, .mode = TL_FOG_DISTANCE, .density = density, .color = {fog[0], fog[1],
                                                                                                 fog[2]}};
            tl_renderer *fogged = tl_test_render_once(&q.s, d);
            TL_CHECK(plain && fogged);
            if (!plain || !fogged) continue;
            float *a = tl_test_read_target(plain, TL_TARGET_HDR, (size_t)W * H), *b = tl_test_read_target(fogged, TL_TARGET_HDR, (size_t)W * H);
            TL_CHECK(a && b);
            double worst = 0.0, t = tan(0.5), aspect = (double)W / H;
            for (int y = 0; a && b && y < H; y++)
                for (int x = 0; x < W; x++) {
                    double nx = (x + 0.5) / W * 2.0 - 1.0, ny = (y + 0.5) / H * 2.0 - 1.0;
                    double dd = dist * sqrt(1.0 + nx * nx * t * t * aspect * aspect + ny * ny * t * t);
                    double tr = exp(-density * dd);
                    for (int c = 0; c < 3; c++) {
                        size_t i = ((size_t)y * W + x) * 4 + c;
                        double want = a[i] * tr + fog[c] * (1.0 - tr);
                        double tol = 2.0 * want * TL_HALF_REL_STEP + 1e-5;
                        worst = fmax(worst, fabs(b[i] - want) / tol);
                    }
                }
            printf("  fog, %s, depth %d: worst error %.3f of the tolerance\n", tl_render_mode_name(modes[m]),
                   (int)depths[z], worst);
            TL_CHECK(worst <= 1.0);
            free(a);
            free(b);
            tl_renderer_destroy(plain);
            tl_renderer_destroy(fogged);
        }
    /* looking away from the wall: background at the infinite far plane */
    q.s.camera.target[2] = 10.0f;
    tl_renderer *r = tl_test_render_once(&q.s, (tl_renderer_desc){.width = 8, .height = 8,
                                                                  .options.fog = {.enabled = 1, .mode = TL_FOG_DISTANCE,
                                                                                  .color = {fog[0], fog[1], fog[2]}}});
    float *h = r ? tl_test_read_target(r, TL_TARGET_HDR, 64) : NULL;
    TL_CHECK(h);
    for (size_t i = 0; h && i < 64; i++)
        for (int c = 0; c < 3; c++) TL_CHECK(fabs(h[i * 4 + c] - fog[c]) <= fog[c] * TL_HALF_REL_STEP);
    free(h);
    tl_renderer_destroy(r);
}

/* ---- vignette ----------------------------------------------------------------------------------- */

/* HDR with the vignette is HDR without it times 1 - s smoothstep(r, r + w, d), d the pixel centre's
 * distance from the image's centre over the half-diagonal, evaluated in double: within the factor's
 * R16F rounding and the blend's FP16 rounding (half a step each), in every mode and depth format. */
TL_TEST(vignette_matches_formula_every_mode)
{
    quads q;
    wall_scene(&q, 5.0f);
    const tl_vignette_desc v = {.enabled = 1, .strength = 0.8f, .radius = 0.2f, .softness = 0.6f};
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++)
        for (size_t z = 0; z < 2; z++) {
            tl_renderer_desc d = {.width = W, .height = H, .options.mode = modes[m], .options.depth_format = depths[z]};
            tl_renderer *plain = tl_test_render_once(&q.s, d);
            d.options.vignette = v;
            tl_renderer *dark = tl_test_render_once(&q.s, d);
            float *a = plain ? tl_test_read_target(plain, TL_TARGET_HDR, (size_t)W * H) : NULL;
            float *b = dark ? tl_test_read_target(dark, TL_TARGET_HDR, (size_t)W * H) : NULL;
            TL_CHECK(a && b);
            double worst = 0.0;
            for (int y = 0; a && b && y < H; y++)
                for (int x = 0; x < W; x++) {
                    double u = (x + 0.5) / W * 2.0 - 1.0, w = (y + 0.5) / H * 2.0 - 1.0;
                    double dist = sqrt(u * u + w * w) * sqrt(0.5), t = (dist - v.radius) / v.softness;
                    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
                    double f = 1.0 - v.strength * t * t * (3.0 - 2.0 * t);
                    for (int c = 0; c < 3; c++) {
                        size_t i = ((size_t)y * W + x) * 4 + c;
                        double want = a[i] * f, tol = 2.0 * want * TL_HALF_REL_STEP + 1e-6;
                        worst = fmax(worst, fabs(b[i] - want) / tol);
                    }
                }
            printf("  vignette, %s, depth %d: worst error %.3f of the tolerance\n", tl_render_mode_name(modes[m]),
                   (int)depths[z], worst);
            TL_CHECK(worst <= 1.0);
            free(a);
            free(b);
            tl_renderer_destroy(plain);
            tl_renderer_destroy(dark);
        }
}

/* ---- depth of field ------------------------------------------------------------------------------ */

/* The wall at the focus distance (the camera's target): every pixel's CoC is below half a pixel,
 * no tap reaches another pixel, HDR is unchanged bit for bit. Focused nearer, the same wall is
 * blurred: some pixel changes. A light makes the wall's shading vary across the image. */
TL_TEST(dof_focus_plane_unchanged)
{
    quads q;
    wall_scene(&q, 10.0f);
    q.light[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {1, 1, -9}, .color = {4, 4, 4}, .radius = 3};
    q.s.lights = q.light;
    q.s.light_count = 1;
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        tl_renderer_desc d = {.width = W, .height = H, .options.mode = modes[m]};
        tl_renderer *plain = tl_test_render_once(&q.s, d);
        d.options.dof = (tl_dof_desc){.enabled = 1, .aperture = 0.02f};
        tl_renderer *focused = tl_test_render_once(&q.s, d);
        d.options.dof.focus_distance = 5.0f;
        tl_renderer *near = tl_test_render_once(&q.s, d);
        TL_CHECK(plain && focused && near);
        if (!plain || !focused || !near) continue;
        size_t n = (size_t)W * H;
        float *a = tl_test_read_target(plain, TL_TARGET_HDR, n), *b = tl_test_read_target(focused, TL_TARGET_HDR, n),
              *c = tl_test_read_target(near, TL_TARGET_HDR, n);
        TL_CHECK(a && b && c);
        size_t changed = 0, blurred = 0;
        for (size_t i = 0; a && b && c && i < n * 4; i++) {
            changed += memcmp(&a[i], &b[i], sizeof a[i]) != 0;
            blurred += fabsf(a[i] - c[i]) > 1e-3f;
        }
        printf("  dof, %s: %zu values changed in focus, %zu out of focus\n", tl_render_mode_name(modes[m]), changed, blurred);
        TL_CHECK(changed == 0);
        TL_CHECK(blurred > 0);
        free(a);
        free(b);
        free(c);
        tl_renderer_destroy(plain);
        tl_renderer_destroy(focused);
        tl_renderer_destroy(near);
    }
}

/* The dof target's alpha is the circle of confusion the gather used (tl_renderer_read_target):
 * a wall at distance 10 focused at 5 with aperture a has c = min(a |10 - 5| / 10, largest) x
 * height pixels at every pixel (the wall is a plane of constant view depth), within an FP16
 * rounding; focused on the wall, 0. */
TL_TEST(dof_target_alpha_is_the_circle_of_confusion)
{
    quads q;
    wall_scene(&q, 10.0f);
    const float aperture = 0.02f, largest[2] = {0.04f, 0.005f}, focus[3] = {5.0f, 10.0f, 20.0f};
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++)
        for (int f = 0; f < 3; f++)
            for (int l = 0; l < 2; l++) {
                tl_renderer_desc d = {.width = W, .height = H, .options.mode = modes[m],
                                      .options.dof = {.enabled = 1, .aperture = aperture, .max_radius = largest[l],
                                              .focus_distance = focus[f], .samples = 8}};
                tl_renderer *r = tl_test_render_once(&q.s, d);
                float *t = r ? tl_test_read_target(r, TL_TARGET_DOF, (size_t)W * H) : NULL;
                TL_CHECK(t != NULL);
                double want = fmin(aperture * fabs(10.0 - focus[f]) / 10.0, largest[l]) * H, worst = 0.0;
                for (size_t i = 0; t && i < (size_t)W * H; i++) worst = fmax(worst, fabs(t[4 * i + 3] - want));
                if (f == 0 && l == 0)
                    printf("  dof coc, %s: want %.4f px, worst error %.2g\n", tl_render_mode_name(modes[m]), want, worst);
                TL_CHECK(worst <= want * TL_HALF_REL_STEP + 1e-4);
                free(t);
                tl_renderer_destroy(r);
            }
}
