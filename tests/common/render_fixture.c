/* The renderer tests' shared context (render_fixture.h). */
#include "render_fixture.h"

#include "context_fixture.h"

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

tl_renderer *tl_test_render_once(const tl_scene *s, tl_renderer_desc d)
{
    if (!ensure_context()) return NULL;
    d.options.keep_targets = TL_TARGETS_ALL;
    d.get_proc_address = tl_context_proc_loader;
    d.get_proc_address_user = g_ctx;
    d.logger = tl_test_logger;
    tl_renderer *r = NULL;
    if (tl_renderer_create(&d, &r) != TL_OK) return NULL;
    if (tl_renderer_set_scene(r, s) != TL_OK || tl_renderer_render(r, NULL, NULL) != TL_OK ||
        tl_renderer_wait(r, NULL) != TL_OK) {
        tl_renderer_destroy(r);
        return NULL;
    }
    return r;
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
