/* Stability cases, FP16 limits: 10^4 lights on one pixel and intensities at the FP16 maximum
 * (stability.h). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "stability.h"

/* ---- FP16 accumulation ---------------------------------------------------------------------- */

/* A blend unit's add into an FP16 target: float add, then the store's rounding. */
static double blend_add(double dst, double src, int toward_zero)
{
    float s = (float)dst + (float)src;
    return toward_zero ? half_rz(s) : half_rn(s);
}

/* The exact G-buffer sample of the test wall (z = -5 facing the camera, normal +Z) at a pixel. */
static void wall_sample(const tl_projection *pr, uint32_t x, uint32_t y, uint32_t w, uint32_t h, double gloss,
                        gsample *g)
{
    float ndc[2];
    pixel_ndc(x, y, w, h, ndc);
    g->p[0] = 5.0 * ((double)ndc[0] + pr->m[8]) / pr->m[0];
    g->p[1] = 5.0 * ((double)ndc[1] + pr->m[9]) / pr->m[5];
    g->p[2] = -5.0;
    g->n[0] = g->n[1] = 0.0;
    g->n[2] = 1.0;
    g->gloss = gloss;
    memcpy(g->p_lo, g->p, sizeof g->p);
    memcpy(g->p_hi, g->p, sizeof g->p);
}

/* 10^4 point lights clustered 1.5-2.5 m in front of a wall, each covering the whole 16x16 frame
 * (the camera is inside every volume, so all are drawn by back faces in scene order).
 *
 * With light volumes:
 * thin-lpp: additive blending into the RGBA16F light buffer rounds after every light. The buffer
 * must equal the same sequence of FP16 additions of the model's terms, bracketed by each term's
 * float error and depth read step (light_terms): lower and upper sequences, under round to
 * nearest or under round toward zero (whichever the implementation's store uses; both are
 * monotonic, so the GPU's sum lies between the two sequences of its mode).
 * Every mode: the frame is finite, 10^4 lights give no less than their first 5000 (accumulation
 * is monotonic), no more than the exact sum, and the fraction of the exact (double) HDR lost is
 * reported: once a term falls below an FP16 step of the running sum it is lost, while forward
 * shading sums in float and rounds to FP16 once (asserted within 2^-10 + 10^4 x 2^-23).
 *
 * With tiles every mode sums each pixel's lights in float and rounds once, as forward shading
 * does: the HDR must be within the same bound of the exact sum (thin-deferred's albedo aside). The
 * tile's list (10^4 entries) does not fit the first frame's buffer, so this is also the overflow
 * path: every light is looped over, none lost. */
