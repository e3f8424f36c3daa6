/* tl_context_create refuses bad descriptors with a result and a message, never a crash; NULL
 * objects are harmless everywhere. */
#include <string.h>

#include "thinlight/context.h"
#include "tl_test.h"

/* Bad descriptors fail with a result and a message, never a crash. */
TL_TEST(gl_context_bad_input)
{
    tl_context *ctx = (tl_context *)&ctx; /* must be overwritten with NULL */
    TL_CHECK(tl_context_create(NULL, NULL) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(strlen(tl_context_last_error(NULL)) > 0);
    TL_CHECK(tl_context_create(&(tl_context_desc){.backend = TL_CONTEXT_BACKEND_COUNT_}, &ctx) ==
             TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(ctx == NULL);
    TL_CHECK(tl_context_create(&(tl_context_desc){.gl_major = 2, .gl_minor = 1}, &ctx) ==
             TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_context_create(&(tl_context_desc){.width = 1u << 20}, &ctx) == TL_ERROR_LIMIT);
    TL_CHECK(tl_context_create(&(tl_context_desc){.width = 40000, .height = 4}, &ctx) ==
             TL_ERROR_LIMIT);
    printf("40000x4: %s\n", tl_context_last_error(NULL));
    TL_CHECK(ctx == NULL);
    /* GLFW without a display (or not built) fails cleanly; with a display it may succeed. */
    tl_result r = tl_context_create(&(tl_context_desc){.backend = TL_CONTEXT_BACKEND_GLFW}, &ctx);
    printf("GLFW: %s: %s\n", tl_result_string(r), r == TL_OK ? "ok" : tl_context_last_error(NULL));
    TL_CHECK((r == TL_OK) == (ctx != NULL));
    if (r != TL_OK) TL_CHECK(strlen(tl_context_last_error(NULL)) > 0);
    tl_context_destroy(ctx);
    tl_context_destroy(NULL);
    TL_CHECK(tl_context_get_proc_address(NULL, "glGetString") == NULL);
    TL_CHECK(strcmp(tl_context_renderer_string(NULL), "") == 0);
}
