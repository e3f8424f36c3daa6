/**
 * @file thinlight/scene.h
 * @brief What the renderer draws: a plain CPU-side description (arrays and counts, as cgltf
 * does) that the built-in generator and the glTF loader both fill; the renderer uploads it.
 * Everything a scene owns is freed by tl_scene_destroy().
 */
#ifndef THINLIGHT_SCENE_H
#define THINLIGHT_SCENE_H

#include "thinlight/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Interleaved vertex: 48 bytes. */
typedef struct tl_vertex {
    float position[3]; /**< object space */
    float normal[3];   /**< object space, unit */
    float uv[2];       /**< texture coordinates, (0,0) at the image's top-left (glTF) */
    float tangent[4]; /**< xyz unit tangent along +u, w = +-1 with bitangent = w * cross(normal, xyz)
                           along +v; may be zero when the object has no normal map */
} tl_vertex;

/** An RGBA8 texture; albedo textures hold sRGB-encoded colour. tl_renderer_set_scene refuses a
 *  texture outside these ranges, naming it (docs/renderer-limits.md). */
typedef struct tl_texture {
    uint32_t width;  /**< pixels, 1..GL_MAX_TEXTURE_SIZE (16384 or more; the glTF loader keeps to 16384) */
    uint32_t height; /**< pixels, 1..GL_MAX_TEXTURE_SIZE */
    uint8_t *rgba; /**< width * height * 4 bytes, rows top to bottom; not NULL */
    char name[64];   /**< for debug labels and messages, NUL-terminated */
} tl_texture;

/** A material's reference to texture `index` of tl_scene.textures: the index + 1, so that 0, the
 *  zeroed field, means "no texture" (`.albedo_map = TL_TEXTURE_MAP(0)` is texture 0). */
#define TL_TEXTURE_MAP(index) ((uint32_t)(index) + 1u)

/** The albedo of a material with no colour at all (tl_material): plain grey, linear. */
#define TL_MATERIAL_DEFAULT_ALBEDO 0.8f

/**
 * The renderer's material: Lambert diffuse + normalised Blinn-Phong specular (docs/renderer.md).
 * Every field's zero is its default, so a zeroed tl_material is plain grey: albedo
 * TL_MATERIAL_DEFAULT_ALBEDO, no specular, no emission, opaque, no texture.
 *
 * Textures are maps: a texture's index in the scene's textures + 1 (TL_TEXTURE_MAP), 0 for none; a
 * map past texture_count is refused by tl_renderer_set_scene, naming the field. Colour textures
 * (albedo, emissive) hold sRGB-encoded values; data textures (normal, metallic-roughness,
 * occlusion) linear.
 *
 * With TL_MATERIAL_METALLIC_ROUGHNESS the material is glTF's metallic-roughness model, converted
 * per pixel by the one function of docs/gltf.md: base = albedo * albedo texture,
 * metal = metallic * mr.b, rough = roughness * mr.g; diffuse = base * (1 - metal),
 * specular = mix(0.04, base, metal), gloss = 1 - rough. Without the flag albedo, specular and gloss
 * are used as they are (the loader has already converted constant factors).
 */
