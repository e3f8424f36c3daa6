// The tiled light pass as a compute pass: one invocation per pixel, 8 x 8 per workgroup, no shared
// memory; image stores into the light buffer, or a read-add-write of HDR (deferred modes).
// MSAA per-sample edges (TL_GBUFFER_SAMPLES, gbuffer_samples.glsl): one invocation per pixel and
// sample (z); an edge pixel's sample is lit at its own depth and position and stored to that
// sample alone, every other pixel is lit once (by z = 0) as the fragment pass lights it and
// stored to all its samples, so the two variants write the same values. "All" is the samples the
// targets have (imageSamples), which the context may make more than asked (llvmpipe: 4 for 2), as
// the fragment pass's full-screen triangle and its sample-rate shading reach them.
#ifdef TL_GBUFFER_SAMPLES
#define TL_MSAA_COMPUTE
#define TL_IMAGE2D image2DMS
#define tl_image_store(img, px, s, v) imageStore(img, px, s, v)
#define tl_image_load(img, px, s) imageLoad(img, px, s)
#define tl_image_samples(img) imageSamples(img)
#else
#define TL_IMAGE2D image2D
#define tl_image_store(img, px, s, v) imageStore(img, px, v)
#define tl_image_load(img, px, s) imageLoad(img, px)
#define tl_image_samples(img) 1
#endif
#include "lights_tiled.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
#ifdef TL_LIGHT_ACCUM
layout(TL_LIGHT_IMAGE_FORMAT, binding = TL_IMAGE_LIGHT_DIFFUSE) uniform writeonly TL_IMAGE2D u_light_diffuse_image;
#ifdef TL_SPECULAR_EXACT
layout(TL_LIGHT_IMAGE_FORMAT, binding = TL_IMAGE_LIGHT_SPECULAR) uniform writeonly TL_IMAGE2D u_light_specular_image;
#endif
#ifdef TL_FRESNEL_SUMS
layout(TL_LIGHT_IMAGE_FORMAT, binding = TL_IMAGE_LIGHT_FRESNEL) uniform writeonly TL_IMAGE2D u_light_fresnel_image;
#endif
#ifdef TL_COAT_SUMS
layout(TL_LIGHT_IMAGE_FORMAT, binding = TL_IMAGE_LIGHT_COAT) uniform writeonly image2D u_light_coat_image;
#endif
#define TL_TILED_IMAGE u_light_diffuse_image
#else
layout(rgba16f, binding = TL_IMAGE_HDR) uniform TL_IMAGE2D u_hdr_image;
#define TL_TILED_IMAGE u_hdr_image
#endif

// The pixel's result into sample s (sample 0 without MSAA).
void tl_tiled_store(ivec2 px, int s, tl_tiled_result r)
{
#ifdef TL_LIGHT_ACCUM
#if defined(TL_SPECULAR_EXACT)
    tl_image_store(u_light_diffuse_image, px, s, vec4(r.diffuse, 0.0));
    tl_image_store(u_light_specular_image, px, s, vec4(r.specular, 0.0));
#ifdef TL_FRESNEL_SUMS
    tl_image_store(u_light_fresnel_image, px, s, vec4(r.fresnel, 0.0));
#endif
#elif defined(TL_SPECULAR_COMPACT)
    tl_image_store(u_light_diffuse_image, px, s, vec4(r.diffuse, min(tl_luminance(r.specular), 65504.0)));
#else
    tl_image_store(u_light_diffuse_image, px, s, vec4(r.diffuse, 0.0));
#endif
#ifdef TL_COAT_SUMS // planned without MSAA only: s is 0
    imageStore(u_light_coat_image, px, vec4(tl_tiled_coat(px), 0.0));
#endif
#else
    if (!r.surface) return;
    vec4 c = tl_image_load(u_hdr_image, px, s);
    tl_image_store(u_hdr_image, px, s, vec4(min(c.rgb + r.diffuse, vec3(65504.0)), c.a));
#endif
}

void main()
{
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
#ifdef TL_LIGHT_SHIFT
    if (any(greaterThanEqual(px, textureSize(u_depth, 0)))) return; // the light buffer's size
#else
    if (px.x >= int(round(1.0 / u_inv_size.x)) || px.y >= int(round(1.0 / u_inv_size.y))) return;
#endif
#ifdef TL_GBUFFER_SAMPLES
    int s = int(gl_GlobalInvocationID.z);
    tl_msaa_per_sample = tl_msaa_edge(px);
    if (!tl_msaa_per_sample && s != 0) return; // z = 0 lights the pixel for every sample
    tl_gbuffer_sample = tl_msaa_per_sample ? s : 0;
    int end = tl_msaa_per_sample ? s + 1 : tl_image_samples(TL_TILED_IMAGE);
#else
    const int s = 0, end = 1;
#endif
    tl_tiled_result r = tl_tiled_shade(px);
    for (int k = s; k < end; k++) tl_tiled_store(px, k, r);
}
