// Image-based light (docs/lighting.md, "Light from the environment"): the radiance a surface
// reflects from the environment set by tl_renderer_set_environment, in every shading pass (the
// material pass of thin-lpp, forward, and the G-buffer pass of thin-deferred and fat, each with
// the material's own albedo, F0, gloss, occlusion and normal). Diffuse: the irradiance from 9 SH
// coefficients (Ramamoorthi and Hanrahan 2001); specular: the GGX-prefiltered chain times the
// split-sum table, F0 A + B (Karis 2013). All of it made on the CPU (src/render/environment/ibl_bake.c).

#ifndef TL_IBL_GLSL
#define TL_IBL_GLSL

#include "codec.glsl" // tl_gloss_to_ggx_alpha
#include "frame.glsl"

// environment.c fills it: c_i with sum c_i Y_i(n) = irradiance / pi, then the parameters
layout(std140, binding = TL_UBO_ENVIRONMENT) uniform tl_environment_block {
    vec4 u_env_sh[9];
    vec4 u_env_params; // x: intensity, y: the chain's top level (roughness 1)
};
layout(binding = TL_UNIT_ENV_SPECULAR) uniform sampler2D u_env_specular;
layout(binding = TL_UNIT_ENV_BRDF) uniform sampler2D u_env_brdf;

// Equirectangular coordinates of a world direction: u = atan2(z, x) / 2 pi + 1/2, v = acos(y) / pi
// (acos as atan: llvmpipe's acos is far less precise, docs/lighting.md).
vec2 tl_env_uv(vec3 d)
{
    const float pi = 3.14159265358979;
    float r = length(d.xz);
    return vec2(r > 0.0 ? atan(d.z, d.x) * (0.5 / pi) + 0.5 : 0.5, atan(r, d.y) / pi);
}

// A view-space direction in the world (the view matrix is a rotation and a translation).
vec3 tl_env_world(vec3 d)
{
    return transpose(mat3(u_view)) * d;
}

// Irradiance over pi at unit world normal n: the radiance of a white Lambertian surface.
vec3 tl_env_diffuse(vec3 n)
{
    vec3 e = u_env_sh[0].rgb * 0.282094792 + u_env_sh[1].rgb * (0.488602512 * n.y) +
             u_env_sh[2].rgb * (0.488602512 * n.z) + u_env_sh[3].rgb * (0.488602512 * n.x) +
             u_env_sh[4].rgb * (1.092548431 * n.x * n.y) + u_env_sh[5].rgb * (1.092548431 * n.y * n.z) +
             u_env_sh[6].rgb * (0.315391565 * (3.0 * n.z * n.z - 1.0)) + u_env_sh[7].rgb * (1.092548431 * n.x * n.z) +
             u_env_sh[8].rgb * (0.546274215 * (n.x * n.x - n.y * n.y));
    return max(e, vec3(0.0)); // the 9-term series rings below zero behind a bright source
}

// The reflected radiance: albedo E / pi + prefiltered(r, roughness) (F0 A(n.v, roughness) + B),
// times the intensity and the material's occlusion. n, v: unit, view space.
vec3 tl_ibl(vec3 albedo, vec3 f0, float gloss, float occlusion, vec3 n, vec3 v)
{
    float rough = clamp(1.0 - gloss, 0.0, 1.0), nv = clamp(dot(n, v), 0.0, 1.0);
    // the lobe's dominant direction leans from r towards n as it widens (Lagarde and de Rousiers 2014)
    float a = tl_gloss_to_ggx_alpha(gloss), lean = (1.0 - a) * (sqrt(1.0 - a) + a);
    vec3 r = tl_env_world(normalize(mix(n, reflect(-v, n), lean)));
    vec3 pre = textureLod(u_env_specular, tl_env_uv(r), rough * u_env_params.y).rgb;
    vec2 ab = textureLod(u_env_brdf, vec2(nv, rough), 0.0).rg;
    vec3 c = albedo * tl_env_diffuse(tl_env_world(n)) + pre * (f0 * ab.x + ab.y);
    return c * (u_env_params.x * occlusion);
}

#endif
