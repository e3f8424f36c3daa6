// Pass 3: the second geometry pass applies materials to the accumulated light (depth EQUAL).
#include "lighting.glsl"

in vec3 v_normal;
in vec2 v_uv;

uniform sampler2D u_light_diffuse;
uniform sampler2D u_light_specular;
uniform sampler2D u_albedo_texture;
uniform vec3 u_albedo;
uniform vec3 u_specular;
uniform vec3 u_emissive;
uniform vec3 u_ambient;

layout(location = 0) out vec4 o_color;

vec3 tl_finite(vec3 c) // FP16 sums of many bright lights can reach Inf: keep targets finite
{
    return vec3(isinf(c.r) || isnan(c.r) ? 65504.0 : c.r, isinf(c.g) || isnan(c.g) ? 65504.0 : c.g,
                isinf(c.b) || isnan(c.b) ? 65504.0 : c.b);
}

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 ld = texelFetch(u_light_diffuse, px, 0);
    vec3 diffuse = tl_finite(ld.rgb);
#ifdef TL_SPECULAR_EXACT
    vec3 specular = tl_finite(texelFetch(u_light_specular, px, 0).rgb);
#else
    // Compact layout: specular colour follows the diffuse light's chromaticity.
    float lum = tl_luminance(diffuse);
    vec3 specular = lum > 1e-8 ? diffuse * (min(ld.a, 65504.0) / lum) : vec3(0.0);
#endif
    vec3 albedo = u_albedo;
#ifdef TL_HAS_UV
    vec3 t = texture(u_albedo_texture, v_uv).rgb; // sRGB texture: decoded to linear by the sampler
    albedo *= t;
#endif
    vec3 c = albedo * (diffuse + u_ambient) + u_specular * specular + u_emissive;
    o_color = vec4(min(c, vec3(65504.0)), 1.0);
}