typedef struct tl_material {
    /** Linear diffuse colour (glTF: base colour), times the albedo map. All three zero with
     *  specular and emissive zero too (a material with no colour at all, as a zeroed one):
     *  TL_MATERIAL_DEFAULT_ALBEDO. A negative component means exactly 0: `.albedo = {-1, -1, -1}`
     *  is a black material that reflects and emits nothing. */
    float albedo[3];
    float specular[3];        /**< linear specular colour (F0); all zero = no specular */
    float gloss;              /**< [0,1], see tl_gloss_to_specular_power */
    float emissive[3];        /**< linear emitted radiance, times the emissive map; zero: none */
    /** Opacity, times the albedo map's alpha; read only with TL_MATERIAL_ALPHA_MASK or
     *  TL_MATERIAL_ALPHA_BLEND (without them, the default, the material is opaque). */
    float alpha;
    float alpha_cutoff;       /**< alpha-test threshold (alpha mode MASK) */
    float metallic;           /**< TL_MATERIAL_METALLIC_ROUGHNESS only */
    float roughness;          /**< TL_MATERIAL_METALLIC_ROUGHNESS only */
    float normal_scale;       /**< scales the normal map's xy (glTF normalTexture.scale); 0 = 1 */
    float occlusion_strength; /**< glTF occlusionTexture.strength, scales the ambient term; 0 = 1 */
    uint32_t albedo_map;      /**< RGBA: colour, alpha; TL_TEXTURE_MAP(index), 0 = none */
    uint32_t normal_map;      /**< tangent-space normal map (the plan adds tangents); 0 = none */
    uint32_t metallic_roughness_map; /**< G roughness, B metallic (glTF); 0 = none */
    uint32_t emissive_map;    /**< times emissive; 0 = none */
    uint32_t occlusion_map;   /**< R ambient occlusion; 0 = none */
    uint32_t flags;           /**< TL_MATERIAL_*; 0: single-sided, opaque, Blinn-Phong */
    char name[64];            /**< for messages, NUL-terminated; may be empty */
    /** TL_MAP_* bits: the maps sampled with the second texture coordinate set (tl_scene.uv1,
     *  glTF textureInfo.texCoord = 1); 0: every map reads tl_vertex.uv. In a scene without uv1
     *  such a map reads tl_vertex.uv. */
    uint32_t uv1_maps;
    /** tl_material_model: how the material pass shades it (docs/lighting.md, "Material models");
     *  0: the standard model. The fields below are read only by the model they name. */
    uint32_t model;
    /** TL_MATERIAL_METALLIC_ROUGHNESS: the dielectric F0 that `specular = mix(F0, base, metal)`
     *  starts from (glTF KHR_materials_ior and _specular); all zero = 0.04 (ior 1.5), a negative
     *  component means exactly 0. */
    float dielectric_f0[3];
    float clearcoat;           /**< TL_MATERIAL_MODEL_CLEARCOAT: the coat's weight (0,1]; 0 = 1 */
    float clearcoat_roughness; /**< TL_MATERIAL_MODEL_CLEARCOAT: the coat's perceptual roughness; 0 = the smoothest lobe */
    float sheen_color[3];      /**< TL_MATERIAL_MODEL_SHEEN: linear sheen colour; all zero = white */
    float sheen_roughness;     /**< TL_MATERIAL_MODEL_SHEEN: [0,1], floored at 0.07; 0 = 0.5 */
    float wrap;                /**< TL_MATERIAL_MODEL_WRAP: how far light wraps past the terminator (0,1]; 0 = 0.5 */
    uint32_t toon_steps;       /**< TL_MATERIAL_MODEL_TOON: bands of the diffuse ramp, 1..64; 0 = 3 */
} tl_material;

/** Per-material shading models (tl_material.model; docs/lighting.md, "Material models"). */
typedef enum tl_material_model {
    TL_MATERIAL_MODEL_STANDARD = 0, /**< Lambert + the frame's specular (today's model) */
    TL_MATERIAL_MODEL_UNLIT,        /**< albedo + emissive, no light (KHR_materials_unlit) */
    TL_MATERIAL_MODEL_CLEARCOAT,    /**< standard under a GGX coat of F0 0.04 (KHR_materials_clearcoat) */
    TL_MATERIAL_MODEL_SHEEN,        /**< standard plus a Charlie sheen lobe (KHR_materials_sheen, cloth) */
    TL_MATERIAL_MODEL_WRAP,         /**< wrapped diffuse (thin translucent, skin-like) */
    TL_MATERIAL_MODEL_TOON,         /**< a banded ramp on the light sums */
    TL_MATERIAL_MODEL_COUNT_        /**< number of values */
} tl_material_model;
/** The model's name ("standard", "unlit", "clearcoat", "sheen", "wrap", "toon"); "unknown" past them. */
TL_API const char *tl_material_model_name(uint32_t model);

