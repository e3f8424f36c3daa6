/* tl_context_create refuses bad descriptors with a result and a message, never a crash; NULL
 * objects are harmless everywhere. Errors follow the model of every layer (docs/getting-started.md,
 * "Errors, logging and memory"): a result, one line to the logger, the last error where there is an
 * object, memory from the descriptor's allocator, and nothing printed. */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "platform.h" /* struct tl_context: the test makes a back end's call fail */
#include "stderr_capture.h"
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


/* An allocator that fails the `fail_at`-th request (1-based; 0: never), or with `fail_rest` every
 * request from that one on, and counts what is live. */
typedef struct failing_alloc {
    size_t calls, live, failed, fail_at;
    int fail_rest;
} failing_alloc;

static void *failing_alloc_fn(size_t size, void *user)
{
    failing_alloc *a = user;
    a->calls++;
    if (a->fail_at && (a->calls == a->fail_at || (a->fail_rest && a->calls > a->fail_at))) {
        a->failed++;
        return NULL;
    }
    void *p = malloc(size);
    if (p) a->live++;
    return p;
}

static void failing_free_fn(void *ptr, void *user)
{
    failing_alloc *a = user;
    a->live--;
    free(ptr);
}

/* Every allocation of tl_context_create failing in turn, once or from then on, for the default
 * back end and for AUTO: an allocation that failed makes the create fail with
 * TL_ERROR_OUT_OF_MEMORY and one error line saying so (AUTO does not take a failed allocation for
 * a missing back end and go on to the next), and nothing is left allocated. */
TL_TEST(context_failing_allocator_out_of_memory_logged_no_leak)
{
    static const tl_context_backend backends[] = {TL_CONTEXT_BACKEND_DEFAULT, TL_CONTEXT_BACKEND_AUTO};
    for (size_t b = 0; b < sizeof backends / sizeof backends[0]; b++)
        for (int rest = 0; rest <= 1; rest++)
            for (size_t k = 1; k <= 6; k++) {
                failing_alloc fa = {.fail_at = k, .fail_rest = rest};
                logged l = {0};
                tl_context *ctx = NULL;
                tl_context_desc desc = {.backend = backends[b], .width = 32, .height = 16,
                                        .allocator = {failing_alloc_fn, failing_free_fn, &fa},
                                        .logger = {log_count, &l}};
                tl_result r = tl_context_create(&desc, &ctx);
                if (fa.failed) {
                    if (r != TL_ERROR_OUT_OF_MEMORY || l.errors != 1 || !strstr(l.last, "out of memory"))
                        printf("%s, allocation %zu%s failing: %s (%d lines): %s\n",
                               tl_context_backend_name(backends[b]), k, rest ? " and later" : "",
                               tl_result_string(r), l.errors, l.last);
                    TL_CHECK(r == TL_ERROR_OUT_OF_MEMORY && ctx == NULL);
                    TL_CHECK(l.errors == 1 && strstr(l.last, "out of memory") != NULL);
                    TL_CHECK(!strchr(l.last, '\n'));
                } else {
                    TL_CHECK(r == TL_OK && ctx != NULL && fa.live > 0 && l.errors == 0);
                }
                tl_context_destroy(ctx);
                TL_CHECK(fa.live == 0);
            }
}

/* A call on a context that the platform refuses (OSMesaMakeCurrent, given a width of 0) returns its result and hands one line to the logger, and that line is what
 * tl_context_last_error says from then on, until the next failure (as tl_renderer_last_error). */
TL_TEST(context_call_failure_one_line_to_logger_and_last_error)
{
    logged l = {0};
    tl_context *ctx = NULL;
    TL_CHECK(tl_context_create(&(tl_context_desc){.width = 16, .height = 16, .logger = {log_count, &l}}, &ctx) ==
             TL_OK);
    if (!ctx) return;
    TL_CHECK(strcmp(tl_context_last_error(ctx), "") == 0 && l.errors == 0);
    uint32_t width = ctx->width;
    ctx->width = 0; /* OSMesaMakeCurrent refuses a buffer 0 pixels wide */
    TL_CHECK(tl_context_make_current(ctx) == TL_ERROR_GL);
    ctx->width = width;
    printf("make_current: %s\n", l.last);
    TL_CHECK(l.errors == 1 && l.last[0] && !strchr(l.last, '\n'));
    TL_CHECK(strcmp(tl_context_last_error(ctx), l.last) == 0);
    TL_CHECK(tl_context_make_current(ctx) == TL_OK && tl_context_swap(ctx) == TL_OK);
    TL_CHECK(l.errors == 1 && strcmp(tl_context_last_error(ctx), l.last) == 0);
    tl_context_destroy(ctx);
}

/* Failing context calls print nothing: their messages go to the logger only. */
TL_TEST(context_failures_print_nothing_on_stderr)
{
    logged l = {0};
    tl_logger logger = {log_count, &l};
    failing_alloc fa = {.fail_at = 1, .fail_rest = 1};
    tl_context *ctx = NULL, *good = NULL;
    tlc_stderr cap;
    tlc_stderr_begin(&cap);
    tl_context_create(&(tl_context_desc){.logger = logger}, NULL);
    tl_context_create(&(tl_context_desc){.backend = TL_CONTEXT_BACKEND_COUNT_, .logger = logger}, &ctx);
    tl_context_create(&(tl_context_desc){.width = 40000, .height = 4, .logger = logger}, &ctx);
    tl_context_create(&(tl_context_desc){.gl_major = 4, .gl_minor = 9, .exact_version = true, .logger = logger},
                      &ctx);
    tl_context_create(&(tl_context_desc){.allocator = {failing_alloc_fn, failing_free_fn, &fa}, .logger = logger},
                      &ctx);
    tl_context_egl_devices(NULL, 0, NULL, &logger);
    if (tl_context_create(&(tl_context_desc){.width = 8, .height = 8, .logger = logger}, &good) == TL_OK) {
        good->width = 0;
        tl_context_make_current(good);
        good->width = 8;
        tl_context_destroy(good);
    }
    char printed[4096];
    long n = tlc_stderr_end(&cap, printed, sizeof printed);
    printf("%d error lines; %ld bytes on stderr%s%s\n", l.errors, n, n > 0 ? ": " : "", n > 0 ? printed : "");
    TL_CHECK(n == 0);
    TL_CHECK(l.errors == 7);
    TL_CHECK(fa.live == 0);
}
