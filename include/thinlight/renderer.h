/**
 * @file thinlight/renderer.h
 * @brief The renderer: a light pre-pass frame over the thin G-buffer, in whatever GL 4.5 core
 * context is current (the renderer never creates one; see context.h for OSMesa and GLFW).
 * The same binary holds the reference paths (thin deferred, fat full-float deferred, forward), so
 * that every comparison is made in one run. Each frame follows a plan made from the scene's
 * features (tl_frame_plan_build): targets, passes and shader permutations nobody needs are left out.
 *
 * @code
 *   tl_renderer *r;
 *   tl_renderer_create(&(tl_renderer_desc){ .width = 1280, .height = 720,
 *                                           .get_proc_address = my_loader }, &r);
 *   tl_renderer_set_scene(r, scene);
 *   tl_renderer_render(r, NULL, &stats);
 *   tl_renderer_read_output(r, rgba, size);
 * @endcode
 */
#ifndef THINLIGHT_RENDERER_H
#define THINLIGHT_RENDERER_H

#include "thinlight/base.h"
#include "thinlight/codec.h"
#include "thinlight/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A renderer: GL objects in one context plus the uploaded scene. Opaque. */
typedef struct tl_renderer tl_renderer;

/** How a frame is rendered. All modes share one lighting model (shaders/lighting.glsl). */
typedef enum tl_render_mode {
    TL_MODE_DEFAULT = 0,   /**< = TL_MODE_THIN_LPP */
    TL_MODE_THIN_LPP,      /**< "thin-lpp": thin G-buffer, light buffer, second geometry pass */
    TL_MODE_THIN_DEFERRED, /**< "thin-deferred": thin G-buffer with RT1 (YCbCr albedo, specular), lights shade directly */
    TL_MODE_FAT,           /**< "fat": full-float deferred, 44 B/px; the precision reference */
    TL_MODE_FORWARD,       /**< "forward": per-object light lists, optional depth pre-pass */
    TL_MODE_COUNT_         /**< number of values */
} tl_render_mode;

/** "thin-lpp", "thin-deferred", "fat", "forward" ("unknown" otherwise). */
TL_API const char *tl_render_mode_name(tl_render_mode mode);
/** Parses a name of tl_render_mode_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_render_mode_from_name(const char *name, tl_render_mode *mode);

/** How the thin G-buffer's RT0 holds normal and gloss (codec.h). */
typedef enum tl_rt0_packing {
    TL_RT0_DEFAULT = 0, /**< = TL_RT0_RGBA8 */
    TL_RT0_RGBA8,       /**< octahedral 2x12 + gloss 8 */
    TL_RT0_RGB10A2,     /**< octahedral 2x10 + gloss 10 + 2 flags */
    TL_RT0_COUNT_       /**< number of values */
} tl_rt0_packing;

/** Light-buffer layout. */
typedef enum tl_light_buffer {
    TL_LIGHT_BUFFER_DEFAULT = 0, /**< = TL_LIGHT_BUFFER_EXACT */
    TL_LIGHT_BUFFER_EXACT,       /**< RGBA16F diffuse + RGBA16F specular: exact coloured specular */
    TL_LIGHT_BUFFER_COMPACT,     /**< one RGBA16F: RGB diffuse, A specular luminance; specular colour
                                      approximated by the diffuse light's chromaticity */
    TL_LIGHT_BUFFER_COUNT_       /**< number of values */
} tl_light_buffer;

/** FXAA 3.11-style quality presets (edge search lengths as in the 12 / 29 / 39 presets). */
typedef enum tl_fxaa_preset {
    TL_FXAA_DEFAULT = 0, /**< = TL_FXAA_29 */
    TL_FXAA_OFF,         /**< no anti-aliasing (the tone-mapped image is the output) */
    TL_FXAA_12,          /**< 5 search steps */
    TL_FXAA_29,          /**< 12 search steps */
    TL_FXAA_39,          /**< 12 search steps with finer increments */
    TL_FXAA_COUNT_       /**< number of values */
} tl_fxaa_preset;

/** A GL entry point as a loader returns it. */
typedef void (*tl_gl_function)(void);
/** Loader for GL entry points, e.g. tl_context_proc_loader or a wrapper of glfwGetProcAddress. */
typedef tl_gl_function (*tl_get_proc_address_fn)(void *user, const char *name);

