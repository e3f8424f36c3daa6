/* Shared by the renderer tests: one lazily created OSMesa context per test process, current for
 * every case and destroyed at exit; renderers load GL through tl_context_proc_loader with g_ctx as
 * the user pointer. */
#ifndef TL_RENDER_FIXTURE_H
#define TL_RENDER_FIXTURE_H

#include "thinlight/context.h"
#include "thinlight/renderer.h"

#include <stddef.h>

extern tl_context *g_ctx;

/* Renderer and context failures, one line each on stderr. */
extern const tl_logger tl_test_logger;

/* 1 when g_ctx exists (creating it on the first call, with the GL debug callback below), 0 after
 * a message on stderr. */
int ensure_context(void);

/* A renderer on g_ctx for `d` (every target kept, g_ctx's loader, the test logger) with scene `s`
 * set and one frame rendered and waited for; NULL when any step fails (its message logged). */
tl_renderer *tl_test_render_once(const tl_scene *s, tl_renderer_desc d);
/* The RGBA float pixels (n of them, rows bottom-up) of a target, malloc'd; NULL when it cannot be
 * read. */
float *tl_test_read_target(tl_renderer *r, tl_target_id id, size_t n);

/* ---- GL errors (gl_debug.c) ------------------------------------------------------------------
 * On g_ctx a synchronous KHR_debug callback follows the debug groups (the renderer pushes one per
 * pass, named as in the plan) and turns every GL error and every high-severity message into a
 * failure of the running case: one line on stderr, "GL error in pass 'NAME': message" (or
 * "outside any pass"), and tl_test_failures + 1. */
#define TL_TEST_GL_ERROR_SIZE 512

/* Installs the callback on `ctx` (current); 1, or 0 when the context has no KHR_debug. */
int tl_test_gl_debug_install(tl_context *ctx);
/* Whether the callback is installed on g_ctx. */
int tl_test_gl_debug_active(void);
/* The last error line the callback made ("" before any). */
const char *tl_test_gl_last_error(void);

/* Errors a case provokes on purpose: with capture on, they are counted here instead of failing. */
typedef struct tl_test_gl_errors {
    unsigned count;
    char first[TL_TEST_GL_ERROR_SIZE]; /* the first one's line */
} tl_test_gl_errors;
/* Starts capturing into `into` (zeroed here); NULL: errors fail the case again. */
void tl_test_gl_errors_capture(tl_test_gl_errors *into);

#endif
