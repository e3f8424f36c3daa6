// MSAA through the light pre-pass (TL_MSAA_LIGHT; docs/antialiasing.md): the material pass runs
// multisampled over the one-sample G-buffer and light buffer. A fragment (one per pixel and
// primitive; its colour goes to the samples it covers) whose surface is the one the G-buffer kept
// at its pixel's centre takes that texel's light, exactly as at one sample: every interior pixel.
// At an edge, the fragment of the other surface (its depth off the texel's, or its normal) is re-lit
// from its tile's or its object's lights (light_relight.glsl), as forward would light it, and
// counted in light.fixup. Measured on the crypt (640x360, 4 samples, 72 lights, tiles): taking a
// neighbour texel of the same plane and normal instead (the light scale's upsample weights over the
// 3x3 texels) was both slower (material pass 531 against 268 ms: llvmpipe runs the search for every
// SIMD block an edge crosses) and further from forward's samples (51.2 against 55.2 dB).
#ifndef TL_LIGHT_MSAA_GLSL
#define TL_LIGHT_MSAA_GLSL

#include "light_relight.glsl"

#ifdef TL_LIGHT_SAMPLES
// MSAA with per-sample lighting on edges (pass_msaa.c): depth, RT0 and the light buffer have
// TL_LIGHT_SAMPLES samples, an edge pixel's light lit per sample. A fragment takes the light of the
// first sample it covers that holds its surface (each sample's depth within the fragment's slope
// over the sample's offset from the centre), else of any such sample, else it is re-lit as below.
// (The material pass's sampler2D light buffer is unused in this variant: these read its units.)
layout(binding = TL_UNIT_DEPTH) uniform sampler2DMS u_depth;
layout(binding = TL_UNIT_LIGHT_DIFFUSE) uniform sampler2DMS u_light_diffuse_ms;
layout(binding = TL_UNIT_LIGHT_SPECULAR) uniform sampler2DMS u_light_specular_ms;
layout(binding = TL_UNIT_LIGHT_FRESNEL) uniform sampler2DMS u_light_fresnel_ms;
#else
layout(binding = TL_UNIT_DEPTH) uniform sampler2D u_depth;
#endif

const float TL_MSAA_SAME_DEPTH = 0.5;  // the depth weight below it: another surface
const float TL_MSAA_SAME_NORMAL = 0.9; // a normal further than 25 degrees: another surface (a crease)
// Window-depth rounding: D24 stores 2^-24 steps, float depth the interpolated value (relative)
#ifdef TL_DEPTH_FLOAT
#define TL_MSAA_DEPTH_EPSILON(z) (abs(z) * 1.0e-6)
#else
#define TL_MSAA_DEPTH_EPSILON(z) (4.0 / 16777215.0)
#endif

// Whether the G-buffer's texel at this pixel (sample s with TL_LIGHT_SAMPLES) holds this
// fragment's surface: its depth on the fragment's plane within half a pixel's slope (dzw: window
// depth per pixel; window depth is affine on a plane, so no linearisation; a mesh's neighbouring
// facet, extrapolated to the centre, stays within it; a sample, off the centre by less than half
// a pixel per axis, within the whole of it) and its normal within 25 degrees of the fragment's (n_f).
bool tl_msaa_same_surface(ivec2 px, int s, vec2 dzw, vec3 n_f)
{
    float d = texelFetch(u_depth, px, s).r;
    float tol = 0.5 * (abs(dzw.x) + abs(dzw.y)) + TL_MSAA_DEPTH_EPSILON(gl_FragCoord.z);
#ifdef TL_LIGHT_SAMPLES
    bool depth = d != u_clear_depth && abs(d - gl_FragCoord.z) <= tol;
#else
    float wz = d == u_clear_depth ? 0.0 : clamp(1.0 - abs(d - gl_FragCoord.z) / tol, 0.0, 1.0);
    bool depth = wz >= TL_MSAA_SAME_DEPTH;
#endif
    return depth && dot(tl_relight_rt0(texelFetch(u_rt0, px, s)).xyz, n_f) >= TL_MSAA_SAME_NORMAL;
}

// The sample whose light this fragment takes (0 at one sample), -1 for none.
int tl_msaa_own_sample(ivec2 px, vec2 dzw, vec3 n_f)
{
#ifdef TL_LIGHT_SAMPLES
    for (int s = 0; s < TL_LIGHT_SAMPLES; s++)
        if ((gl_SampleMaskIn[0] & (1 << s)) != 0 && tl_msaa_same_surface(px, s, dzw, n_f)) return s;
    for (int s = 0; s < TL_LIGHT_SAMPLES; s++)
        if (tl_msaa_same_surface(px, s, dzw, n_f)) return s;
    return -1;
#else
    return tl_msaa_same_surface(px, 0, dzw, n_f) ? 0 : -1;
#endif
}

// Adds the light of sample s of pixel px to the sums.
void tl_msaa_light_add(ivec2 px, int s, inout vec4 ld, inout vec3 ls, inout vec3 lf)
{
#ifdef TL_LIGHT_SAMPLES
    ld += texelFetch(u_light_diffuse_ms, px, s);
#ifdef TL_SPECULAR_EXACT
    ls += texelFetch(u_light_specular_ms, px, s).rgb;
#ifdef TL_FRESNEL_SUMS
    lf += texelFetch(u_light_fresnel_ms, px, s).rgb;
#endif
#endif
#else
    tl_light_texel_add(px, 1.0, ld, ls, lf);
#endif
}

// The light of this fragment (dzw: its window depth's slope, taken before any discard; n_f: its
// normal; gloss). True when it was re-lit from the lists.
bool tl_msaa_light(vec2 dzw, vec3 n_f, float gloss, out vec3 diffuse, out vec3 specular, out vec3 fresnel)
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 ld = vec4(0.0);
    vec3 ls = vec3(0.0), lf = vec3(0.0);
    int s = tl_msaa_own_sample(px, dzw, n_f);
    bool relit = s < 0;
    if (relit) {
        atomicAdd(tl_fixup_counters.w, 1u);
        tl_relight(n_f, gloss, tl_relight_linear_depth(gl_FragCoord.z), ld, ls, lf);
    } else {
        tl_msaa_light_add(px, s, ld, ls, lf);
    }
    tl_relight_finish(ld, ls, lf, relit, diffuse, specular, fresnel);
    return relit;
}

#endif
