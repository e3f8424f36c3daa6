// light-upsample (light_scale below 1; docs/frame.md, "Light at reduced resolution"): the full-size
// light buffer the material pass reads as at scale 1, made of the reduced one the light pass wrote.
// TL_UPSAMPLE is the light buffer's shift, K = 2^TL_UPSAMPLE. One invocation per quad of reduced
// texels (base .. base + 1): it reads the four texels once (depth, where each was lit, RT0, light)
// and writes the K x K frame pixels between their centres. A pixel takes the four texels, each
// weighted by
//   bilinear x depth similarity x normal similarity.
// Depth: the texel's depth (the nearest sample of its block) against the pixel's own depth carried
// along the pixel's plane to the pixel that sample came from, within 1 % of the distance plus the
// depth change across half a block: a texel of another surface (a silhouette, a step) weighs 0, one
// of the same plane 1 however steeply it is seen. The plane's slope is the smaller one-sided
// difference of the frame's depth on each axis (a neighbour across an edge is the larger one).
// Normal: the texel's RT0 normal against the pixel's own (the same encoding, so a flat surface
// compares exactly), raised to a power: 16, or with specular materials in the frame the lobe's
// own power (tl_gloss_to_specular_power, 16 to 256), so a highlight is not interpolated between
// normals its lobe tells apart. A pixel of an interior quad (light_reduce.frag.glsl, flag 32) with
// the quad's normal takes the bilinear weights alone (they would all be 1).
// A pixel whose credible weight sums to less than TL_UPSAMPLE_CREDIBLE (no texel of its surface near
// it: thin features, silhouettes, creases) is re-lit exactly as the light pass lights a pixel at
// scale 1, from its tile's lists (the tiles are in the frame's pixels and their depth bounds cover
// every pixel). The workgroup gathers its re-lit pixels first and then re-lights them together, so
// the loop over lights runs on full SIMD groups; every re-lit pixel takes the same code whichever
// invocation runs it, so the bytes never depend on the order of the gathering.
#include "codec.glsl"
#include "frame.glsl"
#include "light_eval.glsl"
#include "tile_lights.glsl" // the visible lights, the tile lists and their sums

#define TL_GROUP 16
layout(local_size_x = TL_GROUP, local_size_y = TL_GROUP) in;

layout(binding = TL_UNIT_DEPTH) uniform sampler2D u_depth;
layout(binding = TL_UNIT_RT0) uniform sampler2D u_rt0;
layout(binding = TL_UNIT_LIGHT_DEPTH) uniform sampler2D u_light_depth;
layout(binding = TL_UNIT_LIGHT_RT0) uniform sampler2D u_light_rt0;
layout(binding = TL_UNIT_LIGHT_OFFSET) uniform sampler2D u_light_offset;
layout(binding = TL_UNIT_LIGHT_REDUCED_DIFFUSE) uniform sampler2D u_reduced_diffuse;
layout(TL_LIGHT_IMAGE_FORMAT, binding = TL_IMAGE_LIGHT_DIFFUSE) uniform writeonly image2D u_diffuse_image;
#ifdef TL_SPECULAR_EXACT
layout(binding = TL_UNIT_LIGHT_REDUCED_SPECULAR) uniform sampler2D u_reduced_specular;
layout(TL_LIGHT_IMAGE_FORMAT, binding = TL_IMAGE_LIGHT_SPECULAR) uniform writeonly image2D u_specular_image;
#ifdef TL_FRESNEL_SUMS
layout(binding = TL_UNIT_LIGHT_REDUCED_FRESNEL) uniform sampler2D u_reduced_fresnel;
layout(TL_LIGHT_IMAGE_FORMAT, binding = TL_IMAGE_LIGHT_FRESNEL) uniform writeonly image2D u_fresnel_image;
#endif
#endif
// light.fixup (fixup.c): the fourth counter counts the re-lit pixels
layout(std430, binding = TL_SSBO_FIXUP) buffer tl_fixup_buffer { uvec4 tl_fixup_counters; };

const int TL_K = 1 << TL_UPSAMPLE;
const float TL_UPSAMPLE_CREDIBLE = 0.5; // below it, the pixel is re-lit
const float TL_UPSAMPLE_DEPTH_RELATIVE = 0.01;
const float TL_UPSAMPLE_NORMAL_POWER = 16.0; // cos 10 degrees: 0.78, cos 30 degrees: 0.1
const float TL_UPSAMPLE_LOBE_POWER_MAX = 256.0;

shared uint s_relit[TL_GROUP * TL_GROUP * TL_K * TL_K]; // the group's re-lit pixels, x | y << 16
shared uint s_relit_count;

vec4 tl_upsample_rt0(vec4 t) { return tl_rt0_texel_decode(t); } // normal and gloss, as the light pass decodes them

float tl_upsample_linear(float d)
{
    return tl_depth_linearize(d, u_depth_params.x, u_depth_params.y, u_depth_params.z, u_depth_params.w > 0.5);
}

