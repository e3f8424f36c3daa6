/* The per-frame streaming buffer (stream.h). */
#include "gl/stream.h"

#include <string.h>

static void tl__stream_wait(const GladGLContext *gl, tl__stream *s, unsigned region)
{
    GLsync f = s->fences[region];
    if (!f) return;
    GLenum r = gl->ClientWaitSync(f, 0, 0);
    if (r == GL_TIMEOUT_EXPIRED) {
        s->waits++;
        while (gl->ClientWaitSync(f, GL_SYNC_FLUSH_COMMANDS_BIT, 1000000000u) == GL_TIMEOUT_EXPIRED) {}
    }
    gl->DeleteSync(f);
    s->fences[region] = NULL;
}

static tl_result tl__stream_grow(const GladGLContext *gl, tl__stream *s, size_t need, const char *label)
{
    size_t size = s->region_size ? s->region_size : 64 * 1024;
    while (size < need) size *= 2;
    if (s->buffer) gl->DeleteBuffers(1, &s->buffer); /* the GPU keeps what queued frames read */
    for (unsigned i = 0; i < TL__STREAM_REGIONS; i++)
        if (s->fences[i]) gl->DeleteSync(s->fences[i]);
    memset(s->fences, 0, sizeof s->fences);
    const GLbitfield flags = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    gl->CreateBuffers(1, &s->buffer);
    gl->NamedBufferStorage(s->buffer, (GLsizeiptr)(size * TL__STREAM_REGIONS), NULL, flags);
    s->map = (uint8_t *)gl->MapNamedBufferRange(s->buffer, 0, (GLsizeiptr)(size * TL__STREAM_REGIONS), flags);
    if (!s->map) {
        gl->DeleteBuffers(1, &s->buffer);
        memset(s, 0, sizeof *s);
        return TL_ERROR_GL;
    }
    tl__gl_label(gl, GL_BUFFER, s->buffer, label);
    s->region_size = size;
    return TL_OK;
}

tl_result tl__stream_begin(const GladGLContext *gl, tl__stream *s, size_t need, const char *label)
{
    if (!s->buffer || need > s->region_size) {
        tl_result res = tl__stream_grow(gl, s, need, label);
        if (res != TL_OK) return res;
        s->current = 0;
    } else {
        s->current = (s->current + 1) % TL__STREAM_REGIONS;
    }
    tl__stream_wait(gl, s, s->current);
    s->used = 0;
    s->bind_count = 0;
    return TL_OK;
}

void tl__stream_bind_range(const GladGLContext *gl, tl__stream *s, GLenum target, GLuint index, size_t offset,
                           size_t size)
{
    gl->BindBufferRange(target, index, s->buffer, (GLintptr)offset, (GLsizeiptr)size);
    if (s->bind_count < TL__STREAM_MAX_BINDS) s->binds[s->bind_count++] = (tl__stream_bind){target, index, 0, offset, size};
}

void tl__stream_bind_buffer(const GladGLContext *gl, tl__stream *s, GLenum target, GLuint index, GLuint buffer)
{
    gl->BindBufferBase(target, index, buffer);
    if (s->bind_count < TL__STREAM_MAX_BINDS) s->binds[s->bind_count++] = (tl__stream_bind){target, index, buffer, 0, 0};
}

void tl__stream_rebind(const GladGLContext *gl, const tl__stream *s)
{
    for (size_t i = 0; i < s->bind_count; i++) {
        const tl__stream_bind *b = &s->binds[i];
        if (b->buffer) gl->BindBufferBase(b->target, b->index, b->buffer);
        else gl->BindBufferRange(b->target, b->index, s->buffer, (GLintptr)b->offset, (GLsizeiptr)b->size);
    }
}

void *tl__stream_reserve(tl__stream *s, size_t size, size_t align, size_t *offset)
{
    size_t at = (s->used + align - 1) / align * align;
    if (!s->map || at + size > s->region_size) return NULL;
    s->used = at + size;
    *offset = s->current * s->region_size + at;
    return s->map + *offset;
}

void tl__stream_end(const GladGLContext *gl, tl__stream *s)
{
    if (!s->buffer) return;
    if (s->fences[s->current]) gl->DeleteSync(s->fences[s->current]);
    s->fences[s->current] = gl->FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

void tl__stream_destroy(const GladGLContext *gl, tl__stream *s)
{
    for (unsigned i = 0; i < TL__STREAM_REGIONS; i++)
        if (s->fences[i]) gl->DeleteSync(s->fences[i]);
    if (s->buffer) gl->DeleteBuffers(1, &s->buffer);
    memset(s, 0, sizeof *s);
}
