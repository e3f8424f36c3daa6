/* thinlight-viewer's shadow views (docs/viewer.md) against the renderer in this process, drawing
 * the same frame (the crypt with --shadows, the scene's camera, the harness's tiled strategy):
 * shadow-atlas shows every atlas texel read back with tl_renderer_read_shadow_atlas as docs/viewer.md
 * maps it, shadow-only the shadow-debug target's term, shadow-cascades its cascade colour shaded by
 * the output's luma. The legend's rows are left out. */
#include <math.h>

#include "render_fixture.h"
#include "viewer_harness.h"

enum { SW = 480, SH = 270, LEGEND_ROWS = 48 };

static void put(uint8_t *p, float r, float g, float b)
{
    float c[3] = {r, g, b};
    for (int k = 0; k < 3; k++) p[k] = (uint8_t)(c[k] <= 0.0f ? 0 : c[k] >= 1.0f ? 255 : (int)(c[k] * 255.0f + 0.5f));
}

/* The crypt with its casting lights, as the viewer draws it (thin-lpp, tiled, every target kept). */
static tl_renderer *crypt_renderer(tl_scene **scene)
{
    if (tl_scene_create_default(&(tl_default_scene_desc){.shadows = 1}, scene) != TL_OK) return NULL;
    tl_renderer_options o = {.light_strategy = TL_LIGHT_STRATEGY_TILED, .shadow_debug = 1};
    return tl_test_render_once(*scene, (tl_renderer_desc){.width = SW, .height = SH, .options = o});
}

/* Largest channel difference between the screenshot and `want` (RGB8, rows bottom-up) above the legend. */
static int worst_diff(const image *im, const uint8_t *want, size_t *compared)
{
    int worst = 0;
    for (uint32_t y = 0; y + LEGEND_ROWS < SH; y++)
        for (uint32_t x = 0; x < SW; x++) {
            const uint8_t *p = at(im, x, y), *q = want + 3 * ((size_t)(SH - 1 - y) * SW + x);
            for (int k = 0; k < 3; k++) worst = abs(p[k] - q[k]) > worst ? abs(p[k] - q[k]) : worst;
            (*compared)++;
        }
    return worst;
}

/* docs/viewer.md's mapping of the atlas texel d of view v. */
static void atlas_texel(const tl_shadow_view_info *v, float d, uint8_t *px)
{
    float n = v->near_z, f = v->far_z;
    if (d == 0.0f) { /* reversed depth: the far value, nothing drawn */
        put(px, 0.0f, 0.0f, 0.3f);
        return;
    }
    float z = v->perspective ? n * f / (n + d * (f - n)) : f - d * (f - n), t = (z - n) / (f - n);
    put(px, 1.0f - 0.85f * t, 1.0f - 0.85f * t, 1.0f - 0.85f * t);
}

/* The atlas in the square of side SH at the right: texel (x - x0) * side / SH; tile edges cyan
 * (point), magenta (spot), yellow (directional); black where no view lies. */
static void atlas_expected(const float *atlas, uint32_t side, const tl_shadow_view_info *v, size_t n, uint8_t *want)
{
    static const float edge[4][3] = {{1, 1, 1}, {0, 1, 1}, {1, 0, 1}, {1, 1, 0}};
    const uint32_t x0 = SW - SH;
    memset(want, 0, (size_t)SW * SH * 3);
    for (uint32_t y = 0; y < SH; y++)
        for (uint32_t x = x0; x < SW; x++) {
            uint32_t tx = (x - x0) * side / SH, ty = y * side / SH, ex = (x - x0 + 1) * side / SH, ey = (y + 1) * side / SH;
            for (size_t k = 0; k < n; k++) {
                if (tx < v[k].x || ty < v[k].y || tx >= v[k].x + v[k].size || ty >= v[k].y + v[k].size) continue;
                uint8_t *px = want + 3 * ((size_t)y * SW + x);
                if (tx == v[k].x || ty == v[k].y || ex >= v[k].x + v[k].size || ey >= v[k].y + v[k].size)
                    put(px, edge[v[k].type][0], edge[v[k].type][1], edge[v[k].type][2]);
                else atlas_texel(&v[k], atlas[(size_t)ty * side + tx], px);
                break;
            }
        }
}

