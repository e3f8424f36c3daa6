// Normals and tangents for primitives that lack them (or carry broken ones). Every vertex leaves
// with a unit normal and, where a normal map needs it, a unit tangent orthogonal to the normal
// with the handedness in w; degenerate input falls back to an arbitrary but valid frame.
#include <cmath>

#include "gltf_internal.h"
#include "gltf_math.h"

namespace tl_gltf {
namespace {

const float fallback_normal[3] = {0.0f, 0.0f, 1.0f};

// Twice the triangle's area times its unit normal (counter-clockwise front, as glTF).
void face_normal(const tl_vertex *v, uint32_t a, uint32_t b, uint32_t c, double out[3])
{
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = (double)v[b].position[k] - v[a].position[k];
        e2[k] = (double)v[c].position[k] - v[a].position[k];
    }
    cross3(e1, e2, out);
}

void set_unit(float dst[3], const double src[3])
{
    double n[3] = {src[0], src[1], src[2]};
    if (!normalize3(n)) {
        for (int k = 0; k < 3; k++) dst[k] = fallback_normal[k];
        return;
    }
    for (int k = 0; k < 3; k++) dst[k] = (float)n[k];
    // float rounding can leave the length a few ULP off 1; one more pass in float settles it
    normalize3(dst);
}

} // namespace

void orthogonal(const float n[3], float out[3])
{
    // The axis least aligned with n, made orthogonal to it.
    float a[3] = {0, 0, 0};
    a[std::fabs(n[0]) < 0.57f ? 0 : std::fabs(n[1]) < 0.57f ? 1 : 2] = 1.0f;
    float d = dot3(a, n);
    for (int k = 0; k < 3; k++) out[k] = a[k] - n[k] * d;
    if (!normalize3(out)) {
        out[0] = 1.0f;
        out[1] = out[2] = 0.0f;
    }
}

void flat_normals(tl_vertex *v, size_t vertex_count)
{
    for (size_t t = 0; t + 2 < vertex_count; t += 3) {
        double n[3];
        face_normal(v, (uint32_t)t, (uint32_t)t + 1, (uint32_t)t + 2, n);
        for (size_t k = 0; k < 3; k++) set_unit(v[t + k].normal, n);
    }
    // Vertices past the last whole triangle belong to none; they still get a unit normal.
    for (size_t i = vertex_count - vertex_count % 3; i < vertex_count; i++)
        for (int k = 0; k < 3; k++) v[i].normal[k] = fallback_normal[k];
}

void smooth_normals(const tl_vertex *v, size_t vertex_count, const uint32_t *idx, size_t index_count, float *out)
{
    // Area-weighted: the unnormalised face normal already carries the triangle's area.
    for (size_t i = 0; i < 3 * vertex_count; i++) out[i] = 0.0f;
    for (size_t t = 0; t + 2 < index_count; t += 3) {
        double n[3];
        face_normal(v, idx[t], idx[t + 1], idx[t + 2], n);
        for (size_t k = 0; k < 3; k++)
            for (int j = 0; j < 3; j++) out[3 * idx[t + k] + j] = to_float(out[3 * idx[t + k] + j] + n[j]);
    }
    for (size_t i = 0; i < vertex_count; i++) {
        double n[3] = {out[3 * i], out[3 * i + 1], out[3 * i + 2]};
        set_unit(out + 3 * i, n);
    }
}

size_t repair_normals(const context &c, tl_vertex *v, size_t vertex_count, const uint32_t *idx, size_t index_count)
{
    size_t bad = 0;
    for (size_t i = 0; i < vertex_count; i++) {
        float *n = v[i].normal;
        // A denormal-length normal is as useless as a zero one.
        if (!(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2])) || !(dot3(n, n) > 1e-24f) ||
            !normalize3(n)) {
            n[0] = n[1] = n[2] = NAN; // marks it for replacement below
            bad++;
        }
    }
    if (!bad) return 0;
    vec<float> smooth = make_vec<float>(c);
    smooth.resize(3 * vertex_count);
    smooth_normals(v, vertex_count, idx, index_count, smooth.data());
    for (size_t i = 0; i < vertex_count; i++)
        if (std::isnan(v[i].normal[0]))
            for (int k = 0; k < 3; k++) v[i].normal[k] = smooth[3 * i + k];
    return bad;
}

size_t fix_tangents(tl_vertex *v, size_t vertex_count)
{
    size_t bad = 0;
    for (size_t i = 0; i < vertex_count; i++) {
        float *t = v[i].tangent;
        const float *n = v[i].normal;
        float d = dot3(t, n);
        float o[3] = {t[0] - n[0] * d, t[1] - n[1] * d, t[2] - n[2] * d};
        if (!std::isfinite(t[3]) || !normalize3(o)) {
            orthogonal(n, o);
            t[3] = 1.0f;
            bad++;
        }
        for (int k = 0; k < 3; k++) t[k] = o[k];
        t[3] = t[3] < 0.0f ? -1.0f : 1.0f;
    }
    return bad;
}

void generate_tangents(const context &c, tl_vertex *v, size_t vertex_count, const uint32_t *idx, size_t index_count)
{
    // Per triangle, the position derivatives along u and v (solving the 2x2 UV system), summed per
    // vertex; then Gram-Schmidt against the normal, and w from which side the v-derivative lies.
    vec<double> acc = make_vec<double>(c);
    acc.assign(6 * vertex_count, 0.0);
    for (size_t t = 0; t + 2 < index_count; t += 3) {
        const tl_vertex &a = v[idx[t]], &b = v[idx[t + 1]], &d = v[idx[t + 2]];
        double e1[3], e2[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = (double)b.position[k] - a.position[k];
            e2[k] = (double)d.position[k] - a.position[k];
        }
        double du1 = (double)b.uv[0] - a.uv[0], dv1 = (double)b.uv[1] - a.uv[1];
        double du2 = (double)d.uv[0] - a.uv[0], dv2 = (double)d.uv[1] - a.uv[1];
        double det = du1 * dv2 - du2 * dv1;
        if (!(std::fabs(det) > 1e-20)) continue; // no UV area: no information about the frame
        double r = 1.0 / det;
        for (size_t k = 0; k < 3; k++) {
            double *s = &acc[6 * idx[t + k]];
            for (int j = 0; j < 3; j++) {
                s[j] += (e1[j] * dv2 - e2[j] * dv1) * r;     // dP/du
                s[3 + j] += (e2[j] * du1 - e1[j] * du2) * r; // dP/dv
            }
        }
    }
    for (size_t i = 0; i < vertex_count; i++) {
        const double *s = &acc[6 * i];
        const float *n = v[i].normal;
        double nd[3] = {n[0], n[1], n[2]};
        double d = dot3(s, nd);
        double t[3] = {s[0] - nd[0] * d, s[1] - nd[1] * d, s[2] - nd[2] * d};
        float *out = v[i].tangent;
        if (normalize3(t)) {
            for (int k = 0; k < 3; k++) out[k] = (float)t[k];
            normalize3(out);
            // A float-rounded tangent may drift off orthogonal by an ULP; project once more.
            float e = dot3(out, n);
            for (int k = 0; k < 3; k++) out[k] -= n[k] * e;
            normalize3(out);
        } else {
            orthogonal(n, out);
        }
        double b[3];
        cross3(nd, t, b);
        out[3] = dot3(b, s + 3) < 0.0 ? -1.0f : 1.0f;
    }
}

} // namespace tl_gltf
