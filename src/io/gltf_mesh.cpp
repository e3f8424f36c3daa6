// glTF primitives to the scene's vertex and index arrays. Planning validates and counts (so the
// scene's arrays are allocated once, at their final size); building reads the accessors into the
// primitive's slice, then makes normals and tangents where they are missing or broken.
#include <cmath>

#include "gltf_internal.h"

namespace tl_gltf {
namespace {

std::string role_of(int mesh, int primitive)
{
    return element("meshes", (size_t)mesh) + "." + element("primitives", (size_t)primitive);
}

int attribute(const tinygltf::Primitive &p, const char *name)
{
    auto it = p.attributes.find(name);
    return it == p.attributes.end() ? -1 : it->second;
}

struct views {
    accessor_view pos, nrm, uv, tan, idx;
};

void get_views(const tinygltf::Model &m, const tinygltf::Primitive &pr, const std::string &role, const primitive_plan &p,
               views *v)
{
    v->pos = get_accessor(m, attribute(pr, "POSITION"), TINYGLTF_TYPE_VEC3, false, role + " POSITION");
    auto same_count = [&](const accessor_view &a, const char *what) {
        if (a.count != v->pos.count)
            fail(TL_ERROR_PARSE, element("accessors", (size_t)a.index) + ": " + what + " has " + std::to_string(a.count) +
                                     " elements, POSITION " + std::to_string(v->pos.count));
    };
    if (p.has_normals) {
        v->nrm = get_accessor(m, attribute(pr, "NORMAL"), TINYGLTF_TYPE_VEC3, false, role + " NORMAL");
        same_count(v->nrm, "NORMAL");
    }
    if (p.has_uvs) {
        v->uv = get_accessor(m, attribute(pr, "TEXCOORD_0"), TINYGLTF_TYPE_VEC2, false, role + " TEXCOORD_0");
        same_count(v->uv, "TEXCOORD_0");
    }
    if (p.has_tangents) {
        v->tan = get_accessor(m, attribute(pr, "TANGENT"), TINYGLTF_TYPE_VEC4, false, role + " TANGENT");
        same_count(v->tan, "TANGENT");
    }
    if (p.indexed) v->idx = get_accessor(m, pr.indices, TINYGLTF_TYPE_SCALAR, true, role + " indices");
}

} // namespace

void plan_primitive(const context &c, const tinygltf::Model &m, int mesh, int primitive, primitive_plan *p)
{
    const tinygltf::Primitive &pr = m.meshes[(size_t)mesh].primitives[(size_t)primitive];
    const std::string role = role_of(mesh, primitive);
    p->mesh = mesh;
    p->primitive = primitive;
    p->gltf_material = pr.material;
    int mode = pr.mode < 0 ? TINYGLTF_MODE_TRIANGLES : pr.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES) {
        warn(c, role + ": mode " + std::to_string(mode) + " is not a triangle list; skipped");
        p->skipped = true;
        return;
    }
    if (attribute(pr, "POSITION") < 0) {
        warn(c, role + ": no POSITION; skipped");
        p->skipped = true;
        return;
    }
    p->indexed = pr.indices >= 0;
    p->has_normals = attribute(pr, "NORMAL") >= 0;
    p->has_uvs = attribute(pr, "TEXCOORD_0") >= 0;
    p->has_tangents = attribute(pr, "TANGENT") >= 0;
    views v;
    get_views(m, pr, role, *p, &v);

    size_t n = p->indexed ? v.idx.count : v.pos.count;
    if (n % 3)
        warn(c, role + ": " + std::to_string(n) + (p->indexed ? " indices" : " vertices") +
                    " is not a multiple of 3; the last " + std::to_string(n % 3) + " are ignored");
    p->index_count = n - n % 3;
    // Flat normals need a vertex per corner; a non-indexed primitive already has one.
    p->unweld = p->indexed && !p->has_normals && c.normals != TL_GLTF_NORMALS_SMOOTH;
    p->vertex_count = p->unweld ? p->index_count : v.pos.count;
}