TL_TEST(viewer_shadow_atlas_shows_the_atlas_texels)
{
    image im = shot(SW, SH, "--shadows --view shadow-atlas", "shadow_atlas.png");
    tl_scene *scene = NULL;
    tl_renderer *r = crypt_renderer(&scene);
    size_t n = 0, bytes = 0, compared = 0;
    uint32_t side = 0;
    TL_CHECK(im.px && r && tl_renderer_get_shadow_views(r, NULL, &n, &side) == TL_OK && n > 6 && side == 4096);
    tl_shadow_view_info *v = malloc((n ? n : 1) * sizeof *v);
    float *atlas = malloc((size_t)side * side * sizeof(float));
    uint8_t *want = malloc((size_t)SW * SH * 3);
    bytes = (size_t)side * side * sizeof(float);
    if (im.px && r && v && atlas && want && tl_renderer_get_shadow_views(r, v, &n, NULL) == TL_OK &&
        tl_renderer_read_shadow_atlas(r, atlas, &bytes) == TL_OK) {
        atlas_expected(atlas, side, v, n, want);
        int worst = worst_diff(&im, want, &compared);
        printf("shadow-atlas: %zu views, %zu pixels compared, worst channel difference %d\n", n, compared, worst);
        TL_CHECK(worst <= 1);
        TL_CHECK(colours(&im) > 16);
    } else {
        TL_CHECK(0);
    }
    free(v);
    free(atlas);
    free(want);
    release(&im);
    tl_renderer_destroy(r);
    tl_scene_destroy(scene);
}

static const float cascade_colours[4][3] = {{1.0f, 0.25f, 0.2f}, {0.25f, 0.9f, 0.3f}, {0.3f, 0.45f, 1.0f},
                                            {1.0f, 0.85f, 0.2f}};

/* shadow-only: grey R, dark blue where G = 0, black sky; shadow-cascades: the cascade's colour
 * (stripes of the next over the blend) times 0.35 + 0.65 luma of the output, grey beyond. */
static void debug_expected(const float *d, const uint8_t *output, int cascades, uint8_t *want)
{
    for (uint32_t y = 0; y < SH; y++)
        for (uint32_t x = 0; x < SW; x++) {
            size_t i = (size_t)y * SW + x;
            const float *p = d + 4 * i;
            uint8_t *w = want + 3 * i;
            if (!cascades) {
                if (p[3] < 0.5f) put(w, 0, 0, 0);
                else if (p[1] <= 0.0f) put(w, 0.05f, 0.05f, 0.3f);
                else put(w, p[0], p[0], p[0]);
                continue;
            }
            const uint8_t *o = output + 4 * i;
            float shade = p[3] < 0.5f ? 0.0f : 0.35f + 0.65f * (0.2126f * o[0] + 0.7152f * o[1] + 0.0722f * o[2]) / 255.0f;
            const float grey[3] = {0.4f, 0.4f, 0.4f}, *c = grey;
            if (p[2] >= 0.0f) {
                int k = p[2] >= 3.0f ? 3 : (int)p[2];
                c = cascade_colours[k < 3 && (float)((x + y) % 8u) < 8.0f * (p[2] - (float)k) ? k + 1 : k];
            }
            put(w, c[0] * shade, c[1] * shade, c[2] * shade);
        }
}

TL_TEST_FULL(viewer_shadow_only_and_cascades_show_the_debug_target)
{
    tl_scene *scene = NULL;
    tl_renderer *r = crypt_renderer(&scene);
    float *d = r ? tl_test_read_target(r, TL_TARGET_SHADOW_DEBUG, (size_t)SW * SH) : NULL;
    uint8_t *out = malloc((size_t)SW * SH * 4), *want = malloc((size_t)SW * SH * 3);
    size_t size = (size_t)SW * SH * 4;
    TL_CHECK(d && out && want && tl_renderer_read_output(r, out, &size) == TL_OK);
    for (int cascades = 0; cascades < 2 && d && out && want; cascades++) {
        const char *view = cascades ? "shadow-cascades" : "shadow-only";
        char args[128], png[64];
        snprintf(args, sizeof args, "--shadows --view %s", view);
        snprintf(png, sizeof png, "%s.png", view);
        image im = shot(SW, SH, args, png);
        TL_CHECK(im.px != NULL);
        if (!im.px) continue;
        debug_expected(d, out, cascades, want);
        size_t compared = 0, shadowed = 0, lit = 0;
        int worst = worst_diff(&im, want, &compared);
        for (size_t i = 0; i < (size_t)SW * SH; i++) {
            shadowed += d[4 * i + 3] > 0.5f && d[4 * i + 1] > 0.0f && d[4 * i] < 0.1f;
            lit += d[4 * i + 3] > 0.5f && d[4 * i + 1] > 0.0f && d[4 * i] > 0.9f;
        }
        printf("%s: %zu pixels compared, worst channel difference %d; term: %zu shadowed, %zu lit\n", view, compared,
               worst, shadowed, lit);
        TL_CHECK(worst <= (cascades ? 2 : 1)); /* cascades: the output's luma rounds once more */
        TL_CHECK(shadowed > 1000 && lit > 1000);
        release(&im);
    }
    free(d);
    free(out);
    free(want);
    tl_renderer_destroy(r);
    tl_scene_destroy(scene);
}

