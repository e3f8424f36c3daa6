/* The renderer's private state, shared by the files of src/render. Helpers live below their
 * users: renderer.c (public entry points) uses graph.c, frame.c, readback.c, scene_upload.c;
 * frame.c runs the compiled passes through the pass table; the passes use draw.c,
 * light_volumes.c and forward_lists.c; everything uses src/core and src/gl. */
#ifndef TL_RENDER_RENDERER_INTERNAL_H
#define TL_RENDER_RENDERER_INTERNAL_H

#include "bindings.h"
#include "core/alloc.h"
#include "core/log.h"
#include "gl/gl.h"
#include "gl/state.h"
#include "gl/stream.h"
#include "math3d.h"
#include "pass.h"
#include "scene/validate.h"
#include "targets.h"
#include "thinlight/renderer.h"

#include <threads.h>

enum { TL__LIGHT_KINDS = 3 }; /* point, spot, directional: index = type - 1 */
#define TL__QUERY_RING 4      /* frames whose queries may be in flight */
#define TL__OUTPUTS_KNOWN 4   /* framebuffers render_to checked and does not ask about again */
enum { TL__WARNED_NEAR = 1u }; /* warnings given once per scene (tl_renderer.warned) */

/* One light volume instance (light.vert attributes 1..4), world space. */
typedef struct tl__instance {
    float position_radius[4];
    float color[4];
    float direction_cos_outer[4];
    float cos_inner, source_radius; /* attribute 4 (vec2) */
} tl__instance;

/* One light of the forward pass's storage buffer (forward.frag.glsl), view space. */
typedef struct tl__forward_light {
    float position_radius[4];
    float color_type[4];
    float direction_cos_outer[4];
    float cos_inner[4]; /* cos_inner, source radius, 0, 0 */
} tl__forward_light;

/* std140 block tl_frame_block of shaders/frame.glsl. */
typedef struct tl__frame_ubo {
    float view[16], proj[16], view_proj[16];
    float depth_params[4]; /* a = m[10], b = m[14], c = m[11], reversed */
    float ray_params[4];   /* m[0], m[5], m[8], m[9] */
    float ambient[3], clear_depth;
    float inv_size[2], exposure, fxaa_subpix;
    float fxaa_edge_threshold, fxaa_edge_threshold_min, pad[2];
    uint32_t tiles[4];        /* tile side, tiles across, tiles down, list entries the buffer holds */
    uint32_t light_counts[4]; /* visible directional lights (first), local lights after them */
    float ssao[4];            /* effects (effects.c): radius, k_b, k_d, exponent */
    float fog_color[4];       /* rgb, density */
    float fog[4];             /* height, height falloff, noise, noise scale */
    float effects[4];         /* noise speed, time, focus distance, aperture */
    float dof[4];             /* largest CoC (fraction of the height), 0, 0, 0 */
    float bloom[4];           /* threshold, knee (absolute), intensity, scatter */
    float ssr[4];             /* max distance, thickness, min gloss, edge fade */
    float ssr2[4];            /* intensity, near plane distance, 0, 0 */
} tl__frame_ubo;

/* std430 element of tl_object_buffer (shaders/object.glsl). */
typedef struct tl__object_gpu {
    float model[16];
    float normal_view[12]; /* mat3: three columns of vec4 */
    uint32_t light_first, light_count, pad[2];
} tl__object_gpu;

/* std140 block tl_material_block of shaders/material.glsl. */
typedef struct tl__material_ubo {
    float albedo[3], gloss;
    float specular[3], alpha;
    float emissive[3], alpha_cutoff;
    float metallic, roughness, normal_scale, occlusion_strength;
    int32_t flags, texture_mask, pad[2];
} tl__material_ubo;

typedef struct tl__gpu_material {
    uint32_t flags;
    GLuint textures[TL__MATERIAL_TEXTURES]; /* albedo, normal, mr, emissive, occlusion; 0 = none */
} tl__gpu_material;

typedef struct tl__program_entry {
    char key[512];
    GLuint program;
} tl__program_entry;

struct tl__view {
    tl__mat4 view, proj, view_proj;
    tl_projection projection;
    float planes[5][4];
    float clear_depth;
    float eye[3];
    float near_z;
    float target_distance, time; /* the camera's distance to its target; seconds (frames at 60 Hz) */
    tl_view_info info;
};

