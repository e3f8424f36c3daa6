/* Tiled light accumulation (issue 11) against light volumes and the full-screen reference: the
 * light-volume edge cases, tile and image borders, every mode with D24 and reversed D32F, Forward+
 * against per-object forward lists, list overflow, the R11G11B10F light buffer, and the planner's
 * choice. Tolerances come from FP16 rounding: the volumes (and the full-screen reference) round the
 * light buffer to FP16 after every light, the tiled pass once per pixel. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_room.h"
#include "thinlight/codec.h"
#include "tl_test.h"

#define BIT(t) TL_TARGET_BIT(t)

/* llvmpipe stores FP16 rounding toward zero: one store is off by less than one FP16 step
 * (TL_HALF_REL_STEP relative, or FP16's smallest subnormal step 2^-24 below 2^-14); a sum of n
 * blended terms by less than n steps. */
static double fp16_sum_tol(double value, double stores) { return value * stores * TL_HALF_REL_STEP + stores * 0x1.0p-24; }

static float *read(tl_renderer *r, tl_target_id id, size_t n)
{
    float *p = malloc(n * 4 * sizeof *p);
    size_t size = n * 4 * sizeof *p;
    if (!p || tl_renderer_read_target(r, id, p, &size) != TL_OK) {
        free(p);
        return NULL;
    }
    return p;
}

static uint8_t *read_output(tl_renderer *r, size_t n)
{
    uint8_t *p = malloc(n * 4);
    if (p && tl_renderer_read_output(r, p, &(size_t){n * 4}) != TL_OK) {
        free(p);
        return NULL;
    }
    return p;
}

/* Largest step between two RGBA8 images (RGB), and how many values are more than one apart. */
static int max_step(const uint8_t *a, const uint8_t *b, size_t n, size_t *over_one)
{
    int m = 0;
    *over_one = 0;
    for (size_t i = 0; i < n * 4; i++) {
        if (i % 4 == 3) continue;
        int d = abs((int)a[i] - (int)b[i]);
        m = d > m ? d : m;
        *over_one += d > 1;
    }
    return m;
}

/* Light buffers of `r` and `ref` (same scene and camera) agree within the FP16 rounding of
 * `stores` blended lights per pixel plus one rounding; returns the count of values beyond it. */
static size_t compare_light_buffers(tl_renderer *r, tl_renderer *ref, size_t n, double stores, const char *label)
{
    const tl_target_id ids[2] = {TL_TARGET_LIGHT_DIFFUSE, TL_TARGET_LIGHT_SPECULAR};
    size_t bad = 0;
    for (int k = 0; k < 2; k++) {
        float *a = read(r, ids[k], n), *b = read(ref, ids[k], n);
        TL_CHECK(a && b);
        double max_rel = 0.0, sum = 0.0;
        for (size_t i = 0; a && b && i < n * 4; i++) {
            if (i % 4 == 3) continue;
            double m = fmax(fabs(a[i]), fabs(b[i])), d = fabs((double)a[i] - b[i]);
            if (!isfinite(a[i]) || d > fp16_sum_tol(m, stores + 1.0)) bad++;
            if (m > 0.0) max_rel = fmax(max_rel, d / m);
            sum += b[i];
        }
        printf("  %s %s: sum %.3f, max relative difference %.3g\n", label, k ? "specular" : "diffuse", sum, max_rel);
        if (k == 0) TL_CHECK(sum > 1.0);
        free(a);
        free(b);
    }
    return bad;
}

/* ---- the light-volume edge cases, tiled -------------------------------------------------------- */

