// The tiled light pass's work for one pixel: the G-buffer read and decoded once, then the
// directional lights and the pixel's tile list (every visible local light for a tile whose list
// overflowed), summed in float and written once. Each light's terms and its clamp are those of
// the light volumes (light.frag.glsl), so the strategies differ only in summation order and FP16
// rounding. TL_LIGHT_ACCUM, TL_LIGHT_SHADE_THIN or TL_LIGHT_SHADE_FAT as for the volumes.
#include "gbuffer_decode.glsl"
#include "light_eval.glsl" // first here: files are included once, at their first #include
#if defined(TL_MATERIAL_MODELS) && !defined(TL_LIGHT_ACCUM)
#include "fat_models.glsl" // each light under the pixel's material model (before the loop: its visitor)
#endif
#include "light_loop.glsl"

struct tl_tiled_result {
    bool surface;   // false: background, nothing to add
    vec3 diffuse;   // light sum (accumulating modes) or shaded radiance (deferred modes)
    vec3 specular;  // the specular sum times F0 (one sum of both parts, unless TL_FRESNEL_SUMS)
    vec3 fresnel;   // TL_FRESNEL_SUMS: GGX's Schlick part, added as it is
};

tl_tiled_result tl_tiled_shade(ivec2 px)
{
    tl_tiled_result res;
    res.surface = false;
    res.diffuse = res.specular = res.fresnel = vec3(0.0);
    vec3 p, n;
    float gloss;
#ifdef TL_LIGHT_SHADE_FAT
    vec3 albedo, spec_color;
    if (!tl_fat_position(px, p)) return res;
    tl_fat_surface(px, n, gloss, albedo, spec_color);
#else
    if (!tl_gbuffer_position(px, p)) return res;
    tl_gbuffer_normal_gloss(px, n, gloss);
#endif
    res.surface = true;
    vec3 v = normalize(-p);
    float shape = tl_lobe_shape(gloss);
    tl_light_point at = tl_light_point_at(p, n, v, shape);
    tl_light_sums sums = tl_light_sums_zero();
#ifdef TL_LIGHT_SHIFT
    ivec2 frame_px = px << TL_LIGHT_SHIFT; // tiles are in the frame's pixels
#else
    ivec2 frame_px = px;
#endif
#if defined(TL_MATERIAL_MODELS) && !defined(TL_LIGHT_ACCUM)
    at.fm = tl_fat_model_read(px, n, v);
    if (at.fm.model != 0) {
#ifdef TL_LIGHT_SHADE_THIN
        tl_rt1_read(px, at.albedo, at.spec_color);
#else
        at.albedo = albedo;
        at.spec_color = spec_color;
#endif
        tl_tile_lights_walk(TL_LIGHTS_MODELS, frame_px, at, sums);
        res.diffuse = min(sums.diffuse, TL_FP16_MAX);
        return res;
    }
#endif
    tl_tile_lights_walk(TL_LIGHTS_SUMS, frame_px, at, sums);
#ifdef TL_LIGHT_ACCUM
    tl_light_sums_fold(sums);
    res.diffuse = min(sums.diffuse, TL_FP16_MAX);
    res.specular = min(sums.specular, TL_FP16_MAX);
    res.fresnel = min(sums.fresnel, TL_FP16_MAX);
#else
#ifdef TL_LIGHT_SHADE_THIN
    vec3 albedo, spec_color;
    tl_rt1_read(px, albedo, spec_color);
#endif
    res.diffuse = tl_light_sums_radiance(sums, albedo, spec_color);
#endif
    return res;
}

#ifdef TL_COAT_SUMS
#include "coat_sums.glsl"
// The coat's specular sum S1 + S2 at the coat's gloss where a coat is (zero elsewhere): the
// pixel's lights again, with the coat's lobe.
vec3 tl_tiled_coat(ivec2 px)
{
    vec3 p, n;
    float g, base_gloss;
    if (!tl_coat_gloss(px, g) || !tl_gbuffer_position(px, p)) return vec3(0.0);
    tl_gbuffer_normal_gloss(px, n, base_gloss);
    tl_light_sums s = tl_light_sums_zero();
    tl_tile_lights_walk(TL_LIGHTS_SUMS, px, tl_light_point_at(p, n, normalize(-p), tl_lobe_shape(g)), s);
    return min(s.specular + s.fresnel, TL_FP16_MAX);
}
#endif
