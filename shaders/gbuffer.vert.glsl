// Every geometry pass (depth pre-pass, G-buffer, material, forward, transparent) uses this vertex
// shader, so that depth EQUAL holds between passes (invariant gl_Position).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_tangent;

uniform mat4 u_model;
uniform mat4 u_view;
uniform mat4 u_view_proj;
uniform mat3 u_normal_view; // inverse transpose of (view * model), upper 3x3

out vec3 v_normal;
out vec2 v_uv;
out vec4 v_tangent;
out vec3 v_view_position;
invariant gl_Position;

void main()
{
    vec4 world = u_model * vec4(a_position, 1.0);
    gl_Position = u_view_proj * world;
    v_view_position = (u_view * world).xyz;
    v_normal = u_normal_view * a_normal;
#ifdef TL_HAS_UV
    v_uv = a_uv;
#else
    v_uv = vec2(0.0);
#endif
#ifdef TL_NORMAL_MAP
    v_tangent = vec4(mat3(u_view) * (mat3(u_model) * a_tangent.xyz), a_tangent.w);
#else
    v_tangent = vec4(0.0);
#endif
}