TL_TEST(stability_10k_lights_fp16_accumulation)
{
    enum { N = 10000, W = 16 };
    const double gloss = 0.3, albedo = 0.5, specular = 0.5;
    tl_light *lights = malloc(N * sizeof *lights);
    double *exact = malloc((size_t)W * W * 3 * sizeof *exact);
    TL_CHECK(lights && exact);
    if (!lights || !exact) return;
    tl_rng rng = {0x10A11u};
    for (size_t k = 0; k < N; k++) {
        float x = (float)(tl_rng_unit(&rng) - 0.5), y = (float)(tl_rng_unit(&rng) - 0.5);
        float z = (float)(-2.5 - tl_rng_unit(&rng));
        float c = (float)(0.5 + tl_rng_unit(&rng));
        lights[k] = point_light(x, y, z, 6.0f, 0.05f * c, 0.04f, 0.03f * (1.5f - c));
    }
    /* exact HDR of every pixel, in double, at the exact wall */
    tl_projection pr0;
    TL_CHECK(tl_projection_perspective(TL_DEPTH_FORMAT_D24, 1.0471976f, 1.0f, 0.1f, 100.0f, &pr0) == TL_OK);
    for (uint32_t y = 0; y < W; y++)
        for (uint32_t x = 0; x < W; x++) {
            gsample g;
            wall_sample(&pr0, x, y, W, W, gloss, &g);
            double sum[2][3] = {{0}};
            for (size_t k = 0; k < N; k++) {
                double t[2], e[2];
                model_terms(&lights[k], g.p, g.n, g.gloss, t, e);
                for (int ch = 0; ch < 3; ch++) {
                    sum[0][ch] += lights[k].color[ch] * t[0];
                    sum[1][ch] += lights[k].color[ch] * t[1];
                }
            }
            for (int ch = 0; ch < 3; ch++)
                exact[((size_t)y * W + x) * 3 + ch] = albedo * sum[0][ch] + specular * sum[1][ch];
        }
    for (int tiled = 0; tiled < 2; tiled++)
    for (size_t mi = 0; mi < MODE_COUNT; mi++) {
        tl_light_strategy strategy = tiled ? TL_LIGHT_STRATEGY_TILED : TL_LIGHT_STRATEGY_VOLUMES;
        mini_scene m;
        mini_init(&m, 1.0471976f, 0.1f, 100.0f);
        m.mat[0] = plain_material((float)albedo, (float)specular, (float)gloss);
        add_wall(&m, 5.0f, 0);
        m.s.lights = lights;
        char label[64];
        snprintf(label, sizeof label, "10^4 lights, %s, %s", tl_render_mode_name(modes[mi]), tl_light_strategy_name(strategy));
        run u, half_run;
        m.s.light_count = N / 2;
        tl_renderer_desc d = {.options.mode = modes[mi], .width = W, .height = W, .options.light_strategy = strategy};
        if (!run_scene(&half_run, d, &m.s, "5000 lights")) continue;
        m.s.light_count = N;
        if (!run_scene(&u, d, &m.s, label)) {
            run_free(&half_run);
            continue;
        }
        check_all_targets_finite(&u, label);
        if (tiled) {
            TL_CHECK_EQ_U(u.stats.light_pairs, (uint64_t)W * W * N); /* every light at every pixel */
            TL_CHECK_EQ_U(u.stats.light_list_entries, N);
            TL_CHECK_EQ_U(u.stats.tile_overflows, 1);
        } else if (modes[mi] == TL_MODE_FORWARD) {
            TL_CHECK_EQ_U(u.stats.forward_light_pairs, N);
        } else {
            TL_CHECK_EQ_U(u.stats.lights_drawn[TL_LIGHT_POINT], N);
        }
        /* thin-lpp with volumes: the light buffer against FP16 accumulation */
        size_t outside[2] = {0, 0}, px = 0;
        double max_bracket = 0.0;
        if (modes[mi] == TL_MODE_THIN_LPP && !tiled) {
            TL_CHECK(u.f.rt0 && u.f.diffuse && u.f.specular);
            for (uint32_t y = 0; u.f.rt0 && u.f.diffuse && u.f.specular && y < W; y++)
                for (uint32_t x = 0; x < W; x++) {
                    gsample g;
                    if (!gbuffer_sample(&u.f, &u.pr, u.clear, x, y, &g)) continue;
                    double lo[2][2][3] = {{{0}}}, hi[2][2][3] = {{{0}}}; /* [rounding][diffuse/specular][channel] */
                    for (size_t k = 0; k < N; k++) {
                        double t[2], e[2];
                        light_terms(&lights[k], &g, t, e);
                        for (int rz = 0; rz < 2; rz++)
                            for (int s = 0; s < 2; s++)
                                for (int ch = 0; ch < 3; ch++) {
                                    double col = lights[k].color[ch];
                                    lo[rz][s][ch] = blend_add(lo[rz][s][ch], fmax(0.0, col * (t[s] - e[s])), rz);
                                    hi[rz][s][ch] = blend_add(hi[rz][s][ch], col * (t[s] + e[s]), rz);
                                }
                    }
                    size_t i = ((size_t)y * W + x) * 4;
                    px++;
                    for (int rz = 0; rz < 2; rz++)
                        for (int s = 0; s < 2; s++)
                            for (int ch = 0; ch < 3; ch++) {
                                double gpu = (s ? u.f.specular : u.f.diffuse)[i + ch];
                                if (!(gpu >= lo[rz][s][ch] && gpu <= hi[rz][s][ch])) outside[rz]++;
                                double width = (hi[rz][s][ch] - lo[rz][s][ch]) / fmax(hi[rz][s][ch], 1e-30);
                                max_bracket = fmax(max_bracket, width);
                            }
                }
            printf("  %s: light buffer outside the FP16 accumulation bracket: %zu values (round to nearest), "
                   "%zu (toward zero), of %zu; widest bracket %.3g relative\n",
                   label, outside[0], outside[1], px * 6, max_bracket);
            TL_CHECK(px == (size_t)W * W);
            if (outside[0] && outside[1])
                fprintf(stderr, "  %s: the light buffer is no FP16 accumulation of the lights' terms\n", label);
            TL_CHECK(outside[0] == 0 || outside[1] == 0);
        }
        /* thin-lpp with tiles: the light buffer is the float sum of the same terms, rounded once */
        if (modes[mi] == TL_MODE_THIN_LPP && tiled) {
            const double once = 0x1.0p-11 + N * (double)FLT_EPSILON; /* one FP16 rounding, N float adds */
            for (uint32_t y = 0; u.f.rt0 && u.f.diffuse && u.f.specular && y < W; y++)
                for (uint32_t x = 0; x < W; x++) {
                    gsample g;
                    if (!gbuffer_sample(&u.f, &u.pr, u.clear, x, y, &g)) continue;
                    double lo[2][3] = {{0}}, hi[2][3] = {{0}};
                    for (size_t k = 0; k < N; k++) {
                        double t[2], e[2];
                        light_terms(&lights[k], &g, t, e);
                        for (int sp = 0; sp < 2; sp++)
                            for (int ch = 0; ch < 3; ch++) {
                                lo[sp][ch] += fmax(0.0, lights[k].color[ch] * (t[sp] - e[sp]));
                                hi[sp][ch] += lights[k].color[ch] * (t[sp] + e[sp]);
                            }
                    }
                    size_t i = ((size_t)y * W + x) * 4;
                    px++;
                    for (int sp = 0; sp < 2; sp++)
                        for (int ch = 0; ch < 3; ch++) {
                            double gpu = (sp ? u.f.specular : u.f.diffuse)[i + ch];
                            if (!(gpu >= lo[sp][ch] * (1.0 - once) && gpu <= hi[sp][ch] * (1.0 + once))) outside[0]++;
                        }
                }
            printf("  %s: light buffer outside the float sum of the terms, rounded once: %zu values of %zu\n", label,
                   outside[0], px * 6);
            TL_CHECK(px == (size_t)W * W);
            TL_CHECK_EQ_U(outside[0], 0);
        }
        /* every mode: HDR against the exact sum */
        size_t decreasing = 0, above = 0;
        double loss_sum = 0.0, loss_max = 0.0, worst_rel = 0.0;
        /* one FP16 step of the store, one float ULP (FLT_EPSILON = 2^-23 relative) per addition, and
         * 2^-12 more (a margin, not from a format) */
        const double fwd_tol = TL_HALF_REL_STEP + N * (double)FLT_EPSILON + 0x1.0p-12;
        /* thin-deferred reads albedo back from RT1's 8-bit sRGB YCbCr: up to ~2 steps (2.5 %) brighter;
         * thin-lpp with tiles keeps the whole sum, so the G-buffer's own error shows (its light
         * buffer is checked against the terms of the G-buffer above instead) */
        const double above_tol = modes[mi] == TL_MODE_THIN_DEFERRED ? 0.025
                                 : modes[mi] == TL_MODE_THIN_LPP && tiled ? 0.01
                                                                          : fwd_tol;
        for (size_t i = 0; i < (size_t)W * W; i++)
            for (int ch = 0; ch < 3; ch++) {
                double gpu = u.f.hdr[4 * i + ch], ex = exact[3 * i + ch];
                if (half_run.f.hdr[4 * i + ch] > gpu) decreasing++;
                if (gpu > ex * (1.0 + above_tol)) above++;
                double loss = 1.0 - gpu / ex;
                loss_sum += loss;
                loss_max = fmax(loss_max, loss);
                worst_rel = fmax(worst_rel, fabs(loss));
            }
        double loss_mean = loss_sum / (double)(W * W * 3);
        printf("  %s: HDR below the exact sum by %.1f %% on average, %.1f %% at most (|relative error| max %.3g); "
               "%zu values above it, %zu darker than with 5000 lights\n",
               label, 100.0 * loss_mean, 100.0 * loss_max, worst_rel, above, decreasing);
        TL_CHECK_EQ_U(decreasing, 0);
        TL_CHECK_EQ_U(above, 0);
        /* visibility sums its tiles' lights in float in its resolve as forward does (volumes asked:
         * tiles, by the mode) */
        if (modes[mi] == TL_MODE_FORWARD || modes[mi] == TL_MODE_VISIBILITY || (tiled && modes[mi] == TL_MODE_FAT))
            TL_CHECK_LE(worst_rel, fwd_tol);
        if (tiled && modes[mi] == TL_MODE_THIN_DEFERRED) TL_CHECK_LE(worst_rel, above_tol + fwd_tol);
        run_free(&u);
        run_free(&half_run);
    }
    free(lights);
    free(exact);
}

