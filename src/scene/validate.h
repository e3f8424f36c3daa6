/* One validation of what a scene hands the renderer: cameras, textures, materials' texture indices
 * and lights. The glTF loader (src/io) and the renderer (src/render) both run these checks, so what
 * loads renders: the loader turns a failed check into its documented fallback with a warning, the
 * renderer into an error; both carry the message written here, which names the field
 * ("camera.fov_y = 3.14159: outside (0, pi)"). Pure C (and C++-includable), no GL, no allocation.
 * The tables of decisions are in docs/gltf.md and docs/renderer-limits.md. */
#ifndef TL_SCENE_VALIDATE_H
#define TL_SCENE_VALIDATE_H

#include <stddef.h>
#include <stdint.h>

#include "thinlight/codec.h"
#include "thinlight/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* GL_MAX_TEXTURE_SIZE that every GL 4.5 context has: the loader's largest texture side. */
#define TL__GL45_MAX_TEXTURE_SIZE 16384u

/* Room for any message of these checks (the caller's prefix included). */
#define TL__CHECK_MESSAGE_SIZE 320

/* A camera with its defaults and fallbacks applied: what a frame is rendered with. */
typedef struct tl__camera_view {
    double eye[3];
    double right[3], up[3], back[3]; /* orthonormal, world space; the view looks along -back */
    float fov_y, near_z, far_z;      /* far_z 0: an infinite far plane */
    float target_distance;           /* |target - position| */
    int near_raised; /* near_z was below the depth format's floor and was raised to it (a warning) */
} tl__camera_view;

/* The union of the objects' bounds (non-finite boxes left out); 0 when nothing is left. */
int tl__objects_bounds(const tl_object *objects, size_t count, float min[3], float max[3]);

/* ---- objects: their defaults (bounds.c) and their check (validate.c) ---- */

/* Whether all 16 entries of a transform are zero (the default: the identity). */
int tl__transform_is_zero(const float m[16]);
/* Whether all six bounds of an object are zero (the default: computed from its vertices). */
int tl__bounds_are_zero(const tl_object *o);
/* An object's primitive (a tl_primitive), its transform (finite) and its bounds unless zero (finite, min <= max on every axis;
 * checked for objects with indices only: an empty object is never drawn). TL_ERROR_INVALID_ARGUMENT
 * naming the field after `what` ("objects[3].bounds_min = (1, nan, 0): not finite"). */
tl_result tl__object_check(const tl_object *o, const char *what, char *message, size_t size);
/* Indices per element of a primitive (3 triangles, 2 lines, 1 points), 0 for a value outside
 * tl_primitive; and the element's name for messages ("triangles", "lines", "points"). */
uint32_t tl__primitive_indices(uint32_t primitive);
const char *tl__primitive_name(uint32_t primitive);
/* tl_object_compute_bounds for an object whose index range, indices and positions the caller has
 * checked: no error. */
void tl__object_bounds_compute(const tl_scene *s, const tl_object *o, float min[3], float max[3]);
/* An object as the renderer draws it: a zero transform made the identity, zero bounds computed.
 * `o` must be valid in `s` (tl_renderer_set_scene's checks). */
void tl__object_defaults(const tl_scene *s, tl_object *o);
/* The union of the bounds of the scene's objects that have indices, zero bounds computed (as
 * tl__object_defaults); 0 when no object has indices. Objects must be valid in `s`. */
int tl__scene_objects_bounds(const tl_scene *s, float min[3], float max[3]);

/* The default view (tl_camera): from the front, right and above the bounds (glTF: +Z front, +Y
 * up), far enough that their bounding sphere fits the vertical field of view `fov_y` with 5% to
 * spare; near_z half the distance to the sphere, far_z twice the distance to its far side, up +Y,
 * fov_y as given. The glTF loader's camera for a file without one. */
void tl__camera_frame(const float bmin[3], const float bmax[3], double fov_y, tl_camera *out);

