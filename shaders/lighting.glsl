// Lighting model shared by every mode (docs/renderer.md): Lambert diffuse and normalised
// Blinn-Phong specular; light colours have pi folded in, so diffuse radiance = albedo * sum.

#ifndef TL_LIGHTING_GLSL
#define TL_LIGHTING_GLSL

const float TL_PI = 3.14159265358979;
// A single light's contribution is clamped here so that one light never overflows FP16 alone.
const float TL_LIGHT_CLAMP = 4096.0;

// Windowed inverse square (scene.h): exactly zero at d = radius, finite at d = 0.
float tl_attenuation(float d, float radius)
{
    float x = d / radius;
    float x2 = x * x;
    float w = clamp(1.0 - x2 * x2, 0.0, 1.0);
    float m = 0.01 * radius;
    return (w * w) / max(d * d, m * m);
}

// Smooth spot cone; `to_light` is the unit vector from the surface to the light.
float tl_spot(vec3 to_light, vec3 direction, float cos_inner, float cos_outer)
{
    float c = dot(-to_light, direction);
    float t = clamp((c - cos_outer) / max(cos_inner - cos_outer, 1e-4), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Normalised Blinn-Phong lobe (n + 8) / (8 pi) * (N.H)^n, with n from the gloss mapping.
float tl_specular_lobe(vec3 n, vec3 l, vec3 v, float power)
{
    vec3 h = l + v;
    float len2 = dot(h, h);
    if (len2 < 1e-12) return 0.0; // light exactly behind the viewer's direction
    float nh = max(dot(n, h * inversesqrt(len2)), 0.0);
    return (power + 8.0) / (8.0 * TL_PI) * pow(nh, power);
}

float tl_luminance(vec3 c)
{
    return dot(c, vec3(0.2126, 0.7152, 0.0722));
}

// Radiance scale of one light at a view-space point: returns (diffuse weight, specular weight)
// to multiply the light colour with. type: 1 point, 2 spot, 3 directional.
vec2 tl_light_terms(int type, vec3 p, vec3 n, vec3 v, float power, vec3 light_pos, float radius,
                    vec3 direction, float cos_inner, float cos_outer)
{
    vec3 l;
    float att = 1.0;
    if (type == 3) {
        l = -direction;
    } else {
        vec3 d = light_pos - p;
        float dist = length(d);
        l = dist > 1e-6 ? d / dist : n; // a light at the shaded point lights it head-on
        att = tl_attenuation(dist, radius);
        if (type == 2) att *= tl_spot(l, direction, cos_inner, cos_outer);
    }
    float nl = max(dot(n, l), 0.0);
    float diffuse = min(att * nl, TL_LIGHT_CLAMP);
    float spec = min(diffuse * tl_specular_lobe(n, l, v, power), TL_LIGHT_CLAMP);
    return vec2(diffuse, spec);
}

#endif
