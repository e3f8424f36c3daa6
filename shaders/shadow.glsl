// Shadow lookup (docs/shadows.md), included by every lighting pass when the plan has TL_SHADOWS.
// A casting light's slot (tl_light_data.cos_inner.z, the volumes' colour alpha) is its record + 1;
// the record names its views in the atlas: one spot map, six cube faces or four cascades. The
// lookup point is moved off the surface by a bias derived from the texel's world size, the PCF
// kernel's reach and the two depth formats' quantisation (never a tuned constant):
//   along n: (r + 1) w sin(theta) + e_gbuffer(z),   along l: e_atlas(w)
// where w is the texel's world size at the point, r the kernel radius, theta the angle between n
// and l, e_gbuffer the rebuilt position's error and e_atlas the atlas depth's quantum.
#ifndef TL_SHADOW_GLSL
#define TL_SHADOW_GLSL

#include "frame.glsl"

struct tl_shadow_view {
    mat4 m;      // view space to the view's clip space
    vec4 rect;   // atlas uv offset (xy) and scale (zw) of the view's tile
    vec4 texel;  // x: texel world size per clip w; y, z, w: atlas depth quantum c0 + c1 w + c2 w^2 (world)
};
struct tl_shadow_light {
    uvec4 info;  // first view, view count, kind (1 point, 2 spot, 3 directional), 0
    vec4 fade;   // x: strength 0..1 (a light losing or gaining its map fades), y: tile side in texels
    vec4 splits; // cascades: the view depth where each ends
};
layout(std430, binding = TL_SSBO_SHADOWS) readonly buffer tl_shadow_buffer {
    vec4 u_shadow_params;   // 1 / atlas side, PCF radius, G-buffer error: a z + b z^2 (a, b)
    uvec4 u_shadow_flags;   // x: reversed depth (atlas compare GEQUAL)
    tl_shadow_light tl_shadow_lights[64];
    tl_shadow_view tl_shadow_views[];
};
layout(binding = TL_UNIT_SHADOW_ATLAS) uniform sampler2DShadow u_shadow_atlas;

// The view's PCF result at view-space point q (already biased); 1 outside the tile.
float tl_shadow_sample(tl_shadow_view sv, vec3 q)
{
    vec4 c = sv.m * vec4(q, 1.0);
    if (c.w <= 0.0) return 1.0;
    vec3 ndc = c.xyz / c.w;
    float ref = u_shadow_flags.x != 0u ? ndc.z : ndc.z * 0.5 + 0.5;
    vec2 uv = sv.rect.xy + (ndc.xy * 0.5 + 0.5) * sv.rect.zw;
    float t = u_shadow_params.x;
    vec2 lo = sv.rect.xy + vec2(0.5 * t), hi = sv.rect.xy + sv.rect.zw - vec2(0.5 * t);
    // kernel radius r: (2 r)^2 bilinear compare taps half a texel off the grid cover the
    // (2 r + 1)^2 texels a tent-weighted r-texel kernel reads (r = 0: one bilinear tap)
    int r = int(u_shadow_params.y);
    if (r == 0) return texture(u_shadow_atlas, vec3(clamp(uv, lo, hi), ref));
    float sum = 0.0;
    for (int y = 0; y < 2 * r; y++)
        for (int x = 0; x < 2 * r; x++)
            sum += texture(u_shadow_atlas, vec3(clamp(uv + (vec2(x, y) - float(r) + 0.5) * t, lo, hi), ref));
    return sum / float(4 * r * r);
}

// How far view v's tile contains p: max(|ndc.x|, |ndc.y|) (above 1: outside), 2 behind the view.
float tl_shadow_extent(uint v, vec3 p)
{
    vec4 c = tl_shadow_views[v].m * vec4(p, 1.0);
    if (c.w <= 0.0) return 2.0;
    vec2 a = abs(c.xy / c.w);
    return max(a.x, a.y);
}

// p biased for view sv: n and l unit, view space (l towards the light).
vec3 tl_shadow_biased(tl_shadow_view sv, vec3 p, vec3 n, vec3 l)
{
    vec4 c = sv.m * vec4(p, 1.0);
    float w = max(c.w, 0.0);
    float texel = sv.texel.x * w;
    float cos_t = clamp(dot(n, l), 0.0, 1.0), sin_t = sqrt(1.0 - cos_t * cos_t);
    float z = -p.z;
    float e_gbuffer = u_shadow_params.z * z + u_shadow_params.w * z * z;
    float e_atlas = sv.texel.y + sv.texel.z * w + sv.texel.w * w * w;
    return p + n * ((u_shadow_params.y + 1.0) * texel * sin_t + e_gbuffer) + l * e_atlas;
}

// The visibility of light slot `slot` (> 0) at view-space p with normal n, l towards the light and
// `light` its view-space position (point lights).
float tl_shadow(float slot, vec3 p, vec3 n, vec3 l, vec3 light)
{
    tl_shadow_light sl = tl_shadow_lights[uint(slot) - 1u];
    uint first = sl.info.x, count = sl.info.y;
    if (count == 0u || sl.fade.x <= 0.0) return 1.0;
    float margin = 1.0 - 2.0 * (u_shadow_params.y + 2.0) / sl.fade.y; // kernel and offset stay inside
    float s = 1.0;
    if (sl.info.z == 3u) { // cascades: by view depth (each one's sphere holds its slice), blended
        float z = -p.z;    // into the next over the last 10 % of its slice
        uint i = z < sl.splits.x ? 0u : z < sl.splits.y ? 1u : z < sl.splits.z ? 2u : 3u;
        if (z >= sl.splits.w) return 1.0;
        float end = sl.splits[i], start = i > 0u ? sl.splits[i - 1u] : 0.0;
        tl_shadow_view sv = tl_shadow_views[first + i];
        s = tl_shadow_sample(sv, tl_shadow_biased(sv, p, n, l));
        float blend = smoothstep(end - 0.1 * (end - start), end, z);
        if (blend > 0.0 && i + 1u < count && tl_shadow_extent(first + i + 1u, p) <= margin) {
            tl_shadow_view nv = tl_shadow_views[first + i + 1u];
            s = mix(s, tl_shadow_sample(nv, tl_shadow_biased(nv, p, n, l)), blend);
        }
    } else {
        uint v = first; // spot: its map; point: the cube face of the direction's major axis (world space)
        if (sl.info.z == 1u) {
            vec3 d = transpose(mat3(u_view)) * (p - light), a = abs(d);
            v += a.x >= a.y && a.x >= a.z ? (d.x >= 0.0 ? 0u : 1u) : a.y >= a.z ? (d.y >= 0.0 ? 2u : 3u) : (d.z >= 0.0 ? 4u : 5u);
        }
        tl_shadow_view sv = tl_shadow_views[v]; // loaded once: storage loads are what a lookup costs
        vec4 c = sv.m * vec4(p, 1.0);
        if (c.w <= 0.0 || max(abs(c.x), abs(c.y)) > c.w) return 1.0;
        s = tl_shadow_sample(sv, tl_shadow_biased(sv, p, n, l));
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

#endif
