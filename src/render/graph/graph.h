/* The graph module: the frame's plan (plan.c) and its GL objects (graph.c): one texture per memory
 * block with a view per target where a block backs several, one framebuffer per pass, each pass's
 * clears, texture units and programs; and the application passes the plan places. The compile step
 * runs when the plan changes, never per frame, and keeps the textures whose format and size the new
 * plan keeps. */
#ifndef TL_RENDER_GRAPH_H
#define TL_RENDER_GRAPH_H

#include "pass.h"
#include "targets.h"

/* A pass of the current plan as GL objects. */
typedef struct tl__compiled_pass {
    const tl__pass_def *def; /* NULL: application pass */
    int app;                 /* application pass index, -1 for built-in ones */
    const tl_plan_pass *plan;
    const tl__pass_decl *decl;
    GLuint fbo;
    GLuint programs[TL__PASS_MAX_PROGRAMS];
    uint8_t clear_locations[TL__FRAMEBUFFER_MAX_COLORS];
    uint8_t clear_count;
    uint8_t clear_uint;  /* bit k: clear_locations[k] is an integer target (the visibility id), cleared as such */
    uint8_t clear_depth;
    uint8_t bind_count;  /* the targets it samples, on units 0 .. bind_count - 1 in tl_target_id order */
    GLuint textures[TL__TARGET_UNITS];
    uint8_t unit_of[TL_TARGET_COUNT]; /* each target's unit in this pass, TL__UNIT_NONE where it is not sampled */
    uint8_t image_count; /* compute passes: targets written as images, on image units 0 .. image_count - 1 */
    GLuint image_textures[TL__IMAGE_UNITS_USED];
    GLenum image_formats[TL__IMAGE_UNITS_USED];
    uint8_t writes_output;
    /* it writes a target with mip levels: a framebuffer and a one-level view per level
     * (level_fbos[0] is fbo) */
    uint8_t level_count;
    uint32_t level_width, level_height;
    uint32_t fb_width, fb_height; /* its framebuffer's size, the viewport of its draws (0: the frame's) */
    GLuint level_fbos[TL__MAX_LEVELS];
    GLuint level_textures[TL__MAX_LEVELS];
    /* it splits its writes (tl__pass_decl.split_writes): a framebuffer per colour write */
    uint8_t write_count;
    GLuint write_fbos[TL__FRAMEBUFFER_MAX_COLORS];
    GLuint write_textures[TL__FRAMEBUFFER_MAX_COLORS];
} tl__compiled_pass;

typedef struct tl__graph {
    tl__plan plan;
    tl__target targets[TL_TARGET_COUNT]; /* each target's texture: its block's storage, or a view of it */
    tl__target blocks[TL_TARGET_COUNT];  /* the storage of each memory block of the plan */
    uint8_t block_linear[TL_TARGET_COUNT]; /* the storage filters bilinearly */
    tl_target_set views;                 /* targets whose texture is a view of their block's (TL_TARGET_BIT) */
    tl__target levels[TL_TARGET_COUNT][TL__MAX_LEVELS]; /* one-level views of targets with mip levels */
    tl__compiled_pass passes[TL_PLAN_MAX_PASSES];
    size_t pass_count;
    int programs_ready;
    unsigned light_data;     /* TL__LIGHTS_* some pass of the plan reads */
    tl__compiled_pass luma;  /* tl_renderer_apply_fxaa's first pass (with FXAA on) */
    tl__pass_decl luma_decl;
    tl_plan_pass luma_plan;
    tl__app_pass apps[TL_MAX_APP_PASSES];
    size_t app_count;
    /* MSAA: the samples HDR has (the plan's count, which the renderer made one the context has:
     * compile checks GL_SAMPLES against it) and their positions in the pixel (x, y pairs, GL window
     * space, the first 8), read once at compile for the compute tiled pass (no gl_SamplePosition) */
    uint32_t samples;
    float sample_positions[16];
} tl__graph;

/* graph.c: the compile step of the plan in g->plan; programs too when `programs` is set
 * (a scene says which are needed; apply_fxaa compiles its own). */
tl_result tl__graph_compile(tl__device *dev, tl__graph *g, int programs);
tl_result tl__graph_programs(tl__device *dev, tl__graph *g);
void tl__graph_release(tl__device *dev, tl__graph *g);

#endif
