// The shadow pass (src/render/shadows/shadows.c): casters' depth into one view of the shadow atlas.
// The view's matrix (world to the view's clip space) is its block at TL_UBO_PASS.
#include "object.glsl"

layout(std140, binding = TL_UBO_PASS) uniform tl_shadow_view_block { mat4 u_shadow_view_proj; };

layout(location = 0) in vec3 a_position;
layout(location = 4) in uint a_object; // one per instance: the draw's base instance

void main() { gl_Position = u_shadow_view_proj * (tl_objects[a_object].model * vec4(a_position, 1.0)); }