static void compare_tiled(test_scene *t, const tl_camera *cam, tl_depth_format depth, uint32_t tile, const char *label)
{
    const uint32_t w = 160, h = 96;
    const size_t n = (size_t)w * h;
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_renderer_desc d = {.width = w, .height = h, .options.depth_format = depth, .options.fxaa = TL_FXAA_OFF,
                          .options.tile_size = tile};
    tl_renderer_desc dr = d;
    dr.options.fullscreen_lights = 1;
    dr.options.light_strategy = TL_LIGHT_STRATEGY_VOLUMES;
    tl_renderer *ref = tl_test_renderer(&(tl_test_renderer_desc){.renderer = dr, .readable = true});
    TL_CHECK(ref && tl_renderer_set_scene(ref, &t->s) == TL_OK && tl_renderer_render(ref, cam, NULL) == TL_OK);
    uint8_t *ref_out = ref ? read_output(ref, n) : NULL;
    for (int compute = 0; compute < 2; compute++) {
        d.options.light_strategy = TL_LIGHT_STRATEGY_TILED;
        d.options.tiled_shading = compute ? TL_TILED_SHADING_COMPUTE : TL_TILED_SHADING_FRAGMENT;
        tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = d, .readable = true});
        TL_CHECK(r && tl_renderer_set_scene(r, &t->s) == TL_OK && tl_renderer_render(r, cam, NULL) == TL_OK);
        if (!r || !ref) continue;
        char name[160];
        snprintf(name, sizeof name, "%s, %u px tiles, %s", label, tile, compute ? "compute" : "fragment");
        TL_CHECK_EQ_U(compare_light_buffers(r, ref, n, (double)t->s.light_count, name), 0);
        uint8_t *out = read_output(r, n);
        size_t over = 0;
        int step = out && ref_out ? max_step(out, ref_out, n, &over) : 99;
        printf("  %s: final image at most %d step(s) from the full-screen reference\n", name, step);
        TL_CHECK(step <= 1);
        free(out);
        tl_renderer_destroy(r);
    }
    free(ref_out);
    tl_renderer_destroy(ref);
}

static void set_point(test_scene *t, float x, float y, float z, float radius)
{
    t->lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {x, y, z}, .direction = {0, -1, 0},
                              .color = {4, 3, 2}, .radius = radius};
    t->s.light_count = 1;
}

TL_TEST(tiled_light_volume_edge_cases)
{
    test_scene t;
    const tl_depth_format depths[2] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};
    for (int dz = 0; dz < 2; dz++) {
        const char *dn = dz ? "reversed D32F" : "D24";
        char label[96];
        build_room(&t);
        set_point(&t, 0.5f, 3.2f, 7.0f, 6.0f); /* the camera at (0,3,8) inside the light's range */
        snprintf(label, sizeof label, "camera inside (%s)", dn);
        compare_tiled(&t, NULL, depths[dz], 16, label);
        tl_camera near_cam = {{0, 3, 8}, {0, 0, 0}, {0, 1, 0}, 1.2f, 1.0f, 100.0f};
        set_point(&t, 1.8f, 1.2f, 6.5f, 2.8f); /* cut by the near plane at 1.0 */
        snprintf(label, sizeof label, "near plane (%s)", dn);
        compare_tiled(&t, &near_cam, depths[dz], 16, label);
        tl_camera far_cam = {{0, 3, 8}, {0, 3, -10}, {0, 1, 0}, 1.2f, 0.1f, 17.5f};
        set_point(&t, 0.0f, 3.0f, -8.0f, 5.0f); /* reaching past the far plane */
        snprintf(label, sizeof label, "far plane (%s)", dn);
        compare_tiled(&t, &far_cam, depths[dz], 16, label);
        t.lights[0] = (tl_light){.type = TL_LIGHT_SPOT, .position = {0, 4, 8.5f}, .direction = {0, -0.5f, -1},
                                 .color = {6, 6, 9}, .radius = 14.0f, .cos_inner = 0.9f, .cos_outer = 0.75f};
        snprintf(label, sizeof label, "spot, camera inside (%s)", dn);
        compare_tiled(&t, NULL, depths[dz], 16, label);
        t.lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {-4, 2, -2}, .direction = {0, -1, 0},
                                 .color = {3, 1, 1}, .radius = 4.0f};
        t.lights[1] = (tl_light){.type = TL_LIGHT_POINT, .position = {4, 1, 0}, .direction = {0, -1, 0},
                                 .color = {1, 3, 1}, .radius = 3.0f};
        t.lights[2] = (tl_light){.type = TL_LIGHT_SPOT, .position = {0, 9, 0}, .direction = {0, -1, 0},
                                 .color = {2, 2, 4}, .radius = 12.0f, .cos_inner = 0.95f, .cos_outer = 0.8f};
        t.lights[3] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {-0.3f, -1, -0.2f},
                                 .color = {0.2f, 0.2f, 0.3f}};
        t.s.light_count = 4;
        snprintf(label, sizeof label, "mixed types (%s)", dn);
        compare_tiled(&t, NULL, depths[dz], 16, label);
    }
}

