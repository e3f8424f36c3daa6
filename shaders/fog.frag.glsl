// Fog from linear depth (docs/effects.md), blended over HDR (SRC_ALPHA, ONE_MINUS_SRC_ALPHA): the
// output is the fog colour with alpha 1 - T, so HDR becomes HDR T + colour (1 - T).
// TL_FOG_DISTANCE: T = exp(-density d), d the distance to the eye. TL_FOG_HEIGHT: density
// sigma(y) = density exp(-falloff (y - height)) integrated along the view ray, in closed form.
// The background is at infinite distance (T = 0, or a finite integral for rays climbing out of
// height fog). TL_FOG_NOISE scales the density by 1 + noise (2 fbm - 1), fbm a 4-octave value noise
// of the world position, drifting with the camera's time.
#include "effects.glsl"

layout(std140, binding = TL_UBO_PASS) uniform tl_fog_block {
    vec4 u_fog_color;  // rgb, density
    vec4 u_fog;        // height, height falloff, noise, noise scale
    vec4 u_fog_motion; // noise speed, the camera's time, 0, 0
};

in vec2 v_uv;
layout(location = TL_OUT_HDR) out vec4 o_fog;

float tl_hash3(vec3 c)
{
    return fract(sin(dot(c, vec3(127.1, 311.7, 74.7))) * 43758.5453);
}

float tl_value_noise(vec3 x)
{
    vec3 i = floor(x), f = fract(x);
    f = f * f * (3.0 - 2.0 * f);
    float a = mix(mix(tl_hash3(i), tl_hash3(i + vec3(1, 0, 0)), f.x),
                  mix(tl_hash3(i + vec3(0, 1, 0)), tl_hash3(i + vec3(1, 1, 0)), f.x), f.y);
    float b = mix(mix(tl_hash3(i + vec3(0, 0, 1)), tl_hash3(i + vec3(1, 0, 1)), f.x),
                  mix(tl_hash3(i + vec3(0, 1, 1)), tl_hash3(i + vec3(1, 1, 1)), f.x), f.y);
    return mix(a, b, f.z);
}

float tl_fbm(vec3 x)
{
    float sum = 0.0, amp = 0.5;
    for (int o = 0; o < 4; o++, amp *= 0.5, x *= 2.03) sum += amp * tl_value_noise(x);
    return sum / 0.9375;
}

// Optical depth along the ray from the eye (world height y0, unit direction's y component dy) over
// distance d (inf: to infinity) of density sigma(y) = density exp(-k (y - h)).
float tl_height_optical_depth(float y0, float dy, float d, float density, float h, float k)
{
    float e0 = exp(-k * (y0 - h));
    float kd = k * dy * d;
    if (!isinf(d) && abs(kd) < 1e-4) return density * e0 * d * (1.0 - 0.5 * kd);
    if (isinf(d) && dy <= 0.0) return uintBitsToFloat(0x7f800000u);
    float e1 = isinf(d) ? 0.0 : exp(-k * (y0 + dy * d - h));
    return density * (e0 - e1) / (k * dy);
}

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    float z = tl_fx_linear_depth(px);
    vec2 ndc = (vec2(px) + 0.5) * u_inv_size * 2.0 - 1.0;
    vec3 ray = tl_view_position(-1.0, ndc, u_ray_params); // the point at linear depth 1
    float d = isinf(z) ? z : z * length(ray);             // distance to the eye
    vec3 dir = normalize(ray);
    mat3 to_world = transpose(mat3(u_view));
    vec3 eye = -(to_world * u_view[3].xyz), dir_w = to_world * dir;
    float density = u_fog_color.a;
#ifdef TL_FOG_NOISE
    vec3 at = (eye + dir_w * min(d, 20.0)) * u_fog.w + vec3(1.0, 0.2, 0.7) * (u_fog_motion.x * u_fog_motion.y);
    density *= 1.0 + u_fog.z * (2.0 * tl_fbm(at) - 1.0);
#endif
#ifdef TL_FOG_HEIGHT
    float tau = tl_height_optical_depth(eye.y, dir_w.y, d, density, u_fog.x, u_fog.y);
#else
    float tau = density * d;
#endif
    float t = isnan(tau) ? 0.0 : exp(-min(tau, 1e30));
    o_fog = vec4(u_fog_color.rgb, 1.0 - t);
}
