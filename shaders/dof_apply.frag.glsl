// Depth of field: the blurred colour back into HDR. The dof target's alpha holds the circle of
// confusion (for readback); HDR's alpha becomes 1, as opaque pixels' already is (no pass after
// the opaque ones reads it).
#include "frame.glsl"

in vec2 v_uv;
layout(binding = TL_UNIT_DOF) uniform sampler2D u_dof;
layout(location = TL_OUT_HDR) out vec4 o_hdr;

void main() { o_hdr = vec4(texelFetch(u_dof, ivec2(gl_FragCoord.xy), 0).rgb, 1.0); }
