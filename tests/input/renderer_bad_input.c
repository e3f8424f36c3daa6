/* The renderer refuses bad descriptors and bad scenes with a result and a message (no crash,
 * nothing drawn from them). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "render_room.h"
#include "tl_test.h"

static void capture_log(void *user, tl_log_level level, const char *message)
{
    if (level == TL_LOG_ERROR) snprintf((char *)user, 512, "%s", message);
}

TL_TEST(renderer_bad_input)
{
    TL_CHECK(ensure_context());
    if (!g_ctx) return;
    tl_renderer *r = NULL;
    char err[512] = "";
    TL_CHECK(tl_renderer_create(NULL, &r) == TL_ERROR_INVALID_ARGUMENT && !r);
    /* a failing create has no object: its message goes to the descriptor's logger */
    tl_renderer_desc d = {.width = 100000, .height = 10, .get_proc_address = tl_context_proc_loader, .get_proc_address_user = g_ctx,
                          .logger = {capture_log, err}};
    TL_CHECK(tl_renderer_create(&d, &r) == TL_ERROR_LIMIT && !r && strstr(err, "100000"));
    r = tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = 32, .height = 32, .options = {.depth_format = TL_DEPTH_FORMAT_D24, .fxaa = TL_FXAA_OFF}},
        .readable = true});
    if (!r) return;
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_ERROR_INVALID_ARGUMENT); /* no scene yet */
    test_scene t;
    build_room(&t);
    t.idx[5] = 100000; /* index out of range */
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_ERROR_INVALID_ARGUMENT);
    build_room(&t);
    t.lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {NAN, 0, 0}, .direction = {0, -1, 0},
                             .color = {1, 1, 1}, .radius = 2};
    t.s.light_count = 1;
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(strlen(tl_renderer_last_error(r)) > 0);
    tl_renderer_destroy(r);
}