void build_primitive(const context &c, const tinygltf::Model &m, const primitive_plan &p, tl_vertex *vertices,
                     uint32_t *indices)
{
    const tinygltf::Primitive &pr = m.meshes[(size_t)p.mesh].primitives[(size_t)p.primitive];
    const std::string role = role_of(p.mesh, p.primitive);
    views v;
    get_views(m, pr, role, p, &v);
    tl_vertex *vtx = vertices + p.first_vertex;
    uint32_t *ind = indices + p.first_index;
    size_t nv = p.vertex_count, ni = p.index_count;

    // Local indices first (generation works on the primitive alone); made global at the end.
    for (size_t k = 0; k < ni; k++) {
        uint32_t i = p.indexed ? read_index(v.idx, k) : (uint32_t)k;
        if (i >= v.pos.count)
            fail(TL_ERROR_PARSE, element("accessors", (size_t)v.idx.index) + ": index " + std::to_string(i) + " at element " +
                                     std::to_string(k) + " out of range (" + std::to_string(v.pos.count) + " vertices)");
        ind[k] = i;
    }

    size_t bad_uvs = 0;
    for (size_t i = 0; i < nv; i++) {
        size_t src = p.unweld ? ind[i] : i; // unwelded: vertex i is corner i
        tl_vertex &out = vtx[i];
        out = tl_vertex{};
        read_floats(v.pos, src, out.position);
        if (!(std::isfinite(out.position[0]) && std::isfinite(out.position[1]) && std::isfinite(out.position[2])))
            fail(TL_ERROR_PARSE, element("accessors", (size_t)v.pos.index) + ": POSITION element " + std::to_string(src) +
                                     " is not finite");
        if (p.has_normals) read_floats(v.nrm, src, out.normal);
        if (p.has_uvs) {
            read_floats(v.uv, src, out.uv);
            if (!(std::isfinite(out.uv[0]) && std::isfinite(out.uv[1]))) {
                out.uv[0] = out.uv[1] = 0.0f;
                bad_uvs++;
            }
        }
        if (p.has_tangents) read_floats(v.tan, src, out.tangent);
    }
    if (p.unweld)
        for (size_t k = 0; k < ni; k++) ind[k] = (uint32_t)k;
    if (bad_uvs) warn(c, role + ": " + std::to_string(bad_uvs) + " non-finite TEXCOORD_0 values set to 0");

    if (!p.has_normals) {
        if (p.unweld || (!p.indexed && c.normals != TL_GLTF_NORMALS_SMOOTH)) {
            flat_normals(vtx, nv);
        } else {
            vec<float> n = make_vec<float>(c);
            n.resize(3 * nv);
            smooth_normals(vtx, nv, ind, ni, n.data());
            for (size_t i = 0; i < nv; i++)
                for (int k = 0; k < 3; k++) vtx[i].normal[k] = n[3 * i + k];
        }
    } else {
        size_t repaired = repair_normals(c, vtx, nv, ind, ni);
        if (repaired)
            warn(c, role + ": " + std::to_string(repaired) + " zero-length or non-finite normals regenerated");
    }

    if (p.needs_tangents) {
        if (!p.has_uvs) warn(c, role + ": normal map without TEXCOORD_0; the tangent frame is arbitrary");
        size_t bad = p.has_tangents ? fix_tangents(vtx, nv) : 0;
        if (p.has_tangents && bad) warn(c, role + ": " + std::to_string(bad) + " unusable tangents; all regenerated");
        if (!p.has_tangents || bad) generate_tangents(c, vtx, nv, ind, ni);
    } else if (p.has_tangents) {
        fix_tangents(vtx, nv);
    }

    for (size_t k = 0; k < ni; k++) ind[k] += (uint32_t)p.first_vertex;
}

} // namespace tl_gltf
