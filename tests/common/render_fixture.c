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
