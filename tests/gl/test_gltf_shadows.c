/* Shadows from a glTF file (docs/gltf.md, "Shadows"): a box floating over a floor under a spot
 * light looking straight down, written at run time (tlf_write_shadow_scene). The loader's rule
 * (tl_gltf_options.shadow_lights, the tools' --shadows) or the light's extras flag makes it cast:
 * the floor under the box is dark where the box's analytic shadow lies and untouched elsewhere;
 * without either, nothing casts and the image is the image without shadows. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_fixtures.h"
#include "render_fixture.h"
#include "tl_test.h"
#include "thinlight/io.h"

enum { W = 160, H = 90 };

/* The file `name` (a tlf_write_case name) loaded with the rule's budget (0: the flags alone). */
static tl_scene *tl__load(const char *name, uint32_t budget)
{
    char dir[1024], path[1024];
    snprintf(dir, sizeof dir, "%s/gltf_shadows_work", TL_TEST_WORK_DIR);
    if (tlf_mkdir_p(dir) || tlf_write_case(dir, name, path, sizeof path)) return NULL;
    tl_scene *s = NULL;
    tl_gltf_options o = {.logger = tl_test_logger, .shadow_lights = budget};
    return tl_scene_load_gltf(path, &o, &s) == TL_OK ? s : NULL;
}

/* The HDR luminance of `s` rendered alone (ambient off), rows bottom-up; malloc'd. */
static float *tl__render_mode(const tl_scene *s, tl_render_mode mode, uint32_t *plan_shadow_lights)
{
    tl_renderer_options o = {.mode = mode, .ambient = {-1.0f, -1.0f, -1.0f}, .synchronous_stats = 1};
    tl_renderer *r = tl_test_render_once(s, (tl_renderer_desc){.width = W, .height = H, .options = o});
    float *p = r ? tl_test_read_target(r, TL_TARGET_HDR, (size_t)W * H) : NULL;
    tl_frame_plan plan;
    if (r && tl_renderer_get_plan(r, &plan) == TL_OK) *plan_shadow_lights = plan.shadow_lights;
    tl_renderer_destroy(r);
    for (size_t i = 0; p && i < (size_t)W * H; i++) p[i] = p[4 * i] + p[4 * i + 1] + p[4 * i + 2];
    return p;
}

static float *tl__render(const tl_scene *s, uint32_t *plan_shadow_lights)
{
    return tl__render_mode(s, TL_MODE_DEFAULT, plan_shadow_lights);
}

/* Where pixel (x, y) sees the floor, from the scene's camera (the renderer's: fov_y, aspect W/H,
 * up +Y): 1 and the floor point, or 0 when the ray hits the box first or misses the floor. */
static int tl__floor_point(const tl_camera *c, uint32_t x, uint32_t y, double out[2])
{
    double f[3], up[3] = {0, 1, 0}, r[3], u[3], d[3];
    double n = 0.0;
    for (int k = 0; k < 3; k++) f[k] = (double)c->target[k] - c->position[k], n += f[k] * f[k];
    for (int k = 0; k < 3; k++) f[k] /= sqrt(n);
    r[0] = f[1] * up[2] - f[2] * up[1], r[1] = f[2] * up[0] - f[0] * up[2], r[2] = f[0] * up[1] - f[1] * up[0];
    n = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int k = 0; k < 3; k++) r[k] /= n;
    u[0] = r[1] * f[2] - r[2] * f[1], u[1] = r[2] * f[0] - r[0] * f[2], u[2] = r[0] * f[1] - r[1] * f[0];
    double t = tan(0.5 * (double)c->fov_y), sx = ((x + 0.5) / W * 2.0 - 1.0) * t * W / H, sy = ((y + 0.5) / H * 2.0 - 1.0) * t;
    for (int k = 0; k < 3; k++) d[k] = f[k] + sx * r[k] + sy * u[k];
    /* the box: slabs */
    double lo = 0.0, hi = INFINITY;
    for (int k = 0; k < 3; k++) {
        double centre = k == 1 ? TLF_SHADOW_BOX_Y : 0.0, a = centre - TLF_SHADOW_BOX_HALF, b = centre + TLF_SHADOW_BOX_HALF;
        double t0 = (a - c->position[k]) / d[k], t1 = (b - c->position[k]) / d[k];
        lo = fmax(lo, fmin(t0, t1)), hi = fmin(hi, fmax(t0, t1));
    }
    if (lo <= hi) return 0;
    if (d[1] >= 0.0) return 0;
    double s = -c->position[1] / d[1];
    out[0] = c->position[0] + s * d[0], out[1] = c->position[2] + s * d[2];
    return fabs(out[0]) < 10.0 && fabs(out[1]) < 10.0;
}

/* The box's shadow on the floor from the spot straight above: its top face (the farther from the
 * floor of its two faces across the light) projected, half size h (y_spot / (y_spot - top)). */
static double tl__shadow_half(void)
{
    double top = TLF_SHADOW_BOX_Y + TLF_SHADOW_BOX_HALF;
    return TLF_SHADOW_BOX_HALF * TLF_SHADOW_SPOT_Y / (TLF_SHADOW_SPOT_Y - top);
}

