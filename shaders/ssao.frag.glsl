// SSAO estimator (docs/effects.md). TL_SSAO_DISC: the deferred-shading slides' estimator over
// screen-space neighbours p_i on a golden-angle spiral (a Poisson-disc-like set) of the view-space
// radius: AO = sum (1 - A B)^x / n, A = 1 - smoothstep(0, k_d, |p_i - p| - k_b),
// B = max(0, n . (p_i - p) / |p_i - p|). TL_SSAO_HEMISPHERE: points s_i in the normal-oriented
// hemisphere, occluded (o_i = 1) when the surface they project to lies in front of them by more
// than k_b and above p's tangent plane by more than 5 degrees: AO = sum (1 - o_i A_i)^x / n, A_i the same falloff of the surface's distance to p.
// The spiral is rotated per pixel; ssao-blur removes the noise.
#include "effects.glsl"

layout(std140, binding = TL_UBO_PASS) uniform tl_ssao_block {
    vec4 u_ssao; // radius, k_b, k_d, exponent
};

in vec2 v_uv;
layout(location = TL_OUT_AO_RAW) out vec4 o_ao;

// (1 - A b)^x for a neighbour q of p; b is B (disc) or o_i (hemisphere). Coincident or
// non-finite neighbours count as open.
float tl_ssao_term(vec3 p, vec3 q, float b)
{
    float l = length(q - p);
    if (isinf(l) || isnan(l) || isnan(b) || l <= 1e-6 * max(1.0, abs(p.z))) return 1.0;
    float a = 1.0 - smoothstep(0.0, u_ssao.z, l - u_ssao.y);
    return pow(max(1.0 - a * b, 0.0), u_ssao.w);
}

float tl_ssao(ivec2 px, vec3 p, vec3 n)
{
    float height = 1.0 / u_inv_size.y;
    float r_px = min(u_ssao.x * u_ray_params.y * 0.5 * height / max(-p.z, 1e-30), height);
    float turn = 6.2831853 * tl_fx_noise(gl_FragCoord.xy), sum = 0.0;
#ifdef TL_SSAO_HEMISPHERE
    vec3 t = normalize(abs(n.z) < 0.9 ? cross(n, vec3(0.0, 0.0, 1.0)) : cross(n, vec3(1.0, 0.0, 0.0)));
    vec3 bt = cross(n, t);
#endif
    for (int i = 0; i < TL_SSAO_SAMPLES; i++) {
        float f = (float(i) + 0.5) / float(TL_SSAO_SAMPLES), a = float(i) * 2.39996323 + turn;
        vec2 dir = vec2(cos(a), sin(a));
        vec3 q;
        float term = 1.0;
#ifdef TL_SSAO_HEMISPHERE
        vec2 xy = dir * sqrt(f) * 0.95; // cosine-distributed, kept 18 degrees above the tangent plane
        vec3 s = p + (t * xy.x + bt * xy.y + n * sqrt(1.0 - dot(xy, xy))) * (u_ssao.x * mix(0.1, 1.0, f * f));
        vec4 c = u_proj * vec4(s, 1.0);
        if (c.w > 0.0) {
            ivec2 qx = ivec2(floor((c.xy / c.w * 0.5 + 0.5) / u_inv_size));
            // the surface seen there occludes s when it lies in front of s and above p's tangent
            // plane (by more than 5 degrees: a pixel's surface point is not the one behind s, and
            // on a grazing plane the two differ by much of a pixel's depth range)
            if (tl_fx_position(qx, q)) {
                bool above = dot(n, q - p) > 0.087 * length(q - p);
                term = tl_ssao_term(p, q, q.z >= s.z + u_ssao.y && above ? 1.0 : 0.0);
            }
        }
#else
        ivec2 qx = px + ivec2(round(dir * sqrt(f) * r_px));
        if (qx != px && tl_fx_position(qx, q)) {
            vec3 d = q - p;
            float l = length(d);
            term = tl_ssao_term(p, q, l > 0.0 ? max(0.0, dot(n, d) / l) : 0.0);
        }
#endif
        sum += term;
    }
    return sum / float(TL_SSAO_SAMPLES);
}

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 p;
    float ao = 1.0;
    if (tl_fx_position(px, p)) ao = tl_ssao(px, p, tl_fx_normal(px, p));
    o_ao = vec4(isnan(ao) ? 1.0 : clamp(ao, 0.0, 1.0), 0.0, 0.0, 1.0);
}
