// The load: runs the steps (parse, scene graph, primitives, materials, geometry, lights, camera)
// and assembles the tl_scene. Every failure inside is an exception that the C entry points
// (gltf_api.cpp) turn into a tl_result plus one message line; the scene under construction is
// freed exactly as tl_scene_destroy would free it.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "gltf_internal.h"
#include "gltf_math.h"
#include "scene/validate.h"

namespace tl_gltf {
namespace {

// The same frees in the same order as tl_scene_destroy (src/scene/scene.c), with the same
// allocator, so that a half-built scene leaves nothing behind.
void free_scene(const context &c, tl_scene *s)
{
    if (!s) return;
    if (s->textures)
        for (size_t i = 0; i < s->texture_count; i++)
            free_bytes(c, s->textures[i].rgba, (size_t)s->textures[i].width * s->textures[i].height * 4);
    free_bytes(c, s->textures, s->texture_count * sizeof(tl_texture));
    free_bytes(c, s->vertices, s->vertex_count * sizeof(tl_vertex));
    free_bytes(c, s->indices, s->index_count * sizeof(uint32_t));
    free_bytes(c, s->objects, s->object_count * sizeof(tl_object));
    free_bytes(c, s->materials, s->material_count * sizeof(tl_material));
    free_bytes(c, s->lights, s->light_count * sizeof(tl_light));
    free_bytes(c, s->colors, s->colors ? s->vertex_count * 4 * sizeof(float) : 0);
    free_bytes(c, s->uv1, s->uv1 ? s->vertex_count * 2 * sizeof(float) : 0);
    free_bytes(c, s, sizeof(tl_scene));
}

struct scene_guard {
    const context &c;
    tl_scene *s;
    ~scene_guard() { free_scene(c, s); }
};

// An exact-size array for the scene; NULL for none (tl_scene allows NULL with a zero count).
template <class T> T *scene_array(const context &c, size_t n, const std::string &what)
{
    return n ? static_cast<T *>(alloc_bytes(c, n, sizeof(T), what)) : nullptr;
}

// Extensions whose content we read (or that need nothing from us, as KHR_mesh_quantization:
// integer attributes go through the generic accessor reader).
bool supported_extension(const std::string &e)
{
    return e == "KHR_lights_punctual" || e == "KHR_materials_emissive_strength" || e == "KHR_mesh_quantization" ||
           e == "KHR_materials_unlit" || e == "KHR_materials_clearcoat" || e == "KHR_materials_sheen" ||
           e == "KHR_materials_specular" || e == "KHR_materials_ior";
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

// a + b, or a failure naming `what` when the sum passes `limit` (or size_t).
size_t add_counted(size_t a, size_t b, size_t limit, const std::string &what)
{
    if (b > limit || a > limit - b) fail(TL_ERROR_LIMIT, what);
    return a + b;
}

// Everything between the parsed model and the scene's arrays.
struct load_state {
    explicit load_state(const context &c)
        : g(c), mesh_plan(make_vec<size_t>(c)), plans(make_vec<primitive_plan>(c)), textures(c),
          materials(make_vec<tl_material>(c))
    {
    }
    scene_graph g;
    vec<size_t> mesh_plan;       // per glTF mesh: its first plan, or SIZE_MAX when no node draws it
    vec<primitive_plan> plans;   // one per primitive of every drawn mesh; instances share it
    texture_table textures;
    vec<tl_material> materials;  // in order of first use
    size_t object_total = 0, vertex_total = 0, index_total = 0;
};

// One plan per primitive of every mesh some node instantiates.
void plan_meshes(const context &c, const tinygltf::Model &model, load_state *st)
{
    st->mesh_plan.assign(model.meshes.size(), SIZE_MAX);
    for (const mesh_instance &mi : st->g.meshes) {
        if (st->mesh_plan[(size_t)mi.mesh] != SIZE_MAX) continue;
        st->mesh_plan[(size_t)mi.mesh] = st->plans.size();
        const tinygltf::Mesh &mesh = model.meshes[(size_t)mi.mesh];
        for (size_t p = 0; p < mesh.primitives.size(); p++) {
            primitive_plan plan;
            plan_primitive(c, model, mi.mesh, (int)p, &plan);
            st->plans.push_back(plan);
        }
    }
}

// Materials in order of first use; slot materials.size() of the table is the default one.
void plan_materials(const context &c, const tinygltf::Model &model, load_state *st)
{
    vec<uint32_t> material_slot = make_vec<uint32_t>(c);
    const uint32_t unset = UINT32_MAX;
    material_slot.assign(model.materials.size() + 1, unset);
    for (primitive_plan &p : st->plans) {
        if (p.skipped) continue;
        if (p.gltf_material >= 0 && (size_t)p.gltf_material >= model.materials.size())
            fail(TL_ERROR_PARSE, element("meshes", (size_t)p.mesh) + "." + element("primitives", (size_t)p.primitive) +
                                     ": material " + std::to_string(p.gltf_material) + " out of range (" +
                                     std::to_string(model.materials.size()) + " materials)");
        size_t slot = p.gltf_material >= 0 ? (size_t)p.gltf_material : model.materials.size();
        if (material_slot[slot] == unset) {
            st->materials.push_back(convert_material(c, model, p.gltf_material, &st->textures));
            material_slot[slot] = (uint32_t)(st->materials.size() - 1);
        }
        p.material = material_slot[slot];
        p.needs_tangents = st->materials[p.material].normal_map != 0 && p.draws == TL_PRIMITIVE_TRIANGLES;
    }
}

// Objects and the drawn-triangle limit, which primitives need a mirrored index copy, and each
// primitive's slice of the shared arrays. Every sum is checked: indices are 32-bit, and so are
// the objects' index ranges, and a count may be anything up to 2^64 - 1 in the JSON.
void plan_geometry(const context &c, const tinygltf::Model &model, load_state *st)
{
    const std::string over_triangles = "more than the limit of " + std::to_string(c.max_triangles) + " triangles";
    const std::string over_32 = "more than 2^32 - 1 vertices or indices";
    size_t drawn = 0;
    for (const mesh_instance &mi : st->g.meshes) {
        size_t first = st->mesh_plan[(size_t)mi.mesh];
        for (size_t p = 0; p < model.meshes[(size_t)mi.mesh].primitives.size(); p++) {
            primitive_plan &pl = st->plans[first + p];
            if (pl.skipped || !pl.index_count) continue;
            st->object_total++;
            // points and lines count as triangles: one per point or line
            drawn = add_counted(drawn, pl.index_count / tl__primitive_indices(pl.draws), c.max_triangles, over_triangles);
            if (mirrors(mi.world) && pl.draws == TL_PRIMITIVE_TRIANGLES) pl.mirrored = true;
        }
    }
    for (primitive_plan &p : st->plans) {
        if (p.skipped) continue;
        p.first_vertex = st->vertex_total;
        p.first_index = st->index_total;
        st->vertex_total = add_counted(st->vertex_total, p.vertex_count, UINT32_MAX, over_32);
        st->index_total = add_counted(st->index_total, p.index_count, UINT32_MAX, over_32);
        if (p.mirrored) {
            p.mirrored_first_index = st->index_total;
            st->index_total = add_counted(st->index_total, p.index_count, UINT32_MAX, over_32);
        }
    }
    // Vertices need not be referenced, and an accessor without a buffer view is all zeros at no
    // cost in the file: without this bound a few bytes of JSON could ask for gigabytes.
    if (st->vertex_total / 3 > c.max_triangles)
        fail(TL_ERROR_LIMIT, std::to_string(st->vertex_total) + " vertices: more than 3 per triangle of the limit of " +
                                 std::to_string(c.max_triangles));
}

// Whether the scene keeps vertex colours (some drawn primitive has COLOR_0) and a second UV set
// (some drawn primitive has TEXCOORD_1 and its material reads it).
void plan_extras(const load_state &st, bool *colors, bool *uv1)
{
    *colors = *uv1 = false;
    for (const primitive_plan &p : st.plans) {
        if (p.skipped || !p.index_count) continue;
        *colors = *colors || p.has_colors;
        *uv1 = *uv1 || (p.has_uv1 && st.materials[p.material].uv1_maps != 0);
    }
}

// The shared vertex and index arrays (with the optional colours and second UV set), and the
// mirrored index copies.
void build_geometry(const context &c, const tinygltf::Model &model, const load_state &st, tl_scene *s)
{
    s->vertices = scene_array<tl_vertex>(c, st.vertex_total, std::to_string(st.vertex_total) + " vertices");
    s->vertex_count = st.vertex_total;
    s->indices = scene_array<uint32_t>(c, st.index_total, std::to_string(st.index_total) + " indices");
    s->index_count = st.index_total;
    bool colors, uv1;
    plan_extras(st, &colors, &uv1);
    if (colors) s->colors = scene_array<float>(c, 4 * st.vertex_total, "vertex colours");
    if (uv1) s->uv1 = scene_array<float>(c, 2 * st.vertex_total, "TEXCOORD_1");
    vertex_extras extras;
    extras.colors = s->colors;
    extras.uv1 = s->uv1;
    for (const primitive_plan &p : st.plans) {
        if (p.skipped) continue;
        build_primitive(c, model, p, s->vertices, s->indices, extras);
        if (!p.mirrored) continue;
        const uint32_t *src = s->indices + p.first_index;
        uint32_t *dst = s->indices + p.mirrored_first_index;
        for (size_t t = 0; t + 2 < p.index_count; t += 3) {
            dst[t] = src[t];
            dst[t + 1] = src[t + 2];
            dst[t + 2] = src[t + 1];
        }
    }
}

// One object per drawn primitive per instance, with world bounds; the scene's bounds.
void build_objects(const context &c, const tinygltf::Model &model, const load_state &st, tl_scene *s)
{
    s->objects = scene_array<tl_object>(c, st.object_total, std::to_string(st.object_total) + " objects");
    float bmin[3] = {0, 0, 0}, bmax[3] = {0, 0, 0};
    for (const mesh_instance &mi : st.g.meshes) {
        size_t first = st.mesh_plan[(size_t)mi.mesh];
        for (size_t p = 0; p < model.meshes[(size_t)mi.mesh].primitives.size(); p++) {
            const primitive_plan &pl = st.plans[first + p];
            if (pl.skipped || !pl.index_count) continue;
            tl_object &o = s->objects[s->object_count];
            o = tl_object{};
            o.first_index = (uint32_t)(mirrors(mi.world) ? pl.mirrored_first_index : pl.first_index);
            o.index_count = (uint32_t)pl.index_count;
            o.material = pl.material;
            o.primitive = pl.draws;
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
}

// Materials and textures move into the scene (which then owns the pixels); lights and camera.
void finish_scene(const context &c, const tinygltf::Model &model, load_state *st, tl_scene *s)
{
    s->materials = scene_array<tl_material>(c, st->materials.size(), "materials");
    if (!st->materials.empty()) std::memcpy(s->materials, st->materials.data(), st->materials.size() * sizeof(tl_material));
    s->material_count = st->materials.size();
    vec<tl_texture> &tex = st->textures.textures;
    s->textures = scene_array<tl_texture>(c, tex.size(), "textures");
    if (!tex.empty()) {
        std::memcpy(s->textures, tex.data(), tex.size() * sizeof(tl_texture));
        s->texture_count = tex.size();
        tex.clear(); // the scene owns the pixels now
    }

    vec<tl_light> lights = make_vec<tl_light>(c);
    vec<signed char> flags = make_vec<signed char>(c);
    convert_lights(c, model, st->g, &lights, &flags);
    if (lights.empty() && c.default_lights) {
        default_rig(s->bounds_min, s->bounds_max, &lights);
        drop_unrenderable(c, "default_rig[", 0, &lights);
    }
    size_t first_extra = lights.size();
    extra_lights(c, s->bounds_min, s->bounds_max, &lights);
    drop_unrenderable(c, "extra_lights[", first_extra, &lights);
    shadow_rule(c, flags, &lights);
    s->lights = scene_array<tl_light>(c, lights.size(), std::to_string(lights.size()) + " lights");
    if (!lights.empty()) std::memcpy(s->lights, lights.data(), lights.size() * sizeof(tl_light));
    s->light_count = lights.size();

    make_camera(c, model, st->g, s->bounds_min, s->bounds_max, s, &s->camera);
    for (float &a : s->ambient) a = ambient;
}

} // namespace

tl_scene *load_scene(context &c, const unsigned char *data, size_t size, const tl_allocator &user_allocator)
{
    budget_hold parsed(c); // what tinygltf holds; released after the model below is destroyed
    tinygltf::Model model;
    parse_gltf(c, data, size, &model, &parsed);
    check_extensions(c, model);
    load_state st(c);
    walk_scene(c, model, &st.g);
    plan_meshes(c, model, &st);
    plan_materials(c, model, &st);
    plan_geometry(c, model, &st);

    scene_guard sg{c, static_cast<tl_scene *>(alloc_bytes(c, 1, sizeof(tl_scene), "scene"))};
    *sg.s = tl_scene{};
    build_geometry(c, model, st, sg.s);
    build_objects(c, model, st, sg.s);
    finish_scene(c, model, &st, sg.s);
    sg.s->allocator = user_allocator;
    tl_scene *s = sg.s;
    sg.s = nullptr;
    return s;
}

} // namespace tl_gltf
