/* The context check's API (issue 25): tl_context_is_current, which a renderer loading GL through
 * tl_context_proc_loader asks before each call, and tl_renderer_desc.is_current, an application's
 * own answer. */
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include "render_room.h"
#include "tl_test.h"

static void *is_current_elsewhere(void *arg)
{
    int *answer = (int *)arg;
    *answer = tl_context_is_current(g_ctx);
    return NULL;
}

/* Current on the thread that made it current, on no other, and not after a release. */
TL_TEST(context_is_current_follows_make_current)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    TL_CHECK(tl_context_is_current(g_ctx));
    TL_CHECK(!tl_context_is_current(NULL));
    int elsewhere = -1;
    pthread_t th;
    TL_CHECK(pthread_create(&th, NULL, is_current_elsewhere, &elsewhere) == 0);
    pthread_join(th, NULL);
    TL_CHECK(elsewhere == 0);
    TL_CHECK(tl_context_make_current(NULL) == TL_OK);
    TL_CHECK(!tl_context_is_current(g_ctx));
    TL_CHECK(tl_context_make_current(g_ctx) == TL_OK);
    TL_CHECK(tl_context_is_current(g_ctx));
}

typedef struct answer {
    int current;
    unsigned long asked;
} answer;

static int app_is_current(void *user)
{
    answer *a = (answer *)user;
    a->asked++;
    return a->current;
}

static tl_gl_function app_loader(void *user, const char *name)
{
    (void)user;
    return tl_context_get_proc_address(g_ctx, name);
}

/* The descriptor's callback is the answer: "no" fails create, and every call that uses GL, with
 * TL_ERROR_GL; "yes" renders. */
TL_TEST(renderer_is_current_callback_decides)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    answer a = {0, 0};
    tl_renderer_desc d = {.width = 32, .height = 32, .get_proc_address = app_loader, .get_proc_address_user = &a,
                          .is_current = app_is_current};
    tl_renderer *r = NULL;
    TL_CHECK(tl_renderer_create(&d, &r) == TL_ERROR_GL && !r && a.asked == 1);
    a.current = 1;
    TL_CHECK(tl_renderer_create(&d, &r) == TL_OK && r);
    if (!r) return;
    static test_scene t;
    build_room(&t);
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    a.current = 0;
    unsigned long before = a.asked;
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_ERROR_GL);
    TL_CHECK(strstr(tl_renderer_last_error(r), "tl_renderer_render: the renderer's GL context is not current") != NULL);
    TL_CHECK(tl_renderer_resize(r, 16, 16) == TL_ERROR_GL);
    TL_CHECK(a.asked == before + 2);
    tl_renderer_destroy(r); /* refused: frees nothing */
    a.current = 1;
    uint32_t w = 0, h = 0;
    tl_renderer_get_size(r, &w, &h);
    TL_CHECK(w == 32 && h == 32);
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    tl_renderer_destroy(r);
}
