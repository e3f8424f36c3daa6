// Reading the G-buffer back in the light pass. Thin: depth -> view position (view-ray method),
// RT0 -> normal and gloss, RT1 -> albedo (edge-aware chroma reconstruction) and specular. Fat:
// everything read as stored.
#include "codec.glsl"
#include "frame.glsl"

// MSAA with per-sample lighting on edges (gbuffer_samples.glsl): the G-buffer is multisampled.
#ifdef TL_GBUFFER_SAMPLES
#define TL_GSAMPLER sampler2DMS
int tl_gbuffer_sample = 0; // the sample read, unless the pass is the per-sample one (gl_SampleID)
#ifdef TL_MSAA_SAMPLE
#define TL_GSAMPLE gl_SampleID
#else
#define TL_GSAMPLE tl_gbuffer_sample
#endif
#define tl_gfetch(s, p) texelFetch(s, p, TL_GSAMPLE)
#define tl_gsize(s) textureSize(s)
#else
#define TL_GSAMPLER sampler2D
#define tl_gfetch(s, p) texelFetch(s, p, 0)
#define tl_gsize(s) textureSize(s, 0)
#endif

#ifdef TL_LIGHT_SHIFT
// The light scale: the light pass writes the reduced light buffer (LIGHT_REDUCED_*, which
// light-upsample makes the full-size one of) under the names it has at scale 1
#ifdef TL_OUT_LIGHT_REDUCED_DIFFUSE
#define TL_OUT_LIGHT_DIFFUSE TL_OUT_LIGHT_REDUCED_DIFFUSE
#endif
#ifdef TL_OUT_LIGHT_REDUCED_SPECULAR
#define TL_OUT_LIGHT_SPECULAR TL_OUT_LIGHT_REDUCED_SPECULAR
#endif
#ifdef TL_OUT_LIGHT_REDUCED_FRESNEL
#define TL_OUT_LIGHT_FRESNEL TL_OUT_LIGHT_REDUCED_FRESNEL
#endif
#undef TL_IMAGE_LIGHT_DIFFUSE
#define TL_IMAGE_LIGHT_DIFFUSE TL_IMAGE_LIGHT_REDUCED_DIFFUSE
#undef TL_IMAGE_LIGHT_SPECULAR
#define TL_IMAGE_LIGHT_SPECULAR TL_IMAGE_LIGHT_REDUCED_SPECULAR
#undef TL_IMAGE_LIGHT_FRESNEL
#define TL_IMAGE_LIGHT_FRESNEL TL_IMAGE_LIGHT_REDUCED_FRESNEL
// and reads the reduced depth and RT0 (light_reduce.frag.glsl)
layout(binding = TL_UNIT_LIGHT_DEPTH) uniform sampler2D u_depth;
layout(binding = TL_UNIT_LIGHT_RT0) uniform sampler2D u_rt0;
layout(binding = TL_UNIT_LIGHT_OFFSET) uniform sampler2D u_light_offset;

// The pixel of the frame a reduced texel's depth and RT0 came from.
vec2 tl_reduced_pixel_centre(ivec2 px)
{
    uint o = uint(texelFetch(u_light_offset, px, 0).r * 255.0 + 0.5) & 31u; // 32: the upsample's flag
    const float k = float(1 << TL_LIGHT_SHIFT);
    return o == 16u ? (vec2(px) + 0.5) * k : vec2(px * (1 << TL_LIGHT_SHIFT) + ivec2(o & 3u, o >> 2)) + 0.5;
}
#else
layout(binding = TL_UNIT_DEPTH) uniform TL_GSAMPLER u_depth;
layout(binding = TL_UNIT_RT0) uniform TL_GSAMPLER u_rt0;
#endif
layout(binding = TL_UNIT_RT1) uniform TL_GSAMPLER u_rt1;
layout(binding = TL_UNIT_FAT_POSITION) uniform TL_GSAMPLER u_fat_position;
layout(binding = TL_UNIT_FAT_NORMAL) uniform TL_GSAMPLER u_fat_normal;
layout(binding = TL_UNIT_FAT_ALBEDO) uniform TL_GSAMPLER u_fat_albedo;
layout(binding = TL_UNIT_FAT_MATERIAL) uniform TL_GSAMPLER u_fat_material;
#ifdef TL_GBUFFER_SAMPLES
#include "gbuffer_samples.glsl"
#else
bool tl_msaa_lit_here(ivec2 px) { return true; }
float tl_gbuffer_depth(ivec2 px) { return texelFetch(u_depth, px, 0).r; }
vec2 tl_gbuffer_point(ivec2 px) { return vec2(px) + 0.5; }
#endif

