/* The scene on the GPU: geometry buffers, the vertex array the plan's attributes need, the
 * objects (kept on the CPU: their transforms and bounds are read every frame, so changing one
 * object is changing one record), materials as std140 records, textures uploaded on first use by
 * a material, the camera and bounds, and each frame's visible objects. scene_upload.c fills and
 * frees it; draw.c culls and draws it. */
#ifndef TL_RENDER_SCENE_GPU_H
#define TL_RENDER_SCENE_GPU_H

#include "pass.h"
#include "scene/validate.h"
#include "view.h"

/* The most indices a scene may have: a 2 GiB index buffer (GLsizei draw counts, 32-bit GLsizeiptr). */
#define TL__MAX_SCENE_INDICES ((size_t)1 << 29)
enum { TL__WARNED_NEAR = 1u }; /* warnings given once per scene (tl__scene_gpu.warned) */

/* std430 element of tl_object_buffer (shaders/object.glsl). */
typedef struct tl__object_gpu {
    float model[16];
    /* mat3: three columns of vec4; the fourth words of the first two are the object's first index and
     * material (visibility's resolve: object.glsl), as uint32_t */
    float normal_view[12];
    uint32_t light_first, light_count, pad[2]; /* pad[0]: the object's stipple layer (0: none) */
} tl__object_gpu;

/* std140 block tl_material_block of shaders/material.glsl. */
typedef struct tl__material_ubo {
    float albedo[3], gloss;
    float specular[3], alpha;
    float emissive[3], alpha_cutoff;
    float metallic, roughness, normal_scale, occlusion_strength;
    int32_t flags, texture_mask, uv1_mask, model;
    float dielectric_f0[3], clearcoat;    /* the models' parameters (material_models.glsl) */
    float sheen_color[3], sheen_roughness;
    float clearcoat_roughness, wrap, toon_steps;
    uint32_t index; /* the material's index (visibility's resolve) */
} tl__material_ubo;

typedef struct tl__gpu_material {
    uint32_t flags;
    GLuint textures[TL__MATERIAL_TEXTURES]; /* albedo, normal, mr, emissive, occlusion; 0 = none */
    uint32_t model; /* tl_material_model: the material pass's program */
} tl__gpu_material;

/* What an object slot is besides its tl_object (tl__scene_gpu.object_state). */
enum { TL__OBJECT_HIDDEN = 1u, TL__OBJECT_REMOVED = 2u };

/* An axis-aligned box. */
typedef struct tl__box {
    float min[3], max[3];
} tl__box;

struct tl__scene_gpu {
    GLuint vao, vbo, ibo, vbo_object_ids, ubo_materials;
    GLuint vbo_colors, vbo_uv1; /* tl_scene.colors and uv1 (vertex_capacity entries), 0 when the scene has none */
    size_t vertex_count, index_count;        /* in the two buffers */
    size_t vertex_capacity, index_capacity;  /* what the buffers hold room for (tl_renderer_add_geometry) */
    uint32_t vao_attributes; /* TL_ATTRIBUTE_* the vertex array binds */
    size_t material_stride;
    tl_object *objects;       /* as drawn: transform and bounds resolved; removed slots have no indices */
    size_t object_count;      /* slots in use or removed (ids are slots: stable until removed) */
    size_t object_capacity;   /* slots the arrays and the object-id buffer hold */
    uint8_t *object_state;    /* TL__OBJECT_* per slot */
    uint32_t *free_slots;     /* removed slots, reused by add_object (made at the first removal) */
    size_t free_count;
    tl__box *object_local;    /* per slot: its triangles' box in object space (bounds follow transforms) */
    int bounds_dirty;         /* an object moved: bounds_min/max are made again before the next view */
    uint32_t *material_uses;  /* per material: the objects with indices that draw it */
    size_t points_lines_objects; /* objects with indices that draw points or lines */
    tl_scene_feature_set *material_features; /* per material: what it alone needs (tl_scene_features) */
    tl__gpu_material *materials;
    size_t material_count;
    size_t material_capacity; /* records the per-material arrays and ubo_materials hold (add_material) */
    GLuint *tex_srgb, *tex_linear; /* per scene texture, created on first use by a material */
    size_t texture_count;
    size_t texture_capacity;  /* entries tex_srgb and tex_linear hold (add_texture) */
    /* per frame: opaque triangles in scene order, then transparent ones far to near, then points and
     * lines in scene order */
    uint32_t *visible;
    float *draw_keys;    /* scratch for sorting transparent objects */
    size_t visible_opaque, visible_transparent, visible_points_lines;
    tl_camera camera;
    float bounds_min[3], bounds_max[3]; /* the union of the objects' bounds: the near plane's floor */
    int has_bounds;
    tl__camera_view frame_camera; /* the last frame's camera as resolved (after set_scene: the scene's) */
    unsigned warned;              /* TL__WARNED_* given since the scene was set */
    float ambient[3];             /* the scene's own (tl_renderer_options.ambient may replace it) */
    tl_scene_feature_set features;
    int loaded;
};

