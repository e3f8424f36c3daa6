// Vignette (src/render/passes/pass_vignette.c). TL_VIGNETTE_FACTOR: the factor f = 1 - strength *
// smoothstep(radius, radius + softness, d), d the distance from the centre over the half-diagonal,
// into the vignette target. Otherwise: (0, 0, 0, 1 - f) blended SRC_ALPHA, ONE_MINUS_SRC_ALPHA onto
// HDR, which becomes HDR f. Each draw writes its pass's one target at location 0.
#include "frame.glsl"

layout(std140, binding = TL_UBO_PASS) uniform tl_vignette_block {
    vec4 u_vignette; // strength, radius, softness, 0
};

in vec2 v_uv;
layout(location = 0) out vec4 o_color;

#ifdef TL_VIGNETTE_FACTOR
void main()
{
    float d = length(v_uv * 2.0 - 1.0) * 0.70710678;
    float f = 1.0 - u_vignette.x * smoothstep(u_vignette.y, u_vignette.y + u_vignette.z, d);
    o_color = vec4(f, 0.0, 0.0, 1.0);
}
#else
layout(binding = TL_UNIT_VIGNETTE) uniform sampler2D u_factor;

void main() { o_color = vec4(0.0, 0.0, 0.0, 1.0 - texelFetch(u_factor, ivec2(gl_FragCoord.xy), 0).r); }
#endif
