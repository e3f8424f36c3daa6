// Depth of field: the blurred image back into HDR (a copy).
#include "frame.glsl"

in vec2 v_uv;
layout(binding = TL_UNIT_DOF) uniform sampler2D u_dof;
layout(location = TL_OUT_HDR) out vec4 o_hdr;

void main() { o_hdr = texelFetch(u_dof, ivec2(gl_FragCoord.xy), 0); }
