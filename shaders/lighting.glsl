// Lighting models shared by every mode (docs/renderer.md, docs/lighting.md): Lambert diffuse with
// normalised Blinn-Phong specular, or with GGX specular and spherical area lights; light colours
// have pi folded in, so diffuse radiance = albedo * sum. Every function is pure (no uniforms);
// tests/reference/lighting_ref.c is the double-precision twin the tests compare them with.

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

// ---- GGX (Karis, "Real Shading in Unreal Engine 4", 2013) ------------------------------------

// A point inside (or on) a sphere light is lit as if at distance radius / sqrt(this) from its
// centre (lighting_ref.h TL_REF_SPHERE_MAX_SIN2), so every term stays finite.
const float TL_SPHERE_MAX_SIN2 = 0.9990234375; // 1 - 2^-10

// Trowbridge-Reitz distribution alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2), with the bracket
// written as |n x h|^2 + (n.h)^2 alpha^2: no cancellation at the peak, and insensitive to the
// float rounding of the lengths of n and h. 0 for n.h <= 0.
float tl_ggx_d(vec3 n, vec3 h, float alpha)
{
    float nh = dot(n, h);
    if (!(nh > 0.0)) return 0.0;
    vec3 c = cross(n, h);
    float a2 = alpha * alpha;
    float den = dot(c, c) + nh * nh * a2;
    return a2 / (TL_PI * den * den);
}

// Schlick-GGX Smith visibility G1(n.l) G1(n.v) / (4 n.l n.v), G1(x) = x / (x (1 - k) + k) with
// k = alpha / 2, written without the divisions by n.l and n.v (finite at 0). nl, nv in [0, 1].
float tl_ggx_vis(float nl, float nv, float alpha)
{
    float k = 0.5 * alpha;
    float gl = nl * (1.0 - k) + k;
    float gv = nv * (1.0 - k) + k;
    return 0.25 / (gl * gv);
}

// Schlick's weight s = (1 - v.h)^5: F = F0 + (1 - F0) s = F0 (1 - s) + s.
float tl_fresnel_weight(float vh)
{
    float t = 1.0 - clamp(vh, 0.0, 1.0);
    float t2 = t * t;
    return t2 * t2 * t;
}

// The same weight for unit v and h, with 1 - v.h as |v - h|^2 / 2: accurate where v and h nearly
// coincide (1 - v.h cancels there) and insensitive to the rounding of their lengths.
float tl_fresnel_weight_of(vec3 v, vec3 h)
{
    vec3 d = v - h;
    float t = min(0.5 * dot(d, d), 1.0);
    float t2 = t * t;
    return t2 * t2 * t;
}

vec3 tl_fresnel_schlick(vec3 f0, float cos_theta)
{
    float s = tl_fresnel_weight(cos_theta);
    return f0 * (1.0 - s) + vec3(s);
}

// Windowed falloff without the inverse square: clamp(1 - (d / range)^4, 0, 1)^2.
float tl_falloff_window(float d, float range)
{
    float x = d / range;
    float x2 = x * x;
    float w = clamp(1.0 - x2 * x2, 0.0, 1.0);
    return w * w;
}

// Irradiance of a Lambertian sphere light of unit intensity at squared distance d2 (already
// clamped to >= radius^2 / TL_SPHERE_MAX_SIN2), cos_beta from the normal to the centre: cos / d2
// while the sphere is above the horizon, the exact form factor of its visible part while the
// horizon cuts it (Snyder 1996; Lagarde and de Rousiers, "Moving Frostbite to PBR", 2014), 0 below.
float tl_sphere_irradiance(float cos_beta, float d2, float radius)
{
    float r2 = radius * radius;
    float s = r2 / d2; // sin^2 of the sphere's half-angle
    float c2 = cos_beta * cos_beta;
    if (c2 >= s) return max(cos_beta, 0.0) / d2;
    // The horizon cuts the sphere: s > c2 >= 0, so s > 0 and sin(beta) > 0.
    float sin_b = sqrt(1.0 - c2);
    float x = sqrt(1.0 / s - 1.0);
    float y = -x * cos_beta / sin_b;
    float sy = sqrt(max(1.0 - y * y, 0.0));
    float q = sin_b * sy;
    // acos(y) as atan(sqrt(1 - y^2), y): GLSL leaves acos's precision to the implementation, and
    // llvmpipe's is 1.6e-4 rad against atan's 3.3e-6 (tests/test_lighting_glsl.c measures both)
    float e = (cos_beta * atan(sy, y) - x * q) * s + atan(q, x);
    return max(e, 0.0) / (TL_PI * r2);
}

