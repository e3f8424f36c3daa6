/* thinlight-shadows-report: the images of docs/shadows.md, into DIR (default docs/img):
 *   shadows_crypt.png            the crypt with its moonlight and braziers casting (thin-lpp);
 *   shadows_truth_brazier_d24.png, shadows_truth_brazier_d32f.png
 *                                the nearest brazier's shadow term in thin-lpp (left) beside the
 *                                Embree truth (right: white lit, grey shadowed, dark blue facing
 *                                away; dimmed where the light adds nothing, which is not compared)
 *                                with the render's acne red and its leaks green (the penumbra band
 *                                the figures leave out included);
 *   shadows_stiff_plane.png      the same for the stiff scene's grazing plane under the
 *                                directional light 10 degrees above it (reversed D32F).
 * Built with the shadow tests (tests/gl/CMakeLists.txt: it uses their scenes and the ray tracer, so
 * only where Embree 3 is found) and THINLIGHT_WITH_IO (PNG); the term is the bench's
 * (bench_shadows_term.c). Prints each image's
 * wrong-state figures. Exit 0, 1 (a render or a write failed, one line), 2 (bad usage). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_shadows.h"
#include "shadow_rt.h"
#include "shadow_scenes.h"
#include "tool_gl.h"
#include "tool_util.h"

#define TOOL "thinlight-shadows-report"
enum { W = 640, H = 360, BAND = 2 };

/* term | truth as RGB, rows bottom up (tl_image_desc.bottom_up): the test's comparison image. */
static void compose(const float *term, const uint8_t *state, uint32_t w, uint32_t h, uint8_t *rgb)
{
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < 2 * w; x++) {
            size_t i = (size_t)y * w + x % w;
            uint8_t *px = &rgb[((size_t)y * 2 * w + x) * 3];
            px[0] = px[1] = 0, px[2] = 64; /* the light adds nothing here */
            if (x < w && term[i] >= 0.0f) px[0] = px[1] = px[2] = (uint8_t)(term[i] * 255.0f);
            if (x < w) continue;
            uint8_t s = state[i], v = s == TL_RT_LIT ? 255 : s == TL_RT_SHADOWED ? 96 : 0;
            px[0] = px[1] = px[2] = term[i] >= 0.0f ? v : v / 4; /* dim beyond the light's reach */
            if (s == TL_RT_AWAY) px[2] = 128;
            if (term[i] >= 0.0f && s == TL_RT_LIT && term[i] < 0.5f) px[0] = 255, px[1] = px[2] = 0;
            if (term[i] >= 0.0f && s == TL_RT_SHADOWED && term[i] >= 0.5f) px[1] = 255, px[0] = px[2] = 0;
        }
}

static int write_png(const char *dir, const char *name, uint32_t w, uint32_t h, const uint8_t *rgb, uint32_t channels)
{
    char *path = tl_tool_strf("%s/%s", dir, name);
    tl_image_desc d = {.width = w, .height = h, .channels = channels, .type = TL_PIXEL_U8, .bottom_up = 1};
    int err = !path || tl_tool_write_image(TOOL, path, &d, rgb);
    if (!err) printf("wrote %s\n", path);
    free(path);
    return err;
}

/* A renderer of `scene` with `o` on ctx, W x H, after one frame; NULL after one line. */
static tl_renderer *renderer(tl_context *ctx, const tl_scene *scene, tl_renderer_options o)
{
    tl_renderer *r = NULL;
    tl_renderer_desc d = {.width = W, .height = H, .options = o, .get_proc_address = tl_context_proc_loader,
                          .get_proc_address_user = ctx, .logger = tl_tool_logger(TOOL)};
    if (tl_renderer_create(&d, &r) == TL_OK && tl_renderer_set_scene(r, scene) == TL_OK &&
        tl_renderer_render(r, NULL, NULL) == TL_OK && tl_renderer_wait(r, NULL) == TL_OK)
        return r;
    tl_renderer_destroy(r);
    return NULL;
}

