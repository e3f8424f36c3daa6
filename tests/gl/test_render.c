/* Renderer tests on OSMesa: light volumes against the same lights shaded full-screen, FXAA on
 * rendered edges and on generated images, the built-in scene. The room scene is in
 * tests/common/render_room.c, bad descriptors and scenes in tests/input/renderer_bad_input.c. */
#include "tl_test.h"

#include "thinlight/context.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"

#include "render_room.h"

/* Renders the scene with volumes and full-screen and compares the diffuse and specular light
 * buffers. Both paths run the same fragment code on the same G-buffer, so every pixel the volume
 * covers must match; pixels it skips must be exactly zero in the full-screen image (the falloff
 * reaches zero at the radius). The tolerance is half an FP16 step of the larger value. */
static void compare_volumes(test_scene *t, const tl_camera *cam, tl_depth_format depth, const char *label)
{
    const uint32_t w = 160, h = 96;
    TL_CHECK(ensure_context());
    if (!g_ctx) return;
    tl_test_renderer_desc d = {.renderer = {.width = w, .height = h, .options = {.depth_format = depth, .fxaa = TL_FXAA_OFF}},
                               .scene = &t->s, .readable = true};
    tl_renderer *vol = tl_test_renderer(&d);
    d.renderer.options.fullscreen_lights = 1;
    tl_renderer *ref = tl_test_renderer(&d);
    if (!vol || !ref) return;
    tl_frame_stats sv, sr;
    TL_CHECK(tl_renderer_render(vol, cam, &sv) == TL_OK);
    TL_CHECK(tl_renderer_render(ref, cam, &sr) == TL_OK);
    size_t n = (size_t)w * h * 4;
    float *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
    const tl_target_id ids[2] = {TL_TARGET_LIGHT_DIFFUSE, TL_TARGET_LIGHT_SPECULAR};
    for (int k = 0; k < 2; k++) {
        TL_CHECK(tl_renderer_read_target(vol, ids[k], a, &(size_t){n * sizeof *a}) == TL_OK);
        TL_CHECK(tl_renderer_read_target(ref, ids[k], b, &(size_t){n * sizeof *b}) == TL_OK);
        double max_rel = 0.0, sum = 0.0;
        size_t lit = 0, bad = 0;
        for (size_t i = 0; i < n; i++) {
            if (i % 4 == 3) continue;
            TL_CHECK(isfinite(a[i]) && isfinite(b[i]));
            double m = fmax(fabs(a[i]), fabs(b[i])), d = fabs((double)a[i] - b[i]);
            double tol = m * (0.5 * TL_HALF_REL_STEP) + 1e-7;
            if (d > tol) bad++;
            if (m > 0) max_rel = fmax(max_rel, d / m);
            if (b[i] > 1e-3) lit++;
            sum += b[i];
        }
        printf("%s %s: lit %zu of %zu values, sum %.3f, max relative difference %.3g, %zu beyond tolerance\n", label,
               k ? "specular" : "diffuse", lit, n / 4 * 3, sum, max_rel, bad);
        if (k == 0) TL_CHECK(lit > n / 400); /* the light does reach the scene */
        if (k == 1) TL_CHECK(sum > 0.01);    /* and makes a highlight */
        TL_CHECK_EQ_U(bad, 0);
    }
    free(a);
    free(b);
    tl_renderer_destroy(vol);
    tl_renderer_destroy(ref);
}

static void set_point(test_scene *t, float x, float y, float z, float radius)
{
    t->lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {x, y, z}, .direction = {0, -1, 0},
                              .color = {4, 3, 2}, .radius = radius};
    t->s.light_count = 1;
}

TL_TEST(light_volume_camera_inside)
{
    test_scene t;
    build_room(&t);
    set_point(&t, 0.5f, 3.2f, 7.0f, 6.0f); /* the camera at (0,3,8) is 1.1 from the light */
    compare_volumes(&t, NULL, TL_DEPTH_FORMAT_D24, "camera inside (D24)");
    compare_volumes(&t, NULL, TL_DEPTH_FORMAT_D32F_REVERSED, "camera inside (reversed D32F)");
}

