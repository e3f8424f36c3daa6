/* thinlight io: glTF 2.0 scenes through tinygltf and image files through OpenImageIO (C++ kept
 * inside src/io behind this C API). Errors are a tl_result plus one line to the logger in the
 * options; images are encoded in memory and written by tl_file_write (thinlight/file.h), so an
 * output is whole or absent. */
#ifndef THINLIGHT_IO_H
#define THINLIGHT_IO_H

#include "thinlight/base.h"
#include "thinlight/file.h"
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

/** Layout of the pixels given to tl_image_write, and where its error goes. */
typedef struct tl_image_desc {
    uint32_t width;         /**< pixels, 1..65536 */
    uint32_t height;        /**< pixels, 1..65536 */
    uint32_t channels;      /**< 1..4 */
    tl_pixel_type type;     /**< component type in memory */
    int bottom_up;          /**< 1 when the first row in memory is the bottom one (GL readback) */
    tl_logger logger;       /**< receives the error line on failure ("PATH: reason"); zeroed: silent */
    /** EXR only, with TL_PIXEL_F32 data: 1 stores 32-bit floats (depth, positions, decoded
     *  normals: what half floats would round); 0 (default) stores half floats. */
    int full_float;
} tl_image_desc;

/**
 * Writes an image; the file type follows the extension (.png, .exr, .jpg, .tif, ... as OIIO
 * supports). Float data written to an 8-bit format is clamped to [0,1] and rounded; alpha is
 * stored as given (straight, never divided out of or into the colour). OIIO encodes the image
 * in memory and tl_file_write writes the bytes (thinlight/file.h): `path` holds either its old
 * content or the whole new image, never part of one, even on a full disk or when the process is
 * killed, and only an absent path or a regular file is replaced (a FIFO, a device, a directory
 * or a symbolic link is refused; `-` is no file extension). Returns TL_OK,
 * TL_ERROR_INVALID_ARGUMENT (NULL arguments, a layout out of range, no extension),
 * TL_ERROR_UNSUPPORTED (no OIIO writer for the extension, one that cannot encode into memory, or
 * a JPEG over 65500 pixels a side, which libjpeg would end the process for), TL_ERROR_IO (the
 * encoder or the file failed) or TL_ERROR_OUT_OF_MEMORY. On failure one line naming the file
 * and the reason goes to desc->logger.
 */
TL_API tl_result tl_image_write(const char *path, const tl_image_desc *desc, const void *pixels);

/** Options of tl_image_read_rgba8 and tl_image_decode_rgba8; a zeroed field means the default
 *  beside it, and NULL options mean all defaults. */
typedef struct tl_image_read_desc {
    tl_allocator allocator; /**< zeroed: malloc/free; the pixels and every temporary buffer */
    tl_logger logger;       /**< receives the error line on failure ("NAME: reason"); zeroed: silent */
    size_t max_pixels;      /**< 0 = 2^26; a larger image is TL_ERROR_LIMIT, found from the header
                                 before any pixel is decoded; at most 65536 per side in any case */
    const char *name;       /**< tl_image_decode_rgba8: how the message names the data; NULL = "image" */
} tl_image_read_desc;

/** RGBA8 pixels from tl_image_read_rgba8 or tl_image_decode_rgba8, freed by tl_rgba8_image_free. */
typedef struct tl_rgba8_image {
    uint32_t width;         /**< pixels */
    uint32_t height;        /**< pixels */
    uint8_t *rgba;          /**< width * height * 4 bytes, rows top to bottom, straight alpha */
    tl_allocator allocator; /**< what allocated `rgba` */
} tl_rgba8_image;

/**
 * Decodes a PNG or JPEG image held in memory (recognised by its signature) to RGBA8, as stored
 * (sRGB-encoded colour stays encoded); grey, grey-alpha and RGB are widened, 16-bit PNG is
 * rounded to 8 bits. Returns TL_ERROR_INVALID_ARGUMENT (NULL data or out, an allocator with one
 * function), TL_ERROR_UNSUPPORTED (not PNG or JPEG), TL_ERROR_PARSE (truncated or corrupt data,
 * or a header that promises more pixels than the data can hold), TL_ERROR_LIMIT (max_pixels) or
 * TL_ERROR_OUT_OF_MEMORY; on failure *out is zeroed.
 */
