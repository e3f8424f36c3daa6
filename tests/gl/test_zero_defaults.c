/* Zero is the default, everywhere (issue 26; docs/architecture.md): each public struct, zeroed where a call
 * accepts it, means what its header documents and works. The renderer's cases run on five boxes
 * away from the origin (so that a box left at the origin, which is where zeroed bounds put it, is
 * outside the view), lit by one directional light; each zeroed frame is compared byte for byte
 * with the frame of the same scene written out in full (the documented default spelled out), and
 * each must draw its 5 objects.
 *
 * Structs of the public headers that are outputs only (tl_frame_stats, tl_frame_plan and its
 * parts, tl_scene_feature_set, tl_view_info, tl_app_pass_context, tl_egl_device, tl_projection,
 * tl_image_error, tl_rgba8_image) are not inputs, so no zeroed instance of them is given to a
 * call; tl_vertex is data. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_fixture.h"
#include "thinlight/context.h"
#include "thinlight/file.h"
#include "thinlight/metrics.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"
#include "tl_test.h"

#define W 64
#define H 64
#define BOXES 5

typedef struct boxes {
    tl_vertex v[BOXES * 24];
    uint32_t idx[BOXES * 36];
    tl_object obj[BOXES];
    tl_material mat[1];
    tl_texture tex[1];
    uint8_t red[4 * 4 * 4];
    tl_light light[1];
    tl_scene s;
} boxes;

/* Box i: a cube of side 2 standing on y = 0 at x = 15 + 2.5 i, z = 0. */
static void box_centre(int i, float c[3])
{
    c[0] = 15.0f + 2.5f * (float)i;
    c[1] = 1.0f;
    c[2] = 0.0f;
}

/* The six faces of the cube of side 2 around `c` (24 vertices, 36 indices from `base`). */
static void add_cube(tl_vertex *v, uint32_t *idx, uint32_t base, const float c[3])
{
    static const float n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int f = 0; f < 6; f++) {
        int a = 0;
        while (n[f][a] == 0.0f) a++;
        int u = (a + 1) % 3, w = (a + 2) % 3;
        float s = n[f][a];
        for (int k = 0; k < 4; k++) {
            tl_vertex *x = &v[f * 4 + k];
            memset(x, 0, sizeof *x);
            float du = (k == 1 || k == 2) ? 1.0f : -1.0f, dw = k >= 2 ? 1.0f : -1.0f;
            x->position[a] = c[a] + s;
            x->position[u] = c[u] + du * s; /* flipped on the negative face: counter-clockwise outside */
            x->position[w] = c[w] + dw;
            memcpy(x->normal, n[f], sizeof x->normal);
            x->uv[0] = 0.5f * (du + 1.0f);
            x->uv[1] = 0.5f * (dw + 1.0f);
        }
        const uint32_t q[6] = {0, 1, 2, 0, 2, 3};
        for (int k = 0; k < 6; k++) idx[f * 6 + k] = base + (uint32_t)(f * 4) + q[k];
    }
}

/* The world-space bounds of object `o`, by brute force over its indices (double, rounded). */
static void brute_bounds(const tl_scene *s, const tl_object *o, float lo[3], float hi[3])
{
    double l[3] = {INFINITY, INFINITY, INFINITY}, h[3] = {-INFINITY, -INFINITY, -INFINITY};
    int zero = 1;
    for (int k = 0; k < 16; k++) zero &= o->transform[k] == 0.0f;
    for (uint32_t i = o->first_index; i < o->first_index + o->index_count; i++) {
        const float *p = s->vertices[s->indices[i]].position;
        for (int r = 0; r < 3; r++) {
            double x = zero ? p[r]
                            : (double)o->transform[r] * p[0] + (double)o->transform[4 + r] * p[1] +
                                  (double)o->transform[8 + r] * p[2] + (double)o->transform[12 + r];
            l[r] = x < l[r] ? x : l[r];
            h[r] = x > h[r] ? x : h[r];
        }
    }
    for (int r = 0; r < 3; r++) {
        lo[r] = o->index_count ? (float)l[r] : 0.0f;
        hi[r] = o->index_count ? (float)h[r] : 0.0f;
    }
}