/* Small lights whose ranges straddle tile borders, the image's edges, the near plane, and one
 * behind the camera, for every tile size: a light a tile's list misses shows as a difference. */
TL_TEST(tiled_tile_and_image_borders)
{
    const uint32_t w = 160, h = 96;
    const size_t n = (size_t)w * h;
    if (!ensure_context()) { tl_test_failures++; return; }
    static tl_light lights[64];
    test_scene t;
    build_room(&t);
    size_t k = 0;
    tl_rng rng = {0xB0DE4u};
    for (; k < 56; k++) /* on the back and side walls and the floor, across the whole view */
        lights[k] = (tl_light){.type = TL_LIGHT_POINT,
                               .position = {(float)(tl_rng_unit(&rng) * 20.0 - 10.0), (float)(tl_rng_unit(&rng) * 6.0),
                                (float)(tl_rng_unit(&rng) * 14.0 - 10.0)},
                               .direction = {0, -1, 0}, .color = {1.5f, 1.2f, 0.8f},
                               .radius = (float)(0.6 + tl_rng_unit(&rng) * 1.4)};
    lights[k++] = (tl_light){.type = TL_LIGHT_POINT, .position = {0.0f, 3.0f, 9.5f}, .direction = {0, -1, 0},
                             .color = {5, 5, 5}, .radius = 1.0f};  /* behind the eye */
    lights[k++] = (tl_light){.type = TL_LIGHT_POINT, .position = {0.4f, 2.8f, 7.95f}, .direction = {0, -1, 0},
                             .color = {2, 2, 2}, .radius = 0.5f}; /* at the near plane */
    lights[k++] = (tl_light){.type = TL_LIGHT_SPOT, .position = {-9.5f, 6.0f, 5.0f}, .direction = {0.2f, -1, -0.3f},
                             .color = {3, 2, 1}, .radius = 8.0f, .cos_inner = 0.95f, .cos_outer = 0.85f};
    t.s.lights = lights;
    t.s.light_count = k;
    const uint32_t tiles[3] = {8, 16, 32};
    for (int ti = 0; ti < 3; ti++) {
        tl_renderer_desc d = {.width = w, .height = h, .options.fxaa = TL_FXAA_OFF, .options.tile_size = tiles[ti]};
        tl_renderer_desc dr = d;
        dr.options.fullscreen_lights = 1;
        dr.options.light_strategy = TL_LIGHT_STRATEGY_VOLUMES;
        d.options.light_strategy = TL_LIGHT_STRATEGY_TILED;
        tl_renderer *ref = tl_test_renderer(&(tl_test_renderer_desc){.renderer = dr, .readable = true});
        tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = d, .readable = true});
        TL_CHECK(ref && r);
        if (!ref || !r) continue;
        TL_CHECK(tl_renderer_set_scene(ref, &t.s) == TL_OK && tl_renderer_render(ref, NULL, NULL) == TL_OK);
        tl_frame_stats st;
        TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK && tl_renderer_render(r, NULL, &st) == TL_OK);
        char label[64];
        snprintf(label, sizeof label, "%zu lights at borders, %u px tiles", k, tiles[ti]);
        /* at most 8 of these lights overlap any surface point (their ranges are small) */
        TL_CHECK_EQ_U(compare_light_buffers(r, ref, n, 8.0, label), 0);
        printf("  %s: %llu pixel-light pairs, %llu list entries, %u tiles overflowed\n", label,
               (unsigned long long)st.light_pairs, (unsigned long long)st.light_list_entries, st.tile_overflows);
        TL_CHECK(st.light_pairs > 0 && st.tile_overflows == 0);
        tl_renderer_destroy(ref);
        tl_renderer_destroy(r);
    }
}

