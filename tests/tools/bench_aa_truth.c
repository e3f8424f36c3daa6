/* The AA measurement's truth (examples/bench/bench_aa_truth.c): its CPU tone map is the renderer's
 * (fat with FXAA off, its HDR target tone-mapped on the CPU, equals the renderer's output within
 * one 8-bit step, at two exposures), and its resolve averages tone-mapped samples, not radiance. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "bench.h"
#include "render_fixture.h"
#include "tl_test.h"

/* The ACES fit and the sRGB encoding in double precision, written out from the shader's formulas. */
static double aces(double x)
{
    double y = (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
    return y < 0.0 ? 0.0 : y > 1.0 ? 1.0 : y;
}

static double srgb(double l) { return l <= 0.0031308 ? l * 12.92 : 1.055 * pow(l, 1.0 / 2.4) - 0.055; }

TL_TEST(bench_aa_tone_clamps_and_follows_aces)
{
    TL_CHECK(bench_aa_tone(0.0f, 1.0f) == 0.0f);
    TL_CHECK(bench_aa_tone(-5.0f, 1.0f) == 0.0f);
    TL_CHECK(bench_aa_tone(NAN, 1.0f) == 0.0f);
    TL_CHECK(bench_aa_tone(INFINITY, 1.0f) == 1.0f); /* clamped to 65504 first, then to 1 */
    for (double x = 0.001; x < 100.0; x *= 1.7) {
        TL_CHECK_LE(fabs(bench_aa_tone((float)x, 1.0f) - aces((float)x)), 1e-6);
        TL_CHECK_LE(fabs(bench_aa_tone((float)x, 0.5f) - aces((float)x * 0.5)), 1e-6);
    }
    for (int k = 0; k <= 255; k++) { /* the encoding lands each step's linear value on that step */
        double s = k / 255.0, l = s <= 0.04045 ? s / 12.92 : pow((s + 0.055) / 1.055, 2.4);
        TL_CHECK_EQ_U(bench_aa_srgb8((float)l), (unsigned)k);
    }
}

/* Two black samples and two over the tone curve's top: half the tone-mapped range, encoded
 * (srgb(0.5) = 0.7354, step 188); averaging radiance first would saturate (255). */
TL_TEST(bench_aa_resolve_averages_tone_mapped_samples)
{
    const float big = 1000.0f;
    float hdr[2 * 2 * 4] = {0, 0, 0, 1, big, big, big, 1, big, big, big, 1, 0, 0, 0, 1};
    uint8_t rgb[3];
    bench_aa_resolve(hdr, 1, 1, 2, 1.0f, rgb);
    unsigned want = (unsigned)lround(255.0 * srgb(0.5 * aces(big)));
    TL_CHECK_EQ_U(want, 188u);
    for (int c = 0; c < 3; c++) TL_CHECK_EQ_U(rgb[c], want);
    /* scale 1 is the plain tone map, pixel by pixel */
    uint8_t one[4 * 3];
    bench_aa_resolve(hdr, 2, 2, 1, 1.0f, one);
    TL_CHECK_EQ_U(one[0], 0u);
    TL_CHECK_EQ_U(one[3], 255u);
}

TL_TEST(bench_aa_reduce_mask_marks_the_pixel_of_a_sample)
{
    uint8_t fine[8 * 4] = {0}, mask[2 * 1];
    fine[3 * 8 + 5] = 1; /* row 3, column 5: pixel (1, 0) at scale 4 */
    TL_CHECK_EQ_U(bench_aa_reduce_mask(fine, 2, 1, 4, mask), 1u);
    TL_CHECK_EQ_U(mask[0], 0u);
    TL_CHECK_EQ_U(mask[1], 1u);
}

/* fat with FXAA off: the output is the tone pass's; the CPU tone map of its HDR target must give it
 * within one step (rounding of the 8-bit conversion), over a frame with dark and bright pixels. */
TL_TEST(bench_aa_cpu_tone_map_matches_renderer_fat_fxaa_off)
{
    const uint32_t w = 160, h = 90;
    const size_t n = (size_t)w * h;
    tl_scene *scene = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 16, .detail = 2}, &scene) == TL_OK);
    for (int e = 0; scene && e < 2; e++) {
        float exposure = e ? 2.5f : 1.0f;
        tl_renderer *r = tl_test_render_once(scene, (tl_renderer_desc){.width = w, .height = h,
                                                                       .options.mode = TL_MODE_FAT,
                                                                       .options.fxaa = TL_FXAA_OFF,
                                                                       .options.exposure = exposure});
        TL_CHECK(r != NULL);
        float *hdr = r ? tl_test_read_target(r, TL_TARGET_HDR, n) : NULL;
        uint8_t *out = malloc(n * 4), *cpu = malloc(n * 3);
        TL_CHECK(hdr && out && cpu && tl_renderer_read_output(r, out, &(size_t){n * 4}) == TL_OK);
        if (hdr && out && cpu) {
            bench_aa_resolve(hdr, w, h, 1, exposure, cpu);
            int worst = 0, lo = 255, hi = 0;
            for (size_t i = 0; i < n; i++)
                for (int c = 0; c < 3; c++) {
                    int d = abs((int)cpu[3 * i + c] - (int)out[4 * i + c]);
                    worst = d > worst ? d : worst;
                    lo = out[4 * i + c] < lo ? out[4 * i + c] : lo;
                    hi = out[4 * i + c] > hi ? out[4 * i + c] : hi;
                }
            TL_CHECK_LE(worst, 1);
            TL_CHECK_LE(lo, 16); /* the frame spans the range: the comparison means something */
            TL_CHECK_LE(200, hi);
        }
        free(hdr);
        free(out);
        free(cpu);
        tl_renderer_destroy(r);
    }
    tl_scene_destroy(scene);
}
