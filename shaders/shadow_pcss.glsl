// Percentage-closer soft shadows (docs/shadows.md, "Soft shadows (PCSS)"), included by shadow.glsl
// with TL_PCSS. A blocker search over the view's tile gives the blockers' mean distance from
// the light; the penumbra's radius at the point follows from the light's size (sv.depth.z, in
// texels); a PCF of that radius (at least the PCF radius, at most u_shadow_flags.y) follows. The
// point is biased as for the PCF radius and every tap compares against the receiver's plane (its
// depth slope in the atlas), so a wide kernel neither self-shadows nor shifts the shadow.
// Every read stays one texel inside the view's tile: nothing bleeds in from a neighbouring view.
#ifndef TL_SHADOW_PCSS_GLSL
#define TL_SHADOW_PCSS_GLSL

#define TL_SHADOW_PCSS_TAPS 10 // most bilinear taps per axis of the kernel

// The light-space distance of a stored depth d.
float tl_shadow_distance(tl_shadow_view sv, float d)
{
    float k = sv.depth.x * d + sv.depth.y;
    return sv.depth.w != 0.0 ? 1.0 / k : k;
}

// The radius, in texels at the receiver, of the cone from a receiver at distance zr to the light's
// disc where it crosses blockers at distance zb (similar triangles; perspective views measure
// the tile in angle, so the receiver's and the blocker's distances both divide).
float tl_shadow_penumbra(tl_shadow_view sv, float zb, float zr)
{
    float r = sv.depth.z * max(zr - zb, 0.0);
    return sv.depth.w != 0.0 ? r / max(zb * zr, 1e-30) : r;
}

// The view's atlas uv (xy) and reference depth (z) of view-space q; w < 0 behind a perspective view.
vec4 tl_shadow_project(tl_shadow_view sv, vec3 q)
{
    vec4 c = sv.m * vec4(q, 1.0);
    if (c.w <= 0.0) return vec4(0.0, 0.0, 0.0, -1.0);
    vec3 ndc = c.xyz / c.w;
    float ref = ndc.z;
    return vec4(sv.rect.xy + (ndc.xy * 0.5 + 0.5) * sv.rect.zw, ref, 1.0);
}

// One bilinear compare tap (what a depth-compare sampler returns), from the four texels' depths.
float tl_shadow_tap(vec2 uv, float ref)
{
    vec4 d = textureGather(u_shadow_depth, uv);
    vec4 lit = vec4(greaterThanEqual(vec4(ref), d)); // reversed depth: nearer is greater
    vec2 f = fract(uv / u_shadow_params.x - 0.5);
    return mix(mix(lit.w, lit.z, f.x), mix(lit.x, lit.y, f.x), f.y);
}

// The receiver's plane in the atlas: the reference depth's change per unit of atlas uv along the
// plane through q with normal n (q moved `step` along two tangents and projected: window depth is
// affine in the view's xy over a plane, so this is exact for any step); 0 where the plane is seen
// edge-on from the light. A tap at uv offset o compares against ref + dot(slope, o).
vec2 tl_shadow_slope(tl_shadow_view sv, vec3 q, vec3 n, vec4 a, float step)
{
    vec3 t1 = normalize(cross(n, abs(n.x) < 0.6 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0))), t2 = cross(n, t1);
    vec4 a1 = tl_shadow_project(sv, q + t1 * step), a2 = tl_shadow_project(sv, q + t2 * step);
    vec3 d1 = a1.xyz - a.xyz, d2 = a2.xyz - a.xyz;
    float det = d1.x * d2.y - d1.y * d2.x;
    if (a1.w < 0.0 || a2.w < 0.0 || abs(det) <= 1e-12 * (dot(d1.xy, d1.xy) + dot(d2.xy, d2.xy))) return vec2(0.0);
    return vec2(d1.z * d2.y - d2.z * d1.y, d2.z * d1.x - d1.z * d2.x) / det;
}

