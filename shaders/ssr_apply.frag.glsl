// Screen-space reflections: the reflected radiance added to HDR (blended ONE, ONE).
#include "frame.glsl"

in vec2 v_uv;
layout(binding = TL_UNIT_SSR) uniform sampler2D u_ssr;
layout(location = TL_OUT_HDR) out vec4 o_hdr;

void main() { o_hdr = vec4(texelFetch(u_ssr, ivec2(gl_FragCoord.xy), 0).rgb, 0.0); }
