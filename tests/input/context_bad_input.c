/* tl_context_create refuses bad descriptors with a result and a message, never a crash; NULL
 * objects are harmless everywhere. */
#include <stdio.h>
#include <string.h>

#include "thinlight/context.h"
#include "tl_test.h"

/* Counts the messages a failed create hands to its logger (there is no object to keep them). */
typedef struct logged {
    int errors;
    char last[1024];
} logged;

static void log_count(void *user, tl_log_level level, const char *message)
{
    logged *l = user;
    if (level == TL_LOG_ERROR) l->errors++;
    snprintf(l->last, sizeof l->last, "%s", message);
}

/* Bad descriptors fail with a result and one logged message, never a crash. */
TL_TEST(gl_context_bad_input)
{
    tl_context *ctx = (tl_context *)&ctx; /* must be overwritten with NULL */
    logged l = {0};
    tl_logger logger = {log_count, &l};
    TL_CHECK(tl_context_create(&(tl_context_desc){.logger = logger}, NULL) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(l.errors == 1 && strlen(l.last) > 0);
    TL_CHECK(tl_context_create(NULL, NULL) == TL_ERROR_INVALID_ARGUMENT); /* no logger: silent */
    TL_CHECK(strcmp(tl_context_last_error(NULL), "") == 0);               /* no thread-local error */
    TL_CHECK(tl_context_create(&(tl_context_desc){.backend = TL_CONTEXT_BACKEND_COUNT_, .logger = logger}, &ctx) ==
             TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(ctx == NULL && l.errors == 2);
    TL_CHECK(tl_context_create(&(tl_context_desc){.gl_major = 2, .gl_minor = 1, .logger = logger}, &ctx) ==
             TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_context_create(&(tl_context_desc){.width = 1u << 20, .logger = logger}, &ctx) == TL_ERROR_LIMIT);
    TL_CHECK(tl_context_create(&(tl_context_desc){.width = 40000, .height = 4, .logger = logger}, &ctx) ==
             TL_ERROR_LIMIT);
    printf("40000x4: %s\n", l.last);
    TL_CHECK(ctx == NULL && l.errors == 5);
    /* GLFW without a display (or not built) fails cleanly; with a display it may succeed. */
    tl_result r = tl_context_create(&(tl_context_desc){.backend = TL_CONTEXT_BACKEND_GLFW, .logger = logger}, &ctx);
    printf("GLFW: %s: %s\n", tl_result_string(r), r == TL_OK ? "ok" : l.last);
    TL_CHECK((r == TL_OK) == (ctx != NULL));
    if (r != TL_OK) TL_CHECK(l.errors == 6);
    tl_context_destroy(ctx);
    tl_context_destroy(NULL);
    TL_CHECK(tl_context_get_proc_address(NULL, "glGetString") == NULL);
    TL_CHECK(strcmp(tl_context_renderer_string(NULL), "") == 0);
}