/* Without casting lights the shadow views say why (the placeholder), and the viewer exits 0. */
TL_TEST(viewer_shadow_views_without_casters_show_the_placeholder)
{
    static const char *const views[] = {"shadow-atlas", "shadow-cascades", "shadow-only"};
    for (int k = 0; k < 3; k++) {
        char args[64], png[64];
        snprintf(args, sizeof args, "--view %s", views[k]);
        snprintf(png, sizeof png, "noshadow_%d.png", k);
        image im = shot(160, 90, args, png);
        TL_CHECK(im.px && is_placeholder(&im));
        release(&im);
    }
}

/* The grid with --shadows: the three shadow views (the grid's last three cells) are images. */
TL_TEST(viewer_shadow_views_in_the_grid)
{
    image g = shot(640, 360, "--shadows --grid", "shadow_grid.png");
    TL_CHECK(g.px != NULL);
    for (int v = 21; g.px && v < 24; v++) {
        image c = cell(&g, v);
        printf("grid cell %d: %zu colours%s\n", v, colours(&c), is_placeholder(&c) ? " (placeholder)" : "");
        TL_CHECK(c.px && !is_placeholder(&c) && colours(&c) > 4);
        release(&c);
    }
    release(&g);
}

/* A glTF file's shadows (docs/gltf.md, "Shadows"): --shadows makes the spot over the floating box
 * cast (pixels of the floor get darker, none lighter); the light's "thinlight_shadow": true casts
 * without it (the same screenshot as the rule's); false casts nothing even with --shadows (the
 * screenshot without shadows). */
TL_TEST(viewer_gltf_shadows_rule_and_flag)
{
#ifdef TL_MAKE_SCENES
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "'%s' '%s/scenes' shadow_spot shadow_spot_cast shadow_spot_no_cast >/dev/null", TL_MAKE_SCENES,
             TL_WORK);
    TL_CHECK(run(cmd) == 0);
    static const char *const runs[4][3] = {{"shadow_spot", "", "plain.png"},
                                           {"shadow_spot", "--shadows", "rule.png"},
                                           {"shadow_spot_cast", "", "cast.png"},
                                           {"shadow_spot_no_cast", "--shadows", "no_cast.png"}};
    image im[4];
    for (int k = 0; k < 4; k++) {
        char more[900];
        /* FXAA off: it blends the box's silhouette with the floor behind, shadowed or not */
        snprintf(more, sizeof more, "'%s/scenes/%s.gltf' --fxaa off %s", TL_WORK, runs[k][0], runs[k][1]);
        im[k] = shot(160, 90, more, runs[k][2]);
        TL_CHECK(im[k].px != NULL);
    }
    if (im[0].px && im[1].px && im[2].px && im[3].px) {
        size_t n = (size_t)im[0].w * im[0].h, darker = 0, lighter = 0, cast_differs = 0, no_cast_differs = 0;
        for (size_t i = 0; i < n; i++)
            for (int c = 0; c < 3; c++) {
                int a = im[0].px[4 * i + c], b = im[1].px[4 * i + c];
                darker += b + 8 < a, lighter += b > a + 1;
                cast_differs += im[2].px[4 * i + c] != b;
                no_cast_differs += im[3].px[4 * i + c] != a;
            }
        printf("viewer-gltf-shadows: with --shadows %zu channels darker by more than 8 levels, %zu lighter; flag true "
               "vs the rule %zu channels differ, flag false with --shadows vs none %zu\n", darker, lighter, cast_differs,
               no_cast_differs);
        TL_CHECK(darker >= 100);
        TL_CHECK_EQ_U(lighter, 0);
        TL_CHECK_EQ_U(cast_differs, 0);
        TL_CHECK_EQ_U(no_cast_differs, 0);
    }
    for (int k = 0; k < 4; k++) release(&im[k]);
#else
    printf("no make_gltf_scenes in this build\n");
#endif
}