enum { WORLD_SPACE = 1, WITH_BOUNDS = 2, WITH_TEXTURE = 4 };

/* The five boxes. WORLD_SPACE: vertices in world space and zeroed transforms (else each cube
 * around the origin, moved by a translation); WITH_BOUNDS: every object's bounds (else zero);
 * WITH_TEXTURE: one red 4x4 texture in the scene, which no material names. The material is zeroed. */
static void build_boxes(boxes *b, int how)
{
    memset(b, 0, sizeof *b);
    for (int i = 0; i < BOXES; i++) {
        float c[3], origin[3] = {0, 0, 0};
        box_centre(i, c);
        add_cube(b->v + i * 24, b->idx + i * 36, (uint32_t)(i * 24), (how & WORLD_SPACE) ? c : origin);
        tl_object *o = &b->obj[i];
        o->first_index = (uint32_t)(i * 36);
        o->index_count = 36;
        if (!(how & WORLD_SPACE)) {
            o->transform[0] = o->transform[5] = o->transform[10] = o->transform[15] = 1.0f;
            memcpy(o->transform + 12, c, sizeof c);
        }
    }
    b->s.vertices = b->v;
    b->s.vertex_count = BOXES * 24;
    b->s.indices = b->idx;
    b->s.index_count = BOXES * 36;
    b->s.objects = b->obj;
    b->s.object_count = BOXES;
    b->s.materials = b->mat;
    b->s.material_count = 1;
    if (how & WITH_BOUNDS)
        for (int i = 0; i < BOXES; i++) brute_bounds(&b->s, &b->obj[i], b->obj[i].bounds_min, b->obj[i].bounds_max);
    if (how & WITH_TEXTURE) {
        for (int p = 0; p < 16; p++) memcpy(b->red + 4 * p, (const uint8_t[4]){255, 0, 0, 255}, 4);
        b->tex[0] = (tl_texture){.width = 4, .height = 4, .rgba = b->red, .name = "red"};
        b->s.textures = b->tex;
        b->s.texture_count = 1;
    }
    b->light[0] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {-0.4f, -1.0f, -0.6f}, .color = {3, 3, 3}};
    b->s.lights = b->light;
    b->s.light_count = 1;
    b->s.ambient[0] = b->s.ambient[1] = b->s.ambient[2] = 0.05f;
    /* the origin, where zeroed bounds lie, is 20 units left of the view's centre: outside it */
    b->s.camera = (tl_camera){.position = {20, 6, 12}, .target = {20, 1, 0}};
}

/* The material that a zeroed tl_material documents: plain grey, nothing else. */
static tl_material plain_grey(void)
{
    const float g = TL_MATERIAL_DEFAULT_ALBEDO;
    return (tl_material){.albedo = {g, g, g}};
}

typedef struct shot {
    tl_result set, render;
    char error[512];
    uint8_t px[W * H * 4];
    tl_frame_stats stats;
    tl_frame_plan plan;
} shot;

/* One frame of `s` at W x H with `camera` (NULL: the scene's): results, output and plan. */
static void take(const tl_scene *s, const tl_camera *camera, shot *out)
{
    memset(out, 0, sizeof *out);
    out->set = out->render = TL_ERROR_GL;
    tl_renderer *r =
        tl_test_renderer(&(tl_test_renderer_desc){.renderer = {.width = W, .height = H, .options.synchronous_stats = 1}});
    if (!r) return;
    out->set = tl_renderer_set_scene(r, s);
    if (out->set == TL_OK) {
        tl_renderer_get_plan(r, &out->plan);
        out->render = tl_renderer_render(r, camera, &out->stats);
        size_t size = sizeof out->px;
        if (out->render == TL_OK) tl_renderer_read_output(r, out->px, &size);
    }
    snprintf(out->error, sizeof out->error, "%s", tl_renderer_last_error(r));
    tl_renderer_destroy(r);
}

static size_t lit_pixels(const uint8_t *px)
{
    size_t n = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) n += px[4 * i] > 8 || px[4 * i + 1] > 8 || px[4 * i + 2] > 8;
    return n;
}

