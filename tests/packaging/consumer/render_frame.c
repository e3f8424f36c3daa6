/* Renders one frame headless through an installed libthinlight (OSMesa context, built-in scene,
 * 160x90, 8 point lights) and checks it: no NaN or Inf in the HDR target, and a mean luma of the
 * output that is neither black nor white. The context is made with a counting allocator and a
 * logger, which must see every allocation freed and every failure. Exit 0 when all is well. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "thinlight/context.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"

#define W 160u
#define H 90u

typedef struct counts {
    size_t allocs, frees, logged;
    char last[512];
} counts;

static void *count_alloc(size_t size, void *user)
{
    ((counts *)user)->allocs++;
    return malloc(size);
}

static void count_free(void *ptr, void *user)
{
    ((counts *)user)->frees++;
    free(ptr);
}

static void count_log(void *user, tl_log_level level, const char *message)
{
    counts *c = user;
    if (level == TL_LOG_ERROR) c->logged++;
    snprintf(c->last, sizeof c->last, "%s", message);
}

/* The context's allocator and logger: every failure logged, every allocation freed. */
static int check_context_allocator_and_logger(void)
{
    counts c = {0};
    tl_context *ctx = NULL;
    tl_context_desc desc = {.width = 8, .height = 8, .allocator = {count_alloc, count_free, &c},
                            .logger = {count_log, &c}};
    int ok = 1;
    desc.gl_major = 2; /* below 3.3: refused before anything is allocated */
    if (tl_context_create(&desc, &ctx) != TL_ERROR_INVALID_ARGUMENT || ctx || c.logged != 1 || !c.last[0]) {
        fprintf(stderr, "a refused version was not reported through the logger\n");
        ok = 0;
    }
    desc.gl_major = 0;
    desc.allocator.free = NULL; /* half an allocator */
    if (tl_context_create(&desc, &ctx) != TL_ERROR_INVALID_ARGUMENT || c.logged != 2) {
        fprintf(stderr, "an allocator without free was accepted\n");
        ok = 0;
    }
    desc.allocator.free = count_free;
    tl_result r = tl_context_create(&desc, &ctx);
    if (r != TL_OK) {
        fprintf(stderr, "context with an allocator: %s: %s\n", tl_result_string(r), c.last);
        return 0;
    }
    tl_context_destroy(ctx);
    if (c.allocs == 0 || c.allocs != c.frees) {
        fprintf(stderr, "context allocator: %zu allocations, %zu frees\n", c.allocs, c.frees);
        ok = 0;
    }
    printf("context allocator: %zu allocations, all freed; %zu failures logged\n", c.allocs, c.logged);
    return ok;
}

static void keep_error(void *user, tl_log_level level, const char *message)
{
    if (level == TL_LOG_ERROR) snprintf((char *)user, 256, "%s", message);
}

int main(void)
{
    tl_context *ctx = NULL;
    tl_scene *scene = NULL;
    tl_renderer *r = NULL;
    char error[256] = "";
    static uint8_t rgba[W * H * 4];
    static float hdr[W * H * 4];
    int ok = 0;

    counts c = {0};
    tl_result res = tl_context_create(&(tl_context_desc){.width = W, .height = H, .logger = {count_log, &c}}, &ctx);
    if (res != TL_OK) {
        fprintf(stderr, "context: %s: %s\n", tl_result_string(res), c.last);
        return 1;
    }
    res = tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 8, .detail = 1}, &scene);
    if (res == TL_OK)
        res = tl_renderer_create(&(tl_renderer_desc){.width = W, .height = H,
                                                     .options.keep_targets = TL_TARGET_BIT(TL_TARGET_HDR),
                                                     .get_proc_address = tl_context_proc_loader,
                                                     .get_proc_address_user = ctx,
                                                     .logger = {keep_error, error}},
                                 &r);
    if (res == TL_OK) res = tl_renderer_set_scene(r, scene);
    if (res == TL_OK) res = tl_renderer_render(r, NULL, NULL);
    if (res == TL_OK) res = tl_renderer_read_output(r, rgba, &(size_t){sizeof rgba});
    if (res == TL_OK) res = tl_renderer_read_target(r, TL_TARGET_HDR, hdr, &(size_t){sizeof hdr});
    if (res != TL_OK) {
        fprintf(stderr, "render: %s: %s\n", tl_result_string(res), r ? tl_renderer_last_error(r) : error);
    } else {
        size_t nonfinite = 0;
        double luma = 0.0;
        for (size_t i = 0; i < (size_t)W * H; i++) {
            for (size_t c = 0; c < 4; c++) nonfinite += !isfinite(hdr[i * 4 + c]);
            luma += (0.2126 * rgba[i * 4] + 0.7152 * rgba[i * 4 + 1] + 0.0722 * rgba[i * 4 + 2]) / 255.0;
        }
        luma /= (double)W * H;
        ok = nonfinite == 0 && luma > 0.01 && luma < 0.9;
        printf("%ux%u frame: mean luma %.4f, %zu non-finite HDR values: %s\n", W, H, luma, nonfinite,
               ok ? "ok" : "FAILED");
    }
    tl_renderer_destroy(r);
    tl_scene_destroy(scene);
    tl_context_destroy(ctx);
    if (!check_context_allocator_and_logger()) ok = 0;
    return ok ? 0 : 1;
}
