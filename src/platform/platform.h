/* Private: the context object shared by the back ends (osmesa.c, egl.c, glfw.c) and context.c. */
#ifndef TL_PLATFORM_PLATFORM_H
#define TL_PLATFORM_PLATFORM_H

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
    char error[512];        /* last failure on this context */
    void *impl;             /* back-end state */
    tl_allocator allocator; /* from the desc; zeroed: malloc/free */
    tl_logger logger;       /* from the desc; zeroed: silent */
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

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static inline void tl__context_error(tl_context *ctx, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(ctx->error, sizeof ctx->error, fmt, ap);
    va_end(ap);
}

/* Allocation through an allocator (zeroed: malloc/free). tl__alloc_zeroed clears the memory. */
static inline void *tl__alloc(const tl_allocator *a, size_t size)
{
    return a->alloc ? a->alloc(size, a->user) : malloc(size);
}
static inline void *tl__alloc_zeroed(const tl_allocator *a, size_t size)
{
    void *p = tl__alloc(a, size);
    if (p) memset(p, 0, size);
    return p;
}
static inline void tl__free(const tl_allocator *a, void *ptr)
{
    if (!ptr) return;
    if (a->free)
        a->free(ptr, a->user);
    else
        free(ptr);
}

/* One back end. create fills ctx->impl, major/minor and ctx->platform and makes the context
 * current; on failure it leaves ctx->impl NULL, writes ctx->error and cleans up after itself.
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