/* Largest difference between the colour channels of one pixel, over the lit pixels. */
static int most_colour(const uint8_t *px)
{
    int worst = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        const uint8_t *p = px + 4 * i;
        int d = abs((int)p[0] - p[1]) > abs((int)p[1] - p[2]) ? abs((int)p[0] - p[1]) : abs((int)p[1] - p[2]);
        if (d > worst) worst = d;
    }
    return worst;
}

static size_t bytes_differing(const uint8_t *a, const uint8_t *b)
{
    size_t n = 0;
    for (size_t i = 0; i < (size_t)W * H * 4; i++) n += a[i] != b[i];
    return n;
}

static void report(const char *what, const shot *s)
{
    fprintf(stderr, "  %s: set_scene %s, render %s, %u of %d objects drawn, %zu lit pixels, colour %d%s%s\n", what,
            tl_result_string(s->set), tl_result_string(s->render), (unsigned)s->stats.objects_drawn, BOXES,
            lit_pixels(s->px), most_colour(s->px), s->error[0] ? ": " : "", s->error);
}

/* ---- tl_material ------------------------------------------------------------------------------- */

/* A zeroed material is plain grey (TL_MATERIAL_DEFAULT_ALBEDO, no specular, no texture): the frame
 * of the material written out, with no UV or tangent attribute in the plan. Before, its five
 * texture indices were texture 0: a scene without textures was refused ("materials[0].albedo_texture
 * = 0: past the scene's 0 textures") and the material was black (albedo 0). */
TL_TEST(zero_material_renders_plain_grey_without_tangents)
{
    static boxes b;
    static shot zero, spelled;
    build_boxes(&b, WITH_BOUNDS);
    take(&b.s, NULL, &zero);
    b.mat[0] = plain_grey();
    take(&b.s, NULL, &spelled);
    report("zeroed material", &zero);
    report("plain grey written out", &spelled);
    TL_CHECK(zero.set == TL_OK && zero.render == TL_OK);
    TL_CHECK(spelled.set == TL_OK && spelled.render == TL_OK);
    TL_CHECK_EQ_U(zero.stats.objects_drawn, BOXES);
    TL_CHECK_EQ_U(bytes_differing(zero.px, spelled.px), 0);
    TL_CHECK_LE(W * H / 16, lit_pixels(zero.px));
    TL_CHECK_LE(most_colour(zero.px), 1); /* grey: R, G and B within one step */
    TL_CHECK_EQ_U(zero.plan.vertex_attributes & (TL_ATTRIBUTE_UV | TL_ATTRIBUTE_TANGENT), 0);
    tl_scene_feature_set f;
    tl_scene_features(&b.s, &f);
    TL_CHECK(!f.has_textures && !f.has_normal_maps && !f.has_specular && !f.has_emissive);
}

/* With a texture in the scene the zeroed material still samples nothing: before, it drew texture 0
 * (red) as its albedo, normal, metallic-roughness, emissive and occlusion map, and planned UVs and
 * tangents for it. */
TL_TEST(zero_material_ignores_texture_0)
{
    static boxes b;
    static shot zero, spelled;
    build_boxes(&b, WITH_BOUNDS | WITH_TEXTURE);
    tl_scene_feature_set f;
    tl_scene_features(&b.s, &f);
    fprintf(stderr, "  features: textures %d, normal maps %d, occlusion %d, emissive %d\n", f.has_textures,
            f.has_normal_maps, f.has_occlusion, f.has_emissive);
    TL_CHECK(!f.has_textures && !f.has_normal_maps && !f.has_occlusion && !f.has_emissive_texture);
    take(&b.s, NULL, &zero);
    b.mat[0] = plain_grey();
    take(&b.s, NULL, &spelled);
    report("zeroed material, texture 0 red", &zero);
    TL_CHECK(zero.set == TL_OK && zero.render == TL_OK);
    TL_CHECK_EQ_U(bytes_differing(zero.px, spelled.px), 0);
    TL_CHECK_LE(most_colour(zero.px), 1);
    TL_CHECK_EQ_U(zero.plan.vertex_attributes & (TL_ATTRIBUTE_UV | TL_ATTRIBUTE_TANGENT), 0);
}

