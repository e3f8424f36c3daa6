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
 *   tl_renderer_render(r, NULL, NULL);
 *   size_t size = 0;
 *   tl_renderer_read_output(r, NULL, &size);   // asks for the size: width * height * 4
 *   tl_renderer_read_output(r, rgba, &size);
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
    TL_MODE_VISIBILITY,    /**< "visibility": depth and a 32-bit triangle id per pixel; a compute resolve
                                rebuilds each pixel's attributes from its triangle and shades it with the
                                tile lists (docs/frame.md, "Visibility buffer") */
    TL_MODE_COUNT_         /**< number of values */
} tl_render_mode;

/** "thin-lpp", "thin-deferred", "fat", "forward", "visibility" ("unknown" otherwise). */
TL_API const char *tl_render_mode_name(tl_render_mode mode);
/** Parses a name of tl_render_mode_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_render_mode_from_name(const char *name, tl_render_mode *mode);

/** A behaviour that is on unless turned off (docs/option-changes.md, "One polarity"): zero, the
 *  default, is on. Options that are off by default are an `int` (`enabled`, `fullscreen_lights`):
 *  zero is off and 1 turns them on. */
typedef enum tl_switch {
    TL_SWITCH_DEFAULT = 0, /**< "on": the default */
    TL_SWITCH_ON,          /**< "on", said explicitly */
    TL_SWITCH_OFF,         /**< "off" */
    TL_SWITCH_COUNT_       /**< number of values */
} tl_switch;

/** "on" (TL_SWITCH_DEFAULT and TL_SWITCH_ON), "off" ("unknown" otherwise). */
TL_API const char *tl_switch_name(tl_switch value);
/** Parses a name of tl_switch_name ("on" gives TL_SWITCH_ON); TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_switch_from_name(const char *name, tl_switch *value);

/** How the thin G-buffer's RT0 holds normal and gloss (codec.h). */
typedef enum tl_rt0_packing {
    TL_RT0_DEFAULT = 0, /**< = TL_RT0_RGBA8 */
    TL_RT0_RGBA8,       /**< octahedral 2x12 + gloss 8 */
    TL_RT0_RGB10A2,     /**< octahedral 2x10 + gloss 10 + 2 flags */
    TL_RT0_COUNT_       /**< number of values */
} tl_rt0_packing;

/** "rgba8" (TL_RT0_DEFAULT too), "rgb10a2" ("unknown" otherwise). */
TL_API const char *tl_rt0_packing_name(tl_rt0_packing value);
/** Parses a name of tl_rt0_packing_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_rt0_packing_from_name(const char *name, tl_rt0_packing *value);

/** Light-buffer layout. */
typedef enum tl_light_buffer {
    TL_LIGHT_BUFFER_DEFAULT = 0, /**< = TL_LIGHT_BUFFER_EXACT */
    TL_LIGHT_BUFFER_EXACT,       /**< RGBA16F diffuse + RGBA16F specular: exact coloured specular */
    TL_LIGHT_BUFFER_COMPACT,     /**< one RGBA16F: RGB diffuse, A specular luminance; specular colour
                                      approximated by the diffuse light's chromaticity */
    TL_LIGHT_BUFFER_COUNT_       /**< number of values */
} tl_light_buffer;

/** "exact" (TL_LIGHT_BUFFER_DEFAULT too), "compact" ("unknown" otherwise). */
TL_API const char *tl_light_buffer_name(tl_light_buffer value);
/** Parses a name of tl_light_buffer_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_light_buffer_from_name(const char *name, tl_light_buffer *value);

/** How the light pass accumulates lights (docs/frame.md). */
typedef enum tl_light_strategy {
    TL_LIGHT_STRATEGY_DEFAULT = 0, /**< "auto": the planner picks per scene (tl_frame_plan.light_strategy says which, and why) */
    TL_LIGHT_STRATEGY_VOLUMES,     /**< "volumes": instanced spheres, cones and a full-screen triangle, blended per
                                        light; in forward mode, per-object light lists */
    TL_LIGHT_STRATEGY_TILED,       /**< "tiled": per-tile depth bounds and light lists (a compute pass), then one pass
                                        that reads the G-buffer once per pixel and loops over its tile's lights;
                                        in forward mode, Forward+ (tile lists after the depth pre-pass) */
    TL_LIGHT_STRATEGY_COUNT_       /**< number of values */
} tl_light_strategy;

/** "auto", "volumes", "tiled" ("unknown" otherwise). */
TL_API const char *tl_light_strategy_name(tl_light_strategy strategy);
/** Parses a name of tl_light_strategy_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_light_strategy_from_name(const char *name, tl_light_strategy *strategy);

/** Which pass shades the tiles of the tiled strategy. */
typedef enum tl_tiled_shading {
    TL_TILED_SHADING_DEFAULT = 0, /**< = TL_TILED_SHADING_AUTO: the planner picks (docs/frame.md, "Fragment or
                                       compute"); tl_frame_plan.tiled_shading says which */
    TL_TILED_SHADING_FRAGMENT,    /**< a full-screen triangle */
    TL_TILED_SHADING_COMPUTE,     /**< a compute pass, one invocation per pixel, image stores */
    TL_TILED_SHADING_COUNT_,      /**< number of values */
    TL_TILED_SHADING_AUTO = TL_TILED_SHADING_DEFAULT /**< the planner picks */
} tl_tiled_shading;

/** "auto" (TL_TILED_SHADING_DEFAULT), "fragment", "compute" ("unknown" otherwise). */
TL_API const char *tl_tiled_shading_name(tl_tiled_shading value);
/** Parses a name of tl_tiled_shading_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_tiled_shading_from_name(const char *name, tl_tiled_shading *value);

/** How a multisampled frame is lit (`msaa` above 1; docs/antialiasing.md). */
typedef enum tl_msaa_lighting {
    TL_MSAA_LIGHTING_DEFAULT = 0,      /**< thin-lpp: the material pass; thin-deferred and fat: per-sample edges */
    TL_MSAA_LIGHTING_MATERIAL_PASS,    /**< thin-lpp: G-buffer and light buffer at 1x, the material pass multisampled */
    TL_MSAA_LIGHTING_SAMPLE_EDGES,     /**< multisampled G-buffer (thin-lpp: and light buffer); edge pixels
                                            (samples differing in depth, normal or material) lit per sample,
                                            the rest per pixel (thin-lpp, thin-deferred, fat; volumes or the
                                            fragment tiled pass) */
    TL_MSAA_LIGHTING_COUNT_            /**< number of values */
} tl_msaa_lighting;

/** "default", "material-pass", "per-sample-edges" ("unknown" otherwise). */
TL_API const char *tl_msaa_lighting_name(tl_msaa_lighting value);
/** Parses a name of tl_msaa_lighting_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_msaa_lighting_from_name(const char *name, tl_msaa_lighting *value);

/** thin-lpp: how a clearcoat material's coat is lit from the light buffer (docs/lighting.md,
 *  "Material models"). */
typedef enum tl_clearcoat_lighting {
    TL_CLEARCOAT_DEFAULT = 0,     /**< "auto": TL_CLEARCOAT_SUMS where they can be planned (a clearcoat drawn, light
                                       scale 1, no MSAA), else TL_CLEARCOAT_APPROXIMATE; tl_frame_plan.clearcoat
                                       says which, and why */
    TL_CLEARCOAT_APPROXIMATE,     /**< "approx": RT0 holds the coat's gloss: the base's specular takes the coat's
                                       lobe (no extra bytes) */
    TL_CLEARCOAT_SUMS,            /**< "sums": when a clearcoat is drawn: the coat's gloss in a G-buffer byte and
                                       its own specular sum in one more light target (9 B/px with RGBA16F); both
                                       lobes exact, with the stipple too. Planned at light scale 1 without MSAA
                                       (elsewhere a downgrade to the approximation, tl_frame_plan.downgrades) */
    TL_CLEARCOAT_COUNT_           /**< number of values */
} tl_clearcoat_lighting;

/** "auto", "approx", "sums" ("unknown" otherwise). */
TL_API const char *tl_clearcoat_lighting_name(tl_clearcoat_lighting value);
/** Parses a name of tl_clearcoat_lighting_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_clearcoat_lighting_from_name(const char *name, tl_clearcoat_lighting *value);

/** Storage of the light buffer's targets (thin-lpp). */
typedef enum tl_light_format {
    TL_LIGHT_FORMAT_DEFAULT = 0, /**< = TL_LIGHT_FORMAT_RGBA16F */
    TL_LIGHT_FORMAT_RGBA16F,     /**< 8 B/px per target, FP16 */
    TL_LIGHT_FORMAT_R11G11B10F,  /**< 4 B/px per target (6- and 5-bit mantissas, no alpha): the exact layout only */
    TL_LIGHT_FORMAT_COUNT_       /**< number of values */
} tl_light_format;

/** "rgba16f" (TL_LIGHT_FORMAT_DEFAULT too), "r11g11b10f" ("unknown" otherwise). */
TL_API const char *tl_light_format_name(tl_light_format value);
/** Parses a name of tl_light_format_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_light_format_from_name(const char *name, tl_light_format *value);

/** The lighting model of a frame (docs/lighting.md); one model per frame, every mode. */
typedef enum tl_lighting_model {
    TL_LIGHTING_DEFAULT = 0,  /**< "auto": the planner picks from the scene's materials: GGX when some drawn
                                   material is authored for it (glTF, TL_MATERIAL_MICROFACET or metallic-roughness),
                                   else Blinn-Phong (the crypt's materials are authored for it) */
    TL_LIGHTING_BLINN_PHONG,  /**< "blinn-phong": normalised Lambert + normalised Blinn-Phong */
    TL_LIGHTING_GGX,          /**< "ggx": normalised Lambert + GGX / Schlick-GGX (k = alpha/2) / Schlick Fresnel */
    TL_LIGHTING_COUNT_        /**< number of values */
} tl_lighting_model;

/** "auto", "blinn-phong", "ggx" ("unknown" otherwise). */
TL_API const char *tl_lighting_model_name(tl_lighting_model model);
/** Parses a name of tl_lighting_model_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_lighting_model_from_name(const char *name, tl_lighting_model *model);

/** How alpha-blended materials are drawn (docs/frame.md, "2d. Transparency through the light
 *  buffer"). */
typedef enum tl_transparency {
    TL_TRANSPARENCY_DEFAULT = 0, /**< "auto": stipple where it applies (thin-lpp, light scale 1, at most
                                      TL_STIPPLE_LAYERS blended objects, no fog, depth of field or
                                      reflections), else forward; tl_frame_plan.transparency says which and why */
    TL_TRANSPARENCY_FORWARD,     /**< "forward": a pass after the opaque frame shades them forward, far to near */
    TL_TRANSPARENCY_STIPPLE,     /**< "stipple": Inferred Lighting's stipple: up to TL_STIPPLE_LAYERS layers
                                      written into the G-buffer on a 2x2 pattern, lit by the light pass and
                                      resolved with stipple-aware filtering; forward where it does not apply */
    TL_TRANSPARENCY_COUNT_       /**< number of values */
} tl_transparency;

