/* What the renderer refuses says exactly what is wrong (issue 38): every option out of range names
 * the field, the value and the range (one table row per option, so a new option is one line); a
 * scene's bad object names the one field that fails; an MSAA count over the context's names
 * options.msaa; and reading the output before a frame drew it is refused, not zero bytes. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_room.h"
#include "tl_test.h"

#define W 64
#define H 64

typedef struct said {
    int errors;
    char last[512];
} said;

static void said_log(void *user, tl_log_level level, const char *message)
{
    said *s = (said *)user;
    if (level != TL_LOG_ERROR) return;
    s->errors++;
    snprintf(s->last, sizeof s->last, "%s", message);
}

static tl_renderer *renderer(said *log)
{
    tl_renderer_desc d = {.width = W, .height = H, .get_proc_address = tl_context_proc_loader,
                          .get_proc_address_user = g_ctx, .logger = {said_log, log}};
    tl_renderer *r = NULL;
    TL_CHECK(tl_renderer_create(&d, &r) == TL_OK);
    return r;
}

static void lit_room(test_scene *t)
{
    build_room(t);
    t->lights[0] = (tl_light){TL_LIGHT_POINT, {3, 6, -2}, {0, 0, 0}, {60, 55, 50}, 30, 0, 0, 0, 0};
    t->s.light_count = 1;
}

/* ---- reading the output before a frame ---------------------------------------------------------- */

/* read_output before render drew a frame at the renderer's size (none yet, only render_to, or a
 * resize since) is TL_ERROR_INVALID_ARGUMENT saying so, and the buffer is left alone; after a
 * render it reads. Before: TL_OK and whatever the fresh target held. */
TL_TEST(renderer_read_output_before_any_frame_refused)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    said log = {0};
    tl_renderer *r = renderer(&log);
    if (!r) return;
    static test_scene t;
    lit_room(&t);
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
    static uint8_t px[W * H * 4], blank[W * H * 4];
    memset(px, 0xAB, sizeof px);
    memset(blank, 0xAB, sizeof blank);
    size_t size = 0;
    TL_CHECK(tl_renderer_read_output(r, NULL, &size) == TL_OK && size == sizeof px); /* asking is fine */
    const char *why = "tl_renderer_read_output: no frame was rendered into the output at 64x64";
    int refused = 0;
    tl_result res = tl_renderer_read_output(r, px, &size);
    refused += res == TL_ERROR_INVALID_ARGUMENT && strstr(log.last, why) && memcmp(px, blank, sizeof px) == 0;
    printf("  before any frame: %s \"%s\"\n", tl_result_string(res), log.last);
    /* render_to draws into the caller's framebuffer (0: OSMesa's), not the output */
    TL_CHECK(tl_renderer_render_to(r, NULL, &(tl_render_output){0}, NULL) == TL_OK);
    res = tl_renderer_read_output(r, px, &size);
    refused += res == TL_ERROR_INVALID_ARGUMENT && strstr(log.last, why) && memcmp(px, blank, sizeof px) == 0;
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_read_output(r, px, &size) == TL_OK && memcmp(px, blank, sizeof px) != 0);
    TL_CHECK(tl_renderer_resize(r, 32, 32) == TL_OK);
    memset(px, 0xAB, sizeof px);
    size = sizeof px;
    res = tl_renderer_read_output(r, px, &size);
    refused += res == TL_ERROR_INVALID_ARGUMENT && strstr(log.last, "no frame was rendered into the output at 32x32") &&
               memcmp(px, blank, sizeof px) == 0;
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_read_output(r, px, &size) == TL_OK && size == (size_t)32 * 32 * 4);
    printf("  %d of 3 reads refused (before a frame, after render_to only, after a resize)\n", refused);
    TL_CHECK_EQ_U(refused, 3);
    tl_renderer_destroy(r);
}
