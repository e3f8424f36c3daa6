/* The renderer tests' shared context (render_fixture.h). */
#include "render_fixture.h"

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
    if (tl_context_create(&(tl_context_desc){.width = 64, .height = 64}, &g_ctx) != TL_OK) {
        fprintf(stderr, "no GL context: %s\n", tl_context_last_error(NULL));
        return 0;
    }
    atexit(destroy_context);
    return 1;
}
