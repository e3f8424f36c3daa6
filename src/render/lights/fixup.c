/* The light scale's and MSAA's edge fix-up count (docs/frame.md, "Light at reduced resolution"):
 * the buffer the material pass counts the pixels (or samples) it re-lit in, and the read-back of
 * the count a few frames later, as the tiles' counters. The count is all it holds: every re-lit
 * pixel is lit where it is found, so nothing of the image depends on the order of the adds. */
#include <string.h>

#include "lights.h"

void tl__fixup_release(tl__device *dev, tl__fixup *f)
{
    const GladGLContext *gl = &dev->gl;
    for (int i = 0; i < TL__QUERY_RING; i++)
        if (f->fences[i]) gl->DeleteSync(f->fences[i]);
    GLuint buffers[2] = {f->buffer, f->readback};
    for (int i = 0; i < 2; i++)
        if (buffers[i]) gl->DeleteBuffers(1, &buffers[i]);
    memset(f, 0, sizeof *f);
}

tl_result tl__fixup_configure(tl__device *dev, tl__fixup *f)
{
    if (f->buffer) return TL_OK;
    const GladGLContext *gl = &dev->gl;
    gl->CreateBuffers(1, &f->buffer);
    gl->NamedBufferStorage(f->buffer, 16, NULL, 0);
    tl__gl_label(gl, GL_BUFFER, f->buffer, "buffer.fixup");
    const GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    gl->CreateBuffers(1, &f->readback);
    gl->NamedBufferStorage(f->readback, TL__QUERY_RING * 16, NULL, flags);
    f->readback_map = (const uint32_t *)gl->MapNamedBufferRange(f->readback, 0, TL__QUERY_RING * 16, flags);
    tl__gl_label(gl, GL_BUFFER, f->readback, "buffer.fixup.readback");
    if (!f->readback_map) return tl__fail(dev, TL_ERROR_GL, "renderer: could not map the fix-up counters' read-back");
    return TL_OK;
}

void tl__fixup_bind(tl__device *dev, tl__fixup *f)
{
    if (f->buffer) dev->gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TL__SSBO_FIXUP, f->buffer);
}

/* Counters to 0. */
void tl__fixup_begin(const GladGLContext *gl, tl__fixup *f)
{
    static const GLuint start[4] = {0u, 0u, 0u, 0u};
    if (!f->buffer) return;
    gl->ClearNamedBufferSubData(f->buffer, GL_RGBA32UI, 0, 16, GL_RGBA_INTEGER, GL_UNSIGNED_INT, start);
    gl->MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void tl__fixup_end(const GladGLContext *gl, tl__fixup *f, uint64_t frame)
{
    if (!f->buffer) return;
    gl->MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    unsigned s = (unsigned)(frame % TL__QUERY_RING);
    gl->CopyNamedBufferSubData(f->buffer, f->readback, 0, (GLintptr)(16 * s), 16);
    if (f->fences[s]) gl->DeleteSync(f->fences[s]);
    f->fences[s] = gl->FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    f->fence_frame[s] = frame;
}

void tl__fixup_collect(tl__device *dev, tl__fixup *f, uint32_t pixels, tl_frame_stats *st)
{
    unsigned s = (unsigned)(st->frame % TL__QUERY_RING);
    if (!f->readback_map || f->fence_frame[s] != st->frame || !f->fences[s]) return;
    GLenum w = dev->gl.ClientWaitSync(f->fences[s], GL_SYNC_FLUSH_COMMANDS_BIT, 1000000000u);
    if (w != GL_ALREADY_SIGNALED && w != GL_CONDITION_SATISFIED) return;
    st->relit_pixels = f->readback_map[4 * s + 3];
    st->relit_fraction = pixels ? (double)st->relit_pixels / (double)pixels : 0.0;
}