/** Transparent layers the stipple has room for: one pixel of each 2x2 quad each, the opaque surface
 *  keeps the fourth. */
#define TL_STIPPLE_LAYERS 3

/** "auto", "forward", "stipple" ("unknown" otherwise). */
TL_API const char *tl_transparency_name(tl_transparency transparency);
/** Parses a name of tl_transparency_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_transparency_from_name(const char *name, tl_transparency *transparency);

/** How thin-lpp's light buffer keeps GGX's Schlick Fresnel, which needs the material's F0 that the
 *  light pass does not have (EXACT light buffer; the compact one always uses TL_FRESNEL_NV). The
 *  other modes evaluate Fresnel per light with the true v.h. */
typedef enum tl_fresnel_layout {
    TL_FRESNEL_DEFAULT = 0, /**< = TL_FRESNEL_TWO_SUMS (docs/renderer.md gives the measurements) */
    TL_FRESNEL_TWO_SUMS,    /**< "two-sums": S1 = sum c w (1 - s) in light.specular, S2 = sum c w s in
                                 light.fresnel, s = (1 - v.h)^5; the material pass forms F0 S1 + S2 (exact) */
    TL_FRESNEL_NV,          /**< "nv": one sum S1 + S2; the material pass applies Schlick with n.v per pixel */
    TL_FRESNEL_COUNT_       /**< number of values */
} tl_fresnel_layout;

/** "two-sums", "nv" ("unknown" otherwise; TL_FRESNEL_DEFAULT is "two-sums"). */
TL_API const char *tl_fresnel_layout_name(tl_fresnel_layout layout);
/** Parses a name of tl_fresnel_layout_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_fresnel_layout_from_name(const char *name, tl_fresnel_layout *layout);

/** FXAA 3.11-style quality presets (edge search lengths as in the 12 / 29 / 39 presets). */
typedef enum tl_fxaa_preset {
    TL_FXAA_DEFAULT = 0, /**< = TL_FXAA_29 */
    TL_FXAA_OFF,         /**< no anti-aliasing (the tone-mapped image is the output) */
    TL_FXAA_12,          /**< 5 search steps */
    TL_FXAA_29,          /**< 12 search steps */
    TL_FXAA_39,          /**< 12 search steps with finer increments */
    TL_FXAA_COUNT_       /**< number of values */
} tl_fxaa_preset;

/** "29" (TL_FXAA_DEFAULT too), "off", "12", "39" ("unknown" otherwise). */
TL_API const char *tl_fxaa_preset_name(tl_fxaa_preset value);
/** Parses a name of tl_fxaa_preset_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_fxaa_preset_from_name(const char *name, tl_fxaa_preset *value);

/** How screen-space ambient occlusion estimates occlusion (docs/effects.md). */
typedef enum tl_ssao_method {
    TL_SSAO_DEFAULT = 0, /**< = TL_SSAO_DISC */
    TL_SSAO_DISC,       /**< "disc": the deferred-shading slides' estimator over a Poisson-disc set of screen-space
                             neighbours p_i: AO = sum (1 - A B)^x / n, A = 1 - smoothstep(0, k_d, |p_i - p| - k_b),
                             B = max(0, n . (p_i - p) / |p_i - p|) */
    TL_SSAO_HEMISPHERE, /**< "hemisphere": points in the normal-oriented hemisphere of the radius, occluded where the surface
                             they project to lies in front of them; each weighted by A as above */
    TL_SSAO_COUNT_      /**< number of values */
} tl_ssao_method;

/** "disc" (TL_SSAO_DEFAULT too), "hemisphere" ("unknown" otherwise). */
TL_API const char *tl_ssao_method_name(tl_ssao_method value);
/** Parses a name of tl_ssao_method_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_ssao_method_from_name(const char *name, tl_ssao_method *value);

/** Screen-space ambient occlusion from depth and RT0 (fat: its position and normal targets;
 *  forward: normals rebuilt from the depth pre-pass). Zeroed: off. */
typedef struct tl_ssao_desc {
    int enabled;           /**< 1: on (default 0: no pass, no target) */
    tl_ssao_method method; /**< default disc */
    uint32_t samples;      /**< samples per pixel, 1..64; default 16 */
    float radius;          /**< view-space radius of the neighbourhood; default 1 */
    float bias;            /**< k_b: distance within which a neighbour occludes fully; default 0 */
    float falloff;         /**< k_d: width of the smoothstep after k_b; default 2 x radius */
    float exponent;        /**< x; default 3 */
    uint32_t blur_radius;  /**< half-width in pixels of the depth-aware blur, 1..8; default 2 */
    int diffuse;           /**< 1: AO also scales the diffuse light (default: the ambient term only) */
} tl_ssao_desc;

/** How fog density varies (docs/effects.md). */
typedef enum tl_fog_mode {
    TL_FOG_DEFAULT = 0, /**< = TL_FOG_DISTANCE */
    TL_FOG_DISTANCE, /**< "distance": constant density: transmittance exp(-density * distance) */
    TL_FOG_HEIGHT,   /**< "height": density * exp(-height_falloff * (y - height)), integrated along the view ray */
    TL_FOG_COUNT_    /**< number of values */
} tl_fog_mode;

/** "distance" (TL_FOG_DEFAULT too), "height" ("unknown" otherwise). */
TL_API const char *tl_fog_mode_name(tl_fog_mode value);
/** Parses a name of tl_fog_mode_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_fog_mode_from_name(const char *name, tl_fog_mode *value);

/** Fog from linear depth, blended over HDR: c = c T + colour (1 - T). Zeroed: off. */
typedef struct tl_fog_desc {
    int enabled;          /**< 1: on (default 0: no pass) */
    tl_fog_mode mode;     /**< default distance */
    float color[3];       /**< linear radiance of the fog; default black */
    float density;        /**< extinction per unit length (height fog: at y = height); default 0.05 */
    float height;         /**< height fog: world y of the reference density; default 0 */
    float height_falloff; /**< height fog: per unit of height; default 0.5 */
    float noise;          /**< 0..1: fractal-noise modulation of the density (computed in the shader, drifting
                               with the frame counter taken at 60 frames per second); default 0: none */
    float noise_scale;    /**< noise: features per unit length; default 0.5 */
    float noise_speed;    /**< noise: drift in units per second; default 0.3 */
} tl_fog_desc;

/** Depth of field: circle of confusion from linear depth, a gather blur in which sharp
 *  foreground does not bleed onto blurred background. Zeroed: off. */
typedef struct tl_dof_desc {
    int enabled;          /**< 1: on */
    float focus_distance; /**< view distance in focus; default: the camera's distance to its target */
    float aperture;       /**< CoC radius at infinity as a fraction of the image height; default 0.01 */
    float max_radius;     /**< largest CoC radius, fraction of the image height; default 2 x aperture */
    uint32_t samples;     /**< gather taps, 8..128; default 48 */
} tl_dof_desc;

/** Bloom: the HDR image above a threshold, blurred by a downsample / upsample chain of half-size
 *  mip levels (the 13-tap downsample and 3x3 tent upsample of Jimenez, "Next generation post
 *  processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014; each upsample blends the coarser
 *  level over the finer one by `scatter`, as Unity's URP bloom does), added to HDR in the tone-map
 *  pass. The chain conserves energy: with threshold 0 the bloom image sums to the HDR image it was
 *  made from (docs/effects.md). Zeroed: off. */
typedef struct tl_bloom_desc {
    int enabled;         /**< 1: on */
    float threshold;     /**< HDR brightness (largest channel) where bloom starts; default 1; negative: exactly 0 */
    float knee;          /**< soft knee as a fraction of the threshold, 0..1; default 0.5; negative: exactly 0 (hard) */
    float intensity;     /**< weight of the bloom image added to HDR; default 0.5 */
    float scatter;       /**< 0..1: weight of each coarser level in the upsample (larger: wider glow); default 0.7 */
    uint32_t levels;     /**< mip levels of the chain, 1..8, the first at half size; default 6 (fewer when the
                              size runs out: a level is never smaller than 1x1) */
} tl_bloom_desc;
/** Screen-space reflections (docs/effects.md): a view-space ray march of the reflected view ray
 *  against the depth buffer (linear steps, then a binary refinement), a hit where the ray lies
 *  behind the surface by less than `thickness`; the HDR colour there, weighted by gloss (RT0),
 *  Schlick's Fresnel with F0 = 0.04, and fades at the screen's edges and the ray's end, is added
 *  to HDR. Thin-lpp, thin-deferred and fat (forward has no gloss to read: not planned). Zeroed: off. */
typedef struct tl_ssr_desc {
    int enabled;        /**< 1: on */
    uint32_t steps;     /**< linear steps along the ray, 4..256; default 48 */
    uint32_t refine;    /**< binary refinement steps after a hit, 0..8 (0 means the default); default 4 */
    float max_distance; /**< view-space length of a ray; default 16 */
    float thickness;    /**< how far behind the depth buffer's surface a ray still hits it (view units);
                             default 0.4 */
    float min_gloss;    /**< gloss below which a pixel reflects nothing (weight rises linearly to 1 at
                             gloss 1), below 1; default 0.4, a negative value means 0 */
    float edge_fade;    /**< fraction of the screen over which hits fade out at its edges, 0..0.5;
                             default 0.1 */
    float intensity;    /**< scale of the added reflection; default 1 */
} tl_ssr_desc;

/** Vignette: HDR darkened towards the corners, by 1 - strength * smoothstep(radius, radius + softness, d)
 *  with d the distance from the image's centre as a fraction of its half-diagonal. Zeroed: off. */
typedef struct tl_vignette_desc {
    int enabled;    /**< 1: on */
    float strength; /**< darkening at full fall-off, 0..1; default 0.5 */
    float radius;   /**< where the fall-off starts (fraction of the half-diagonal); default 0.5 */
    float softness; /**< the fall-off's width (same unit); default 0.5 */
} tl_vignette_desc;

/** How the shadow atlas is filtered (tl_shadow_desc.filter; docs/shadows.md). */
typedef enum tl_shadow_filter {
    TL_SHADOW_FILTER_DEFAULT = 0, /**< = TL_SHADOW_FILTER_PCF */
    TL_SHADOW_FILTER_PCF,         /**< "pcf": percentage-closer filtering with a fixed kernel (pcf_radius) */
    /** Percentage-closer soft shadows: a blocker search in the view's tile, then a PCF whose radius
     *  follows the penumbra of the light's size (tl_light.source_radius for point and spot lights,
     *  tl_shadow_desc.directional_angle for directional ones), at least pcf_radius ("pcss"). */
    TL_SHADOW_FILTER_PCSS,
    TL_SHADOW_FILTER_BILINEAR,    /**< "bilinear": a single bilinear compare tap (the PCF kernel of radius 0) */
    TL_SHADOW_FILTER_COUNT_       /**< number of values */
} tl_shadow_filter;