/*
 * Resolves a camera as a frame uses it. Errors (TL_ERROR_INVALID_ARGUMENT, the message naming the
 * field after `what`, e.g. "camera"): a non-finite position, target or up; position == target
 * (not both zero); fov_y negative, NaN, not below pi or too narrow for a float projection;
 * near_z negative or not finite; far_z negative, NaN, or finite and not beyond near_z.
 * Defaults: fov_y 0 = 60 degrees,
 * near_z 0 = 0.1, far_z 0 or +Inf = infinite, up 0 = +Y; position and target both zero: the
 * default view, tl__camera_frame of the bounds (near_z 0 = its near plane), or with NULL bounds
 * the origin looking down -Z; an up parallel to the view is replaced by the limit of views
 * tilted towards -Z (or +Y when up is along Z), so the view stays defined.
 * Fallback (TL_OK, out->near_raised, the warning in `message`): a near_z below 2^-24 of the
 * distance to the bounds' farthest corner (or the far plane when nearer), where D24 holds nothing
 * of the scene and clipping loses triangles in either depth format, is raised to 2^-16 of that
 * distance. NULL bounds: no floor.
 */
tl_result tl__camera_resolve(const tl_camera *c, const char *what, tl_depth_format depth, const float *bounds_min,
                             const float *bounds_max, tl__camera_view *out, char *message, size_t size);

/* The column-major view matrix (world to view) of a resolved camera. */
void tl__camera_view_matrix(const tl__camera_view *v, float m[16]);

/* A texture's size and pixels: width and height 1..max_side, pixels present. TL_ERROR_INVALID_ARGUMENT
 * or TL_ERROR_LIMIT (over max_side) with the message naming the field after `what`. */
tl_result tl__texture_check(const tl_texture *t, const char *what, uint32_t max_side, char *message, size_t size);

/* The texture maps of tl_material, in the renderer's order (albedo, normal, metallic-roughness,
 * emissive, occlusion), and whether each holds sRGB-encoded colour. */
#define TL__MATERIAL_TEXTURE_SLOTS 5
enum { TL__MAP_ALBEDO, TL__MAP_NORMAL, TL__MAP_METALLIC_ROUGHNESS, TL__MAP_EMISSIVE, TL__MAP_OCCLUSION };
typedef struct tl__texture_slot {
    const char *name; /* the field's name */
    size_t offset;    /* of its uint32_t map (texture index + 1) in tl_material */
    int srgb;
} tl__texture_slot;
extern const tl__texture_slot tl__material_texture_slots[TL__MATERIAL_TEXTURE_SLOTS];
/* What tl__material_texture gives for a map of 0. */
#define TL__NO_TEXTURE UINT32_MAX
/* The texture index that map k of `m` names (the map - 1), or TL__NO_TEXTURE. */
uint32_t tl__material_texture(const tl_material *m, int k);
/* Whether map k of `m` names one of `texture_count` textures. */
int tl__material_has_texture(const tl_material *m, int k, size_t texture_count);

/* Every map of a material is 0 or names a texture below texture_count. */
tl_result tl__material_check(const tl_material *m, const char *what, size_t texture_count, char *message, size_t size);
/* A material with its zeroes resolved as tl_material documents them: a material with no colour
 * (albedo, specular and emissive all zero) gets TL_MATERIAL_DEFAULT_ALBEDO, a negative albedo
 * component is 0, normal_scale and occlusion_strength 0 are 1. */
void tl__material_defaults(const tl_material *in, tl_material *out);
/* material_models.c: the models' parameters with their zeroes resolved (called by
 * tl__material_defaults) and their check (called by tl__material_check). */
void tl__material_model_defaults(tl_material *m);
tl_result tl__material_model_check(const tl_material *m, const char *what, char *message, size_t size);
/* Sets in *out the flags (has_*) that `material` alone needs, as tl_scene_features counts them
 * for a material some object draws; `texture_count` is the scene's. Counts are left alone. */
void tl__material_features(const tl_material *material, size_t texture_count, tl_scene_feature_set *out);

/* How far below 0 a spot's cos_outer may lie and still be 90 degrees: cosf of the float nearest
 * pi/2 is -4.4e-8. */
#define TL__SPOT_COS_SLACK 1e-6f

/* A light's type and values: finite position, direction and colour (a negative colour is allowed:
 * the renderer takes it as 0); point and spot: a finite radius > 0 and source_radius >= 0; spot and
 * directional: a direction that is not zero; spot: cosines in -1..1, cos_outer >= 0 (at most 90
 * degrees, within TL__SPOT_COS_SLACK) and cos_outer < cos_inner. */
tl_result tl__light_check(const tl_light *l, const char *what, char *message, size_t size);

#ifdef __cplusplus
}
#endif
#endif
