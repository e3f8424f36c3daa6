// Pass 2: light volumes. One instanced draw per light type: TL_LIGHT_TYPE 1 point (sphere),
// 2 spot (cone), 3 directional (full-screen triangle). Each instance is the light's record
// (tl_light_data, light_eval.glsl) in world space; the fragments get it in view space.
#include "frame.glsl"
#include "fullscreen.glsl"

layout(location = 0) in vec3 a_position;           // unit volume mesh (sphere or cone)
layout(location = 1) in vec4 i_position_radius;    // world
layout(location = 2) in vec4 i_color_type;
layout(location = 3) in vec4 i_direction_cos_outer; // world direction light travels
layout(location = 4) in vec4 i_cos_inner;           // as tl_light_data's

// the light's record, view space (light.frag.glsl)
flat out vec4 f_position_radius;
flat out vec4 f_color_type;
flat out vec4 f_direction_cos_outer;
flat out vec4 f_cos_inner;

void main()
{
    f_position_radius = vec4((u_view * vec4(i_position_radius.xyz, 1.0)).xyz, i_position_radius.w);
    f_color_type = i_color_type;
    f_direction_cos_outer = vec4(normalize(mat3(u_view) * i_direction_cos_outer.xyz), i_direction_cos_outer.w);
    f_cos_inner = i_cos_inner;
#if TL_LIGHT_TYPE == 3 || defined(TL_LIGHT_FULLSCREEN)
    gl_Position = vec4(tl_fullscreen_position(gl_VertexID), 0.0, 1.0);
#elif TL_LIGHT_TYPE == 2
    // Cone: apex at the light, axis +Z of the mesh along the direction; mesh z in [0,1] is scaled
    // by the radius, xy by radius * tan(outer angle) (the mesh already contains the true cone).
    // Past 60 degrees that base grows without bound (at 90, the widest cone a light may have, it
    // is infinite): a 45-degree cone whose apex sits 1.1 radii behind the light contains the whole
    // half ball in front of it instead, so every cone up to 90 degrees is drawn whole
    // (light_volumes.c bounds it alike).
    vec3 w = normalize(i_direction_cos_outer.xyz);
    vec3 a = abs(w.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 u = normalize(cross(a, w));
    vec3 v = cross(w, u);
    float c = clamp(i_direction_cos_outer.w, 0.0, 1.0), r = i_position_radius.w;
    vec3 apex = i_position_radius.xyz;
    float len = r, base = r * sqrt(1.0 - c * c) / max(c, 0.5);
    if (c < 0.5) {
        apex -= w * (1.1 * r);
        len = base = 2.1 * r;
    }
    vec3 world = apex + u * (a_position.x * base) + v * (a_position.y * base) + w * (a_position.z * len);
    gl_Position = u_view_proj * vec4(world, 1.0);
#else
    gl_Position = u_view_proj * vec4(i_position_radius.xyz + a_position * i_position_radius.w, 1.0);
#endif
}