/* A pass of the current plan as GL objects (graph.c). */
struct tl__compiled_pass {
    const tl__pass_def *def; /* NULL: application pass */
    int app;                 /* application pass index, -1 for built-in ones */
    const tl_plan_pass *plan;
    const tl__pass_decl *decl;
    GLuint fbo;
    GLuint programs[TL__PASS_MAX_PROGRAMS];
    uint8_t clear_locations[TL__FRAMEBUFFER_MAX_COLORS];
    uint8_t clear_count;
    uint8_t clear_depth;
    uint8_t bind_count;
    uint8_t units[TL_TARGET_COUNT];
    GLuint textures[TL_TARGET_COUNT];
    uint8_t image_count; /* compute passes: targets written as images */
    uint8_t image_units[TL__IMAGE_UNITS_USED];
    GLuint image_textures[TL__IMAGE_UNITS_USED];
    GLenum image_formats[TL__IMAGE_UNITS_USED];
    uint8_t writes_output;
    /* it writes a target with mip levels: a framebuffer per level (level_fbos[0] is fbo) */
    uint8_t level_count;
    GLuint level_fbos[TL__MAX_LEVELS];
};

/* What the CPU knows about a frame (the GPU's figures arrive with its queries). */
struct tl__frame_record {
    tl_frame_stats st;
    size_t indices[TL_PLAN_MAX_PASSES];   /* scene indices drawn per pass (vertex fetch) */
    size_t instances[TL_PLAN_MAX_PASSES]; /* light instances drawn per pass */
    size_t stream_bytes;                  /* per-frame data the prepare steps will upload */
};

/* Tiled light lists (tiles.c): four counters (entries used, tiles that overflowed, shaded pairs as
 * two 32-bit halves) then (offset, count) per tile; the entries; and a ring of read-back copies of
 * the counters, read once their fence has passed (never waited for in a frame). */
typedef struct tl__tiles {
    GLuint headers, entries;
    size_t capacity;            /* entries the buffer holds */
    size_t needed;              /* most entries a finished frame used (read back) */
    uint32_t size, x, y;        /* tile side in pixels, tiles across and down */
    uint32_t chunks;            /* light chunks (TL__CULL_CHUNK) the headers hold lists for */
    uint32_t frame_chunks;      /* chunks this frame's visible local lights make */
    GLuint readback;
    const uint32_t *readback_map;  /* TL__QUERY_RING x 4 counters */
    GLsync fences[TL__QUERY_RING];
    uint64_t fence_frame[TL__QUERY_RING];
} tl__tiles;

typedef struct tl__query_slot {
    GLuint time[TL_PLAN_MAX_PASSES][2];
    GLuint samples[TL_PLAN_MAX_PASSES][TL__PASS_MAX_QUERIES];
    int pending;
    tl__frame_record rec;
} tl__query_slot;

struct tl_renderer {
    tl_allocator alloc;
    tl__log log;
    tl_renderer_desc desc; /* defaults resolved */
    tl_renderer_options options_given; /* as the caller gave them (tl_renderer_get_options) */
    GladGLContext gl;
    tl__state state;
    size_t ubo_align, ssbo_align;
    size_t storage_max; /* bytes one storage block binding may hold (GL's, or the descriptor's lower one) */
    GLint max_texture_size; /* GL_MAX_TEXTURE_SIZE, read at creation */

    /* the context check (context_check.c) */
    int (*is_current)(void *user); /* the descriptor's, thinlight's own, or NULL: the thread check */
    thrd_t thread;                 /* the thread that last had the context (without is_current) */
    int thread_known;
    GLuint outputs_known[TL__OUTPUTS_KNOWN]; /* framebuffers render_to found complete */
    unsigned output_known_count, output_next;
    size_t max_lights;  /* TL_RENDERER_MAX_LIGHTS, or fewer when storage_max holds fewer */

    /* the plan and its GL objects (graph.c) */
    tl__plan plan;
    tl_scene_feature_set features;
    tl__target targets[TL_TARGET_COUNT]; /* textures or views of blocks */
    tl__target blocks[TL_TARGET_COUNT];  /* storage of blocks shared by several targets */
    tl__target levels[TL_TARGET_COUNT][TL__MAX_LEVELS]; /* one-level views of targets with mip levels */
    tl__compiled_pass passes[TL_PLAN_MAX_PASSES];
    size_t pass_count;
    int programs_ready;
    tl__compiled_pass luma;  /* tl_renderer_apply_fxaa's first pass (with FXAA on) */
    tl__pass_decl luma_decl;
    tl_plan_pass luma_plan;
    int object_lists;        /* some pass of the plan reads the per-object light lists */
    tl__app_pass apps[TL_MAX_APP_PASSES];
    size_t app_count;

