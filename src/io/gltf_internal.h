// Private to the glTF adapter (src/io/gltf_*.cpp): the load context, failures, allocation through
// the caller's allocator, and the steps gltf_load.cpp runs in order. C++ never leaves src/io.
#ifndef TL_GLTF_INTERNAL_H
#define TL_GLTF_INTERNAL_H

#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <new>
#include <string>
#include <vector>

#include "core/alloc.h"
#include "core/log.h"
#include "thinlight/io.h"

namespace tl_gltf {

// ---- context and messages (gltf_context.cpp) ------------------------------------------------

// Everything one load needs; options are resolved (no zero "defaults" left).
struct context {
    tl_allocator alloc{};           // resolved (both functions set); used through core/alloc.h
    tl_logger logger{};             // errors and warnings go through core/log.h
    std::string name;               // the path, or options.name for memory loads; prefixes every message
    tl_gltf_files files{};          // external buffers and images; read == nullptr: none
    tl_gltf_normals normals = TL_GLTF_NORMALS_FLAT;
    size_t max_texture_pixels = 0;
    size_t max_triangles = 0;
    size_t budget = 0;              // max_memory
    mutable size_t used = 0;        // bytes held now against the budget (see charge())
    mutable size_t peak = 0;
    uint32_t scene_number = 0;
    uint32_t extra_lights = 0;
    uint32_t shadow_lights = 0;     // the shadow rule's budget; 0: the extras' flags only
    uint64_t seed = 1;
    bool default_lights = true;
    // Set when reading an external buffer fails inside tinygltf, so that the failure keeps its
    // own result and message rather than becoming tinygltf's parse error.
    tl_result io_result = TL_OK;
    std::string io_detail;
};

// JSON nested deeper than this is refused before any parser sees it (docs/gltf.md, "Limits").
constexpr size_t max_json_depth = 64;

// A failure: thrown anywhere inside the adapter, turned into a tl_result and one message line at
// the C boundary (tl__logger_fail, core/log.h). `message` is "element: what", without the file
// name.
struct failure {
    tl_result result;
    std::string message;
};

[[noreturn]] void fail(tl_result result, const std::string &message);
// Logs "name: message" as a warning (one line; embedded newlines are split into lines).
void warn(const context &c, const std::string &message);

// "meshes[2].primitives[0]" style element names.
std::string element(const char *array, size_t index);
// A byte count for messages: "812 bytes", "35.2 KiB", "512.0 MiB".
std::string byte_size(size_t bytes);

// ---- the memory budget and allocation through the caller's allocator -------------------------

// Counts `bytes` against the load's budget (c.budget); throws failure{TL_ERROR_LIMIT} naming
// `what` when they do not fit. Every allocation of the load goes through here: the caller's
// allocator (alloc_bytes, stl_allocator) and, as estimates or exact sizes, what tinygltf and
// nlohmann-json hold in the C++ heap (gltf_parse.cpp).
void charge(const context &c, size_t bytes, const std::string &what);
void uncharge(const context &c, size_t bytes);
// What the budget still allows.
size_t budget_left(const context &c);

// A charge held until the end of a scope.
struct budget_hold {
    const context &c;
    size_t bytes = 0;
    explicit budget_hold(const context &ctx) : c(ctx) {}
    ~budget_hold() { uncharge(c, bytes); }
    void add(size_t n, const std::string &what)
    {
        charge(c, n, what);
        bytes += n;
    }
    budget_hold(const budget_hold &) = delete;
    budget_hold &operator=(const budget_hold &) = delete;
};

// count * size bytes (overflow-checked), charged to the budget; throws failure naming `what`
// (TL_ERROR_LIMIT over the budget, TL_ERROR_OUT_OF_MEMORY when the allocator fails).
void *alloc_bytes(const context &c, size_t count, size_t size, const std::string &what);
// Frees what alloc_bytes returned for `bytes` (count * size) bytes.
void free_bytes(const context &c, void *ptr, size_t bytes);

// A standard allocator over the context's allocator and budget, so temporary vectors count as
// the caller's allocations too; failure throws (std::bad_alloc from the allocator, failure from
// the budget), which the C boundary reports.
template <class T> struct stl_allocator {
    using value_type = T;
    const context *c;
    explicit stl_allocator(const context *ctx) noexcept : c(ctx) {}
    template <class U> stl_allocator(const stl_allocator<U> &o) noexcept : c(o.c) {}
    T *allocate(size_t n)
    {
        if (n > std::numeric_limits<size_t>::max() / sizeof(T)) throw std::bad_alloc();
        size_t bytes = n * sizeof(T);
        charge(*c, bytes, "temporary arrays");
        void *p = tl__alloc(&c->alloc, bytes);
        if (!p) {
            uncharge(*c, bytes);
            throw std::bad_alloc();
        }
        return static_cast<T *>(p);
    }
    void deallocate(T *p, size_t n) noexcept
    {
        uncharge(*c, n * sizeof(T));
        tl__free(&c->alloc, p);
    }
    template <class U> bool operator==(const stl_allocator<U> &o) const noexcept { return c == o.c; }
    template <class U> bool operator!=(const stl_allocator<U> &o) const noexcept { return c != o.c; }
};

template <class T> using vec = std::vector<T, stl_allocator<T>>;
template <class T> vec<T> make_vec(const context &c) { return vec<T>(stl_allocator<T>(&c)); }

// ---- external files (gltf_external.cpp) ------------------------------------------------------

// The bytes of one external file, read through c.files and charged to the budget until freed.
struct external_file {
    const context &c;
    void *data = nullptr;
    size_t size = 0;
    explicit external_file(const context &ctx) : c(ctx) {}
    ~external_file();
    external_file(const external_file &) = delete;
    external_file &operator=(const external_file &) = delete;
};
// Reads `uri` (percent-decoded) through c.files. False with *result and *why ("'uri': reason")
// when it cannot be read; throws failure for memory (the budget, TL_ERROR_LIMIT or
// TL_ERROR_OUT_OF_MEMORY from the callback).
bool read_external(const context &c, const std::string &uri, external_file *out, tl_result *result, std::string *why);

// ---- the folder reader (gltf_folder.cpp) ----------------------------------------------------

// The default tl_gltf_files of path loads: regular files in the glTF file's folder and below,
// allocated through the context's allocator. `dir` is the folder as the path names it.
struct folder_reader {
    const context *c = nullptr;
    std::string root;   // realpath of the folder, "" when it cannot be resolved
    std::string why;    // the last failure's reason (tl_gltf_files.read's *why)
};
// Fills `r` for the folder of `path` and returns the tl_gltf_files that use it.
tl_gltf_files folder_files(const context &c, const std::string &path, folder_reader *r);
// The glTF file itself, read through the context's allocator (charged): only a regular file,
// opened without blocking. Throws failure.
struct file_bytes {
    const context &c;
    unsigned char *data = nullptr;
    size_t size = 0;
    explicit file_bytes(const context &ctx) : c(ctx) {}
    ~file_bytes() { free_bytes(c, data, size); }
    file_bytes(const file_bytes &) = delete;
    file_bytes &operator=(const file_bytes &) = delete;
};
void read_main_file(const context &c, const std::string &path, file_bytes *out);

// ---- the load (gltf_load.cpp) ---------------------------------------------------------------

// Parses `size` bytes and builds the scene; throws failure. The C entry points (gltf_api.cpp)
// resolve the options into `c` and catch.
tl_scene *load_scene(context &c, const unsigned char *data, size_t size, const tl_allocator &user_allocator);

// ---- parsing (gltf_parse.cpp) ---------------------------------------------------------------

// JSON whose shape would be costly to parse: nesting and how much parsed memory it may need.
struct json_shape {
    size_t depth = 0;        // deepest nesting of objects and arrays
    size_t deep_at = 0;      // byte offset where nesting first passed max_json_depth (depth > max)
    size_t containers = 0;   // objects and arrays
    size_t members = 0;      // object members (key: value)
    size_t items = 0;        // values after the first in arrays, members after the first in objects
    size_t elements = 0;     // objects directly inside a top-level array (tinygltf structs)...
    size_t materials = 0;    // ... and those of "materials" (the largest struct) apart
    size_t string_bytes = 0; // bytes inside strings, keys included
};
// One pass over the text, no allocation, no recursion; stops at max_json_depth + 1.
json_shape scan_json(const unsigned char *text, size_t size);
// What parsing a document of that shape may hold in the C++ heap (nlohmann's DOM and tinygltf's
// model together), an upper estimate.
size_t json_parse_cost(const json_shape &s);

// What tinygltf would trust without checking, checked on nlohmann's parse of the same text (a
// malformed text is left for tinygltf to report): in a GLB only buffers[0] may use the BIN chunk
// (tinygltf copies the chunk for every buffer without a URI), charged to `hold`; an image's
// buffer view starts inside its buffer (tinygltf indexes the buffer before any check). Throws.
void check_json(const context &c, const unsigned char *json, size_t size, bool glb, size_t bin_size, budget_hold *hold);

// Parses `size` bytes (.gltf or .glb by content) into `model`; buffers are loaded, images are
// kept encoded (decoded later, only when a material uses them). What tinygltf holds is charged
// to `hold` for as long as the model lives. Throws failure.
void parse_gltf(context &c, const unsigned char *data, size_t size, tinygltf::Model *model, budget_hold *hold);

// ---- accessors (gltf_accessor.cpp) ----------------------------------------------------------

// A validated accessor: every element lies inside its buffer.
struct accessor_view {
    int index = -1;               // into model.accessors
    const unsigned char *data = nullptr; // first element; nullptr: no bufferView, all zeros
    size_t count = 0;
    size_t stride = 0;
    int component_type = 0;
    int components = 0;
    bool normalized = false;
};

// Validates model.accessors[index] for `role` (e.g. "meshes[0].primitives[1] POSITION"):
// `type` is TINYGLTF_TYPE_*; `indices` restricts components to unsigned 8/16/32-bit. Throws.
accessor_view get_accessor(const tinygltf::Model &m, int index, int type, bool indices, const std::string &role);
// Element i as floats (normalised integers mapped to [0,1] or [-1,1]); writes view.components.
void read_floats(const accessor_view &v, size_t i, float *out);
uint32_t read_index(const accessor_view &v, size_t i);

// ---- scene graph (gltf_nodes.cpp) -----------------------------------------------------------

struct mesh_instance {
    int node;
    int mesh;
    double world[16]; // column-major
};
struct light_instance {
    int node;
    int light;
    double world[16];
};
struct scene_graph {
    explicit scene_graph(const context &c) : meshes(make_vec<mesh_instance>(c)), lights(make_vec<light_instance>(c)) {}
    vec<mesh_instance> meshes;
    vec<light_instance> lights;
    int camera_node = -1; // first camera node in depth-first order
    double camera_world[16] = {0};
};

// Picks the scene (options.scene_number), checks the node graph (references, one parent, no
// cycles) and walks it depth-first, composing world transforms. Throws.
void walk_scene(const context &c, const tinygltf::Model &m, scene_graph *g);

// ---- images and textures (gltf_image.cpp, gltf_texture.cpp) ---------------------------------

// RGBA8 pixels owned through the context's allocator.
struct decoded_image {
    uint32_t width = 0, height = 0;
    uint8_t *rgba = nullptr;
};
// Decodes an encoded PNG or JPEG image from memory (image_decode.h), its pixels charged to the
// budget. Returns false with `why` set when the data cannot be decoded (the caller warns and
// falls back); throws failure for TL_ERROR_LIMIT (c.max_texture_pixels, the budget) and out of
// memory.
bool decode_image_memory(const context &c, const unsigned char *data, size_t size, const std::string &mime,
                         const std::string &what, decoded_image *out, std::string *why);

// The scene's textures while loading: owns their pixels until handed to the scene.
struct texture_table {
    explicit texture_table(const context &ctx)
        : c(&ctx), textures(make_vec<tl_texture>(ctx)), image_slot(make_vec<uint32_t>(ctx))
    {
    }
    ~texture_table();
    texture_table(const texture_table &) = delete;
    texture_table &operator=(const texture_table &) = delete;
    const context *c;
    vec<tl_texture> textures;
    vec<uint32_t> image_slot; // per glTF image: its map (index into textures + 1), 0 for none, or unset
};
constexpr uint32_t image_unset = UINT32_MAX;

// The map (tl_material: the scene texture's index + 1) for glTF texture `index` (decoded once per
// image), or 0 after a warning naming `what` when the image is missing or undecodable; 0 for
// index -1 (no texture). Throws on bad references and limits.
uint32_t texture_for(const context &c, const tinygltf::Model &m, texture_table *t, int index, const std::string &what);

// ---- materials (gltf_material.cpp) ----------------------------------------------------------

// glTF material (or -1, the default material) to tl_material; textures are decoded into `t`.
tl_material convert_material(const context &c, const tinygltf::Model &m, int index, texture_table *t);
// gltf_material_ext.cpp: the material extensions into the model, its parameters and the
// dielectric F0 (base: the base colour factor, metal: the metallic factor).
void convert_material_extensions(const context &c, const tinygltf::Material &g, const std::string &name,
                                 const float base[3], float metal, tl_material *out);

// ---- meshes (gltf_mesh.cpp, gltf_normals.cpp) -----------------------------------------------

// One glTF primitive's slice of the scene's vertex and index arrays (shared by every instance).
struct primitive_plan {
    int mesh = -1, primitive = -1;
    bool skipped = false;       // no POSITION, or an unknown mode: warned, no object
    int mode = 4;               // glTF's primitive mode (TINYGLTF_MODE_*)
    uint32_t draws = 0;         // what its indices draw (tl_primitive): strips and fans become lists
    bool indexed = false;
    bool has_normals = false;
    bool has_uvs = false;
    bool has_tangents = false;
    bool has_colors = false;    // COLOR_0
    bool has_uv1 = false;       // TEXCOORD_1
    bool unweld = false;        // flat normals to generate on an indexed primitive
    bool needs_tangents = false; // the material has a normal map
    int gltf_material = -1;
    uint32_t material = 0;      // scene material index
    size_t first_vertex = 0, vertex_count = 0;
    size_t first_index = 0, index_count = 0;
    // A copy of the indices with every triangle reversed, for instances under a mirroring
    // transform (glTF: a negative determinant flips the winding).
    bool mirrored = false;
    size_t mirrored_first_index = 0;
};

// Validates the primitive's accessors and fills counts (not offsets). Throws.
void plan_primitive(const context &c, const tinygltf::Model &m, int mesh, int primitive, primitive_plan *p);
// The scene's optional per-vertex arrays (nullptr when the scene has none): RGBA colours (white
// where a primitive has no COLOR_0) and the second UV set (the first where it has no TEXCOORD_1).
struct vertex_extras {
    float *colors = nullptr;
    float *uv1 = nullptr;
};
// Fills vertices[p.first_vertex ...], indices[p.first_index ...] (global indices) and the extras
// of its vertices. Throws.
void build_primitive(const context &c, const tinygltf::Model &m, const primitive_plan &p, tl_vertex *vertices,
                     uint32_t *indices, const vertex_extras &extras);

// Normal and tangent generation on one primitive (`idx` are local indices, 3 per triangle).
void flat_normals(tl_vertex *v, size_t vertex_count); // vertices unshared: 3 per triangle
void smooth_normals(const tl_vertex *v, size_t vertex_count, const uint32_t *idx, size_t index_count, float *out);
// Replaces non-finite or zero-length normals by smooth ones; normalises the rest. Returns how
// many were replaced.
size_t repair_normals(const context &c, tl_vertex *v, size_t vertex_count, const uint32_t *idx, size_t index_count);
void generate_tangents(const context &c, tl_vertex *v, size_t vertex_count, const uint32_t *idx, size_t index_count);
// Keeps given tangents usable: orthonormal to the normal, w = +-1. Returns how many were bad
// (zero or non-finite); the caller regenerates them all when any was.
size_t fix_tangents(tl_vertex *v, size_t vertex_count);
// Any unit vector orthogonal to unit n.
void orthogonal(const float n[3], float out[3]);

// ---- lights and camera (gltf_lights.cpp, gltf_camera.cpp) -----------------------------------

// `flags` receives each converted light's extras.thinlight_shadow: 1 true, 0 false, -1 none.
void convert_lights(const context &c, const tinygltf::Model &m, const scene_graph &g, vec<tl_light> *out,
                    vec<signed char> *flags);
// Sets tl_light.shadow from the flags (-1 beyond flags' size) and, with c.shadow_lights, the rule.
void shadow_rule(const context &c, const vec<signed char> &flags, vec<tl_light> *lights);
void default_rig(const float bmin[3], const float bmax[3], vec<tl_light> *out);
void extra_lights(const context &c, const float bmin[3], const float bmax[3], vec<tl_light> *out);
// Skips, with a warning naming `what`N], each light from `first` on that the renderer would refuse.
void drop_unrenderable(const context &c, const char *what, size_t first, vec<tl_light> *lights);
// The file's camera, or the framing camera; `s` holds the scene's objects (the near plane's floor).
void make_camera(const context &c, const tinygltf::Model &m, const scene_graph &g, const float bmin[3],
                 const float bmax[3], const tl_scene *s, tl_camera *out);

// Linear ambient radiance of every loaded scene (docs/gltf.md).
constexpr float ambient = 0.03f;

} // namespace tl_gltf

#endif
