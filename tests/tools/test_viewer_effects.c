/* thinlight-viewer with the screen-space effects (docs/effects.md, docs/viewer.md), under Xvfb:
 * the final view with each effect is thinlight-render's image with the same flag, and differs
 * from the image without it; the effects' views (ao-raw, ao, dof-coc, ssr, bloom) show something
 * in every mode, differ where they must, the crypt's AO is below 1 in its corners and its bloom
 * glows where HDR is brightest; the views that map
 * a scalar to colours carry their legend in the screenshot, with the colour bar's pixels where the
 * viewer's geometry puts them; every effect flag's bad value exits 2 with one line and no file. */
#include "viewer_harness.h"

#include <math.h>

enum { W = 320, H = 180, BIG_W = 640, BIG_H = 360 };

static const char *const modes[4] = {"thin-lpp", "thin-deferred", "fat", "forward"};
/* The effects' views: their place in the grid (after the 14 views without effects). */
enum { V_AO_RAW = 14, V_AO = 15, V_DOF_COC = 16, V_SSR = 17, V_BLOOM = 18, V_DEPTH = 6, V_FINAL = 0, NV = 19 };

/* Final view = thinlight-render with the same effect flags, bit for bit; and not the image
 * without the effect. */
TL_TEST_FULL(viewer_final_view_with_each_effect_equals_thinlight_render)
{
    static const char *const effects[6] = {"", "--ssao", "--fog --fog-color 0.3,0.3,0.35 --fog-density 0.08",
                                           "--dof --dof-aperture 0.02", "--ssr", "--bloom"};
    image plain = {0, 0, NULL};
    for (int e = 0; e < 6; e++) {
        char args[256], png[64], ref[64], cmd[2048];
        snprintf(args, sizeof args, "--size %ux%u --mode thin-lpp %s", W, H, effects[e]);
        snprintf(png, sizeof png, "fx_final_%d.png", e);
        snprintf(ref, sizeof ref, "fx_render_%d.png", e);
        TL_CHECK(viewer(args, png) == 0);
        snprintf(cmd, sizeof cmd, "'%s' default --size %ux%u --mode thin-lpp --light-strategy tiled %s -o '%s/%s' 2>/dev/null",
                 TL_RENDER, W, H, effects[e], TL_WORK, ref);
        TL_CHECK(run(cmd) == 0);
        image a = load(png), b = load(ref);
        tl_image_error same = compare(&a, &b);
        TL_CHECK(a.px && colours(&a) > 32 && same.max_abs == 0.0);
        if (e == 0) { plain = a; release(&b); continue; }
        tl_image_error diff = compare(&a, &plain);
        printf("'%s': vs thinlight-render max %.0f; vs no effect mean %.3f levels\n", effects[e], same.max_abs, diff.mean_abs);
        TL_CHECK(diff.mean_abs > 0.05);
        release(&a);
        release(&b);
    }
    release(&plain);
}

/* In every mode with every effect on: the effects' thumbnails show an image (not the placeholder,
 * not one colour; forward plans no reflections: their placeholder); ao-raw differs from ao (the
 * blur), ao from the final view, the CoC from the depth view, the reflections from the final view. */
TL_TEST_FULL(viewer_effect_views_each_mode)
{
    for (int m = 0; m < 4; m++) {
        char args[256], png[64];
        snprintf(args, sizeof args, "--size %ux%u --mode %s --grid --ssao --fog --dof --ssr --bloom", BIG_W, BIG_H, modes[m]);
        snprintf(png, sizeof png, "fx_grid_%s.png", modes[m]);
        TL_CHECK(viewer(args, png) == 0);
        image g = load(png);
        TL_CHECK(g.px && g.w == BIG_W);
        if (!g.px) continue;
        image c[NV];
        for (int v = 0; v < NV; v++) c[v] = cell(&g, v);
        for (int v = V_AO_RAW; v <= V_BLOOM; v++) {
            printf("%s view %d: %zu colours%s\n", modes[m], v, colours(&c[v]), is_placeholder(&c[v]) ? " (placeholder)" : "");
            if (v == V_SSR && m == 3) TL_CHECK(is_placeholder(&c[v]));
            else TL_CHECK(!is_placeholder(&c[v]) && colours(&c[v]) > 4);
        }
        static const int differ[][2] = {{V_AO_RAW, V_AO}, {V_AO, V_FINAL}, {V_DOF_COC, V_DEPTH}, {V_DOF_COC, V_FINAL},
                                        {V_SSR, V_FINAL}, {V_BLOOM, V_FINAL}};
        for (size_t k = 0; k < sizeof differ / sizeof differ[0]; k++) {
            if (differ[k][0] == V_SSR && m == 3) continue;
            tl_image_error e = compare(&c[differ[k][0]], &c[differ[k][1]]);
            printf("%s: view %d vs %d mean %.2f levels\n", modes[m], differ[k][0], differ[k][1], e.mean_abs);
            TL_CHECK(e.mean_abs > 0.5);
        }
        for (int v = 0; v < NV; v++) free(c[v].px);
        release(&g);
    }
}

