/* glTF primitive modes and vertex attributes in rendered frames, every mode (issue 30): strips and
 * fans give the image of their triangle lists; points and lines are drawn by the points-lines pass,
 * which only scenes with them plan; COLOR_0 multiplies the base colour and alpha (triangles, lines
 * and points); TEXCOORD_1 feeds the maps whose texCoord is 1. Expected colours are computed:
 * with no lights and an ambient of 1 a pixel is albedo x vertex colour (x texel), within FP16. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_doc.h"
#include "gltf_prims.h"
#include "render_fixture.h"
#include "thinlight/io.h"
#include "tl_test.h"

#define W 64
#define H 48

static const tl_render_mode modes[] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_FORWARD,
                                        TL_MODE_VISIBILITY};
#define MODES ((int)(sizeof modes / sizeof modes[0]))

static void work_dir(char *out, size_t n, const char *test)
{
    snprintf(out, n, "%s/gltf_prims/%s", TL_TEST_WORK_DIR, test);
    TL_CHECK(tlf_mkdir_p(out) == 0);
}

static tl_scene *load(const char *path, int lights)
{
    tl_gltf_options o = {.no_default_lights = !lights};
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_load_gltf(path, &o, &s) == TL_OK);
    return s;
}

/* The HDR target of one frame (W x H, malloc'd) and its plan; NULL on failure. */
static float *render_hdr(const tl_scene *s, tl_render_mode mode, float ambient, tl_frame_plan *plan)
{
    tl_renderer_desc d = {.width = W, .height = H, .options = {.mode = mode}};
    for (int k = 0; k < 3; k++) d.options.ambient[k] = ambient;
    tl_renderer *r = tl_test_render_once(s, d);
    TL_CHECK(r != NULL);
    if (!r) return NULL;
    float *hdr = tl_test_read_target(r, TL_TARGET_HDR, (size_t)W * H);
    TL_CHECK(hdr != NULL);
    if (plan) TL_CHECK(tl_renderer_get_plan(r, plan) == TL_OK);
    tl_renderer_destroy(r);
    return hdr;
}

static int has_pass(const tl_frame_plan *p, tl_pass pass)
{
    for (size_t i = 0; i < p->pass_count; i++)
        if (p->passes[i].pass == pass) return 1;
    return 0;
}

/* FP16 holds 11 significant bits: a value and its expectation agree within 2^-10 relative. */
static int fp16_near(float got, float want) { return fabsf(got - want) <= fabsf(want) * 0x1p-10f + 1e-6f; }

/* A bent strip (a roof over x) as strip, fan and their lists in the specification's order. */
static const float roof[8][3] = {{0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}, {2, 1.5f, 0}, {2, 0, 1}, {3, 1, 0}, {3, 0, 1}};

TL_TEST(gltf_strip_and_fan_render_as_their_triangle_lists)
{
    char dir[1024], a[1024], b[1024];
    work_dir(dir, sizeof dir, "strip_fan");
    uint32_t list[2][18];
    size_t n[2] = {0, 0};
    for (uint32_t i = 0; i + 2 < 8; i++) { /* strip: v[i], v[i + 1 + i % 2], v[i + 2 - i % 2] */
        uint32_t t[3] = {i, i + 1 + i % 2, i + 2 - i % 2};
        for (int c = 0; c < 3; c++) list[0][n[0]++] = t[c];
    }
    for (uint32_t i = 0; i + 2 < 8; i++) { /* fan: v[i + 1], v[i + 2], v[0] */
        uint32_t t[3] = {i + 1, i + 2, 0};
        for (int c = 0; c < 3; c++) list[1][n[1]++] = t[c];
    }
    for (int f = 0; f < 2; f++) {
        tlf_prim fan = {.mode = f ? 6 : 5, .pos = roof, .nv = 8, .material = -1};
        tlf_prim tri = {.mode = -1, .pos = roof, .nv = 8, .idx = list[f], .ni = n[f], .material = -1};
        const char *mat = "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.8,0.6,0.4,1],\"metallicFactor\":0.2}}";
        fan.material = tri.material = 0;
        if (tlf_write_prims(dir, f ? "fan" : "strip", &fan, 1, mat, "", a, sizeof a) ||
            tlf_write_prims(dir, f ? "fan_list" : "strip_list", &tri, 1, mat, "", b, sizeof b)) {
            TL_CHECK(0 && "written");
            return;
        }
        tl_scene *sa = load(a, 1), *sb = load(b, 1);
        for (int m = 0; m < MODES && sa && sb; m++) {
            float *ha = render_hdr(sa, modes[m], 0.0f, NULL), *hb = render_hdr(sb, modes[m], 0.0f, NULL);
            size_t drawn = 0;
            for (size_t i = 0; ha && i < (size_t)W * H; i++) drawn += ha[4 * i] > 0.0f;
            TL_CHECK(drawn > (size_t)W * H / 20); /* the roof is on screen, lit */
            if (ha && hb) TL_CHECK(memcmp(ha, hb, (size_t)W * H * 4 * sizeof(float)) == 0);
            if (ha && hb && memcmp(ha, hb, (size_t)W * H * 4 * sizeof(float)))
                fprintf(stderr, "%s differs from its list in %s\n", f ? "fan" : "strip", tl_render_mode_name(modes[m]));
            free(ha);
            free(hb);
        }
        tl_scene_destroy(sa);
        tl_scene_destroy(sb);
    }
}

