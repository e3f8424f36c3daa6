// The one light loop (docs/frame.md, "One light loop"): every pass that sums lights walks them
// here and adds each with the visitor of its mode, so each of these is written once:
//   the reach test     tl_light_reaches: range, and cone for a spot (the volumes discard elsewhere);
//   the shadow gate    tl_light_visibility: a casting light's shadow where its terms are not zero;
//   the accumulation   tl_light_sums: one light's FP16-clamped (or float) terms, their sum, the
//                      Fresnel fold, the deferred radiance, the coat's sum;
//   the tile walk      tl_tile_lights_walk: directional lights, then each chunk's list of the tile;
//   the object walk    tl_object_lights_walk: an object's light list (where object.glsl is included first).
// The visitor (tl_light_visit) is chosen by a mode, a constant at every call: once inlined, each
// program keeps only its own. Models: fat_models.glsl (the deferred modes' per-model radiance) and
// material_models.glsl (forward's model terms) are included before this file where used.
#ifndef TL_LIGHT_LOOP_GLSL
#define TL_LIGHT_LOOP_GLSL

#include "light_eval.glsl"
#include "tiles.glsl" // the lights block and the tile lists
#ifdef TL_SHADOWS
#include "shadow.glsl"
#endif

const vec3 TL_FP16_MAX = vec3(65504.0);

// Whether light l (of `type`) can reach p: inside its range, and its cone for a spot.
bool tl_light_reaches(tl_light_data l, int type, vec3 p)
{
    if (type == 3) return true;
    vec3 to_light = l.position_radius.xyz - p;
    float d2 = dot(to_light, to_light);
    if (d2 >= l.position_radius.w * l.position_radius.w) return false;
    return !(type == 2 && d2 > 0.0 && dot(-to_light, l.direction_cos_outer.xyz) <= l.direction_cos_outer.w * sqrt(d2));
}

// One light's weights at p (tl_light_data_weights), zero where it cannot reach p.
vec3 tl_light_reached_weights(tl_light_data l, int type, vec3 p, vec3 n, vec3 v, float shape)
{
    if (!tl_light_reaches(l, type, p)) return vec3(0.0);
    return tl_light_data_weights(l, type, p, n, v, shape);
}

// The shadow gate: a casting light's (its slot in cos_inner.z) visibility at p where `lit`, else 1.
// One light's radiance is linear in its visibility, whatever the model.
float tl_light_visibility(tl_light_data l, int type, vec3 p, vec3 n, bool lit)
{
#ifdef TL_SHADOWS
    if (l.cos_inner.z > 0.0 && lit)
        return tl_light_shadow(l.cos_inner.z, type, p, n, l.position_radius.xyz, l.direction_cos_outer.xyz);
#endif
    return 1.0;
}

// Light sums: the colour times tl_light_data_weights's x (diffuse, times albedo), y (specular,
// times F0) and z (specular added as it is: GGX's Schlick part).
struct tl_light_sums {
    vec3 diffuse;
    vec3 specular;
    vec3 fresnel;
};

tl_light_sums tl_light_sums_zero() { return tl_light_sums(vec3(0.0), vec3(0.0), vec3(0.0)); }

// One light's terms t in colour `color`. `clamped`: each at most the FP16 maximum (an Inf would
// poison every later sum: the light passes and the re-lighting); forward sums in float and clamps
// its output.
tl_light_sums tl_light_sums_of(vec3 color, vec3 t, bool clamped)
{
    tl_light_sums s = tl_light_sums(color * t.x, color * t.y, color * t.z);
    if (clamped) {
        s.diffuse = min(s.diffuse, TL_FP16_MAX);
        s.specular = min(s.specular, TL_FP16_MAX);
        s.fresnel = min(s.fresnel, TL_FP16_MAX);
    }
    return s;
}

void tl_light_sums_add(inout tl_light_sums s, tl_light_sums one)
{
    s.diffuse += one.diffuse;
    s.specular += one.specular;
    s.fresnel += one.fresnel;
}

// Without TL_FRESNEL_SUMS, one specular sum: Fresnel is applied per pixel.
void tl_light_sums_fold(inout tl_light_sums s)
{
#ifndef TL_FRESNEL_SUMS
    s.specular += s.fresnel;
    s.fresnel = vec3(0.0);
#endif
}

// The radiance of sums s on a surface of albedo and F0 `spec_color`, clamped: the deferred modes'.
vec3 tl_light_sums_radiance(tl_light_sums s, vec3 albedo, vec3 spec_color)
{
#ifdef TL_SPECULAR_NONE
    spec_color = vec3(0.0);
    s.fresnel = vec3(0.0);
#endif
    return min(albedo * s.diffuse + spec_color * s.specular + s.fresnel, TL_FP16_MAX);
}

// The coat's sum of one light (TL_COAT_SUMS): its specular S1 + S2 at the coat's lobe, clamped.
vec3 tl_light_coat(vec3 color, vec3 t) { return min(color * (t.y + t.z), TL_FP16_MAX); }

// The surface point a walk lights, and (fat_models.glsl) the pixel's material model.
struct tl_light_point {
    vec3 p;
    vec3 n;
    vec3 v;
    float shape;
#ifdef TL_FAT_MODELS_GLSL
    tl_fat_model fm;
    vec3 albedo;
    vec3 spec_color;
#endif
};

tl_light_point tl_light_point_at(vec3 p, vec3 n, vec3 v, float shape)
{
    tl_light_point at;
    at.p = p;
    at.n = n;
    at.v = v;
    at.shape = shape;
    return at;
}

