/* The shadow debug outputs (docs/shadows.md, "Debug views"): the shadow-debug pass's target
 * (tl_renderer_options.shadow_debug) against ray-traced truth and the documented cascade splits,
 * the atlas read back against the geometry it holds, and the plan without the option unchanged. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_fixture.h"
#include "shadow_rt.h"
#include "shadow_scenes.h"
#include "tl_test.h"

enum { W = 240, H = 135, BAND = 2 };

static tl_renderer *tl__renderer(const tl_shadow_case *c, const tl_light *lights, size_t n, tl_renderer_options o,
                                 uint32_t w, uint32_t h)
{
    tl_scene s = *c->scene;
    s.lights = (tl_light *)lights;
    s.light_count = n;
    o.synchronous_stats = 1;
    return tl_test_render_once(&s, (tl_renderer_desc){.width = w, .height = h, .options = o});
}

static int tl__has_pass(const tl_frame_plan *p, const char *name)
{
    for (size_t i = 0; i < p->pass_count; i++)
        if (!strcmp(p->passes[i].name, name)) return 1;
    return 0;
}

/* Off (or on without a casting light): the plan is byte for byte the plan without the option. On:
 * the same passes, programs and HDR image, plus the shadow-debug pass, its target and its program,
 * the only one with TL_SHADOW_DEBUG. */
TL_TEST(shadow_debug_plan_unchanged_when_off)
{
    tl_shadow_case c;
    TL_CHECK(tl_shadow_stiff_case(&c));
    tl_light none[2] = {c.lights[0], c.lights[1]};
    none[0].shadow = none[1].shadow = 0;
    tl_renderer *off = tl__renderer(&c, c.lights, 2, (tl_renderer_options){0}, 160, 90);
    tl_renderer *on = tl__renderer(&c, c.lights, 2, (tl_renderer_options){.shadow_debug = 1}, 160, 90);
    tl_renderer *a = tl__renderer(&c, none, 2, (tl_renderer_options){0}, 160, 90);
    tl_renderer *b = tl__renderer(&c, none, 2, (tl_renderer_options){.shadow_debug = 1}, 160, 90);
    TL_CHECK(off && on && a && b);
    tl_frame_plan po, pn, pa, pb;
    if (off && on && a && b && tl_renderer_get_plan(off, &po) == TL_OK && tl_renderer_get_plan(on, &pn) == TL_OK &&
        tl_renderer_get_plan(a, &pa) == TL_OK && tl_renderer_get_plan(b, &pb) == TL_OK) {
        TL_CHECK(memcmp(&pa, &pb, sizeof pa) == 0); /* no casting light: the option changes nothing */
        TL_CHECK(!tl__has_pass(&po, "shadow-debug") && tl__has_pass(&pn, "shadow-debug"));
        TL_CHECK(!(po.targets & TL_TARGET_BIT(TL_TARGET_SHADOW_DEBUG)));
        TL_CHECK(pn.targets & TL_TARGET_BIT(TL_TARGET_SHADOW_DEBUG));
        TL_CHECK_EQ_U(pn.pass_count, po.pass_count + 1);
        TL_CHECK_EQ_U(pn.program_count, po.program_count + 1);
        for (size_t i = 0, j = 0; i < pn.program_count && j < po.program_count; i++) {
            int debug = strstr(pn.programs[i].defines, "TL_SHADOW_DEBUG") != NULL;
            TL_CHECK(debug == !strcmp(pn.programs[i].name, "shadow-debug"));
            if (debug) continue;
            TL_CHECK(!strcmp(pn.programs[i].name, po.programs[j].name));
            TL_CHECK(!strcmp(pn.programs[i].defines, po.programs[j].defines));
            j++;
        }
        for (size_t i = 0; i < po.program_count; i++) TL_CHECK(!strstr(po.programs[i].defines, "TL_SHADOW_DEBUG"));
        float *ho = tl_test_read_target(off, TL_TARGET_HDR, 160 * 90), *hn = tl_test_read_target(on, TL_TARGET_HDR, 160 * 90);
        TL_CHECK(ho && hn && memcmp(ho, hn, 160 * 90 * 4 * sizeof(float)) == 0);
        free(ho);
        free(hn);
    }
    TL_CHECK(tl_renderer_set_options(on, &(tl_renderer_options){.shadow_debug = 2}) == TL_ERROR_INVALID_ARGUMENT);
    tl_renderer_destroy(off);
    tl_renderer_destroy(on);
    tl_renderer_destroy(a);
    tl_renderer_destroy(b);
    tl_shadow_case_free(&c);
}

/* The shadow-only term (R where some casting light reaches, G > 0) of one light in every mode
 * (the low sun, a point light beside the pole and above the box),
 * against the truth: no acne, at most 0.5 % of the counted pixels in the wrong state. */
