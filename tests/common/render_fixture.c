/* The renderer tests' shared context (render_fixture.h). */
#include "render_fixture.h"

#include "context_fixture.h"
#include "tl_test.h"

#include <stdio.h>
#include <stdlib.h>

tl_context *g_ctx;

static void tl_test_log(void *user, tl_log_level level, const char *message)
{
    (void)user;
    if (level != TL_LOG_INFO) fprintf(stderr, "%s: %s\n", level == TL_LOG_ERROR ? "error" : "warning", message);
}

const tl_logger tl_test_logger = {tl_test_log, NULL};

static void destroy_context(void)
{
    tl_context_destroy(g_ctx);
    g_ctx = NULL;
}

int ensure_context(void)
{
    if (g_ctx) return 1;
    if (tl_test_context_create(64, 64, &g_ctx) != TL_OK) return 0; /* the reason is printed */
    atexit(destroy_context);
    if (!tl_test_gl_debug_install(g_ctx)) /* every context the tests use has it (GL 4.3 core) */
        fprintf(stderr, "warning: no KHR_debug: GL errors are seen only at the end of frames\n");
    return 1;
}

/* Fails the running case (unless `t` may fail) naming the step; destroys `r`; NULL. */
static tl_renderer *tl_test_renderer_failed(const tl_test_renderer_desc *t, tl_renderer *r, const char *step,
                                            tl_result res)
{
    const tl_renderer_desc *d = &t->renderer;
    fprintf(stderr, "%s: %s failed (%ux%u, mode %s): %s%s%s\n", t->may_fail ? "note" : "error", step, d->width,
            d->height, tl_render_mode_name(d->options.mode), tl_result_string(res), r ? ": " : "",
            r ? tl_renderer_last_error(r) : "");
    if (!t->may_fail) tl_test_failures++;
    tl_renderer_destroy(r);
    return NULL;
}

tl_renderer *tl_test_renderer(const tl_test_renderer_desc *t)
{
    tl_renderer_desc d = t->renderer;
    if (!d.get_proc_address) d.get_proc_address = tl_context_proc_loader;
    if (!d.get_proc_address_user) {
        if (!ensure_context()) return tl_test_renderer_failed(t, NULL, "the test context", TL_ERROR_GL);
        d.get_proc_address_user = g_ctx;
    }
    if (!d.logger.fn) d.logger = tl_test_logger;
    if (t->readable) {
        d.options.keep_targets = TL_TARGETS_ALL;
        d.options.synchronous_stats = 1;
    }
    tl_renderer *r = NULL;
    tl_result res = tl_renderer_create(&d, &r);
    if (res != TL_OK) return tl_test_renderer_failed(t, r, "tl_renderer_create", res);
    if (t->scene && (res = tl_renderer_set_scene(r, t->scene)) != TL_OK)
        return tl_test_renderer_failed(t, r, "tl_renderer_set_scene", res);
    for (size_t i = 0; i < t->pass_count; i++)
        if ((res = tl_renderer_add_pass(r, &t->passes[i])) != TL_OK)
            return tl_test_renderer_failed(t, r, "tl_renderer_add_pass", res);
    for (uint32_t f = 0; f < t->frames; f++)
        if ((res = tl_renderer_render(r, NULL, NULL)) != TL_OK)
            return tl_test_renderer_failed(t, r, "tl_renderer_render", res);
    if (t->frames && (res = tl_renderer_wait(r, NULL)) != TL_OK)
        return tl_test_renderer_failed(t, r, "tl_renderer_wait", res);
    return r;
}

tl_renderer *tl_test_render_once(const tl_scene *s, tl_renderer_desc d)
{
    d.options.keep_targets = TL_TARGETS_ALL;
    return tl_test_renderer(&(tl_test_renderer_desc){.renderer = d, .scene = s, .frames = 1, .may_fail = true});
}

float *tl_test_read_target(tl_renderer *r, tl_target_id id, size_t n)
{
    size_t size = n * 4 * sizeof(float);
    float *p = malloc(size);
    if (p && tl_renderer_read_target(r, id, p, &size) != TL_OK) {
        free(p);
        return NULL;
    }
    return p;
}
