// The ALU probe (tl_renderer_light_probe; docs/bandwidth.md, "Reading the results"): the light
// function of the tiled loop (light_loop.glsl, tl_light_visit in TL_LIGHTS_SUMS: the range and cone
// tests, then tl_light_data_weights under the plan's lighting model, then the clamped sums) for 8 lights held in
// registers, with no list and no G-buffer read. Each light comes with a surface point inside its
// range and cone and a normal facing it and the eye, so every pair runs the whole function. One
// invocation per pixel, u_probe.y rounds over the 8 lights; the sums are written only when they
// are not finite, so nothing but the evaluations costs.
#include "light_loop.glsl"

layout(local_size_x = 64) in;
// 8 (point, normal with the lobe's shape in w) pairs, one per light of tl_lights[0 .. 7]
layout(std430, binding = TL_SSBO_FORWARD_INDICES) readonly buffer tl_probe_geometry { vec4 tl_probe_surface[16]; };
layout(std430, binding = TL_SSBO_OBJECTS) writeonly buffer tl_probe_result { vec4 tl_probe_sum; };
layout(location = 0) uniform uvec2 u_probe; // invocations, rounds

void main()
{
    uint id = gl_GlobalInvocationID.x;
    if (id >= u_probe.x) return;
    tl_light_data l[8];
    vec3 p[8], n[8];
    float shape = tl_lobe_shape(tl_probe_surface[1].w);
    float jitter = float(id & 1023u) * 1.0e-7;
    for (int k = 0; k < 8; k++) {
        l[k] = tl_lights[k];
        p[k] = tl_probe_surface[2 * k].xyz + vec3(jitter, -jitter, 0.0);
        n[k] = tl_probe_surface[2 * k + 1].xyz;
    }
    tl_light_sums sums = tl_light_sums_zero();
    for (uint it = 0u; it < u_probe.y; it++) {
        float step = float(it) * 1.0e-7;
        for (int k = 0; k < 8; k++) {
            vec3 q = p[k] + vec3(step);
            tl_light_visit(TL_LIGHTS_SUMS, l[k], false, tl_light_point_at(q, n[k], normalize(-q), shape), sums);
        }
    }
    vec3 s = sums.diffuse + sums.specular + sums.fresnel;
    if (any(isnan(s)) || any(isinf(s))) tl_probe_sum = vec4(s, float(id));
}