/* ---- the crypt, every mode ---------------------------------------------------------------------- */

/* Camera basis of tl_camera (look-at, as the renderer builds it), for world positions of pixels. */
typedef struct basis {
    double eye[3], s[3], u[3], f[3];
} basis;

static void camera_basis(const tl_camera *c, basis *b)
{
    double f[3], l = 0.0;
    for (int k = 0; k < 3; k++) {
        f[k] = (double)c->target[k] - c->position[k];
        l += f[k] * f[k];
        b->eye[k] = c->position[k];
    }
    for (int k = 0; k < 3; k++) b->f[k] = f[k] / sqrt(l);
    double up[3] = {c->up[0], c->up[1], c->up[2]};
    if (up[0] == 0.0 && up[1] == 0.0 && up[2] == 0.0) up[1] = 1.0;
    double s[3] = {b->f[1] * up[2] - b->f[2] * up[1], b->f[2] * up[0] - b->f[0] * up[2], b->f[0] * up[1] - b->f[1] * up[0]};
    double sl = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (int k = 0; k < 3; k++) b->s[k] = s[k] / sl;
    b->u[0] = b->s[1] * b->f[2] - b->s[2] * b->f[1];
    b->u[1] = b->s[2] * b->f[0] - b->s[0] * b->f[2];
    b->u[2] = b->s[0] * b->f[1] - b->s[1] * b->f[0];
}

/* How many of the scene's local lights reach the surface at each pixel (from the read-back depth:
 * window depth and distance along the view axis): the FP16 stores the volumes made there. */
static void lights_per_pixel(const tl_scene *s, const float *depth, uint32_t w, uint32_t h, float clear, double *count)
{
    basis b;
    camera_basis(&s->camera, &b);
    tl_projection pr;
    float fov = s->camera.fov_y > 0.0f ? s->camera.fov_y : 1.0471976f;
    tl_projection_perspective(TL_DEPTH_FORMAT_D24, fov, (float)w / (float)h, 0.1f, 0.0f, &pr);
    for (size_t i = 0; i < (size_t)w * h; i++) {
        count[i] = 0.0;
        if (depth[4 * i] == clear) continue;
        double dist = depth[4 * i + 1], nx = ((double)(i % w) + 0.5) / w * 2.0 - 1.0, ny = ((double)(i / w) + 0.5) / h * 2.0 - 1.0;
        double vx = dist * (nx + pr.m[8]) / pr.m[0], vy = dist * (ny + pr.m[9]) / pr.m[5];
        for (size_t k = 0; k < s->light_count; k++) {
            const tl_light *l = &s->lights[k];
            if (l->type == TL_LIGHT_DIRECTIONAL) {
                count[i] += 1.0;
                continue;
            }
            double d2 = 0.0;
            for (int c = 0; c < 3; c++) {
                double p = b.eye[c] + b.s[c] * vx + b.u[c] * vy + b.f[c] * dist;
                d2 += (p - l->position[c]) * (p - l->position[c]);
            }
            count[i] += d2 < (double)l->radius * l->radius * 1.0001 + 1e-4;
        }
    }
}