TL_TEST(shadow_debug_only_term_against_truth)
{
    static const tl_render_mode modes[] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_FORWARD,
                                           TL_MODE_VISIBILITY};
    tl_shadow_case c;
    TL_CHECK(tl_shadow_stiff_case(&c));
    tl_light lights[2] = {c.lights[0], /* and a point light above the box */
                          {.type = TL_LIGHT_POINT, .position = {-0.5f, 2.0f, -7.0f}, .color = {20, 20, 20},
                           .radius = 30.0f, .shadow = 1}};
    tl_shadow_rt *rt = tl_shadow_rt_create(c.scene);
    uint8_t *state = malloc(W * H);
    uint32_t *object = malloc(W * H * sizeof *object);
    float *term = malloc(W * H * sizeof *term);
    TL_CHECK(rt && state && object && term);
    for (size_t l = 0; rt && state && object && term && l < 2; l++) {
        tl_shadow_rt_truth(rt, &c.scene->camera, W, H, &lights[l], state, object);
        for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
            tl_renderer *r = tl__renderer(&c, &lights[l], 1, (tl_renderer_options){.mode = modes[m], .shadow_debug = 1}, W, H);
            float *d = r ? tl_test_read_target(r, TL_TARGET_SHADOW_DEBUG, W * H) : NULL;
            TL_CHECK(d != NULL);
            size_t shadowed = 0;
            for (size_t i = 0; d && i < W * H; i++) {
                term[i] = d[4 * i + 3] > 0.5f && d[4 * i + 1] > 0.0f ? d[4 * i] : -1.0f;
                shadowed += term[i] >= 0.0f && term[i] < 0.5f;
            }
            tl_shadow_error e = d ? tl_shadow_rt_compare(state, object, term, W, H, BAND) : (tl_shadow_error){0};
            printf("shadow-only light=%zu mode=%s counted=%zu shadowed=%zu acne=%zu leaks=%zu wrong=%.4f%%\n", l,
                   tl_render_mode_name(modes[m]), e.counted, shadowed, e.acne, e.leaks, 100.0 * e.wrong);
            TL_CHECK(e.counted > W * H / 4);
            TL_CHECK(shadowed > 100); /* the box's (and the pole's) shadow is there */
            TL_CHECK_LE(e.acne, 0);
            TL_CHECK_LE(e.wrong, 0.005);
            free(d);
            tl_renderer_destroy(r);
        }
    }
    tl_shadow_rt_destroy(rt);
    free(state);
    free(object);
    free(term);
    tl_shadow_case_free(&c);
}

/* The documented splits (docs/shadows.md, Cascades): the camera's range from the near plane to the
 * farthest corner of the scene's bounds, split logarithmically from far / 1000. */
static void tl__expected_splits(const tl_scene *s, float splits[4])
{
    const tl_camera *cam = &s->camera;
    float far = 0.0f;
    for (int k = 0; k < 8; k++) {
        float e = 0.0f;
        for (int a = 0; a < 3; a++) {
            float p = (k >> a) & 1 ? s->bounds_max[a] : s->bounds_min[a];
            e += (p - cam->position[a]) * (p - cam->position[a]);
        }
        far = fmaxf(far, sqrtf(e));
    }
    far = fminf(far, cam->far_z);
    float near = fmaxf(cam->near_z, far * 1e-3f);
    for (int i = 0; i < 4; i++) splits[i] = near * powf(far / near, (float)(i + 1) / 4.0f);
}

