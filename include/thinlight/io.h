/* thinlight io: glTF 2.0 scenes through tinygltf and image files through OpenImageIO (C++ kept
 * inside src/io behind this C API). Image writers go through a temporary file in the same
 * directory and rename it into place, so a failure never leaves a partial file behind. */
#ifndef THINLIGHT_IO_H
#define THINLIGHT_IO_H

#include "thinlight/base.h"
#include "thinlight/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Component type of pixels in memory. */
typedef enum tl_pixel_type {
    TL_PIXEL_DEFAULT = 0, /**< = TL_PIXEL_U8 */
    TL_PIXEL_U8,          /**< 8-bit unsigned, 0..255 */
    TL_PIXEL_F32,         /**< 32-bit float */
    TL_PIXEL_TYPE_COUNT_
} tl_pixel_type;

/** Layout of the pixels given to tl_image_write. */
typedef struct tl_image_desc {
    uint32_t width;         /**< pixels, 1..65536 */
    uint32_t height;        /**< pixels, 1..65536 */
    uint32_t channels;      /**< 1..4 */
    tl_pixel_type type;     /**< component type in memory */
    int bottom_up;          /**< 1 when the first row in memory is the bottom one (GL readback) */
} tl_image_desc;

/**
 * Writes an image; the file type follows the extension (.png, .exr, .tif, .jpg, ... as OIIO
 * supports). Float data written to an 8-bit format is clamped to [0,1] and rounded. On failure a
 * message naming the file and the reason is written to `error` (may be NULL).
 */
TL_API tl_result tl_image_write(const char *path, const tl_image_desc *desc, const void *pixels, char *error,
                                size_t error_size);

/**
 * Reads an image as RGBA8 (sRGB-encoded as stored). *rgba is allocated with malloc and freed with
 * tl_image_free. Images larger than max_pixels (0: 2^26) give TL_ERROR_LIMIT.
 */
TL_API tl_result tl_image_read_rgba8(const char *path, size_t max_pixels, uint32_t *width, uint32_t *height,
                                     uint8_t **rgba, char *error, size_t error_size);
TL_API void tl_image_free(void *pixels);

/* ---- glTF 2.0 scenes (docs/gltf.md) ---------------------------------------------------------- */

/** How normals are made for primitives without a NORMAL attribute. */
typedef enum tl_gltf_normals {
    TL_GLTF_NORMALS_DEFAULT = 0, /**< = TL_GLTF_NORMALS_FLAT, what the glTF specification asks for */
    TL_GLTF_NORMALS_FLAT,        /**< one face normal per triangle (vertices are unshared) */
    TL_GLTF_NORMALS_SMOOTH,      /**< area-weighted average of the faces around each vertex */
    TL_GLTF_NORMALS_COUNT_
} tl_gltf_normals;

/** Options of tl_scene_load_gltf; a zeroed field means the default beside it. */
typedef struct tl_gltf_options {
    tl_allocator allocator;    /**< zeroed: malloc/free; every allocation of the scene and of the
                                    loader's own temporary buffers (tinygltf's model excepted) */
    tl_logger logger;          /**< errors and warnings, one line each: "FILE: element: message" */
    uint32_t scene_number;     /**< 0: the file's "scene", else scenes[0]; N: scenes[N - 1] */
    uint32_t extra_lights;     /**< seeded point lights added inside the scene bounds; at most 65536 */
    uint64_t seed;             /**< for extra_lights; 0 = 1; same seed, same lights */
    int no_default_lights;     /**< 1: a file without lights gets no default rig */
    tl_gltf_normals normals;   /**< generated normals; default flat */
    size_t max_texture_pixels; /**< per image; 0 = 2^26; a larger image is TL_ERROR_LIMIT */
    size_t max_triangles;      /**< triangles drawn (instances count each time); 0 = 2^26; the
                                    scene's vertices may be at most 3 times this */
    char *error;               /**< optional: receives the error line on failure (file: element: ...) */
    size_t error_size;         /**< bytes at `error`, including the terminating NUL */
} tl_gltf_options;

/**
 * Loads a glTF 2.0 file (.gltf with external or data-URI buffers and images, or .glb; the
 * content decides, not the extension) into a scene freed by tl_scene_destroy. NULL options means
 * all defaults. Materials follow the one conversion of docs/gltf.md (diffuse = base * (1 - metal),
 * specular F0 = mix(0.04, base, metal), gloss = 1 - roughness; done here for constant factors,
 * per pixel by the renderer with a metallic-roughness texture, see tl_material). A file without
 * lights gets a default rig, one without a camera a camera framing its bounds, one without
 * triangles loads as an empty scene (with a warning). Missing or undecodable images become
 * warnings and flat colours. Returns
 * TL_ERROR_INVALID_ARGUMENT (NULL path or out, bad options, a scene number past the file's),
 * TL_ERROR_IO (the file or a buffer cannot be read), TL_ERROR_PARSE (malformed JSON, GLB or
 * references), TL_ERROR_UNSUPPORTED (a required extension, sparse accessors),
 * TL_ERROR_LIMIT (texture pixels, triangles, extra lights) or TL_ERROR_OUT_OF_MEMORY; nothing is
 * leaked and *out is NULL on failure.
 */
TL_API tl_result tl_scene_load_gltf(const char *path, const tl_gltf_options *options, tl_scene **out);

#ifdef __cplusplus
}
#endif
#endif