/** Bits of tl_material.uv1_maps, one per texture map. */
#define TL_MAP_ALBEDO 1u
#define TL_MAP_NORMAL 2u             /**< see TL_MAP_ALBEDO */
#define TL_MAP_METALLIC_ROUGHNESS 4u /**< see TL_MAP_ALBEDO */
#define TL_MAP_EMISSIVE 8u           /**< see TL_MAP_ALBEDO */
#define TL_MAP_OCCLUSION 16u         /**< see TL_MAP_ALBEDO */

/** Material flag: no back-face culling; back faces are shaded with the flipped normal. */
#define TL_MATERIAL_DOUBLE_SIDED 1u
/** Material flag: alpha test against alpha_cutoff (opaque passes discard below it). */
#define TL_MATERIAL_ALPHA_MASK 2u
/** Material flag: alpha-blended, drawn forward-lit after the opaque frame, far to near. */
#define TL_MATERIAL_ALPHA_BLEND 4u
/** Material flag: glTF metallic-roughness, converted per pixel (see tl_material). */
#define TL_MATERIAL_METALLIC_ROUGHNESS 8u
/** Material flag: authored for the GGX microfacet model (every glTF material): with
 *  TL_LIGHTING_DEFAULT a scene that draws one is lit with GGX. */
#define TL_MATERIAL_MICROFACET 16u

/** What an object's indices draw (tl_object.primitive). Points and lines have no surface for a
 *  G-buffer: every mode draws them forward after the opaque frame, 1 pixel wide (GL core has no
 *  wider lines), lit with their normal, or facing the viewer where their normal is zero
 *  (docs/gltf.md, "Points and lines"). */
typedef enum tl_primitive {
    TL_PRIMITIVE_TRIANGLES = 0, /**< 3 indices a triangle (the default) */
    TL_PRIMITIVE_LINES,         /**< 2 indices a line segment */
    TL_PRIMITIVE_POINTS,        /**< 1 index a point */
    TL_PRIMITIVE_COUNT_         /**< number of values */
} tl_primitive;

/** A drawable object: a range of the scene's index buffer with one material and a world transform. */
typedef struct tl_object {
    uint32_t first_index;  /**< first index in tl_scene.indices */
    /** A multiple of 3 for triangles, of 2 for lines (`primitive`); 0: an empty object, never drawn */
    uint32_t index_count;
    /** Index into tl_scene.materials; in a scene with no materials, 0 is the zeroed (plain grey)
     *  material. */
    uint32_t material;
    float transform[16];   /**< column-major object-to-world; all zero = the identity */
    /** World-space axis-aligned bounds (culling, light lists), or all six zero: the renderer
     *  computes them from the object's vertices at tl_renderer_set_scene, as
     *  tl_object_compute_bounds does (one pass over its indices). Otherwise finite with
     *  bounds_min <= bounds_max on every axis, else refused, naming the field; bounds that do not
     *  contain the object let culling drop it where it is visible. */
    float bounds_min[3];
    float bounds_max[3];   /**< see bounds_min */
    uint32_t primitive;    /**< tl_primitive; 0: triangles */
} tl_object;

/** Kinds of light; each is drawn as its own instanced light volume. */
typedef enum tl_light_type {
    TL_LIGHT_DEFAULT = 0, /**< = TL_LIGHT_POINT */
    TL_LIGHT_POINT,       /**< sphere of influence of `radius` */
    TL_LIGHT_SPOT,        /**< cone of length `radius` between cos_inner and cos_outer */
    TL_LIGHT_DIRECTIONAL, /**< no position, no range: a full-screen pass */
    TL_LIGHT_TYPE_COUNT_  /**< number of values */
} tl_light_type;

/**
 * A light with a finite range. Point and spot lights fall off with the windowed inverse square
 *   attenuation(d) = clamp(1 - (d / radius)^4, 0, 1)^2 / max(d^2, (0.01 radius)^2),
 * which reaches exactly zero at d = radius and stays finite at d = 0. The built-in scene leaves
 * the fields a type does not use at zero. Every field must be finite; a light outside the ranges
 * below is refused by tl_renderer_set_lights and set_scene, naming the field.
 */