TL_TEST_FULL(tiled_matches_volumes_every_mode)
{
    const uint32_t w = 192, h = 108;
    const size_t n = (size_t)w * h;
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 64, .detail = 1}, &s) == TL_OK);
    if (!s) return;
    double *count = malloc(n * sizeof *count);
    const tl_depth_format depths[2] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};
    for (int dz = 0; dz < 2; dz++)
        for (int mode = TL_MODE_THIN_LPP; mode < TL_MODE_COUNT_; mode++) {
            tl_renderer_desc d = {.options.mode = (tl_render_mode)mode, .width = w, .height = h,
                                  .options.depth_format = depths[dz],
                                  .options.fxaa = TL_FXAA_OFF, .options.light_strategy = TL_LIGHT_STRATEGY_VOLUMES};
            tl_renderer *vol = tl_test_renderer(&(tl_test_renderer_desc){.renderer = d, .readable = true});
            d.options.light_strategy = TL_LIGHT_STRATEGY_TILED;
            tl_renderer *til = tl_test_renderer(&(tl_test_renderer_desc){.renderer = d, .readable = true});
            TL_CHECK(vol && til);
            if (!vol || !til) continue;
            TL_CHECK(tl_renderer_set_scene(vol, s) == TL_OK && tl_renderer_render(vol, NULL, NULL) == TL_OK);
            TL_CHECK(tl_renderer_set_scene(til, s) == TL_OK && tl_renderer_render(til, NULL, NULL) == TL_OK);
            float *dv = read(vol, TL_TARGET_DEPTH, n), *hv = read(vol, TL_TARGET_HDR, n), *ht = read(til, TL_TARGET_HDR, n);
            TL_CHECK(dv && hv && ht);
            if (!dv || !hv || !ht) continue;
            lights_per_pixel(s, dv, w, h, dz ? 0.0f : 1.0f, count);
            /* HDR: forward sums in float in both (its strategies differ in the lists only); the others
             * round each light's store (volumes) or once (tiles), then the material pass once more */
            size_t bad = 0;
            double worst = 0.0;
            for (size_t i = 0; i < n; i++)
                for (int c = 0; c < 3; c++) {
                    double a = hv[4 * i + c], b = ht[4 * i + c], m = fmax(fabs(a), fabs(b));
                    double stores = mode == TL_MODE_FORWARD ? 1.0 : count[i] + 2.0;
                    if (!isfinite(b) || fabs(a - b) > fp16_sum_tol(m, stores)) bad++;
                    if (m > 1e-3) worst = fmax(worst, fabs(a - b) / m);
                }
            uint8_t *ov = read_output(vol, n), *ot = read_output(til, n);
            size_t over = 0;
            int step = ov && ot ? max_step(ov, ot, n, &over) : 99;
            printf("%-13s %-13s HDR: %zu values beyond the FP16-sum tolerance, worst relative %.3g; final image: max "
                   "%d step(s), %zu of %zu values more than one apart\n",
                   tl_render_mode_name((tl_render_mode)mode), dz ? "reversed D32F" : "D24", bad, worst, step, over, n * 3);
            TL_CHECK_EQ_U(bad, 0);
            /* the volumes' rounding after every light moves a few values of the 8-bit image by two steps */
            TL_CHECK(step <= 2 && over * 200 <= n * 3);
            if (mode == TL_MODE_FORWARD) TL_CHECK(step <= 1); /* Forward+ against per-object lists */
            free(dv);
            free(hv);
            free(ht);
            free(ov);
            free(ot);
            tl_renderer_destroy(vol);
            tl_renderer_destroy(til);
        }
    free(count);
    tl_scene_destroy(s);
}

/* ---- overflowing lists, 65536 lights ------------------------------------------------------------ */

/* 65536 lights: the first frame's lists do not fit (they hold 32 entries a tile to start), its
 * overflowing tiles loop over every light; later frames have grown lists and no overflow. Lists
 * keep the lights' order, so both give the same bits. */
