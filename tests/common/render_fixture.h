/* Shared by the renderer tests: one lazily created OSMesa context per test process, current for
 * every case and destroyed at exit, and the factory of the renderers on it (tl_test_renderer). */
#ifndef TL_RENDER_FIXTURE_H
#define TL_RENDER_FIXTURE_H

#include "thinlight/context.h"
#include "thinlight/renderer.h"

#include <stdbool.h>
#include <stddef.h>

extern tl_context *g_ctx;

/* Renderer and context failures, one line each on stderr. */
extern const tl_logger tl_test_logger;

/* 1 when g_ctx exists (creating it on the first call, with the GL debug callback below), 0 after
 * a message on stderr. */
int ensure_context(void);

/* ---- the renderer factory ----------------------------------------------------------------------
 * Every renderer a test needs for its case comes from here (a case about tl_renderer_create itself
 * calls it). What the test asks for; zero is the default in every field. */
typedef struct tl_test_renderer_desc {
    /* Size, options, allocator and limits as tl_renderer_create takes them. Zero get_proc_address:
     * tl_context_proc_loader; zero get_proc_address_user: g_ctx (created on the first call); zero
     * logger: tl_test_logger. */
    tl_renderer_desc renderer;
    const tl_scene *scene;          /* given to set_scene after create (NULL: none) */
    const tl_app_pass_desc *passes; /* pass_count application passes, added after the scene */
    size_t pass_count;
    uint32_t frames;                /* frames rendered with the scene's camera, then waited for */
    bool readable;                  /* every target kept and synchronous statistics (options.keep_targets =
                                     * TL_TARGETS_ALL, options.synchronous_stats = 1): each frame's targets
                                     * and figures can be read after it */
    bool may_fail;                  /* a failed step returns NULL without failing the running case */
} tl_test_renderer_desc;

/* The renderer `t` describes; NULL when a step failed, after a line on stderr naming the step (and,
 * unless t->may_fail, a failure of the running case). */
tl_renderer *tl_test_renderer(const tl_test_renderer_desc *t);
/* tl_test_renderer for `d` with every target kept and one frame of `s` rendered and waited for;
 * NULL (after the note) when a step fails, for the caller to check. */
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
