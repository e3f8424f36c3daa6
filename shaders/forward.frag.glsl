// Forward shading (forward mode, and alpha-blended materials in every mode): each fragment
// evaluates the lights in its object's list (built on the CPU per frame, lights whose range
// reaches the object's bounds). TL_DEPTH_ONLY: the depth pre-pass. TL_TRANSPARENT: alpha out.
#include "codec.glsl"
#include "frame.glsl"
#include "lighting.glsl"
#include "material.glsl"
#include "object.glsl"

#ifndef TL_DEPTH_ONLY
struct tl_forward_light {
    vec4 position_radius;      // view space
    vec4 color_type;           // linear colour, type (1 point, 2 spot, 3 directional)
    vec4 direction_cos_outer;  // view space
    vec4 cos_inner;
};
layout(std430, binding = TL_SSBO_FORWARD_LIGHTS) readonly buffer tl_light_buffer { tl_forward_light tl_lights[]; };
layout(std430, binding = TL_SSBO_FORWARD_INDICES) readonly buffer tl_light_index_buffer { uint tl_light_indices[]; };

layout(location = TL_OUT_HDR) out vec4 o_color;
#endif

void main()
{
    tl_surface s = tl_material_surface();
    if (tl_material_masked(s)) discard;
#ifndef TL_DEPTH_ONLY
    vec3 n = tl_material_normal();
    vec3 p = v_view_position;
    vec3 v = normalize(-p);
    float power = tl_gloss_to_specular_power(s.gloss);
    vec3 diffuse = vec3(0.0), specular = vec3(0.0);
    uint first = tl_objects[v_object].lights.x, count = tl_objects[v_object].lights.y;
    for (uint i = 0u; i < count; i++) {
        tl_forward_light l = tl_lights[tl_light_indices[first + i]];
        vec2 t = tl_light_terms(int(l.color_type.w), p, n, v, power, l.position_radius.xyz, l.position_radius.w,
                                l.direction_cos_outer.xyz, l.cos_inner.x, l.direction_cos_outer.w);
        diffuse += l.color_type.rgb * t.x;
        specular += l.color_type.rgb * t.y;
    }
#ifdef TL_SPECULAR_NONE
    specular = vec3(0.0);
#endif
    vec3 c = s.albedo * (diffuse + u_ambient * s.occlusion) + s.specular * specular + s.emissive;
#ifdef TL_TRANSPARENT
    o_color = vec4(min(c, vec3(65504.0)), clamp(s.alpha, 0.0, 1.0));
#else
    o_color = vec4(min(c, vec3(65504.0)), 1.0);
#endif
#endif
}