/** "pcf" (TL_SHADOW_FILTER_DEFAULT too), "pcss", "bilinear" ("unknown" otherwise). */
TL_API const char *tl_shadow_filter_name(tl_shadow_filter value);
/** Parses a name of tl_shadow_filter_name; TL_ERROR_INVALID_ARGUMENT for anything else. */
TL_API tl_result tl_shadow_filter_from_name(const char *name, tl_shadow_filter *value);

/** tl_shadow_desc.max_lights's default (what a zero means), for tools that size other things by it
 *  (tl_gltf_options.shadow_lights). */
#define TL_SHADOW_DEFAULT_MAX_LIGHTS 8u

/** Shadows of the lights with tl_light.shadow (docs/shadows.md): one depth atlas holding a
 *  perspective map per spot light, six cube faces per point light and four stable cascades per
 *  directional light; looked up with PCF (or PCSS) and a bias derived from the texel size and the
 *  depth formats. Zeroed: the defaults below (shadows on for lights that ask for them). */
typedef struct tl_shadow_desc {
    tl_switch enabled;    /**< default on; TL_SWITCH_OFF: no light casts, whatever tl_light.shadow says */
    uint32_t atlas_size;  /**< the atlas's side in texels, 1024..16384, a power of two; default 4096 */
    uint32_t max_lights;  /**< most casting lights given a map per frame (the budget), 1..64; default 8 */
    uint32_t pcf_radius;  /**< PCF kernel: (2 r + 1)^2 bilinear compare taps, r in 1..3; 0 means the default 1
                               (TL_SHADOW_FILTER_BILINEAR is the single tap, r = 0) */
    tl_switch cache;      /**< default on: unchanged maps are kept; TL_SWITCH_OFF: every map rendered every frame */
    tl_shadow_filter filter; /**< default PCF; PCSS for penumbrae that widen away from the contact; BILINEAR */
    /** PCSS: the angular radius of directional lights' discs, radians, 0..0.2; 0 means the default
     *  0.00465 (the sun's and the full moon's). */
    float directional_angle;
} tl_shadow_desc;
/** What is seen where no geometry is drawn, and how bright the environment is (docs/renderer.md,
 *  "Background and environment"). Zeroed: black, and an environment (if one is set) as it is. */
typedef struct tl_environment_options {
    /** Linear radiance of the background where no geometry is drawn and no environment is set,
     *  tone-mapped like the scene; zero (the default): black, and no sky pass in the plan.
     *  Components must be finite and at least 0, at most 65504. */
    float background[3];
    /** Scales the environment set by tl_renderer_set_environment, as sky and as light (diffuse and
     *  specular); 0: the default, 1. Finite, at least 0 (a negative value is refused). */
    float intensity;
} tl_environment_options;

/** A GL entry point as a loader returns it. */
typedef void (*tl_gl_function)(void);
/** Loader for GL entry points, e.g. tl_context_proc_loader or a wrapper of glfwGetProcAddress. */
typedef tl_gl_function (*tl_get_proc_address_fn)(void *user, const char *name);
/** Whether the renderer's GL context is current on the calling thread (non-zero: it is), e.g. a
 *  wrapper of `glfwGetCurrentContext() == window`; called with get_proc_address_user. */
typedef int (*tl_is_current_fn)(void *user);

/** A set of targets: bit tl_target_id of a 64-bit word (tl_renderer_options.keep_targets, the
 *  plan's read, write and clear sets, an application pass's reads and writes). */
typedef uint64_t tl_target_set;
/** The set holding one tl_target_id. */
#define TL_TARGET_BIT(target) ((tl_target_set)1 << (target))
/** Every target (tl_renderer_options.keep_targets): each gets memory of its own. */
#define TL_TARGETS_ALL UINT64_MAX

/** How the renderer draws a frame: every field may change between frames (tl_renderer_set_options)
 *  and every zeroed field means its default. tl_renderer_desc.options holds the first ones. Each
 *  field's name, range, default, unit and help are its row of the option registry (options.h);
 *  an on/off field reads positively: `enabled` or an `int` turns on what is off by default, a
 *  tl_switch turns off what is on by default. */
typedef struct tl_renderer_options {
    tl_render_mode mode;               /**< default thin-lpp */
    tl_depth_format depth_format;      /**< default D24 (D24S8); D32F_REVERSED for reversed Z */
    tl_rt0_packing rt0;                /**< default RGBA8 */
    tl_light_buffer light_buffer;      /**< default EXACT */
    tl_light_format light_format;      /**< default RGBA16F; R11G11B10F needs the EXACT layout */
    tl_light_strategy light_strategy;  /**< default auto */
    tl_lighting_model lighting;        /**< default auto: from the scene's materials (tl_frame_plan.lighting) */
    tl_fresnel_layout fresnel;         /**< thin-lpp with GGX: default two sums (exact) */
    uint32_t tile_size;                /**< tiled strategy: tile side in pixels, 8, 16 or 32; 0: the default (docs/frame.md) */
    tl_tiled_shading tiled_shading;    /**< tiled strategy: the light pass as a fragment or a compute pass;
                                            auto (default): the planner picks (tl_frame_plan.tiled_shading) */
    /** thin-lpp: the light buffer's size per axis against the frame's, 1, 0.5 or 0.25 (0: the
     *  default, 1). Below 1 the light is computed on a reduced depth and RT0, upsampled in the
     *  material pass with depth and normal aware weights, and pixels with no credible reduced
     *  neighbour are re-lit at full resolution (docs/frame.md, "Light at reduced resolution").
     *  Other modes plan as with 1. Both light strategies run at the reduced size, chosen as at
     *  scale 1 (light_strategy, or auto: tiles from 32 local lights on), the tiles counted in the
     *  frame's pixels at twice tile_size (tl_frame_plan.light_strategy and tile_size say which). */
    float light_scale;
    /** Alpha-blended materials: auto (default), forward or stipple (tl_transparency). */
    tl_transparency transparency;
    /** Multisample antialiasing (docs/antialiasing.md): samples per pixel, 2, 4 or 8; 0 or 1, the
     *  default: off. A count the context's multisampled targets lack is planned as the next one
     *  they have, with a warning (llvmpipe: 2 runs with 4; tl_frame_plan.msaa says), one past them
     *  is TL_ERROR_UNSUPPORTED naming options.msaa. thin-lpp keeps its G-buffer and light
     *  buffer at one sample and runs the material pass multisampled, each sample taking the light
     *  of the light-buffer texel that matches its surface (or re-lit where none does); forward
     *  renders multisampled; msaa_lighting picks per-sample lighting on edges instead (thin-lpp) or
     *  as the default (thin-deferred, fat). The resolve tone-maps every sample before averaging.
     *  Planned without (a downgrade: tl_frame_plan.downgrades and the logger say why) at a light
     *  scale below 1, with the screen-space effects the mode runs, which read a one-sample HDR or
     *  depth (forward runs no reflections: ssr costs it nothing), and where msaa_lighting names a
     *  method the mode lacks. */
    uint32_t msaa;
    tl_fxaa_preset fxaa;               /**< default 29 */
    float fxaa_edge_threshold;         /**< default 0.166 (relative local contrast) */
    float fxaa_edge_threshold_min;     /**< default 0.0833 (absolute, in gamma-encoded luma) */
    float fxaa_subpix;                 /**< default 0.75; a negative value means 0 */
    float exposure;                    /**< default 1; multiplies HDR colour before tone mapping */
    /** Linear ambient radiance added to every mode as albedo * ambient * occlusion (docs/renderer.md).
     *  All three zero (the default): the scene's tl_scene.ambient (the glTF loader's 0.03, the
     *  crypt's own). Otherwise it replaces the scene's, and a negative component means exactly 0:
     *  `.ambient = {-1, -1, -1}` turns the ambient term off. */
    float ambient[3];
    tl_switch forward_depth_prepass;   /**< forward mode's depth pre-pass: default on; TL_SWITCH_OFF leaves it out */
    tl_switch planning;                /**< default on; TL_SWITCH_OFF: plan for every feature whatever the scene
                                            uses (all light types, specular, textures, normal maps, alpha): shows
                                            what planning saves */
    int fullscreen_lights;             /**< 1: shade point and spot lights over the whole screen instead
                                            of drawing their volumes (the reference the volume tests
                                            compare against; costs every light the full screen) */
    /** Targets (TL_TARGET_BIT bits, or TL_TARGETS_ALL) the caller reads back after a frame with
     *  tl_renderer_read_target: those the plan has get memory of their own (keeping does not
     *  make the plan produce a target nothing needs). Other targets whose lifetimes in the frame
     *  do not overlap share memory, so reading one that a later pass overwrote fails with
     *  TL_ERROR_INVALID_ARGUMENT. The output is always kept. Default 0. */
    tl_target_set keep_targets;
    /** 1: every tl_renderer_render waits for the GPU (glFinish) and reads its queries at once, so
     *  its statistics describe that frame, as tl_renderer_wait does. Default 0: statistics come
     *  from a small ring of queries read a few frames later, and a frame never waits. */
    int synchronous_stats;
    tl_ssao_desc ssao;                 /**< screen-space ambient occlusion; zeroed: off */
    tl_fog_desc fog;                   /**< fog; zeroed: off */
    tl_dof_desc dof;                   /**< depth of field; zeroed: off */
    tl_bloom_desc bloom;               /**< bloom; zeroed: off */
    tl_ssr_desc ssr;                   /**< screen-space reflections; zeroed: off */
    tl_vignette_desc vignette;         /**< vignette; zeroed: off */
    tl_shadow_desc shadows;            /**< the shadow atlas of lights with tl_light.shadow (docs/shadows.md) */
    tl_environment_options environment; /**< background colour and environment intensity; zeroed: black, 1 */
    /** With `msaa` above 1: how the multisampled frame is lit (tl_msaa_lighting; zeroed: the
     *  mode's default, today's behaviour). */
    tl_msaa_lighting msaa_lighting;
    /** 1: the frame also writes TL_TARGET_SHADOW_DEBUG (the shadow-debug pass, docs/shadows.md
     *  "Debug views"), kept for tl_renderer_read_target: per pixel, R the shadow-only term (the
     *  casting lights' diffuse light with their visibility over the same without it, 0..1), G that
     *  unshadowed diffuse light's luminance (0: no casting light reaches the pixel), B the cascade of
     *  the first casting directional light at the pixel's view depth plus the blend towards the next
     *  (-1: none), A 1 on surfaces, 0 on the background. Planned only with casting lights, and not
     *  with a multisampled G-buffer or depth (tl_frame_plan then has no shadow-debug pass). Default 0:
     *  no pass, the plan as without the field. */
    int shadow_debug;
    /** thin-lpp with a clearcoat material drawn: its coat's light (tl_clearcoat_lighting; zeroed:
     *  auto, the coat's own sums wherever they can be planned). */
    tl_clearcoat_lighting clearcoat;
} tl_renderer_options;