typedef struct tl_light {
    tl_light_type type;  /**< point, spot or directional */
    float position[3];   /**< world space (point, spot) */
    float direction[3];  /**< the direction light travels (spot, directional): not zero; made unit */
    float color[3];      /**< linear colour times intensity; the renderer takes a negative component as 0 and
                              saturates what a pixel receives at 65504 (FP16), docs/renderer-limits.md */
    float radius;        /**< range; > 0 for point and spot (0 is refused: it would reach nothing) */
    /** Spot: the cosine of the half angle inside which the light is at full intensity, -1..1 and
     *  above cos_outer (cosines, not angles: `cosf(0.3f)`; else refused, naming the field). */
    float cos_inner;
    /** Spot: the cosine of the half angle outside which it is zero (a smoothstep between the two):
     *  0..1, below cos_inner. 0 is a 90-degree cone, the widest (glTF's outerConeAngle <= pi/2;
     *  cosf of pi/2's float, -4.4e-8, counts as 0); a wider one is refused. */
    float cos_outer;
    /** Point and spot lights: the radius of the emitting sphere (GGX lighting only: the sphere's
     *  irradiance for diffuse, Karis' representative point for specular; docs/lighting.md).
     *  0 (the default): a punctual light; >= 0. The window and the cone are measured from the
     *  centre, so `radius` still bounds everything the light reaches. */
    float source_radius;
    /** Non-zero: the light casts shadows through the shadow atlas (docs/shadows.md); 0 (the
     *  default): it does not, and a scene with no casting light plans and renders as before. */
    int shadow;
    /** The light's specular (highlight) against its diffuse light, in every mode and strategy: 0
     *  (the default) means 1; a value above 0 scales the highlight (0.5 halves it, 2 doubles it);
     *  TL_LIGHT_SPECULAR_NONE lights without a highlight. Finite; another negative value is
     *  refused, naming the field. */
    float specular;
} tl_light;

/** tl_light.specular: a light with no specular term (diffuse only). */
#define TL_LIGHT_SPECULAR_NONE (-1.0f)

/** A perspective camera looking from position at target. The renderer refuses, naming the field,
 *  a camera it cannot draw (tl_renderer_render, and set_scene for the scene's); the table of
 *  what is refused and what falls back is in docs/renderer-limits.md. Every field is finite.
 *  A zeroed camera is the default view: position and target both zero frame the scene's objects
 *  (from the front, right and above, the glTF loader's default camera; at the origin looking
 *  down -Z in a scene that draws nothing), and the other fields keep their own defaults. */
typedef struct tl_camera {
    float position[3]; /**< world space eye */
    /** A world-space point the camera looks at; not the position, unless both are zero (the
     *  default view above). */
    float target[3];
    /** World-space up; zero = +Y. Parallel to the view (looking straight down or up) the view is
     *  the limit of views whose target moves towards -Z (+Y when up lies along Z). */
    float up[3];
    float fov_y;  /**< vertical field of view in radians, in (0, pi); 0 = 60 degrees */
    /** Near plane distance, > 0; 0 = 0.1 (the default view: half the distance to the sphere
     *  around the scene's objects). One so small that the depth format holds nothing of the
     *  scene (below 2^-24 of the distance to its farthest point with D24) is raised to 2^-16 of
     *  that distance, with one warning. */
    float near_z;
    float far_z;  /**< beyond near_z; 0 or +Inf: an infinite far plane */
} tl_camera;

/** A scene: every array is owned by the scene and freed by tl_scene_destroy() with `allocator`
 *  (a scene the application builds itself it frees itself). A zeroed scene is an empty one. */
