// Depth-aware blur of the SSAO estimate: a (2r+1)^2 box whose taps count with weight
// max(0, 1 - |z_q - z_p| / (0.05 z_p)), so occlusion does not leak across depth edges.
#include "effects.glsl"

in vec2 v_uv;
layout(binding = TL_UNIT_AO_RAW) uniform sampler2D u_ao_raw;
layout(location = TL_OUT_AO) out vec4 o_ao;

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy), size = textureSize(u_ao_raw, 0);
    float zc = tl_fx_linear_depth(px);
    float sum = 0.0, wsum = 0.0;
    if (!isinf(zc)) {
        for (int y = -TL_SSAO_BLUR_RADIUS; y <= TL_SSAO_BLUR_RADIUS; y++)
            for (int x = -TL_SSAO_BLUR_RADIUS; x <= TL_SSAO_BLUR_RADIUS; x++) {
                ivec2 q = clamp(px + ivec2(x, y), ivec2(0), size - 1);
                float w = max(0.0, 1.0 - abs(tl_fx_linear_depth(q) - zc) / (0.05 * abs(zc) + 1e-30));
                if (isnan(w)) continue;
                sum += w * texelFetch(u_ao_raw, q, 0).r;
                wsum += w;
            }
    }
    float ao = wsum > 0.0 ? sum / wsum : 1.0;
    o_ao = vec4(isnan(ao) ? 1.0 : clamp(ao, 0.0, 1.0), 0.0, 0.0, 1.0);
}
