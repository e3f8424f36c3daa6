/* tl_context: descriptor defaults, back-end dispatch, the strings read at creation. */
#include <stdlib.h>
#include <string.h>

#include "platform.h"

#define TL__DEFAULT_WIDTH 640u
#define TL__DEFAULT_HEIGHT 480u

#if defined(_WIN32)
#  define TL__GLAPIENTRY __stdcall
#else
#  define TL__GLAPIENTRY
#endif
#define TL__GL_RENDERER 0x1F01
#define TL__GL_VERSION 0x1F02
#define TL__GL_MAJOR_VERSION 0x821B
#define TL__GL_MINOR_VERSION 0x821C
typedef const unsigned char *(TL__GLAPIENTRY *tl__get_string_fn)(unsigned int name);
typedef void(TL__GLAPIENTRY *tl__get_integerv_fn)(unsigned int name, int *data);

/* Why the last tl_context_create on this thread failed: there is no object to hold it. It is
 * diagnostic text only and changes no behaviour. */
static _Thread_local char tl__create_error[576]; /* "GLFW: " + tl_context.error */

static tl__context_config tl__context_desc_defaults(const tl_context_desc *desc)
{
    static const tl_context_desc zero = {0};
    if (!desc) desc = &zero;
    tl__context_config c = {
        .backend = desc->backend ? desc->backend : TL_CONTEXT_BACKEND_OSMESA,
        .width = desc->width ? desc->width : TL__DEFAULT_WIDTH,
        .height = desc->height ? desc->height : TL__DEFAULT_HEIGHT,
        .major = desc->gl_major ? desc->gl_major : 4,
        .minor = desc->gl_major ? desc->gl_minor : 5,
        .exact_version = desc->exact_version,
        .debug = desc->debug,
        .visible = desc->visible,
        .title = desc->title ? desc->title : "thinlight",
        .allocator = desc->allocator,
        .logger = desc->logger,
    };
    return c;
}

static const char *tl__backend_name(tl_context_backend b)
{
    switch (b) {
    case TL_CONTEXT_BACKEND_OSMESA: return "OSMesa";
    case TL_CONTEXT_BACKEND_GLFW: return "GLFW";
    default: return "unknown";
    }
}

/* Reads GL_RENDERER, GL_VERSION and the version numbers through the context's own loader. */
static void tl__read_strings(tl_context *ctx)
{
    tl__get_string_fn get_string = (tl__get_string_fn)tl_context_get_proc_address(ctx, "glGetString");
    tl__get_integerv_fn get_integerv =
        (tl__get_integerv_fn)tl_context_get_proc_address(ctx, "glGetIntegerv");
    const unsigned char *s;
    if (get_string && (s = get_string(TL__GL_RENDERER)) != NULL)
        snprintf(ctx->renderer, sizeof ctx->renderer, "%s", (const char *)s);
    if (get_string && (s = get_string(TL__GL_VERSION)) != NULL)
        snprintf(ctx->version, sizeof ctx->version, "%s", (const char *)s);
    if (get_integerv) {
        int major = 0, minor = 0;
        get_integerv(TL__GL_MAJOR_VERSION, &major);
        get_integerv(TL__GL_MINOR_VERSION, &minor);
        if (major > 0) {
            ctx->major = major;
            ctx->minor = minor;
        }
    }
}

/* Records why tl_context_create failed (thread-local) and hands it to the desc's logger. */
#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
static tl_result tl__create_failed(const tl_context_desc *desc, tl_result r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(tl__create_error, sizeof tl__create_error, fmt, ap);
    va_end(ap);
    if (desc && desc->logger.fn) desc->logger.fn(desc->logger.user, TL_LOG_ERROR, tl__create_error);
    return r;
}

/* Hands a failure of a call on `ctx` (already in ctx->error) to its logger. */
static inline tl_result tl__context_failed(tl_context *ctx, tl_result r)
{
    if (r != TL_OK && ctx->logger.fn) ctx->logger.fn(ctx->logger.user, TL_LOG_ERROR, ctx->error);
    return r;
}