typedef struct tl_scene {
    tl_vertex *vertices;      /**< vertex_count vertices */
    size_t vertex_count;      /**< at most 2^32 - 1 */
    uint32_t *indices;        /**< the objects' triangles, lines and points (tl_object.primitive) */
    size_t index_count;       /**< number of indices */
    tl_object *objects;       /**< object_count objects */
    size_t object_count;      /**< number of objects */
    tl_material *materials;   /**< material_count materials */
    size_t material_count;    /**< number of materials */
    tl_texture *textures;     /**< texture_count textures */
    size_t texture_count;     /**< number of textures */
    tl_light *lights;         /**< light_count lights */
    size_t light_count;       /**< number of lights */
    tl_camera camera;         /**< the view of tl_renderer_render with a NULL camera; zeroed: the default view */
    float ambient[3];         /**< linear ambient radiance; zero: none */
    /** World-space bounds of all objects, for the application (the renderer uses the objects'):
     *  filled by the built-in scene, the glTF loader and tl_scene_compute_bounds. */
    float bounds_min[3];
    float bounds_max[3];      /**< see bounds_min */
    tl_allocator allocator;   /**< what allocated the arrays; zeroed: malloc/free */
    /** Per-vertex colours (glTF COLOR_0): vertex_count linear RGBA quadruples that multiply the
     *  material's base colour and alpha (the albedo and alpha in every mode; the constant specular
     *  of a material without a metallic-roughness map is not tinted, as with an albedo map);
     *  NULL: white. */
    float *colors;
    /** The second texture coordinate set (glTF TEXCOORD_1): vertex_count pairs, read by the maps
     *  named in tl_material.uv1_maps; NULL: none. */
    float *uv1;
} tl_scene;

/** What a scene uses, for the frame planner (docs/frame.md, "The frame planner"). Only materials that some
 *  non-empty object draws with count. */
typedef struct tl_scene_feature_set {
    size_t point_lights;       /**< number of point lights */
    size_t spot_lights;        /**< number of spot lights */
    size_t directional_lights; /**< number of directional lights */
    int has_specular;     /**< some material has non-zero specular (or is metallic-roughness) */
    int has_textures;     /**< some material samples a texture (UVs needed) */
    int has_normal_maps;  /**< tangents needed */
    int has_emissive;     /**< some material emits light */
    int has_alpha_mask;   /**< alpha-tested materials */
    int has_alpha_blend;  /**< alpha-blended materials (a transparent pass) */
    /** Non-empty objects drawn with an alpha-blended material: the stipple has a layer for each of up
     *  to TL_STIPPLE_LAYERS. 0 with has_alpha_blend (a feature set made by hand): not counted, planned forward. */
    size_t alpha_blend_objects;
    int has_metallic_roughness; /**< per-pixel metallic-roughness conversion needed */
    int has_occlusion;    /**< some material has an occlusion texture */
    int has_emissive_texture; /**< some emissive material has an emissive texture */
    int has_double_sided; /**< some material is double-sided */
    int has_microfacet;   /**< some material is authored for GGX (TL_MATERIAL_MICROFACET or metallic-roughness) */
    size_t triangle_count; /**< triangles in the index buffer */
    size_t object_count;   /**< objects in the scene */
    int has_points_lines;  /**< some non-empty object draws points or lines (the points-lines pass) */
    int has_vertex_colors; /**< the scene has colors and some non-empty object (the colour attribute) */
    int has_uv1;           /**< the scene has uv1 and a drawn material samples a map with it */
    size_t shadow_lights;  /**< lights with tl_light.shadow set (the shadow pass and lookups) */
    /** An environment lights the frame (tl_renderer_set_environment; the renderer sets this, the
     *  scene never does): image-based light in the shading passes, the sky pass. */
    int has_environment;
    /** Bits 1u << tl_material_model of the drawn materials' models; 0 (a feature set made by hand)
     *  is the standard model only. */
    uint32_t material_models;
} tl_scene_feature_set;

/** Fills *out with what `scene` uses; a NULL scene gives all zeros. */
TL_API void tl_scene_features(const tl_scene *scene, tl_scene_feature_set *out);

