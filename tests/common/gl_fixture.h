/* Shared by the GL tests: a headless 4.5 core context (OSMesa, or the back end THINLIGHT_TEST_CONTEXT
 * names: context_fixture.h) with glad loaded through it. */
#ifndef TL_GL_FIXTURE_H
#define TL_GL_FIXTURE_H

#include <stdbool.h>
#include <string.h>

#include "gl/gl.h"
#include "context_fixture.h"
#include "thinlight/context.h"
#include "tl_test.h"

typedef struct tl_gl_fixture {
    tl_context *ctx;
    GladGLContext gl;
} tl_gl_fixture;

static inline GLADapiproc tl_gl_fixture_load(void *user, const char *name)
{
    return (GLADapiproc)tl_context_get_proc_address((tl_context *)user, name);
}

/* Opens a size x size context and loads glad; false (after a failed check) when impossible. */
static inline bool tl_gl_fixture_open(tl_gl_fixture *f, uint32_t size)
{
    memset(f, 0, sizeof *f);
    tl_result r = tl_test_context_create(size, size, &f->ctx);
    TL_CHECK(r == TL_OK);
    if (r != TL_OK) return false;
    char msg[256];
    r = tl__gl_load(&f->gl, tl_gl_fixture_load, f->ctx, msg, sizeof msg);
    if (r != TL_OK) fprintf(stderr, "tl__gl_load: %s\n", msg);
    TL_CHECK(r == TL_OK);
    if (r != TL_OK) {
        tl_context_destroy(f->ctx);
        f->ctx = NULL;
        return false;
    }
    return true;
}

/* Checks that no GL error is pending, then destroys the context. */
static inline void tl_gl_fixture_close(tl_gl_fixture *f)
{
    TL_CHECK_EQ_U(f->gl.GetError(), GL_NO_ERROR);
    tl_context_destroy(f->ctx);
    f->ctx = NULL;
}

#endif
