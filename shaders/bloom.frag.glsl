// Bloom (docs/effects.md, src/render/passes/pass_bloom.c): one of three steps, all sampling bilinearly
// (the taps sit on texel corners, where the bilinear weights are exact).
//   TL_BLOOM_PREFILTER: soft threshold of HDR, then the 13-tap downsample into level 0.
//   TL_BLOOM_DOWN:      the 13-tap downsample of the level above (Jimenez 2014, slide 150): the
//                       centre 4x4 box weighs 1/2, the four overlapping corner boxes 1/8 each.
//   TL_BLOOM_UP:        the 3x3 tent [1 2 1]/4 x [1 2 1]/4 of the coarser level, alpha = scatter
//                       (blended SRC_ALPHA, ONE_MINUS_SRC_ALPHA over the finer level).
#include "frame.glsl"

layout(std140, binding = TL_UBO_PASS) uniform tl_bloom_block {
    vec4 u_bloom; // threshold, knee (absolute), intensity, scatter
};

in vec2 v_uv;
#ifdef TL_BLOOM_PREFILTER
layout(binding = TL_UNIT_HDR) uniform sampler2D u_src;
#else
layout(binding = TL_UNIT_BLOOM) uniform sampler2D u_src;
#endif
layout(location = TL_OUT_BLOOM) out vec4 o_bloom;

// Finite, non-negative, at most the FP16 maximum: one bad pixel must not spread over the chain.
vec3 tl_bloom_sanitize(vec3 c)
{
    c = vec3(isnan(c.r) ? 0.0 : c.r, isnan(c.g) ? 0.0 : c.g, isnan(c.b) ? 0.0 : c.b);
    return clamp(c, vec3(0.0), vec3(65504.0));
}

vec3 tl_bloom_tap(vec2 uv)
{
    vec3 c = textureLod(u_src, uv, 0.0).rgb;
#ifdef TL_BLOOM_PREFILTER
    // Soft knee (the quadratic curve of Unity's bloom): 0 below threshold - knee, the excess above
    // threshold + knee, a quadratic between. Threshold 0 and knee 0 pass the colour unchanged.
    c = tl_bloom_sanitize(c);
    float bright = max(c.r, max(c.g, c.b)), t = u_bloom.x, knee = u_bloom.y;
    float soft = clamp(bright - t + knee, 0.0, 2.0 * knee);
    soft = knee > 0.0 ? soft * soft / (4.0 * knee) : 0.0;
    c *= bright > 0.0 ? max(soft, bright - t) / bright : 0.0;
#endif
    return c;
}

void main()
{
    vec2 texel = 1.0 / vec2(textureSize(u_src, 0));
#ifdef TL_BLOOM_UP
    vec3 s = 4.0 * tl_bloom_tap(v_uv);
    s += 2.0 * (tl_bloom_tap(v_uv + vec2(texel.x, 0.0)) + tl_bloom_tap(v_uv - vec2(texel.x, 0.0)) +
                tl_bloom_tap(v_uv + vec2(0.0, texel.y)) + tl_bloom_tap(v_uv - vec2(0.0, texel.y)));
    s += tl_bloom_tap(v_uv + texel) + tl_bloom_tap(v_uv - texel) + tl_bloom_tap(v_uv + vec2(texel.x, -texel.y)) +
         tl_bloom_tap(v_uv + vec2(-texel.x, texel.y));
    o_bloom = vec4(tl_bloom_sanitize(s * (1.0 / 16.0)), u_bloom.w);
#else
    vec3 e = tl_bloom_tap(v_uv);
    vec3 inner = tl_bloom_tap(v_uv + vec2(-1.0, 1.0) * texel) + tl_bloom_tap(v_uv + vec2(1.0, 1.0) * texel) +
                 tl_bloom_tap(v_uv + vec2(-1.0, -1.0) * texel) + tl_bloom_tap(v_uv + vec2(1.0, -1.0) * texel);
    vec3 corners = tl_bloom_tap(v_uv + vec2(-2.0, 2.0) * texel) + tl_bloom_tap(v_uv + vec2(2.0, 2.0) * texel) +
                   tl_bloom_tap(v_uv + vec2(-2.0, -2.0) * texel) + tl_bloom_tap(v_uv + vec2(2.0, -2.0) * texel);
    vec3 edges = tl_bloom_tap(v_uv + vec2(0.0, 2.0) * texel) + tl_bloom_tap(v_uv + vec2(-2.0, 0.0) * texel) +
                 tl_bloom_tap(v_uv + vec2(2.0, 0.0) * texel) + tl_bloom_tap(v_uv + vec2(0.0, -2.0) * texel);
    // weights: inner 4 x 1/8, centre 1/8, corners 4 x 1/32, edges 4 x 1/16: sum 1
    vec3 s = 0.125 * (inner + e) + 0.03125 * corners + 0.0625 * edges;
    o_bloom = vec4(tl_bloom_sanitize(s), 1.0);
#endif
}
