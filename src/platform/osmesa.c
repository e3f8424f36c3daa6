/* OSMesa back end: an off-screen core-profile context (llvmpipe) current on an RGBA8
 * buffer. No display, no window system. */
#include <stdlib.h>

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

static tl_result tl__osmesa_create(tl_context *ctx, const tl__context_config *cfg)
{
    static const int fallbacks[][2] = TL__CONTEXT_FALLBACKS;
    tl__osmesa *o = tl__alloc_zeroed(&ctx->allocator, sizeof *o);
    if (!o) {
        tl__context_error(ctx, "out of memory");
        return TL_ERROR_OUT_OF_MEMORY;
    }

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
    if (!o->context) {
        if (cfg->exact_version)
            tl__context_error(ctx, "OSMesaCreateContextAttribs refused an OpenGL %d.%d core context",
                              cfg->major, cfg->minor);
        else
            tl__context_error(ctx,
                              "OSMesaCreateContextAttribs refused OpenGL %d.%d core and every "
                              "core version down to 3.3 (is this Mesa built with llvmpipe?)",
                              cfg->major, cfg->minor);
        tl__free(&ctx->allocator, o);
        return TL_ERROR_GL;
    }

    /* The screen behind every OSMesa context answers this before anything is current. */
    GLint max_w = 0, max_h = 0;
    OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &max_w);
    OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &max_h);
    if ((max_w > 0 && cfg->width > (uint32_t)max_w) || (max_h > 0 && cfg->height > (uint32_t)max_h)) {
        tl__context_error(ctx, "%ux%u exceeds the OSMesa maximum of %dx%d", (unsigned)cfg->width,
                          (unsigned)cfg->height, (int)max_w, (int)max_h);
        OSMesaDestroyContext(o->context);
        tl__free(&ctx->allocator, o);
        return TL_ERROR_LIMIT;
    }
    o->buffer = tl__alloc(&ctx->allocator, (size_t)cfg->width * cfg->height * 4u);
    if (!o->buffer) {
        tl__context_error(ctx, "out of memory for a %ux%u RGBA8 buffer", (unsigned)cfg->width,
                          (unsigned)cfg->height);
        OSMesaDestroyContext(o->context);
        tl__free(&ctx->allocator, o);
        return TL_ERROR_OUT_OF_MEMORY;
    }
    if (!OSMesaMakeCurrent(o->context, o->buffer, GL_UNSIGNED_BYTE, (GLsizei)cfg->width,
                           (GLsizei)cfg->height)) {
        tl__context_error(ctx, "OSMesaMakeCurrent failed for a %ux%u RGBA8 buffer",
                          (unsigned)cfg->width, (unsigned)cfg->height);
        OSMesaDestroyContext(o->context);
        tl__free(&ctx->allocator, o->buffer);
        tl__free(&ctx->allocator, o);
        return TL_ERROR_GL;
    }
    ctx->impl = o;
    ctx->major = major;
    ctx->minor = minor;
    snprintf(ctx->platform, sizeof ctx->platform, "OSMesa");
    return TL_OK;
}

static tl_result tl__osmesa_make_current(tl_context *ctx)
{
    tl__osmesa *o = ctx->impl;
    if (!OSMesaMakeCurrent(o->context, o->buffer, GL_UNSIGNED_BYTE, (GLsizei)ctx->width,
                           (GLsizei)ctx->height)) {
        tl__context_error(ctx, "OSMesaMakeCurrent failed");
        return TL_ERROR_GL;
    }
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
