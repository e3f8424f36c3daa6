// The stipple's filters (docs/frame.md, "2d. Transparency through the light buffer"): the light of
// a surface from the G-buffer samples that belong to it. A sample belongs by its depth, on the
// fragment's plane (screen-space derivatives of the view depth, as the light scale's upsample), and
// its RT0 normal against the fragment's, raised to the lobe's power (a crease weighs 0). Every
// weight is >= 0 and the sums are normalised, so the result is a convex combination of the light at
// the samples: its error is at most the light's range over them (the tests' bound).
//   - tl_stipple_opaque: an opaque pixel whose sample a layer took takes the 4 nearest (0, 0)
//     pixels, which no layer owns: its quad's and its neighbours' (two at an edge, four at a corner
//     of the quad, at equal weights: exact where the light varies linearly);
//   - tl_stipple_layer_light: a transparent fragment takes the 4 nearest pixels of its own layer.
// Both are bilinear on a lattice of every other pixel.
// Below TL_STIPPLE_CREDIBLE the caller lights the fragment itself from its object's lights.
// TL_STIPPLE_COAT (the clearcoat's material program with the coat's own sums, coat_sums.glsl): each
// gather also sums the coat's light with its weights into tl_stipple_coat.
#ifndef TL_STIPPLE_GATHER_GLSL
#define TL_STIPPLE_GATHER_GLSL

#include "codec.glsl"
#include "frame.glsl"
#include "lighting.glsl"
#include "stipple.glsl"

layout(binding = TL_UNIT_DEPTH) uniform sampler2D u_stipple_depth;
layout(binding = TL_UNIT_RT0) uniform sampler2D u_stipple_rt0;
layout(binding = TL_UNIT_LIGHT_DIFFUSE) uniform sampler2D u_stipple_diffuse;
layout(binding = TL_UNIT_LIGHT_SPECULAR) uniform sampler2D u_stipple_specular;
layout(binding = TL_UNIT_LIGHT_FRESNEL) uniform sampler2D u_stipple_fresnel;
#ifdef TL_STIPPLE_COAT
layout(binding = TL_UNIT_LIGHT_COAT) uniform sampler2D u_stipple_light_coat;
vec3 tl_stipple_coat; // the last gather's weighted sum of the coat's light (not normalised)
#endif

const float TL_STIPPLE_CREDIBLE = 0.5;
const float TL_STIPPLE_DEPTH_RELATIVE = 0.005;
const float TL_STIPPLE_NORMAL_POWER = 16.0;
const float TL_STIPPLE_LOBE_POWER_MAX = 256.0;
const float TL_STIPPLE_SAME_DEPTH = 1.0 / 8388608.0; // two D24 steps: the sample is the fragment's own

float tl_stipple_linear_depth(float d)
{
    return tl_depth_linearize(d, u_depth_params.x, u_depth_params.y, u_depth_params.z, u_depth_params.w > 0.5);
}

vec3 tl_stipple_normal(vec4 t) { return tl_rt0_texel_decode(t).xyz; } // as the light pass decodes RT0

// cos^power falls as a specular lobe does: a highlight is not carried across normals it tells apart
float tl_stipple_power(bool glossy, float gloss)
{
    return glossy ? clamp(tl_gloss_to_specular_power(gloss), TL_STIPPLE_NORMAL_POWER, TL_STIPPLE_LOBE_POWER_MAX)
                  : TL_STIPPLE_NORMAL_POWER;
}

// How much the sample at q belongs to this fragment's surface (view depth z_f, slope dz, normal n_f).
float tl_stipple_weight(ivec2 q, float z_f, vec2 dz, vec3 n_f, float power)
{
    float d = texelFetch(u_stipple_depth, q, 0).r;
    if (d == u_clear_depth) return 0.0;
    float predicted = z_f + dot(dz, vec2(q) + 0.5 - gl_FragCoord.xy);
    float tol = TL_STIPPLE_DEPTH_RELATIVE * abs(z_f) + 0.5 * (abs(dz.x) + abs(dz.y));
    float wz = clamp(1.0 - abs(tl_stipple_linear_depth(d) - predicted) / tol, 0.0, 1.0);
    if (wz <= 0.0) return 0.0;
    return wz * pow(clamp(dot(tl_stipple_normal(texelFetch(u_stipple_rt0, q, 0)), n_f), 0.0, 1.0), power);
}

