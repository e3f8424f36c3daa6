// Pass 2: light accumulation into the FP16 light buffer (additive blending).
#include "gbuffer_decode.glsl"
#include "lighting.glsl"

flat in vec4 f_position_radius;
flat in vec3 f_color;
flat in vec4 f_direction_cos_outer;
flat in float f_cos_inner;

layout(location = 0) out vec4 o_diffuse;
#ifdef TL_SPECULAR_EXACT
layout(location = 1) out vec4 o_specular;
#endif

void main()
{
    vec3 p, n;
    float gloss;
    if (!tl_gbuffer_read(ivec2(gl_FragCoord.xy), p, n, gloss)) discard;
    vec3 v = normalize(-p);
    vec2 t = tl_light_terms(TL_LIGHT_TYPE, p, n, v, tl_gloss_to_specular_power(gloss), f_position_radius.xyz,
                            f_position_radius.w, f_direction_cos_outer.xyz, f_cos_inner, f_direction_cos_outer.w);
    vec3 diffuse = f_color * t.x;
    vec3 specular = f_color * t.y;
#ifdef TL_SPECULAR_EXACT
    o_diffuse = vec4(diffuse, 0.0);
    o_specular = vec4(specular, 0.0);
#else
    o_diffuse = vec4(diffuse, tl_luminance(specular));
#endif
}