static float tl__smoothstep(float a, float b, float x)
{
    float t = fminf(fmaxf((x - a) / (b - a), 0.0f), 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

/* The cascade coordinate (B) against the view depth and the splits: its index is the number of
 * split ends at or before the depth (so it grows with depth), its fraction the blend over the
 * slice's last 10 %; all four cascades show on the plane running to the horizon. */
TL_TEST(shadow_debug_cascades_follow_splits)
{
    tl_shadow_case c;
    TL_CHECK(tl_shadow_stiff_case(&c));
    c.scene->camera.position[1] = 6.0f; /* higher, looking down the plane: cascades 0 to 3 on screen */
    c.scene->camera.target[2] = -200.0f;
    float want[4];
    tl__expected_splits(c.scene, want);
    for (int dfmt = 0; dfmt < 2; dfmt++) {
        tl_renderer_options o = {.shadow_debug = 1, .depth_format = dfmt ? TL_DEPTH_FORMAT_D32F_REVERSED : TL_DEPTH_FORMAT_D24};
        tl_renderer *r = tl__renderer(&c, c.lights, 1, o, W, H);
        tl_shadow_view_info v[8];
        size_t n = 8;
        TL_CHECK(r && tl_renderer_get_shadow_views(r, v, &n, NULL) == TL_OK);
        TL_CHECK_EQ_U(n, 4);
        for (size_t i = 0; i < n && i < 4; i++) {
            TL_CHECK(v[i].type == TL_LIGHT_DIRECTIONAL && v[i].index == i && !v[i].perspective);
            TL_CHECK_LE(fabsf(v[i].split - want[i]), 1e-4f * want[i]);
        }
        float *d = r ? tl_test_read_target(r, TL_TARGET_SHADOW_DEBUG, W * H) : NULL;
        float *z = r ? tl_test_read_target(r, TL_TARGET_DEPTH, W * H) : NULL;
        TL_CHECK(d && z);
        size_t per[5] = {0}, wrong = 0;
        for (size_t i = 0; d && z && i < W * H; i++) {
            if (d[4 * i + 3] < 0.5f) continue;
            float depth = z[4 * i + 1], b = d[4 * i + 2];
            int k = 0;
            while (k < 4 && depth >= want[k]) k++;
            float start = k ? want[k - 1] : 0.0f, blend = 0.0f;
            if (k < 3) blend = tl__smoothstep(want[k] - 0.1f * (want[k] - start), want[k], depth);
            float expect = k == 4 ? -1.0f : (float)k + blend;
            /* the stored depth's step at this depth, two of them (docs/shadows.md, e_gbuffer): the
             * shader and this test linearise it with different rounding */
            const tl_camera *cam = &c.scene->camera;
            float dz = dfmt ? ldexpf(depth, -21)
                            : ldexpf(depth * depth, -22) * (cam->far_z - cam->near_z) / (cam->far_z * cam->near_z);
            if (fabsf(depth - start) < dz || (k < 4 && fabsf(depth - want[k]) < dz)) continue; /* on a split */
            per[k]++;
            wrong += fabsf(b - expect) > 0.01f + (k < 4 ? 15.0f * dz / (want[k] - start) : 0.0f);
        }
        printf("shadow-cascades depth=%d pixels per cascade %zu %zu %zu %zu beyond %zu wrong=%zu\n", dfmt, per[0],
               per[1], per[2], per[3], per[4], wrong);
        for (int k = 0; k < 3; k++) TL_CHECK(per[k] > 50);
        TL_CHECK(per[3] > 0);
        TL_CHECK_EQ_U(wrong, 0);
        free(d);
        free(z);
        tl_renderer_destroy(r);
    }
    tl_shadow_case_free(&c);
}

/* The atlas read back: a spot light 4 m straight above the plane looks at a plane 4 m down its
 * axis, so every texel of its tile, linearised as tl_renderer_read_shadow_atlas documents, is 4 m. */
TL_TEST(shadow_debug_atlas_holds_the_plane)
{
    tl_shadow_case c;
    TL_CHECK(tl_shadow_stiff_case(&c));
    tl_light spot = {.type = TL_LIGHT_SPOT, .position = {-8.0f, 4.0f, -20.0f}, .direction = {0, -1, 0},
                     .color = {5, 5, 5}, .radius = 10.0f, .cos_inner = 0.9f, .cos_outer = 0.8f, .shadow = 1};
    for (int dfmt = 0; dfmt < 2; dfmt++) { /* the atlas is reversed whatever the frame's format */
        tl_renderer_options o = {.depth_format = dfmt ? TL_DEPTH_FORMAT_D32F_REVERSED : TL_DEPTH_FORMAT_D24,
                                 .shadows = {.atlas_size = 1024}};
        tl_renderer *r = tl__renderer(&c, &spot, 1, o, 160, 90);
        tl_shadow_view_info v;
        size_t n = 1, bytes = 0;
        uint32_t side = 0;
        TL_CHECK(r && tl_renderer_get_shadow_views(r, &v, &n, &side) == TL_OK && n == 1 && side == 1024);
        TL_CHECK(r && tl_renderer_read_shadow_atlas(r, NULL, &bytes) == TL_OK && bytes == 1024u * 1024u * 4u);
        float *a = malloc(bytes);
        TL_CHECK(a && r && tl_renderer_read_shadow_atlas(r, a, &bytes) == TL_OK);
        if (!a || !r || n != 1) {
            free(a);
            tl_renderer_destroy(r);
            continue;
        }
        TL_CHECK(v.type == TL_LIGHT_SPOT && v.perspective && v.size == 128 && v.light == 0);
        float nz = v.near_z, fz = v.far_z, worst = 0.0f;
        for (uint32_t y = v.y; y < v.y + v.size; y++)
            for (uint32_t x = v.x; x < v.x + v.size; x++) {
                float dv = a[(size_t)y * 1024 + x];
                float zl = nz * fz / (nz + dv * (fz - nz));
                worst = fmaxf(worst, fabsf(zl - 4.0f));
            }
        printf("shadow-atlas depth=%d tile %u,%u size %u near %g far %g worst |z - 4 m| = %g\n", dfmt, v.x, v.y, v.size,
               (double)nz, (double)fz, (double)worst);
        TL_CHECK_LE(worst, 4e-3f);
        free(a);
        tl_renderer_destroy(r);
    }
    tl_shadow_case_free(&c);
}
