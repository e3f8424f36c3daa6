// The tiled light pass's work for one pixel: the G-buffer read and decoded once, then the
// directional lights and the pixel's tile list (every visible local light for a tile whose list
// overflowed), summed in float and written once. Each light's terms and its clamp are those of
// the light volumes (light.frag.glsl), so the strategies differ only in summation order and FP16
// rounding. TL_LIGHT_ACCUM, TL_LIGHT_SHADE_THIN or TL_LIGHT_SHADE_FAT as for the volumes.
#include "gbuffer_decode.glsl"
#include "tile_lights.glsl"
#if defined(TL_MATERIAL_MODELS) && !defined(TL_LIGHT_ACCUM)
#include "fat_models.glsl" // each light under the pixel's material model

// fat, thin-deferred: one light's radiance under the pixel's model; nothing where it cannot reach p (as tl_tiled_add).
vec3 tl_fat_tiled_add(tl_fat_model fm, tl_light_data l, vec3 p, vec3 n, vec3 v, float shape, vec3 albedo,
                      vec3 spec_color)
{
    int type = int(l.color_type.w);
    if (type != 3) {
        vec3 to_light = l.position_radius.xyz - p;
        float d2 = dot(to_light, to_light);
        if (d2 >= l.position_radius.w * l.position_radius.w) return vec3(0.0);
        if (type == 2 && d2 > 0.0 && dot(-to_light, l.direction_cos_outer.xyz) <= l.direction_cos_outer.w * sqrt(d2))
            return vec3(0.0);
    }
    vec3 c = tl_fat_model_radiance(fm, l, type, p, n, v, shape, albedo, spec_color);
#ifdef TL_SHADOWS
    if (l.cos_inner.z > 0.0 && c != vec3(0.0)) // a casting light (its shadow slot): linear in its visibility
        c *= tl_light_shadow(l.cos_inner.z, type, p, n, l.position_radius.xyz, l.direction_cos_outer.xyz);
#endif
    return c;
}

// fat, thin-deferred: the directional lights, then the lights of frame pixel px's tile lists, as tl_tile_lights_add visits them.
vec3 tl_fat_tile_models(tl_fat_model fm, ivec2 px, vec3 p, vec3 n, vec3 v, float shape, vec3 albedo, vec3 spec_color)
{
    vec3 c = vec3(0.0);
    for (uint i = 0u; i < u_light_counts.x; i++) c += tl_fat_tiled_add(fm, tl_lights[i], p, n, v, shape, albedo, spec_color);
    uint tile = tl_tile_index(px), bit = tl_tile_block_bit(px), chunks = tl_tile_chunks();
    for (uint ch = 0u; ch < chunks; ch++) {
        uvec2 h = tl_tile_headers[tl_tile_header_index(tile, ch)];
        uint count = tl_tile_list_size(h, ch);
        for (uint k = 0u; k < count; k++) {
            uint e = tl_tile_list_entry(h, k), i = tl_tile_entry_light(e, ch);
            if ((e & bit) != 0u && tl_light_reaches(i, p))
                c += tl_fat_tiled_add(fm, tl_lights[i], p, n, v, shape, albedo, spec_color);
        }
    }
    return c;
}
#endif

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
    vec3 diffuse = vec3(0.0), specular = vec3(0.0), fresnel = vec3(0.0);
#ifdef TL_LIGHT_SHIFT
    ivec2 frame_px = px << TL_LIGHT_SHIFT; // tiles are in the frame's pixels
#else
    ivec2 frame_px = px;
#endif
#if defined(TL_MATERIAL_MODELS) && !defined(TL_LIGHT_ACCUM)
    tl_fat_model fm = tl_fat_model_read(px, n, v);
    if (fm.model != 0) {
#ifdef TL_LIGHT_SHADE_THIN
        vec3 albedo, spec_color;
        tl_rt1_read(px, albedo, spec_color);
#endif
        res.diffuse = min(tl_fat_tile_models(fm, frame_px, p, n, v, shape, albedo, spec_color), vec3(65504.0));
        return res;
    }
#endif
    tl_tile_lights_add(frame_px, p, n, v, shape, diffuse, specular, fresnel);
    const vec3 fp16_max = vec3(65504.0);
#ifdef TL_LIGHT_ACCUM
#ifndef TL_FRESNEL_SUMS
    specular += fresnel; // one sum: Fresnel is applied per pixel
    fresnel = vec3(0.0);
#endif
    res.diffuse = min(diffuse, fp16_max);
    res.specular = min(specular, fp16_max);
    res.fresnel = min(fresnel, fp16_max);
#else
#ifdef TL_LIGHT_SHADE_THIN
    vec3 albedo, spec_color;
    tl_rt1_read(px, albedo, spec_color);
#endif
#ifdef TL_SPECULAR_NONE
    spec_color = vec3(0.0);
    fresnel = vec3(0.0);
#endif
    res.diffuse = min(albedo * diffuse + spec_color * specular + fresnel, fp16_max);
#endif
    return res;
}

#ifdef TL_COAT_SUMS
#include "coat_sums.glsl"
// The coat's specular sum S1 + S2 at the coat's gloss where a coat is (zero elsewhere): the
// pixel's lights again, with the coat's lobe.
vec3 tl_tiled_coat(ivec2 px)
{
    vec3 p, n, d = vec3(0.0), s = vec3(0.0), f = vec3(0.0);
    float g, base_gloss;
    if (!tl_coat_gloss(px, g) || !tl_gbuffer_position(px, p)) return vec3(0.0);
    tl_gbuffer_normal_gloss(px, n, base_gloss);
    tl_tile_lights_add(px, p, n, normalize(-p), tl_lobe_shape(g), d, s, f);
    return min(s + f, vec3(65504.0));
}
#endif