// The reference for a tap at uv: the normal offset (for the PCF radius) covers the taps within that
// radius of a.xy; beyond it the reference follows the receiver's plane for the excess distance.
float tl_shadow_plane(vec4 a, vec2 slope, vec2 uv)
{
    vec2 o = uv - a.xy;
    float len = length(o), inner = u_shadow_params.y * u_shadow_params.x;
    return len > inner ? a.z + dot(slope, o) * (1.0 - inner / len) : a.z;
}

// The mean light distance of the texels in front of the receiver's plane within `radius` texels of
// uv (4 x 4 gathers, 64 texels); -1 when there is none.
float tl_shadow_blockers(tl_shadow_view sv, vec4 a, vec2 slope, float radius, vec2 lo, vec2 hi)
{
    float sum = 0.0, count = 0.0, step = radius / 1.5 * u_shadow_params.x;
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            vec2 uv = clamp(a.xy + (vec2(x, y) - 1.5) * step, lo, hi);
            float ref = tl_shadow_plane(a, slope, uv);
            vec4 d = textureGather(u_shadow_depth, uv);
            vec4 b = vec4(greaterThan(d, vec4(ref)));
            for (int k = 0; k < 4; k++) sum += b[k] * tl_shadow_distance(sv, d[k]);
            count += dot(b, vec4(1.0));
        }
    return count > 0.0 ? sum / count : -1.0;
}

// A PCF of radius r texels (r may be fractional): up to TL_SHADOW_PCSS_TAPS^2 bilinear taps on a
// grid over the disc of radius r (taps outside it are skipped), each against the receiver's plane.
float tl_shadow_disc(vec4 a, vec2 slope, float r, vec2 lo, vec2 hi)
{
    int taps = clamp(2 * int(ceil(r)), 2, TL_SHADOW_PCSS_TAPS);
    float step = 2.0 * r / float(taps), centre = 0.5 * float(taps - 1), sum = 0.0, count = 0.0;
    for (int y = 0; y < taps; y++)
        for (int x = 0; x < taps; x++) {
            vec2 o = (vec2(x, y) - centre) * step;
            if (dot(o, o) > r * r) continue;
            vec2 uv = clamp(a.xy + o * u_shadow_params.x, lo, hi);
            sum += tl_shadow_tap(uv, tl_shadow_plane(a, slope, uv));
            count += 1.0;
        }
    return sum / max(count, 1.0);
}

// PCSS for view sv whose clip w at p is w. The point is biased as for the PCF radius (the normal
// offset covers the bilinear footprint and that kernel); every tap further out compares against
// the receiver's plane. The blocker search covers the penumbra of blockers at the view's near
// plane, clamped to the largest radius; with no blocker found the kernel is the PCF radius.
float tl_shadow_pcss(tl_shadow_view sv, float w, vec3 p, vec3 n, vec3 l)
{
    float t = u_shadow_params.x, rmin = u_shadow_params.y, rmax = float(u_shadow_flags.y);
    vec2 lo = sv.rect.xy + vec2(t), hi = sv.rect.xy + sv.rect.zw - vec2(t);
    vec3 q = tl_shadow_biased(sv, w, p, n, l, rmin);
    vec4 a = tl_shadow_project(sv, q);
    if (a.w < 0.0) return 1.0;
    vec2 slope = tl_shadow_slope(sv, q, n, a, rmax * sv.texel.x * max(w, 0.0));
    float zr = tl_shadow_distance(sv, a.z), near = tl_shadow_distance(sv, 1.0);
    float search = clamp(tl_shadow_penumbra(sv, near, zr), rmin, rmax);
    float zb = tl_shadow_blockers(sv, a, slope, search, lo, hi);
    float r = zb < 0.0 ? rmin : clamp(tl_shadow_penumbra(sv, zb, zr), rmin, rmax);
    return tl_shadow_disc(a, slope, r, lo, hi);
}

#endif