TL_API tl_result tl_image_decode_rgba8(const void *data, size_t size, const tl_image_read_desc *desc,
                                       tl_rgba8_image *out);
/**
 * Reads a PNG or JPEG file as tl_image_decode_rgba8 decodes it. Only a regular file is opened (a
 * directory, FIFO or device is TL_ERROR_IO at once, never a wait); a file larger than 1 GiB is
 * TL_ERROR_LIMIT. Results as tl_image_decode_rgba8, plus TL_ERROR_IO when it cannot be read.
 */
TL_API tl_result tl_image_read_rgba8(const char *path, const tl_image_read_desc *desc, tl_rgba8_image *out);
/** Frees the pixels with the allocator that made them and zeroes *image; NULL is ignored. */
TL_API void tl_rgba8_image_free(tl_rgba8_image *image);

/** Linear RGB float pixels from tl_image_read_rgb_float, freed by tl_float_image_free. */
typedef struct tl_float_image {
    uint32_t width;         /**< pixels */
    uint32_t height;        /**< pixels */
    float *rgb;             /**< width * height * 3 floats, rows top to bottom */
    tl_allocator allocator; /**< what allocated `rgb` */
} tl_float_image;

/**
 * Reads a high-dynamic-range image file (Radiance .hdr, OpenEXR .exr, or another format
 * OpenImageIO reads) as linear RGB floats, e.g. an environment for tl_renderer_set_environment:
 * the first three channels (grey is widened), values as stored. Only a regular file is opened.
 * Returns TL_ERROR_INVALID_ARGUMENT (NULL path or out), TL_ERROR_IO (missing, unreadable, not a
 * regular file), TL_ERROR_PARSE (not an image OIIO reads, truncated or corrupt), TL_ERROR_LIMIT
 * (desc.max_pixels, 65536 per side) or TL_ERROR_OUT_OF_MEMORY, with one line to desc.logger
 * naming the file; on failure *out is zeroed.
 */
TL_API tl_result tl_image_read_rgb_float(const char *path, const tl_image_read_desc *desc, tl_float_image *out);
/** Frees the pixels with the allocator that made them and zeroes *image; NULL is ignored. */
TL_API void tl_float_image_free(tl_float_image *image);

/* ---- glTF 2.0 scenes (docs/gltf.md) ---------------------------------------------------------- */

/** How normals are made for primitives without a NORMAL attribute. */
typedef enum tl_gltf_normals {
    TL_GLTF_NORMALS_DEFAULT = 0, /**< = TL_GLTF_NORMALS_FLAT, what the glTF specification asks for */
    TL_GLTF_NORMALS_FLAT,        /**< one face normal per triangle (vertices are unshared) */
    TL_GLTF_NORMALS_SMOOTH,      /**< area-weighted average of the faces around each vertex */
    TL_GLTF_NORMALS_COUNT_
} tl_gltf_normals;

/**
 * How a load reads the external files that buffers and images name (as cgltf_file_options):
 * the application's own file system, an archive, a network cache. A zeroed struct means the
 * default: tl_scene_load_gltf reads regular files in the glTF file's folder and below, nothing
 * else; tl_scene_parse_gltf reads no external file at all.
 */
typedef struct tl_gltf_files {
    /**
     * Reads the file `uri` names: the URI as the glTF file writes it, percent-decoded (never a
     * data: URI; it may be anything else, "../x.bin" or "http://..." included: whether to read
     * it is this function's choice). On success sets *data and *size and returns TL_OK; the
     * bytes stay valid and unchanged until `release`. A file larger than `max_size` (what the
     * load's memory budget still allows) must not be read: return TL_ERROR_LIMIT. On failure
     * return TL_ERROR_IO (or another code) and optionally point *why at a one-line reason, valid
     * until the next call; it becomes part of the load's message.
     */
    tl_result (*read)(void *user, const char *uri, size_t max_size, void **data, size_t *size,
                      const char **why);
    /** Frees what `read` returned; may be NULL when there is nothing to free. */
    void (*release)(void *user, void *data, size_t size);
    void *user; /**< passed to both functions */
} tl_gltf_files;

/** The default of tl_gltf_options.max_memory: 512 MiB (docs/gltf.md, "Limits"). */
#define TL_GLTF_DEFAULT_MAX_MEMORY ((size_t)512 << 20)

/** Options of tl_scene_load_gltf and tl_scene_parse_gltf; a zeroed field means the default
 *  beside it. */