/** Options of tl_renderer_create(); every zeroed field means its default. */
typedef struct tl_renderer_desc {
    tl_render_mode mode;               /**< default thin-lpp */
    uint32_t width;                    /**< default 1280 */
    uint32_t height;                   /**< default 720 */
    tl_depth_format depth_format;      /**< default D24 (D24S8); D32F_REVERSED for reversed Z */
    tl_rt0_packing rt0;                /**< default RGBA8 */
    tl_light_buffer light_buffer;      /**< default EXACT */
    tl_fxaa_preset fxaa;               /**< default 29 */
    float fxaa_edge_threshold;         /**< default 0.166 (relative local contrast) */
    float fxaa_edge_threshold_min;     /**< default 0.0833 (absolute, in gamma-encoded luma) */
    float fxaa_subpix;                 /**< default 0.75; a negative value means 0 */
    float exposure;                    /**< default 1; multiplies HDR colour before tone mapping */
    int forward_no_depth_prepass;      /**< forward mode: 1 leaves out the depth pre-pass (default: on) */
    int no_planning;                   /**< 1: plan for every feature whatever the scene uses (all light
                                            types, specular, textures, normal maps, alpha): shows what
                                            planning saves */
    int fullscreen_lights;             /**< 1: shade point and spot lights over the whole screen instead
                                            of drawing their volumes (the reference the volume tests
                                            compare against; costs every light the full screen) */
    tl_get_proc_address_fn get_proc_address; /**< required */
    void *get_proc_address_user;       /**< passed to get_proc_address */
    tl_allocator allocator;            /**< zeroed: malloc/free; every allocation of the renderer */
    tl_logger logger;                  /**< zeroed: silent; every failure is also in tl_renderer_last_error */
} tl_renderer_desc;

/** Passes a frame may run, in execution order; a plan holds the ones its mode and scene need. */
typedef enum tl_pass {
    TL_PASS_DEPTH_PREPASS, /**< forward: depth only */
    TL_PASS_GBUFFER,       /**< thin or fat G-buffer (deferred modes also write emissive + ambient into HDR) */
    TL_PASS_LIGHTS,        /**< light volumes: into the light buffer (thin-lpp) or shading into HDR */
    TL_PASS_MATERIAL,      /**< thin-lpp second geometry pass, depth EQUAL */
    TL_PASS_FORWARD,       /**< forward shading with per-object light lists */
    TL_PASS_TRANSPARENT,   /**< alpha-blended materials, forward-lit after the opaque frame */
    TL_PASS_TONEMAP,
    TL_PASS_FXAA,          /**< or a copy when FXAA is off */
    TL_PASS_COUNT          /**< number of values */
} tl_pass;

/** Render targets the renderer may allocate. */
typedef enum tl_target_id {
    TL_TARGET_DEPTH,          /**< D24S8, or D32F(S8) reversed; fat: D32F */
    TL_TARGET_RT0,            /**< octahedral normal + gloss */
    TL_TARGET_RT1,            /**< Y, checkerboard chroma, specular intensity, flags (thin-deferred) */
    TL_TARGET_LIGHT_DIFFUSE,  /**< light buffer (thin-lpp) */
    TL_TARGET_LIGHT_SPECULAR, /**< exact coloured specular (thin-lpp, EXACT layout, specular materials) */
    TL_TARGET_FAT_POSITION,   /**< fat: view-space position RGBA32F */
    TL_TARGET_FAT_NORMAL,     /**< fat: view-space normal + gloss RGBA16F */
    TL_TARGET_FAT_ALBEDO,     /**< fat: linear albedo RGBA16F */
    TL_TARGET_FAT_MATERIAL,   /**< fat: specular colour RGBA16F */
    TL_TARGET_HDR,            /**< RGBA16F linear radiance */
    TL_TARGET_LDR,            /**< RGBA8 tone-mapped, luma in alpha (only with FXAA) */
    TL_TARGET_OUTPUT,         /**< RGBA8 final image */
    TL_TARGET_COUNT           /**< number of values */
} tl_target_id;

/** Vertex position attribute bit (bits of tl_frame_plan.vertex_attributes). */
#define TL_ATTRIBUTE_POSITION 1u
/** Vertex normal attribute bit. */
#define TL_ATTRIBUTE_NORMAL 2u
/** Texture coordinate attribute bit (only with textures). */
#define TL_ATTRIBUTE_UV 4u
/** Tangent attribute bit (only with normal maps). */
#define TL_ATTRIBUTE_TANGENT 8u

