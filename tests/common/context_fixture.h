/* The context every GL test runs on: THINLIGHT_TEST_CONTEXT names the back end
 * (tl_context_backend_name: osmesa, egl, auto, ...; unset or empty: the library's default, OSMesa),
 * so the same cases run under either headless back end (tests/egl.cmake registers some under EGL).
 * A failed create prints its reason (the descriptor's logger: there is no object to ask). */
#ifndef TL_CONTEXT_FIXTURE_H
#define TL_CONTEXT_FIXTURE_H

#include <stdio.h>
#include <stdlib.h>

#include "thinlight/context.h"

static inline void tl_test_context_log(void *user, tl_log_level level, const char *message)
{
    (void)user;
    if (level == TL_LOG_ERROR) fprintf(stderr, "tl_context_create: %s\n", message);
}

/* The back end THINLIGHT_TEST_CONTEXT asks for; false (after a line on stderr) for a bad name. */
static inline bool tl_test_context_backend(tl_context_backend *backend)
{
    const char *name = getenv("THINLIGHT_TEST_CONTEXT");
    *backend = TL_CONTEXT_BACKEND_DEFAULT;
    if (!name || !*name) return true;
    if (tl_context_backend_from_name(name, backend) == TL_OK) return true;
    fprintf(stderr, "THINLIGHT_TEST_CONTEXT=%s is not a back end (osmesa, egl, auto, glfw)\n", name);
    return false;
}

/* A width x height context of the back end the environment names, current on this thread. */
static inline tl_result tl_test_context_create(uint32_t width, uint32_t height, tl_context **out)
{
    tl_context_desc desc = {.width = width, .height = height, .logger = {tl_test_context_log, NULL}};
    *out = NULL;
    if (!tl_test_context_backend(&desc.backend)) return TL_ERROR_INVALID_ARGUMENT;
    return tl_context_create(&desc, out);
}

#endif