/** What tl_renderer_create() needs: the first options and what only creation decides (the
 *  context, memory, logging and limits); every zeroed field means its default. */
typedef struct tl_renderer_desc {
    uint32_t width;                    /**< default 1280 (tl_renderer_resize changes it) */
    uint32_t height;                   /**< default 720 */
    tl_renderer_options options;       /**< the first frame's options (tl_renderer_set_options changes them) */
    /** The most memory, in bytes, the frame's targets may take (the memory blocks of the plan,
     *  tl_frame_plan.allocated_bytes_per_pixel times the pixels, light lists included): a plan
     *  that needs more is TL_ERROR_LIMIT naming both sizes, from create, set_scene, set_lights,
     *  resize, add_pass or set_options; the renderer keeps its previous plan, size, passes and
     *  options (after a refused set_scene it has no scene). 0: no budget
     *  beyond GL's own limits (docs/renderer-limits.md). */
    size_t max_target_bytes;
    /** The most bytes one storage buffer binding of the renderer may hold: the frame's lights (64 B
     *  each: this bounds the light count, see TL_RENDERER_MAX_LIGHTS), the tiled light lists and
     *  the forward per-object light lists. 0 or more than GL_MAX_SHADER_STORAGE_BLOCK_SIZE: that
     *  (128 MiB on llvmpipe; GL guarantees 16 MiB). A lower value lowers every limit that derives
     *  from it (docs/renderer-limits.md). */
    size_t max_storage_block_bytes;
    tl_get_proc_address_fn get_proc_address; /**< required */
    void *get_proc_address_user;       /**< passed to get_proc_address (and is_current) */
    /** Asked at the start of every call that uses GL (create, destroy, set_scene, set_lights,
     *  set_options, resize, add_pass, remove_pass, render, render_to, wait, the reads and
     *  apply_fxaa): when the
     *  context is not current the call fails with TL_ERROR_GL and a message that says so, and
     *  changes nothing (destroy frees nothing; call it again where the context is current).
     *  Zeroed: with tl_context_proc_loader as get_proc_address, the context's own answer
     *  (tl_context_is_current, exact); otherwise one GL query whenever the calling thread differs
     *  from the last one that had the context (it catches a thread with no context or another
     *  one current, not a context switched on the same thread; docs/getting-started.md). */
    tl_is_current_fn is_current;
    tl_allocator allocator;            /**< zeroed: malloc/free; every allocation of the renderer */
    tl_logger logger;                  /**< zeroed: silent; every failure is also in tl_renderer_last_error */
} tl_renderer_desc;

/** Passes a frame may run, by a stable index (statistics arrays, tl_plan_pass.pass): a new pass is
 *  appended and no value is ever renumbered. The order a frame runs them is the plan's
 *  (tl_frame_plan.passes, the renderer's pass table), not this enum's; a plan holds the ones its
 *  mode, options and scene need. Application passes name their place by pass name. */
typedef enum tl_pass {
    TL_PASS_DEPTH_PREPASS, /**< forward: depth only */
    TL_PASS_GBUFFER,       /**< thin or fat G-buffer (deferred modes also write emissive + ambient into HDR) */
    TL_PASS_SSAO,          /**< SSAO estimator into ao.raw */
    TL_PASS_SSAO_BLUR,     /**< depth-aware blur of ao.raw into ao */
    TL_PASS_SSAO_APPLY,    /**< deferred modes: albedo x ambient x (1 - AO) taken from HDR */
    TL_PASS_LIGHT_CULL,    /**< tiled: per-tile depth bounds and light lists (compute) */
    TL_PASS_LIGHTS,        /**< light volumes: into the light buffer (thin-lpp) or shading into HDR */
    TL_PASS_LIGHTS_TILED,  /**< tiled: every pixel once, looping over its tile's lights */
    TL_PASS_MATERIAL,      /**< thin-lpp second geometry pass, depth EQUAL */
    TL_PASS_FORWARD,       /**< forward shading with per-object light lists */
    TL_PASS_TRANSPARENT,   /**< alpha-blended materials, forward-lit after the opaque frame */
    TL_PASS_SSR,           /**< screen-space reflections: the ray march into ssr */
    TL_PASS_SSR_APPLY,     /**< screen-space reflections: ssr added to HDR */
    TL_PASS_FOG,           /**< fog blended over HDR */
    TL_PASS_DOF,           /**< depth of field: the gather blur of HDR into dof */
    TL_PASS_DOF_APPLY,     /**< depth of field: dof copied into HDR */
    TL_PASS_BLOOM,         /**< bloom: threshold and the downsample / upsample chain of HDR into bloom */
    TL_PASS_TONEMAP,       /**< (bloom added), exposure, tone curve, sRGB encoding */
    TL_PASS_FXAA,          /**< FXAA, when it is on */
    TL_PASS_VIGNETTE,      /**< vignette: its mask, then HDR darkened by it (runs before the tone map) */
    TL_PASS_LIGHT_REDUCE,  /**< light_scale below 1: depth and RT0 reduced to the light buffer's size */
    TL_PASS_STIPPLE_DEPTH, /**< stipple: the opaque depth copied before the transparent layers overwrite it */
    TL_PASS_STIPPLE,       /**< stipple: transparent layers into depth and RT0, one pixel of each 2x2 quad each */
    TL_PASS_STIPPLE_RESOLVE, /**< "stipple-blend": transparent layers blended onto HDR with the light of their own pixels */
    TL_PASS_POINTS_LINES,  /**< points and lines, forward-lit after the opaque frame (1 pixel wide) */
    TL_PASS_SKY,           /**< the background colour or the environment where no geometry is drawn */
    TL_PASS_MSAA_CLASSIFY, /**< MSAA per-sample edges: the pixels whose samples differ in depth or normal, into msaa.edges */
    TL_PASS_LIGHTS_SAMPLES, /**< MSAA per-sample edges: the light pass again, per sample, on edge pixels only */
    TL_PASS_SHADOW_DEBUG,  /**< tl_renderer_options.shadow_debug: the shadow term and cascade of each pixel, into shadow.debug */
    TL_PASS_SHADOWS,       /**< the casting lights' changed views rendered into the shadow atlas (first in the frame) */
    TL_PASS_LIGHT_UPSAMPLE, /**< light_scale below 1: the reduced light buffer upsampled into the full-size one, edges re-lit (compute) */
    TL_PASS_VIS_CLASSIFY,  /**< visibility: each tile's materials, into their lists of tiles (compute) */
    TL_PASS_VIS_RESOLVE,   /**< visibility: per material, its tiles' pixels rebuilt from their triangles and shaded into HDR (compute) */
    TL_PASS_COUNT          /**< number of values; in a plan, the id of an application pass */
} tl_pass;

/** Render targets the renderer may allocate, by a stable index (TL_TARGET_BIT sets, statistics,
 *  readbacks): a new target is appended and no value is ever renumbered. */