/* The crypt's AO (after the blur): open floor and walls at 1, the inner corners (floor against
 * walls and columns) below it. The legend's rows are left out. */
TL_TEST(viewer_ao_view_crypt_below_one_in_corners)
{
    char args[256];
    snprintf(args, sizeof args, "--size %ux%u --view ao --ssao", BIG_W, BIG_H);
    TL_CHECK(viewer(args, "fx_ao.png") == 0);
    image a = load("fx_ao.png");
    TL_CHECK(a.px != NULL);
    size_t open = 0, dark = 0, n = 0, grey = 1;
    for (uint32_t y = 0; a.px && y < a.h - 48; y++)
        for (uint32_t x = 0; x < a.w; x++) {
            const uint8_t *p = at(&a, x, y);
            grey &= p[0] == p[1] && p[1] == p[2];
            open += p[0] == 255;
            dark += p[0] < 230; /* AO below 0.9 */
            n++;
        }
    printf("ao: %.1f%% at 1, %.1f%% below 0.9\n", 100.0 * open / n, 100.0 * dark / n);
    TL_CHECK(grey);
    TL_CHECK(open > n / 5);     /* most of an open room is unoccluded */
    TL_CHECK(dark > n / 200);   /* its corners are not */
    TL_CHECK(dark < n / 2);
    release(&a);
}

/* The bloom view: where the HDR view clips (radiance times exposure above 1 in some channel, which
 * is what the default threshold of 1 lets into the chain) it is on average brighter than elsewhere,
 * more so than a blur that ignores brightness could be; with a threshold no pixel reaches and a
 * hard knee the chain holds exactly 0 and the view is black. */
TL_TEST(viewer_bloom_view_glows_where_hdr_is_brightest)
{
    image h = shot(BIG_W, BIG_H, "--view hdr --bloom", "fx_bloom_hdr.png"),
          b = shot(BIG_W, BIG_H, "--view bloom --bloom", "fx_bloom.png"),
          z = shot(BIG_W, BIG_H, "--view bloom --bloom --bloom-threshold 1e30 --bloom-knee 0", "fx_bloom_none.png");
    TL_CHECK(h.px && b.px && z.px && h.w == b.w && h.h == b.h);
    if (h.px && b.px && z.px) {
        double lit[2] = {0, 0}, n[2] = {0, 0}, top = 0;
        size_t nonzero = 0;
        for (uint32_t y = 0; y < h.h; y++)
            for (uint32_t x = 0; x < h.w; x++) {
                const uint8_t *p = at(&h, x, y), *q = at(&b, x, y), *o = at(&z, x, y);
                int clip = p[0] == 255 || p[1] == 255 || p[2] == 255;
                double v = (q[0] + q[1] + q[2]) / 3.0;
                lit[clip] += v;
                n[clip] += 1;
                top = v > top ? v : top;
                nonzero += o[0] || o[1] || o[2];
            }
        double in = n[1] ? lit[1] / n[1] : 0, out = n[0] ? lit[0] / n[0] : 0;
        printf("bloom view: %.0f clipped HDR pixels, mean %.1f levels there, %.1f elsewhere, brightest %.0f; "
               "unreachable threshold: %zu non-black pixels\n", n[1], in, out, top, nonzero);
        TL_CHECK(n[1] > 0 && n[0] > 0);
        TL_CHECK(in > 2.0 * out);
        TL_CHECK(top > 32.0);
        TL_CHECK(nonzero == 0);
    }
    release(&h);
    release(&b);
    release(&z);
}

/* The viewer's heat scale (views.c: black, blue, green, yellow, red, white). */
static void heat(double t, double rgb[3])
{
    static const double stops[6][3] = {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}, {1, 1, 1}};
    double f = t * 5.0;
    int i = f >= 5.0 ? 4 : (int)f;
    for (int c = 0; c < 3; c++) rgb[c] = 255.0 * (stops[i][c] * (1.0 - (f - i)) + stops[i + 1][c] * (f - i));
}

static void depth_grey(double t, double rgb[3]) { rgb[0] = rgb[1] = rgb[2] = 255.0 * (1.0 - 0.9 * t); }

