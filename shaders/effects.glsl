// Shared by the screen-space effects (docs/effects.md): positions and normals of a pixel from the
// thin G-buffer (depth + RT0), the fat one (TL_SSAO_FAT) or depth alone (TL_SSAO_DEPTH_NORMALS),
// linear depth, and per-pixel noise.
#include "gbuffer_decode.glsl"

#ifndef TL_EFFECTS_GLSL
#define TL_EFFECTS_GLSL

ivec2 tl_fx_size()
{
#ifdef TL_SSAO_FAT
    return textureSize(u_fat_position, 0);
#else
    return textureSize(u_depth, 0);
#endif
}

// The view-space position; false outside the image and for background pixels.
bool tl_fx_position(ivec2 px, out vec3 p)
{
    p = vec3(0.0);
    if (any(lessThan(px, ivec2(0))) || any(greaterThanEqual(px, tl_fx_size()))) return false;
#ifdef TL_SSAO_FAT
    return tl_fat_position(px, p);
#else
    return tl_gbuffer_position(px, p);
#endif
}

// Of the two neighbours along one axis, the difference to the one on the same surface (the smaller
// depth step); zero when neither is.
vec3 tl_fx_tangent(ivec2 px, vec3 p, ivec2 step)
{
    vec3 a, b;
    bool ha = tl_fx_position(px + step, a), hb = tl_fx_position(px - step, b);
    vec3 da = a - p, db = p - b;
    if (ha && hb) return abs(da.z) <= abs(db.z) ? da : db;
    return ha ? da : hb ? db : vec3(0.0);
}

// The view-space unit normal of a foreground pixel, facing the eye.
vec3 tl_fx_normal(ivec2 px, vec3 p)
{
#if defined(TL_SSAO_FAT)
    vec3 n = texelFetch(u_fat_normal, px, 0).xyz;
#elif defined(TL_SSAO_DEPTH_NORMALS)
    vec3 n = cross(tl_fx_tangent(px, p, ivec2(1, 0)), tl_fx_tangent(px, p, ivec2(0, 1)));
    if (dot(n, p) > 0.0) n = -n;
#else
    vec3 n;
    float gloss;
    tl_gbuffer_normal_gloss(px, n, gloss);
#endif
    float l2 = dot(n, n);
    return l2 > 1e-20 && !isinf(l2) ? n * inversesqrt(l2) : vec3(0.0, 0.0, 1.0);
}

// Positive view distance along -z of a pixel from the depth target; +inf for the background.
float tl_fx_linear_depth(ivec2 px)
{
    float d = texelFetch(u_depth, px, 0).r;
    if (d == u_clear_depth) return uintBitsToFloat(0x7f800000u);
    return -tl_depth_linearize(d, u_depth_params.x, u_depth_params.y, u_depth_params.z, u_depth_params.w > 0.5);
}

// Interleaved gradient noise (Jimenez 2014) in [0, 1).
float tl_fx_noise(vec2 frag)
{
    return fract(52.9829189 * fract(dot(frag, vec2(0.06711056, 0.00583715))));
}

#endif
