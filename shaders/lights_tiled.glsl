// The tiled light pass's work for one pixel: the G-buffer read and decoded once, then the
// directional lights and the pixel's tile list (every visible local light for a tile whose list
// overflowed), summed in float and written once. Each light's terms and its clamp are those of
// the light volumes (light.frag.glsl), so the strategies differ only in summation order and FP16
// rounding. TL_LIGHT_ACCUM, TL_LIGHT_SHADE_THIN or TL_LIGHT_SHADE_FAT as for the volumes.
#include "gbuffer_decode.glsl"
#include "light_eval.glsl"
#include "tiles.glsl"

struct tl_tiled_result {
    bool surface;   // false: background, nothing to add
    vec3 diffuse;   // light sum (accumulating modes) or shaded radiance (deferred modes)
    vec3 specular;  // the specular sum times F0 (one sum of both parts, unless TL_FRESNEL_SUMS)
    vec3 fresnel;   // TL_FRESNEL_SUMS: GGX's Schlick part, added as it is
};

// One light's clamped terms added to the sums; nothing when it cannot reach p (as the volumes discard).
void tl_tiled_add(tl_light_data l, vec3 p, vec3 n, vec3 v, float shape, inout vec3 diffuse, inout vec3 specular,
                  inout vec3 fresnel)
{
    int type = int(l.color_type.w);
    if (type != 3) {
        vec3 to_light = l.position_radius.xyz - p;
        float d2 = dot(to_light, to_light);
        if (d2 >= l.position_radius.w * l.position_radius.w) return;
        if (type == 2 && d2 > 0.0 && dot(-to_light, l.direction_cos_outer.xyz) <= l.direction_cos_outer.w * sqrt(d2)) return;
    }
    vec3 t = tl_light_weights(type, p, n, v, shape, l.position_radius, l.direction_cos_outer.xyz, l.cos_inner.x,
                              l.direction_cos_outer.w, l.cos_inner.y);
    const vec3 fp16_max = vec3(65504.0);
    diffuse += min(l.color_type.rgb * t.x, fp16_max);
    specular += min(l.color_type.rgb * t.y, fp16_max);
    fresnel += min(l.color_type.rgb * t.z, fp16_max);
}

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
    for (uint i = 0u; i < u_light_counts.x; i++) tl_tiled_add(tl_lights[i], p, n, v, shape, diffuse, specular, fresnel);
#ifdef TL_LIGHT_SHIFT
    uint tile = tl_tile_index(px << TL_LIGHT_SHIFT), chunks = tl_tile_chunks(); // tiles are in the frame's pixels
#else
    uint tile = tl_tile_index(px), chunks = tl_tile_chunks();
#endif
    for (uint c = 0u; c < chunks; c++) {
        uvec2 h = tl_tile_headers[tl_tile_header_index(tile, c)];
        uint count = tl_tile_list_size(h, c);
        for (uint k = 0u; k < count; k++)
            tl_tiled_add(tl_lights[tl_tile_list_light(h, c, k)], p, n, v, shape, diffuse, specular, fresnel);
    }
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