/* Counts the pixels equal to `want` (FP16, or within `tol` when given) and those neither background
 * (0) nor any of `n`. */
static void classify(const float *hdr, const float (*want)[3], const float (*tol)[3], size_t n, size_t *count,
                     size_t *other)
{
    *other = 0;
    for (size_t k = 0; k < n; k++) count[k] = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        const float *p = hdr + 4 * i;
        if (p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f) continue;
        size_t k = 0;
        while (k < n && !(tol ? fabsf(p[0] - want[k][0]) <= tol[k][0] && fabsf(p[1] - want[k][1]) <= tol[k][1] &&
                                    fabsf(p[2] - want[k][2]) <= tol[k][2]
                              : fp16_near(p[0], want[k][0]) && fp16_near(p[1], want[k][1]) && fp16_near(p[2], want[k][2])))
            k++;
        if (k < n) count[k]++;
        else if ((*other)++ == 0 && getenv("TL_DEBUG_PRIMS"))
            fprintf(stderr, "pixel %zu: %g %g %g (want %g %g %g)\n", i, p[0], p[1], p[2], want[0][0], want[0][1], want[0][2]);
    }
}

TL_TEST(gltf_vertex_colors_multiply_base_colour_and_alpha_in_every_mode)
{
    /* two triangles with one colour each (unwelded: flat), a third with alpha 0.25 under MASK
     * (discarded), a line loop and points, each one colour; base colour (0.8, 0.6, 0.5) */
    static const float tri[9][3] = {{-2, -1, 0}, {-1, -1, 0}, {-2, 0, 0}, {-1, -1, 0}, {-1, 0, 0}, {-2, 0, 0},
                                    {1.5f, -1, 0}, {2.5f, -1, 0}, {2, 0, 0}};
    static const float c[9][4] = {{1, 0.5f, 0.25f, 1}, {1, 0.5f, 0.25f, 1}, {1, 0.5f, 0.25f, 1},
                                  {0.25f, 1, 0.5f, 1}, {0.25f, 1, 0.5f, 1}, {0.25f, 1, 0.5f, 1},
                                  {0.5f, 0.5f, 1, 0.25f}, {0.5f, 0.5f, 1, 0.25f}, {0.5f, 0.5f, 1, 0.25f}};
    static const float sq[4][3] = {{-0.5f, 0.3f, 0}, {0.5f, 0.3f, 0}, {0.5f, 1.3f, 0}, {-0.5f, 1.3f, 0}};
    static const float line_c[4][4] = {{0.5f, 0.25f, 1, 1}, {0.5f, 0.25f, 1, 1}, {0.5f, 0.25f, 1, 1}, {0.5f, 0.25f, 1, 1}};
    static const float pts[3][3] = {{-0.5f, -0.9f, 0}, {0, -0.9f, 0}, {0.5f, -0.9f, 0}};
    static const float pt_c[3][4] = {{0.2f, 0.8f, 0.8f, 1}, {0.2f, 0.8f, 0.8f, 1}, {0.2f, 0.8f, 0.8f, 1}};
    const char *mats = "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.8,0.6,0.5,1],\"metallicFactor\":0}},"
                       "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.8,0.6,0.5,1],\"metallicFactor\":0},"
                       "\"alphaMode\":\"MASK\",\"alphaCutoff\":0.5}";
    tlf_prim p[4] = {{.mode = -1, .pos = tri, .nv = 6, .color = c, .color_components = 4, .color_type = U8, .material = 0},
                     {.mode = -1, .pos = tri + 6, .nv = 3, .color = c + 6, .color_components = 4, .material = 1},
                     {.mode = 2, .pos = sq, .nv = 4, .color = line_c, .color_components = 3, .color_type = U16, .material = 0},
                     {.mode = 0, .pos = pts, .nv = 3, .color = pt_c, .color_components = 4, .material = 0}};
    char dir[1024], path[1024];
    work_dir(dir, sizeof dir, "vertex_colors");
    if (tlf_write_prims(dir, "colors", p, 4, mats, "", path, sizeof path)) {
        TL_CHECK(0 && "written");
        return;
    }
    tl_scene *s = load(path, 0);
    const float base[3] = {0.8f, 0.6f, 0.5f};
    const float *vc[5] = {c[0], c[3], line_c[0], pt_c[0], c[6]};
    float want[5][3];
    for (int k = 0; k < 5; k++)
        for (int ch = 0; ch < 3; ch++) {
            /* u8 colours arrive as n / 255 */
            float v = k < 2 ? roundf(vc[k][ch] * 255.0f) / 255.0f : k == 2 ? roundf(vc[k][ch] * 65535.0f) / 65535.0f : vc[k][ch];
            want[k][ch] = base[ch] * v;
        }
    for (int m = 0; m < MODES && s; m++) {
        tl_frame_plan plan;
        float *hdr = render_hdr(s, modes[m], 1.0f, &plan);
        if (!hdr) continue;
        size_t count[5], other;
        classify(hdr, (const float(*)[3])want, NULL, 5, count, &other);
        TL_CHECK(has_pass(&plan, TL_PASS_POINTS_LINES));
        TL_CHECK(plan.vertex_attributes & TL_ATTRIBUTE_COLOR);
        TL_CHECK(count[0] >= 10 && count[1] >= 10); /* both triangles (about 15 pixels each) */
        TL_CHECK(count[2] >= 8 && count[3] >= 3); /* the loop's pixels, the three points */
        TL_CHECK_EQ_U(count[4], 0);               /* alpha 0.25 < 0.5: discarded */
        TL_CHECK_EQ_U(other, 0);
        if (other || count[4] || count[3] < 3 || count[2] < 8)
            fprintf(stderr, "%s: %zu %zu %zu %zu %zu, %zu other pixels\n", tl_render_mode_name(modes[m]), count[0],
                    count[1], count[2], count[3], count[4], other);
        free(hdr);
    }
    tl_scene_destroy(s);
}

