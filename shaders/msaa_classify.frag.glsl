// MSAA per-sample edges, the classification (pass_msaa.c): a pixel is an edge when one of its
// samples lies on another surface than sample 0's: background against surface, a view position off
// sample 0's plane by more than TL_MSAA_EDGE_PLANE pixel footprints at its depth (samples of one
// plane stay within one: thin positions are rebuilt on the pixel's centre ray, fat's are the
// primitive's at the centre), normals more than acos(TL_MSAA_EDGE_NORMAL) apart, or, within one
// plane, materials that differ (albedo or specular by more than TL_MSAA_EDGE_MATERIAL: a decal, a
// cloth on a wall, where forward's MSAA shades both primitives). Edge pixels
// write 1 into msaa.edges (cleared to 0); the rest discard, so the pass's samples-passed count is
// the edge pixels (tl_frame_stats.msaa_edge_pixels).
#define TL_MSAA_CLASSIFY
#include "gbuffer_decode.glsl"

#define TL_MSAA_EDGE_PLANE 1.0
#define TL_MSAA_EDGE_NORMAL 0.98
#define TL_MSAA_EDGE_MATERIAL 0.03

layout(location = TL_OUT_MSAA_EDGES) out vec4 o_edge;

vec3 tl_classify_normal(ivec2 px, int s)
{
    tl_gbuffer_sample = s;
#ifdef TL_CLASSIFY_FAT
    vec3 n = tl_gfetch(u_fat_normal, px).xyz;
    float l2 = dot(n, n);
    return l2 > 0.0 ? n * inversesqrt(l2) : vec3(0.0, 0.0, 1.0);
#else
    vec3 n;
    float gloss;
    tl_gbuffer_normal_gloss(px, n, gloss);
    return n;
#endif
}

// Sample s's material as stored: thin RT1 (luma, the pixel's chroma, specular), fat albedo and specular.
// thin-lpp: none (its material pass shades each primitive's samples with their own material).
vec4 tl_classify_material(ivec2 px, int s)
{
#if defined(TL_CLASSIFY_FAT)
    return vec4(texelFetch(u_fat_albedo, px, s).rgb, texelFetch(u_fat_material, px, s).r);
#elif defined(TL_CLASSIFY_RT1)
    return texelFetch(u_rt1, px, s);
#else
    return vec4(0.0);
#endif
}

// Sample s's view position, false on background.
bool tl_classify_position(ivec2 px, int s, out vec3 p)
{
    tl_gbuffer_sample = s;
    p = vec3(0.0);
#ifdef TL_CLASSIFY_FAT
    vec4 pos = tl_gfetch(u_fat_position, px);
    p = pos.xyz;
    return pos.w > 0.5;
#else
    float d = tl_gfetch(u_depth, px).r;
    if (d == u_clear_depth) return false;
    float z = tl_depth_linearize(d, u_depth_params.x, u_depth_params.y, u_depth_params.z, u_depth_params.w > 0.5);
    p = tl_view_position(z, (vec2(px) + 0.5) * u_inv_size * 2.0 - 1.0, u_ray_params);
    return true;
#endif
}

bool tl_classify_edge(ivec2 px)
{
    vec3 p0, p;
    bool surface0 = tl_classify_position(px, 0, p0);
    vec3 n0 = surface0 ? tl_classify_normal(px, 0) : vec3(0.0);
    vec4 m0 = tl_classify_material(px, 0);
    // one pixel's extent in view space at sample 0's depth
    float footprint = abs(p0.z) * 2.0 * u_inv_size.y / abs(u_ray_params.y);
    for (int s = 1; s < TL_GBUFFER_SAMPLES; s++) {
        if (tl_classify_position(px, s, p) != surface0) return true;
        if (!surface0) continue;
        if (abs(dot(p - p0, n0)) > TL_MSAA_EDGE_PLANE * footprint) return true;
        if (dot(tl_classify_normal(px, s), n0) < TL_MSAA_EDGE_NORMAL) return true;
        vec4 dm = abs(tl_classify_material(px, s) - m0);
        if (max(max(dm.x, dm.y), max(dm.z, dm.w)) > TL_MSAA_EDGE_MATERIAL) return true;
    }
    return false;
}

void main()
{
    if (!tl_classify_edge(ivec2(gl_FragCoord.xy))) discard;
    o_edge = vec4(1.0);
}
