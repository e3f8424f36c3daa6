// tl_scene_load_gltf: the C entry point. Resolves the options, runs the steps (parse, scene graph,
// primitives, materials, geometry, lights, camera) and assembles the tl_scene. Every failure inside
// is an exception caught here and turned into a tl_result plus one message line; the scene under
// construction is freed exactly as tl_scene_destroy would free it.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "gltf_internal.h"
#include "gltf_math.h"

namespace tl_gltf {
namespace {

void *default_alloc(size_t size, void *) { return std::malloc(size); }
void default_free(void *ptr, void *) { std::free(ptr); }

// The same frees in the same order as tl_scene_destroy (src/scene/scene.c), with the same
// allocator, so that a half-built scene leaves nothing behind.
void free_scene(const context &c, tl_scene *s)
{
    if (!s) return;
    if (s->textures)
        for (size_t i = 0; i < s->texture_count; i++) free_bytes(c, s->textures[i].rgba);
    free_bytes(c, s->textures);
    free_bytes(c, s->vertices);
    free_bytes(c, s->indices);
    free_bytes(c, s->objects);
    free_bytes(c, s->materials);
    free_bytes(c, s->lights);
    free_bytes(c, s);
}

struct scene_guard {
    const context &c;
    tl_scene *s;
    ~scene_guard() { free_scene(c, s); }
};

// An exact-size array for the scene; NULL for none (tl_scene allows NULL with a zero count).
template <class T> T *scene_array(const context &c, size_t n, const char *what)
{
    return n ? static_cast<T *>(alloc_bytes(c, n, sizeof(T), what)) : nullptr;
}

// Extensions whose content we read (or that need nothing from us, as KHR_mesh_quantization:
// integer attributes go through the generic accessor reader).
bool supported_extension(const std::string &e)
{
    return e == "KHR_lights_punctual" || e == "KHR_materials_emissive_strength" || e == "KHR_mesh_quantization";
}

void check_extensions(const context &c, const tinygltf::Model &m)
{
    for (const std::string &e : m.extensionsRequired)
        if (!supported_extension(e)) fail(TL_ERROR_UNSUPPORTED, "extensionsRequired: " + e + " is not supported");
    for (const std::string &e : m.extensionsUsed)
        if (!supported_extension(e)) warn(c, "extensionsUsed: " + e + " is ignored");
}

// A transform that turns a right-handed frame left-handed (negative determinant).
bool mirrors(const double m[16])
{
    double det = m[0] * (m[5] * m[10] - m[6] * m[9]) - m[4] * (m[1] * m[10] - m[2] * m[9]) + m[8] * (m[1] * m[6] - m[2] * m[5]);
    return det < 0.0;
}

// World-space bounds of the vertices; false when they do not fit single precision.
bool object_bounds(const tl_vertex *v, size_t count, const double world[16], float bmin[3], float bmax[3])
{
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (size_t i = 0; i < count; i++) {
        double p[3] = {v[i].position[0], v[i].position[1], v[i].position[2]}, w[3];
        mat_point(world, p, w);
        for (int k = 0; k < 3; k++) {
            lo[k] = w[k] < lo[k] ? w[k] : lo[k];
            hi[k] = w[k] > hi[k] ? w[k] : hi[k];
        }
    }
    for (int k = 0; k < 3; k++) {
        if (count && (!fits_float(lo[k]) || !fits_float(hi[k]))) return false;
        bmin[k] = count ? (float)lo[k] : 0.0f;
        bmax[k] = count ? (float)hi[k] : 0.0f;
    }
    return true;
}

tl_scene *load(context &c, const tl_allocator &user_allocator)
{
    tinygltf::Model model;
    parse_file(c, &model);
    check_extensions(c, model);
    scene_graph g(c);
    walk_scene(c, model, &g);

    // One plan per primitive of every mesh some node instantiates; instances share it.
    vec<size_t> mesh_plan = make_vec<size_t>(c);
    mesh_plan.assign(model.meshes.size(), SIZE_MAX);
    vec<primitive_plan> plans = make_vec<primitive_plan>(c);
    for (const mesh_instance &mi : g.meshes) {
        if (mesh_plan[(size_t)mi.mesh] != SIZE_MAX) continue;
        mesh_plan[(size_t)mi.mesh] = plans.size();
        const tinygltf::Mesh &mesh = model.meshes[(size_t)mi.mesh];
        for (size_t p = 0; p < mesh.primitives.size(); p++) {
            primitive_plan plan;
            plan_primitive(c, model, mi.mesh, (int)p, &plan);
            plans.push_back(plan);
        }
    }

    // Materials in order of first use; slot materials.size() of the table is the default one.
    texture_table textures(c);
    vec<tl_material> materials = make_vec<tl_material>(c);
    vec<uint32_t> material_slot = make_vec<uint32_t>(c);
    material_slot.assign(model.materials.size() + 1, TL_NO_TEXTURE);
    for (primitive_plan &p : plans) {
        if (p.skipped) continue;
        if (p.gltf_material >= 0 && (size_t)p.gltf_material >= model.materials.size())
            fail(TL_ERROR_PARSE, element("meshes", (size_t)p.mesh) + "." + element("primitives", (size_t)p.primitive) +
                                     ": material " + std::to_string(p.gltf_material) + " out of range (" +
                                     std::to_string(model.materials.size()) + " materials)");
        size_t slot = p.gltf_material >= 0 ? (size_t)p.gltf_material : model.materials.size();
        if (material_slot[slot] == TL_NO_TEXTURE) {
            materials.push_back(convert_material(c, model, p.gltf_material, &textures));
            material_slot[slot] = (uint32_t)(materials.size() - 1);
        }
        p.material = material_slot[slot];
        p.needs_tangents = materials[p.material].normal_texture != TL_NO_TEXTURE;
    }

    // Objects and the drawn-triangle limit; which primitives need a mirrored index copy.
    size_t drawn = 0, object_total = 0;
    for (const mesh_instance &mi : g.meshes) {
        size_t first = mesh_plan[(size_t)mi.mesh];
        for (size_t p = 0; p < model.meshes[(size_t)mi.mesh].primitives.size(); p++) {
            primitive_plan &pl = plans[first + p];
            if (pl.skipped || !pl.index_count) continue;
            object_total++;
            drawn += pl.index_count / 3;
            if (drawn > c.max_triangles)
                fail(TL_ERROR_LIMIT, "more than the limit of " + std::to_string(c.max_triangles) + " triangles");
            if (mirrors(mi.world)) pl.mirrored = true;
        }
    }
    // Slices of the shared arrays; indices are 32-bit, and so are the objects' index ranges.
    size_t vertex_total = 0, index_total = 0;
    for (primitive_plan &p : plans) {
        if (p.skipped) continue;
        p.first_vertex = vertex_total;
        p.first_index = index_total;
        vertex_total += p.vertex_count;
        index_total += p.index_count;
        if (p.mirrored) {
            p.mirrored_first_index = index_total;
            index_total += p.index_count;
        }
        if (vertex_total > UINT32_MAX || index_total > UINT32_MAX) fail(TL_ERROR_LIMIT, "more than 2^32 vertices or indices");
    }
    // Vertices need not be referenced, and an accessor without a buffer view is all zeros at no
    // cost in the file: without this bound a few bytes of JSON could ask for gigabytes.
    if (vertex_total / 3 > c.max_triangles)
        fail(TL_ERROR_LIMIT, std::to_string(vertex_total) + " vertices: more than 3 per triangle of the limit of " +
                                 std::to_string(c.max_triangles));

    scene_guard sg{c, static_cast<tl_scene *>(alloc_bytes(c, 1, sizeof(tl_scene), "scene"))};
    tl_scene *s = sg.s;
    *s = tl_scene{};
    s->vertices = scene_array<tl_vertex>(c, vertex_total, "vertices");
    s->vertex_count = vertex_total;
    s->indices = scene_array<uint32_t>(c, index_total, "indices");
    s->index_count = index_total;
    for (const primitive_plan &p : plans) {
        if (p.skipped) continue;
        build_primitive(c, model, p, s->vertices, s->indices);
        if (!p.mirrored) continue;
        const uint32_t *src = s->indices + p.first_index;
        uint32_t *dst = s->indices + p.mirrored_first_index;
        for (size_t t = 0; t + 2 < p.index_count; t += 3) {
            dst[t] = src[t];
            dst[t + 1] = src[t + 2];
            dst[t + 2] = src[t + 1];
        }
    }

    s->objects = scene_array<tl_object>(c, object_total, "objects");
    float bmin[3] = {0, 0, 0}, bmax[3] = {0, 0, 0};
    for (const mesh_instance &mi : g.meshes) {
        size_t first = mesh_plan[(size_t)mi.mesh];
        for (size_t p = 0; p < model.meshes[(size_t)mi.mesh].primitives.size(); p++) {
            const primitive_plan &pl = plans[first + p];
            if (pl.skipped || !pl.index_count) continue;
            tl_object &o = s->objects[s->object_count];
            o = tl_object{};
            o.first_index = (uint32_t)(mirrors(mi.world) ? pl.mirrored_first_index : pl.first_index);
            o.index_count = (uint32_t)pl.index_count;
            o.material = pl.material;
            for (int k = 0; k < 16; k++) o.transform[k] = (float)mi.world[k];
            if (!object_bounds(s->vertices + pl.first_vertex, pl.vertex_count, mi.world, o.bounds_min, o.bounds_max))
                fail(TL_ERROR_PARSE, element("nodes", (size_t)mi.node) + ": world-space positions overflow single precision");
            for (int k = 0; k < 3; k++) {
                bmin[k] = s->object_count == 0 || o.bounds_min[k] < bmin[k] ? o.bounds_min[k] : bmin[k];
                bmax[k] = s->object_count == 0 || o.bounds_max[k] > bmax[k] ? o.bounds_max[k] : bmax[k];
            }
            s->object_count++;
        }
    }
    if (!s->object_count) warn(c, "the scene draws no triangles; loaded as an empty scene");
    for (int k = 0; k < 3; k++) {
        s->bounds_min[k] = bmin[k];
        s->bounds_max[k] = bmax[k];
    }

    s->materials = scene_array<tl_material>(c, materials.size(), "materials");
    if (!materials.empty()) std::memcpy(s->materials, materials.data(), materials.size() * sizeof(tl_material));
    s->material_count = materials.size();
    s->textures = scene_array<tl_texture>(c, textures.textures.size(), "textures");
    if (!textures.textures.empty()) {
        std::memcpy(s->textures, textures.textures.data(), textures.textures.size() * sizeof(tl_texture));
        s->texture_count = textures.textures.size();
        textures.textures.clear(); // the scene owns the pixels now
    }

    vec<tl_light> lights = make_vec<tl_light>(c);
    convert_lights(c, model, g, &lights);
    if (lights.empty() && c.default_lights) default_rig(bmin, bmax, &lights);
    extra_lights(c, bmin, bmax, &lights);
    s->lights = scene_array<tl_light>(c, lights.size(), "lights");
    if (!lights.empty()) std::memcpy(s->lights, lights.data(), lights.size() * sizeof(tl_light));
    s->light_count = lights.size();

    make_camera(c, model, g, bmin, bmax, &s->camera);
    for (float &a : s->ambient) a = ambient;
    s->allocator = user_allocator;
    sg.s = nullptr;
    return s;
}

void report(const context &c, const std::string &message, char *error, size_t error_size)
{
    std::string line = c.path + ": " + message;
    for (char &ch : line)
        if (ch == '\n' || ch == '\r') ch = ' ';
    if (c.logger.fn) c.logger.fn(c.logger.user, TL_LOG_ERROR, line.c_str());
    if (error && error_size) std::snprintf(error, error_size, "%s", line.c_str());
}

} // namespace
} // namespace tl_gltf