/** Capacity of tl_frame_plan.programs. */
#define TL_PLAN_MAX_PROGRAMS 48

/** One pass of a plan: the targets it reads and writes, as bits (1u << tl_target_id). */
typedef struct tl_plan_pass {
    tl_pass pass;     /**< which pass */
    uint32_t reads;   /**< targets sampled or depth-tested against */
    uint32_t writes;  /**< targets rendered to */
} tl_plan_pass;

/** A shader permutation the plan needs: the program's name and its preprocessor defines. */
typedef struct tl_plan_program {
    tl_pass pass;      /**< the pass that runs it */
    char name[32];     /**< e.g. "gbuffer", "lights.point" */
    char defines[160]; /**< space-separated NAME or NAME=VALUE switches */
} tl_plan_program;

/** What a frame allocates, runs and compiles (DESIGN.md section 4). */
typedef struct tl_frame_plan {
    tl_render_mode mode;                         /**< the mode planned for */
    uint32_t width;                              /**< target width in pixels */
    uint32_t height;                             /**< target height in pixels */
    size_t pass_count;                           /**< entries used in passes */
    tl_plan_pass passes[TL_PASS_COUNT];          /**< in execution order */
    uint32_t targets;                            /**< allocated targets, bits (1u << tl_target_id) */
    uint32_t target_bytes_per_pixel[TL_TARGET_COUNT]; /**< 0 = not allocated */
    uint32_t bytes_per_pixel;                    /**< sum over allocated targets */
    uint32_t gbuffer_bytes_per_pixel;            /**< depth + G-buffer + light buffer (what the technique stores) */
    uint32_t vertex_attributes;                  /**< TL_ATTRIBUTE_* bound by the geometry passes */
    uint32_t light_types;                        /**< bits (1u << tl_light_type) drawn by the light pass */
    size_t program_count;                        /**< entries used in programs */
    tl_plan_program programs[TL_PLAN_MAX_PROGRAMS]; /**< every permutation the frame compiles */
} tl_frame_plan;

/**
 * Plans a frame for `desc` (defaults resolved as tl_renderer_create does) and a scene with
 * `features`. Pure: no GL, no allocation. TL_ERROR_INVALID_ARGUMENT for NULL pointers or an option
 * out of range.
 */
TL_API tl_result tl_frame_plan_build(const tl_renderer_desc *desc, const tl_scene_feature_set *features,
                                     tl_frame_plan *plan);
/** Writes the plan as text (passes with inputs and outputs, targets with bytes per pixel,
 *  attributes, programs). Returns the length it needs without the NUL, like snprintf. */
TL_API size_t tl_frame_plan_format(const tl_frame_plan *plan, char *buffer, size_t size);

/** What one frame cost and allocated (tl_renderer_render). */
typedef struct tl_frame_stats {
    double pass_ms[TL_PASS_COUNT];      /**< GPU time per pass (timer queries); 0 for passes not in the
                                             plan, -1 when unavailable */
    uint64_t pass_fragments[TL_PASS_COUNT]; /**< fragments that passed the depth test (samples-passed query) */
    double pass_bytes[TL_PASS_COUNT];   /**< estimate of bytes moved per pass (docs/bandwidth.md) */
    double bytes_moved;                 /**< sum of pass_bytes */
    double gpu_ms;                      /**< sum of pass_ms */
    double cpu_ms;                      /**< wall clock of the render call incl. glFinish */
    size_t target_bytes[TL_TARGET_COUNT]; /**< bytes each allocated target occupies; 0 = not allocated */
    size_t gbuffer_bytes;               /**< depth + RT0 + RT1 + FAT_* */
    size_t light_buffer_bytes;          /**< LIGHT_DIFFUSE + LIGHT_SPECULAR */
    size_t total_target_bytes;          /**< sum of target_bytes */
    uint32_t objects_drawn;             /**< after frustum culling, per geometry pass */
    uint32_t lights_drawn[TL_LIGHT_TYPE_COUNT_]; /**< instances per light type after culling */
    uint64_t light_fragments[TL_LIGHT_TYPE_COUNT_]; /**< pixels covered by each type's light volumes
                                                        (fragments shaded in the light pass) */
    uint64_t forward_light_pairs;       /**< forward: sum over drawn objects of the lights in their list */
    uint32_t draw_calls;                /**< GL draw calls of the frame */
    uint32_t programs_compiled;         /**< shader programs compiled so far by this renderer (cache misses) */
} tl_frame_stats;