TL_TEST(light_volume_crossing_near_plane)
{
    test_scene t;
    build_room(&t);
    /* near plane at 1.0: the sphere (radius 2.8) is cut by it but does not hold the camera */
    tl_camera cam = {{0, 3, 8}, {0, 0, 0}, {0, 1, 0}, 1.2f, 1.0f, 100.0f};
    set_point(&t, 1.8f, 1.2f, 6.5f, 2.8f);
    float c[3] = {1.8f, 1.2f - 3.0f, 6.5f - 8.0f}, dir[3] = {0.0f, -3.0f, -8.0f};
    float dl = sqrtf(dir[1] * dir[1] + dir[2] * dir[2]);
    float depth = (c[1] * dir[1] + c[2] * dir[2]) / dl; /* light centre's distance along the view axis */
    TL_CHECK(sqrtf(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) > 2.8f); /* camera outside the sphere */
    TL_CHECK(depth - 2.8f < 1.0f && depth + 2.8f > 1.0f);            /* sphere cut by the near plane */
    compare_volumes(&t, &cam, TL_DEPTH_FORMAT_D24, "near plane (D24)");
    compare_volumes(&t, &cam, TL_DEPTH_FORMAT_D32F_REVERSED, "near plane (reversed D32F)");
}

TL_TEST(light_volume_crossing_far_plane)
{
    test_scene t;
    build_room(&t);
    /* far plane at 17.5: the back wall (distance 18 along the axis, nearer off-axis) straddles it and
     * the light's sphere reaches past it */
    tl_camera cam = {{0, 3, 8}, {0, 3, -10}, {0, 1, 0}, 1.2f, 0.1f, 17.5f};
    set_point(&t, 0.0f, 3.0f, -8.0f, 5.0f);
    compare_volumes(&t, &cam, TL_DEPTH_FORMAT_D24, "far plane (D24)");
    compare_volumes(&t, &cam, TL_DEPTH_FORMAT_D32F_REVERSED, "far plane (reversed D32F)");
}

TL_TEST(light_volume_spot_camera_inside)
{
    test_scene t;
    build_room(&t);
    t.lights[0] = (tl_light){.type = TL_LIGHT_SPOT, .position = {0, 4, 8.5f}, .direction = {0, -0.5f, -1},
                             .color = {6, 6, 9}, .radius = 14.0f, .cos_inner = 0.9f, .cos_outer = 0.75f};
    t.s.light_count = 1;
    compare_volumes(&t, NULL, TL_DEPTH_FORMAT_D24, "spot, camera inside (D24)");
}

/* Spot cones up to 90 degrees, the widest a light may have (glTF's outerConeAngle <= pi/2), drawn
 * by their volume exactly as over the full screen: a spot pointing along the floor lights it up to
 * the plane through the light, the band near 90 degrees in view; a large one holding the camera
 * (back faces) and a small one the camera is outside of (front faces). Past 60 degrees the volume
 * is light.vert.glsl's 45-degree cone behind the light (before: the cone of acos(0.05), 87 degrees,
 * whose bounding sphere, 24 radii, held the camera in any room). */
TL_TEST(light_volume_spot_up_to_90_degrees_matches_full_screen)
{
    const float outer[4] = {0.0f, cosf(1.5707964f) /* -4.4e-8: cosf of pi/2's float */, 0.26f, 0.5f};
    for (int i = 0; i < 8; i++) {
        test_scene t;
        build_room(&t);
        const tl_light large = {.type = TL_LIGHT_SPOT, .position = {0, 1.5f, 2}, .direction = {0, 0, -1},
                                .color = {9, 8, 7}, .radius = 14.0f, .cos_inner = outer[i % 4] + 0.25f,
                                .cos_outer = outer[i % 4]},
                       small = {.type = TL_LIGHT_SPOT, .position = {2, 1, 3}, .direction = {1, 0, 0},
                                .color = {9, 8, 7}, .radius = 2.0f, .cos_inner = outer[i % 4] + 0.25f,
                                .cos_outer = outer[i % 4]};
        t.lights[0] = i < 4 ? large : small;
        t.s.light_count = 1;
        char label[64];
        snprintf(label, sizeof label, "%s spot, cos_outer %g (%.1f degrees)", i < 4 ? "large" : "small",
                 (double)outer[i % 4], acos((double)outer[i % 4]) * 180.0 / 3.14159265358979);
        compare_volumes(&t, NULL, TL_DEPTH_FORMAT_D24, label);
        compare_volumes(&t, NULL, TL_DEPTH_FORMAT_D32F_REVERSED, label);
    }
}