static float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : powf((c + 0.055f) / 1.055f, 2.4f); }

TL_TEST(gltf_texcoord1_selects_the_second_uv_set_in_every_mode)
{
    /* a 2x2 texture (rows top to bottom); quad A reads texCoord 1 = the bottom-right texel, quad B
     * texCoord 0 = the top-left one; both quads carry both sets */
    static const uint8_t px[16] = {200, 40, 40, 255, 40, 200, 40, 255, 40, 40, 200, 255, 120, 160, 60, 255};
    static const float qa[6][3] = {{-2, -1, 0}, {-0.2f, -1, 0}, {-0.2f, 1, 0}, {-2, -1, 0}, {-0.2f, 1, 0}, {-2, 1, 0}};
    static const float qb[6][3] = {{0.2f, -1, 0}, {2, -1, 0}, {2, 1, 0}, {0.2f, -1, 0}, {2, 1, 0}, {0.2f, 1, 0}};
    static const float uv0[6][2] = {{0.25f, 0.25f}, {0.25f, 0.25f}, {0.25f, 0.25f}, {0.25f, 0.25f}, {0.25f, 0.25f}, {0.25f, 0.25f}};
    static const float uv1[6][2] = {{0.75f, 0.75f}, {0.75f, 0.75f}, {0.75f, 0.75f}, {0.75f, 0.75f}, {0.75f, 0.75f}, {0.75f, 0.75f}};
    char dir[1024], path[1024];
    work_dir(dir, sizeof dir, "texcoord1");
    TL_CHECK(write_png(dir, "t.png", 2, 2, px) == 0);
    const char *mats = "{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0,\"texCoord\":1},\"metallicFactor\":0}},"
                       "{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0},\"metallicFactor\":0}}";
    const char *more = "\"images\":[{\"uri\":\"t.png\"}],\"textures\":[{\"source\":0}]";
    tlf_prim p[2] = {{.mode = -1, .pos = qa, .nv = 6, .uv0 = uv0, .uv1 = uv1, .material = 0},
                     {.mode = -1, .pos = qb, .nv = 6, .uv0 = uv0, .uv1 = uv1, .material = 1}};
    if (tlf_write_prims(dir, "uv1", p, 2, mats, more, path, sizeof path)) {
        TL_CHECK(0 && "written");
        return;
    }
    tl_scene *s = load(path, 0);
    /* sRGB8 decoding may round to the neighbouring linear value: half an 8-bit step either way */
    float want[2][3], tol[2][3];
    for (int ch = 0; ch < 3; ch++)
        for (int k = 0; k < 2; k++) {
            float v = px[(k ? 0 : 12) + ch]; /* texel (1, 1) for A, (0, 0) for B */
            want[k][ch] = srgb_to_linear(v / 255.0f);
            tol[k][ch] = 0.5f * (srgb_to_linear((v + 1.0f) / 255.0f) - srgb_to_linear((v - 1.0f) / 255.0f)) +
                         want[k][ch] * 0x1p-10f;
        }
    for (int m = 0; m < MODES && s; m++) {
        tl_frame_plan plan;
        float *hdr = render_hdr(s, modes[m], 1.0f, &plan);
        if (!hdr) continue;
        size_t count[2], other;
        classify(hdr, (const float(*)[3])want, (const float(*)[3])tol, 2, count, &other);
        TL_CHECK(plan.vertex_attributes & TL_ATTRIBUTE_UV1);
        TL_CHECK(count[0] > 100 && count[1] > 100);
        TL_CHECK_EQ_U(other, 0);
        if (other || count[0] <= 100 || count[1] <= 100)
            fprintf(stderr, "%s: %zu %zu, %zu other pixels\n", tl_render_mode_name(modes[m]), count[0], count[1], other);
        free(hdr);
    }
    tl_scene_destroy(s);
}