/* The colour bar where legend.h puts it in a w x h image (scale 2 from 960 across): 128 x scale
 * columns from x = 11 scale, 8 x scale rows from y = h - 28 scale (rows from the top); column i
 * is colour(i / (columns - 1)). Returns the worst channel error over the bar, in levels. */
static double bar_error(const image *im, void (*colour)(double, double[3]))
{
    uint32_t s = im->w >= 960 ? 2 : 1, bw = 128 * s, bx = 11 * s, by = im->h - 28 * s;
    double worst = 0;
    for (uint32_t y = by; y < by + 8 * s; y++)
        for (uint32_t i = 0; i < bw; i++) {
            double want[3];
            colour((double)i / (bw - 1), want);
            const uint8_t *p = at(im, bx + i, y);
            for (int c = 0; c < 3; c++) worst = fmax(worst, fabs(p[c] - want[c]));
        }
    return worst;
}

/* Some pixel of the label row under the bar is the font's white. */
static int has_labels(const image *im)
{
    uint32_t s = im->w >= 960 ? 2 : 1;
    size_t white = 0;
    for (uint32_t y = im->h - 18 * s; y < im->h - 11 * s; y++)
        for (uint32_t x = 11 * s; x < 139 * s; x++) white += memcmp(at(im, x, y), "\377\377\377", 3) == 0;
    return white > 10;
}

TL_TEST(viewer_screenshot_carries_the_legend)
{
    static const struct {
        const char *args;
        void (*colour)(double, double[3]);
        uint32_t w, h;
    } cases[] = {
        {"--view diff-fat", heat, BIG_W, BIG_H},  {"--view diff-fat", heat, 1280, 720},
        {"--view tile-lights", heat, BIG_W, BIG_H}, {"--view depth", depth_grey, BIG_W, BIG_H},
        {"--view dof-coc --dof", heat, BIG_W, BIG_H},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char args[256], png[64];
        snprintf(args, sizeof args, "--size %ux%u %s", cases[k].w, cases[k].h, cases[k].args);
        snprintf(png, sizeof png, "fx_legend_%zu.png", k);
        TL_CHECK(viewer(args, png) == 0);
        image im = load(png);
        TL_CHECK(im.px && im.w == cases[k].w);
        if (!im.px) continue;
        double e = bar_error(&im, cases[k].colour);
        printf("%s at %ux%u: colour bar worst error %.0f levels, labels %s\n", cases[k].args, im.w, im.h, e,
               has_labels(&im) ? "yes" : "no");
        TL_CHECK(e <= 1.0);
        TL_CHECK(has_labels(&im));
        release(&im);
    }
}

/* Bad values of the effect flags: exit 2, one line on stderr, no screenshot (the arguments fail
 * before any window, so no display is needed). */
TL_TEST_FULL(viewer_effect_flags_bad_values_exit_2_one_line)
{
    static const char *const bad[] = {
        "--ssao-samples 0",   "--ssao-samples 65", "--ssao-radius nan",    "--ssao-radius 0",  "--ssao-bias -1",
        "--ssao-falloff 0",   "--ssao-exponent x", "--ssao-blur 9",        "--ssao-method ring", "--fog-mode up",
        "--fog-density -1",   "--fog-color 1,2",   "--fog-color 1,2,-3",   "--fog-falloff 0",  "--fog-noise 2",
        "--fog-height inf",   "--dof-focus 0",     "--dof-aperture 2",     "--dof-max 0",      "--dof-samples 7",
        "--dof-samples 129",  "--ssao-radius",     "--ssr-steps 3",        "--ssr-steps 257",  "--ssr-distance 0",
        "--ssr-thickness -1", "--ssr-min-gloss 1", "--ssr-intensity nan",
    };
    char err[1024], shot[1024], cmd[4096], line[512];
    snprintf(err, sizeof err, "%s/fx_bad.txt", TL_WORK);
    snprintf(shot, sizeof shot, "%s/fx_bad.png", TL_WORK);
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        remove(shot);
        snprintf(cmd, sizeof cmd, VW_ENV "'%s' --screenshot '%s' %s 2>'%s'", TL_VIEWER, shot, bad[k], err);
        int status = run(cmd);
        FILE *f = fopen(err, "r"), *png = fopen(shot, "rb");
        int lines = 0;
        line[0] = 0;
        while (f && fgets(line, sizeof line, f)) lines++;
        if (f) fclose(f);
        if (png) fclose(png);
        printf("%-22s exit %d, %d line(s)\n", bad[k], status, lines);
        TL_CHECK(status == 2);
        TL_CHECK(lines == 1);
        TL_CHECK(png == NULL);
    }
}