TL_TEST(light_volume_mixed_types_draw_calls)
{
    test_scene t;
    build_room(&t);
    t.lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {-4, 2, -2}, .direction = {0, -1, 0},
                             .color = {3, 1, 1}, .radius = 4.0f};
    t.lights[1] = (tl_light){.type = TL_LIGHT_POINT, .position = {4, 1, 0}, .direction = {0, -1, 0},
                             .color = {1, 3, 1}, .radius = 3.0f};
    t.lights[2] = (tl_light){.type = TL_LIGHT_SPOT, .position = {0, 9, 0}, .direction = {0, -1, 0},
                             .color = {2, 2, 4}, .radius = 12.0f, .cos_inner = 0.95f, .cos_outer = 0.8f};
    t.lights[3] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {-0.3f, -1, -0.2f},
                             .color = {0.2f, 0.2f, 0.3f}};
    t.s.light_count = 4;
    compare_volumes(&t, NULL, TL_DEPTH_FORMAT_D24, "mixed types (D24)");
    /* draw calls grow with light types, not counts */
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = 96, .height = 64, .options = {.depth_format = TL_DEPTH_FORMAT_D24, .fxaa = TL_FXAA_OFF}},
        .scene = &t.s, .readable = true});
    if (!r) return;
    tl_frame_stats st;
    TL_CHECK(tl_renderer_render(r, NULL, &st) == TL_OK);
    TL_CHECK_EQ_U(st.lights_drawn[TL_LIGHT_POINT], 2);
    TL_CHECK_EQ_U(st.lights_drawn[TL_LIGHT_SPOT], 1);
    TL_CHECK_EQ_U(st.lights_drawn[TL_LIGHT_DIRECTIONAL], 1);
    TL_CHECK_EQ_U(st.draw_calls, 2u * st.objects_drawn + 3u + 1u); /* G-buffer, material; 3 light types; tone map */
    tl_renderer_destroy(r);
}

/* ---- FXAA -------------------------------------------------------------------------------- */

static double luma8(const uint8_t *p) { return (0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]) / 255.0; }