/* A texture is named by its index + 1: TL_TEXTURE_MAP(0) is texture 0, which paints the boxes red. */
TL_TEST(material_map_is_texture_index_plus_one)
{
    static boxes b;
    static shot red;
    build_boxes(&b, WITH_BOUNDS | WITH_TEXTURE);
    b.mat[0] = plain_grey();
    b.mat[0].albedo_map = TL_TEXTURE_MAP(0);
    take(&b.s, NULL, &red);
    report("albedo_map = TL_TEXTURE_MAP(0), red", &red);
    TL_CHECK(red.set == TL_OK && red.render == TL_OK);
    size_t reddish = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) reddish += red.px[4 * i] > 16 && red.px[4 * i + 1] <= 1;
    TL_CHECK_LE(W * H / 16, reddish);
    TL_CHECK(red.plan.vertex_attributes & TL_ATTRIBUTE_UV);
    TL_CHECK(!(red.plan.vertex_attributes & TL_ATTRIBUTE_TANGENT));
    /* map 2 is texture 1, past the scene's one texture: refused naming the field and both numbers */
    b.mat[0].albedo_map = 0;
    b.mat[0].occlusion_map = 2;
    take(&b.s, NULL, &red);
    fprintf(stderr, "  occlusion_map = 2: %s\n", red.error);
    TL_CHECK(red.set == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(strstr(red.error, "materials[0].occlusion_map = 2: texture 1, past the scene's 1 textures") != NULL);
}

/* A scene without materials draws every object with the zeroed material: before, it was refused
 * ("object 0 draws ... material 0, outside the scene's ... 0 materials"). */
TL_TEST(zero_materials_in_scene_is_the_plain_grey_material)
{
    static boxes b;
    static shot none, zero;
    build_boxes(&b, WITH_BOUNDS);
    take(&b.s, NULL, &zero);
    b.s.materials = NULL;
    b.s.material_count = 0;
    take(&b.s, NULL, &none);
    report("no materials", &none);
    TL_CHECK(none.set == TL_OK && none.render == TL_OK);
    TL_CHECK_EQ_U(none.stats.objects_drawn, BOXES);
    TL_CHECK_EQ_U(bytes_differing(none.px, zero.px), 0);
    /* material 1 of a scene without materials is still out of range */
    b.obj[2].material = 1;
    take(&b.s, NULL, &none);
    TL_CHECK(none.set == TL_ERROR_INVALID_ARGUMENT);
}

/* ---- tl_object --------------------------------------------------------------------------------- */

/* Bounds left zero are computed from the object's vertices: every box drawn, the frame of the same
 * scene with its bounds written out. Before: 0 of 5 drawn, a black frame (the zero box at the
 * origin lies outside the view, so culling dropped every object). */
TL_TEST(zero_object_bounds_are_computed)
{
    static boxes b;
    static shot zero, spelled;
    build_boxes(&b, 0);
    take(&b.s, NULL, &zero);
    build_boxes(&b, WITH_BOUNDS);
    take(&b.s, NULL, &spelled);
    report("zero bounds", &zero);
    report("bounds written out", &spelled);
    TL_CHECK(zero.set == TL_OK && zero.render == TL_OK);
    TL_CHECK_EQ_U(zero.stats.objects_drawn, BOXES);
    TL_CHECK_EQ_U(spelled.stats.objects_drawn, BOXES);
    TL_CHECK_LE(W * H / 16, lit_pixels(zero.px));
    TL_CHECK_EQ_U(bytes_differing(zero.px, spelled.px), 0);
}

/* A zeroed transform is the identity (a zero matrix would put every vertex at one point): boxes
 * in world space with zeroed transforms and zero bounds draw the frame of the translated boxes.
 * Before: nothing drawn. */
TL_TEST(zero_object_transform_is_identity)
{
    static boxes b;
    static shot zero, moved;
    build_boxes(&b, WORLD_SPACE);
    take(&b.s, NULL, &zero);
    build_boxes(&b, WITH_BOUNDS);
    take(&b.s, NULL, &moved);
    report("zero transforms and bounds", &zero);
    TL_CHECK(zero.set == TL_OK && zero.render == TL_OK);
    TL_CHECK_EQ_U(zero.stats.objects_drawn, BOXES);
    TL_CHECK_LE(W * H / 16, lit_pixels(zero.px));
    TL_CHECK_EQ_U(bytes_differing(zero.px, moved.px), 0);
}

