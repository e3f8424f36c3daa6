/* Private GL layer: the glad2 loader (one GladGLContext per GL context, --mx), programs built from
 * the shaders embedded at build time, render targets that account for their own bytes, timer
 * queries and KHR_debug labels/groups. Everything takes the loaded context explicitly; nothing
 * here creates a context, prints, aborts or keeps global state.
 *
 * Messages: calls that can fail take an optional `char *msg, size_t msg_size` buffer (NULL/0 to
 * ignore) that receives one detailed line (or a full info log for programs), always
 * NUL-terminated and truncated to fit. */
#ifndef TL_GL_GL_H
#define TL_GL_GL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <glad/gl.h>

#include "thinlight/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- loading, errors, KHR_debug ------------------------------------------------------------- */

/* The version the GL layer requires (direct state access everywhere). */
#define TL__GL_MIN_MAJOR 4
#define TL__GL_MIN_MINOR 5

/* Loads `gl` from the current context through `load` (e.g. tl_context_get_proc_address wrapped
 * to GLADuserptrloadfunc). TL_ERROR_GL when nothing loads (no current context),
 * TL_ERROR_UNSUPPORTED when the context is below 4.5; the message names the version found. */
tl_result tl__gl_load(GladGLContext *gl, GLADuserptrloadfunc load, void *user, char *msg,
                      size_t msg_size);

/* "GL_INVALID_ENUM", ...; never NULL. */
const char *tl__gl_error_string(GLenum error);

/* True when glObjectLabel / glPushDebugGroup can be called (GL 4.3 or KHR_debug, and loaded). */
bool tl__gl_has_debug(const GladGLContext *gl);

/* glObjectLabel when available (label NULL or "" does nothing); truncated to GL_MAX_LABEL_LENGTH. */
void tl__gl_label(const GladGLContext *gl, GLenum identifier, GLuint name, const char *label);

/* glPush/PopDebugGroup (GL_DEBUG_SOURCE_APPLICATION) when available, no-ops otherwise. Use the
 * same names as the objects the group touches, so a capture reads like the design. Pushes beyond
 * GL_MAX_DEBUG_GROUP_STACK_DEPTH (at least 64) raise GL_STACK_OVERFLOW in the context. */
void tl__gl_debug_push(const GladGLContext *gl, const char *name);
void tl__gl_debug_pop(const GladGLContext *gl);

/* ---- embedded shaders and programs ---------------------------------------------------------- */

/* The text of shaders/<name> as embedded at build time (e.g. "codec.glsl"), NULL if absent. */
const char *tl__shader_source(const char *name);

/* One stage: `source` when non-NULL, else the embedded file `name`. `name` labels the stage in
 * logs either way. */
typedef struct tl__shader_stage {
    GLenum type; /* GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER, ...; 0 ends the list */
    const char *name;
    const char *source;
} tl__shader_stage;

#define TL__PROGRAM_MAX_STAGES 6

typedef struct tl__program_desc {
    const char *label;                                /* glObjectLabel of the program */
    tl__shader_stage stages[TL__PROGRAM_MAX_STAGES]; /* first entry with type 0 ends the list */
    const char *const *defines; /* "NAME", "NAME=VALUE" or "NAME VALUE" (permutation switches) */
    size_t define_count;
} tl__program_desc;

/* Each stage is compiled as
 *     #version 450 core
 *     #define <each define>
 *     <source with #include "file.glsl" expanded from the embedded table>
 * Includes: a line `#include "name"` (optionally followed by a // comment) is replaced by that
 * embedded file, each file at most once per stage (implicit include guard), nested up to 8 deep;
 * they are expanded before the GLSL preprocessor runs, so neither #if nor a block comment hides
 * them (a line whose first non-blank token is #include is one). A `#version`
 * line inside a file is dropped (the header above wins). `#line` keeps log line numbers right:
 * source-string 0 is the stage, N is embedded file N (the log lists the mapping).
 * Results: TL_ERROR_INVALID_ARGUMENT (no stage, unknown embedded name, bad define),
 * TL_ERROR_PARSE (an #include that is malformed or names no embedded file), TL_ERROR_LIMIT (too
 * many includes/defines), TL_ERROR_GL (compile or link failed: `log` holds the info log). On
 * success `log` holds compiler warnings, if any, else "". */
tl_result tl__program_build(const GladGLContext *gl, const tl__program_desc *desc,
                            GLuint *out_program, char *log, size_t log_size);

/* ---- formats and render targets ------------------------------------------------------------- */

typedef enum tl__format_kind {
    TL__FORMAT_COLOR = 1,
    TL__FORMAT_DEPTH,
    TL__FORMAT_DEPTH_STENCIL,
    TL__FORMAT_STENCIL
} tl__format_kind;

typedef struct tl__format_info {
    GLenum internal_format;
    const char *name;         /* "GL_RGBA16F" */
    uint8_t bytes_per_pixel;  /* storage the driver allocates (D24 and D32F_S8 padded to 4 / 8) */
    uint8_t kind;             /* tl__format_kind */
    GLenum format, type;      /* natural pixel-transfer pair for readback */
} tl__format_info;

/* The table entry for a sized internal format, NULL for formats the table does not know
 * (unsized and non-renderable 3-channel formats are left out on purpose). */
const tl__format_info *tl__format_lookup(GLenum internal_format);
/* Bytes per pixel from the table, 0 for unknown formats. */
size_t tl__format_bytes_per_pixel(GLenum internal_format);
/* The texture-view compatibility class of a colour format (GL 4.5 table 8.22: uncompressed colour
 * formats of the same size share a class), as its size in bits; 0 for depth and stencil formats
 * and unknown ones, which share memory with nothing. */
