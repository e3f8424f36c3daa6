/* Shared by the renderer tests: one lazily created context per test process (OSMesa, or the back
 * end THINLIGHT_TEST_CONTEXT names: context_fixture.h), current for every case; renderers load GL
 * through tl_context_proc_loader with g_ctx as the user pointer. */
#ifndef TL_RENDER_FIXTURE_H
#define TL_RENDER_FIXTURE_H

#include <stdio.h>

#include "context_fixture.h"
#include "thinlight/context.h"

static tl_context *g_ctx;

static int ensure_context(void)
{
    if (g_ctx) return 1;
    if (tl_test_context_create(64, 64, &g_ctx) != TL_OK) return 0; /* the reason is printed */
    return 1;
}

#endif
