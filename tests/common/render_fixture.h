/* Shared by the renderer tests: one lazily created OSMesa context per test process, current for
 * every case and destroyed at exit; renderers load GL through tl_context_proc_loader with g_ctx as
 * the user pointer. */
#ifndef TL_RENDER_FIXTURE_H
#define TL_RENDER_FIXTURE_H

#include "thinlight/context.h"

extern tl_context *g_ctx;

/* Renderer and context failures, one line each on stderr. */
extern const tl_logger tl_test_logger;

/* 1 when g_ctx exists (creating it on the first call), 0 after a message on stderr. */
int ensure_context(void);

#endif