unsigned tl__format_view_class(GLenum internal_format);

typedef struct tl__target_desc {
    const char *label;      /* glObjectLabel of the texture, e.g. "gbuffer.rt0" */
    GLenum internal_format; /* a format tl__format_lookup knows */
    uint32_t width, height; /* 1 .. GL_MAX_TEXTURE_SIZE */
    uint32_t samples;       /* 0 or 1: GL_TEXTURE_2D; 2 .. GL_MAX_SAMPLES: GL_TEXTURE_2D_MULTISAMPLE (one level, fixed sample locations) */
} tl__target_desc;

typedef struct tl__target {
    GLuint texture; /* immutable GL_TEXTURE_2D, nearest filtering (or linear), clamp to edge */
    GLenum internal_format;
    uint32_t width, height; /* of level 0 */
    uint32_t levels;
    uint32_t samples; /* 1, or the samples of a GL_TEXTURE_2D_MULTISAMPLE texture */
    size_t bytes; /* bytes_per_pixel * width * height over its levels, times its samples */
} tl__target;

/* TL_ERROR_UNSUPPORTED for unknown formats, TL_ERROR_LIMIT beyond GL_MAX_TEXTURE_SIZE,
 * TL_ERROR_GL when the storage could not be allocated. `out` is zeroed on failure. */
tl_result tl__target_create(const GladGLContext *gl, const tl__target_desc *desc, tl__target *out,
                            char *msg, size_t msg_size);
/* The same with `levels` mip levels (0 means 1; fewer when the size ends at 1x1 first) and, with
 * `linear`, bilinear filtering of level 0 instead of nearest. */
tl_result tl__target_create_levels(const GladGLContext *gl, const tl__target_desc *desc, uint32_t levels, int linear,
                                   tl__target *out, char *msg, size_t msg_size);
/* A texture view (glTextureView) of `storage`'s level 0 with a view-compatible format: same size,
 * same memory. TL_ERROR_INVALID_ARGUMENT for formats of different view classes. The view
 * accounts for no bytes of its own (bytes = 0); the storage does. */
tl_result tl__target_create_view(const GladGLContext *gl, const tl__target *storage, GLenum internal_format,
                                 const char *label, tl__target *out, char *msg, size_t msg_size);
/* A one-level view of `storage`'s mip `level` (same format, linear filtering, clamp to edge), to
 * sample one level while another is rendered, or to attach it: width and height are the level's. */
tl_result tl__target_create_level(const GladGLContext *gl, const tl__target *storage, uint32_t level, const char *label,
                                  tl__target *out, char *msg, size_t msg_size);
/* Deletes the texture and zeroes `t`; a zeroed target is fine. */
void tl__target_destroy(const GladGLContext *gl, tl__target *t);

/* Reads level 0 into `dst` tightly packed (pack alignment 1, no pack buffer; both restored).
 * `format`/`type` 0 mean the table's natural pair. TL_ERROR_LIMIT when dst_size is too small. */
tl_result tl__target_read(const GladGLContext *gl, const tl__target *t, GLenum format, GLenum type,
                          void *dst, size_t dst_size, char *msg, size_t msg_size);

#define TL__FRAMEBUFFER_MAX_COLORS 8

/* A framebuffer with colors[i] at GL_COLOR_ATTACHMENTi (draw buffers 0..n-1, read buffer 0) and
 * an optional depth / depth-stencil / stencil target. All targets must share one size. Fails with
 * TL_ERROR_GL naming the completeness status (e.g. GL_FRAMEBUFFER_UNSUPPORTED) when incomplete. */
tl_result tl__framebuffer_create(const GladGLContext *gl, const char *label,
                                 const tl__target *const *colors, size_t color_count,
                                 const tl__target *depth, GLuint *out_fbo, char *msg,
                                 size_t msg_size);
void tl__framebuffer_destroy(const GladGLContext *gl, GLuint *fbo);
const char *tl__framebuffer_status_string(GLenum status);

/* ---- timer queries -------------------------------------------------------------------------- */

typedef enum tl__timer_mode {
    TL__TIMER_NONE = 0,  /* the context has no timer bits: begin/end do nothing */
    TL__TIMER_TIMESTAMP, /* two GL_TIMESTAMP counters: spans may nest and overlap */
    TL__TIMER_ELAPSED    /* GL_TIME_ELAPSED: spans of this kind must not nest */
} tl__timer_mode;

typedef struct tl__timer {
    GLuint queries[2];
    tl__timer_mode mode;
    GLint bits;   /* GL_QUERY_COUNTER_BITS of the query type in use, 0 in TL__TIMER_NONE */
    int state;    /* private: 0 idle, 1 begun, 2 ended (a result is pending or read) */
} tl__timer;

/* Prefers GL_TIMESTAMP, falls back to GL_TIME_ELAPSED, then to TL__TIMER_NONE (still TL_OK: a
 * zeroed tl__timer is a valid "no timing" timer). */
tl_result tl__timer_create(const GladGLContext *gl, const char *label, tl__timer *out);
void tl__timer_begin(const GladGLContext *gl, tl__timer *t);
void tl__timer_end(const GladGLContext *gl, tl__timer *t);
/* GPU time between begin and end in nanoseconds. With `wait` blocks until the result exists;
 * without, *out_ready says whether it did. TL_ERROR_UNSUPPORTED in TL__TIMER_NONE,
 * TL_ERROR_INVALID_ARGUMENT when no begin/end pair was recorded. */
tl_result tl__timer_read(const GladGLContext *gl, tl__timer *t, bool wait, bool *out_ready,
                         uint64_t *out_ns);
void tl__timer_destroy(const GladGLContext *gl, tl__timer *t);

#ifdef __cplusplus
}
#endif
#endif