/* Counts first (TL_ERROR_LIMIT past 32-bit indices, GL sizes, the light limit), then arrays, ranges
 * and index values (TL_ERROR_INVALID_ARGUMENT); reads nothing an array's count does not vouch for. */
tl_result tl__scene_validate(tl__device *dev, const tl_scene *s);
/* The scene's camera as resolved with its objects' bounds (an error naming the field), and the
 * near plane's warning ("" when none), which set_scene gives once it has taken the scene. */
typedef struct tl__scene_frame {
    float bounds_min[3], bounds_max[3];
    int has_bounds;
    tl__camera_view camera;
    char warning[TL__CHECK_MESSAGE_SIZE];
} tl__scene_frame;
tl_result tl__scene_camera(tl__device *dev, const tl_scene *s, tl_depth_format depth, tl__scene_frame *out);
/* Objects, materials, textures and geometry buffers, and the scene's features. */
tl_result tl__scene_upload(tl__device *dev, tl__scene_gpu *g, const tl_scene *s);
/* Takes the camera, bounds and warning of a scene just uploaded. */
void tl__scene_take_frame(tl__device *dev, tl__scene_gpu *g, const tl__scene_frame *f);
void tl__scene_release(tl__device *dev, tl__scene_gpu *g);
/* The vertex array for `attributes` (TL_ATTRIBUTE_*), made again only when they change. */
void tl__scene_vao(tl__device *dev, tl__scene_gpu *g, uint32_t attributes);
/* tl_renderer_options.ambient over the scene's: all zero keeps the scene's, negative = 0. */
void tl__ambient_resolve(const float options[3], const float scene[3], float out[3]);

/* scene_update.c: objects and materials changed between frames (tl_renderer_set_object, ...).
 * Each returns 1 through `replan` when the scene's features (what the plan depends on) changed. */
void tl__scene_objects_init(tl__scene_gpu *g, const tl_scene *s);
tl_result tl__scene_object_id(tl__device *dev, const tl__scene_gpu *g, uint32_t id, const char *call);
tl_result tl__scene_set_transform(tl__device *dev, tl__scene_gpu *g, uint32_t id, const float transform[16]);
tl_result tl__scene_set_visible(tl__device *dev, tl__scene_gpu *g, uint32_t id, int visible);
tl_result tl__scene_set_object(tl__device *dev, tl__scene_gpu *g, uint32_t id, const tl_object *o, int *replan);
tl_result tl__scene_add_object(tl__device *dev, tl__scene_gpu *g, const tl_object *o, uint32_t *id, int *replan);
tl_result tl__scene_remove_object(tl__device *dev, tl__scene_gpu *g, uint32_t id, int *replan);
tl_result tl__scene_add_geometry(tl__device *dev, tl__scene_gpu *g, const tl_vertex *vertices, size_t vertex_count,
                                 const uint32_t *indices, size_t index_count, uint32_t *first_index);
tl_result tl__scene_set_material(tl__device *dev, tl__scene_gpu *g, uint32_t index, const tl_material *m, int *replan);
/* A texture uploaded now (sRGB; a linear copy is made on the GPU when a material reads it as data)
 * and a material appended; each writes the new index. The caller sets the pixel store. */
tl_result tl__scene_add_texture(tl__device *dev, tl__scene_gpu *g, const tl_texture *t, uint32_t *index);
tl_result tl__scene_add_material(tl__device *dev, tl__scene_gpu *g, const tl_material *m, uint32_t *index, int *replan);
/* Whether the features changed with the materials' uses or records (sets tl__scene_gpu.features). */
int tl__scene_features_refresh(tl__scene_gpu *g);
/* The union of the objects' bounds again, after objects moved (before a view is resolved). */
void tl__scene_bounds_refresh(tl__scene_gpu *g);

/* draw.c: the visible objects once per frame (returns the opaque triangles' count), their per-object data
 * (with the per-object light lists' ranges when `first` is not NULL). */
size_t tl__visibility(tl__scene_gpu *g, const tl__view *v);
/* Material `index`'s record (a range of the materials' buffer) and textures, bound. */
void tl__bind_material(const GladGLContext *gl, const tl__scene_gpu *g, uint32_t index);
void tl__objects_fill(const tl__scene_gpu *g, const tl__view *v, const uint32_t *first, const uint32_t *count,
                      tl__object_gpu *out);

#endif
