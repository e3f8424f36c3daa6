// The sky pass: where no geometry was drawn (the full-screen triangle lies at the cleared depth and
// passes the depth test only there), the background colour, or with TL_SKY_ENV the environment
// in the pixel's view direction. HDR's alpha stays 0, as cleared.
#include "frame.glsl"
#ifdef TL_SKY_ENV
#include "ibl.glsl"
layout(binding = TL_UNIT_ENV_SKY) uniform sampler2D u_env_sky;
#endif

layout(std140, binding = TL_UBO_PASS) uniform tl_sky_block {
    vec3 u_background; // tl_environment_options.background
    float u_intensity; // tl_environment_options.intensity
};

in vec2 v_uv;
layout(location = TL_OUT_HDR) out vec4 o_color;

void main()
{
#ifdef TL_SKY_ENV
    // the view ray through the pixel: x = (ndc.x + m[8]) / m[0] at z = -1 (an orthographic camera: -z)
    vec2 ndc = v_uv * 2.0 - 1.0;
    vec3 ray = u_proj[2][3] != 0.0 ? vec3((ndc.x + u_ray_params.z) / u_ray_params.x, (ndc.y + u_ray_params.w) / u_ray_params.y, -1.0)
                                   : vec3(0.0, 0.0, -1.0);
    // level 0 only: the chain's derivatives jump at the image's wrap, a mip there would be a seam
    vec3 c = textureLod(u_env_sky, tl_env_uv(normalize(tl_env_world(ray))), 0.0).rgb * u_intensity;
#else
    vec3 c = u_background;
#endif
    o_color = vec4(min(c, vec3(65504.0)), 0.0);
}
