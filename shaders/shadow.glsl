// Shadow lookup (docs/shadows.md), included by every lighting pass when the plan has TL_SHADOWS.
// A casting light's slot (tl_light_data.cos_inner.z, the volumes' colour alpha) is its record + 1;
// the record names its views in the atlas: one spot map, six cube faces or four cascades. The
// lookup point is moved off the surface by a bias derived from the texel's world size, the PCF
// kernel's reach and the two depth formats' quantisation (never a tuned constant):
//   along n: (r + 1) w sin(theta) + (R + 1) w e_n + e_gbuffer(z),   along l: e_atlas(w)
// where w is the texel's world size at the point, r the kernel radius, theta the angle between n
// and the map's depth axis (l for cascades; tl_shadow_biased), R the largest kernel radius, e_n the
// stored normal's angular error, e_gbuffer the rebuilt position's error and e_atlas the atlas
// depth's quantum. With TL_PCSS the view is filtered by shadow_pcss.glsl instead of the fixed PCF
// kernel.
#ifndef TL_SHADOW_GLSL
#define TL_SHADOW_GLSL

#include "frame.glsl"

struct tl_shadow_view {
    mat4 m;      // view space to the view's clip space
    vec4 rect;   // atlas uv offset (xy) and scale (zw) of the view's tile
    vec4 texel;  // x: texel world size per clip w; y, z: atlas depth quantum c0 + c1 w (world); w: e_arith's constant part
    vec4 depth;  // PCSS: stored depth d to light distance z (w = 1: 1/z = x d + y; else z = x d + y), z: light size in texels
};
struct tl_shadow_light {
    uvec4 info;  // first view, view count, kind (1 point, 2 spot, 3 directional), 0
    vec4 fade;   // x: strength 0..1 (a light losing or gaining its map fades), y: tile side in texels
    vec4 splits; // cascades: the view depth where each ends
};
// A uniform block, not a storage buffer: on llvmpipe the lookup's per-lane storage loads were most
// of the shadows' cost (docs/shadows.md, Cost); 48 + 64 x 48 + 384 x 112 bytes = 45 KiB.
layout(std140, binding = TL_UBO_SHADOWS) uniform tl_shadow_block {
    vec4 u_shadow_params;   // 1 / atlas side, PCF radius, G-buffer error: a z + b z^2 (a, b)
    uvec4 u_shadow_flags;   // y: PCSS's largest radius in texels (the atlas: reversed depth, compare GEQUAL)
    vec4 u_shadow_bias;     // x: the lighting normal's angular error bound, radians (its storage)
    tl_shadow_light tl_shadow_lights[TL_SHADOW_LIGHTS];
    tl_shadow_view tl_shadow_views[TL_SHADOW_VIEWS];
};
#ifdef TL_PCSS
// PCSS reads the atlas's depth values (a sampler without compare, shadows.c) and compares itself
layout(binding = TL_UNIT_SHADOW_ATLAS) uniform sampler2D u_shadow_depth;
#else
layout(binding = TL_UNIT_SHADOW_ATLAS) uniform sampler2DShadow u_shadow_atlas;


// The view's PCF result at view-space point q (already biased); 1 outside the tile. One tap site
// for every radius: (2 r)^2 bilinear compare taps half a texel off the grid cover the (2 r + 1)^2
// texels a tent-weighted r-texel kernel reads (r = 0: one tap, at the point).
float tl_shadow_sample(tl_shadow_view sv, vec3 q)
{
    vec4 c = sv.m * vec4(q, 1.0);
    if (c.w <= 0.0) return 1.0;
    vec3 ndc = c.xyz / c.w;
    float ref = ndc.z;
    vec2 uv = sv.rect.xy + (ndc.xy * 0.5 + 0.5) * sv.rect.zw;
    float t = u_shadow_params.x;
    vec2 lo = sv.rect.xy + vec2(0.5 * t), hi = sv.rect.xy + sv.rect.zw - vec2(0.5 * t);
    int taps = max(2 * int(u_shadow_params.y), 1);
    float centre = 0.5 * float(taps - 1), sum = 0.0;
    for (int y = 0; y < taps; y++)
        for (int x = 0; x < taps; x++)
            sum += texture(u_shadow_atlas, vec3(clamp(uv + (vec2(x, y) - centre) * t, lo, hi), ref));
    return sum / float(taps * taps);
}
#endif