    /* programs, cached by sources and defines for the renderer's life (programs.c) */
    tl__program_entry *cache;
    size_t cache_count, cache_capacity;
    uint32_t programs_compiled;
    GLuint sampler_linear;

    /* the scene (scene_upload.c) */
    GLuint vao_scene, vbo_scene, ibo_scene, vbo_object_ids, ubo_materials;
    size_t material_stride;
    tl_object *objects;
    size_t object_count;
    tl__gpu_material *materials;
    size_t material_count;
    GLuint *tex_srgb, *tex_linear; /* per scene texture, created on first use by a material */
    size_t texture_count;
    uint32_t *visible;   /* per frame: opaque objects in scene order, then transparent far to near */
    float *draw_keys;    /* scratch for sorting transparent objects */
    size_t visible_opaque, visible_transparent;
    tl_camera camera;
    float bounds_min[3], bounds_max[3]; /* the union of the objects' bounds: the near plane's floor */
    int has_bounds;
    tl__camera_view frame_camera; /* the last frame's camera as resolved (after set_scene: the scene's) */
    unsigned warned;              /* TL__WARNED_* given since the scene was set */
    float ambient[3];       /* resolved: the options' or the scene's */
    float scene_ambient[3]; /* the scene's own */
    int has_scene;

    /* lights (light_volumes.c) */
    tl_light *lights;
    size_t light_count;
    tl__instance *instances;  /* per frame: the visible lights by type, outside volumes first */
    size_t instance_base[TL__LIGHT_KINDS], instance_count[TL__LIGHT_KINDS], instance_outside[TL__LIGHT_KINDS];
    GLuint vao_light[TL__LIGHT_KINDS];
    GLuint vao_empty;
    GLuint vbo_volume[2], ibo_volume[2];
    uint32_t volume_index_count[2];

    /* the frame's visible lights in view space, directional ones first (light_lists.c): forward,
     * Forward+ and tiled shading read them */
    tl__forward_light *view_lights;
    uint32_t *view_light_index;     /* scene light index of each */
    float (*view_light_spheres)[4]; /* world-space bounding sphere of each; radius < 0: reaches everything */
    size_t view_light_count, view_dir_count;
    uint64_t view_lights_frame, view_lights_uploaded; /* frames they were built and uploaded for */
    /* forward per-object lists (forward_lists.c) */
    uint32_t *fwd_indices;
    size_t fwd_index_capacity, fwd_index_count;
    uint32_t *fwd_first, *fwd_count; /* per object */

    /* tiled light lists (tiles.c) */
    tl__tiles tiles;

    /* per frame */
    tl__stream stream;
    uint64_t frame_index;
    double frame_start_ms;
    tl__query_slot ring[TL__QUERY_RING];
    int timestamps;        /* GL_TIMESTAMP queries work in this context */
    GLint timestamp_bits;
    tl__frame_record last; /* the last frame's CPU figures */
    int last_measured;     /* the last frame issued queries (into ring[last_slot]) */
    unsigned last_slot;
};

/* Records the message as the renderer's last error, logs it, returns res. */
#define tl__fail(r, res, ...) tl__log_fail(&(r)->log, (res), __VA_ARGS__)

/* ---- the files of src/render, lowest first ---------------------------------------------------- */

/* programs.c: permutations built on demand, cached by (vertex, fragment, defines). */
tl_result tl__program_get(tl_renderer *r, const char *label, const tl__program_src *src, const char *defines,
                          GLuint *out);
void tl__program_cache_destroy(tl_renderer *r);

/* context_check.c: the renderer's context is current (the descriptor's is_current, thinlight's own
 * contexts, or one GL query when the calling thread changes); render_to's framebuffer. */
void tl__context_check_init(tl_renderer *r);
int tl__context_current(tl_renderer *r);
/* TL_ERROR_GL naming `call` when the context is not current. */
tl_result tl__need_context(tl_renderer *r, const char *call);
/* TL_ERROR_INVALID_ARGUMENT for a framebuffer that does not exist or is not complete. */
tl_result tl__output_check(tl_renderer *r, const tl_render_output *out);

/* view.c: the camera's matrices and frustum; the per-frame uniform block. */
/* Resolves a camera (scene/validate.h) with the scene's bounds: an error naming the field after
 * `what`, or TL_OK after the near plane's warning (once per scene). */