// The view-space position from depth; false for background pixels (depth at the clear value).
bool tl_gbuffer_position(ivec2 px, out vec3 p)
{
    p = vec3(0.0);
    if (!tl_msaa_lit_here(px)) return false; // MSAA per-sample edges: the other light pass's pixel
    float d = tl_gbuffer_depth(px);
    if (d == u_clear_depth) return false;
    float z = tl_depth_linearize(d, u_depth_params.x, u_depth_params.y, u_depth_params.z, u_depth_params.w > 0.5);
#ifdef TL_LIGHT_SHIFT
    // a reduced texel is lit at the position of the pixel its depth and normal came from
    vec2 ndc = tl_reduced_pixel_centre(px) * u_inv_size * 2.0 - 1.0;
#else
    vec2 ndc = tl_gbuffer_point(px) * u_inv_size * 2.0 - 1.0;
#endif
    p = tl_view_position(z, ndc, u_ray_params);
    return true;
}

// RT0 -> view-space normal and gloss.
void tl_gbuffer_normal_gloss(ivec2 px, out vec3 n, out float gloss)
{
    vec4 ng = tl_rt0_texel_decode(tl_gfetch(u_rt0, px));
    n = ng.xyz;
    gloss = ng.w;
}

float tl_srgb_to_linear1(float c)
{
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

// RT1: the pixel's luma and own chroma, the missing chroma from the 4 neighbours (which store it)
// with the codec's edge-aware weights; neighbours outside the image are mirrored back in, as in
// tl_albedo_reconstruct. Specular is stored as sqrt of its luminance (grey F0). A multisampled
// RT1 (per-sample edges): the neighbours' same sample index, whose chroma parity is the
// neighbour pixel's, as at one sample.
void tl_rt1_read(ivec2 px, out vec3 albedo, out vec3 specular)
{
    ivec2 size = tl_gsize(u_rt1);
    uvec4 c = tl_unorm8_bytes(tl_gfetch(u_rt1, px));
    ivec2 offs[4] = ivec2[4](ivec2(-1, 0), ivec2(1, 0), ivec2(0, -1), ivec2(0, 1));
    ivec4 nl = ivec4(0), nc = ivec4(0);
    int count = 0;
    for (int i = 0; i < 4; i++) {
        ivec2 q = px + offs[i];
        if (q.x < 0) q.x = 1;
        if (q.y < 0) q.y = 1;
        if (q.x >= size.x) q.x = size.x - 2;
        if (q.y >= size.y) q.y = size.y - 2;
        if (q.x < 0 || q.y < 0) continue;
        uvec4 b = tl_unorm8_bytes(tl_gfetch(u_rt1, q));
        nl[count] = int(b.x);
        nc[count] = int(b.y);
        count++;
    }
    float missing = tl_albedo_edge_chroma(int(c.x), nl, nc, count);
    float own = float(c.y) / 255.0;
    bool even = tl_chroma_parity(uvec2(px)) == 0u;
    vec3 srgb = tl_luma_chroma_to_rgb(1u, vec3(float(c.x) / 255.0, even ? own : missing, even ? missing : own));
    albedo = vec3(tl_srgb_to_linear1(srgb.r), tl_srgb_to_linear1(srgb.g), tl_srgb_to_linear1(srgb.b));
    float s = float(c.z) / 255.0;
    specular = vec3(s * s);
}

bool tl_fat_position(ivec2 px, out vec3 p)
{
    vec4 pos = tl_gfetch(u_fat_position, px);
    p = pos.xyz;
    return pos.w > 0.5 && tl_msaa_lit_here(px);
}

void tl_fat_surface(ivec2 px, out vec3 n, out float gloss, out vec3 albedo, out vec3 specular)
{
    vec4 ng = tl_gfetch(u_fat_normal, px);
    float l2 = dot(ng.xyz, ng.xyz);
    n = l2 > 0.0 ? ng.xyz * inversesqrt(l2) : vec3(0.0, 0.0, 1.0);
    gloss = ng.w;
    albedo = tl_gfetch(u_fat_albedo, px).rgb;
#ifdef TL_SPECULAR_NONE
    specular = vec3(0.0);
#else
    specular = tl_gfetch(u_fat_material, px).rgb;
#endif
}
