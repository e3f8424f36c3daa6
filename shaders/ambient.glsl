// The ambient term of the shading passes (the material pass, forward, visibility's resolve): the
// frame's ambient radiance times the surface's occlusion, and with SSAO (docs/effects.md) times the
// pixel's AO, which with TL_SSAO_DIFFUSE also scales the diffuse light.
#ifndef TL_AMBIENT_GLSL
#define TL_AMBIENT_GLSL

#ifdef TL_SSAO_AMBIENT
layout(binding = TL_UNIT_AO) uniform sampler2D u_ao;
#endif

vec3 tl_ambient(float occlusion, ivec2 px, inout vec3 diffuse)
{
#ifdef TL_SSAO_AMBIENT
    float ao = texelFetch(u_ao, px, 0).r;
#ifdef TL_SSAO_DIFFUSE
    diffuse *= ao;
#endif
    return u_ambient * (occlusion * ao);
#else
    return u_ambient * occlusion;
#endif
}

#endif
