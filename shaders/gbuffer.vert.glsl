// Every geometry pass (depth pre-pass, G-buffer, material, forward, transparent) uses this vertex
// shader, so that depth EQUAL holds between passes (invariant gl_Position).
#include "frame.glsl"
#include "object.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_tangent;
layout(location = 4) in uint a_object; // one per instance: the draw's base instance
#ifdef TL_VCOLOR
layout(location = 5) in vec4 a_color; // tl_scene.colors
out vec4 v_color;
#endif
#ifdef TL_UV1
layout(location = 6) in vec2 a_uv1; // tl_scene.uv1
out vec2 v_uv1;
#endif

out vec3 v_normal;
out vec2 v_uv;
out vec4 v_tangent;
out vec3 v_view_position;
flat out uint v_object;
invariant gl_Position;

void main()
{
    mat4 model = tl_objects[a_object].model;
    vec4 world = model * vec4(a_position, 1.0);
    gl_Position = u_view_proj * world;
    v_view_position = (u_view * world).xyz;
    v_normal = tl_object_normal_view(a_object) * a_normal;
    v_object = a_object;
#ifdef TL_HAS_UV
    v_uv = a_uv;
#else
    v_uv = vec2(0.0);
#endif
#ifdef TL_VCOLOR
    v_color = a_color;
#endif
#ifdef TL_UV1
    v_uv1 = a_uv1;
#endif
#ifdef TL_NORMAL_MAP
    v_tangent = vec4(mat3(u_view) * (mat3(model) * a_tangent.xyz), a_tangent.w);
#else
    v_tangent = vec4(0.0);
#endif
}
