/* The view of a frame: the camera resolved against the scene (scene/validate.h), its matrices and
 * frustum, and the frame's uniform block (shaders/frame.glsl). */
#ifndef TL_RENDER_VIEW_H
#define TL_RENDER_VIEW_H

#include "device.h"
#include "math3d.h"
#include "scene/validate.h"

typedef struct tl__scene_gpu tl__scene_gpu;

typedef struct tl__view {
    tl__mat4 view, proj, view_proj;
    tl_projection projection;
    float planes[5][4];
    float clear_depth;
    float eye[3];
    float near_z;
    float target_distance, time; /* the camera's distance to its target; seconds (frames at 60 Hz) */
    tl_view_info info;
} tl__view;

/* std140 block tl_frame_block of shaders/frame.glsl. */
typedef struct tl__frame_ubo {
    float view[16], proj[16], view_proj[16];
    float depth_params[4]; /* a = m[10], b = m[14], c = m[11], reversed */
    float ray_params[4];   /* m[0], m[5], m[8], m[9] */
    float ambient[3], clear_depth;
    float inv_size[2], pad[2];
    uint32_t tiles[4];        /* tile side, tiles across, tiles down, list entries the buffer holds */
    uint32_t light_counts[4]; /* visible directional lights (first), local lights after them, end of the casting ones */
    float sample_positions[16]; /* MSAA: the samples' positions in the pixel (x, y pairs; tl__graph) */
} tl__frame_ubo;

/* Resolves a camera (scene/validate.h) with the scene's bounds: an error naming the field after
 * `what`, or TL_OK after the near plane's warning (once per scene). */
tl_result tl__camera_check(tl__device *dev, tl__scene_gpu *scene, tl_depth_format depth, const tl_camera *c,
                           const char *what, tl__camera_view *out);
/* The camera's view for a frame of `width` x `height` (frame counts the time). */
tl_result tl__view_setup(tl__device *dev, tl__scene_gpu *scene, const tl_renderer_desc *d, const tl_camera *c,
                         const char *what, uint64_t frame, tl__view *v);
/* Only what full-screen post passes read (the size), for work outside a frame. */
void tl__frame_ubo_post(const tl_renderer_desc *d, tl__frame_ubo *u);
/* The whole block: the view, the ambient term, the tiles' layout, the visible lights' counts. */
void tl__frame_ubo_fill(const tl_renderer_desc *d, const tl__view *v, const float ambient[3], const uint32_t tiles[4],
                        const uint32_t light_counts[3], tl__frame_ubo *u);
#endif
