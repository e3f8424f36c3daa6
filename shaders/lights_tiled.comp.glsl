// The tiled light pass as a compute pass: one invocation per pixel, 8 x 8 per workgroup, no shared
// memory; image stores into the light buffer, or a read-add-write of HDR (deferred modes).
#include "lights_tiled.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
#ifdef TL_LIGHT_ACCUM
layout(TL_LIGHT_IMAGE_FORMAT, binding = TL_IMAGE_LIGHT_DIFFUSE) uniform writeonly image2D u_light_diffuse_image;
#ifdef TL_SPECULAR_EXACT
layout(TL_LIGHT_IMAGE_FORMAT, binding = TL_IMAGE_LIGHT_SPECULAR) uniform writeonly image2D u_light_specular_image;
#endif
#ifdef TL_FRESNEL_SUMS
layout(TL_LIGHT_IMAGE_FORMAT, binding = TL_IMAGE_LIGHT_FRESNEL) uniform writeonly image2D u_light_fresnel_image;
#endif
#ifdef TL_COAT_SUMS
layout(TL_LIGHT_IMAGE_FORMAT, binding = TL_IMAGE_LIGHT_COAT) uniform writeonly image2D u_light_coat_image;
#endif
#else
layout(rgba16f, binding = TL_IMAGE_HDR) uniform image2D u_hdr_image;
#endif

void main()
{
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
#ifdef TL_LIGHT_SHIFT
    if (any(greaterThanEqual(px, textureSize(u_depth, 0)))) return; // the light buffer's size
#else
    if (px.x >= int(round(1.0 / u_inv_size.x)) || px.y >= int(round(1.0 / u_inv_size.y))) return;
#endif
    tl_tiled_result r = tl_tiled_shade(px);
#ifdef TL_LIGHT_ACCUM
#if defined(TL_SPECULAR_EXACT)
    imageStore(u_light_diffuse_image, px, vec4(r.diffuse, 0.0));
    imageStore(u_light_specular_image, px, vec4(r.specular, 0.0));
#ifdef TL_FRESNEL_SUMS
    imageStore(u_light_fresnel_image, px, vec4(r.fresnel, 0.0));
#endif
#elif defined(TL_SPECULAR_COMPACT)
    imageStore(u_light_diffuse_image, px, vec4(r.diffuse, min(tl_luminance(r.specular), 65504.0)));
#else
    imageStore(u_light_diffuse_image, px, vec4(r.diffuse, 0.0));
#endif
#ifdef TL_COAT_SUMS
    imageStore(u_light_coat_image, px, vec4(tl_tiled_coat(px), 0.0));
#endif
#else
    if (!r.surface) return;
    vec4 c = imageLoad(u_hdr_image, px);
    imageStore(u_hdr_image, px, vec4(min(c.rgb + r.diffuse, vec3(65504.0)), c.a));
#endif
}
