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
    accessor_view pos, nrm, uv, tan, idx, col, uv1;
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
    if (p.has_colors) {
        int a = attribute(pr, "COLOR_0");
        bool vec4 = a >= 0 && (size_t)a < m.accessors.size() && m.accessors[(size_t)a].type == TINYGLTF_TYPE_VEC4;
        v->col = get_accessor(m, a, vec4 ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3, false, role + " COLOR_0");
        same_count(v->col, "COLOR_0");
    }
    if (p.has_uv1) {
        v->uv1 = get_accessor(m, attribute(pr, "TEXCOORD_1"), TINYGLTF_TYPE_VEC2, false, role + " TEXCOORD_1");
        same_count(v->uv1, "TEXCOORD_1");
    }
    if (p.indexed) v->idx = get_accessor(m, pr.indices, TINYGLTF_TYPE_SCALAR, true, role + " indices");
}

// What each glTF mode draws: the scene's primitive, and the indices of one element of its list.
struct mode_info {
    uint32_t primitive;
    size_t per_element;
};
bool mode_of(int mode, mode_info *out)
{
    static const mode_info table[7] = {
        {TL_PRIMITIVE_POINTS, 1},    {TL_PRIMITIVE_LINES, 2},     {TL_PRIMITIVE_LINES, 2}, {TL_PRIMITIVE_LINES, 2},
        {TL_PRIMITIVE_TRIANGLES, 3}, {TL_PRIMITIVE_TRIANGLES, 3}, {TL_PRIMITIVE_TRIANGLES, 3}};
    if (mode < 0 || mode > 6) return false;
    *out = table[mode];
    return true;
}

// The primitive's elements as a list: strips and fans become triangle lists in the glTF
// specification's vertex order (strip triangle i: v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]; fan
// triangle i: v[i + 1], v[i + 2], v[0]), which keeps every triangle's winding; line strips and
// loops become line lists. `src(k)` is the k-th vertex of the glTF primitive (its index, or k);
// `emit` takes each index of the list. A strip or fan triangle that repeats an index (the way
// strips are joined) draws nothing and is dropped; lists keep what they are given, and an
// incomplete last element is left out. Returns the indices emitted.
template <class Src, class Emit> size_t assemble(int mode, size_t n, Src src, Emit emit)
{
    size_t out = 0;
    auto put = [&](uint32_t i) {
        emit(out, i);
        out++;
    };
    auto triangle = [&](uint32_t a, uint32_t b, uint32_t c) {
        if (a == b || b == c || a == c) return;
        put(a), put(b), put(c);
    };
    switch (mode) {
    case TINYGLTF_MODE_POINTS:
        for (size_t k = 0; k < n; k++) put(src(k));
        break;
    case TINYGLTF_MODE_LINE:
        for (size_t k = 0; k + 1 < n; k += 2) put(src(k)), put(src(k + 1));
        break;
    case TINYGLTF_MODE_LINE_LOOP:
    case TINYGLTF_MODE_LINE_STRIP:
        for (size_t k = 0; k + 1 < n; k++) put(src(k)), put(src(k + 1));
        if (mode == TINYGLTF_MODE_LINE_LOOP && n > 2) put(src(n - 1)), put(src(0));
        break;
    case TINYGLTF_MODE_TRIANGLE_STRIP:
        for (size_t i = 0; i + 2 < n; i++) triangle(src(i), src(i + 1 + i % 2), src(i + 2 - i % 2));
        break;
    case TINYGLTF_MODE_TRIANGLE_FAN:
        for (size_t i = 0; i + 2 < n; i++) triangle(src(i + 1), src(i + 2), src(0));
        break;
    default:
        for (size_t k = 0; k + 2 < n; k += 3) put(src(k)), put(src(k + 1)), put(src(k + 2));
        break;
    }
    return out;
}

// How many indices assemble() emits for `n` glTF vertices, computed without reading them where no
// element can be dropped (counts come from the JSON: up to 2^64 - 1). Only indexed strips and fans
// read their indices (bounded by the bytes of their buffer; an accessor without data is all
// zeros: every triangle repeats an index). A count past size_t saturates; plan_geometry refuses it.
template <class Src> size_t count_indices(const primitive_plan &p, const views &v, size_t n, Src src)
{
    bool fans = p.mode == TINYGLTF_MODE_TRIANGLE_STRIP || p.mode == TINYGLTF_MODE_TRIANGLE_FAN;
    if (fans && p.indexed)
        return v.idx.data ? assemble(p.mode, n, src, [](size_t, uint32_t) {}) : 0;
    size_t elements = 0, per = 1;
    switch (p.mode) {
    case TINYGLTF_MODE_POINTS: elements = n; break;
    case TINYGLTF_MODE_LINE: elements = n / 2, per = 2; break;
    case TINYGLTF_MODE_LINE_STRIP: elements = n ? n - 1 : 0, per = 2; break;
    case TINYGLTF_MODE_LINE_LOOP: elements = n > 2 ? n : n ? n - 1 : 0, per = 2; break;
    case TINYGLTF_MODE_TRIANGLE_STRIP:
    case TINYGLTF_MODE_TRIANGLE_FAN: elements = n > 2 ? n - 2 : 0, per = 3; break;
    default: elements = n / 3, per = 3; break;
    }
    return elements > SIZE_MAX / per ? SIZE_MAX / per * per : elements * per; // plan_geometry refuses it
}

