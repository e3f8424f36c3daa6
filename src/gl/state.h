/* A cache of the GL state the renderer changes (sokol_gfx keeps one like it): a pass declares the
 * pipeline state it needs and only what differs from the last applied state becomes GL calls.
 * The cache starts every frame "unknown", since the caller may have changed anything between
 * frames, and tl__state_reset leaves the state tl_renderer_render_to promises. */
#ifndef TL_GL_STATE_H
#define TL_GL_STATE_H

#include <stdint.h>

#include "gl/gl.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum tl__depth_test {
    TL__DEPTH_OFF = 0,
    TL__DEPTH_LESS,    /* nearer passes: LESS, GREATER with reversed Z */
    TL__DEPTH_EQUAL,   /* the same surface as an earlier pass */
    TL__DEPTH_LEQUAL,  /* in front of or on the surface: LEQUAL, GEQUAL reversed */
    TL__DEPTH_GEQUAL   /* behind or on the surface: GEQUAL, LEQUAL reversed */
} tl__depth_test;

typedef enum tl__blend {
    TL__BLEND_OFF = 0,
    TL__BLEND_ADD,  /* ONE, ONE */
    TL__BLEND_ALPHA /* SRC_ALPHA, ONE_MINUS_SRC_ALPHA for colour; destination alpha kept */
} tl__blend;

typedef enum tl__cull { TL__CULL_OFF = 0, TL__CULL_BACK, TL__CULL_FRONT } tl__cull;

/* Fixed-function state of a pass (or of one draw inside it). */
typedef struct tl__pipeline {
    uint8_t depth_test;  /* tl__depth_test */
    uint8_t depth_write; /* 0/1 */
    uint8_t color_write; /* 0/1: all four channels */
    uint8_t blend;       /* tl__blend */
    uint8_t cull;        /* tl__cull */
    uint8_t depth_clamp; /* 0/1 */
    uint8_t clip_zero_one; /* 0/1: glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) (reversed Z) */
} tl__pipeline;

typedef struct tl__state {
    int known;           /* 0: the next apply sets everything */
    int reversed;        /* depth comparisons flipped (reversed Z) */
    tl__pipeline p;
    GLuint program, vertex_array, framebuffer;
    GLint viewport[4];
} tl__state;

/* Enters the renderer's GL work (a frame, apply_fxaa): sets every piece of fixed-function state a
 * pass depends on but never changes to GL's initial value (front face, depth range, logic op,
 * polygon offset and mode, rasteriser discard, primitive restart, multisample coverage, sRGB
 * writes, clip distances, provoking vertex, stencil write mask, dither; docs/renderer.md, "The GL
 * contract"), takes sampler objects off units [0, units) and forgets the cache, so that nothing an
 * application left changes the image. */
void tl__state_enter(const GladGLContext *gl, tl__state *s, GLuint units);
/* Forgets what is applied (the next calls set everything). */
void tl__state_invalidate(tl__state *s);
/* Applies a pipeline, issuing only the calls whose state differs. */
void tl__state_apply(const GladGLContext *gl, tl__state *s, const tl__pipeline *p);
void tl__state_program(const GladGLContext *gl, tl__state *s, GLuint program);
void tl__state_vertex_array(const GladGLContext *gl, tl__state *s, GLuint vao);
void tl__state_framebuffer(const GladGLContext *gl, tl__state *s, GLuint fbo);
void tl__state_viewport(const GladGLContext *gl, tl__state *s, GLint x, GLint y, GLsizei w, GLsizei h);
void tl__state_cull(const GladGLContext *gl, tl__state *s, tl__cull cull);
/* The state the renderer promises on return (renderer.h, tl_renderer_render_to): default
 * framebuffer, no program, vertex array, textures or samplers on units [0, units), no buffers
 * on uniform / storage binding points [0, buffers), no images on image units [0, images);
 * capabilities off, masks on, default clip
 * control. The viewport is left as it is. */
void tl__state_reset(const GladGLContext *gl, tl__state *s, GLuint units, GLuint buffers, GLuint images);

/* Pixel-store state of one direction (pack: reading into client memory; unpack: uploading from
 * it) and its pixel buffer binding, saved so that a transfer runs with GL's defaults (alignment
 * 1) and the application's values come back afterwards. */
typedef struct tl__pixel_store {
    int unpack;       /* 0: pack, 1: unpack */
    GLint values[8];  /* swap bytes, LSB first, row length, image height, skip rows, skip pixels,
                         skip images, alignment */
    GLint buffer;     /* GL_PIXEL_PACK_BUFFER or GL_PIXEL_UNPACK_BUFFER binding */
} tl__pixel_store;

/* Saves the direction's state into *saved and sets the defaults with alignment 1 and no buffer. */
void tl__pixel_store_enter(const GladGLContext *gl, int unpack, tl__pixel_store *saved);
/* Puts back what tl__pixel_store_enter saved. */
void tl__pixel_store_leave(const GladGLContext *gl, const tl__pixel_store *saved);

#ifdef __cplusplus
}
#endif
#endif
