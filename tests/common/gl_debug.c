/* GL error discipline for the renderer tests (render_fixture.h): a KHR_debug callback, synchronous,
 * on the test's context. It follows the debug groups the renderer pushes around every pass (their
 * push and pop messages carry the pass name), so a GL error or a high-severity message fails the
 * running case with one line naming the pass it happened in. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "render_fixture.h"
#include "tl_test.h"

/* The KHR_debug names this file needs (GL 4.3 core values), without a GL header. */
typedef unsigned int tl_glenum;
typedef void (*tl_gl_debug_proc)(tl_glenum source, tl_glenum type, unsigned int id, tl_glenum severity, int length,
                                 const char *message, const void *user);
enum {
    TL_GL_DONT_CARE = 0x1100,
    TL_GL_DEBUG_OUTPUT_SYNCHRONOUS = 0x8242,
    TL_GL_DEBUG_TYPE_ERROR = 0x824C,
    TL_GL_DEBUG_TYPE_PUSH_GROUP = 0x8269,
    TL_GL_DEBUG_TYPE_POP_GROUP = 0x826A,
    TL_GL_DEBUG_SEVERITY_HIGH = 0x9146,
    TL_GL_DEBUG_OUTPUT = 0x92E0,
};

#define TL_GL_GROUP_DEPTH 16
#define TL_GL_GROUP_NAME 64

/* The one context's debug state: the test process has one thread and one context (g_ctx). */
typedef struct tl_gl_debug {
    char groups[TL_GL_GROUP_DEPTH][TL_GL_GROUP_NAME];
    int depth; /* may pass TL_GL_GROUP_DEPTH: deeper names are not kept */
    int active;
    tl_test_gl_errors *capture;
    char last[TL_TEST_GL_ERROR_SIZE];
} tl_gl_debug;

static tl_gl_debug g_gl_debug;

static const char *tl_gl_current_pass(const tl_gl_debug *d)
{
    if (d->depth <= 0) return NULL;
    return d->groups[d->depth <= TL_GL_GROUP_DEPTH ? d->depth - 1 : TL_GL_GROUP_DEPTH - 1];
}

static void tl_gl_message(tl_glenum source, tl_glenum type, unsigned int id, tl_glenum severity, int length,
                          const char *message, const void *user)
{
    (void)source, (void)id;
    tl_gl_debug *d = (tl_gl_debug *)(uintptr_t)user;
    size_t n = length < 0 ? strlen(message) : (size_t)length;
    if (type == TL_GL_DEBUG_TYPE_PUSH_GROUP) {
        if (d->depth < TL_GL_GROUP_DEPTH)
            snprintf(d->groups[d->depth], TL_GL_GROUP_NAME, "%.*s", (int)(n < TL_GL_GROUP_NAME ? n : TL_GL_GROUP_NAME - 1), message);
        d->depth++;
        return;
    }
    if (type == TL_GL_DEBUG_TYPE_POP_GROUP) {
        if (d->depth > 0) d->depth--;
        return;
    }
    if (type != TL_GL_DEBUG_TYPE_ERROR && severity != TL_GL_DEBUG_SEVERITY_HIGH) return;
    const char *pass = tl_gl_current_pass(d);
    snprintf(d->last, sizeof d->last, "GL %s %s%s%s: %.*s", type == TL_GL_DEBUG_TYPE_ERROR ? "error" : "high-severity message",
             pass ? "in pass '" : "outside any pass", pass ? pass : "", pass ? "'" : "", (int)n, message);
    if (d->capture) {
        if (!d->capture->count) snprintf(d->capture->first, sizeof d->capture->first, "%s", d->last);
        d->capture->count++;
        return;
    }
    fprintf(stderr, "%s\n", d->last);
    tl_test_failures++;
}

int tl_test_gl_debug_install(tl_context *ctx)
{
    typedef void (*enable_fn)(tl_glenum cap);
    typedef void (*callback_fn)(tl_gl_debug_proc fn, const void *user);
    typedef void (*control_fn)(tl_glenum source, tl_glenum type, tl_glenum severity, int count, const unsigned int *ids,
                               unsigned char enabled);
    enable_fn enable = (enable_fn)tl_context_proc_loader(ctx, "glEnable");
    callback_fn callback = (callback_fn)tl_context_proc_loader(ctx, "glDebugMessageCallback");
    control_fn control = (control_fn)tl_context_proc_loader(ctx, "glDebugMessageControl");
    memset(&g_gl_debug, 0, sizeof g_gl_debug);
    if (!enable || !callback || !control) return 0;
    enable(TL_GL_DEBUG_OUTPUT);
    enable(TL_GL_DEBUG_OUTPUT_SYNCHRONOUS); /* the callback runs inside the call that failed */
    control(TL_GL_DONT_CARE, TL_GL_DONT_CARE, TL_GL_DONT_CARE, 0, NULL, 1); /* group messages are off by default */
    callback(tl_gl_message, &g_gl_debug);
    g_gl_debug.active = 1;
    return 1;
}

int tl_test_gl_debug_active(void) { return g_gl_debug.active; }

void tl_test_gl_errors_capture(tl_test_gl_errors *into)
{
    if (into) memset(into, 0, sizeof *into);
    g_gl_debug.capture = into;
}

const char *tl_test_gl_last_error(void) { return g_gl_debug.last; }
