// MSAA with per-sample lighting on edges (docs/antialiasing.md, src/render/passes/pass_msaa.c): the
// G-buffer has TL_GBUFFER_SAMPLES samples per pixel. msaa-classify marks the edge pixels (samples
// that differ in depth or normal) in msaa.edges; the light pass (volumes or tiles) then lights
// every other pixel once, from sample 0's surface at the pixel's centre, its output going to every
// covered sample, and lights-samples (TL_MSAA_SAMPLE: gl_SampleID, sample-rate shading) lights the
// edge pixels once per sample. The compute tiled pass (TL_MSAA_COMPUTE) does both in one dispatch:
// it picks the pixel and sample itself and says which through tl_msaa_per_sample and
// tl_gbuffer_sample. Included by gbuffer_decode.glsl after its samplers.
layout(binding = TL_UNIT_MSAA_EDGES) uniform sampler2D u_msaa_edges;

bool tl_msaa_edge(ivec2 px) { return texelFetch(u_msaa_edges, px, 0).r > 0.5; }

#ifdef TL_MSAA_COMPUTE
bool tl_msaa_per_sample = false; // an edge pixel's sample tl_gbuffer_sample is lit, not the pixel

// The context's position of sample s in its pixel (read at compile into the frame block): a
// compute shader has no gl_SamplePosition.
vec2 tl_sample_position(int s)
{
    vec4 two = u_sample_positions[s >> 1];
    return (s & 1) == 0 ? two.xy : two.zw;
}
#endif

// Whether this pass lights the pixel: the per-sample pass the edges, the per-pixel pass the rest.
bool tl_msaa_lit_here(ivec2 px)
{
#if defined(TL_MSAA_CLASSIFY) || defined(TL_MSAA_COMPUTE)
    return true;
#elif defined(TL_MSAA_SAMPLE)
    return tl_msaa_edge(px);
#else
    return !tl_msaa_edge(px);
#endif
}

// The window depth a pixel is lit at: the sample's in the per-sample pass; else the mean of the
// samples, which on a plane is the depth at the pixel's centre (the standard sample patterns are
// symmetric about it), so a pixel inside a surface is lit where the one-sample frame lights it.
float tl_gbuffer_depth(ivec2 px)
{
#if defined(TL_MSAA_SAMPLE) || defined(TL_MSAA_CLASSIFY)
    return tl_gfetch(u_depth, px).r;
#else
#ifdef TL_MSAA_COMPUTE
    if (tl_msaa_per_sample) return tl_gfetch(u_depth, px).r;
#endif
    float d0 = texelFetch(u_depth, px, 0).r, sum = 0.0;
    if (d0 == u_clear_depth) return d0; // not an edge: every sample is background
    for (int s = 0; s < TL_GBUFFER_SAMPLES; s++) sum += texelFetch(u_depth, px, s).r;
    return sum / float(TL_GBUFFER_SAMPLES);
#endif
}

// The window position a pixel is lit at (with tl_gbuffer_depth): the sample's, or the centre.
vec2 tl_gbuffer_point(ivec2 px)
{
#ifdef TL_MSAA_SAMPLE
    return vec2(px) + gl_SamplePosition;
#else
#ifdef TL_MSAA_COMPUTE
    if (tl_msaa_per_sample) return vec2(px) + tl_sample_position(tl_gbuffer_sample);
#endif
    return vec2(px) + 0.5;
#endif
}
