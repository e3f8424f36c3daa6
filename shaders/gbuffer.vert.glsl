// Geometry passes (G-buffer and material): both use this shader, so that depth EQUAL holds.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;

uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform mat4 u_view;
uniform mat3 u_normal_view; // inverse transpose of (view * model), upper 3x3

out vec3 v_normal;
out vec2 v_uv;
invariant gl_Position;

void main()
{
    gl_Position = u_view_proj * (u_model * vec4(a_position, 1.0));
    v_normal = u_normal_view * a_normal;
#ifdef TL_HAS_UV
    v_uv = a_uv;
#else
    v_uv = vec2(0.0);
#endif
}