tl_result tl_context_create(const tl_context_desc *desc, tl_context **out)
{
    tl__create_error[0] = '\0';
    if (out) *out = NULL;
    if (!out) return tl__create_failed(desc, TL_ERROR_INVALID_ARGUMENT, "tl_context_create: NULL output");
    if (desc && !desc->allocator.alloc != !desc->allocator.free)
        return tl__create_failed(desc, TL_ERROR_INVALID_ARGUMENT,
                                 "tl_context_create: the allocator needs both alloc and free, or neither");
    tl__context_config cfg = tl__context_desc_defaults(desc);
    if ((unsigned)cfg.backend >= TL_CONTEXT_BACKEND_COUNT_)
        return tl__create_failed(desc, TL_ERROR_INVALID_ARGUMENT, "tl_context_create: unknown back end %d",
                                 (int)cfg.backend);
    if (cfg.major < 3 || (cfg.major == 3 && cfg.minor < 3) || cfg.minor < 0 || cfg.major > 4 ||
        cfg.minor > 9)
        return tl__create_failed(desc, TL_ERROR_INVALID_ARGUMENT,
                                 "tl_context_create: OpenGL %d.%d requested, core profiles are 3.3 to 4.6",
                                 cfg.major, cfg.minor);
    if (cfg.width > 65536 || cfg.height > 65536)
        return tl__create_failed(desc, TL_ERROR_LIMIT, "tl_context_create: %ux%u is beyond any back end's limit",
                                 (unsigned)cfg.width, (unsigned)cfg.height);

    tl_context *ctx = tl__alloc_zeroed(&cfg.allocator, sizeof *ctx);
    if (!ctx) return tl__create_failed(desc, TL_ERROR_OUT_OF_MEMORY, "tl_context_create: out of memory");
    ctx->allocator = cfg.allocator;
    ctx->logger = cfg.logger;
    ctx->backend = cfg.backend;
    ctx->width = cfg.width;
    ctx->height = cfg.height;

    tl_result r = TL_ERROR_UNSUPPORTED;
    switch (cfg.backend) {
    case TL_CONTEXT_BACKEND_OSMESA:
#if defined(TL_HAVE_OSMESA)
        r = tl__osmesa_create(ctx, &cfg);
#else
        tl__context_error(ctx, "the OSMesa back end is not built into this thinlight "
                               "(configure with -DTHINLIGHT_WITH_OSMESA=ON and libosmesa6-dev)");
#endif
        break;
    case TL_CONTEXT_BACKEND_GLFW:
#if defined(TL_HAVE_GLFW)
        r = tl__glfw_create(ctx, &cfg);
#else
        tl__context_error(ctx, "the GLFW back end is not built into this thinlight "
                               "(configure with -DTHINLIGHT_WITH_GLFW=ON and libglfw3-dev)");
#endif
        break;
    default: break;
    }
    if (r != TL_OK) {
        char ctx_error[sizeof ctx->error];
        memcpy(ctx_error, ctx->error, sizeof ctx_error);
        tl__free(&cfg.allocator, ctx);
        return tl__create_failed(desc, r, "%s: %s", tl__backend_name(cfg.backend), ctx_error);
    }
    tl__read_strings(ctx);
    *out = ctx;
    return TL_OK;
}

tl_result tl_context_make_current(tl_context *ctx)
{
    if (!ctx) {
#if defined(TL_HAVE_OSMESA)
        tl__osmesa_release();
#endif
#if defined(TL_HAVE_GLFW)
        tl__glfw_release();
#endif
        return TL_OK;
    }
    ctx->error[0] = '\0';
    switch (ctx->backend) {
#if defined(TL_HAVE_OSMESA)
    case TL_CONTEXT_BACKEND_OSMESA: return tl__context_failed(ctx, tl__osmesa_make_current(ctx));
#endif
#if defined(TL_HAVE_GLFW)
    case TL_CONTEXT_BACKEND_GLFW: return tl__context_failed(ctx, tl__glfw_make_current(ctx));
#endif
    default: return TL_ERROR_UNSUPPORTED;
    }
}

tl_gl_proc tl_context_get_proc_address(tl_context *ctx, const char *name)
{
    if (!ctx || !name) return NULL;
    switch (ctx->backend) {
#if defined(TL_HAVE_OSMESA)
    case TL_CONTEXT_BACKEND_OSMESA: return tl__osmesa_proc(ctx, name);
#endif
#if defined(TL_HAVE_GLFW)
    case TL_CONTEXT_BACKEND_GLFW: return tl__glfw_proc(ctx, name);
#endif
    default: return NULL;
    }
}

tl_result tl_context_swap(tl_context *ctx)
{
    if (!ctx) return TL_ERROR_INVALID_ARGUMENT;
    ctx->error[0] = '\0';
#if defined(TL_HAVE_GLFW)
    if (ctx->backend == TL_CONTEXT_BACKEND_GLFW) return tl__context_failed(ctx, tl__glfw_swap(ctx));
#endif
    return TL_OK; /* OSMesa renders straight into its buffer */
}

void tl_context_destroy(tl_context *ctx)
{
    if (!ctx) return;
    switch (ctx->backend) {
#if defined(TL_HAVE_OSMESA)
    case TL_CONTEXT_BACKEND_OSMESA: tl__osmesa_destroy(ctx); break;
#endif
#if defined(TL_HAVE_GLFW)
    case TL_CONTEXT_BACKEND_GLFW: tl__glfw_destroy(ctx); break;
#endif
    default: break;
    }
    tl_allocator allocator = ctx->allocator;
    tl__free(&allocator, ctx);
}

tl_gl_proc tl_context_proc_loader(void *ctx, const char *name)
{
    return tl_context_get_proc_address(ctx, name);
}

const char *tl_context_last_error(const tl_context *ctx)
{
    return ctx ? ctx->error : tl__create_error;
}

const char *tl_context_renderer_string(const tl_context *ctx) { return ctx ? ctx->renderer : ""; }

const char *tl_context_version_string(const tl_context *ctx) { return ctx ? ctx->version : ""; }

void tl_context_gl_version(const tl_context *ctx, int *major, int *minor)
{
    if (major) *major = ctx ? ctx->major : 0;
    if (minor) *minor = ctx ? ctx->minor : 0;
}

tl_context_backend tl_context_get_backend(const tl_context *ctx)
{
    return ctx ? ctx->backend : TL_CONTEXT_BACKEND_DEFAULT;
}

void tl_context_get_size(const tl_context *ctx, uint32_t *width, uint32_t *height)
{
#if defined(TL_HAVE_GLFW)
    if (ctx && ctx->backend == TL_CONTEXT_BACKEND_GLFW) {
        tl__glfw_size(ctx, width, height);
        return;
    }
#endif
    if (width) *width = ctx ? ctx->width : 0;
    if (height) *height = ctx ? ctx->height : 0;
}