// The k-th vertex of the glTF primitive, checked against its vertices.
uint32_t source_index(const primitive_plan &p, const views &v, size_t k)
{
    if (!p.indexed) return (uint32_t)k;
    uint32_t i = read_index(v.idx, k);
    if (i >= v.pos.count)
        fail(TL_ERROR_PARSE, element("accessors", (size_t)v.idx.index) + ": index " + std::to_string(i) + " at element " +
                                 std::to_string(k) + " out of range (" + std::to_string(v.pos.count) + " vertices)");
    return i;
}

} // namespace

void plan_primitive(const context &c, const tinygltf::Model &m, int mesh, int primitive, primitive_plan *p)
{
    const tinygltf::Primitive &pr = m.meshes[(size_t)mesh].primitives[(size_t)primitive];
    const std::string role = role_of(mesh, primitive);
    p->mesh = mesh;
    p->primitive = primitive;
    p->gltf_material = pr.material;
    p->mode = pr.mode < 0 ? TINYGLTF_MODE_TRIANGLES : pr.mode;
    mode_info mi;
    if (!mode_of(p->mode, &mi)) {
        warn(c, role + ": mode " + std::to_string(p->mode) + " is not a glTF primitive mode; skipped");
        p->skipped = true;
        return;
    }
    if (attribute(pr, "POSITION") < 0) {
        warn(c, role + ": no POSITION; skipped");
        p->skipped = true;
        return;
    }
    p->draws = mi.primitive;
    p->indexed = pr.indices >= 0;
    p->has_normals = attribute(pr, "NORMAL") >= 0;
    p->has_uvs = attribute(pr, "TEXCOORD_0") >= 0;
    // points and lines have no tangent frame: their normal maps see a zero tangent (material.glsl)
    p->has_tangents = attribute(pr, "TANGENT") >= 0 && mi.primitive == TL_PRIMITIVE_TRIANGLES;
    p->has_colors = attribute(pr, "COLOR_0") >= 0;
    p->has_uv1 = attribute(pr, "TEXCOORD_1") >= 0;
    views v;
    get_views(m, pr, role, *p, &v);

    size_t n = p->indexed ? v.idx.count : v.pos.count;
    bool list = p->mode == TINYGLTF_MODE_TRIANGLES || p->mode == TINYGLTF_MODE_LINE;
    if (list && n % mi.per_element)
        warn(c, role + ": " + std::to_string(n) + (p->indexed ? " indices" : " vertices") + " is not a multiple of " +
                    std::to_string(mi.per_element) + "; the last " + std::to_string(n % mi.per_element) + " are ignored");
    p->index_count = count_indices(*p, v, n, [&](size_t k) { return source_index(*p, v, k); });
    if (!list && n && !p->index_count)
        warn(c, role + ": mode " + std::to_string(p->mode) + " with " + std::to_string(n) + " vertices draws nothing");
    // Flat normals need a vertex per triangle corner; a non-indexed list already has one.
    bool flat = mi.primitive == TL_PRIMITIVE_TRIANGLES && !p->has_normals && c.normals != TL_GLTF_NORMALS_SMOOTH;
    p->unweld = flat && (p->indexed || p->mode != TINYGLTF_MODE_TRIANGLES);
    p->vertex_count = p->unweld ? p->index_count : v.pos.count;
}