/* One light of a case against the truth with thin-lpp light volumes and `depth`: prints, writes. */
static int comparison(tl_context *ctx, const char *dir, const char *name, const tl_shadow_case *c,
                      const tl_light *light, tl_depth_format depth)
{
    tl_renderer_options o = {.mode = TL_MODE_THIN_LPP, .depth_format = depth, .ambient = {-1.0f, -1.0f, -1.0f},
                             .keep_targets = TL_TARGET_BIT(TL_TARGET_HDR)};
    tl_shadow_rt *rt = tl_shadow_rt_create(c->scene);
    tl_renderer *r = renderer(ctx, c->scene, o);
    uint8_t *state = malloc((size_t)W * H), *rgb = malloc((size_t)W * H * 6);
    uint32_t *object = malloc((size_t)W * H * sizeof *object);
    float *term = r ? bench_shadow_term(r, light, (size_t)W * H) : NULL;
    int err = !rt || !state || !rgb || !object || !term;
    if (err) tl_tool_fail(TOOL, "%s: the truth or the render failed", name);
    if (!err) {
        tl_shadow_rt_truth(rt, &c->scene->camera, W, H, light, state, object);
        tl_shadow_error e = tl_shadow_rt_compare(state, object, term, W, H, BAND);
        printf("%s: %ux%u, counted %zu, acne %zu, leaks %zu, wrong %.4f %%\n", name, W, H, e.counted, e.acne, e.leaks,
               100.0 * e.wrong);
        compose(term, state, W, H, rgb);
        err = write_png(dir, name, 2 * W, H, rgb, 3);
    }
    tl_renderer_destroy(r);
    tl_shadow_rt_destroy(rt);
    free(state), free(rgb), free(object), free(term);
    return err;
}

/* The crypt as thinlight-render default --shadows draws it (thin-lpp). */
static int crypt_image(tl_context *ctx, const char *dir)
{
    tl_scene *s = NULL;
    if (tl_scene_create_default(&(tl_default_scene_desc){.shadows = 1}, &s) != TL_OK) {
        tl_tool_fail(TOOL, "the crypt could not be built");
        return 1;
    }
    tl_renderer *r = renderer(ctx, s, (tl_renderer_options){.mode = TL_MODE_THIN_LPP});
    uint8_t *rgba = malloc((size_t)W * H * 4);
    int err = !r || !rgba || tl_renderer_read_output(r, rgba, &(size_t){(size_t)W * H * 4}) != TL_OK;
    if (err) tl_tool_fail(TOOL, "the crypt's render failed");
    for (size_t i = 0; !err && i < (size_t)W * H; i++) memmove(&rgba[3 * i], &rgba[4 * i], 3);
    if (!err) err = write_png(dir, "shadows_crypt.png", W, H, rgba, 3);
    tl_renderer_destroy(r);
    tl_scene_destroy(s);
    free(rgba);
    return err;
}

int main(int argc, char **argv)
{
    if (argc > 2 || (argc == 2 && (argv[1][0] == '-' || !argv[1][0]))) {
        fprintf(stderr, "usage: " TOOL " [DIR]   (writes the PNGs of docs/shadows.md; default docs/img)\n");
        return 2;
    }
    const char *dir = argc == 2 ? argv[1] : "docs/img";
    if (!tl_tool_is_dir(dir)) {
        tl_tool_fail(TOOL, "'%s' is not a directory", dir);
        return 1;
    }
    tl_context *ctx = NULL;
    if (tl_tool_context_open(TOOL, &(tl_tool_context_options){0}, W, H, &ctx)) return 1;
    tl_shadow_case crypt = {0}, stiff = {0};
    int err = !tl_shadow_crypt_case(&crypt, 0) || !tl_shadow_stiff_case(&stiff) || crypt.light_count < 2;
    if (err) tl_tool_fail(TOOL, "the shadow scenes could not be built");
    if (!err) err = crypt_image(ctx, dir);
    /* lights[1]: the brazier nearest the camera (shadow_scenes.c) */
    if (!err)
        err = comparison(ctx, dir, "shadows_truth_brazier_d24.png", &crypt, &crypt.lights[1], TL_DEPTH_FORMAT_D24);
    if (!err)
        err = comparison(ctx, dir, "shadows_truth_brazier_d32f.png", &crypt, &crypt.lights[1],
                         TL_DEPTH_FORMAT_D32F_REVERSED);
    if (!err)
        err = comparison(ctx, dir, "shadows_stiff_plane.png", &stiff, &stiff.lights[0], TL_DEPTH_FORMAT_D32F_REVERSED);
    tl_shadow_case_free(&crypt);
    tl_shadow_case_free(&stiff);
    tl_context_destroy(ctx);
    return err ? 1 : 0;
}