/* The term of `cast` (light casting) over `plain`: in the analytic shadow shrunk by `margin` every
 * lit floor pixel is below 0.5; beyond it grown by `margin` every one is at least 1 - 2^-10 (two
 * FP16 roundings of half a step: a shadow of exactly 1 is the same float operations). */
static void tl__check_shadow(const float *cast, const float *plain, const tl_camera *c, const char *what)
{
    /* the margin: the kernel's reach and the edge's texels (512-texel spot map over +-tan(0.6) at
     * 5 m: 1.3 cm a texel, PCF reaches 2) and half a pixel's footprint on the floor (about 4 cm) */
    const double margin = 0.1, half = tl__shadow_half();
    size_t inside = 0, dark = 0, outside = 0, changed = 0;
    float darkest_outside = 1.0f, brightest_inside = 0.0f;
    for (uint32_t y = 0; y < H; y++)
        for (uint32_t x = 0; x < W; x++) {
            size_t i = (size_t)y * W + x;
            double p[2];
            if (!tl__floor_point(c, x, y, p) || plain[i] <= 2.44e-4f) continue; /* no floor, or the spot adds nothing */
            float term = cast[i] / plain[i];
            double e = fmax(fabs(p[0]), fabs(p[1]));
            if (e < half - margin) {
                inside++, dark += term < 0.5f;
                brightest_inside = fmaxf(brightest_inside, term);
            } else if (e > half + margin) {
                outside++, changed += term < 1.0f - (float)TL_HALF_REL_STEP;
                darkest_outside = fminf(darkest_outside, term);
            }
        }
    printf("gltf-shadow %s: shadow half size %.3f m, inside %zu floor pixels (%zu below 0.5, brightest %.4f), "
           "outside %zu (%zu below 1 - 2^-10, darkest %.6f)\n", what, half, inside, dark, (double)brightest_inside,
           outside, changed, (double)darkest_outside);
    TL_CHECK(inside >= 100);
    TL_CHECK_EQ_U(dark, inside);
    TL_CHECK(outside >= 1000);
    TL_CHECK_EQ_U(changed, 0);
}

/* The rule (the tools' --shadows) makes the file's spot cast: the floor is dark in the box's
 * analytic shadow and unchanged around it; without the rule nothing casts: no shadow in the plan
 * and the image of the light without shadows. In the default mode and in visibility (its resolve
 * gates the tile lists' lights by the same shadow lookup). */
TL_TEST(gltf_shadows_rule_casts_the_box_shadow)
{
    tl_scene *rule = tl__load("shadow_spot", 8), *none = tl__load("shadow_spot", 0);
    TL_CHECK(rule && none && rule->light_count == 1 && none->light_count == 1);
    if (!rule || !none || rule->light_count != 1 || none->light_count != 1) goto done;
    TL_CHECK(rule->lights[0].shadow && !none->lights[0].shadow);
    const tl_render_mode modes[2] = {TL_MODE_DEFAULT, TL_MODE_VISIBILITY};
    for (int m = 0; m < 2; m++) {
        uint32_t with = 0, without = 1;
        float *cast = tl__render_mode(rule, modes[m], &with), *plain = tl__render_mode(none, modes[m], &without);
        TL_CHECK(cast && plain);
        TL_CHECK_EQ_U(with, 1);
        TL_CHECK_EQ_U(without, 0);
        if (cast && plain) tl__check_shadow(cast, plain, &rule->camera, m ? "rule, visibility" : "rule");
        free(cast);
        free(plain);
    }
done:
    tl_scene_destroy(rule);
    tl_scene_destroy(none);
}

/* The light's own flag: "thinlight_shadow": true casts without the rule, false never casts (even
 * with it), and a value that is not a boolean counts as absent. */
TL_TEST(gltf_shadows_extras_flag_honoured)
{
    tl_scene *plain_scene = tl__load("shadow_spot", 0);
    uint32_t planned = 9;
    float *plain = plain_scene ? tl__render(plain_scene, &planned) : NULL;
    TL_CHECK(plain && planned == 0);
    static const struct {
        const char *file;
        uint32_t budget;
        int casts;
    } cases[] = {{"shadow_spot_cast", 0, 1}, {"shadow_spot_no_cast", 8, 0}, {"shadow_spot_bad_flag", 0, 0},
                 {"shadow_spot_bad_flag", 8, 1}};
    for (size_t k = 0; plain && k < sizeof cases / sizeof cases[0]; k++) {
        tl_scene *s = tl__load(cases[k].file, cases[k].budget);
        TL_CHECK(s && s->light_count == 1);
        if (!s || s->light_count != 1) {
            tl_scene_destroy(s);
            continue;
        }
        TL_CHECK((s->lights[0].shadow != 0) == cases[k].casts);
        uint32_t lights = 9;
        float *img = tl__render(s, &lights);
        TL_CHECK(img != NULL);
        TL_CHECK_EQ_U(lights, (uint32_t)cases[k].casts);
        char what[96];
        snprintf(what, sizeof what, "%s budget %u", cases[k].file, cases[k].budget);
        if (img && cases[k].casts) tl__check_shadow(img, plain, &s->camera, what);
        if (img && !cases[k].casts) TL_CHECK(memcmp(img, plain, (size_t)W * H * sizeof(float)) == 0);
        free(img);
        tl_scene_destroy(s);
    }
    free(plain);
    tl_scene_destroy(plain_scene);
}