namespace {

// Position, normal, UVs and tangent of glTF vertex `src` into `out`; returns whether its UVs were
// not finite (then set to 0).
bool read_vertex(const primitive_plan &p, const views &v, size_t src, tl_vertex *out)
{
    *out = tl_vertex{};
    read_floats(v.pos, src, out->position);
    if (!(std::isfinite(out->position[0]) && std::isfinite(out->position[1]) && std::isfinite(out->position[2])))
        fail(TL_ERROR_PARSE, element("accessors", (size_t)v.pos.index) + ": POSITION element " + std::to_string(src) +
                                 " is not finite");
    if (p.has_normals) read_floats(v.nrm, src, out->normal);
    if (p.has_tangents) read_floats(v.tan, src, out->tangent);
    if (!p.has_uvs) return false;
    read_floats(v.uv, src, out->uv);
    if (std::isfinite(out->uv[0]) && std::isfinite(out->uv[1])) return false;
    out->uv[0] = out->uv[1] = 0.0f;
    return true;
}

// COLOR_0 (RGB or RGBA, alpha 1) clamped to [0, 1] (non-finite: 1) and TEXCOORD_1 (non-finite: 0;
// without it, the first UV set) of glTF vertex `src`. Returns the values replaced.
size_t read_extras(const primitive_plan &p, const views &v, size_t src, const tl_vertex &vtx, float *rgba, float *uv1)
{
    size_t bad = 0;
    if (rgba) {
        float c[4] = {1, 1, 1, 1};
        if (p.has_colors) read_floats(v.col, src, c);
        for (int k = 0; k < 4; k++) {
            bad += !std::isfinite(c[k]);
            rgba[k] = !std::isfinite(c[k]) ? 1.0f : c[k] < 0.0f ? 0.0f : c[k] > 1.0f ? 1.0f : c[k];
        }
    }
    if (uv1) {
        float t[2] = {vtx.uv[0], vtx.uv[1]};
        if (p.has_uv1) read_floats(v.uv1, src, t);
        for (int k = 0; k < 2; k++) {
            bad += !std::isfinite(t[k]);
            uv1[k] = std::isfinite(t[k]) ? t[k] : 0.0f;
        }
    }
    return bad;
}

// Points and lines: given normals made unit; a missing, zero or non-finite one stays zero, which
// the renderer shades as facing the viewer.
void point_line_normals(tl_vertex *vtx, size_t nv)
{
    for (size_t i = 0; i < nv; i++) {
        float *n = vtx[i].normal;
        double len = std::sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]);
        bool ok = std::isfinite(len) && len > 1e-30;
        for (int k = 0; k < 3; k++) n[k] = ok ? (float)(n[k] / len) : 0.0f;
    }
}

// Normals and tangents of a triangle primitive: made where missing, repaired where broken.
void triangle_frames(const context &c, const primitive_plan &p, const std::string &role, tl_vertex *vtx, size_t nv,
                     const uint32_t *ind, size_t ni)
{
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
}

} // namespace

void build_primitive(const context &c, const tinygltf::Model &m, const primitive_plan &p, tl_vertex *vertices,
                     uint32_t *indices, const vertex_extras &extras)
{
    const tinygltf::Primitive &pr = m.meshes[(size_t)p.mesh].primitives[(size_t)p.primitive];
    const std::string role = role_of(p.mesh, p.primitive);
    views v;
    get_views(m, pr, role, p, &v);
    tl_vertex *vtx = vertices + p.first_vertex;
    uint32_t *ind = indices + p.first_index;
    size_t nv = p.vertex_count, ni = p.index_count;

    // Local indices first (generation works on the primitive alone); made global at the end.
    size_t n = p.indexed ? v.idx.count : v.pos.count;
    assemble(p.mode, n, [&](size_t k) { return source_index(p, v, k); }, [&](size_t k, uint32_t i) { ind[k] = i; });

    size_t bad_uvs = 0, bad_extras = 0;
    float *rgba = extras.colors ? extras.colors + 4 * p.first_vertex : nullptr;
    float *uv1 = extras.uv1 ? extras.uv1 + 2 * p.first_vertex : nullptr;
    for (size_t i = 0; i < nv; i++) {
        size_t src = p.unweld ? ind[i] : i; // unwelded: vertex i is corner i
        bad_uvs += read_vertex(p, v, src, &vtx[i]);
        bad_extras += read_extras(p, v, src, vtx[i], rgba ? rgba + 4 * i : nullptr, uv1 ? uv1 + 2 * i : nullptr);
    }
    if (p.unweld)
        for (size_t k = 0; k < ni; k++) ind[k] = (uint32_t)k;
    if (bad_uvs) warn(c, role + ": " + std::to_string(bad_uvs) + " non-finite TEXCOORD_0 values set to 0");
    if (bad_extras) warn(c, role + ": " + std::to_string(bad_extras) + " non-finite COLOR_0 or TEXCOORD_1 values replaced");

    if (p.draws == TL_PRIMITIVE_TRIANGLES) triangle_frames(c, p, role, vtx, nv, ind, ni);
    else point_line_normals(vtx, nv);

    for (size_t k = 0; k < ni; k++) ind[k] += (uint32_t)p.first_vertex;
}

} // namespace tl_gltf
