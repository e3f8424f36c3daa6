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
#include "light_loop.glsl" // the visible lights block and the object lists

void tl_stipple_relight(bool wanted, vec3 p, vec3 n, float gloss, out vec3 diffuse, out vec3 specular, out vec3 fresnel)
{
    tl_light_sums s = tl_light_sums_zero();
    tl_object_lights_walk(TL_LIGHTS_PLAIN, tl_objects[v_object].lights.x, wanted ? tl_objects[v_object].lights.y : 0u,
                          tl_light_point_at(p, n, normalize(-p), tl_lobe_shape(gloss)), s);
    tl_light_sums_fold(s);
#ifdef TL_SPECULAR_NONE
    s.specular = s.fresnel = vec3(0.0);
#endif
    diffuse = tl_stipple_finite(s.diffuse);
    specular = tl_stipple_finite(s.specular);
    fresnel = tl_stipple_finite(s.fresnel);
}

#ifdef TL_STIPPLE_COAT
// The coat's sum S1 + S2 at its gloss from the object's lights, as the light pass forms it.
vec3 tl_stipple_relight_coat(vec3 p, vec3 n)
{
    tl_light_sums s = tl_light_sums_zero();
    tl_object_lights_walk(TL_LIGHTS_COAT, tl_objects[v_object].lights.x, tl_objects[v_object].lights.y,
                          tl_light_point_at(p, n, normalize(-p), tl_lobe_shape(1.0 - u_clearcoat_roughness)), s);
    return tl_stipple_finite(s.specular);
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
