// Screen-space reflections (docs/effects.md): from a pixel's view-space position p (depth: the
// view-ray method; fat: its position target) the reflected view ray r = reflect(p / |p|, n) is
// marched in TL_SSR_STEPS linear steps of view space up to the largest distance (shortened so that
// it stays in front of the near plane), each step jittered per pixel. A step whose pixel's surface
// lies in front of the ray by more than a small bias and less than the thickness is a hit, refined
// by TL_SSR_REFINE bisections, unless the surface hit faces away from the ray (a thickness false
// hit, e.g. behind a floor's far edge); a ray that leaves the screen or meets only background adds nothing.
// The HDR colour at the hit is weighted by gloss (zero below the least gloss, 1 at gloss 1),
// Schlick's Fresnel with F0 = 0.04, a fade over the screen's edges and one over the ray's last
// fifth. Output: the weighted colour and, in alpha, its weight.
#include "effects.glsl"

layout(std140, binding = TL_UBO_PASS) uniform tl_ssr_block {
    vec4 u_ssr_march;  // max distance, thickness, min gloss, edge fade
    vec4 u_ssr_weight; // intensity, near plane distance, 0, 0
};

in vec2 v_uv;
layout(binding = TL_UNIT_HDR) uniform sampler2D u_hdr;
layout(location = TL_OUT_SSR) out vec4 o_ssr;

// The view distance of the surface at a pixel; +inf for the background.
float tl_ssr_scene_z(ivec2 q)
{
#ifdef TL_SSAO_FAT
    vec4 p = texelFetch(u_fat_position, q, 0);
    return p.w > 0.5 ? -p.z : uintBitsToFloat(0x7f800000u);
#else
    return tl_fx_linear_depth(q);
#endif
}

float tl_ssr_gloss(ivec2 px)
{
#ifdef TL_SSAO_FAT
    return texelFetch(u_fat_normal, px, 0).w;
#else
    vec3 n;
    float gloss;
    tl_gbuffer_normal_gloss(px, n, gloss);
    return gloss;
#endif
}

// The pixel (fractional) a view-space point projects to; false behind the eye or off the screen.
bool tl_ssr_pixel(vec3 s, vec2 size, out vec2 q)
{
    vec4 c = u_proj * vec4(s, 1.0);
    q = vec2(-1.0);
    if (!(c.w > 0.0)) return false;
    q = (c.xy / c.w * 0.5 + 0.5) * size;
    return all(greaterThanEqual(q, vec2(0.0))) && all(lessThan(q, size));
}

// How far the ray at t lies behind the surface at its pixel (> 0: behind; -inf over the
// background); `on` is false when the point is off the screen or behind the eye.
float tl_ssr_behind(vec3 p, vec3 r, float t, vec2 size, out vec2 q, out bool on)
{
    vec3 s = p + r * t;
    on = tl_ssr_pixel(s, size, q);
    return on ? -s.z - tl_ssr_scene_z(ivec2(q)) : uintBitsToFloat(0xff800000u);
}

// The march: the ray parameter of the hit, or -1.
float tl_ssr_march(vec3 p, vec3 r, float len, vec2 size, out vec2 q)
{
    float step = len / float(TL_SSR_STEPS), jitter = tl_fx_noise(gl_FragCoord.xy), prev = 0.0;
    float bias = 1e-3 * max(-p.z, 1e-6);
    bool on;
    for (int i = 0; i < TL_SSR_STEPS; i++) {
        float t = (float(i) + 0.5 + 0.5 * jitter) * step, b = tl_ssr_behind(p, r, t, size, q, on);
        if (!on) return -1.0; // left the screen: nothing beyond it is known
        if (b > bias && b < u_ssr_march.y) {
            float lo = prev, hi = t;
            for (int k = 0; k < TL_SSR_REFINE; k++) {
                float mid = 0.5 * (lo + hi);
                vec2 qm;
                if (tl_ssr_behind(p, r, mid, size, qm, on) > bias) hi = mid;
                else lo = mid;
            }
            tl_ssr_behind(p, r, hi, size, q, on);
            return hi;
        }
        prev = t;
    }
    return -1.0;
}

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec2 size = vec2(tl_fx_size());
    o_ssr = vec4(0.0);
    vec3 p;
    if (!tl_fx_position(px, p)) return;
    float wg = clamp((tl_ssr_gloss(px) - u_ssr_march.z) / max(1.0 - u_ssr_march.z, 1e-6), 0.0, 1.0);
    vec3 n = tl_fx_normal(px, p), v = normalize(p), r = reflect(v, n);
    if (!(wg > 0.0) || dot(r, n) <= 0.0 || any(isnan(r))) return;
    float len = u_ssr_march.x;
    if (r.z > 0.0) len = min(len, max(-p.z - 1.001 * u_ssr_weight.y, 0.0) / r.z); // stay in front of the near plane
    if (!(len > 0.0)) return;
    vec2 q;
    float t = tl_ssr_march(p, r, len, size, q);
    if (t < 0.0) return;
    vec3 ph;
    if (!tl_fx_position(ivec2(q), ph) || dot(tl_fx_normal(ivec2(q), ph), r) > 0.0) return; // a back face: not seen
    vec3 c = texelFetch(u_hdr, ivec2(q), 0).rgb;
    if (any(isnan(c))) return;
    c = min(c, vec3(65504.0));
    vec2 uv = q / size;
    float edge = min(min(uv.x, 1.0 - uv.x), min(uv.y, 1.0 - uv.y));
    float fe = clamp(edge / u_ssr_march.w, 0.0, 1.0), fd = 1.0 - smoothstep(0.8, 1.0, t / u_ssr_march.x);
    float f = 0.04 + 0.96 * pow(clamp(1.0 - dot(n, -v), 0.0, 1.0), 5.0);
    float w = wg * fe * fd * f * u_ssr_weight.x;
    o_ssr = vec4(min(c * w, vec3(65504.0)), w);
}