// What a walk does with each light (tl_light_visit):
const int TL_LIGHTS_SUMS = 0;    // reach test, shadow gate, FP16-clamped sums: tiled, re-lighting
const int TL_LIGHTS_PLAIN = 1;   // FP16-clamped sums, no reach test or shadow: the stipple's re-lighting
const int TL_LIGHTS_COAT = 2;    // the coat's sums into .specular, no reach test or shadow: the stipple's
const int TL_LIGHTS_FORWARD = 3; // shadow gate, float sums, the material model's own terms: forward
const int TL_LIGHTS_MODELS = 4;  // reach test, radiance under the pixel's model (fat_models.glsl), shadow gate, into .diffuse

// One light l added to s. `shadowed`: l may cast (false: the gate's code is left out).
void tl_light_visit(int mode, tl_light_data l, bool shadowed, tl_light_point at, inout tl_light_sums s)
{
    int type = int(l.color_type.w);
#ifdef TL_FAT_MODELS_GLSL
    if (mode == TL_LIGHTS_MODELS) {
        vec3 c = vec3(0.0);
        if (tl_light_reaches(l, type, at.p))
            c = tl_fat_model_radiance(at.fm, l, type, at.p, at.n, at.v, at.shape, at.albedo, at.spec_color);
        if (shadowed) c *= tl_light_visibility(l, type, at.p, at.n, c != vec3(0.0));
        s.diffuse += c;
        return;
    }
#endif
    if (mode == TL_LIGHTS_FORWARD) {
        vec3 t = tl_light_data_weights(l, type, at.p, at.n, at.v, at.shape);
#if defined(TL_MATERIAL_MODELS_GLSL) && defined(TL_MATERIAL_MODELS) && defined(TL_FORWARD)
        bool lit = true; // a model's own terms (wrap, sheen) may reach past the standard ones
#else
        bool lit = t != vec3(0.0);
#endif
        float vis = shadowed ? tl_light_visibility(l, type, at.p, at.n, lit) : 1.0;
        t *= vis;
        tl_light_sums_add(s, tl_light_sums_of(l.color_type.rgb, t, false));
#if defined(TL_MATERIAL_MODELS_GLSL) && defined(TL_MATERIAL_MODELS) && defined(TL_FORWARD)
        tl_model_light_add(l, at.p, at.n, at.v, vis);
#endif
        return;
    }
    if (mode == TL_LIGHTS_SUMS) {
        vec3 t = tl_light_reached_weights(l, type, at.p, at.n, at.v, at.shape);
        if (shadowed) t *= tl_light_visibility(l, type, at.p, at.n, t != vec3(0.0));
        tl_light_sums_add(s, tl_light_sums_of(l.color_type.rgb, t, true));
        return;
    }
    vec3 t = tl_light_data_weights(l, type, at.p, at.n, at.v, at.shape);
    if (mode == TL_LIGHTS_COAT) s.specular += tl_light_coat(l.color_type.rgb, t);
    else tl_light_sums_add(s, tl_light_sums_of(l.color_type.rgb, t, true));
}

// The directional lights, then every light of the lists of frame pixel px's tile, chunk by chunk in
// their order (a list that overflowed: every local light of its chunk), skipping the entries whose
// block mask lacks px's block. The casting local lights come first in the lights block
// (u_light_counts.z ends them), so a list starts with them: only that first run of a list carries
// the shadow lookup's code, which llvmpipe would otherwise run (masked) for every light of the
// list. After it, the modes with a reach test read a light's position and range alone and the
// rest of its record only where it reaches p (llvmpipe reads each field of a record as a gather).
void tl_tile_lights_walk(int mode, ivec2 px, tl_light_point at, inout tl_light_sums s)
{
    for (uint i = 0u; i < u_light_counts.x; i++) tl_light_visit(mode, tl_lights[i], true, at, s);
    uint tile = tl_tile_index(px), bit = tl_tile_block_bit(px), chunks = tl_tile_chunks();
    bool reach_first = mode == TL_LIGHTS_SUMS || mode == TL_LIGHTS_MODELS;
    for (uint c = 0u; c < chunks; c++) {
        uvec2 h = tl_tile_headers[tl_tile_header_index(tile, c)];
        uint count = tl_tile_list_size(h, c), k = 0u;
#ifdef TL_SHADOWS
        for (; k < count; k++) {
            uint e = tl_tile_list_entry(h, k), i = tl_tile_entry_light(e, c);
            if (i >= u_light_counts.z) break;
            if ((e & bit) != 0u) tl_light_visit(mode, tl_lights[i], true, at, s);
        }
#endif
        for (; k < count; k++) {
            uint e = tl_tile_list_entry(h, k), i = tl_tile_entry_light(e, c);
            if ((e & bit) != 0u && (!reach_first || tl_light_range_reaches(i, at.p)))
                tl_light_visit(mode, tl_lights[i], false, at, s);
        }
    }
}

#ifdef TL_OBJECT_GLSL // the per-object data (object.glsl), included before this file
// Per-object light lists (forward_lists.c): an object's lights are `count` indices from `first`.
layout(std430, binding = TL_SSBO_FORWARD_INDICES) readonly buffer tl_light_index_buffer { uint tl_light_indices[]; };

void tl_object_lights_walk(int mode, uint first, uint count, tl_light_point at, inout tl_light_sums s)
{
    for (uint k = 0u; k < count; k++) tl_light_visit(mode, tl_lights[tl_light_indices[first + k]], true, at, s);
}
#endif

#endif
