/* The renderer's private state, shared by the files of src/render. */
#ifndef TL_RENDER_RENDERER_INTERNAL_H
#define TL_RENDER_RENDERER_INTERNAL_H

#include "gl/gl.h"
#include "math3d.h"
#include "plan_internal.h"
#include "thinlight/renderer.h"

enum { TL__LIGHT_KINDS = 3 }; /* point, spot, directional: index = type - 1 */

/* Texture units of the geometry passes (material.glsl). */
enum { TL__UNIT_ALBEDO = 2, TL__UNIT_NORMAL, TL__UNIT_MR, TL__UNIT_EMISSIVE, TL__UNIT_OCCLUSION, TL__MATERIAL_TEXTURES = 5 };

typedef struct tl__instance {
    float position_radius[4];
    float color[4];
    float direction_cos_outer[4];
    float cos_inner;
} tl__instance;

/* One light of the forward pass's storage buffer (forward.frag.glsl), view space. */
typedef struct tl__forward_light {
    float position_radius[4];
    float color_type[4];
    float direction_cos_outer[4];
    float cos_inner[4];
} tl__forward_light;

typedef struct tl__gpu_material {
    tl_material m;
    GLuint textures[TL__MATERIAL_TEXTURES]; /* albedo, normal, mr, emissive, occlusion; 0 = none */
    int texture_mask;
} tl__gpu_material;

typedef struct tl__program_entry {
    char key[256];
    GLuint program;
} tl__program_entry;

typedef struct tl__view {
    tl__mat4 view, proj, view_proj;
    tl_projection projection;
    float planes[5][4];
    float clear_depth;
    float eye[3];
    float near_z;
} tl__view;

struct tl_renderer {
    tl_allocator alloc;
    tl_renderer_desc desc; /* defaults resolved */
    GladGLContext gl;
    char error[4096];

    tl_frame_plan plan;
    tl_scene_feature_set features;
    tl__target targets[TL_TARGET_COUNT];
    GLuint fbo[TL_PASS_COUNT];
    GLuint fbo_tonemap_ldr; /* LDR only, for tl_renderer_apply_fxaa */

    /* programs of the current plan, owned by the cache */
    GLuint prog[TL_PASS_COUNT];
    GLuint prog_light[TL__LIGHT_KINDS];
    GLuint prog_luma;
    tl__program_entry *cache;
    size_t cache_count, cache_capacity;
    uint32_t programs_compiled;

    GLuint sampler_linear;

    GLuint vao_scene, vbo_scene, ibo_scene;
    size_t scene_index_count;
    tl_object *objects;
    size_t object_count;
    tl__gpu_material *materials;
    size_t material_count;
    GLuint *tex_srgb, *tex_linear; /* per scene texture, created on first use by a material */
    size_t texture_count;
    uint32_t *draw_order; /* scratch: object indices (transparent objects sorted far to near) */
    float *draw_keys;
    tl_camera camera;
    float ambient[3];
    int has_scene;

    tl_light *lights;
    size_t light_count;
    tl__instance *instances; /* scratch for culled instances */
    GLuint vbo_instances[TL__LIGHT_KINDS];
    size_t instance_capacity[TL__LIGHT_KINDS];
    GLuint vao_light[TL__LIGHT_KINDS];
    GLuint vao_empty;
    GLuint vbo_volume[2], ibo_volume[2];
    uint32_t volume_index_count[2];

    /* forward lists: visible lights (view space) and per-object index ranges */
    tl__forward_light *fwd_lights;
    uint32_t *fwd_visible;   /* scene light index of each forward light */
    float (*fwd_spheres)[4]; /* world-space bounding sphere of each forward light; radius < 0: reaches everything */
    uint32_t *fwd_indices;
    size_t fwd_index_capacity;
    uint32_t *fwd_first, *fwd_count; /* per object */
    GLuint ssbo_lights, ssbo_indices;
    size_t ssbo_lights_capacity, ssbo_indices_capacity;

    tl__timer timers[TL_PASS_COUNT];
    GLuint queries[TL_PASS_COUNT];
    GLuint light_queries[TL__LIGHT_KINDS];
};

void *tl__alloc(const tl_allocator *a, size_t size);
void tl__free(const tl_allocator *a, void *p);
/* Records a message in r->error and sends it to the logger; returns res. */
tl_result tl__fail(tl_renderer *r, tl_result res, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* programs.c: permutations built on demand and cached by (vertex, fragment, defines). */
tl_result tl__program_get(tl_renderer *r, const char *label, const char *vs, const char *fs, const char *defines,
                          GLuint *out);
void tl__program_cache_destroy(tl_renderer *r);
/* Builds every program the plan names. */
tl_result tl__plan_programs(tl_renderer *r);

/* targets.c: the plan's targets and one framebuffer per pass. */
tl_result tl__plan_targets(tl_renderer *r);
void tl__targets_destroy(tl_renderer *r);
/* Re-plans from r->features; reallocates targets and programs when the plan changed. */
tl_result tl__replan(tl_renderer *r);

/* scene_upload.c */
void tl__release_scene(tl_renderer *r);
tl_result tl__scene_vao(tl_renderer *r);

/* forward_lists.c: per-object light lists of the visible lights. */
tl_result tl__forward_lists(tl_renderer *r, const tl__view *v, uint64_t *pairs);

/* frame.c */
void tl__fxaa_image(tl_renderer *r); /* LDR -> OUTPUT */
tl_result tl__setup_view(tl_renderer *r, const tl_camera *c, tl__view *v);

#endif
