// Reading the thin G-buffer back in the light pass: depth -> view position, RT0 -> normal, gloss.
#include "codec.glsl"

uniform sampler2D u_depth;
uniform sampler2D u_rt0;
uniform vec4 u_depth_params; // a = m[10], b = m[14], c = m[11], reversed (0/1)
uniform vec4 u_ray_params;   // m[0], m[5], m[8], m[9]
uniform vec2 u_inv_size;
uniform float u_clear_depth;

// False for background pixels (depth at the clear value).
bool tl_gbuffer_read(ivec2 px, out vec3 p, out vec3 n, out float gloss)
{
    float d = texelFetch(u_depth, px, 0).r;
    p = vec3(0.0);
    n = vec3(0.0, 0.0, 1.0);
    gloss = 0.0;
    if (d == u_clear_depth) return false;
    float z = tl_depth_linearize(d, u_depth_params.x, u_depth_params.y, u_depth_params.z, u_depth_params.w > 0.5);
    vec2 ndc = (vec2(px) + 0.5) * u_inv_size * 2.0 - 1.0;
    p = tl_view_position(z, ndc, u_ray_params);
    vec4 t = texelFetch(u_rt0, px, 0);
#ifdef TL_RT0_RGB10A2
    uvec4 q = uvec4(t * vec4(1023.0, 1023.0, 1023.0, 3.0) + 0.5);
    vec4 ng = tl_rt0_decode_rgb10a2(q.x | (q.y << 10) | (q.z << 20) | (q.w << 30));
#else
    vec4 ng = tl_rt0_decode_rgba8(tl_unorm8_bytes(t));
#endif
    n = ng.xyz;
    gloss = ng.w;
    return true;
}