/* Light colours at and beyond the FP16 maximum (65504), alone and in pairs whose sum exceeds it,
 * and at 1 mm from the surface with radius 0.5, where the weight reaches the per-light clamp 4096
 * (1 / (0.01 radius)^2 = 40000 before it): docs/stability.md says no NaN or Inf may reach any
 * target. Every allocated target is read back; the pixel under the light (the centre of the 63x63
 * frame) must come out white, not black or NaN. llvmpipe stores FP16 rounding toward zero, which
 * saturates at 65504 where round-to-nearest hardware gives Inf (colour x weight > 65520, or a
 * blended sum beyond it): the cases that overflow only there are marked. */
TL_TEST(stability_intensity_fp16_max)
{
    static const struct { float color, dist, radius; int count; const char *what; } cases[] = {
        {65504.0f, 1.0f, 4.0f, 1, "one light 65504 at 1 m"},
        {65504.0f, 0.001f, 0.5f, 1, "one light 65504 at 1 mm, weight clamped to 4096 (Inf with RN)"},
        {40000.0f, 1.0f, 4.0f, 2, "two lights 40000 at 1 m, sum > 65504 (Inf with RN)"},
        {16.0f, 0.001f, 0.5f, 1, "one light 16 at 1 mm: 16 x 4096 = 65536 (Inf with RN)"},
        {1e30f, 1.0f, 4.0f, 1, "one light 1e30 (Inf with RN)"},
        {FLT_MAX, 0.5f, 4.0f, 1, "one light FLT_MAX"},
    };
    const uint32_t W = 63;
    for (size_t mi = 0; mi < MODE_COUNT; mi++)
        for (int lb = TL_LIGHT_BUFFER_EXACT;
             lb <= (modes[mi] == TL_MODE_THIN_LPP ? TL_LIGHT_BUFFER_COMPACT : TL_LIGHT_BUFFER_EXACT); lb++)
            for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ci++) {
                mini_scene m;
                mini_init(&m, 1.0471976f, 0.1f, 100.0f);
                m.mat[0] = plain_material(0.5f, 1.0f, 0.5f);
                add_wall(&m, 5.0f, 0);
                for (int k = 0; k < cases[ci].count; k++) {
                    float c = cases[ci].color;
                    m.light[k] = point_light(0.3f * (float)k, 0.0f, -5.0f + cases[ci].dist, cases[ci].radius, c, c, c);
                }
                m.s.light_count = (size_t)cases[ci].count;
                char label[160];
                snprintf(label, sizeof label, "%s, %s%s", cases[ci].what, tl_render_mode_name(modes[mi]),
                         modes[mi] != TL_MODE_THIN_LPP ? "" : lb == TL_LIGHT_BUFFER_EXACT ? " (exact)" : " (compact)");
                run u;
                if (!run_scene(&u, (tl_renderer_desc){.options.mode = modes[mi], .width = W, .height = W,
                                                      .options.light_buffer = (tl_light_buffer)lb}, &m.s, label))
                    continue;
                size_t bad = 0, n = count_nonfinite_all_targets(u.r, label, &bad);
                TL_CHECK(n >= 3); /* depth, HDR, output at least */
                if (bad) fprintf(stderr, "  RENDERER BUG (DESIGN 5: no NaN or Inf in any target): %s\n", label);
                TL_CHECK_EQ_U(bad, 0);
                uint8_t *img = malloc((size_t)W * W * 4);
                TL_CHECK(tl_renderer_read_output(u.r, img, &(size_t){(size_t)W * W * 4}) == TL_OK);
                size_t i = ((size_t)(W / 2) * W + W / 2) * 4;
                double hdr_max = 0.0, light_max = 0.0;
                for (size_t k = 0; k < (size_t)W * W * 4; k++)
                    if (k % 4 != 3) {
                        if (isfinite(u.f.hdr[k])) hdr_max = fmax(hdr_max, u.f.hdr[k]);
                        if (u.f.diffuse && isfinite(u.f.diffuse[k])) light_max = fmax(light_max, u.f.diffuse[k]);
                    }
                char lmax[32] = "none";
                if (u.f.diffuse) snprintf(lmax, sizeof lmax, "%.6g", light_max);
                printf("  %s: %zu non-finite values; light buffer max %s, HDR max %.6g; output under the light "
                       "(%u, %u, %u)\n", label, bad, lmax, hdr_max, img[i], img[i + 1], img[i + 2]);
                TL_CHECK(img[i] >= 250 && img[i + 1] >= 250 && img[i + 2] >= 250);
                TL_CHECK_LE(hdr_max, 65504.0);
                free(img);
                run_free(&u);
            }
}
