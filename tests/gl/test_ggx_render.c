/* The lighting models in rendered frames (issue 13): ambient as a parameter, GGX in every mode
 * and light strategy against the double-precision reference (tests/common/reference) pixel by
 * pixel, the light pre-pass's two specular layouts against fat, and extreme cases. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ggx_scene.h"
#include "render_fixture.h"
#include "tl_test.h"

#define W 160
#define H 120

typedef struct frame {
    float *hdr, *pos; /* W x H x 4; pos only when asked (fat) */
} frame;

static tl_renderer *make(tl_renderer_desc d)
{
    if (!ensure_context()) return NULL;
    d.width = W;
    d.height = H;
    d.fxaa = TL_FXAA_OFF;
    d.keep_targets = TL_TARGETS_ALL;
    d.synchronous_stats = 1;
    d.get_proc_address = tl_context_proc_loader;
    d.get_proc_address_user = g_ctx;
    d.logger = tl_test_logger;
    tl_renderer *r = NULL;
    tl_renderer_create(&d, &r);
    return r;
}

static float *read_target(tl_renderer *r, tl_target_id t)
{
    size_t size = (size_t)W * H * 4 * sizeof(float);
    float *buf = malloc(size);
    if (buf && tl_renderer_read_target(r, t, buf, &size) != TL_OK) {
        free(buf);
        buf = NULL;
    }
    return buf;
}

/* Renders the scene once; 0 after a failed check. */
static int render(tl_renderer_desc d, const tl_scene *s, frame *f)
{
    memset(f, 0, sizeof *f);
    tl_renderer *r = make(d);
    TL_CHECK(r != NULL);
    if (!r) return 0;
    int ok = tl_renderer_set_scene(r, s) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK &&
             tl_renderer_wait(r, NULL) == TL_OK;
    TL_CHECK(ok);
    if (ok) {
        f->hdr = read_target(r, TL_TARGET_HDR);
        if (d.mode == TL_MODE_FAT) f->pos = read_target(r, TL_TARGET_FAT_POSITION);
    }
    tl_renderer_destroy(r);
    TL_CHECK(f->hdr != NULL);
    return ok && f->hdr;
}

static void frame_free(frame *f)
{
    free(f->hdr);
    free(f->pos);
}

/* ---- ambient as a parameter ------------------------------------------------------------------ */

/* No lights, no emission: HDR is albedo * ambient exactly (to FP16), the scene's ambient by
 * default, the descriptor's when set, and exactly 0 when asked for with negative components. */
TL_TEST(ambient_parameter_scene_default_override_and_zero)
{
    ggx_scene *g = malloc(sizeof *g);
    ggx_scene_build(g);
    g->s.light_count = 0;
    const float asked[3][3] = {{0, 0, 0}, {0.25f, 0.5f, 1.0f}, {-1, -1, -1}};
    const double expect[3][3] = {{0.03, 0.03, 0.03}, {0.25, 0.5, 1.0}, {0, 0, 0}};
    for (int m = TL_MODE_THIN_LPP; m < TL_MODE_COUNT_; m++)
        for (int c = 0; c < 3; c++) {
            tl_renderer_desc d = {.mode = (tl_render_mode)m};
            memcpy(d.ambient, asked[c], sizeof d.ambient);
            frame f;
            if (!render(d, &g->s, &f)) continue;
            /* the plane's pixel in the bottom row centre: albedo 0.5 */
            const float *px = &f.hdr[(size_t)(2 * W + W / 2) * 4];
            for (int k = 0; k < 3; k++) {
                double want = 0.5 * expect[c][k];
                TL_CHECK_LE(fabs(px[k] - want), want * TL_HALF_REL_STEP * 2 + 1e-7);
            }
            frame_free(&f);
        }
    free(g);
}

TL_TEST(ambient_parameter_not_finite_is_refused)
{
    if (!ensure_context()) {
        TL_CHECK(0);
        return;
    }
    tl_renderer_desc d = {.width = 8, .height = 8, .get_proc_address = tl_context_proc_loader,
                          .get_proc_address_user = g_ctx, .ambient = {0, NAN, 0}};
    tl_renderer *r = (tl_renderer *)&d;
    TL_CHECK(tl_renderer_create(&d, &r) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(r == NULL);
}