TL_TEST(fxaa_reduces_edge_gradient)
{
    const uint32_t w = 320, h = 180;
    TL_CHECK(ensure_context());
    if (!g_ctx) return;
    test_scene t;
    build_room(&t);
    t.lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {2, 4, 4}, .direction = {0, -1, 0},
                             .color = {30, 30, 30}, .radius = 14.0f};
    t.s.light_count = 1;
    /* a slightly rotated view so that the box's silhouette edges are not axis-aligned */
    tl_camera cam = {{2.5f, 2.2f, 6.5f}, {0, 1.2f, 0}, {0.12f, 1, 0}, 0.9f, 0.1f, 100.0f};
    tl_test_renderer_desc d = {.renderer = {.width = w, .height = h, .options = {.depth_format = TL_DEPTH_FORMAT_D24, .fxaa = TL_FXAA_OFF}},
                               .scene = &t.s, .readable = true};
    tl_renderer *off = tl_test_renderer(&d);
    d.renderer.options.fxaa = TL_FXAA_29;
    tl_renderer *on = tl_test_renderer(&d);
    if (!off || !on) return;
    TL_CHECK(tl_renderer_render(off, &cam, NULL) == TL_OK && tl_renderer_render(on, &cam, NULL) == TL_OK);
    size_t n = (size_t)w * h * 4;
    uint8_t *a = malloc(n), *b = malloc(n);
    TL_CHECK(tl_renderer_read_output(off, a, &(size_t){n}) == TL_OK && tl_renderer_read_output(on, b, &(size_t){n}) == TL_OK);
    /* hard edges: neighbour luma steps above 0.2 in the aliased image */
    double ga = 0, gb = 0, flat_change = 0;
    size_t edges = 0, flats = 0;
    for (uint32_t y = 1; y + 1 < h; y++)
        for (uint32_t x = 1; x + 1 < w; x++) {
            size_t i = ((size_t)y * w + x) * 4;
            double dxa = fabs(luma8(a + i) - luma8(a + i + 4)), dya = fabs(luma8(a + i) - luma8(a + i + 4 * w));
            double dxb = fabs(luma8(b + i) - luma8(b + i + 4)), dyb = fabs(luma8(b + i) - luma8(b + i + 4 * w));
            if (dxa > 0.2 || dya > 0.2) {
                ga += fmax(dxa, dya);
                gb += fmax(dxb, dyb);
                edges++;
            }
            double local = 0; /* flat: the whole 3x3 neighbourhood within one 8-bit step */
            for (int k = -1; k <= 1; k++)
                local = fmax(local, fmax(fabs(luma8(a + i) - luma8(a + i + 4 * k)), fabs(luma8(a + i) - luma8(a + i + 4 * (int)w * k))));
            if (local <= 1.0 / TL_UNORM_MAX(8)) {
                flat_change = fmax(flat_change, fabs(luma8(a + i) - luma8(b + i)));
                flats++;
            }
        }
    printf("edge pixels %zu: mean gradient %.4f without FXAA, %.4f with; flat pixels %zu, max change %.4f\n", edges,
           ga / (double)edges, gb / (double)edges, flats, flat_change);
    TL_CHECK(edges > 100);
    TL_CHECK(flats > 1000);
    TL_CHECK_LE(gb / (double)edges, 0.8 * ga / (double)edges); /* edges at least 20 % softer */
    TL_CHECK_LE(flat_change, 1.5 / TL_UNORM_MAX(8));            /* flat regions untouched: 1.5 8-bit steps */
    for (size_t i = 3; i < n; i += 4) TL_CHECK(b[i] == 255);     /* alpha forced back to 1 */
    free(a);
    free(b);
    tl_renderer_destroy(off);
    tl_renderer_destroy(on);
}

/* A 1-pixel text-like pattern (dark strokes on a light page) and a flat image through FXAA. */
TL_TEST(fxaa_flat_and_text_pattern_bounded)
{
    const uint32_t w = 128, h = 64;
    TL_CHECK(ensure_context());
    if (!g_ctx) return;
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = w, .height = h, .options = {.depth_format = TL_DEPTH_FORMAT_D24, .fxaa = TL_FXAA_29}}, .readable = true});
    if (!r) return;
    size_t n = (size_t)w * h * 4;
    uint8_t *img = malloc(n), *out = malloc(n);
    for (size_t i = 0; i < n; i += 4) img[i] = 120, img[i + 1] = 140, img[i + 2] = 90, img[i + 3] = 255;
    TL_CHECK(tl_renderer_apply_fxaa(r, img, out, &(size_t){n}) == TL_OK);
    int flat_max = 0;
    for (size_t i = 0; i < n; i++)
        if (i % 4 != 3) flat_max = abs((int)out[i] - (int)img[i]) > flat_max ? abs((int)out[i] - (int)img[i]) : flat_max;
    printf("flat image: max change %d steps\n", flat_max);
    TL_CHECK(flat_max == 0);
    /* glyph-like strokes: 5x7 cells with 1-pixel vertical, horizontal and diagonal strokes */
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            uint32_t cx = x % 6, cy = y % 8, glyph = (x / 6 + 3 * (y / 8)) % 4;
            int ink = 0;
            if (cx < 5 && cy < 7) {
                if (glyph == 0) ink = cx == 0 || cy == 0 || cy == 3;       /* F-like */
                if (glyph == 1) ink = cx == 2 || cy == 6;                  /* T/L-like */
                if (glyph == 2) ink = cx == cy * 5 / 7 || cy == 0;         /* diagonal */
                if (glyph == 3) ink = (cx == 0 || cx == 4) || cy == 3;     /* H-like */
            }
            uint8_t v = ink ? 20 : 235;
            size_t i = ((size_t)y * w + x) * 4;
            img[i] = img[i + 1] = img[i + 2] = v;
            img[i + 3] = 255;
        }
    TL_CHECK(tl_renderer_apply_fxaa(r, img, out, &(size_t){n}) == TL_OK);
    double mean = 0, ink_out = 0, paper_out = 0;
    size_t ink = 0, outside = 0;
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            size_t i = ((size_t)y * w + x) * 4;
            mean += fabs((double)out[i] - img[i]) / 255.0;
            if (img[i] == 20) {
                ink++;
                ink_out += out[i];
            } else {
                paper_out += out[i];
            }
            /* FXAA only interpolates: each result lies within its 3x3 neighbourhood's range
             * (bilinear taps reach no further), give or take one 8-bit rounding step */
            int lo = 255, hi = 0;
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    int xx = (int)x + dx, yy = (int)y + dy;
                    if (xx < 0 || yy < 0 || xx >= (int)w || yy >= (int)h) continue;
                    int v = img[((size_t)yy * w + (size_t)xx) * 4];
                    lo = v < lo ? v : lo;
                    hi = v > hi ? v : hi;
                }
            if (out[i] + 1 < lo || out[i] > hi + 1) outside++;
        }
    mean /= (double)(w * h);
    double contrast = (paper_out / (double)(w * h - ink) - ink_out / (double)ink) / (235.0 - 20.0);
    printf("text pattern: mean change %.4f, stroke contrast kept %.3f, values outside their 3x3 range %zu\n", mean,
           contrast, outside);
    /* FXAA cannot tell 1-pixel strokes from aliasing and softens them; it must keep them legible:
     * at least half the stroke/paper contrast, at most 20 % mean change, no invented values. */
    TL_CHECK(contrast >= 0.5);
    TL_CHECK_LE(mean, 0.20);
    TL_CHECK_EQ_U(outside, 0);
    free(img);
    free(out);
    tl_renderer_destroy(r);
}

