// MSAA through the light pre-pass (TL_MSAA_LIGHT; docs/antialiasing.md): the material pass runs
// multisampled over the one-sample G-buffer and light buffer. A fragment (one per pixel and
// primitive; its colour goes to the samples it covers) whose surface is the one the G-buffer kept
// at its pixel takes that texel's light, as at one sample: every interior pixel. At an edge the
// fragment of the other surface covers some samples: it takes the light of the 3x3 neighbour texels
// that lie on its plane (the depth predicted along its own screen-space slope) with its normal,
// weighted by those similarities as the light scale's upsample weighs them (light_upsample.glsl);
// with no credible neighbour it is re-lit from its tile's or its object's lights (light_relight.glsl)
// and counted in light.fixup.
#ifndef TL_LIGHT_MSAA_GLSL
#define TL_LIGHT_MSAA_GLSL

#include "light_relight.glsl"

layout(binding = TL_UNIT_DEPTH) uniform sampler2D u_depth;

const float TL_MSAA_CREDIBLE = 0.5;      // the neighbours' weight below it: re-lit
const float TL_MSAA_NORMAL_POWER = 16.0; // as the light scale's upsample (light_upsample.glsl)
const float TL_MSAA_LOBE_POWER_MAX = 256.0;
const float TL_MSAA_SAME_NORMAL = 0.9;   // its own texel: a normal within 25 degrees
// window-depth tolerance beyond half a pixel's slope: 8 steps of D24 (D32F rounds finer)
const float TL_MSAA_DEPTH_EPSILON = 8.0 / 16777215.0;

// How well texel q's depth lies on the fragment's plane: 1 on it, 0 half a pixel's slope away or
// more. Window depth is affine across the screen on a plane: predicted from the fragment's own
// depth at its pixel's centre and its slope (dzw per pixel), no linearisation.
float tl_msaa_depth_weight(ivec2 q, vec2 dzw)
{
    float d = texelFetch(u_depth, q, 0).r;
    float predicted = gl_FragCoord.z + dot(dzw, vec2(q) + 0.5 - gl_FragCoord.xy);
    float tol = 0.5 * (abs(dzw.x) + abs(dzw.y)) + TL_MSAA_DEPTH_EPSILON;
    return d == u_clear_depth ? 0.0 : clamp(1.0 - abs(d - predicted) / tol, 0.0, 1.0);
}

void tl_msaa_fetch(ivec2 q, float w, inout vec4 ld, inout vec3 ls, inout vec3 lf)
{
    ld += w * texelFetch(u_light_diffuse, q, 0);
#ifdef TL_SPECULAR_EXACT
    ls += w * texelFetch(u_light_specular, q, 0).rgb;
#ifdef TL_FRESNEL_SUMS
    lf += w * texelFetch(u_light_fresnel, q, 0).rgb;
#endif
#endif
}

// The light of this fragment (dzw: its window depth's slope, taken before any discard; n_f: its normal, gloss; glossy: a specular material, whose lobe
// sets the normal power). True when it was re-lit from the lists. Its own texel is tested by depth
// and a coarse normal bound alone (every fragment pays it); the neighbours are weighed only where
// that fails, by depth and by cos^power of the normals.
bool tl_msaa_light(vec2 dzw, vec3 n_f, float gloss, bool glossy, out vec3 diffuse, out vec3 specular, out vec3 fresnel)
{
    ivec2 px = ivec2(gl_FragCoord.xy), size = textureSize(u_depth, 0);
    vec4 ld = vec4(0.0);
    vec3 ls = vec3(0.0), lf = vec3(0.0);
    float total = 0.0;
    if (tl_msaa_depth_weight(px, dzw) >= TL_MSAA_CREDIBLE &&
        dot(tl_relight_rt0(texelFetch(u_rt0, px, 0)).xyz, n_f) >= TL_MSAA_SAME_NORMAL) { // exactly the 1x light
        tl_msaa_fetch(px, 1.0, ld, ls, lf);
        total = 1.0;
    } else {
        float power = glossy ? clamp(tl_gloss_to_specular_power(gloss), TL_MSAA_NORMAL_POWER, TL_MSAA_LOBE_POWER_MAX)
                             : TL_MSAA_NORMAL_POWER;
        for (int j = 0; j < 9; j++) {
            ivec2 q = px + ivec2(j % 3 - 1, j / 3 - 1);
            if (j == 4 || any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            float w = tl_msaa_depth_weight(q, dzw);
            if (w <= 0.0) continue;
            w *= pow(clamp(dot(tl_relight_rt0(texelFetch(u_rt0, q, 0)).xyz, n_f), 0.0, 1.0), power);
            tl_msaa_fetch(q, w, ld, ls, lf);
            total += w;
        }
    }
    bool relit = total < TL_MSAA_CREDIBLE;
    if (relit) {
        atomicAdd(tl_fixup_counters.w, 1u);
        tl_relight(n_f, gloss, tl_relight_linear_depth(gl_FragCoord.z), ld, ls, lf);
    } else {
        float inv = 1.0 / total;
        ld *= inv;
        ls *= inv;
        lf *= inv;
    }
    tl_relight_finish(ld, ls, lf, relit, diffuse, specular, fresnel);
    return relit;
}

#endif
