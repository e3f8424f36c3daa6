// The C entry points, tl_scene_load_gltf and tl_scene_parse_gltf: argument checks, options
// resolved into one context, the load (gltf_load.cpp) run inside one try block, and every failure
// turned into a tl_result plus one line to the logger (core/log.h, as every layer). The path load
// is the memory load with the file's bytes and the default file callbacks (gltf_folder.cpp).
#include "gltf_internal.h"

namespace tl_gltf {
namespace {

// Checks what can be checked without a context; nullptr when the options are usable.
const char *bad_options(const tl_gltf_options &o)
{
    if (!o.allocator.alloc != !o.allocator.free) return "allocator needs both alloc and free";
    if ((unsigned)o.normals >= TL_GLTF_NORMALS_COUNT_) return "unknown normals mode";
    if (o.files.release && !o.files.read) return "files.release without files.read";
    return nullptr;
}

void resolve(const tl_gltf_options &o, context *c)
{
    tl__allocator_resolve(&o.allocator, &c->alloc); // bad_options refused a half allocator
    c->logger = o.logger;
    c->files = o.files;
    c->normals = o.normals == TL_GLTF_NORMALS_DEFAULT ? TL_GLTF_NORMALS_FLAT : o.normals;
    c->max_texture_pixels = o.max_texture_pixels ? o.max_texture_pixels : (size_t)1 << 26;
    c->max_triangles = o.max_triangles ? o.max_triangles : (size_t)1 << 26;
    c->budget = o.max_memory ? o.max_memory : TL_GLTF_DEFAULT_MAX_MEMORY;
    c->scene_number = o.scene_number;
    c->extra_lights = o.extra_lights;
    c->shadow_lights = o.shadow_lights;
    c->seed = o.seed ? o.seed : 1;
    c->default_lights = !o.no_default_lights;
}

// Runs `body` (which loads into *out) and reports its failure as "NAME: message".
template <class F> tl_result run(const tl_gltf_options &o, const char *name, tl_scene **out, F body)
{
    try {
        context c;
        resolve(o, &c);
        c.name = name;
        tl_result r = TL_OK;
        std::string message;
        try {
            *out = body(c);
            return TL_OK;
        } catch (const failure &f) {
            r = f.result;
            message = f.message;
        } catch (const std::bad_alloc &) {
            r = TL_ERROR_OUT_OF_MEMORY;
            message = "out of memory";
        } catch (const std::exception &e) {
            r = TL_ERROR_PARSE;
            message = e.what();
        } catch (...) {
            r = TL_ERROR_PARSE;
            message = "unknown error";
        }
        return tl__logger_fail(&c.logger, r, "%s: %s", c.name.c_str(), message.c_str());
    } catch (...) {
        // Only reachable when even the context or the message could not be built.
        return tl__logger_fail(&o.logger, TL_ERROR_OUT_OF_MEMORY, "%s: out of memory", name);
    }
}

tl_result early(const tl_gltf_options &o, tl_result r, const std::string &message)
{
    return tl__logger_fail(&o.logger, r, "%s", message.c_str());
}

} // namespace
} // namespace tl_gltf

extern "C" tl_result tl_scene_load_gltf(const char *path, const tl_gltf_options *options, tl_scene **out)
{
    using namespace tl_gltf;
    tl_gltf_options o = options ? *options : tl_gltf_options{};
    if (out) *out = nullptr;
    if (!path || !out) return early(o, TL_ERROR_INVALID_ARGUMENT, "tl_scene_load_gltf: NULL path or out");
    if (const char *bad = bad_options(o)) return early(o, TL_ERROR_INVALID_ARGUMENT, std::string("tl_scene_load_gltf: ") + bad);
    if (o.extra_lights > 65536) return early(o, TL_ERROR_LIMIT, "tl_scene_load_gltf: more than 65536 extra lights");
    return run(o, path, out, [&](context &c) {
        folder_reader folder;
        if (!c.files.read) c.files = folder_files(c, path, &folder);
        file_bytes file(c);
        read_main_file(c, path, &file);
        return load_scene(c, file.data, file.size, o.allocator);
    });
}

extern "C" tl_result tl_scene_parse_gltf(const void *data, size_t size, const tl_gltf_options *options, tl_scene **out)
{
    using namespace tl_gltf;
    tl_gltf_options o = options ? *options : tl_gltf_options{};
    if (out) *out = nullptr;
    const char *name = o.name ? o.name : "memory";
    if ((!data && size) || !out) return early(o, TL_ERROR_INVALID_ARGUMENT, "tl_scene_parse_gltf: NULL data or out");
    if (const char *bad = bad_options(o)) return early(o, TL_ERROR_INVALID_ARGUMENT, std::string("tl_scene_parse_gltf: ") + bad);
    if (o.extra_lights > 65536) return early(o, TL_ERROR_LIMIT, "tl_scene_parse_gltf: more than 65536 extra lights");
    return run(o, name, out, [&](context &c) {
        return load_scene(c, static_cast<const unsigned char *>(data), size, o.allocator);
    });
}