typedef enum tl_target_id {
    TL_TARGET_DEPTH,          /**< D24S8, or D32F reversed; fat: D32F */
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
    TL_TARGET_LIGHT_LISTS,    /**< tiled: per-tile light lists (a storage buffer; its bytes per pixel are its
                                   size over the pixels, rounded up) */
    TL_TARGET_AO_RAW,         /**< R16F SSAO estimate before the blur */
    TL_TARGET_AO,             /**< R16F ambient occlusion (1 = open) */
    TL_TARGET_DOF,            /**< RGBA16F depth-of-field image; alpha: circle of confusion radius in pixels */
    TL_TARGET_LIGHT_FRESNEL,  /**< thin-lpp with GGX, two-sums layout: S2, the Schlick part of specular */
    TL_TARGET_BLOOM,          /**< RGBA16F bloom chain: half size (odd sizes round up), tl_bloom_desc.levels mip levels */
    TL_TARGET_SSR,            /**< RGBA16F reflected radiance as added to HDR; alpha: its weight */
    TL_TARGET_VIGNETTE,       /**< R16F vignette factor (1: untouched) */
    TL_TARGET_LIGHT_DEPTH,    /**< light_scale below 1: the nearest depth of each block, depth's format, the light buffer's size */
    TL_TARGET_LIGHT_RT0,      /**< light_scale below 1: RT0 of that nearest sample, the light buffer's size */
    TL_TARGET_LIGHT_OFFSET,   /**< light_scale below 1: R8, that sample's pixel within its block (x + 4 y; 16: its centre) */
    TL_TARGET_LIGHT_FIXUP,    /**< light_scale below 1 or MSAA: a storage buffer (16 bytes), the count of the
                                   pixels (samples) light-upsample (the light scale) or the material pass (MSAA) re-lit */
    TL_TARGET_OPAQUE_DEPTH,   /**< stipple: the opaque surfaces' depth (depth's format); the material pass tests against it */
    TL_TARGET_DEPTH_MSAA,     /**< thin-lpp with MSAA: the multisampled depth the material pass tests against (depth's format) */
    TL_TARGET_MSAA_EDGES,     /**< MSAA per-sample edges: R8, 1 where the pixel's samples differ in depth or normal */
    TL_TARGET_SHADOW_DEBUG,   /**< tl_renderer_options.shadow_debug: RGBA16F, shadow-only term, its weight, cascade, surface */
    TL_TARGET_COAT_GLOSS,     /**< thin-lpp, TL_CLEARCOAT_SUMS: R8, a clearcoat's coat gloss (1 + 254 gloss; 0: no coat) */
    TL_TARGET_LIGHT_COAT,     /**< thin-lpp, TL_CLEARCOAT_SUMS: the coat's specular sum S1 + S2 at its roughness */
    TL_TARGET_SHADOW_ATLAS,   /**< with casting lights: the shadow atlas (reversed D32F, tl_shadow_desc.atlas_size
                                   square; it keeps unchanged maps from frame to frame; read it with
                                   tl_renderer_read_shadow_atlas) */
    TL_TARGET_LIGHT_REDUCED_DIFFUSE,  /**< light_scale below 1: what the light pass writes into LIGHT_DIFFUSE at scale 1,
                                           the light buffer's size (light-upsample makes LIGHT_DIFFUSE of it) */
    TL_TARGET_LIGHT_REDUCED_SPECULAR, /**< light_scale below 1: LIGHT_SPECULAR at the light buffer's size */
    TL_TARGET_LIGHT_REDUCED_FRESNEL,  /**< light_scale below 1: LIGHT_FRESNEL at the light buffer's size */
    TL_TARGET_VIS_ID,         /**< visibility: R32UI, (object slot + 1) << 20 | triangle within the object; 0: nothing drawn */
    TL_TARGET_VIS_TILES,      /**< visibility: a storage buffer, per material bucket an indirect dispatch and its tiles */
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
/** Vertex colour attribute bit (only with tl_scene.colors). */
#define TL_ATTRIBUTE_COLOR 16u
/** Second texture coordinate attribute bit (only with tl_scene.uv1 and a map that reads it). */
#define TL_ATTRIBUTE_UV1 32u

/** Capacity of tl_frame_plan.programs. */
#define TL_PLAN_MAX_PROGRAMS 48
/** Application passes a renderer holds at most (tl_renderer_add_pass). */
#define TL_MAX_APP_PASSES 8
/** Capacity of tl_frame_plan.passes: every built-in pass plus the application passes. */
#define TL_PLAN_MAX_PASSES (TL_PASS_COUNT + TL_MAX_APP_PASSES)

/** One pass of a plan; target sets are TL_TARGET_BIT bits. */
typedef struct tl_plan_pass {
    tl_pass pass;     /**< which pass; TL_PASS_COUNT for an application pass */
    char name[32];    /**< tl_pass_name, or the application pass's name */
    tl_target_set reads;  /**< targets sampled, depth-tested against or blended onto */
    tl_target_set writes; /**< targets rendered to */
    tl_target_set clears; /**< targets cleared when the pass starts (colour 0, depth to the far value) */
} tl_plan_pass;

/** Where a target lives in the frame and which memory it uses. */
typedef struct tl_plan_target {
    uint32_t format;          /**< GL internal format; 0 = not allocated */
    uint32_t bytes_per_pixel; /**< 0 = not allocated */
    uint32_t first_pass;      /**< index in tl_frame_plan.passes of its first writer */
    uint32_t last_pass;       /**< index of its last reader; pass_count when it must survive the
                                   frame (the output, kept targets) */
    uint32_t block;           /**< index in tl_frame_plan.blocks of the memory it uses */
    uint32_t width;           /**< size of its first level: the frame's, or divided and rounded up */
    uint32_t height;          /**< (never 0) */
    uint32_t levels;          /**< mip levels (1 for most targets; each level is half the last, rounded down, at least 1) */
    size_t bytes;             /**< memory of all its levels and samples; bytes_per_pixel is this over the frame's pixels, rounded up */
    uint32_t samples;         /**< samples per pixel: 1, or the MSAA count of a multisampled target */
} tl_plan_target;

/** One allocation that targets with disjoint lifetimes and view-compatible formats share
 *  (texture views of one immutable texture). */
typedef struct tl_plan_block {
    uint32_t bytes_per_pixel; /**< size of the allocation per pixel */
    tl_target_set targets;    /**< the targets it backs (TL_TARGET_BIT bits) */
} tl_plan_block;

/** Capacity of tl_plan_program.defines. */
#define TL_PLAN_DEFINES_SIZE 2048

/** A shader permutation the plan needs: the program's name and its preprocessor defines. */
typedef struct tl_plan_program {
    tl_pass pass;      /**< the pass that runs it */
    uint32_t slot;     /**< which of the pass's programs (lights: 0 point, 1 spot, 2 directional) */
    char name[32];     /**< e.g. "gbuffer", "lights.point" */
    char defines[TL_PLAN_DEFINES_SIZE]; /**< space-separated NAME or NAME=VALUE switches (never cut: the
                                             size holds every switch the renderer has) */
} tl_plan_program;

/** Capacity of tl_frame_plan.downgrades (more than one plan can make at once). */
#define TL_PLAN_MAX_DOWNGRADES 12

/** An option the plan does not honour as asked (docs/frame.md, "Downgrades"): an option the
 *  caller set to a value whose pass, method or saving the plan leaves out or replaces. The renderer
 *  logs each one once (TL_LOG_WARNING, when it first appears in a plan) and the tools print it;
 *  tl_plan_downgrade_format writes it as one line. */
typedef struct tl_plan_downgrade {
    char option[32];  /**< the tl_renderer_options field as the API spells it ("msaa", "light_scale",
                           "transparency", "clearcoat", "fresnel", "ssr.enabled", ...) */
    char asked[24];   /**< the value asked ("4", "0.5", "stipple", "sums", "1") */
    char planned[24]; /**< what the plan does instead ("1", "forward", "approx", "off") */
    char reason[96];  /**< why */
} tl_plan_downgrade;

/** What a frame allocates, runs and compiles (docs/frame.md, "The frame planner"): the frame graph. */
typedef struct tl_frame_plan {
    tl_render_mode mode;                         /**< the mode planned for */
    uint32_t width;                              /**< target width in pixels */
    uint32_t height;                             /**< target height in pixels */
    size_t pass_count;                           /**< entries used in passes */
    tl_plan_pass passes[TL_PLAN_MAX_PASSES];     /**< in execution order; passes nobody reads are culled */
    tl_target_set targets;                       /**< allocated targets (TL_TARGET_BIT bits) */
    uint32_t target_bytes_per_pixel[TL_TARGET_COUNT]; /**< 0 = not allocated */
    tl_plan_target target_info[TL_TARGET_COUNT]; /**< lifetime and memory of each allocated target */
    size_t block_count;                          /**< entries used in blocks */
    tl_plan_block blocks[TL_TARGET_COUNT];       /**< the allocations behind the targets */
    uint32_t bytes_per_pixel;                    /**< sum over allocated targets */
    uint32_t allocated_bytes_per_pixel;          /**< sum over blocks: the memory actually allocated */
    size_t allocated_bytes;                      /**< the same in bytes (reduced-size targets counted exactly) */
    uint32_t peak_live_bytes_per_pixel;          /**< most bytes live during one pass (a lower bound) */
    uint32_t gbuffer_bytes_per_pixel;            /**< depth + G-buffer + light buffer + tiled light
                                                      lists (what the technique stores) */
    uint32_t vertex_attributes;                  /**< TL_ATTRIBUTE_* bound by the geometry passes */
    uint32_t light_types;                        /**< bits (1u << tl_light_type) drawn by the light pass */
    tl_light_strategy light_strategy;            /**< volumes or tiled (never auto) */
    char strategy_reason[96];                    /**< why the planner chose it */
    tl_lighting_model lighting;                  /**< blinn-phong or ggx (never auto) */
    tl_fresnel_layout fresnel;                   /**< thin-lpp with GGX and specular: how the light buffer keeps
                                                      Fresnel; TL_FRESNEL_DEFAULT where it does not apply */
    char lighting_reason[96];                    /**< why the planner chose the model */
    uint32_t tile_size;                          /**< tiled: tile side in pixels (0 with volumes) */
    uint32_t tiles_x;                            /**< tiled: tiles across */
    uint32_t tiles_y;                            /**< tiled: tiles down */
    tl_tiled_shading tiled_shading;              /**< tiled, deferred modes: the light pass's shader, fragment or
                                                      compute (never auto); TL_TILED_SHADING_DEFAULT otherwise */
    float light_scale;                           /**< the light buffer's size per axis against the frame's
                                                      (1, 0.5, 0.25): 1 outside thin-lpp */
    char light_scale_reason[96];                 /**< why, when the options asked for a scale below 1 */
    tl_transparency transparency;                /**< forward or stipple (never auto); forward without blended materials */
    char transparency_reason[96];                /**< why, when the scene has blended materials */
    uint32_t msaa;                               /**< samples per pixel of the multisampled targets; 1: no MSAA */
    char msaa_reason[96];                        /**< how MSAA is applied, or why not, when the options ask for it */
    size_t program_count;                        /**< entries used in programs */
    tl_plan_program programs[TL_PLAN_MAX_PROGRAMS]; /**< every permutation the frame compiles */
    uint32_t shadow_lights;                      /**< casting lights the plan looks up shadows for; 0: no
                                                      shadow pass and no shadow branch in any shader */
    tl_clearcoat_lighting clearcoat;             /**< thin-lpp with a clearcoat drawn and lights: SUMS or
                                                      APPROXIMATE; TL_CLEARCOAT_DEFAULT where it does not apply */
    char clearcoat_reason[96];                   /**< why, where it applies */
    size_t downgrade_count;                      /**< entries used in downgrades; 0: every option as asked */
    tl_plan_downgrade downgrades[TL_PLAN_MAX_DOWNGRADES]; /**< the options the plan does not honour */
} tl_frame_plan;

/**
 * Plans a frame for `desc` (defaults resolved as tl_renderer_create does) and a scene with
 * `features`: selects the passes from the pass table, culls those whose outputs nobody reads,
 * gives every target a lifetime and lets targets share memory. Pure: no GL, no allocation.
 * TL_ERROR_INVALID_ARGUMENT for NULL pointers or an option out of range.
 */
TL_API tl_result tl_frame_plan_build(const tl_renderer_desc *desc, const tl_scene_feature_set *features,
                                     tl_frame_plan *plan);
/** Writes the plan as text (passes with inputs, outputs and clears, targets with bytes per pixel,
 *  lifetimes and memory, attributes, the downgrades, programs). Returns the length it needs
 *  without the NUL, like snprintf; a NULL buffer asks for it. */
TL_API size_t tl_frame_plan_format(const tl_frame_plan *plan, char *buffer, size_t size);
/** Writes one downgrade as the line the renderer logs, e.g. "options.msaa = 4 is planned as 1: the
 *  reduced light buffer's upsample runs at one sample" (no newline). Returns the length it needs
 *  without the NUL, like snprintf; a NULL buffer asks for it; NULL `downgrade` writes "". */
TL_API size_t tl_plan_downgrade_format(const tl_plan_downgrade *downgrade, char *buffer, size_t size);

/** What one frame cost and allocated (tl_renderer_render, tl_renderer_wait). */
typedef struct tl_frame_stats {
    uint64_t frame;                     /**< which frame these figures describe (1 = the first
                                             rendered); 0 when no frame's queries are ready yet */
    int gpu_valid;                      /**< 1 when the GPU figures (pass_ms, fragments, bytes) are
                                             from that frame's queries */
    double pass_ms[TL_PASS_COUNT];      /**< GPU time per pass (timer queries); 0 for passes not in the
                                             plan, -1 when unavailable */
    double app_pass_ms[TL_MAX_APP_PASSES]; /**< GPU time of each application pass, in the order added */
    uint64_t pass_fragments[TL_PASS_COUNT]; /**< fragments that passed the depth test (samples-passed query) */
    double pass_bytes[TL_PASS_COUNT];   /**< estimate of bytes moved per pass (docs/bandwidth.md) */
    double bytes_moved;                 /**< sum of pass_bytes */
    double gpu_ms;                      /**< sum of pass_ms and app_pass_ms (the shadows pass included) */
    double cpu_ms;                      /**< CPU time of the calling thread in the render call, issuing commands
                                             (thread CPU clock, before any wait for statistics; on llvmpipe it
                                             includes Mesa's vertex processing and binning, which run there) */
    double wall_ms;                     /**< render call start to GPU done; synchronous statistics only, else 0 */
    size_t target_bytes[TL_TARGET_COUNT]; /**< bytes each allocated target occupies; 0 = not allocated */
    size_t gbuffer_bytes;               /**< depth + RT0 + RT1 + FAT_* + VIS_ID (no effect target, no light lists) */
    size_t light_buffer_bytes;          /**< LIGHT_DIFFUSE + LIGHT_SPECULAR + LIGHT_FRESNEL (+ their LIGHT_REDUCED_* copies) */
    size_t total_target_bytes;          /**< sum of target_bytes */
    size_t allocated_target_bytes;      /**< memory the targets actually occupy (shared blocks once) */
    uint32_t objects_drawn;             /**< after frustum culling, per geometry pass */
    uint32_t lights_drawn[TL_LIGHT_TYPE_COUNT_]; /**< instances per light type after culling */
    uint64_t light_fragments[TL_LIGHT_TYPE_COUNT_]; /**< pixels covered by each type's light volumes
                                                        (fragments shaded in the light pass) */
    uint64_t forward_light_pairs;       /**< forward: sum over drawn objects of the lights in their list */
    uint64_t light_pairs;               /**< pixel-light pairs the light pass shaded: fragments of the light
                                             volumes; tiled: pixels x lists of their tiles (from the GPU), a tile
                                             whose list overflowed x every light of its chunk (which it loops over) */
    uint32_t tile_overflows;            /**< tiled: tiles whose list did not fit and that looped over every
                                             visible light instead (none is lost; the lists grow for later frames) */
    uint64_t light_list_entries;        /**< tiled: entries of all tile lists */
    uint32_t draw_calls;                /**< GL draw calls of the frame */
    uint32_t programs_compiled;         /**< shader programs compiled so far by this renderer (cache misses) */
    uint64_t relit_pixels;              /**< light_scale below 1: pixels light-upsample's edge fix-up re-lit at full
                                             resolution, each once; MSAA in thin-lpp: the material pass's re-lit
                                             fragments (a sample two coplanar surfaces both draw counts twice) */
    double relit_fraction;              /**< relit_pixels over the frame's pixels */
    uint32_t shadow_lights;             /**< casting lights with a map this frame (their views in the atlas):
                                             the budget's, plus for 8 frames those leaving it (fading out) */
    uint32_t shadow_lights_fading;      /**< of those, the ones whose shadow is fading in or out */
    uint32_t shadow_maps_rendered;      /**< atlas views (cascades, cube faces, spot maps) rendered this frame */
    uint32_t shadow_maps_cached;        /**< atlas views kept from an earlier frame (nothing in range changed) */
    size_t shadow_atlas_bytes;          /**< the shadow atlas's memory (0 without casting lights) */
    double shadow_ms;                   /**< GPU time of this frame's shadow-map rendering: pass_ms[TL_PASS_SHADOWS]
                                             when a map was rendered, 0 when every map was cached; -1: unavailable */
    uint64_t msaa_edge_pixels;          /**< MSAA per-sample edges: pixels lit per sample (msaa-classify's count) */
    double msaa_edge_fraction;          /**< msaa_edge_pixels over the frame's pixels */
    uint32_t shadow_lights_unmapped;    /**< casting lights that reach the view but have no map this frame:
                                             over the budget (tl_shadow_desc.max_lights); the first time
                                             (and whenever the count grows) the logger gets a warning */
} tl_frame_stats;

/** "gbuffer", "lights", ... ("unknown" out of range); the names of debug groups and timers. */
TL_API const char *tl_pass_name(tl_pass pass);
/** The pass named `name` (tl_pass_name); TL_ERROR_INVALID_ARGUMENT for any other name. */
TL_API tl_result tl_pass_from_name(const char *name, tl_pass *pass);
/** "depth", "rt0", "light.diffuse", ... ("unknown" out of range). */
TL_API const char *tl_target_name(tl_target_id target);
/** The target named `name` (tl_target_name); TL_ERROR_INVALID_ARGUMENT for any other name. */
TL_API tl_result tl_target_from_name(const char *name, tl_target_id *target);

/** Creates the renderer in the current context. On failure *out is NULL and the message naming
 *  the problem goes to desc->logger (there is no object to ask). Every call that uses GL then
 *  needs that context current on the calling thread, or fails with TL_ERROR_GL and changes
 *  nothing (tl_renderer_desc.is_current). */
TL_API tl_result tl_renderer_create(const tl_renderer_desc *desc, tl_renderer **out);
/** Frees every GL object and allocation of the renderer (in its context, which must be current:
 *  otherwise it frees nothing and logs why; call it again where the context is current); NULL is
 *  ignored. Destroy the renderer before its context. */
TL_API void tl_renderer_destroy(tl_renderer *r);
/** The last failure's message on this renderer ("" when none): about this renderer's calls only
 *  (a failed tl_image_write leaves it as it was). The line of whichever call failed last, in any
 *  layer, is in the tl_last_error of a tl_last_error_logger given to every descriptor (base.h). */
TL_API const char *tl_renderer_last_error(const tl_renderer *r);

/** Uploads a scene (geometry, materials, textures, lights), plans the frame from its features,
 *  allocates the plan's targets and compiles the shader permutations it needs (cached across
 *  calls, keyed by their defines). The scene may be freed afterwards.
 *  The renderer trusts that each array holds its count of elements; it checks the counts first,
 *  before reading an array, allocating or calling GL: more than 2^32 - 1 vertices, objects,
 *  materials or textures, more than 2^29 indices (a 2 GiB index buffer), or more than
 *  TL_RENDERER_MAX_LIGHTS lights is TL_ERROR_LIMIT; a count whose array is NULL, an index count
 *  or object range that is not whole triangles, an index >= vertex_count, an object whose index
 *  range or material lies outside the arrays (a scene without materials draws material 0 as the
 *  zeroed tl_material), or a non-finite position is TL_ERROR_INVALID_ARGUMENT. Then objects'
 *  transforms and bounds, textures (a side 0 or over GL_MAX_TEXTURE_SIZE: TL_ERROR_LIMIT, no
 *  pixels), materials' texture maps, lights and the camera are checked as tl_object, tl_texture,
 *  tl_material, tl_light and tl_camera say, each refusal naming the field ("textures[3].width =
 *  0: outside 1..16384"; docs/renderer-limits.md). Zeroes are resolved in the renderer's copy
 *  (the scene is not written): a zero transform is the identity, zero bounds are computed from
 *  the object's triangles, a zeroed material is plain grey, a zeroed camera frames the objects. A
 *  refused scene leaves the previous one in place. */
TL_API tl_result tl_renderer_set_scene(tl_renderer *r, const tl_scene *scene);
/** The most lights a scene or tl_renderer_set_lights may hold: 2^20, or fewer where the GL's
 *  GL_MAX_SHADER_STORAGE_BLOCK_SIZE (or tl_renderer_desc.max_storage_block_bytes) holds fewer
 *  lights of 64 bytes (16 MiB, GL's minimum: 262144). More is TL_ERROR_LIMIT naming both counts,
 *  before anything is allocated; the renderer keeps its lights (docs/renderer-limits.md). */
#define TL_RENDERER_MAX_LIGHTS (1u << 20)

/** Replaces the lights only (same scene geometry); re-plans when the light types change. A light
 *  tl_light does not allow is TL_ERROR_INVALID_ARGUMENT naming it and the field
 *  ("lights[3].radius = 0: a point light needs a finite radius > 0"); the renderer keeps its lights. */
TL_API tl_result tl_renderer_set_lights(tl_renderer *r, const tl_light *lights, size_t count);

/*
 * Scene updates: between two frames, without uploading the scene's vertices again. An object's id
 * is its index in tl_scene.objects, or the id tl_renderer_add_object gave; ids stay until the
 * object is removed, and a removed id is reused by a later add. Every call refuses (naming the
 * field, TL_ERROR_INVALID_ARGUMENT, the scene unchanged) an id that does not exist or was removed,
 * and everything tl_renderer_set_scene refuses in an object or material; before a scene is set
 * they are TL_ERROR_INVALID_ARGUMENT. Changes take effect at the next frame (docs/renderer.md,
 * "Scene updates", gives what each costs).
 */
/** Moves an object: `transform` is column-major object-to-world, all zero the identity. Its bounds
 *  follow: its triangles' box in object space (computed at set_scene, or when the object was set
 *  or added) through the new transform, replacing bounds that were given (give them again with
 *  tl_renderer_set_object). Copies 16 floats and 6 bounds: no GL call, no upload. */
TL_API tl_result tl_renderer_set_object_transform(tl_renderer *r, uint32_t object, const float transform[16]);
/** Shows or hides an object (hidden: never drawn, culled or shaded; it keeps its slot). */
TL_API tl_result tl_renderer_set_object_visible(tl_renderer *r, uint32_t object, int visible);
/** Replaces an object's record (index range, material, transform, bounds; zeroes resolved as at
 *  set_scene: zero bounds from its triangles, read from the GPU once for an index range no object
 *  drew before). Its visibility stays. Re-plans when the scene's features change (a material
 *  with textures, normal maps or blending where none was). */
TL_API tl_result tl_renderer_set_object(tl_renderer *r, uint32_t object, const tl_object *desc);
/** Adds an object drawing a range of the scene's indices (set_scene's, or tl_renderer_add_geometry's)
 *  and writes its id. Grows the per-object arrays by doubling (TL_ERROR_LIMIT past the frame's
 *  per-object storage block, as set_scene). */
TL_API tl_result tl_renderer_add_object(tl_renderer *r, const tl_object *desc, uint32_t *object);
/** Removes an object: its id is free for the next add. */
TL_API tl_result tl_renderer_remove_object(tl_renderer *r, uint32_t object);
/** Appends vertices and indices to the scene's buffers (indices count from the first vertex given)
 *  and writes where the new indices start in the scene's index range, for tl_object.first_index.
 *  Uploads only the new data: the buffers grow by half on the GPU when full (the old contents are
 *  copied there, never from the CPU). Checked as set_scene checks a scene. */
TL_API tl_result tl_renderer_add_geometry(tl_renderer *r, const tl_vertex *vertices, size_t vertex_count,
                                          const uint32_t *indices, size_t index_count, uint32_t *first_index);
/** Replaces material `index` of the scene (one std140 record written). Its maps may name the
 *  textures that some material of the scene named at set_scene (the renderer keeps only those) or
 *  that tl_renderer_add_texture added; another is TL_ERROR_INVALID_ARGUMENT naming the field.
 *  Re-plans when the features change. */
TL_API tl_result tl_renderer_set_material(tl_renderer *r, uint32_t index, const tl_material *material);
/** Adds a texture after set_scene and writes its index in the scene's textures, for
 *  TL_TEXTURE_MAP(index) in the maps of tl_renderer_add_material or set_material: an application's
 *  own textures beside a loaded glTF's. Checked as set_scene checks tl_scene.textures (refused
 *  naming the field, "texture.width = 0: outside 1..16384"). The pixels are uploaded now (kept as
 *  sRGB; a material that reads the texture as data gets a linear copy made on the GPU) and are the
 *  caller's again when the call returns. */
TL_API tl_result tl_renderer_add_texture(tl_renderer *r, const tl_texture *texture, uint32_t *index);
/** Adds a material after set_scene and writes its index, for tl_object.material in
 *  tl_renderer_add_object or set_object. Checked as set_scene checks tl_scene.materials; its maps
 *  may name textures added with tl_renderer_add_texture or named by a material at set_scene. In a
 *  scene without materials, the zeroed material its objects draw becomes material 0 and the first
 *  material added is 1. Re-plans only when an object draws it with something the scene lacked
 *  (docs/getting-started.md, "A loaded scene and your own objects"). */
TL_API tl_result tl_renderer_add_material(tl_renderer *r, const tl_material *material, uint32_t *index);
/** An object as the renderer draws it (transform and bounds resolved) and whether it is visible;
 *  TL_ERROR_INVALID_ARGUMENT for an id that does not exist or was removed. */
TL_API tl_result tl_renderer_get_object(tl_renderer *r, uint32_t object, tl_object *desc, int *visible);
/** An environment: an equirectangular image of linear RGB radiance (docs/renderer.md, "Background
 *  and environment"). Row 0 is the top (+Y, up), column 0 is the direction -X, the middle column
 *  +X, a quarter across -Z (u = atan2(z, x) / 2 pi + 1/2, v = acos(y) / pi, world space). */
typedef struct tl_environment_desc {
    const float *rgb;  /**< width * height * 3 floats, rows top to bottom; NaN and negative values
                            are taken as 0, values above 65504 (and +Inf) as 65504 */
    uint32_t width;    /**< pixels; exactly twice the height, at most 16384 */
    uint32_t height;   /**< pixels; at least 2 */
} tl_environment_desc;

/**
 * Sets the environment drawn as the sky and lighting every material (image-based light: diffuse
 * from 9 spherical-harmonic coefficients, specular from a GGX-prefiltered mip chain and a split-sum
 * BRDF table, both computed here on the CPU), in every mode; NULL removes it. The pixels are
 * copied. TL_ERROR_INVALID_ARGUMENT names the problem (size, NULL pixels); the previous
 * environment stays then. Re-plans when an environment appears or goes.
 */
TL_API tl_result tl_renderer_set_environment(tl_renderer *r, const tl_environment_desc *desc);

/** One face of a cube environment: square, linear RGB radiance. */
typedef struct tl_environment_face {
    const float *rgb;    /**< the face's first row; rows are GL's t = 0 first (the top of a side face) */
    uint32_t width;      /**< pixels; equal to height, and the same for all six faces */
    uint32_t height;     /**< pixels; at least 1 */
    uint32_t row_floats; /**< floats from one row to the next; 0 = width * 3 (6 x 1 strip: 6 * width * 3) */
} tl_environment_face;

/** A cube environment (docs/renderer.md, "Background and environment"): six faces in GL's order
 *  +X, -X, +Y, -Y, +Z, -Z (GL_TEXTURE_CUBE_MAP_POSITIVE_X + i), each oriented as GL samples a cube
 *  map (world space, +Y up): for a direction d with major axis m, face +X spans s = -z, t = -y;
 *  -X s = z, t = -y; +Y s = x, t = z; -Y s = x, t = -z; +Z s = x, t = -y; -Z s = -x, t = -y
 *  (each over [-|m|, |m|]). */
typedef struct tl_environment_cube_desc {
    tl_environment_face faces[6]; /**< +X, -X, +Y, -Y, +Z, -Z */
} tl_environment_cube_desc;

/**
 * Sets a cube environment: resampled (bilinearly, each face clamped at its edges) into the
 * equirectangular image of 4 * size x 2 * size that tl_renderer_set_environment takes, then as that.
 * TL_ERROR_INVALID_ARGUMENT, naming the face, for NULL pixels, a face that is not square, faces of
 * different sizes, or a NaN pixel; TL_ERROR_LIMIT past 4096 pixels a side. NULL removes the
 * environment. The previous environment stays on failure.
 */
TL_API tl_result tl_renderer_set_environment_cube(tl_renderer *r, const tl_environment_cube_desc *desc);
/** The conversion tl_renderer_set_environment_cube makes, for a caller: `rgb` holds
 *  (4 * size) x (2 * size) x 3 floats (size: the faces'). No check: give a checked cube. */
TL_API void tl_environment_cube_to_equirect(const tl_environment_cube_desc *desc, float *rgb);

/**
 * Changes the options from the next frame on (and for tl_renderer_apply_fxaa): mode, depth format,
 * light strategy, lighting model, effects, FXAA, ... Every zeroed field means its default, as in
 * tl_renderer_desc.options. The scene, its lights and the application passes stay; the frame is
 * planned again, and only what the new plan changes is made again: targets whose format or size
 * changed, programs not built before (each permutation is built once per renderer and kept), the
 * scene's vertex array when the plan binds other attributes. An option out of range is
 * TL_ERROR_INVALID_ARGUMENT naming it, a plan over tl_renderer_desc.max_target_bytes
 * TL_ERROR_LIMIT; either way the renderer keeps its options. NULL is TL_ERROR_INVALID_ARGUMENT.
 */
TL_API tl_result tl_renderer_set_options(tl_renderer *r, const tl_renderer_options *options);
/** The options as last given (to tl_renderer_create or tl_renderer_set_options), zeroed fields
 *  as they were: change a field and give them back. A zeroed struct for NULL. */
TL_API void tl_renderer_get_options(const tl_renderer *r, tl_renderer_options *options);
/** Changes the target size (a resized window): re-plans and reallocates the targets. */
TL_API tl_result tl_renderer_resize(tl_renderer *r, uint32_t width, uint32_t height);

/** The current plan; TL_ERROR_INVALID_ARGUMENT before a scene is set. */
TL_API tl_result tl_renderer_get_plan(const tl_renderer *r, tl_frame_plan *plan);

/** Renders one frame with `camera` (NULL: the scene's) into the renderer's own targets. A camera
 *  tl_camera does not allow is TL_ERROR_INVALID_ARGUMENT naming the field ("camera.fov_y =
 *  3.14159: outside (0, pi)"); a near plane below the depth format's floor is raised, with one
 *  warning per scene. It does not wait for the GPU unless tl_renderer_options.synchronous_stats is set. `stats` may be NULL (the
 *  frame then issues no queries); otherwise it receives the newest frame whose queries are ready
 *  (stats->frame says which; CPU figures are of that frame too). */
TL_API tl_result tl_renderer_render(tl_renderer *r, const tl_camera *camera, tl_frame_stats *stats);
/** Waits until the GPU has finished every frame rendered so far (glFinish), reads their queries
 *  and, when `stats` is non-NULL, gives the last frame's statistics. Also reports GL errors the
 *  frames raised (TL_ERROR_GL). */
TL_API tl_result tl_renderer_wait(tl_renderer *r, tl_frame_stats *stats);

/*
 * The light pass's roofline (docs/bandwidth.md, "Reading the results"): the work a frame must do
 * and what one unit of it costs at best, to set beside tl_frame_stats.light_pairs (what the
 * strategy evaluated) and the light passes' time.
 */
/** The exact pixel-light pairs of the last rendered frame (tl_renderer_count_light_pairs). */
typedef struct tl_light_pair_count {
    uint64_t exact_pairs;       /**< pairs of a pixel and a local (point or spot) light whose surface point
                                     lies inside the light's range and, for a spot, its outer cone: the
                                     shaders' own tests (d^2 < r^2; dot(-to_light, axis) > cos_outer d) */
    uint64_t covered_pixels;    /**< pixels with at least one local light in range */
    uint64_t surface_pixels;    /**< pixels with a surface (depth not at the clear value) */
    uint64_t directional_pairs; /**< surface_pixels x the directional lights: every surface pixel is lit by
                                     each; not in exact_pairs (local lights only) */
    uint32_t width;             /**< the grid counted: the frame's width, or the light buffer's below light_scale 1 */
    uint32_t height;            /**< the grid's height */
    uint32_t local_lights;      /**< the scene's point and spot lights, all tested */
    uint32_t directional_lights; /**< the scene's directional lights (directional_pairs) */
} tl_light_pair_count;
/**
 * Counts exactly, on the CPU, the pixel-light pairs of the last frame rendered (tl_renderer_render
 * or render_to), from the depth the light pass read, read back (a glGetTextureImage and a wait),
 * and the renderer's lights in the frame's view space, through the same camera. A pixel's point
 * is reconstructed as the light pass does (its centre, the depth's linear distance); at a
 * light_scale below 1 the grid is the light buffer's, each texel at the pixel its reduced depth came
 * from (TL_TARGET_LIGHT_DEPTH and TL_TARGET_LIGHT_OFFSET). A multisampled depth (MSAA with
 * per-sample lighting, or a mode whose depth is multisampled) is resolved as tl_renderer_read_target
 * resolves it, one sample per pixel: the count is per pixel, not per sample. Each light tests only
 * the pixels of a conservative screen rectangle around its range. Not a steady-frame call: it
 * allocates up to 18 bytes a cell and waits for the GPU. TL_ERROR_INVALID_ARGUMENT before a
 * frame, or when the depth's memory was reused by a later pass (keep it with keep_targets).
 */
TL_API tl_result tl_renderer_count_light_pairs(tl_renderer *r, tl_light_pair_count *out);

/** The ALU probe's figures (tl_renderer_light_probe). */
typedef struct tl_light_probe_result {
    double ns_per_pair;   /**< GPU time per light evaluation: the light function's cost at its floor */
    double ms;            /**< the timed dispatch's evaluations (less the dispatch of 0 rounds) */
    uint64_t pairs;       /**< light evaluations it made */
    uint32_t lights;      /**< the lights it held in registers (up to 8 of the scene's local lights) */
    int gpu_timed;        /**< 1: GL timestamp queries timed it; 0: the wall clock around a glFinish */
} tl_light_probe_result;
/**
 * Times one compute dispatch that evaluates the frame's light function (tl_light_data_weights of
 * shaders/light_eval.glsl under the plan's lighting model, with the range and cone tests the light
 * passes make before it) for up to 8 of the scene's local lights (a unit point light when it has
 * none), loaded once into registers: no light list, no G-buffer read; every pair is in range and
 * faces its light and the eye, so the whole function runs. One invocation per pixel of the frame
 * (at least 4096), as many rounds over the 8 lights as make the evaluations take about 4 ms beyond
 * a dispatch of 0 rounds (the launch and the wait), whose time is taken off; each the fastest of
 * three. Timed by GL timestamp queries, or by the wall clock around the dispatch and a glFinish
 * where the timestamps see less than half of it (llvmpipe). The lighting model is the plan's
 * (Blinn-Phong before a scene). Needs compute shaders (every context thinlight runs on has them);
 * waits for the GPU. Not a steady-frame call: it compiles its program on the first call.
 */
TL_API tl_result tl_renderer_light_probe(tl_renderer *r, tl_light_probe_result *out);

/** A framebuffer owned by the caller (GL name; 0 is the context's default framebuffer). */
typedef struct tl_render_output {
    uint32_t framebuffer;   /**< GL framebuffer name */
    uint32_t x;             /**< left edge of the viewport in it */
    uint32_t y;             /**< bottom edge of the viewport in it */
    uint32_t width;         /**< 0: the renderer's width; otherwise the image is scaled (linear) */
    uint32_t height;        /**< 0: the renderer's height */
} tl_render_output;

/**
 * Renders one frame like tl_renderer_render, with the pass that writes the output writing into
 * `output` instead. The renderer's own output target is not written (tl_renderer_read_output
 * reads the last frame rendered with tl_renderer_render). A framebuffer name that is not a
 * framebuffer object of the current context, or one that is not complete, is
 * TL_ERROR_INVALID_ARGUMENT naming it; the last 4 names found complete are not asked about again.
 *
 * No state the application left in the context changes the image: a frame sets every piece of
 * state its passes depend on (docs/renderer.md, "The GL contract", has the table). The GL state
 * it leaves, as after tl_renderer_render: framebuffer 0 bound for drawing and reading, program 0,
 * vertex array 0, no texture or sampler on the units it used (0..29), no uniform or storage
 * buffer on the binding points it used (0..5) nor on the generic bindings (the dispatch-indirect
 * binding too), no image on the image
 * units it used (0..3); blending, depth test, face culling, depth clamp, scissor and stencil
 * tests off; depth mask and colour mask on; clip control (GL_LOWER_LEFT,
 * GL_NEGATIVE_ONE_TO_ONE); the viewport is the output rectangle (render_to) or the renderer's
 * size (render); the fixed-function state of the table's entry column (front face CCW, depth
 * range [0, 1], logic op, polygon offset, rasteriser discard, primitive restart, sRGB writes and
 * multisample coverage off, ...). Pixel-store state and pixel buffers are the application's again
 * after every call that transfers pixels. Other state is not touched.
 */
TL_API tl_result tl_renderer_render_to(tl_renderer *r, const tl_camera *camera, const tl_render_output *output,
                                       tl_frame_stats *stats);

/** The view of the frame being rendered, as an application pass sees it (column-major matrices,
 *  view space looks down -Z). */
typedef struct tl_view_info {
    float view[16];       /**< world to view */
    float projection[16]; /**< view to clip (tl_projection_perspective for the depth format) */
    float view_projection[16]; /**< projection * view */
    float eye[3];         /**< camera position, world space */
    float near_z;         /**< near plane distance */
    float far_z;          /**< far plane distance; 0 for an infinite far plane */
    int reversed_z;       /**< 1 with TL_DEPTH_FORMAT_D32F_REVERSED (clip control [0,1], depth 1 = near) */
    uint32_t width;       /**< target size in pixels */
    uint32_t height;      /**< target size in pixels */
} tl_view_info;

/** What an application pass receives. */
typedef struct tl_app_pass_context {
    const tl_view_info *view;              /**< the frame's view */
    /** GL texture names of the targets it declared as reads (0 otherwise). TL_TARGET_LIGHT_LISTS is
     *  a storage buffer: its entry is the GL buffer name of the tile headers, four uint32 counters
     *  then, per tile row by row from the bottom left (tl_frame_plan.tiles_x across, tile_size
     *  pixels square), two uint32: the first entry of its list and its count of local lights (first
     *  = 0xFFFFFFFF: the list overflowed and the tile loops over every visible light) */
    uint32_t textures[TL_TARGET_COUNT];
    uint32_t framebuffer;                  /**< bound for drawing, with its declared writes attached
                                                as colour attachments in tl_target_id order (and the
                                                depth target, read-only, when it reads depth); the
                                                viewport covers the targets */
} tl_app_pass_context;

/** An application pass's work. GL state on entry is the state tl_renderer_render_to promises on
 *  return, with `framebuffer` bound; the pass may change any state but must not delete the
 *  renderer's objects or write targets it did not declare. */
typedef void (*tl_app_pass_fn)(void *user, const tl_app_pass_context *ctx);

/** An application pass: inserted into every frame at a named point of the pass table. */
typedef struct tl_app_pass_desc {
    const char *name;   /**< unique among the renderer's application passes; 1..31 characters */
    const char *after;  /**< run right after this built-in pass ("lights", ...); or */
    const char *before; /**< right before this one ("tonemap", ...); exactly one of the two. A pass
                             that the plan leaves out still marks the place */
    tl_target_set reads;  /**< targets it samples (TL_TARGET_BIT bits); they live until the pass */
    tl_target_set writes; /**< TL_TARGET_BIT(TL_TARGET_HDR) and/or TL_TARGET_BIT(TL_TARGET_OUTPUT) */
    tl_app_pass_fn execute; /**< required */
    void *user;         /**< passed to execute */
} tl_app_pass_desc;

/** Adds an application pass and re-plans. TL_ERROR_INVALID_ARGUMENT for a missing or duplicate
 *  name, an unknown anchor, reads or writes it may not declare; TL_ERROR_LIMIT beyond
 *  TL_MAX_APP_PASSES. */
TL_API tl_result tl_renderer_add_pass(tl_renderer *r, const tl_app_pass_desc *desc);
/** Removes the application pass `name` and re-plans; TL_ERROR_INVALID_ARGUMENT if there is none. */
TL_API tl_result tl_renderer_remove_pass(tl_renderer *r, const char *name);

/**
 * Runs the renderer's FXAA pass (with its preset and thresholds) on a caller image: RGBA8
 * gamma-encoded, width x height of the renderer, rows bottom to top; luma is computed from RGB.
 * `out` receives the result (alpha 255). *size is the size in bytes of each buffer; a NULL `out`
 * asks for the size needed (written to *size). Useful to anti-alias an image rendered elsewhere.
 */
TL_API tl_result tl_renderer_apply_fxaa(tl_renderer *r, const uint8_t *rgba, uint8_t *out, size_t *size);

/** Reads the final LDR image as RGBA8 (opaque: alpha 255, with or without FXAA), rows bottom to
 *  top (GL order). *size is the buffer's size
 *  in bytes and receives the bytes written; a NULL `rgba` asks for the size needed. Reading before
 *  tl_renderer_render has drawn a frame at the renderer's size (none yet, only render_to, or a
 *  resize since) is TL_ERROR_INVALID_ARGUMENT, saying so. */
TL_API tl_result tl_renderer_read_output(tl_renderer *r, uint8_t *rgba, size_t *size);
/**
 * Reads a target as floats, 4 per pixel, rows bottom to top: DEPTH gives (window depth, linear
 * view distance, 0, 1); RT0 the decoded normal (view space) and gloss; RT1 its raw channels in
 * [0,1]; LIGHT_*, FAT_* and HDR their RGBA; AO_RAW and AO the occlusion in R (1 = open); DOF the
 * blurred colour and, in alpha, the circle of confusion's radius in pixels that the gather used
 * (docs/effects.md); SSR the reflection added to HDR and its weight; BLOOM its first level
 * (tl_plan_target.width x height, not the frame's size): the bloom image before its intensity;
 * SHADOW_DEBUG its four channels (tl_renderer_options.shadow_debug); VIS_ID the object slot, the
 * triangle within the object, 1 and 1 (-1, -1, 0, 1 where nothing was drawn); LDR and OUTPUT their colour in [0,1]. *size is the
 * buffer's size in bytes and receives the bytes written; a NULL `rgba` asks for the size needed.
 * TL_ERROR_INVALID_ARGUMENT for a target the plan did not allocate, or one whose memory a later
 * pass of the frame reused (list it in tl_renderer_options.keep_targets to read it).
 */
TL_API tl_result tl_renderer_read_target(tl_renderer *r, tl_target_id target, float *rgba, size_t *size);
/** One view of the shadow atlas in the last frame rendered (tl_renderer_get_shadow_views). */
typedef struct tl_shadow_view_info {
    uint32_t light;          /**< index of its light in the scene's lights */
    tl_light_type type;      /**< the light's type (point, spot or directional) */
    uint32_t index;          /**< cascade 0..3, cube face 0..5 (+X, -X, +Y, -Y, +Z, -Z), 0 for a spot map */
    uint32_t x;              /**< its tile in atlas texels: left column */
    uint32_t y;              /**< bottom row */
    uint32_t size;           /**< side */
    int perspective;         /**< 1: a perspective map (spot, cube face); 0: an orthographic cascade */
    float near_z;            /**< its depth range along its view's axis (world units): near ... */
    float far_z;             /**< ... and far (tl_renderer_read_shadow_atlas linearises with them) */
    float split;             /**< cascades: the camera view depth where the cascade ends; else 0 */
    int rendered;            /**< 1: rendered in that frame; 0: kept from an earlier one */
} tl_shadow_view_info;

/**
 * The shadow atlas's views of the last frame rendered, in the lookup's order (a light's views
 * together). *count is the capacity of `views` and receives the views written; a NULL `views`
 * asks for the count. `atlas_size` (may be NULL) receives the atlas's side in texels (0: no atlas).
 * TL_ERROR_INVALID_ARGUMENT for NULL `r` or `count`, or a capacity below the count.
 */
TL_API tl_result tl_renderer_get_shadow_views(tl_renderer *r, tl_shadow_view_info *views, size_t *count,
                                              uint32_t *atlas_size);
/**
 * Reads the shadow atlas's stored depth, one float a texel, atlas_size x atlas_size, rows bottom to
 * top: reversed window depth whatever the frame's depth format (near 1, far and empty 0). A texel
 * of a view at distance z along its light's axis holds, with n and f its near_z and far_z,
 * perspective: n (f - z) / (z (f - n)); orthographic: (f - z) / (f - n). *size is the buffer's
 * size in bytes and receives the bytes written; a NULL `depth` asks for the size.
 * TL_ERROR_INVALID_ARGUMENT without an atlas (no casting light rendered yet) or with a buffer too
 * small.
 */
TL_API tl_result tl_renderer_read_shadow_atlas(tl_renderer *r, float *depth, size_t *size);
/** The renderer's target size (0 x 0 for NULL); either pointer may be NULL. */
TL_API void tl_renderer_get_size(const tl_renderer *r, uint32_t *width, uint32_t *height);

#ifdef __cplusplus
}
#endif

/* The option registry (every field above with its name, range, default and help). */
#include "thinlight/options.h"
#endif
