/* The environment on the GPU (tl_renderer_set_environment): the image the sky pass draws, its
 * GGX-prefiltered mip chain, the split-sum BRDF table and a uniform block with its irradiance SH,
 * all made on the CPU (ibl_bake.c) when it is set, and bound at fixed units (bindings.h) for every
 * pass of a frame that has one. Owned by the renderer; the passes only sample it. */
#ifndef TL_RENDER_ENVIRONMENT_H
#define TL_RENDER_ENVIRONMENT_H

#include "device.h"

typedef struct tl__environment {
    int loaded;
    GLuint sky, specular, brdf; /* textures: the image, the prefiltered chain, the BRDF table */
    GLuint ubo;                 /* tl_environment_block of shaders/ibl.glsl */
    float intensity;            /* what the block holds now (updated when the options change it) */
    uint32_t width, height;     /* the image's */
    double bake_ms;             /* CPU time the last set took (SH, prefiltering, table, upload) */
} tl__environment;

/* Replaces the environment with `d`'s (NULL removes it). On failure the old one stays. */
tl_result tl__environment_set(tl__device *dev, tl__environment *e, const tl_environment_desc *d);
void tl__environment_release(tl__device *dev, tl__environment *e);
/* Binds its textures and block for a frame (nothing without one) with the options' intensity. */
void tl__environment_bind(const GladGLContext *gl, tl__environment *e, const tl_environment_options *o);

#endif
