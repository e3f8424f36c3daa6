// Forward shading (forward mode, and alpha-blended materials in every mode): each fragment
// evaluates the lights in its object's list (built on the CPU per frame, lights whose range
// reaches the object's bounds), or with TL_FORWARD_TILED (Forward+) the directional lights and
// its tile's list. TL_DEPTH_ONLY: the depth pre-pass. TL_TRANSPARENT: alpha out.
#include "codec.glsl"
#include "frame.glsl"
#include "light_eval.glsl"
#include "material.glsl"
#include "object.glsl"
#ifdef TL_IBL
#include "ibl.glsl" // image-based light from the environment
#endif
#ifdef TL_STIPPLE
#include "stipple_gather.glsl" // the layer's light from its own pixels of the G-buffer
#endif

#ifndef TL_DEPTH_ONLY
#if defined(TL_MATERIAL_MODELS) && defined(TL_FORWARD)
#include "material_models.glsl" // per-material models: each light's exact terms (before the loop: its visitor)
#endif
#include "light_loop.glsl" // the lights block, the object lists and (Forward+) the tile lists
#include "forward_color.glsl" // the lights' sums, ambient, the model and the environment into a colour

layout(location = TL_OUT_HDR) out vec4 o_color;
#endif

void main()
{
#ifdef TL_STIPPLE
    float z_s = tl_stipple_linear_depth(gl_FragCoord.z);
    vec2 dz_s = vec2(dFdx(z_s), dFdy(z_s));
#endif
    tl_surface s = tl_material_surface();
    if (tl_material_masked(s)) discard;
#ifndef TL_DEPTH_ONLY
    vec3 n = tl_material_normal();
    vec3 p = v_view_position;
    vec3 v = normalize(-p);
    float shape = tl_lobe_shape(s.gloss);
    tl_light_sums sums = tl_light_sums_zero();
#ifdef TL_FORWARD_TILED
    // Forward+: the directional lights, then the pixel's tile lists
    tl_tile_lights_walk(TL_LIGHTS_FORWARD, ivec2(gl_FragCoord.xy), tl_light_point_at(p, n, v, shape), sums);
#else
#ifdef TL_STIPPLE
    // the stipple's resolve: the light of the layer's own pixels, or (none credible) forward
    vec4 ld;
    vec3 ls, lf;
    float total = tl_stipple_layer_light(tl_stipple_layer(), z_s, dz_s, n,
                                         tl_stipple_power(any(greaterThan(s.specular, vec3(0.0))), s.gloss), ld, ls, lf);
    if (total >= TL_STIPPLE_CREDIBLE) {
        tl_stipple_finish(total, ld, ls, lf, sums.diffuse, sums.specular, sums.fresnel);
#ifdef TL_FRESNEL_NV
        sums.fresnel = tl_fresnel_schlick(s.specular, clamp(dot(n, v), 0.0, 1.0)) * sums.specular; // as the material pass
        sums.specular = vec3(0.0);
#endif
    } else
#endif
        tl_object_lights_walk(TL_LIGHTS_FORWARD, tl_objects[v_object].lights.x, tl_objects[v_object].lights.y,
                              tl_light_point_at(p, n, v, shape), sums);
#endif
    vec3 c = tl_forward_color(s, n, v, sums, ivec2(gl_FragCoord.xy));
#ifdef TL_TRANSPARENT
    o_color = vec4(min(c, vec3(65504.0)), clamp(s.alpha, 0.0, 1.0));
#else
    o_color = vec4(min(c, vec3(65504.0)), 1.0);
#endif
#endif
}
