/* Private: the context object shared by the back ends (osmesa.c, egl.c, glfw.c) and context.c.
 * Errors and memory go through src/core as in every layer: a back end fails with
 * tl__log_fail(&ctx->log, result, ...) and allocates with tl__alloc / tl__calloc / tl__free on
 * ctx->allocator. */
#ifndef TL_PLATFORM_PLATFORM_H
#define TL_PLATFORM_PLATFORM_H

#include <stdio.h>
#include <string.h>

#include "core/alloc.h"
#include "core/log.h"
#include "platform/context_link.h"
#include "thinlight/context.h"

typedef struct tl__context_ops tl__context_ops;

struct tl_context {
    tl_context_backend backend;
    const tl__context_ops *ops; /* the back end's functions */
    uint32_t width, height; /* requested default framebuffer size */
    int major, minor;       /* core version obtained */
    char renderer[128];     /* GL_RENDERER */
    char version[128];      /* GL_VERSION */
    char platform[256];     /* tl_context_platform_string, written by the back end */
    void *impl;             /* back-end state */
    tl_allocator allocator; /* from the desc, resolved: both functions set */
    /* tl_context_last_error and the desc's logger. Silent while tl_context_create runs the back
     * ends (AUTO tries several; the create sends one line for all of them when it fails). */
    tl__log log;
    tl__context_link *dependants; /* cleared by tl_context_destroy (context_link.h) */
};

/* Descriptor with defaults resolved (tl__context_desc_defaults). */
typedef struct tl__context_config {
    tl_context_backend backend;
    uint32_t width, height;
    int major, minor;
    bool exact_version, debug, visible;
    const char *title;
    tl_egl_platform egl_platform;
    uint32_t egl_device;
    bool egl_gpu_only; /* AUTO's first step: a GPU device or TL_ERROR_UNSUPPORTED, no surfaceless */
    tl_allocator allocator;
    tl_logger logger;
} tl__context_config;

/* Core versions tried, best first, after the requested one (unless exact_version). */
#define TL__CONTEXT_FALLBACKS {{4, 6}, {4, 5}, {4, 4}, {4, 3}, {4, 2}, {4, 1}, {4, 0}, {3, 3}}

/* One back end. create fills ctx->impl, major/minor and ctx->platform and makes the context
 * current; on failure it leaves ctx->impl NULL, records why (tl__log_fail) and cleans up after
 * itself. Every other call that fails records why the same way, which also logs it.
 * release makes no context of this back end current on the calling thread; is_current tells whether
 * ctx is the current one. swap and size may be NULL: nothing to present, and the size asked for. */
struct tl__context_ops {
    tl_result (*create)(tl_context *ctx, const tl__context_config *cfg);
    tl_result (*make_current)(tl_context *ctx);
    bool (*is_current)(const tl_context *ctx);
    void (*release)(void);
    tl_gl_proc (*proc)(tl_context *ctx, const char *name);
    tl_result (*swap)(tl_context *ctx);
    void (*size)(const tl_context *ctx, uint32_t *width, uint32_t *height);
    void (*destroy)(tl_context *ctx);
};

#if defined(TL_HAVE_OSMESA)
extern const tl__context_ops tl__osmesa_ops;
#endif
#if defined(TL_HAVE_GLFW)
extern const tl__context_ops tl__glfw_ops;
#endif
#if defined(TL_HAVE_EGL)
extern const tl__context_ops tl__egl_ops;
/* tl_context_egl_devices for a build with EGL; messages go to `logger` (may be NULL). */
tl_result tl__egl_devices(tl_egl_device *devices, size_t capacity, size_t *count, const tl_logger *logger);
#endif

#endif
