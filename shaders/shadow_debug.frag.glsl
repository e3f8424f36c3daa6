// The shadow-debug pass (pass_shadow_debug.c; docs/shadows.md, "Debug views"). Per pixel, the
// surface read as the light pass reads it and every visible casting light looked up as the light
// pass looks it up (the light loop's shadow gate, tl_light_visibility):
//   R: the shadow-only term sum(w_i s_i) / sum(w_i), s_i a casting light's visibility and w_i the
//      luminance of its unshadowed diffuse light at the pixel (attenuation, cone, n.l included);
//   G: sum(w_i) (0: no casting light reaches the pixel, R is then 1);
//   B: the cascade of the first casting directional light at the view depth plus its blend weight
//      towards the next cascade (as tl_shadow blends them), -1 beyond the last or without one;
//   A: 1 on surfaces, 0 on the background (cleared).
#include "gbuffer_decode.glsl"
#include "light_loop.glsl" // the lights block, the reach test and the shadow gate

layout(location = TL_OUT_SHADOW_DEBUG) out vec4 o_debug;

#ifdef TL_SHADOW_DEBUG_DEPTH_NORMALS
// Forward has no normal target: the face's normal from the nearer neighbour on each axis (the one
// on the same surface, unless the pixel is on a one-pixel sliver).
vec3 tl_depth_normal(ivec2 px, vec3 p)
{
    vec3 d[2];
    ivec2 size = textureSize(u_depth, 0);
    for (int a = 0; a < 2; a++) {
        ivec2 e = a == 0 ? ivec2(1, 0) : ivec2(0, 1);
        vec3 q0 = p, q1 = p;
        bool h0 = px - e == clamp(px - e, ivec2(0), size - 1) && tl_gbuffer_position(px - e, q0);
        bool h1 = px + e == clamp(px + e, ivec2(0), size - 1) && tl_gbuffer_position(px + e, q1);
        bool back = h0 && (!h1 || abs(q0.z - p.z) < abs(q1.z - p.z));
        d[a] = back ? p - q0 : q1 - p;
    }
    vec3 n = cross(d[0], d[1]);
    n = dot(n, n) > 0.0 ? normalize(n) : vec3(0.0, 0.0, 1.0);
    return dot(n, p) > 0.0 ? -n : n; // towards the camera
}
#endif

// The pixel's view position and normal; false on the background.
bool tl_debug_surface(ivec2 px, out vec3 p, out vec3 n, out float gloss)
{
    n = vec3(0.0, 0.0, 1.0);
    gloss = 0.0;
#if defined(TL_SHADOW_DEBUG_FAT)
    if (!tl_fat_position(px, p)) return false;
    vec4 ng = tl_gfetch(u_fat_normal, px);
    n = dot(ng.xyz, ng.xyz) > 0.0 ? normalize(ng.xyz) : n;
    gloss = ng.w;
#elif defined(TL_SHADOW_DEBUG_DEPTH_NORMALS)
    if (!tl_gbuffer_position(px, p)) return false;
    n = tl_depth_normal(px, p);
#else
    if (!tl_gbuffer_position(px, p)) return false;
    tl_gbuffer_normal_gloss(px, n, gloss);
#endif
    return true;
}

// The cascade coordinate of the first casting directional light with a map (-1: none).
float tl_debug_cascade(vec3 p)
{
    for (uint i = 0u; i < u_light_counts.x; i++) {
        float slot = tl_lights[i].cos_inner.z;
        if (slot <= 0.0) continue;
        tl_shadow_light sl = tl_shadow_lights[uint(slot) - 1u];
        if (sl.info.y == 0u) continue;
        float blend;
        uint c = tl_shadow_cascade(sl.splits, -p.z, blend);
        return c > 3u ? -1.0 : float(c) + (c + 1u < sl.info.y ? blend : 0.0);
    }
    return -1.0;
}

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 p, n;
    float gloss;
    if (!tl_debug_surface(px, p, n, gloss)) discard;
    vec3 v = normalize(-p);
    float shape = tl_lobe_shape(gloss), lit = 0.0, all = 0.0;
    uint end = max(u_light_counts.z, u_light_counts.x); // directional lights, then the casting local ones
    for (uint i = 0u; i < end; i++) {
        tl_light_data l = tl_lights[i];
        if (l.cos_inner.z <= 0.0) continue;
        int type = int(l.color_type.w);
        float w = tl_luminance(l.color_type.rgb) * tl_light_reached_weights(l, type, p, n, v, shape).x;
        if (w <= 0.0) continue;
        all += w;
        lit += w * tl_light_visibility(l, type, p, n, true);
    }
    o_debug = vec4(all > 0.0 ? lit / all : 1.0, min(all, 65504.0), tl_debug_cascade(p), 1.0);
}
