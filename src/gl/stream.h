/* Per-frame data without implicit waits: one persistently mapped, coherent buffer split into
 * regions used round-robin by consecutive frames, each guarded by a fence. A frame writes its
 * uniform blocks, instances and light lists into its region and binds ranges of it; the CPU
 * waits only when it is a whole ring of frames ahead of the GPU (the driver would otherwise wait
 * on every glBufferSubData to a buffer that a queued frame still reads). */
#ifndef TL_GL_STREAM_H
#define TL_GL_STREAM_H

#include <stddef.h>
#include <stdint.h>

#include "gl/gl.h"

#ifdef __cplusplus
extern "C" {
#endif

#define TL__STREAM_REGIONS 3
#define TL__STREAM_MAX_BINDS 8

/* A range of the stream bound to an indexed binding point for the current frame. */
typedef struct tl__stream_bind {
    GLenum target; /* GL_UNIFORM_BUFFER or GL_SHADER_STORAGE_BUFFER */
    GLuint index;
    GLuint buffer; /* 0: the stream's */
    size_t offset, size;
} tl__stream_bind;

typedef struct tl__stream {
    GLuint buffer;
    uint8_t *map;          /* the whole buffer, persistently mapped */
    size_t region_size;
    size_t used;           /* bytes used in the current region */
    unsigned current;      /* region of the frame being written */
    GLsync fences[TL__STREAM_REGIONS];
    uint32_t waits;        /* frames that had to wait for their region (statistics) */
    tl__stream_bind binds[TL__STREAM_MAX_BINDS]; /* this frame's bound ranges */
    size_t bind_count;
} tl__stream;

/* Starts a frame that will write at most `need` bytes (alignment padding included): moves to the
 * next region, waits for the GPU to release it if it has not, and grows the buffer when `need`
 * exceeds a region. TL_ERROR_GL when the buffer cannot be created or mapped. */
tl_result tl__stream_begin(const GladGLContext *gl, tl__stream *s, size_t need, const char *label);
/* Space for `size` bytes at an `align`ed offset of the current region (absolute offset in the
 * buffer in *offset); NULL if the frame asked for too little in tl__stream_begin. */
void *tl__stream_reserve(tl__stream *s, size_t size, size_t align, size_t *offset);
/* Binds a range of the stream to an indexed binding point and remembers it for tl__stream_rebind. */
void tl__stream_bind_range(const GladGLContext *gl, tl__stream *s, GLenum target, GLuint index, size_t offset,
                           size_t size);
/* Binds a whole buffer (not the stream's) to an indexed binding point, remembered the same way. */
void tl__stream_bind_buffer(const GladGLContext *gl, tl__stream *s, GLenum target, GLuint index, GLuint buffer);
/* Binds this frame's ranges again (after code the renderer does not control ran). */
void tl__stream_rebind(const GladGLContext *gl, const tl__stream *s);
/* Fences the current region: the GPU work issued so far reads it. */
void tl__stream_end(const GladGLContext *gl, tl__stream *s);
void tl__stream_destroy(const GladGLContext *gl, tl__stream *s);

#ifdef __cplusplus
}
#endif
#endif