TL_TEST_FULL(tiled_65536_lights_overflow_then_growth)
{
    const uint32_t w = 96, h = 54;
    const size_t n = (size_t)w * h;
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 65536, .spot_lights = 4096, .detail = 1},
                                     &s) == TL_OK);
    if (!s) return;
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = w, .height = h, .options.light_strategy = TL_LIGHT_STRATEGY_TILED}, .readable = true});
    TL_CHECK(r && tl_renderer_set_scene(r, s) == TL_OK);
    if (!r) return;
    tl_frame_stats first, later;
    TL_CHECK(tl_renderer_render(r, NULL, &first) == TL_OK);
    float *a = read(r, TL_TARGET_HDR, n);
    for (int f = 0; f < 6; f++) TL_CHECK(tl_renderer_render(r, NULL, &later) == TL_OK);
    float *b = read(r, TL_TARGET_HDR, n);
    printf("65536 + 4096 lights: first frame %u tiles overflowed (%llu entries asked for), later frames %u "
           "(%llu entries); %llu pixel-light pairs\n",
           first.tile_overflows, (unsigned long long)first.light_list_entries, later.tile_overflows,
           (unsigned long long)later.light_list_entries, (unsigned long long)later.light_pairs);
    TL_CHECK(first.tile_overflows > 0 && later.tile_overflows == 0);
    TL_CHECK(first.light_list_entries == later.light_list_entries);
    size_t nonfinite = 0;
    for (size_t i = 0; a && b && i < n * 4; i++) nonfinite += !isfinite(a[i]) || !isfinite(b[i]);
    size_t differ = 0;
    double worst = 0.0;
    for (size_t i = 0; a && b && i < n * 4; i++)
        if (a[i] != b[i]) {
            differ++;
            worst = fmax(worst, fabs((double)a[i] - b[i]) / fmax(fabs((double)a[i]), 1e-6));
            if (differ < 4) printf("  value %zu (pixel %zu, %zu): %.9g vs %.9g\n", i, (i / 4) % w, (i / 4) / w, (double)a[i], (double)b[i]);
        }
    printf("  %zu values differ, worst relative %.3g\n", differ, worst);
    TL_CHECK(a && b && nonfinite == 0 && differ == 0);
    free(a);
    free(b);
    tl_renderer_destroy(r);
    tl_scene_destroy(s);
}

/* ---- the R11G11B10F light buffer ---------------------------------------------------------------- */

/* Each light-buffer value rounded once to R11G11B10F (6-bit mantissas for red and green, 5 for
 * blue: relative error below 2^-6 and 2^-5 with rounding toward zero) against RGBA16F. */
TL_TEST(tiled_light_buffer_r11g11b10f)
{
    const uint32_t w = 160, h = 90;
    const size_t n = (size_t)w * h;
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 64, .detail = 1}, &s) == TL_OK);
    if (!s) return;
    tl_renderer_desc d = {.width = w, .height = h, .options.fxaa = TL_FXAA_OFF,
                          .options.light_strategy = TL_LIGHT_STRATEGY_TILED};
    tl_renderer *full = tl_test_renderer(&(tl_test_renderer_desc){.renderer = d, .readable = true});
    d.options.light_format = TL_LIGHT_FORMAT_R11G11B10F;
    tl_renderer *small = tl_test_renderer(&(tl_test_renderer_desc){.renderer = d, .readable = true});
    TL_CHECK(full && small);
    if (!full || !small) return;
    TL_CHECK(tl_renderer_set_scene(full, s) == TL_OK && tl_renderer_render(full, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_set_scene(small, s) == TL_OK && tl_renderer_render(small, NULL, NULL) == TL_OK);
    tl_frame_plan p;
    TL_CHECK(tl_renderer_get_plan(small, &p) == TL_OK);
    TL_CHECK_EQ_U(p.target_bytes_per_pixel[TL_TARGET_LIGHT_DIFFUSE], 4);
    TL_CHECK_EQ_U(p.target_bytes_per_pixel[TL_TARGET_LIGHT_SPECULAR], 4);
    size_t bad = 0;
    for (int k = 0; k < 2; k++) {
        tl_target_id id = k ? TL_TARGET_LIGHT_SPECULAR : TL_TARGET_LIGHT_DIFFUSE;
        float *a = read(full, id, n), *b = read(small, id, n);
        for (size_t i = 0; a && b && i < n * 4; i++) {
            int c = (int)(i % 4);
            if (c == 3) continue;
            double bound = (c == 2 ? 0x1.0p-5 : 0x1.0p-6) + 2.0 * TL_HALF_REL_STEP; /* and FP16's own */
            if (fabs((double)b[i] - a[i]) > bound * fabs((double)a[i]) + 1e-5) bad++;
        }
        free(a);
        free(b);
    }
    uint8_t *oa = read_output(full, n), *ob = read_output(small, n);
    size_t over = 0;
    int step = oa && ob ? max_step(oa, ob, n, &over) : 99;
    printf("R11G11B10F light buffer: %zu values beyond its rounding; final image max %d steps from RGBA16F\n", bad, step);
    TL_CHECK_EQ_U(bad, 0);
    free(oa);
    free(ob);
    /* the compact layout keeps specular luminance in alpha: R11G11B10F has none */
    d.options.light_buffer = TL_LIGHT_BUFFER_COMPACT;
    TL_CHECK(tl_frame_plan_build(&d, &(tl_scene_feature_set){.point_lights = 1}, &p) == TL_ERROR_INVALID_ARGUMENT);
    tl_renderer_destroy(full);
    tl_renderer_destroy(small);
    tl_scene_destroy(s);
}

