/* Render targets that know their size in bytes, framebuffers over them, readback. */
#include <string.h>

#include "gl.h"
#include "msg.h"
#include "state.h"

#define TL__F(fmt, bpp, kind, f, t) {fmt, #fmt, bpp, kind, f, t}

/* Bytes per pixel are what the driver allocates: the declared bits, except D24 (stored in 32
 * bits, as packed D24S8) and D32F_S8 (stored as 64 bits). Three-channel formats are not listed:
 * RGB16F/RGB32F are not required to be renderable and RGB8 is padded differently by drivers. */
static const tl__format_info tl__formats[] = {
    TL__F(GL_R8, 1, TL__FORMAT_COLOR, GL_RED, GL_UNSIGNED_BYTE),
    TL__F(GL_RG8, 2, TL__FORMAT_COLOR, GL_RG, GL_UNSIGNED_BYTE),
    TL__F(GL_RGBA8, 4, TL__FORMAT_COLOR, GL_RGBA, GL_UNSIGNED_BYTE),
    TL__F(GL_SRGB8_ALPHA8, 4, TL__FORMAT_COLOR, GL_RGBA, GL_UNSIGNED_BYTE),
    TL__F(GL_R16, 2, TL__FORMAT_COLOR, GL_RED, GL_UNSIGNED_SHORT),
    TL__F(GL_RG16, 4, TL__FORMAT_COLOR, GL_RG, GL_UNSIGNED_SHORT),
    TL__F(GL_RGBA16, 8, TL__FORMAT_COLOR, GL_RGBA, GL_UNSIGNED_SHORT),
    TL__F(GL_RGB10_A2, 4, TL__FORMAT_COLOR, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV),
    TL__F(GL_RGB10_A2UI, 4, TL__FORMAT_COLOR, GL_RGBA_INTEGER, GL_UNSIGNED_INT_2_10_10_10_REV),
    TL__F(GL_R11F_G11F_B10F, 4, TL__FORMAT_COLOR, GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV),
    TL__F(GL_R16F, 2, TL__FORMAT_COLOR, GL_RED, GL_HALF_FLOAT),
    TL__F(GL_RG16F, 4, TL__FORMAT_COLOR, GL_RG, GL_HALF_FLOAT),
    TL__F(GL_RGBA16F, 8, TL__FORMAT_COLOR, GL_RGBA, GL_HALF_FLOAT),
    TL__F(GL_R32F, 4, TL__FORMAT_COLOR, GL_RED, GL_FLOAT),
    TL__F(GL_RG32F, 8, TL__FORMAT_COLOR, GL_RG, GL_FLOAT),
    TL__F(GL_RGBA32F, 16, TL__FORMAT_COLOR, GL_RGBA, GL_FLOAT),
    TL__F(GL_R8UI, 1, TL__FORMAT_COLOR, GL_RED_INTEGER, GL_UNSIGNED_BYTE),
    TL__F(GL_RG8UI, 2, TL__FORMAT_COLOR, GL_RG_INTEGER, GL_UNSIGNED_BYTE),
    TL__F(GL_RGBA8UI, 4, TL__FORMAT_COLOR, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE),
    TL__F(GL_R16UI, 2, TL__FORMAT_COLOR, GL_RED_INTEGER, GL_UNSIGNED_SHORT),
    TL__F(GL_RG16UI, 4, TL__FORMAT_COLOR, GL_RG_INTEGER, GL_UNSIGNED_SHORT),
    TL__F(GL_RGBA16UI, 8, TL__FORMAT_COLOR, GL_RGBA_INTEGER, GL_UNSIGNED_SHORT),
    TL__F(GL_R32UI, 4, TL__FORMAT_COLOR, GL_RED_INTEGER, GL_UNSIGNED_INT),
    TL__F(GL_RG32UI, 8, TL__FORMAT_COLOR, GL_RG_INTEGER, GL_UNSIGNED_INT),
    TL__F(GL_RGBA32UI, 16, TL__FORMAT_COLOR, GL_RGBA_INTEGER, GL_UNSIGNED_INT),
    TL__F(GL_DEPTH_COMPONENT16, 2, TL__FORMAT_DEPTH, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT),
    TL__F(GL_DEPTH_COMPONENT24, 4, TL__FORMAT_DEPTH, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT),
    TL__F(GL_DEPTH_COMPONENT32F, 4, TL__FORMAT_DEPTH, GL_DEPTH_COMPONENT, GL_FLOAT),
    TL__F(GL_DEPTH24_STENCIL8, 4, TL__FORMAT_DEPTH_STENCIL, GL_DEPTH_STENCIL,
          GL_UNSIGNED_INT_24_8),
    TL__F(GL_DEPTH32F_STENCIL8, 8, TL__FORMAT_DEPTH_STENCIL, GL_DEPTH_STENCIL,
          GL_FLOAT_32_UNSIGNED_INT_24_8_REV),
    TL__F(GL_STENCIL_INDEX8, 1, TL__FORMAT_STENCIL, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE),
};