// One pixel's light sums: diffuse (alpha: the specular luminance, as the light pass writes it),
// specular, Fresnel.
struct tl_upsample_light {
    vec4 d;
    vec3 s, f;
};

void tl_upsample_store(ivec2 px, tl_upsample_light l)
{
    imageStore(u_diffuse_image, px, l.d);
#ifdef TL_SPECULAR_EXACT
    imageStore(u_specular_image, px, vec4(l.s, 0.0));
#ifdef TL_FRESNEL_SUMS
    imageStore(u_fresnel_image, px, vec4(l.f, 0.0));
#endif
#endif
}

tl_upsample_light tl_upsample_texel(ivec2 q)
{
    tl_upsample_light l;
    l.d = texelFetch(u_reduced_diffuse, q, 0);
    l.s = l.f = vec3(0.0);
#ifdef TL_SPECULAR_EXACT
    l.s = texelFetch(u_reduced_specular, q, 0).rgb;
#ifdef TL_FRESNEL_SUMS
    l.f = texelFetch(u_reduced_fresnel, q, 0).rgb;
#endif
#endif
    return l;
}

// The pixel's own sums at its position, normal and gloss, as the light pass at scale 1 (lights_tiled.glsl).
tl_upsample_light tl_upsample_relight(ivec2 px)
{
    float z = tl_upsample_linear(texelFetch(u_depth, px, 0).r);
    vec4 ng = tl_upsample_rt0(texelFetch(u_rt0, px, 0));
    vec2 ndc = (vec2(px) + 0.5) * u_inv_size * 2.0 - 1.0;
    vec3 p = tl_view_position(z, ndc, u_ray_params);
    vec3 v = normalize(-p);
    vec3 diffuse = vec3(0.0), specular = vec3(0.0), fresnel = vec3(0.0);
    tl_tile_lights_add(px, p, ng.xyz, v, tl_lobe_shape(ng.w), diffuse, specular, fresnel);
#ifndef TL_FRESNEL_SUMS
    specular += fresnel; // one sum: Fresnel is applied per pixel
    fresnel = vec3(0.0);
#endif
    return tl_upsample_light(vec4(diffuse, tl_luminance(specular)), specular, fresnel);
}

// The view depth (< 0) of frame pixel px, or 1 for the background and outside the frame.
float tl_upsample_z(ivec2 px, ivec2 fsize)
{
    if (any(lessThan(px, ivec2(0))) || any(greaterThanEqual(px, fsize))) return 1.0;
    float d = texelFetch(u_depth, px, 0).r;
    return d == u_clear_depth ? 1.0 : tl_upsample_linear(d);
}

// The slope of the pixel's plane in view depth per pixel: on each axis the smaller one-sided
// difference to a neighbour on a surface (one across an edge is the larger), 0 without one.
vec2 tl_upsample_slope(ivec2 px, float z, ivec2 fsize)
{
    vec4 n = vec4(tl_upsample_z(px - ivec2(1, 0), fsize), tl_upsample_z(px + ivec2(1, 0), fsize),
                  tl_upsample_z(px - ivec2(0, 1), fsize), tl_upsample_z(px + ivec2(0, 1), fsize));
    vec4 d = vec4(z - n.x, n.y - z, z - n.z, n.w - z);
    d = mix(vec4(1e30), d, lessThan(n, vec4(0.0)));
    vec2 dz = vec2(abs(d.x) < abs(d.y) ? d.x : d.y, abs(d.z) < abs(d.w) ? d.z : d.w);
    return mix(dz, vec2(0.0), greaterThanEqual(abs(dz), vec2(1e29)));
}

// The quad's four texels, read once: where each was lit (frame pixels), its view depth (1: no
// surface, weight 0), RT0 and its normal, and its light.
struct tl_quad {
    vec2 c[4];
    float z[4];
    vec4 rt0[4];
    vec3 n[4];
    tl_upsample_light l[4];
    bool interior; // light_reduce.frag.glsl's flag 32: four texels on one plane with one normal
};

tl_quad tl_upsample_quad(ivec2 base, ivec2 rsize)
{
    tl_quad t;
    for (int j = 0; j < 4; j++) {
        ivec2 q = clamp(base + ivec2(j & 1, j >> 1), ivec2(0), rsize - 1);
        float d = texelFetch(u_light_depth, q, 0).r;
        uint off = uint(texelFetch(u_light_offset, q, 0).r * 255.0 + 0.5) & 31u; // 32: the interior flag
        t.c[j] = off == 16u ? (vec2(q) + 0.5) * float(TL_K) : vec2(q * TL_K + ivec2(off & 3u, off >> 2)) + 0.5;
        t.z[j] = d == u_clear_depth ? 1.0 : tl_upsample_linear(d);
        t.rt0[j] = texelFetch(u_light_rt0, q, 0);
        t.n[j] = tl_upsample_rt0(t.rt0[j]).xyz;
        t.l[j] = tl_upsample_texel(q);
    }
    t.interior = all(greaterThanEqual(base, ivec2(0))) && all(lessThan(base + 1, rsize)) &&
                 (uint(texelFetch(u_light_offset, base, 0).r * 255.0 + 0.5) & 32u) != 0u;
    return t;
}