/* ---- the planner's choice ------------------------------------------------------------------------ */

TL_TEST(tiled_planner_chooses_by_light_count)
{
    tl_frame_plan p;
    tl_renderer_desc d = {.width = 320, .height = 180};
    for (size_t lights = 0; lights < 80; lights++) {
        tl_scene_feature_set f = {.point_lights = lights - lights / 8, .spot_lights = lights / 8, .directional_lights = 1};
        TL_CHECK(tl_frame_plan_build(&d, &f, &p) == TL_OK);
        int tiled = p.light_strategy == TL_LIGHT_STRATEGY_TILED;
        TL_CHECK(tiled == (lights >= 32));
        TL_CHECK(strstr(p.strategy_reason, "auto") != NULL);
        int has_cull = 0, has_volumes = 0;
        for (size_t i = 0; i < p.pass_count; i++) {
            has_cull |= p.passes[i].pass == TL_PASS_LIGHT_CULL;
            has_volumes |= p.passes[i].pass == TL_PASS_LIGHTS;
        }
        TL_CHECK(has_cull == tiled && has_volumes == !tiled);
        TL_CHECK(tiled == ((p.targets & BIT(TL_TARGET_LIGHT_LISTS)) != 0));
        if (tiled) TL_CHECK(p.tiles_x == 20 && p.tiles_y == 12 && p.tile_size == 16);
    }
    d.options.light_strategy = TL_LIGHT_STRATEGY_VOLUMES;
    TL_CHECK(tl_frame_plan_build(&d, &(tl_scene_feature_set){.point_lights = 1000}, &p) == TL_OK);
    TL_CHECK(p.light_strategy == TL_LIGHT_STRATEGY_VOLUMES && strstr(p.strategy_reason, "forced"));
    d.options.light_strategy = TL_LIGHT_STRATEGY_TILED;
    d.options.mode = TL_MODE_FORWARD;
    d.options.forward_depth_prepass = TL_SWITCH_OFF; /* Forward+ keeps its depth pre-pass: the tiles' bounds need it */
    TL_CHECK(tl_frame_plan_build(&d, &(tl_scene_feature_set){.point_lights = 2}, &p) == TL_OK);
    TL_CHECK(p.pass_count >= 3 && p.passes[0].pass == TL_PASS_DEPTH_PREPASS && p.passes[1].pass == TL_PASS_LIGHT_CULL);
    d.options.tile_size = 12;
    TL_CHECK(tl_frame_plan_build(&d, &(tl_scene_feature_set){.point_lights = 2}, &p) == TL_ERROR_INVALID_ARGUMENT);
    tl_light_strategy s;
    TL_CHECK(tl_light_strategy_from_name("tiled", &s) == TL_OK && s == TL_LIGHT_STRATEGY_TILED);
    TL_CHECK(tl_light_strategy_from_name("tiles", &s) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(strcmp(tl_light_strategy_name(TL_LIGHT_STRATEGY_DEFAULT), "auto") == 0);
}