/* ---- the built-in scene ------------------------------------------------------------------ */

static int all_finite(tl_renderer *r, tl_target_id id, float *buf, size_t n, size_t *bad)
{
    if (tl_renderer_read_target(r, id, buf, &(size_t){n * sizeof *buf}) != TL_OK) return 0; /* not allocated */
    for (size_t i = 0; i < n; i++)
        if (!isfinite(buf[i])) (*bad)++;
    return 1;
}

TL_TEST(default_scene_image_sanity)
{
    const uint32_t w = 640, h = 360;
    TL_CHECK(ensure_context());
    if (!g_ctx) return;
    tl_scene *scene = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 64}, &scene) == TL_OK);
    if (!scene) return;
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = w, .height = h, .options = {.depth_format = TL_DEPTH_FORMAT_D24, .fxaa = TL_FXAA_29}}, .readable = true});
    if (!r) {
        tl_scene_destroy(scene);
        return;
    }
    TL_CHECK(tl_renderer_set_scene(r, scene) == TL_OK);
    tl_frame_stats st;
    TL_CHECK(tl_renderer_render(r, NULL, &st) == TL_OK);
    size_t n = (size_t)w * h * 4;
    float *buf = malloc(n * sizeof *buf), *before = malloc(n * sizeof *before), *after = malloc(n * sizeof *after);
    /* no NaN or Inf in any target the frame allocated */
    size_t checked = 0;
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        size_t bad = 0;
        if (!all_finite(r, (tl_target_id)t, buf, n, &bad)) continue;
        checked++;
        if (bad) fprintf(stderr, "target %s: %zu non-finite values\n", tl_target_name((tl_target_id)t), bad);
        TL_CHECK_EQ_U(bad, 0);
    }
    TL_CHECK(checked >= 6);
    /* a non-trivial histogram of the final image */
    uint8_t *img = malloc(n);
    TL_CHECK(tl_renderer_read_output(r, img, &(size_t){n}) == TL_OK);
    size_t hist[256] = {0}, black = 0, white = 0;
    double mean = 0;
    for (size_t i = 0; i < n; i += 4) {
        int l = (int)lround(luma8(img + i) * 255.0);
        hist[l]++;
        black += l <= 2;
        white += l >= 253;
        mean += l / 255.0;
    }
    mean /= (double)(n / 4);
    size_t levels = 0;
    for (int i = 0; i < 256; i++) levels += hist[i] > 0;
    printf("default scene 640x360, 64 point + %u spot + %u directional lights drawn: mean luma %.3f, %zu levels, "
           "%.1f %% black, %.1f %% white\n",
           st.lights_drawn[TL_LIGHT_SPOT], st.lights_drawn[TL_LIGHT_DIRECTIONAL], mean, levels,
           100.0 * (double)black / (double)(n / 4), 100.0 * (double)white / (double)(n / 4));
    TL_CHECK(levels >= 100);
    TL_CHECK(mean > 0.08 && mean < 0.8);
    TL_CHECK(black * 4 < n / 4); /* under a quarter black */
    TL_CHECK(white * 20 < n / 4); /* under 5 % clipped */

    /* removing every light leaves only ambient and emissive: the plan drops the light pass, the
     * light buffer and RT0 (nothing reads them), and no HDR pixel gets brighter */
    const size_t nf = n * sizeof(float);
    TL_CHECK(tl_renderer_read_target(r, TL_TARGET_HDR, before, &(size_t){nf}) == TL_OK);
    TL_CHECK(tl_renderer_set_lights(r, NULL, 0) == TL_OK);
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_read_target(r, TL_TARGET_LIGHT_DIFFUSE, buf, &(size_t){nf}) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_renderer_read_target(r, TL_TARGET_RT0, buf, &(size_t){nf}) == TL_ERROR_INVALID_ARGUMENT);
    tl_frame_plan plan;
    TL_CHECK(tl_renderer_get_plan(r, &plan) == TL_OK);
    for (size_t i = 0; i < plan.pass_count; i++) TL_CHECK(plan.passes[i].pass != TL_PASS_LIGHTS);
    TL_CHECK(tl_renderer_read_target(r, TL_TARGET_HDR, after, &(size_t){nf}) == TL_OK);
    double sum_before = 0, sum_after = 0;
    size_t brighter = 0;
    for (size_t i = 0; i < n; i++) {
        if (i % 4 == 3) continue;
        sum_before += before[i];
        sum_after += after[i];
        if (after[i] > before[i] * (1.0 + TL_HALF_REL_STEP) + 1e-6) brighter++; /* one FP16 step of HDR */
    }
    printf("HDR sum with lights %.1f, without %.1f\n", sum_before, sum_after);
    TL_CHECK(sum_after < 0.5 * sum_before);
    TL_CHECK_EQ_U(brighter, 0);

    /* adding one bright light in front of the camera brightens the image, and no pixel darkens */
    tl_light *more = malloc((scene->light_count + 1) * sizeof *more);
    memcpy(more, scene->lights, scene->light_count * sizeof *more);
    const tl_camera *c = &scene->camera;
    float f[3] = {c->target[0] - c->position[0], c->target[1] - c->position[1], c->target[2] - c->position[2]};
    float fl = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    more[scene->light_count] = (tl_light){.type = TL_LIGHT_POINT,
                                          .position = {c->position[0] + 6 * f[0] / fl, c->position[1] + 6 * f[1] / fl,
                                           c->position[2] + 6 * f[2] / fl},
                                          .direction = {0, -1, 0}, .color = {40, 40, 40}, .radius = 8.0f};
    TL_CHECK(tl_renderer_set_lights(r, more, scene->light_count + 1) == TL_OK);
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_read_target(r, TL_TARGET_HDR, after, &(size_t){nf}) == TL_OK);
    size_t darker = 0, lit = 0;
    for (size_t i = 0; i < n; i++) {
        if (i % 4 == 3) continue;
        if (after[i] < before[i] * (1.0 - TL_HALF_REL_STEP) - 1e-6) darker++;
        if (after[i] > before[i] * 1.05 + 1e-3) lit++;
    }
    printf("extra light: %zu values brighter by > 5 %%, %zu darker\n", lit, darker);
    TL_CHECK(lit > n / 100);
    TL_CHECK_EQ_U(darker, 0);
    free(more);
    free(img);
    free(buf);
    free(before);
    free(after);
    tl_renderer_destroy(r);
    tl_scene_destroy(scene);
}