/* tl_scene_compute_bounds fills every object's bounds and the scene's as the renderer computes
 * those left zero; an object's own bounds are kept by the renderer as given. */
TL_TEST(scene_compute_bounds_fills_objects_and_scene)
{
    static boxes b, ref;
    build_boxes(&b, 0);
    build_boxes(&ref, WITH_BOUNDS);
    TL_CHECK(tl_scene_compute_bounds(&b.s) == TL_OK);
    for (int i = 0; i < BOXES; i++) {
        TL_CHECK(memcmp(b.obj[i].bounds_min, ref.obj[i].bounds_min, sizeof b.obj[i].bounds_min) == 0);
        TL_CHECK(memcmp(b.obj[i].bounds_max, ref.obj[i].bounds_max, sizeof b.obj[i].bounds_max) == 0);
    }
    float c0[3], c4[3];
    box_centre(0, c0);
    box_centre(BOXES - 1, c4);
    const float lo[3] = {c0[0] - 1.0f, 0.0f, -1.0f}, hi[3] = {c4[0] + 1.0f, 2.0f, 1.0f};
    TL_CHECK(memcmp(b.s.bounds_min, lo, sizeof lo) == 0 && memcmp(b.s.bounds_max, hi, sizeof hi) == 0);
}

/* Bounds that are not zero must be finite with min <= max on every axis, and a transform finite:
 * anything else is refused naming the object and the field (NaN bounds were accepted and the
 * object silently culled; a non-finite transform was accepted without a word). */
TL_TEST(object_bounds_nan_or_inverted_refused_naming_the_field)
{
    static boxes b;
    static shot s;
    build_boxes(&b, WITH_BOUNDS);
    b.obj[3].bounds_min[1] = NAN;
    take(&b.s, NULL, &s);
    fprintf(stderr, "  NaN: %s\n", s.error);
    TL_CHECK(s.set == TL_ERROR_INVALID_ARGUMENT && strstr(s.error, "objects[3].bounds_min = (21.5, nan, -1)"));
    build_boxes(&b, WITH_BOUNDS);
    b.obj[1].bounds_max[2] = -2.0f;
    take(&b.s, NULL, &s);
    fprintf(stderr, "  inverted: %s\n", s.error);
    TL_CHECK(s.set == TL_ERROR_INVALID_ARGUMENT && strstr(s.error, "objects[1].bounds_max = (18.5, 2, -2): below "
                                                                    "bounds_min = (16.5, 0, -1) on z"));
    build_boxes(&b, WITH_BOUNDS);
    b.obj[2].transform[5] = INFINITY;
    take(&b.s, NULL, &s);
    fprintf(stderr, "  infinite transform: %s\n", s.error);
    TL_CHECK(s.set == TL_ERROR_INVALID_ARGUMENT && strstr(s.error, "objects[2].transform[5] = inf: not finite"));
}

/* ---- tl_camera, tl_scene ----------------------------------------------------------------------- */

/* A zeroed camera (position and target both zero) frames the scene's objects as the glTF loader's
 * default camera does: every box drawn, none touching the frame's border. Before: refused,
 * "camera.target = (0, 0, 0): the position, no view direction". The scene's own camera zeroed is
 * the same camera. */
TL_TEST(zero_camera_frames_the_scene)
{
    static boxes b;
    static shot given, scene;
    build_boxes(&b, 0);
    tl_camera zero = {0};
    take(&b.s, &zero, &given);
    report("zeroed camera", &given);
    TL_CHECK(given.set == TL_OK && given.render == TL_OK);
    TL_CHECK_EQ_U(given.stats.objects_drawn, BOXES);
    TL_CHECK_LE(W * H / 16, lit_pixels(given.px));
    size_t border = 0;
    for (int i = 0; i < W; i++) {
        const int at[4] = {i, (H - 1) * W + i, i * W, i * W + W - 1};
        for (int k = 0; k < 4; k++) border += given.px[4 * at[k]] > 8 || given.px[4 * at[k] + 1] > 8;
    }
    TL_CHECK_EQ_U(border, 0);
    b.s.camera = (tl_camera){0};
    take(&b.s, NULL, &scene);
    TL_CHECK(scene.set == TL_OK && scene.render == TL_OK);
    TL_CHECK_EQ_U(bytes_differing(scene.px, given.px), 0);
    /* a camera at its target elsewhere is still refused, naming the field */
    tl_camera at = {.position = {1, 2, 3}, .target = {1, 2, 3}};
    take(&b.s, &at, &scene);
    TL_CHECK(scene.render == TL_ERROR_INVALID_ARGUMENT && strstr(scene.error, "camera.target = (1, 2, 3)"));
}

