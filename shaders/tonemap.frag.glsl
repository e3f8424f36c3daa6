// Pass 4: bloom added (docs/effects.md), exposure, ACES-fitted tone curve (Narkowicz 2015) in linear space, sRGB encoding, and
// gamma-encoded luma in alpha for FXAA (FXAA off: alpha 1, the output is opaque).
#include "frame.glsl"

layout(std140, binding = TL_UBO_PASS) uniform tl_tonemap_block {
    float u_exposure;
    float u_bloom_intensity; // bloom's weight (tl_bloom_desc.intensity)
};

in vec2 v_uv;
#ifdef TL_MSAA_SAMPLES // MSAA: every sample tone-mapped, then averaged (docs/antialiasing.md)
layout(binding = TL_UNIT_HDR) uniform sampler2DMS u_hdr;
#else
layout(binding = TL_UNIT_HDR) uniform sampler2D u_hdr;
#endif
#ifdef TL_BLOOM
layout(binding = TL_UNIT_BLOOM) uniform sampler2D u_bloom_image; // half size, bilinear: the 2x upsample
#endif
#ifdef TL_OUT_LDR
layout(location = TL_OUT_LDR) out vec4 o_ldr;
#else
layout(location = TL_OUT_OUTPUT) out vec4 o_ldr; // FXAA off: straight into the output
#endif

vec3 tl_aces(vec3 x)
{
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

float tl_encode_srgb(float c)
{
    return c <= 0.0031308 ? c * 12.92 : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

// Exposure and the tone curve: linear display values in [0, 1].
vec3 tl_tone(vec3 c)
{
    return tl_aces(clamp(c, vec3(0.0), vec3(65504.0)) * u_exposure);
}

void main()
{
    // Blended FP16 sums can overflow to Inf on hardware that rounds to nearest: Inf is the
    // brightest value, NaN (Inf - Inf never happens here, but be safe) is black.
#ifdef TL_MSAA_SAMPLES
    // a bright sample beside a dark one averages to its coverage of the tone-mapped range, not of
    // radiance (which would saturate the whole pixel); a caller's framebuffer of another size takes
    // the nearest pixel
    ivec2 px = ivec2(v_uv * vec2(textureSize(u_hdr)));
    vec3 l = vec3(0.0);
    for (int k = 0; k < TL_MSAA_SAMPLES; k++) {
        vec3 c = texelFetch(u_hdr, px, k).rgb;
        l += tl_tone(vec3(isnan(c.r) ? 0.0 : c.r, isnan(c.g) ? 0.0 : c.g, isnan(c.b) ? 0.0 : c.b));
    }
    l *= 1.0 / float(TL_MSAA_SAMPLES);
#else
    vec3 c = textureLod(u_hdr, v_uv, 0.0).rgb;
    c = vec3(isnan(c.r) ? 0.0 : c.r, isnan(c.g) ? 0.0 : c.g, isnan(c.b) ? 0.0 : c.b);
#ifdef TL_BLOOM
    c = clamp(c, vec3(0.0), vec3(65504.0)) + u_bloom_intensity * textureLod(u_bloom_image, v_uv, 0.0).rgb;
#endif
    vec3 l = tl_tone(c);
#endif
    vec3 s = vec3(tl_encode_srgb(l.r), tl_encode_srgb(l.g), tl_encode_srgb(l.b));
#ifdef TL_OUT_LDR
    o_ldr = vec4(s, dot(s, vec3(0.299, 0.587, 0.114)));
#else
    o_ldr = vec4(s, 1.0); // the output: opaque
#endif
}