const tl__format_info *tl__format_lookup(GLenum internal_format)
{
    for (size_t i = 0; i < sizeof tl__formats / sizeof tl__formats[0]; i++)
        if (tl__formats[i].internal_format == internal_format) return &tl__formats[i];
    return NULL;
}

size_t tl__format_bytes_per_pixel(GLenum internal_format)
{
    const tl__format_info *f = tl__format_lookup(internal_format);
    return f ? f->bytes_per_pixel : 0;
}

unsigned tl__format_view_class(GLenum internal_format)
{
    const tl__format_info *f = tl__format_lookup(internal_format);
    return f && f->kind == TL__FORMAT_COLOR ? 8u * f->bytes_per_pixel : 0u;
}

tl_result tl__target_create(const GladGLContext *gl, const tl__target_desc *desc, tl__target *out,
                            char *msg, size_t msg_size)
{
    return tl__target_create_levels(gl, desc, 1, 0, out, msg, msg_size);
}

/* Filtering of level 0 and clamping to the edge (a multisampled texture has no sampler state:
 * texelFetch reads it). */
static void tl__texture_sampling(const GladGLContext *gl, GLuint tex, GLint filter)
{
    gl->TextureParameteri(tex, GL_TEXTURE_MIN_FILTER, filter);
    gl->TextureParameteri(tex, GL_TEXTURE_MAG_FILTER, filter);
    gl->TextureParameteri(tex, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->TextureParameteri(tex, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

/* What a descriptor asks for that no allocation can give: an unknown format, a size outside
 * 1..GL_MAX_TEXTURE_SIZE or beyond size_t, more samples than GL_MAX_SAMPLES. */
static tl_result tl__target_check(const GladGLContext *gl, const tl__target_desc *desc, const char *label,
                                  const tl__format_info *f, char *msg, size_t msg_size)
{
    if (!f) {
        tl__msg(msg, msg_size, "target \"%s\": internal format 0x%04x is not in the format table",
                label, (unsigned)desc->internal_format);
        return TL_ERROR_UNSUPPORTED;
    }
    GLint max_size = 0;
    gl->GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    if (desc->width == 0 || desc->height == 0 || desc->width > (uint32_t)max_size ||
        desc->height > (uint32_t)max_size) {
        tl__msg(msg, msg_size, "target \"%s\": size %ux%u outside 1..%d (GL_MAX_TEXTURE_SIZE)",
                label, (unsigned)desc->width, (unsigned)desc->height, (int)max_size);
        return desc->width == 0 || desc->height == 0 ? TL_ERROR_INVALID_ARGUMENT : TL_ERROR_LIMIT;
    }
    if ((size_t)desc->width * desc->height > SIZE_MAX / f->bytes_per_pixel) {
        tl__msg(msg, msg_size, "target \"%s\": %ux%u %s overflows size_t", label,
                (unsigned)desc->width, (unsigned)desc->height, f->name);
        return TL_ERROR_LIMIT;
    }
    GLint max_samples = 1;
    if (desc->samples > 1) gl->GetIntegerv(GL_MAX_SAMPLES, &max_samples);
    if (desc->samples > 1 && desc->samples > (uint32_t)max_samples) {
        tl__msg(msg, msg_size, "target \"%s\": %u samples, the context allows %d (GL_MAX_SAMPLES)", label,
                (unsigned)desc->samples, (int)max_samples);
        return TL_ERROR_UNSUPPORTED;
    }
    return TL_OK;
}

/* An immutable texture of `levels` levels (or `samples` samples, one level); 0 after a message. */
static GLuint tl__target_storage(const GladGLContext *gl, const tl__target_desc *desc, const char *label,
                                 const tl__format_info *f, uint32_t levels, uint32_t samples, char *msg, size_t msg_size)
{
    GLuint tex = 0;
    gl->CreateTextures(samples > 1 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D, 1, &tex);
    if (!tex) {
        tl__msg(msg, msg_size, "target \"%s\": glCreateTextures failed", label);
        return 0;
    }
    if (samples > 1)
        gl->TextureStorage2DMultisample(tex, (GLsizei)samples, f->internal_format, (GLsizei)desc->width,
                                        (GLsizei)desc->height, GL_TRUE);
    else
        gl->TextureStorage2D(tex, (GLsizei)levels, f->internal_format, (GLsizei)desc->width, (GLsizei)desc->height);
    /* Storage that failed (GL_OUT_OF_MEMORY, ...) leaves the texture mutable; checking this avoids
     * glGetError, which would also consume the caller's pending errors. */
    GLint immutable = GL_FALSE;
    gl->GetTextureParameteriv(tex, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
    if (!immutable) {
        gl->DeleteTextures(1, &tex);
        tl__msg(msg, msg_size, "target \"%s\": could not allocate %ux%u %s x %u samples (%zu bytes)", label,
                (unsigned)desc->width, (unsigned)desc->height, f->name, (unsigned)samples,
                (size_t)desc->width * desc->height * f->bytes_per_pixel * samples);
        return 0;
    }
    return tex;
}

tl_result tl__target_create_levels(const GladGLContext *gl, const tl__target_desc *desc, uint32_t levels, int linear,
                                   tl__target *out, char *msg, size_t msg_size)
{
    tl__msg(msg, msg_size, "%s", "");
    if (out) memset(out, 0, sizeof *out);
    if (!gl || !desc || !out) {
        tl__msg(msg, msg_size, "tl__target_create: NULL %s",
                !gl ? "context" : !desc ? "descriptor" : "output");
        return TL_ERROR_INVALID_ARGUMENT;
    }
    const char *label = desc->label ? desc->label : "";
    const tl__format_info *f = tl__format_lookup(desc->internal_format);
    tl_result res = tl__target_check(gl, desc, label, f, msg, msg_size);
    if (res != TL_OK) return res;
    uint32_t samples = desc->samples > 1 ? desc->samples : 1u;
    uint32_t side = desc->width > desc->height ? desc->width : desc->height;
    if (!levels || samples > 1) levels = 1;
    while (levels > 1 && (side >> (levels - 1)) == 0) levels--; /* GL's chain ends at 1x1 */
    GLuint tex = tl__target_storage(gl, desc, label, f, levels, samples, msg, msg_size);
    if (!tex) return TL_ERROR_GL;
    if (samples == 1) tl__texture_sampling(gl, tex, linear ? GL_LINEAR : GL_NEAREST);
    tl__gl_label(gl, GL_TEXTURE, tex, desc->label);

    out->texture = tex;
    out->internal_format = f->internal_format;
    out->width = desc->width;
    out->height = desc->height;
    out->levels = levels;
    out->samples = samples;
    out->bytes = 0;
    for (uint32_t k = 0; k < levels; k++) {
        size_t w = desc->width >> k, h = desc->height >> k;
        out->bytes += (w ? w : 1u) * (h ? h : 1u) * f->bytes_per_pixel * samples;
    }
    return TL_OK;
}

tl_result tl__target_create_view(const GladGLContext *gl, const tl__target *storage, GLenum internal_format,
                                 const char *label, tl__target *out, char *msg, size_t msg_size)
{
    tl__msg(msg, msg_size, "%s", "");
    memset(out, 0, sizeof *out);
    unsigned cls = tl__format_view_class(internal_format);
    if (!storage || !storage->texture || !cls || cls != tl__format_view_class(storage->internal_format)) {
        tl__msg(msg, msg_size, "view \"%s\": format 0x%04x cannot view the storage's 0x%04x", label ? label : "",
                (unsigned)internal_format, storage ? (unsigned)storage->internal_format : 0u);
        return TL_ERROR_INVALID_ARGUMENT;
    }
    GLuint tex = 0;
    int ms = storage->samples > 1;
    gl->GenTextures(1, &tex); /* a view needs a name that was never bound: not glCreateTextures */
    gl->TextureView(tex, ms ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D, storage->texture, internal_format, 0, 1, 0, 1);
    if (!ms) tl__texture_sampling(gl, tex, GL_NEAREST);
    tl__gl_label(gl, GL_TEXTURE, tex, label);
    out->texture = tex;
    out->internal_format = internal_format;
    out->width = storage->width;
    out->height = storage->height;
    out->levels = 1;
    out->samples = ms ? storage->samples : 1u;
    out->bytes = 0;
    return TL_OK;
}

tl_result tl__target_create_level(const GladGLContext *gl, const tl__target *storage, uint32_t level, const char *label,
                                  tl__target *out, char *msg, size_t msg_size)
{
    tl__msg(msg, msg_size, "%s", "");
    memset(out, 0, sizeof *out);
    if (!storage || !storage->texture || level >= storage->levels) {
        tl__msg(msg, msg_size, "view \"%s\": level %u of a storage with %u", label ? label : "", (unsigned)level,
                storage ? (unsigned)storage->levels : 0u);
        return TL_ERROR_INVALID_ARGUMENT;
    }
    GLuint tex = 0;
    gl->GenTextures(1, &tex);
    gl->TextureView(tex, GL_TEXTURE_2D, storage->texture, storage->internal_format, level, 1, 0, 1);
    tl__texture_sampling(gl, tex, GL_LINEAR);
    tl__gl_label(gl, GL_TEXTURE, tex, label);
    uint32_t w = storage->width >> level, h = storage->height >> level;
    out->texture = tex;
    out->internal_format = storage->internal_format;
    out->width = w ? w : 1u;
    out->height = h ? h : 1u;
    out->levels = 1;
    out->samples = 1;
    return TL_OK;
}

void tl__target_destroy(const GladGLContext *gl, tl__target *t)
{
    if (!t) return;
    if (gl && t->texture) gl->DeleteTextures(1, &t->texture);
    memset(t, 0, sizeof *t);
}

/* Bytes per pixel of a client-side pixel transfer, 0 if this layer does not know the pair. */
static size_t tl__transfer_bytes(GLenum format, GLenum type)
{
    size_t channels;
    switch (format) {
    case GL_RED: case GL_RED_INTEGER: case GL_DEPTH_COMPONENT: case GL_STENCIL_INDEX:
        channels = 1; break;
    case GL_RG: case GL_RG_INTEGER: channels = 2; break;
    case GL_RGB: case GL_RGB_INTEGER: channels = 3; break;
    case GL_RGBA: case GL_RGBA_INTEGER: channels = 4; break;
    case GL_DEPTH_STENCIL: channels = 1; break; /* only packed types below */
    default: return 0;
    }
    switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return channels;
    case GL_UNSIGNED_SHORT: case GL_SHORT: case GL_HALF_FLOAT: return 2 * channels;
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: return 4 * channels;
    case GL_UNSIGNED_INT_2_10_10_10_REV: case GL_UNSIGNED_INT_10F_11F_11F_REV:
    case GL_UNSIGNED_INT_24_8: return 4;
    case GL_FLOAT_32_UNSIGNED_INT_24_8_REV: return 8;
    default: return 0;
    }
}

/* A multisampled target resolved into a one-sample copy by a blit: colour averaged over the
 * samples, depth as GL's resolve picks one sample. The state a blit obeys (scissor, rasterizer
 * discard, colour and depth masks) is set for it and restored. */
static tl_result tl__target_resolve(const GladGLContext *gl, const tl__target *t, tl__target *out, char *msg,
                                    size_t msg_size)
{
    const tl__format_info *f = tl__format_lookup(t->internal_format);
    tl__target_desc td = {"target.resolve", t->internal_format, t->width, t->height, 1};
    tl_result res = tl__target_create(gl, &td, out, msg, msg_size);
    if (res != TL_OK || !f) return res != TL_OK ? res : TL_ERROR_UNSUPPORTED;
    int color = f->kind == TL__FORMAT_COLOR;
    const tl__target *src = t;
    GLuint fbo[2] = {0, 0};
    res = tl__framebuffer_create(gl, "fbo.resolve.read", color ? &src : NULL, color, color ? NULL : t, &fbo[0], msg, msg_size);
    const tl__target *dst = out;
    if (res == TL_OK)
        res = tl__framebuffer_create(gl, "fbo.resolve.draw", color ? &dst : NULL, color, color ? NULL : out, &fbo[1], msg, msg_size);
    if (res == TL_OK) {
        GLboolean scissor = gl->IsEnabled(GL_SCISSOR_TEST), discard = gl->IsEnabled(GL_RASTERIZER_DISCARD);
        GLboolean cmask[4], dmask;
        gl->GetBooleani_v(GL_COLOR_WRITEMASK, 0, cmask);
        gl->GetBooleanv(GL_DEPTH_WRITEMASK, &dmask);
        gl->Disable(GL_SCISSOR_TEST);
        gl->Disable(GL_RASTERIZER_DISCARD);
        gl->ColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        gl->DepthMask(GL_TRUE);
        gl->BlitNamedFramebuffer(fbo[0], fbo[1], 0, 0, (GLint)t->width, (GLint)t->height, 0, 0, (GLint)t->width,
                                 (GLint)t->height, color ? GL_COLOR_BUFFER_BIT : GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        if (scissor) gl->Enable(GL_SCISSOR_TEST);
        if (discard) gl->Enable(GL_RASTERIZER_DISCARD);
        gl->ColorMaski(0, cmask[0], cmask[1], cmask[2], cmask[3]);
        gl->DepthMask(dmask);
    }
    tl__framebuffer_destroy(gl, &fbo[0]);
    tl__framebuffer_destroy(gl, &fbo[1]);
    if (res != TL_OK) tl__target_destroy(gl, out);
    return res;
}

tl_result tl__target_read(const GladGLContext *gl, const tl__target *t, GLenum format, GLenum type,
                          void *dst, size_t dst_size, char *msg, size_t msg_size)
{
    tl__msg(msg, msg_size, "%s", "");
    if (!gl || !t || !t->texture || !dst) {
        tl__msg(msg, msg_size, "%s", "tl__target_read: NULL context, target, texture or buffer");
        return TL_ERROR_INVALID_ARGUMENT;
    }
    const tl__format_info *f = tl__format_lookup(t->internal_format);
    if (format == 0 && type == 0 && f) {
        format = f->format;
        type = f->type;
    }
    size_t bpp = tl__transfer_bytes(format, type);
    if (bpp == 0) {
        tl__msg(msg, msg_size, "tl__target_read: unknown transfer format 0x%04x / type 0x%04x",
                (unsigned)format, (unsigned)type);
        return TL_ERROR_UNSUPPORTED;
    }
    size_t need = bpp * t->width * t->height;
    if (dst_size < need || need > 0x7fffffff) {
        tl__msg(msg, msg_size, "tl__target_read: %ux%u needs %zu bytes, buffer has %zu",
                (unsigned)t->width, (unsigned)t->height, need, dst_size);
        return TL_ERROR_LIMIT;
    }
    tl__target resolved;
    memset(&resolved, 0, sizeof resolved);
    if (t->samples > 1) {
        tl_result res = tl__target_resolve(gl, t, &resolved, msg, msg_size);
        if (res != TL_OK) return res;
        t = &resolved;
    }
    tl__pixel_store saved; /* the application's pack state and buffer come back afterwards */
    tl__pixel_store_enter(gl, 0, &saved);
    gl->GetTextureImage(t->texture, 0, format, type, (GLsizei)need, dst);
    tl__pixel_store_leave(gl, &saved);
    tl__target_destroy(gl, &resolved);
    return TL_OK;
}

const char *tl__framebuffer_status_string(GLenum status)
{
    switch (status) {
    case GL_FRAMEBUFFER_COMPLETE: return "GL_FRAMEBUFFER_COMPLETE";
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
        return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS: return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
    case 0: return "glCheckNamedFramebufferStatus failed";
    default: return "unknown framebuffer status";
    }
}

/* Every attachment created, of its kind (colour or depth) and of the first one's size. */
static tl_result tl__framebuffer_check(const tl__target *const *colors, size_t color_count, const tl__target *depth,
                                       const char *label, char *msg, size_t msg_size)
{
    const tl__target *first = color_count ? colors[0] : depth;
    for (size_t i = 0; i <= color_count; i++) {
        const tl__target *t = i < color_count ? colors[i] : depth;
        if (!t) {
            if (i < color_count) {
                tl__msg(msg, msg_size, "framebuffer \"%s\": colour target %zu is NULL", label, i);
                return TL_ERROR_INVALID_ARGUMENT;
            }
            continue;
        }
        const tl__format_info *f = tl__format_lookup(t->internal_format);
        bool want_color = i < color_count;
        if (!t->texture || !f || (f->kind == TL__FORMAT_COLOR) != want_color) {
            tl__msg(msg, msg_size, "framebuffer \"%s\": %s target %zu is %s", label,
                    want_color ? "colour" : "depth", i,
                    !t->texture || !f ? "not created" : "of the wrong kind");
            return TL_ERROR_INVALID_ARGUMENT;
        }
        if (t->width != first->width || t->height != first->height) {
            tl__msg(msg, msg_size, "framebuffer \"%s\": target sizes differ (%ux%u and %ux%u)",
                    label, (unsigned)first->width, (unsigned)first->height, (unsigned)t->width,
                    (unsigned)t->height);
            return TL_ERROR_INVALID_ARGUMENT;
        }
    }
    return TL_OK;
}

tl_result tl__framebuffer_create(const GladGLContext *gl, const char *label,
                                 const tl__target *const *colors, size_t color_count,
                                 const tl__target *depth, GLuint *out_fbo, char *msg,
                                 size_t msg_size)
{
    tl__msg(msg, msg_size, "%s", "");
    if (out_fbo) *out_fbo = 0;
    if (!label) label = "";
    if (!gl || !out_fbo || (color_count && !colors)) {
        tl__msg(msg, msg_size, "%s", "tl__framebuffer_create: NULL context, output or colors");
        return TL_ERROR_INVALID_ARGUMENT;
    }
    GLint max_attachments = 0, max_draw_buffers = 0;
    gl->GetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &max_attachments);
    gl->GetIntegerv(GL_MAX_DRAW_BUFFERS, &max_draw_buffers);
    size_t limit = TL__FRAMEBUFFER_MAX_COLORS;
    if ((size_t)max_attachments < limit) limit = (size_t)max_attachments;
    if ((size_t)max_draw_buffers < limit) limit = (size_t)max_draw_buffers;
    if (color_count > limit) {
        tl__msg(msg, msg_size, "framebuffer \"%s\": %zu colour targets, the limit is %zu", label,
                color_count, limit);
        return TL_ERROR_LIMIT;
    }
    if (color_count == 0 && !depth) {
        tl__msg(msg, msg_size, "framebuffer \"%s\": no target", label);
        return TL_ERROR_INVALID_ARGUMENT;
    }
    tl_result res = tl__framebuffer_check(colors, color_count, depth, label, msg, msg_size);
    if (res != TL_OK) return res;

    GLuint fbo = 0;
    gl->CreateFramebuffers(1, &fbo);
    if (!fbo) {
        tl__msg(msg, msg_size, "framebuffer \"%s\": glCreateFramebuffers failed", label);
        return TL_ERROR_GL;
    }
    GLenum draw[TL__FRAMEBUFFER_MAX_COLORS];
    for (size_t i = 0; i < color_count; i++) {
        draw[i] = GL_COLOR_ATTACHMENT0 + (GLenum)i;
        gl->NamedFramebufferTexture(fbo, draw[i], colors[i]->texture, 0);
    }
    if (depth) {
        const tl__format_info *f = tl__format_lookup(depth->internal_format);
        GLenum attachment = f->kind == TL__FORMAT_DEPTH_STENCIL ? GL_DEPTH_STENCIL_ATTACHMENT
                            : f->kind == TL__FORMAT_STENCIL     ? GL_STENCIL_ATTACHMENT
                                                                : GL_DEPTH_ATTACHMENT;
        gl->NamedFramebufferTexture(fbo, attachment, depth->texture, 0);
    }
    if (color_count) {
        gl->NamedFramebufferDrawBuffers(fbo, (GLsizei)color_count, draw);
        gl->NamedFramebufferReadBuffer(fbo, GL_COLOR_ATTACHMENT0);
    } else {
        gl->NamedFramebufferDrawBuffer(fbo, GL_NONE);
        gl->NamedFramebufferReadBuffer(fbo, GL_NONE);
    }
    GLenum status = gl->CheckNamedFramebufferStatus(fbo, GL_DRAW_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        gl->DeleteFramebuffers(1, &fbo);
        tl__msg(msg, msg_size, "framebuffer \"%s\" is incomplete: %s (0x%04x)", label,
                tl__framebuffer_status_string(status), (unsigned)status);
        return TL_ERROR_GL;
    }
    tl__gl_label(gl, GL_FRAMEBUFFER, fbo, label);
    *out_fbo = fbo;
    return TL_OK;
}

void tl__framebuffer_destroy(const GladGLContext *gl, GLuint *fbo)
{
    if (!fbo) return;
    if (gl && *fbo) gl->DeleteFramebuffers(1, fbo);
    *fbo = 0;
}
