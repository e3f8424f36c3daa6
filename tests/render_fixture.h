/* Shared by the renderer tests: one lazily created OSMesa context per test process, current for
 * every case; renderers load GL through tl_context_proc_loader with g_ctx as the user pointer. */
#ifndef TL_RENDER_FIXTURE_H
#define TL_RENDER_FIXTURE_H

#include <stdio.h>

#include "thinlight/context.h"

static tl_context *g_ctx;

/* Renderer and context failures, one line each on stderr. */
static void tl_test_log(void *user, tl_log_level level, const char *message)
{
    (void)user;
    if (level != TL_LOG_INFO) fprintf(stderr, "%s: %s\n", level == TL_LOG_ERROR ? "error" : "warning", message);
}
static const tl_logger tl_test_logger = {tl_test_log, NULL};

static int ensure_context(void)
{
    if (g_ctx) return 1;
    if (tl_context_create(&(tl_context_desc){.width = 64, .height = 64}, &g_ctx) != TL_OK) {
        fprintf(stderr, "no GL context: %s\n", tl_context_last_error(NULL));
        return 0;
    }
    return 1;
}

#endif