TL_TEST(gltf_points_lines_pass_and_attributes_planned_only_when_used)
{
    tl_scene_feature_set f = {.directional_lights = 1};
    for (int m = 0; m < MODES; m++) {
        tl_renderer_desc d = {.width = W, .height = H, .options = {.mode = modes[m]}};
        tl_frame_plan with, without;
        f.has_points_lines = 1;
        f.has_vertex_colors = 1;
        TL_CHECK(tl_frame_plan_build(&d, &f, &with) == TL_OK);
        f.has_points_lines = f.has_vertex_colors = 0;
        TL_CHECK(tl_frame_plan_build(&d, &f, &without) == TL_OK);
        TL_CHECK(has_pass(&with, TL_PASS_POINTS_LINES) && !has_pass(&without, TL_PASS_POINTS_LINES));
        TL_CHECK((with.vertex_attributes & TL_ATTRIBUTE_COLOR) && !(without.vertex_attributes & TL_ATTRIBUTE_COLOR));
        TL_CHECK_EQ_U(with.pass_count, without.pass_count + 1);
        TL_CHECK(!(without.vertex_attributes & TL_ATTRIBUTE_UV1)); /* no uv1 without textures */
    }
}

TL_TEST(renderer_non_finite_vertex_color_or_uv1_refused)
{
    static float colors[3][4] = {{1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}}, uv1[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    tl_vertex v[3] = {{.position = {0, 0, 0}}, {.position = {1, 0, 0}}, {.position = {0, 1, 0}}};
    uint32_t idx[3] = {0, 1, 2};
    tl_object o = {.index_count = 3};
    tl_scene s = {.vertices = v, .vertex_count = 3, .indices = idx, .index_count = 3, .objects = &o, .object_count = 1,
                  .colors = &colors[0][0], .uv1 = &uv1[0][0]};
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = {.width = 8, .height = 8}});
    if (!r) return;
    TL_CHECK(tl_renderer_set_scene(r, &s) == TL_OK);
    colors[1][2] = NAN;
    TL_CHECK(tl_renderer_set_scene(r, &s) == TL_ERROR_INVALID_ARGUMENT);
    colors[1][2] = 1.0f;
    uv1[2][0] = INFINITY;
    TL_CHECK(tl_renderer_set_scene(r, &s) == TL_ERROR_INVALID_ARGUMENT);
    uv1[2][0] = 0.0f;
    TL_CHECK(tl_renderer_set_scene(r, &s) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK);
    tl_renderer_destroy(r);
}
