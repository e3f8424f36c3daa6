/* OSMesa back end: an off-screen core-profile context (llvmpipe) current on an RGBA8
 * buffer. No display, no window system. */
#include <GL/osmesa.h>

#include "platform.h"

typedef struct tl__osmesa {
    OSMesaContext context;
    unsigned char *buffer; /* width * height RGBA8, bottom row first */
} tl__osmesa;

static OSMesaContext tl__osmesa_try(int major, int minor)
{
    const int attribs[] = {
        OSMESA_FORMAT, OSMESA_RGBA,
        OSMESA_DEPTH_BITS, 24,
        OSMESA_STENCIL_BITS, 8,
        OSMESA_ACCUM_BITS, 0,
        OSMESA_PROFILE, OSMESA_CORE_PROFILE,
        OSMESA_CONTEXT_MAJOR_VERSION, major,
        OSMESA_CONTEXT_MINOR_VERSION, minor,
        0,
    };
    return OSMesaCreateContextAttribs(attribs, NULL);
}

/* Undoes a create that failed after its state was allocated; returns `r`. */
static tl_result tl__osmesa_undo(tl_context *ctx, tl__osmesa *o, tl_result r)
{
    if (o->context) OSMesaDestroyContext(o->context);
    tl__free(&ctx->allocator, o->buffer);
    tl__free(&ctx->allocator, o);
    return r;
}

static tl_result tl__osmesa_create(tl_context *ctx, const tl__context_config *cfg)
{
    static const int fallbacks[][2] = TL__CONTEXT_FALLBACKS;
    tl__osmesa *o = tl__calloc(&ctx->allocator, 1, sizeof *o);
    if (!o) return tl__log_fail(&ctx->log, TL_ERROR_OUT_OF_MEMORY, "out of memory");

    int major = cfg->major, minor = cfg->minor;
    o->context = tl__osmesa_try(major, minor);
    for (size_t i = 0; !o->context && !cfg->exact_version && i < sizeof fallbacks / sizeof fallbacks[0];
         i++) {
        int fa = fallbacks[i][0], fi = fallbacks[i][1];
        if (fa > cfg->major || (fa == cfg->major && fi >= cfg->minor)) continue;
        major = fa;
        minor = fi;
        o->context = tl__osmesa_try(major, minor);
    }
    if (!o->context)
        return tl__osmesa_undo(ctx, o,
                               tl__log_fail(&ctx->log, TL_ERROR_GL,
                                            "OSMesaCreateContextAttribs refused OpenGL %d.%d core%s", cfg->major,
                                            cfg->minor,
                                            cfg->exact_version ? " (exact_version)"
                                                               : " and every core version down to 3.3 (is this "
                                                                 "Mesa built with llvmpipe?)"));

    /* The screen behind every OSMesa context answers this before anything is current. */
    GLint max_w = 0, max_h = 0;
    OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &max_w);
    OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &max_h);
    if ((max_w > 0 && cfg->width > (uint32_t)max_w) || (max_h > 0 && cfg->height > (uint32_t)max_h))
        return tl__osmesa_undo(ctx, o,
                               tl__log_fail(&ctx->log, TL_ERROR_LIMIT, "%ux%u exceeds the OSMesa maximum of %dx%d",
                                            (unsigned)cfg->width, (unsigned)cfg->height, (int)max_w, (int)max_h));
    o->buffer = tl__alloc_array(&ctx->allocator, (size_t)cfg->width * cfg->height, 4);
    if (!o->buffer)
        return tl__osmesa_undo(ctx, o,
                               tl__log_fail(&ctx->log, TL_ERROR_OUT_OF_MEMORY, "out of memory for a %ux%u RGBA8 buffer",
                                            (unsigned)cfg->width, (unsigned)cfg->height));
    if (!OSMesaMakeCurrent(o->context, o->buffer, GL_UNSIGNED_BYTE, (GLsizei)cfg->width, (GLsizei)cfg->height))
        return tl__osmesa_undo(ctx, o,
                               tl__log_fail(&ctx->log, TL_ERROR_GL, "OSMesaMakeCurrent failed for a %ux%u RGBA8 buffer",
                                            (unsigned)cfg->width, (unsigned)cfg->height));
    ctx->impl = o;
    ctx->major = major;
    ctx->minor = minor;
    snprintf(ctx->platform, sizeof ctx->platform, "OSMesa");
    return TL_OK;
}

static tl_result tl__osmesa_make_current(tl_context *ctx)
{
    tl__osmesa *o = ctx->impl;
    if (!OSMesaMakeCurrent(o->context, o->buffer, GL_UNSIGNED_BYTE, (GLsizei)ctx->width, (GLsizei)ctx->height))
        return tl__log_fail(&ctx->log, TL_ERROR_GL, "OSMesaMakeCurrent failed for a %ux%u RGBA8 buffer",
                            (unsigned)ctx->width, (unsigned)ctx->height);
    return TL_OK;
}

static bool tl__osmesa_is_current(const tl_context *ctx)
{
    const tl__osmesa *o = ctx->impl;
    return OSMesaGetCurrentContext() == o->context;
}

static void tl__osmesa_release(void)
{
    if (OSMesaGetCurrentContext()) OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
}

static tl_gl_proc tl__osmesa_proc(tl_context *ctx, const char *name)
{
    (void)ctx;
    return (tl_gl_proc)OSMesaGetProcAddress(name);
}

static void tl__osmesa_destroy(tl_context *ctx)
{
    tl__osmesa *o = ctx->impl;
    if (!o) return;
    if (OSMesaGetCurrentContext() == o->context) OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(o->context);
    tl__free(&ctx->allocator, o->buffer);
    tl__free(&ctx->allocator, o);
    ctx->impl = NULL;
}

const tl__context_ops tl__osmesa_ops = {
    .create = tl__osmesa_create,
    .make_current = tl__osmesa_make_current,
    .is_current = tl__osmesa_is_current,
    .release = tl__osmesa_release,
    .proc = tl__osmesa_proc,
    .swap = NULL,
    .size = NULL,
    .destroy = tl__osmesa_destroy,
};