/* A zeroed scene is an empty scene: set_scene and a frame succeed and the frame is black (no
 * ambient, nothing drawn). Before: set_scene refused its camera. */
TL_TEST(zero_scene_renders_an_empty_frame)
{
    static shot s;
    tl_scene zero = {0};
    take(&zero, NULL, &s);
    report("zeroed scene", &s);
    TL_CHECK(s.set == TL_OK && s.render == TL_OK);
    TL_CHECK_EQ_U(lit_pixels(s.px), 0);
    TL_CHECK_EQ_U(s.stats.objects_drawn, 0);
}

/* ---- tl_light, tl_texture ---------------------------------------------------------------------- */

/* A zeroed light is a point light of radius 0, which tl_light documents as refused: the call
 * names the light and the field. */
TL_TEST(zero_light_refused_naming_radius)
{
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = {.width = W, .height = H}});
    tl_light zero = {0};
    TL_CHECK(tl_renderer_set_lights(r, &zero, 1) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(strstr(tl_renderer_last_error(r), "lights[0].radius = 0: a point light needs a finite radius > 0"));
    tl_renderer_destroy(r);
}

/* A zeroed texture has no size and no pixels: refused naming its width. */
TL_TEST(zero_texture_refused_naming_width)
{
    static boxes b;
    static shot s;
    build_boxes(&b, WITH_BOUNDS);
    b.s.textures = b.tex; /* zeroed */
    b.s.texture_count = 1;
    take(&b.s, NULL, &s);
    TL_CHECK(s.set == TL_ERROR_INVALID_ARGUMENT && strstr(s.error, "textures[0].width = 0: outside 1.."));
}

/* ---- tl_renderer_desc and the effects' descriptors, tl_render_output, tl_app_pass_desc ---------- */

/* A zeroed descriptor with only the loader: 1280x720, thin-lpp, D24, FXAA 29, and no effect (each
 * effect's zeroed descriptor is off: no pass, no target). */
TL_TEST(zero_renderer_desc_only_the_loader)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_renderer *r = NULL;
    tl_renderer_desc d = {0};
    d.get_proc_address = tl_context_proc_loader;
    d.get_proc_address_user = g_ctx;
    TL_CHECK(tl_renderer_create(&d, &r) == TL_OK);
    uint32_t w = 0, h = 0;
    tl_renderer_get_size(r, &w, &h);
    TL_CHECK(w == 1280 && h == 720);
    static boxes b;
    build_boxes(&b, 0);
    TL_CHECK(tl_renderer_set_scene(r, &b.s) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK);
    static tl_frame_plan p;
    TL_CHECK(tl_renderer_get_plan(r, &p) == TL_OK);
    TL_CHECK(p.mode == TL_MODE_THIN_LPP && p.width == 1280 && p.height == 720);
    tl_target_set effects = TL_TARGET_BIT(TL_TARGET_AO_RAW) | TL_TARGET_BIT(TL_TARGET_AO) | TL_TARGET_BIT(TL_TARGET_DOF) |
                       TL_TARGET_BIT(TL_TARGET_BLOOM) | TL_TARGET_BIT(TL_TARGET_SSR);
    TL_CHECK_EQ_U(p.targets & effects, 0);
    int fxaa = 0;
    for (size_t i = 0; i < p.pass_count; i++) {
        tl_pass k = p.passes[i].pass;
        TL_CHECK(k != TL_PASS_SSAO && k != TL_PASS_SSAO_BLUR && k != TL_PASS_SSAO_APPLY && k != TL_PASS_FOG &&
                 k != TL_PASS_DOF && k != TL_PASS_DOF_APPLY && k != TL_PASS_BLOOM && k != TL_PASS_SSR &&
                 k != TL_PASS_SSR_APPLY);
        fxaa += k == TL_PASS_FXAA;
    }
    TL_CHECK_EQ_U(fxaa, 1);
    /* the pure planner from zeroed inputs: the same defaults */
    tl_scene_feature_set none = {0};
    static tl_frame_plan q;
    TL_CHECK(tl_frame_plan_build(&(tl_renderer_desc){0}, &none, &q) == TL_OK);
    TL_CHECK(q.mode == TL_MODE_THIN_LPP && q.width == 1280 && q.height == 720 && !(q.targets & effects));
    tl_renderer_destroy(r);
}

