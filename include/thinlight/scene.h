/* thinlight scene: what the renderer draws. A plain CPU-side description (arrays and counts, as
 * cgltf does) that the built-in generator and the glTF loader both fill; the renderer uploads it.
 * Everything a scene owns is freed by tl_scene_destroy. */
#ifndef THINLIGHT_SCENE_H
#define THINLIGHT_SCENE_H

#include "thinlight/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Interleaved vertex: 48 bytes. */
typedef struct tl_vertex {
    float position[3];
    float normal[3];
    float uv[2];
    float tangent[4]; /**< xyz unit tangent along +u, w = +-1 with bitangent = w * cross(normal, xyz)
                           along +v; may be zero when the object has no normal map */
} tl_vertex;

/** An RGBA8 texture; albedo textures hold sRGB-encoded colour. */
typedef struct tl_texture {
    uint32_t width;
    uint32_t height;
    uint8_t *rgba; /**< width * height * 4 bytes, rows top to bottom */
    char name[64];
} tl_texture;

#define TL_NO_TEXTURE UINT32_MAX

/**
 * The renderer's material: Lambert diffuse + normalised Blinn-Phong specular (docs/renderer.md).
 * Textures are indices into the scene's textures or TL_NO_TEXTURE. Colour textures (albedo,
 * emissive) hold sRGB-encoded values; data textures (normal, metallic-roughness, occlusion) linear.
 *
 * With TL_MATERIAL_METALLIC_ROUGHNESS the material is glTF's metallic-roughness model, converted
 * per pixel by the one function of docs/gltf.md: base = albedo * albedo texture,
 * metal = metallic * mr.b, rough = roughness * mr.g; diffuse = base * (1 - metal),
 * specular = mix(0.04, base, metal), gloss = 1 - rough. Without the flag albedo, specular and gloss
 * are used as they are (the loader has already converted constant factors).
 */
typedef struct tl_material {
    float albedo[3];          /**< linear diffuse colour (glTF: base colour), times the texture */
    float specular[3];        /**< linear specular colour (F0); all zero = no specular */
    float gloss;              /**< [0,1], see tl_gloss_to_specular_power */
    float emissive[3];        /**< linear emitted radiance, times the emissive texture */
    float alpha;              /**< opacity for ALPHA_MASK / ALPHA_BLEND, times the albedo texture's alpha */
    float alpha_cutoff;       /**< alpha-test threshold (alpha mode MASK) */
    float metallic;           /**< TL_MATERIAL_METALLIC_ROUGHNESS only */
    float roughness;          /**< TL_MATERIAL_METALLIC_ROUGHNESS only */
    float normal_scale;       /**< scales the normal map's xy (glTF normalTexture.scale); 0 = 1 */
    float occlusion_strength; /**< glTF occlusionTexture.strength, scales the ambient term; 0 = 1 */
    uint32_t albedo_texture;  /**< RGBA: colour, alpha; or TL_NO_TEXTURE */
    uint32_t normal_texture;  /**< tangent-space normal map, or TL_NO_TEXTURE */
    uint32_t metallic_roughness_texture; /**< G roughness, B metallic (glTF), or TL_NO_TEXTURE */
    uint32_t emissive_texture;  /**< or TL_NO_TEXTURE */
    uint32_t occlusion_texture; /**< R ambient occlusion, or TL_NO_TEXTURE */
    uint32_t flags;           /**< TL_MATERIAL_* */
    char name[64];
} tl_material;

#define TL_MATERIAL_DOUBLE_SIDED 1u
#define TL_MATERIAL_ALPHA_MASK 2u
#define TL_MATERIAL_ALPHA_BLEND 4u
#define TL_MATERIAL_METALLIC_ROUGHNESS 8u

/** A drawable object: a range of the scene's index buffer with one material and a world transform. */
typedef struct tl_object {
    uint32_t first_index;
    uint32_t index_count;
    uint32_t material;
    float transform[16];   /**< column-major object-to-world */
    float bounds_min[3];   /**< world-space axis-aligned bounds */
    float bounds_max[3];
} tl_object;

typedef enum tl_light_type {
    TL_LIGHT_DEFAULT = 0, /**< = TL_LIGHT_POINT */
    TL_LIGHT_POINT,
    TL_LIGHT_SPOT,
    TL_LIGHT_DIRECTIONAL,
    TL_LIGHT_TYPE_COUNT_
} tl_light_type;

