// Full-screen pass vertex shader (directional lights, tone map, FXAA): draw 3 vertices with an
// empty vertex array. TL_FULLSCREEN_DEPTH is the NDC depth of the triangle.
#include "fullscreen.glsl"

#ifndef TL_FULLSCREEN_DEPTH
#define TL_FULLSCREEN_DEPTH 0.0
#endif

out vec2 v_uv;

void main()
{
    vec2 p = tl_fullscreen_position(gl_VertexID);
    v_uv = p * 0.5 + 0.5;
    gl_Position = vec4(p, TL_FULLSCREEN_DEPTH, 1.0);
}