// Pixel px at (x, y) in the quad's block: its upsampled sums and their weight (< TL_UPSAMPLE_CREDIBLE:
// to be re-lit).
float tl_upsample_pixel(tl_quad t, ivec2 px, ivec2 xy, ivec2 fsize, out tl_upsample_light sums)
{
    vec2 f = (vec2(xy) + 0.5) / float(TL_K);
    vec4 wb = vec4((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
    vec4 rt0 = texelFetch(u_rt0, px, 0);
    vec4 w = wb;
    float total = 1.0;
    if (!t.interior || !tl_rt0_same_normal(t.rt0[0], rt0)) { // else the weights would all be 1
        float z = tl_upsample_linear(texelFetch(u_depth, px, 0).r);
        vec2 dz = tl_upsample_slope(px, z, fsize);
        vec4 ng = tl_upsample_rt0(rt0);
#if defined(TL_SPECULAR_EXACT) || defined(TL_SPECULAR_COMPACT)
        float power = clamp(tl_gloss_to_specular_power(ng.w), TL_UPSAMPLE_NORMAL_POWER, TL_UPSAMPLE_LOBE_POWER_MAX);
#else
        float power = TL_UPSAMPLE_NORMAL_POWER;
#endif
        float tol_z = TL_UPSAMPLE_DEPTH_RELATIVE * abs(z) + 0.5 * float(TL_K) * (abs(dz.x) + abs(dz.y));
        vec2 c = vec2(px) + 0.5;
        total = 0.0;
        for (int j = 0; j < 4; j++) {
            float predicted = z + dot(dz, t.c[j] - c);
            float wz = clamp(1.0 - abs(t.z[j] - predicted) / tol_z, 0.0, 1.0);
            float wn = tl_rt0_same_normal(t.rt0[j], rt0) ? 1.0 : pow(clamp(dot(t.n[j], ng.xyz), 0.0, 1.0), power);
            w[j] = t.z[j] > 0.0 ? 0.0 : wb[j] * wz * wn;
            total += w[j];
        }
    }
    sums = tl_upsample_light(vec4(0.0), vec3(0.0), vec3(0.0));
    for (int j = 0; j < 4; j++) {
        if (w[j] > 0.0) {
            sums.d += w[j] * t.l[j].d;
            sums.s += w[j] * t.l[j].s;
            sums.f += w[j] * t.l[j].f;
        }
    }
    return total;
}

void main()
{
    ivec2 rsize = textureSize(u_light_depth, 0), fsize = textureSize(u_depth, 0);
    ivec2 base = ivec2(gl_GlobalInvocationID.xy) - 1; // texels base .. base + 1, clamped to the buffer
    ivec2 first = base * TL_K + TL_K / 2;            // the frame pixels between their centres
    uint local = gl_LocalInvocationIndex;
    if (local == 0u) s_relit_count = 0u;
    barrier();
    if (all(lessThan(base, rsize)) && all(lessThan(first, fsize))) {
        tl_quad t = tl_upsample_quad(base, rsize);
        for (int i = 0; i < TL_K * TL_K; i++) {
            ivec2 xy = ivec2(i % TL_K, i / TL_K), px = first + xy;
            if (all(greaterThanEqual(px, ivec2(0))) && all(lessThan(px, fsize))) { // base -1: half a block before the frame
                tl_upsample_light sums = tl_upsample_light(vec4(0.0), vec3(0.0), vec3(0.0));
                float total = 1.0;
                if (texelFetch(u_depth, px, 0).r != u_clear_depth) total = tl_upsample_pixel(t, px, xy, fsize, sums);
                // (the background: nothing reads it; zero, as the light pass writes)
                if (total < TL_UPSAMPLE_CREDIBLE) {
                    s_relit[atomicAdd(s_relit_count, 1u)] = uint(px.x) | (uint(px.y) << 16);
                } else {
                    float inv = 1.0 / total;
                    sums.d *= inv;
                    sums.s *= inv;
                    sums.f *= inv;
                    tl_upsample_store(px, sums);
                }
            }
        }
    }
    barrier();
    uint count = s_relit_count;
    for (uint i = local; i < count; i += uint(TL_GROUP * TL_GROUP)) {
        uint at = s_relit[i];
        ivec2 px = ivec2(at & 0xFFFFu, at >> 16);
        tl_upsample_store(px, tl_upsample_relight(px));
    }
    if (local == 0u && count > 0u) atomicAdd(tl_fixup_counters.w, count);
}
