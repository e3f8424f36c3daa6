// Re-lighting one sample of the material pass from light lists, where the light buffer has no
// texel of its surface: MSAA's edge samples (light_msaa.glsl; the light scale re-lights its pixels
// in light-upsample, light_upsample.comp.glsl). TL_RELIGHT_TILES: the tiled lists of the pixel's tile; otherwise the
// object's own list (the forward path's). Also what both read of the G-buffer and the fix-up
// buffer, where re-lit pixels are counted.
#ifndef TL_LIGHT_RELIGHT_GLSL
#define TL_LIGHT_RELIGHT_GLSL

#include "codec.glsl"
#include "frame.glsl"
#include "light_eval.glsl"
#include "object.glsl"
#include "light_loop.glsl" // the one light loop: the lights block, the tile and object lists, their sums
// light.fixup (fixup.c): counters; the fourth counts the re-lit pixels (or samples)
layout(std430, binding = TL_SSBO_FIXUP) buffer tl_fixup_buffer { uvec4 tl_fixup_counters; };
layout(early_fragment_tests) in; // the counts and the list: only the pixels the depth test keeps

#ifdef TL_LIGHT_SAMPLES // MSAA per-sample edges: the G-buffer is multisampled (light_msaa.glsl)
layout(binding = TL_UNIT_RT0) uniform sampler2DMS u_rt0;
#else
layout(binding = TL_UNIT_RT0) uniform sampler2D u_rt0;
#endif

vec4 tl_relight_rt0(vec4 t) { return tl_rt0_texel_decode(t); } // normal and gloss, as the light pass decodes them

float tl_relight_linear_depth(float d)
{
    return tl_depth_linearize(d, u_depth_params.x, u_depth_params.y, u_depth_params.z, u_depth_params.w > 0.5);
}

// Adds w times the light buffer's texel q to the sums (MSAA's own texel with w = 1).
void tl_light_texel_add(ivec2 q, float w, inout vec4 ld, inout vec3 ls, inout vec3 lf)
{
    ld += w * texelFetch(u_light_diffuse, q, 0);
#ifdef TL_SPECULAR_EXACT
    ls += w * texelFetch(u_light_specular, q, 0).rgb;
#ifdef TL_FRESNEL_SUMS
    lf += w * texelFetch(u_light_fresnel, q, 0).rgb;
#endif
#endif
}

// The pixel's own light sums at view depth z_f on its pixel's centre: over the directional lights
// and its tile's lists (tiled: the tiles are in the frame's pixels and their depth bounds cover
// every pixel), or its object's light list (volumes: every visible light whose range reaches the
// object's bounds).
void tl_relight(vec3 n, float gloss, float z_f, out vec4 ld, out vec3 ls, out vec3 lf)
{
    vec2 ndc = gl_FragCoord.xy * u_inv_size * 2.0 - 1.0;
    vec3 p = tl_view_position(z_f, ndc, u_ray_params);
    vec3 v = normalize(-p);
    float shape = tl_lobe_shape(gloss);
    tl_light_sums s = tl_light_sums_zero();
#ifdef TL_RELIGHT_TILES
    tl_tile_lights_walk(TL_LIGHTS_SUMS, ivec2(gl_FragCoord.xy), tl_light_point_at(p, n, v, shape), s);
#else
    tl_object_lights_walk(TL_LIGHTS_SUMS, tl_objects[v_object].lights.x, tl_objects[v_object].lights.y,
                          tl_light_point_at(p, n, v, shape), s);
#endif
    tl_light_sums_fold(s);
    ld = vec4(s.diffuse, tl_luminance(s.specular));
    ls = s.specular;
    lf = s.fresnel;
}

// Sums as the material pass uses them: finite, and the compact layout's specular recoloured by
// the diffuse light (a re-lit pixel has its own exact specular).
void tl_relight_finish(vec4 ld, vec3 ls, vec3 lf, bool relit, out vec3 diffuse, out vec3 specular, out vec3 fresnel)
{
    diffuse = tl_finite(ld.rgb);
    specular = fresnel = vec3(0.0);
#if defined(TL_SPECULAR_EXACT)
    specular = tl_finite(ls);
#ifdef TL_FRESNEL_SUMS
    fresnel = tl_finite(lf);
#endif
#elif defined(TL_SPECULAR_COMPACT)
    if (relit) specular = tl_finite(ls);
    else {
        float lum = tl_luminance(diffuse);
        specular = lum > 1e-8 ? diffuse * (min(ld.a, 65504.0) / lum) : vec3(0.0);
    }
#endif
}

#endif