tl_result tl__camera_check(tl_renderer *r, const tl_camera *c, const char *what, tl__camera_view *out);
tl_result tl__view_setup(tl_renderer *r, const tl_camera *c, const char *what, tl__view *v);
void tl__frame_ubo_fill(const tl_renderer *r, const tl__view *v, tl__frame_ubo *u);
/* The effects' parameters in the frame block (effects.c). */
void tl__frame_ubo_effects(const tl_renderer_desc *d, const tl__view *v, tl__frame_ubo *u);
/* Only what full-screen post passes read (sizes, exposure, FXAA), for work outside a frame. */
void tl__frame_ubo_post(const tl_renderer *r, tl__frame_ubo *u);

/* draw.c: visible objects once per frame, their per-object data, drawing them in a pass. */
typedef enum tl__draw_set { TL__DRAW_OPAQUE, TL__DRAW_TRANSPARENT } tl__draw_set;
void tl__visibility(tl_renderer *r, const tl__view *v, tl__frame_record *rec);
void tl__objects_fill(const tl_renderer *r, const tl__view *v, int with_lists, tl__object_gpu *out);
void tl__draw_objects(tl_renderer *r, const tl__pass_ctx *ctx, tl__draw_set set);
/* A full-screen triangle with the pass's first program (draw.c). */
void tl__draw_fullscreen(tl_renderer *r, const tl__pass_ctx *ctx);

/* light_volumes.c: volume meshes, per-frame instances (the light pass's prepare and upload). */
void tl__light_volumes_create(tl_renderer *r);
void tl__light_volumes_destroy(tl_renderer *r);
tl_result tl__lights_prepare(tl_renderer *r, const tl__view *v, tl__frame_record *rec);
void tl__lights_upload(tl_renderer *r);

/* light_lists.c: the frame's visible lights in view space (once per frame, however many passes). */
void tl__light_sphere(const tl_light *l, float c[3], float *radius);
void tl__visible_lights(tl_renderer *r, const tl__view *v, tl__frame_record *rec);
void tl__visible_lights_upload(tl_renderer *r);

/* forward_lists.c: per-object light lists of the visible lights (forward and transparent). */
tl_result tl__forward_prepare(tl_renderer *r, const tl__view *v, tl__frame_record *rec);
void tl__forward_upload(tl_renderer *r);

/* tiles.c: the tiled light lists' buffers and the light-cull pass's CPU side and dispatch. */
tl_result tl__tiles_create(tl_renderer *r, uint32_t size, uint32_t x, uint32_t y, size_t capacity);
void tl__tiles_release(tl_renderer *r);
tl_result tl__tiles_prepare(tl_renderer *r, const tl__view *v, tl__frame_record *rec);
void tl__tiles_upload(tl_renderer *r);
void tl__tiles_cull(tl_renderer *r, const tl__pass_ctx *ctx);
void tl__tiles_collect(tl_renderer *r, const uint64_t *results, tl_frame_stats *st);

/* stats.c: the query ring and the bytes-moved estimate. */
double tl__now_ms(void);
double tl__thread_cpu_ms(void); /* CPU time of the calling thread (CLOCK_THREAD_CPUTIME_ID) */
void tl__queries_create(tl_renderer *r);
void tl__queries_destroy(tl_renderer *r);
/* The ring slot for `frame`, read first (blocking) if it still holds an unread frame. */
tl__query_slot *tl__queries_slot(tl_renderer *r, uint64_t frame);
/* Reads every slot whose results are ready; the newest read frame's statistics in *out (0: none). */
int tl__queries_newest(tl_renderer *r, tl_frame_stats *out);
/* Reads every pending slot, waiting for the GPU (before the plan changes, when the caller waits). */
void tl__queries_drain(tl_renderer *r);

/* graph.c: the compile step: targets (shared memory as texture views), framebuffers, clears,
 * texture bindings and programs of the current plan. */
tl_result tl__graph_compile(tl_renderer *r);
tl_result tl__graph_programs(tl_renderer *r);
void tl__graph_release(tl_renderer *r);

/* frame.c: one frame through the compiled passes; one pass on its own (apply_fxaa). */
tl_result tl__frame(tl_renderer *r, const tl_camera *camera, const tl_render_output *out, tl_frame_stats *stats);
/* Waits for every frame, reads their queries, reports GL errors (the public wait). */
tl_result tl__frame_wait(tl_renderer *r, tl_frame_stats *stats);
void tl__run_pass(tl_renderer *r, const tl__compiled_pass *cp, tl__frame_record *rec, size_t index,
                  const tl_render_output *out);

#endif
