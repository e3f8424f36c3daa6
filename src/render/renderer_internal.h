/* The renderer as its modules (the one header that sees them all): the device (device.h), the
 * scene on the GPU (scene_gpu.h), the lights (lights.h), the graph (graph.h) and the statistics
 * ring (stats.h), plus the options. Only the public entry points (renderer.c, readback.c) and the
 * frame that runs the modules together (frame.c) include it; the passes get what they declared
 * (pass.h), never the renderer. */
#ifndef TL_RENDER_RENDERER_INTERNAL_H
#define TL_RENDER_RENDERER_INTERNAL_H

#include "environment.h"
#include "graph.h"
#include "lights.h"
#include "scene_gpu.h"
#include "shadows.h"
#include "stats.h"
#include "view.h"

struct tl_renderer {
    tl__device dev;
    tl_renderer_desc desc;         /* size and options, defaults resolved */
    tl_renderer_options given;     /* the options as the caller gave them (tl_renderer_get_options) */
    tl__scene_gpu scene;
    tl__lights lights;
    tl__graph graph;
    tl__environment env;           /* tl_renderer_set_environment's (environment.c) */
    tl__queries queries;
    float ambient[3];              /* resolved: the options' or the scene's */
    uint64_t frame_index;
    int output_drawn;              /* a render wrote the output target at this size (read_output reads it) */
    double frame_start_ms;
    tl__frame_record last;         /* the last frame's CPU figures (frames without statistics) */
    int last_measured;             /* the last frame issued queries (into queries.ring[last_slot]) */
    unsigned last_slot;
    tl__shadows shadows;           /* the shadow atlas (shadows.c), used while the plan has shadow_lights */
};

/* frame.c: one frame through the compiled passes; the prologue of work outside a frame; waiting. */
tl_result tl__frame(tl_renderer *r, const tl_camera *camera, const tl_render_output *out, tl_frame_stats *stats);
/* Waits for every frame, reads their queries, reports GL errors (the public wait). */
tl_result tl__frame_wait(tl_renderer *r, tl_frame_stats *stats);
/* The stream bytes the parameter blocks of `count` compiled passes take. */
size_t tl__params_bytes(const tl_renderer *r, const tl__compiled_pass *cp, size_t count);
/* One compiled pass outside a frame (apply_fxaa). */
void tl__run_pass(tl_renderer *r, const tl__compiled_pass *cp, tl__frame_record *rec, size_t index);
/* readback.c: the size protocol of every readback (a NULL buffer asks; 1: go on and read), and the
 * output target as it is. */
int tl__size_check(tl_renderer *r, const void *dst, size_t *size, size_t need, const char *what, tl_result *res);
tl_result tl__read_output(tl_renderer *r, uint8_t *rgba, size_t size);

#endif