// p biased for view sv whose clip w at p is w for a kernel of radius r texels: n and l unit, view
// space (l towards the light). theta is the angle between n and the map's depth axis: the light
// direction for cascades, the view's axis (clip w's gradient, a unit vector) for spot maps and cube
// faces, whose stored depth is measured along that axis and not along the ray to the light: there a
// texel x across the map meets the receiver's plane x sin(theta) nearer in that depth however steep
// the ray (a spot tilted over a floor: the ray near the vertical, the axis far from it).
vec3 tl_shadow_biased(tl_shadow_view sv, float w, vec3 p, vec3 n, vec3 l, float r)
{
    w = max(w, 0.0);
    float texel = sv.texel.x * w;
    vec3 axis = vec3(sv.m[0].w, sv.m[1].w, sv.m[2].w); // 0 for an orthographic view
    float cos_t = dot(axis, axis) > 0.0 ? min(abs(dot(n, axis)), 1.0) : clamp(dot(n, l), 0.0, 1.0);
    float sin_t = sqrt(1.0 - cos_t * cos_t);
    // the rebuilt position errs along the camera ray, by e_z (p / z): along n that is e_z |p.n| / z
    float z = -p.z;
    float e_gbuffer = (u_shadow_params.z + u_shadow_params.w * z) * abs(dot(p, n));
    // the light distance's float arithmetic, 2^-24 times 4 (a matrix row's terms) times the size of
    // the coordinates it comes from: the lookup's camera space (|p| + |eye - camera|), the shadow
    // pass's model matrix (|p_world|) and projection (|p_world| + |eye|), |p_world| <= |p| + |camera|:
    // 2^-22 (3 |p| + 2 |eye| + 3 |camera|)
    float e_arith = exp2(-22.0) * (3.0 * length(p) + sv.texel.w);
    float e_atlas = sv.texel.y + sv.texel.z * w + e_arith;
    // the stored normal may be off the surface's by u_shadow_bias.x radians: the plane within the
    // largest kernel's reach (PCSS extends it beyond r) may lie that much steeper
    float reach = (max(r, float(u_shadow_flags.y)) + 1.0) * texel;
    return p + n * ((r + 1.0) * texel * sin_t + reach * u_shadow_bias.x + e_gbuffer) + l * e_atlas;
}
#ifdef TL_PCSS
#include "shadow_pcss.glsl"
#endif

// The cascade of view depth z for a directional light's split ends (4: beyond the last) and, over
// the last 10 % of its slice, the blend weight towards the next cascade (0 before).
uint tl_shadow_cascade(vec4 splits, float z, out float blend)
{
    blend = 0.0;
    if (z >= splits.w) return 4u;
    uint i = z < splits.x ? 0u : z < splits.y ? 1u : z < splits.z ? 2u : 3u;
    float end = splits[i], start = i > 0u ? splits[i - 1u] : 0.0;
    blend = smoothstep(end - 0.1 * (end - start), end, z);
    return i;
}

// The visibility of light slot `slot` (> 0) at view-space p with normal n, l towards the light and
// `light` its view-space position (point lights). The view is chosen first (the cascade of the
// view depth, the cube face of the direction's major axis in world space, or the spot map); one
// loop then samples it and, over the last 10 % of a cascade's slice, the next cascade where its
// tile holds the point: a single sampling site, since llvmpipe runs every branch's code.
float tl_shadow(float slot, vec3 p, vec3 n, vec3 l, vec3 light)
{
    tl_shadow_light sl = tl_shadow_lights[uint(slot) - 1u];
    uint v = sl.info.x, count = sl.info.y;
    if (count == 0u || sl.fade.x <= 0.0) return 1.0;
    float blend = 0.0;
    int views = 1;
    if (sl.info.z == 3u) {
        uint i = tl_shadow_cascade(sl.splits, -p.z, blend);
        if (i > 3u) return 1.0;
        v += i;
        views = blend > 0.0 && i + 1u < count ? 2 : 1;
    } else if (sl.info.z == 1u) {
        vec3 d = transpose(mat3(u_view)) * (p - light), a = abs(d);
        v += a.x >= a.y && a.x >= a.z ? (d.x >= 0.0 ? 0u : 1u) : a.y >= a.z ? (d.y >= 0.0 ? 2u : 3u) : (d.z >= 0.0 ? 4u : 5u);
    }
    // kernel and offset stay inside the next cascade's tile; a spot or face view must hold p
    float margin = 1.0 - 2.0 * (max(u_shadow_params.y, float(u_shadow_flags.y)) + 2.0) / sl.fade.y, s = 1.0;
    for (int k = 0; k < views; k++) {
        tl_shadow_view sv = tl_shadow_views[v + uint(k)];
        vec4 c = sv.m * vec4(p, 1.0);
        float extent = c.w > 0.0 ? max(abs(c.x), abs(c.y)) / c.w : 2.0;
        if (k == 0 && sl.info.z != 3u && extent > 1.0) return 1.0;
        if (k == 1 && extent > margin) break;
#ifdef TL_PCSS
        float sk = tl_shadow_pcss(sv, c.w, p, n, l);
#else
        float sk = tl_shadow_sample(sv, tl_shadow_biased(sv, c.w, p, n, l, u_shadow_params.y));
#endif
        s = k == 0 ? sk : mix(s, sk, blend);
    }
    return mix(1.0, s, sl.fade.x);
}

// The direction towards a light of tl_light_data layout (type 3: directional).
vec3 tl_shadow_to_light(int type, vec3 p, vec3 position, vec3 direction)
{
    vec3 d = position - p;
    float d2 = dot(d, d);
    return type == 3 ? -direction : d2 > 0.0 ? d * inversesqrt(d2) : vec3(0.0, 0.0, 1.0); // a light at the point
}

// The visibility of a light of tl_light_data layout (type 3: directional) with shadow slot `slot`
// (> 0) at view-space p with normal n: tl_shadow with the direction towards the light.
float tl_light_shadow(float slot, int type, vec3 p, vec3 n, vec3 position, vec3 direction)
{
    return tl_shadow(slot, p, n, tl_shadow_to_light(type, p, position, direction), position);
}

#endif
