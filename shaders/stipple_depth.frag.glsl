// The stipple's first pass: the opaque surfaces' depth copied into opaque.depth before the
// transparent layers overwrite some of DEPTH's pixels; the material pass and the resolve test
// against the copy, at EQUAL, so the copy must be exact: a D24 value k / (2^24 - 1) is written a
// quarter step above k, which conversions that round and those that truncate (llvmpipe) both take
// back to k; a D32F value is copied as it is.
#include "frame.glsl"

layout(binding = TL_UNIT_DEPTH) uniform sampler2D u_depth;

void main()
{
    float d = texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r;
#ifdef TL_DEPTH_UNORM24
    const float steps = 16777215.0;
    d = d >= 1.0 ? 1.0 : (floor(d * steps + 0.5) + 0.25) / steps;
#endif
    gl_FragDepth = d;
}