void tl_stipple_add(ivec2 q, float w, inout vec4 ld, inout vec3 ls, inout vec3 lf)
{
    ld += w * texelFetch(u_stipple_diffuse, q, 0);
#ifdef TL_SPECULAR_EXACT
    ls += w * texelFetch(u_stipple_specular, q, 0).rgb;
#ifdef TL_FRESNEL_SUMS
    lf += w * texelFetch(u_stipple_fresnel, q, 0).rgb;
#endif
#endif
#ifdef TL_STIPPLE_COAT
    tl_stipple_coat += w * texelFetch(u_stipple_light_coat, q, 0).rgb;
#endif
}

bool tl_stipple_inside(ivec2 q, ivec2 size) { return all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size)); }

// The light sums of the surface at this fragment from the 4 nearest pixels of the lattice
// slot + 2 (i, j), bilinear weights times tl_stipple_weight; returns their weight. `taps` 0 (the
// pixel's own sample will do) skips the loop; the bound is not a constant, so the loop is not
// unrolled, and llvmpipe, which runs both sides of a branch for every lane, runs one iteration of
// it for a group where no lane gathers rather than four (docs/frame.md 2d measures what is left).
float tl_stipple_lattice(ivec2 slot, int taps, float z_f, vec2 dz, vec3 n_f, float power, out vec4 ld, out vec3 ls,
                         out vec3 lf)
{
    ld = vec4(0.0);
    ls = lf = vec3(0.0);
#ifdef TL_STIPPLE_COAT
    tl_stipple_coat = vec3(0.0);
#endif
    ivec2 size = textureSize(u_stipple_depth, 0);
    vec2 r = (floor(gl_FragCoord.xy) - vec2(slot)) * 0.5; // pixel slot + 2 i sits at lattice point i
    vec2 base = floor(r), f = r - base;
    float total = 0.0;
    for (int j = 0; j < taps; j++) {
        ivec2 o = ivec2(j & 1, j >> 1), q = slot + 2 * (ivec2(base) + o);
        float wb = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
        if (wb <= 0.0 || !tl_stipple_inside(q, size)) continue;
        float w = wb * tl_stipple_weight(q, z_f, dz, n_f, power);
        if (w <= 0.0) continue;
        tl_stipple_add(q, w, ld, ls, lf);
        total += w;
    }
    return total;
}

// An opaque fragment: its own sample where no layer took it (no layer owns (0, 0)), else the
// opaque lattice (0, 0) around it: its quad's and the neighbouring quads' (0, 0) pixels.
float tl_stipple_opaque(float z_f, vec2 dz, vec3 n_f, float power, out vec4 ld, out vec3 ls, out vec3 lf)
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    bool own = ((px.x | px.y) & 1) == 0 || abs(texelFetch(u_stipple_depth, px, 0).r - gl_FragCoord.z) <= TL_STIPPLE_SAME_DEPTH;
    float total = tl_stipple_lattice(ivec2(0), own ? 0 : 4, z_f, dz, n_f, power, ld, ls, lf);
    if (own) {
        tl_stipple_add(px, 1.0, ld, ls, lf);
        total = 1.0;
    }
    return total;
}

// A transparent fragment of `layer`: the 4 nearest pixels its layer owns.
float tl_stipple_layer_light(uint layer, float z_f, vec2 dz, vec3 n_f, float power, out vec4 ld, out vec3 ls, out vec3 lf)
{
    bool any_layer = layer >= 1u && layer <= 3u;
    return tl_stipple_lattice(tl_stipple_slot(layer), any_layer ? 4 : 0, z_f, dz, n_f, power, ld, ls, lf);
}

vec3 tl_stipple_finite(vec3 c)
{
    return vec3(isinf(c.r) || isnan(c.r) ? 65504.0 : c.r, isinf(c.g) || isnan(c.g) ? 65504.0 : c.g,
                isinf(c.b) || isnan(c.b) ? 65504.0 : c.b);
}

// The normalised sums as the material pass reads the light buffer: diffuse; specular (S1, the sum
// S1 + S2 under n.v, the compact layout's recoloured luminance); Fresnel's S2 with two sums.
void tl_stipple_finish(float total, vec4 ld, vec3 ls, vec3 lf, out vec3 diffuse, out vec3 specular, out vec3 fresnel)
{
    float inv = 1.0 / total;
    diffuse = tl_stipple_finite(ld.rgb * inv);
    specular = fresnel = vec3(0.0);
#if defined(TL_SPECULAR_EXACT)
    specular = tl_stipple_finite(ls * inv);
#ifdef TL_FRESNEL_SUMS
    fresnel = tl_stipple_finite(lf * inv);
#endif
#elif defined(TL_SPECULAR_COMPACT)
    float lum = tl_luminance(diffuse);
    specular = lum > 1e-8 ? diffuse * (min(ld.a * inv, 65504.0) / lum) : vec3(0.0);
#endif
}

#endif
