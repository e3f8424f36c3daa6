// SSAO in the modes that write the ambient term in the G-buffer pass (thin-deferred, fat): takes
// the occluded part, (1 - AO) albedo ambient occlusion, from HDR (blended ONE, ONE). The G-buffer
// pass stored the material's occlusion in RT1's or fat.albedo's alpha (TL_AO_STORE).
#include "gbuffer_decode.glsl"

in vec2 v_uv;
layout(binding = TL_UNIT_AO) uniform sampler2D u_ao;
layout(location = TL_OUT_HDR) out vec4 o_hdr;

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    float ao = texelFetch(u_ao, px, 0).r;
    vec3 albedo, specular;
#ifdef TL_SSAO_FAT
    vec4 a = texelFetch(u_fat_albedo, px, 0);
    albedo = a.rgb;
    float occlusion = a.a;
#else
    tl_rt1_read(px, albedo, specular);
    float occlusion = texelFetch(u_rt1, px, 0).a;
#endif
    o_hdr = vec4(-(1.0 - ao) * occlusion * albedo * u_ambient, 0.0);
}