/** "gbuffer", "lights", ... ("unknown" out of range); the names of debug groups and timers. */
TL_API const char *tl_pass_name(tl_pass pass);
/** "depth", "rt0", "light.diffuse", ... ("unknown" out of range). */
TL_API const char *tl_target_name(tl_target_id target);

/** Creates the renderer in the current context. On failure *out is NULL and, when `error` is
 *  non-NULL, a message naming the problem is written there (error_size bytes, NUL-terminated). */
TL_API tl_result tl_renderer_create(const tl_renderer_desc *desc, tl_renderer **out, char *error,
                                    size_t error_size);
/** Frees every GL object and allocation of the renderer (in its context, which must be current); NULL is ignored. */
TL_API void tl_renderer_destroy(tl_renderer *r);
/** The last failure's message on this renderer ("" when none). */
TL_API const char *tl_renderer_last_error(const tl_renderer *r);

/** Uploads a scene (geometry, materials, textures, lights), plans the frame from its features,
 *  allocates the plan's targets and compiles the shader permutations it needs (cached across
 *  calls, keyed by their defines). The scene may be freed afterwards. */
TL_API tl_result tl_renderer_set_scene(tl_renderer *r, const tl_scene *scene);
/** Replaces the lights only (same scene geometry); re-plans when the light types change. */
TL_API tl_result tl_renderer_set_lights(tl_renderer *r, const tl_light *lights, size_t count);

/** The current plan; TL_ERROR_INVALID_ARGUMENT before a scene is set. */
TL_API tl_result tl_renderer_get_plan(const tl_renderer *r, tl_frame_plan *plan);

/** Renders one frame with `camera` (NULL: the scene's) into the renderer's own targets and waits
 *  for it; stats may be NULL. */
TL_API tl_result tl_renderer_render(tl_renderer *r, const tl_camera *camera, tl_frame_stats *stats);

/** A framebuffer owned by the caller (GL name; 0 is the context's default framebuffer). */
typedef struct tl_render_output {
    uint32_t framebuffer;   /**< GL framebuffer name */
    uint32_t x;             /**< left edge of the viewport in it */
    uint32_t y;             /**< bottom edge of the viewport in it */
    uint32_t width;         /**< 0: the renderer's width; otherwise the image is scaled (linear) */
    uint32_t height;        /**< 0: the renderer's height */
} tl_render_output;

/** Renders one frame like tl_renderer_render, with the last pass writing into `output`. The
 *  renderer's own output target is not written (tl_renderer_read_output reads the last frame
 *  rendered with tl_renderer_render). The caller's framebuffer binding is restored to 0. */
TL_API tl_result tl_renderer_render_to(tl_renderer *r, const tl_camera *camera, const tl_render_output *output,
                                       tl_frame_stats *stats);

/**
 * Runs the renderer's FXAA pass (with its preset and thresholds) on a caller image: RGBA8
 * gamma-encoded, width x height of the renderer, rows bottom to top; luma is computed from RGB.
 * `out` receives the result (alpha 255). Useful to anti-alias an image rendered elsewhere.
 */
TL_API tl_result tl_renderer_apply_fxaa(tl_renderer *r, const uint8_t *rgba, uint8_t *out, size_t size);

/** Reads the final LDR image as RGBA8, rows bottom to top (GL order); size >= w*h*4. */
TL_API tl_result tl_renderer_read_output(tl_renderer *r, uint8_t *rgba, size_t size);
/**
 * Reads a target as floats, 4 per pixel, rows bottom to top: DEPTH gives (window depth, linear
 * view distance, 0, 1); RT0 the decoded normal (view space) and gloss; RT1 its raw channels in
 * [0,1]; LIGHT_*, FAT_* and HDR their RGBA; LDR and OUTPUT their colour in [0,1].
 * TL_ERROR_INVALID_ARGUMENT for a target the plan did not allocate.
 */
TL_API tl_result tl_renderer_read_target(tl_renderer *r, tl_target_id target, float *rgba, size_t count);
/** The renderer's target size (0 x 0 for NULL); either pointer may be NULL. */
TL_API void tl_renderer_get_size(const tl_renderer *r, uint32_t *width, uint32_t *height);

#ifdef __cplusplus
}
#endif
#endif
