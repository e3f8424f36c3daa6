// The material pass under the stipple (TL_STIPPLE; docs/frame.md, "2d. Transparency through the
// light buffer"): an opaque pixel's light from its own G-buffer sample, or, where a transparent
// layer took it, from its neighbours' opaque samples of the same surface; with none credible (a thin
// feature, a silhouette under glass) it is lit here from its object's light list, exactly as the
// light pass would (the forward path's per-object lists). Returns true for a pixel lit here.
// TL_STIPPLE_COAT: the clearcoat's coat sum too (tl_stipple_coat), gathered with the coat's own lobe
// (as a pure coat's pixel would be) or re-lit at the coat's gloss; the base's sums as a standard
// pixel's.
#ifndef TL_STIPPLE_OPAQUE_GLSL
#define TL_STIPPLE_OPAQUE_GLSL

#include "light_eval.glsl"
#include "stipple_gather.glsl"
#include "tiles.glsl" // the visible lights block
layout(std430, binding = TL_SSBO_FORWARD_INDICES) readonly buffer tl_light_index_buffer { uint tl_light_indices[]; };

void tl_stipple_relight(bool wanted, vec3 p, vec3 n, float gloss, out vec3 diffuse, out vec3 specular, out vec3 fresnel)
{
    vec3 v = normalize(-p);
    float shape = tl_lobe_shape(gloss);
    const vec3 fp16_max = vec3(65504.0);
    diffuse = specular = fresnel = vec3(0.0);
    uint first = tl_objects[v_object].lights.x, count = wanted ? tl_objects[v_object].lights.y : 0u;
    for (uint i = 0u; i < count; i++) {
        tl_light_data l = tl_lights[tl_light_indices[first + i]];
        vec3 t = tl_light_data_weights(l, int(l.color_type.w), p, n, v, shape);
        diffuse += min(l.color_type.rgb * t.x, fp16_max);
        specular += min(l.color_type.rgb * t.y, fp16_max);
        fresnel += min(l.color_type.rgb * t.z, fp16_max);
    }
#ifndef TL_FRESNEL_SUMS
    specular += fresnel; // one sum: Fresnel is applied per pixel
    fresnel = vec3(0.0);
#endif
#ifdef TL_SPECULAR_NONE
    specular = fresnel = vec3(0.0);
#endif
    diffuse = tl_stipple_finite(diffuse);
    specular = tl_stipple_finite(specular);
    fresnel = tl_stipple_finite(fresnel);
}

#ifdef TL_STIPPLE_COAT
// The coat's sum S1 + S2 at its gloss from the object's lights, as the light pass forms it.
vec3 tl_stipple_relight_coat(vec3 p, vec3 n)
{
    vec3 v = normalize(-p), coat = vec3(0.0);
    float shape = tl_lobe_shape(1.0 - u_clearcoat_roughness);
    uint first = tl_objects[v_object].lights.x, count = tl_objects[v_object].lights.y;
    for (uint i = 0u; i < count; i++) {
        tl_light_data l = tl_lights[tl_light_indices[first + i]];
        vec3 t = tl_light_data_weights(l, int(l.color_type.w), p, n, v, shape);
        coat += min(l.color_type.rgb * (t.y + t.z), vec3(65504.0));
    }
    return tl_stipple_finite(coat);
}

// The coat's light into tl_stipple_coat: gathered with the coat's lobe (a second pass over the
// lattice; the other sums it gathers are dropped), or re-lit where no sample is credible.
void tl_stipple_opaque_coat(float z_f, vec2 dz, vec3 n)
{
    vec4 ld;
    vec3 ls, lf;
    float total = tl_stipple_opaque(z_f, dz, n, tl_stipple_power(true, 1.0 - u_clearcoat_roughness), ld, ls, lf);
    tl_stipple_coat = total < TL_STIPPLE_CREDIBLE ? tl_stipple_relight_coat(v_view_position, n)
                                                  : tl_stipple_finite(tl_stipple_coat / total);
}
#endif

bool tl_stipple_opaque_light(float z_f, vec2 dz, vec3 n, float gloss, bool glossy, out vec3 diffuse, out vec3 specular,
                             out vec3 fresnel)
{
    vec4 ld;
    vec3 ls, lf;
    float total = tl_stipple_opaque(z_f, dz, n, tl_stipple_power(glossy, gloss), ld, ls, lf);
    bool relit = total < TL_STIPPLE_CREDIBLE;
    vec3 rd, rs, rf;
    tl_stipple_relight(relit, v_view_position, n, gloss, rd, rs, rf); // a loop of 0 lights where none is wanted
    tl_stipple_finish(relit ? 1.0 : total, ld, ls, lf, diffuse, specular, fresnel);
    if (relit) {
        diffuse = rd;
        specular = rs;
        fresnel = rf;
    }
#ifdef TL_STIPPLE_COAT
    tl_stipple_opaque_coat(z_f, dz, n); // after the base's gather, which also wrote tl_stipple_coat
#endif
    return relit;
}

#endif