/* A zeroed tl_render_output is the context's default framebuffer at the renderer's size: the same
 * pixels as the renderer's own output. A zeroed tl_app_pass_desc has no name: refused. */
TL_TEST(zero_render_output_is_the_default_framebuffer)
{
    static boxes b;
    build_boxes(&b, 0);
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = {.width = W, .height = H}});
    static uint8_t own[W * H * 4], fb0[W * H * 4];
    TL_CHECK(tl_renderer_set_scene(r, &b.s) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_read_output(r, own, &(size_t){sizeof own}) == TL_OK);
    TL_CHECK(tl_renderer_render_to(r, NULL, &(tl_render_output){0}, NULL) == TL_OK);
    typedef void (*read_pixels_t)(int, int, int, int, unsigned, unsigned, void *);
    read_pixels_t read_pixels = (read_pixels_t)tl_context_get_proc_address(g_ctx, "glReadPixels");
    TL_CHECK(read_pixels != NULL);
    if (read_pixels) read_pixels(0, 0, W, H, 0x1908 /* GL_RGBA */, 0x1401 /* GL_UNSIGNED_BYTE */, fb0);
    size_t off = 0;
    for (size_t i = 0; i < sizeof own; i++) off += (i % 4 != 3) && abs((int)own[i] - fb0[i]) > 1;
    TL_CHECK_EQ_U(off, 0);
    TL_CHECK_LE(W * H / 16, lit_pixels(fb0));
    TL_CHECK(tl_renderer_add_pass(r, &(tl_app_pass_desc){0}) == TL_ERROR_INVALID_ARGUMENT);
    tl_renderer_destroy(r);
}

/* ---- descriptors outside the renderer ---------------------------------------------------------- */

/* tl_default_scene_desc zeroed is the NULL descriptor's scene; tl_context_desc zeroed makes the
 * default 640x480 context; tl_stats zeroed is empty and ready; tl_file_write_desc zeroed writes. */
TL_TEST(zero_descriptors_outside_the_renderer)
{
    tl_scene *a = NULL, *z = NULL;
    TL_CHECK(tl_scene_create_default(NULL, &a) == TL_OK);
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){0}, &z) == TL_OK);
    TL_CHECK(a && z && a->light_count == z->light_count && a->index_count == z->index_count &&
             memcmp(a->lights, z->lights, a->light_count * sizeof *a->lights) == 0);
    tl_scene_destroy(a);
    tl_scene_destroy(z);

    tl_stats st = {0};
    tl_stats_add(&st, 2.0);
    tl_stats_add(&st, 4.0);
    TL_CHECK(st.count == 2 && st.sum == 6.0 && st.min == 2.0 && st.max == 4.0);

    char path[] = "zero_file_write_desc.txt";
    TL_CHECK(tl_file_write(path, "zero", 4, &(tl_file_write_desc){0}) == TL_OK);
    remove(path);

    if (!ensure_context()) { tl_test_failures++; return; }
    tl_context *c = NULL;
    TL_CHECK(tl_context_create(&(tl_context_desc){0}, &c) == TL_OK);
    uint32_t w = 0, h = 0;
    int major = 0, minor = 0;
    tl_context_get_size(c, &w, &h);
    tl_context_gl_version(c, &major, &minor);
    TL_CHECK(w == 640 && h == 480 && major * 10 + minor >= 45);
    tl_context_destroy(c);
    TL_CHECK(tl_context_make_current(g_ctx) == TL_OK);
}

/* ---- texture maps from the glTF loader to the renderer ----------------------------------------- */

#ifdef TL_TEST_GLTF
#include "gltf_fixtures.h"
#include "thinlight/io.h"

