/* Scene and light upload (scene_upload.c), used by the public entry points in renderer.c. */
#ifndef TL_RENDER_SCENE_UPLOAD_H
#define TL_RENDER_SCENE_UPLOAD_H

#include "plan_internal.h"
#include "renderer_internal.h"

/* The most indices a scene may have: a 2 GiB index buffer (GLsizei draw counts, 32-bit GLsizeiptr). */
#define TL__MAX_SCENE_INDICES ((size_t)1 << 29)

/* Counts first (TL_ERROR_LIMIT past 32-bit indices, GL sizes, the light limit), then arrays, ranges
 * and index values (TL_ERROR_INVALID_ARGUMENT); reads nothing an array's count does not vouch for. */
tl_result tl__scene_validate(tl_renderer *r, const tl_scene *s);
/* The scene's camera as resolved with its objects' bounds (an error naming the field), and the
 * near plane's warning ("" when none), which set_scene gives once it has taken the scene. */
typedef struct tl__scene_frame {
    float bounds_min[3], bounds_max[3];
    int has_bounds;
    tl__camera_view camera;
    char warning[TL__CHECK_MESSAGE_SIZE];
} tl__scene_frame;
tl_result tl__scene_camera(tl_renderer *r, const tl_scene *s, tl__scene_frame *out);
/* Objects, materials, textures and geometry buffers; the scene's features into r->features. */
tl_result tl__scene_upload(tl_renderer *r, const tl_scene *s);
void tl__scene_release(tl_renderer *r);
/* The scene's vertex array for the current plan's attributes. */
void tl__scene_vao(tl_renderer *r);
/* Validates and copies the lights (with per-frame scratch for them); counts them per type. */
tl_result tl__lights_store(tl_renderer *r, const tl_light *lights, size_t count, size_t kinds[TL__LIGHT_KINDS]);
void tl__lights_release(tl_renderer *r);
/* tl_renderer_options.ambient over the scene's: all zero keeps the scene's, negative = 0. */
void tl__ambient_resolve(const float options[3], const float scene[3], float out[3]);

#endif
