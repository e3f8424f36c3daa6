// Pass 1: thin G-buffer. RT0 = octahedral view-space normal + gloss (codec.glsl).
#include "codec.glsl"

in vec3 v_normal;
in vec2 v_uv;
uniform float u_gloss;
layout(location = 0) out vec4 o_rt0;

void main()
{
    vec3 n = v_normal;
    if (!gl_FrontFacing) n = -n; // double-sided surfaces face the viewer
#ifdef TL_RT0_RGB10A2
    uint t = tl_rt0_encode_rgb10a2(n, u_gloss, 0u);
    o_rt0 = vec4(float(t & 1023u), float((t >> 10) & 1023u), float((t >> 20) & 1023u), float(t >> 30)) /
            vec4(1023.0, 1023.0, 1023.0, 3.0);
#else
    uvec4 b = tl_rt0_encode_rgba8(n, u_gloss);
    o_rt0 = vec4(b) / 255.0;
#endif
}