/* textured_boxes.gltf end to end: the loader names albedo.png (texture 0) as map 1 on both
 * materials and the metallic-roughness and normal maps as 2 and 3; the renderer samples the
 * texture a map names: with albedo.png's pixels (texture albedo_map - 1) painted pure green, every
 * pixel that changes turns green, and painting the texture after it instead (what a renderer that
 * read the map as the index would sample as albedo) does not turn the boxes green. A zeroed
 * tl_gltf_options loads the same scene as NULL options. */
TL_TEST(gltf_texture_maps_end_to_end)
{
    const char *dir = TL_TEST_WORK_DIR "/zero_gltf";
    TL_CHECK(tlf_mkdir_p(dir) == 0 && tl_test_write_gltf_scenes(dir) == 0);
    char path[512];
    snprintf(path, sizeof path, "%s/textured_boxes.gltf", dir);
    tl_scene *s = NULL, *z = NULL;
    TL_CHECK(tl_scene_load_gltf(path, NULL, &s) == TL_OK);
    TL_CHECK(tl_scene_load_gltf(path, &(tl_gltf_options){0}, &z) == TL_OK);
    if (!s || !z) return;
    TL_CHECK(s->vertex_count == z->vertex_count && s->object_count == z->object_count &&
             memcmp(s->materials, z->materials, s->material_count * sizeof *s->materials) == 0);
    tl_scene_destroy(z);
    TL_CHECK(s->texture_count == 3 && s->material_count == 2);
    if (s->texture_count != 3 || s->material_count != 2) return;
    const tl_material *m = &s->materials[0];
    TL_CHECK(m->albedo_map == 1 && m->metallic_roughness_map == 2 && m->normal_map == 3);
    TL_CHECK(s->materials[1].albedo_map == 1);
    TL_CHECK(strcmp(s->textures[m->albedo_map - 1].name, "albedo.png") == 0);

    static shot plain, green, next;
    take(s, NULL, &plain);
    TL_CHECK(plain.set == TL_OK && plain.render == TL_OK);
    TL_CHECK(plain.plan.vertex_attributes & TL_ATTRIBUTE_TANGENT); /* the normal map needs them */
    tl_texture *albedo = &s->textures[m->albedo_map - 1], *after = &s->textures[m->albedo_map];
    size_t na = (size_t)albedo->width * albedo->height, nb = (size_t)after->width * after->height;
    uint8_t *keep_a = malloc(4 * na), *keep_b = malloc(4 * nb);
    if (!keep_a || !keep_b) { free(keep_a); free(keep_b); tl_scene_destroy(s); tl_test_failures++; return; }
    memcpy(keep_a, albedo->rgba, 4 * na);
    memcpy(keep_b, after->rgba, 4 * nb);
    for (size_t i = 0; i < na; i++) memcpy(albedo->rgba + 4 * i, (const uint8_t[4]){0, 255, 0, 255}, 4);
    take(s, NULL, &green);
    memcpy(albedo->rgba, keep_a, 4 * na);
    for (size_t i = 0; i < nb; i++) memcpy(after->rgba + 4 * i, (const uint8_t[4]){0, 255, 0, 255}, 4);
    take(s, NULL, &next);
    memcpy(after->rgba, keep_b, 4 * nb);
    size_t changed = 0, turned_green = 0, next_green = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        const uint8_t *a = plain.px + 4 * i, *g = green.px + 4 * i, *n = next.px + 4 * i;
        if (abs((int)a[0] - g[0]) + abs((int)a[1] - g[1]) + abs((int)a[2] - g[2]) > 6) {
            changed++;
            turned_green += g[1] > g[0] && g[1] > g[2];
        }
        next_green += n[1] > n[0] + 32 && n[1] > n[2] + 32 && !(a[1] > a[0] + 32 && a[1] > a[2] + 32);
    }
    printf("  albedo.png painted green: %zu pixels changed, %zu of them green; the next texture painted: %zu "
           "pixels turned green\n", changed, turned_green, next_green);
    TL_CHECK_LE(W * H / 16, changed);
    TL_CHECK_EQ_U(turned_green, changed);
    TL_CHECK_EQ_U(next_green, 0);
    free(keep_a);
    free(keep_b);
    tl_scene_destroy(s);
}
#endif
