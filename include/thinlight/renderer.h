/* thinlight renderer: a light pre-pass frame over the thin G-buffer, in whatever GL 4.5 core
 * context is current (the renderer never creates one; see context.h for OSMesa and GLFW).
 *
 *   tl_renderer *r;
 *   tl_renderer_create(&(tl_renderer_desc){ .width = 1280, .height = 720,
 *                                           .get_proc_address = my_loader }, &r);
 *   tl_renderer_set_scene(r, scene);
 *   tl_renderer_render(r, NULL, &stats);
 *   tl_renderer_read_output(r, rgba, size);
 */
#ifndef THINLIGHT_RENDERER_H
#define THINLIGHT_RENDERER_H

#include "thinlight/base.h"
#include "thinlight/codec.h"
#include "thinlight/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct tl_renderer tl_renderer;

/** How the thin G-buffer's RT0 holds normal and gloss (codec.h). */
typedef enum tl_rt0_packing {
    TL_RT0_DEFAULT = 0, /**< = TL_RT0_RGBA8 */
    TL_RT0_RGBA8,       /**< octahedral 2x12 + gloss 8 */
    TL_RT0_RGB10A2,     /**< octahedral 2x10 + gloss 10 + 2 flags */
    TL_RT0_COUNT_
} tl_rt0_packing;

/** Light-buffer layout. */
typedef enum tl_light_buffer {
    TL_LIGHT_BUFFER_DEFAULT = 0, /**< = TL_LIGHT_BUFFER_EXACT */
    TL_LIGHT_BUFFER_EXACT,       /**< RGBA16F diffuse + RGBA16F specular: exact coloured specular */
    TL_LIGHT_BUFFER_COMPACT,     /**< one RGBA16F: RGB diffuse, A specular luminance; specular colour
                                      approximated by the diffuse light's chromaticity */
    TL_LIGHT_BUFFER_COUNT_
} tl_light_buffer;

/** FXAA 3.11-style quality presets (edge search lengths as in the 12 / 29 / 39 presets). */
typedef enum tl_fxaa_preset {
    TL_FXAA_DEFAULT = 0, /**< = TL_FXAA_29 */
    TL_FXAA_OFF,
    TL_FXAA_12,          /**< 5 search steps */
    TL_FXAA_29,          /**< 12 search steps */
    TL_FXAA_39,          /**< 12 search steps with finer increments */
    TL_FXAA_COUNT_
} tl_fxaa_preset;

/** Loader for GL entry points, e.g. wrapping tl_context_get_proc_address or glfwGetProcAddress. */
typedef void (*tl_gl_function)(void);
typedef tl_gl_function (*tl_get_proc_address_fn)(void *user, const char *name);

typedef struct tl_renderer_desc {
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
    int fullscreen_lights;             /**< 1: shade point and spot lights over the whole screen instead
                                            of drawing their volumes (the reference the volume tests
                                            compare against; costs every light the full screen) */
    tl_get_proc_address_fn get_proc_address; /**< required */
    void *get_proc_address_user;
    tl_allocator allocator;            /**< zeroed: malloc/free */
} tl_renderer_desc;

/** Passes of a frame, in order; their times and names are in tl_frame_stats. */
typedef enum tl_pass {
    TL_PASS_GBUFFER,
    TL_PASS_LIGHTS,
    TL_PASS_MATERIAL,
    TL_PASS_TONEMAP,
    TL_PASS_FXAA,
    TL_PASS_COUNT
} tl_pass;

/** Render targets the renderer may allocate. */
typedef enum tl_target_id {
    TL_TARGET_DEPTH,
    TL_TARGET_RT0,
    TL_TARGET_RT1,
    TL_TARGET_LIGHT_DIFFUSE,
    TL_TARGET_LIGHT_SPECULAR,
    TL_TARGET_HDR,
    TL_TARGET_LDR,
    TL_TARGET_OUTPUT,
    TL_TARGET_COUNT
} tl_target_id;

typedef struct tl_frame_stats {
    double pass_ms[TL_PASS_COUNT];      /**< GPU time per pass (timer queries); -1 when unavailable */
    double gpu_ms;                      /**< sum of pass_ms */
    double cpu_ms;                      /**< wall clock of tl_renderer_render incl. glFinish */
    size_t target_bytes[TL_TARGET_COUNT]; /**< bytes each allocated target occupies; 0 = not allocated */
    size_t gbuffer_bytes;               /**< depth + RT0 + RT1 */
    size_t light_buffer_bytes;
    size_t total_target_bytes;
    uint32_t objects_drawn;             /**< after frustum culling, per geometry pass */
    uint32_t lights_drawn[TL_LIGHT_TYPE_COUNT_]; /**< instances per light type after culling */
    uint32_t draw_calls;
} tl_frame_stats;

TL_API const char *tl_pass_name(tl_pass pass);
TL_API const char *tl_target_name(tl_target_id target);

/** Creates the renderer in the current context. On failure *out is NULL and, when `error` is
 *  non-NULL, a message naming the problem is written there (error_size bytes, NUL-terminated). */
TL_API tl_result tl_renderer_create(const tl_renderer_desc *desc, tl_renderer **out, char *error,
                                    size_t error_size);
TL_API void tl_renderer_destroy(tl_renderer *r);
/** The last failure's message on this renderer ("" when none). */
TL_API const char *tl_renderer_last_error(const tl_renderer *r);

/** Uploads a scene (geometry, materials, textures, lights). The scene may be freed afterwards. */
TL_API tl_result tl_renderer_set_scene(tl_renderer *r, const tl_scene *scene);
/** Replaces the lights only (same scene geometry). */
TL_API tl_result tl_renderer_set_lights(tl_renderer *r, const tl_light *lights, size_t count);

/** Renders one frame with `camera` (NULL: the scene's) and waits for it; stats may be NULL. */
TL_API tl_result tl_renderer_render(tl_renderer *r, const tl_camera *camera, tl_frame_stats *stats);

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
 * view distance, 0, 1); RT0 the decoded normal (view space) and gloss; LIGHT_* and HDR their RGBA;
 * LDR and OUTPUT their colour in [0,1]. TL_ERROR_INVALID_ARGUMENT for a target not allocated.
 */
TL_API tl_result tl_renderer_read_target(tl_renderer *r, tl_target_id target, float *rgba, size_t count);
TL_API void tl_renderer_get_size(const tl_renderer *r, uint32_t *width, uint32_t *height);

#ifdef __cplusplus
}
#endif
#endif
