// The colour of a surface forward shading lit (forward.frag.glsl, and visibility's resolve,
// vis_resolve.comp.glsl): its lights' sums with SSAO, the ambient term, the material model and the
// image-based light. Included after light_loop.glsl (and material_models.glsl with TL_MATERIAL_MODELS).
#ifndef TL_FORWARD_COLOR_GLSL
#define TL_FORWARD_COLOR_GLSL

#include "ambient.glsl"

vec3 tl_forward_color(tl_surface s, vec3 n, vec3 v, tl_light_sums sums, ivec2 px)
{
    vec3 diffuse = sums.diffuse, specular = sums.specular, fresnel = sums.fresnel;
#ifdef TL_SPECULAR_NONE
    specular = fresnel = vec3(0.0);
#endif
    vec3 ambient = tl_ambient(s.occlusion, px, diffuse);
    // summed in tl_model_shade's order, so that a standard material's pixel is the same float with
    // the material models' switch on (another model on screen) as without
    vec3 sp = s.specular * specular + fresnel;
    vec3 c = s.albedo * (diffuse + ambient) + sp + s.emissive;
#if defined(TL_MATERIAL_MODELS) && defined(TL_FORWARD) && !defined(TL_STIPPLE)
    c = tl_model_shade(u_material_model, s, clamp(dot(n, v), 0.0, 1.0), diffuse, ambient, sp, tl_model_acc);
#endif
#ifdef TL_IBL
#if defined(TL_MATERIAL_MODELS) && defined(TL_FORWARD) && !defined(TL_STIPPLE)
    if (u_material_model != TL_MODEL_UNLIT) // an unlit material takes no light, the environment's neither
#endif
        c += tl_ibl(s.albedo, s.specular, s.gloss, s.occlusion, n, v);
#endif
    return c;
}

#endif