extern "C" tl_result tl_scene_load_gltf(const char *path, const tl_gltf_options *options, tl_scene **out)
{
    using namespace tl_gltf;
    tl_gltf_options o = options ? *options : tl_gltf_options{};
    if (o.error && o.error_size) o.error[0] = '\0';
    if (out) *out = nullptr;
    auto early = [&](tl_result r, const char *msg) {
        if (o.logger.fn) o.logger.fn(o.logger.user, TL_LOG_ERROR, msg);
        if (o.error && o.error_size) std::snprintf(o.error, o.error_size, "%s", msg);
        return r;
    };
    if (!path || !out) return early(TL_ERROR_INVALID_ARGUMENT, "tl_scene_load_gltf: NULL path or out");
    if (!o.allocator.alloc != !o.allocator.free)
        return early(TL_ERROR_INVALID_ARGUMENT, "tl_scene_load_gltf: allocator needs both alloc and free");
    if ((unsigned)o.normals >= TL_GLTF_NORMALS_COUNT_)
        return early(TL_ERROR_INVALID_ARGUMENT, "tl_scene_load_gltf: unknown normals mode");
    if (o.extra_lights > 65536) return early(TL_ERROR_LIMIT, "tl_scene_load_gltf: more than 65536 extra lights");

    try {
        context c;
        c.alloc = o.allocator.alloc ? o.allocator : tl_allocator{default_alloc, default_free, nullptr};
        c.logger = o.logger;
        c.path = path;
        size_t slash = c.path.find_last_of('/');
        c.base_dir = slash == std::string::npos ? std::string() : c.path.substr(0, slash ? slash : 1);
        c.normals = o.normals == TL_GLTF_NORMALS_DEFAULT ? TL_GLTF_NORMALS_FLAT : o.normals;
        c.max_texture_pixels = o.max_texture_pixels ? o.max_texture_pixels : (size_t)1 << 26;
        c.max_triangles = o.max_triangles ? o.max_triangles : (size_t)1 << 26;
        c.scene_number = o.scene_number;
        c.extra_lights = o.extra_lights;
        c.seed = o.seed ? o.seed : 1;
        c.default_lights = !o.no_default_lights;
        tl_result r = TL_OK;
        std::string message;
        try {
            *out = load(c, o.allocator);
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
        report(c, message, o.error, o.error_size);
        return r;
    } catch (...) {
        // Only reachable when even the context or the message could not be built (out of memory).
        return early(TL_ERROR_OUT_OF_MEMORY, "tl_scene_load_gltf: out of memory");
    }
}