typedef struct tl_gltf_options {
    tl_allocator allocator;    /**< zeroed: malloc/free; the scene and the loader's own buffers */
    tl_logger logger;          /**< errors and warnings, one line each: "FILE: element: message" */
    uint32_t scene_number;     /**< 0: the file's "scene", else scenes[0]; N: scenes[N - 1] */
    uint32_t extra_lights;     /**< seeded point lights added inside the scene bounds; at most 65536 */
    uint64_t seed;             /**< for extra_lights; 0 = 1; same seed, same lights */
    int no_default_lights;     /**< 1: a file without lights gets no default rig */
    tl_gltf_normals normals;   /**< generated normals; default flat */
    size_t max_texture_pixels; /**< per image; 0 = 2^26; a larger image is TL_ERROR_LIMIT */
    size_t max_triangles;      /**< triangles drawn (instances count each time); 0 = 2^26; the
                                    scene's vertices may be at most 3 times this */
    size_t max_memory;         /**< the budget for everything one load holds at once: the file,
                                    its buffers, the parsed JSON, decoded images (each image a
                                    material uses, however many refer to the same bytes), the
                                    scene and temporary arrays; 0 = TL_GLTF_DEFAULT_MAX_MEMORY,
                                    SIZE_MAX = no budget. Over it: TL_ERROR_LIMIT naming what */
    tl_gltf_files files;       /**< external buffers and images; zeroed: see tl_gltf_files */
    const char *name;          /**< tl_scene_parse_gltf: what messages call the data; NULL = "memory" */
    /** Which lights cast shadows (tl_light.shadow; docs/gltf.md, "Shadows"). Always: a
     *  KHR_lights_punctual light whose "extras" hold "thinlight_shadow": true casts, false never
     *  casts. 0: no other light casts. N > 0 (the tools' --shadows, with the renderer's
     *  tl_shadow_desc.max_lights): also every other directional light, then the other point and
     *  spot lights (the default rig's and the extra lights included), brightest first, while fewer
     *  than N lights cast. */
    uint32_t shadow_lights;
} tl_gltf_options;

/**
 * Loads a glTF 2.0 file (.gltf with external or data-URI buffers and images, or .glb; the
 * content decides, not the extension) into a scene freed by tl_scene_destroy: reads `path` (a
 * regular file; a FIFO or device is TL_ERROR_IO at once) and parses it as tl_scene_parse_gltf
 * does, with external files read by options->files or, by default, from the folder of `path`
 * only (docs/gltf.md, "External files"). NULL options means all defaults. Materials follow the
 * one conversion of docs/gltf.md (diffuse = base * (1 - metal), specular F0 = mix(0.04, base,
 * metal), gloss = 1 - roughness; done here for constant factors, per pixel by the renderer with
 * a metallic-roughness texture, see tl_material). A file without lights gets a default rig, one
 * without a camera a camera framing its bounds, one without triangles loads as an empty scene
 * (with a warning). Missing or undecodable images become warnings and flat colours. Returns
 * TL_ERROR_INVALID_ARGUMENT (NULL path or out, bad options, a scene number past the file's),
 * TL_ERROR_IO (the file or a buffer cannot be read, or lies outside the folder),
 * TL_ERROR_PARSE (malformed JSON, GLB or references), TL_ERROR_UNSUPPORTED (a required
 * extension, sparse accessors), TL_ERROR_LIMIT (texture pixels, triangles, 2^32 vertices or
 * indices, extra lights, JSON nesting, the memory budget) or TL_ERROR_OUT_OF_MEMORY; nothing is
 * leaked, *out is NULL on failure and the one error line goes to options->logger.
 */
TL_API tl_result tl_scene_load_gltf(const char *path, const tl_gltf_options *options, tl_scene **out);

/**
 * Parses a glTF 2.0 file held in memory (`size` bytes of .gltf JSON or .glb) into a scene,
 * exactly as tl_scene_load_gltf does with the file's bytes. The bytes are only read, and only
 * during the call. External buffers and images are read through options->files; without it
 * only data: URIs and GLB buffer views are available (an external buffer is TL_ERROR_IO, an
 * external image a warning). Results as tl_scene_load_gltf.
 */
TL_API tl_result tl_scene_parse_gltf(const void *data, size_t size, const tl_gltf_options *options,
                                     tl_scene **out);

#ifdef __cplusplus
}
#endif
#endif