/**
 * The world-space axis-aligned bounds of `object`'s triangles in `scene`: its vertices, as its
 * indices name them, through its transform (all zero: the identity), in double precision rounded
 * to float. An object with no indices gets zero bounds. TL_ERROR_INVALID_ARGUMENT for NULL
 * pointers, an index range outside scene->indices, an index past scene->vertex_count or a
 * position that is not finite; the bounds are then left as they were.
 */
TL_API tl_result tl_object_compute_bounds(const tl_scene *scene, const tl_object *object, float bounds_min[3],
                                          float bounds_max[3]);
/**
 * Computes every object's bounds (tl_object_compute_bounds) and the scene's (their union over the
 * objects that have indices; zero when none has). Call it after building a scene or moving its
 * objects; tl_renderer_set_scene computes bounds left zero itself, in its own copy. Errors as
 * tl_object_compute_bounds, for the first object that has one; the scene is then unchanged.
 */
TL_API tl_result tl_scene_compute_bounds(tl_scene *scene);

/** Parameters of the built-in scene; zero means the default. */
typedef struct tl_default_scene_desc {
    uint32_t point_lights;   /**< default 64; at most 65536 */
    uint32_t spot_lights;    /**< default point_lights / 8 (none below 8 point lights); at most 65536 */
    int no_directional;      /**< 1 to leave out the directional light (moonlight through the roof) */
    uint64_t seed;           /**< default 1; same seed, same scene (the seed moves only the lights) */
    uint32_t detail;         /**< tessellation level 1..8, default 4 (about 206k triangles; 1: 23k,
                                  8: 730k); the layout and object count do not change */
    /** Alpha-blended glass panes across the nave between the camera and the altar (0..8, default
     *  0: none), each its own object, overlapping on screen; the lights do not move
     *  (transparency: docs/frame.md, "2d. Transparency through the light buffer"). */
    uint32_t glass_panes;
    tl_allocator allocator;  /**< zeroed: malloc/free; used for every allocation of the scene */
    /** 1: the moonlight and the braziers (the point lights above the braziers, one in eight of
     *  them at most) cast shadows (tl_light.shadow); default 0: no light casts. */
    int shadows;
    tl_logger logger;        /**< a failure's one line, naming the field and its value; zeroed: silent */
} tl_default_scene_desc;

/** Builds the built-in crypt scene (a vaulted hall crypt, metres, Y up; exposure 1 with an ACES or
 * Reinhard tone map). NULL desc means all defaults. TL_ERROR_INVALID_ARGUMENT for a NULL out,
 * detail > 8, glass_panes > 8 or an allocator with only one of alloc/free; TL_ERROR_LIMIT for more than 65536
 * point or spot lights; TL_ERROR_OUT_OF_MEMORY (nothing leaked). *out is NULL on failure, and one
 * line naming the field and its value goes to desc->logger. */
TL_API tl_result tl_scene_create_default(const tl_default_scene_desc *desc, tl_scene **out);
/** Frees a scene from any tl_scene_* constructor; NULL is ignored. */
TL_API void tl_scene_destroy(tl_scene *scene);

/** Parameters of the material-model showcase; zero means the default. */
typedef struct tl_showcase_scene_desc {
    uint32_t point_lights;  /**< default 8; at most 65536; their total light is the same at any count */
    uint64_t seed;          /**< default 1; moves only the lights */
    tl_allocator allocator; /**< zeroed: malloc/free */
    tl_logger logger;       /**< a failure's one line, naming the field and its value; zeroed: silent */
} tl_showcase_scene_desc;

/** Builds the material-model showcase (docs/lighting.md, "Material models"): a row of five spheres
 *  per tl_material_model (standard nearest the camera, then unlit, clearcoat, sheen, wrap, toon),
 *  perceptual roughness 0.1 to 0.9 from left to right, on a grey floor under seeded point lights.
 *  NULL desc means all defaults. Errors as tl_scene_create_default. *out is NULL on failure. */
TL_API tl_result tl_scene_create_showcase(const tl_showcase_scene_desc *desc, tl_scene **out);

#ifdef __cplusplus
}
#endif
#endif