// Karis' representative point: direction to the point of the sphere (centre at to_light from the
// shaded point) closest to the reflection ray r; `fallback` when that point is the shaded point.
vec3 tl_sphere_specular_dir(vec3 to_light, vec3 r, float radius, vec3 fallback)
{
    float lr = dot(to_light, r);
    vec3 c = lr * r - to_light;
    float c2 = dot(c, c);
    // the ray meets the sphere: the point of the ray closest to the centre, lr r (not to_light + c,
    // which cancels when lr is small against |to_light|)
    vec3 pt = c2 > radius * radius ? to_light + c * (radius * inversesqrt(c2)) : lr * r;
    float len2 = dot(pt, pt);
    return len2 > 1e-12 ? pt * inversesqrt(len2) : fallback;
}

// Karis' energy normalisation of the widened lobe: (alpha / alpha')^2, alpha' = min(alpha +
// radius / (2 d), 1).
float tl_sphere_normalization(float alpha, float radius, float d)
{
    float ap = min(alpha + radius / (2.0 * d), 1.0);
    float q = alpha / ap;
    return q * q;
}

// One light for the GGX model: (diffuse weight, S1 weight, S2 weight). The light pass sums
// colour * weight into the diffuse sum and the two specular sums S1 = sum c w (1 - s) and
// S2 = sum c w s, with w = min(pi D Vis n.l falloff, 4096) and s = (1 - v.h)^5 of each light's own
// half vector; the material pass forms F0 S1 + S2 (tl_ggx_specular_resolve), exactly the sum of
// c w F(v.h). Point and spot lights with source_radius > 0 are spheres: diffuse from the sphere's
// irradiance, specular at the representative point with the energy normalisation, both with the
// distance clamped as TL_SPHERE_MAX_SIN2 says. type: 1 point, 2 spot, 3 directional.
vec3 tl_ggx_light_terms(int type, vec3 p, vec3 n, vec3 v, float alpha, vec3 light_pos, float range,
                        float source_radius, vec3 direction, float cos_inner, float cos_outer)
{
    vec3 lc, ls; // to the light's centre (diffuse) and to its representative point (specular)
    float diffuse, scale = 1.0;
    if (type == 3) {
        lc = -direction;
        ls = lc;
        diffuse = max(dot(n, lc), 0.0);
    } else {
        vec3 to_light = light_pos - p;
        float d2 = dot(to_light, to_light);
        float dist = sqrt(d2);
        lc = dist > 1e-6 ? to_light / dist : n; // a light at the shaded point lights it head-on
        float win = tl_falloff_window(dist, range);
        if (type == 2) win *= tl_spot(lc, direction, cos_inner, cos_outer);
        float r2 = source_radius * source_radius;
        float m = 0.01 * range;
        float d2c = max(d2, max(r2 / TL_SPHERE_MAX_SIN2, m * m));
        diffuse = win * tl_sphere_irradiance(dot(n, lc), d2c, source_radius);
        scale = win / d2c;
        ls = lc;
        if (source_radius > 0.0) {
            ls = tl_sphere_specular_dir(to_light, reflect(-v, n), source_radius, n);
            scale *= tl_sphere_normalization(alpha, source_radius, sqrt(d2c));
        }
    }
    float nl = max(dot(n, ls), 0.0);
    float nv = clamp(dot(n, v), 0.0, 1.0);
    vec3 h = ls + v;
    float hl2 = dot(h, h);
    float spec = 0.0, s = 0.0;
    if (hl2 >= 1e-12 && nl > 0.0) {
        h *= inversesqrt(hl2);
        spec = TL_PI * tl_ggx_d(n, h, alpha) * tl_ggx_vis(nl, nv, alpha) * nl * scale;
        s = tl_fresnel_weight_of(v, h);
    }
    float w = min(spec, TL_LIGHT_CLAMP);
    return vec3(min(diffuse, TL_LIGHT_CLAMP), w * (1.0 - s), w * s);
}

// Material pass, exact layout: F0 S1 + S2 (Schlick is linear in F0).
vec3 tl_ggx_specular_resolve(vec3 f0, vec3 s1, vec3 s2)
{
    return f0 * s1 + s2;
}

// Material pass, cheap layout: one sum S = S1 + S2, Fresnel once per pixel with n.v in place of
// each light's v.h.
vec3 tl_ggx_specular_resolve_nv(vec3 f0, vec3 s, float nv)
{
    return tl_fresnel_schlick(f0, nv) * s;
}

#endif
