// The tiled light pass as a full-screen triangle: every pixel once (lights_tiled.glsl). Writes the
// light buffer without blending (background pixels get zero: nothing clears it), or adds the
// shaded radiance to HDR with one blend per pixel (deferred modes; background pixels discard).
#include "lights_tiled.glsl"

#ifdef TL_LIGHT_ACCUM
layout(location = TL_OUT_LIGHT_DIFFUSE) out vec4 o_diffuse;
#ifdef TL_SPECULAR_EXACT
layout(location = TL_OUT_LIGHT_SPECULAR) out vec4 o_specular;
#endif
#ifdef TL_FRESNEL_SUMS
layout(location = TL_OUT_LIGHT_FRESNEL) out vec4 o_fresnel;
#endif
#ifdef TL_COAT_SUMS
layout(location = TL_OUT_LIGHT_COAT) out vec4 o_coat;
#endif
#else
layout(location = TL_OUT_HDR) out vec4 o_color;
#endif

void main()
{
#ifdef TL_GBUFFER_SAMPLES
    // MSAA per-sample edges (gbuffer_samples.glsl): the other light pass's pixels keep their light
    if (!tl_msaa_lit_here(ivec2(gl_FragCoord.xy))) discard;
#endif
    tl_tiled_result r = tl_tiled_shade(ivec2(gl_FragCoord.xy));
#ifdef TL_LIGHT_ACCUM
#if defined(TL_SPECULAR_EXACT)
    o_diffuse = vec4(r.diffuse, 0.0);
    o_specular = vec4(r.specular, 0.0);
#ifdef TL_FRESNEL_SUMS
    o_fresnel = vec4(r.fresnel, 0.0);
#endif
#elif defined(TL_SPECULAR_COMPACT)
    o_diffuse = vec4(r.diffuse, min(tl_luminance(r.specular), 65504.0));
#else
    o_diffuse = vec4(r.diffuse, 0.0);
#endif
#ifdef TL_COAT_SUMS
    o_coat = vec4(tl_tiled_coat(ivec2(gl_FragCoord.xy)), 0.0);
#endif
#else
    if (!r.surface) discard;
    o_color = vec4(r.diffuse, 0.0);
#endif
}