/**
 * A light with a finite range. Point and spot lights fall off with the windowed inverse square
 *   attenuation(d) = clamp(1 - (d / radius)^4, 0, 1)^2 / max(d^2, (0.01 radius)^2),
 * which reaches exactly zero at d = radius and stays finite at d = 0. The built-in scene leaves
 * the fields a type does not use at zero.
 */
typedef struct tl_light {
    tl_light_type type;
    float position[3];   /**< world space (point, spot) */
    float direction[3];  /**< unit, the direction light travels (spot, directional) */
    float color[3];      /**< linear colour times intensity */
    float radius;        /**< range; > 0 for point and spot */
    float cos_inner;     /**< spot: full intensity inside this cone */
    float cos_outer;     /**< spot: zero outside this cone; cos_outer < cos_inner */
} tl_light;

typedef struct tl_camera {
    float position[3];
    float target[3];
    float up[3];
    float fov_y;  /**< radians */
    float near_z;
    float far_z;  /**< <= 0 or Inf: infinite far plane */
} tl_camera;

typedef struct tl_scene {
    tl_vertex *vertices;
    size_t vertex_count;
    uint32_t *indices;   /**< triangles, 3 per face */
    size_t index_count;
    tl_object *objects;
    size_t object_count;
    tl_material *materials;
    size_t material_count;
    tl_texture *textures;
    size_t texture_count;
    tl_light *lights;
    size_t light_count;
    tl_camera camera;
    float ambient[3];     /**< linear ambient radiance */
    float bounds_min[3];
    float bounds_max[3];
    tl_allocator allocator;
} tl_scene;

/** What a scene uses, for the frame planner (DESIGN.md section 4). Only materials that some
 *  non-empty object draws with count. */
typedef struct tl_scene_feature_set {
    size_t point_lights;
    size_t spot_lights;
    size_t directional_lights;
    int has_specular;     /**< some material has non-zero specular (or is metallic-roughness) */
    int has_textures;     /**< some material samples a texture (UVs needed) */
    int has_normal_maps;  /**< tangents needed */
    int has_emissive;
    int has_alpha_mask;
    int has_alpha_blend;
    int has_metallic_roughness; /**< per-pixel metallic-roughness conversion needed */
    int has_occlusion;    /**< some material has an occlusion texture */
    int has_emissive_texture; /**< some emissive material has an emissive texture */
    int has_double_sided;
    size_t triangle_count;
    size_t object_count;
} tl_scene_feature_set;

/** Fills *out with what `scene` uses; a NULL scene gives all zeros. */
TL_API void tl_scene_features(const tl_scene *scene, tl_scene_feature_set *out);

/** Parameters of the built-in scene; zero means the default. */
typedef struct tl_default_scene_desc {
    uint32_t point_lights;   /**< default 64; at most 65536 */
    uint32_t spot_lights;    /**< default point_lights / 8 (none below 8 point lights); at most 65536 */
    int no_directional;      /**< 1 to leave out the directional light (moonlight through the roof) */
    uint64_t seed;           /**< default 1; same seed, same scene (the seed moves only the lights) */
    uint32_t detail;         /**< tessellation level 1..8, default 4 (about 206k triangles; 1: 23k,
                                  8: 730k); the layout and object count do not change */
    tl_allocator allocator;  /**< zeroed: malloc/free; used for every allocation of the scene */
} tl_default_scene_desc;

/** Builds the built-in crypt scene (a vaulted hall crypt, metres, Y up; exposure 1 with an ACES or
 * Reinhard tone map). NULL desc means all defaults. TL_ERROR_INVALID_ARGUMENT for a NULL out,
 * detail > 8 or an allocator with only one of alloc/free; TL_ERROR_LIMIT for more than 65536
 * point or spot lights; TL_ERROR_OUT_OF_MEMORY (nothing leaked). *out is NULL on failure. */
TL_API tl_result tl_scene_create_default(const tl_default_scene_desc *desc, tl_scene **out);
/** Frees a scene from any tl_scene_* constructor; NULL is ignored. */
TL_API void tl_scene_destroy(tl_scene *scene);

#ifdef __cplusplus
}
#endif
#endif
