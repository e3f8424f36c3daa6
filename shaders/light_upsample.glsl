// The light scale's upsample and edge fix-up, in the material pass (TL_UPSAMPLE = the light
// buffer's shift; docs/frame.md, "Light at reduced resolution"). A pixel takes the 4 nearest reduced
// texels, each weighted by
//   bilinear x depth similarity x normal similarity.
// Depth: the texel's depth (the nearest sample of its block) against the pixel's own depth carried
// along the pixel's plane to the pixel that sample came from (screen-space derivatives), within 1 %
// of the distance plus the depth change across half a block: a texel of another surface (a silhouette, a
// step) weighs 0, one of the same plane 1 however steeply it is seen. Normal: the texel's RT0 normal
// against the pixel's own (the same encoding, so a flat surface compares exactly), raised to a
// power: a crease weighs 0. The power is 16 for diffuse-only materials and the specular lobe's
// own power (tl_gloss_to_specular_power, 16 to 256) for specular ones: cos^p falls as the lobe does
// (about exp(-p angle^2 / 2)), so a highlight is not interpolated between normals the lobe tells
// apart (the crypt's glossy columns: 41.6 -> 46.1 dB at 1/2, for 2.4 -> 3.8 % of pixels re-lit). Depth and normal need nothing beyond what the light pass already reads
// (an object ID would cost a target and miss creases within an object). The light buffer holds
// irradiance, smooth along a surface; albedo and specular colour stay at full resolution.
// A pixel whose credible weight sums to less than TL_UPSAMPLE_CREDIBLE (no texel of its surface
// near it: thin features, silhouettes, creases) is re-lit here, exactly as the light pass would
// at full resolution, by looping over its tile's lights (tiled) or its object's (volumes: the
// forward path's per-object lists): no extra pass, no mask, and the cost falls on the few pixels
// that need it (and on the SIMD groups they share with their neighbours).
#ifndef TL_LIGHT_UPSAMPLE_GLSL
#define TL_LIGHT_UPSAMPLE_GLSL

#include "light_relight.glsl" // RT0 and its decoding, the fix-up buffer, the re-lighting from lists

layout(binding = TL_UNIT_LIGHT_DEPTH) uniform sampler2D u_light_depth;
layout(binding = TL_UNIT_LIGHT_RT0) uniform sampler2D u_light_rt0;
layout(binding = TL_UNIT_LIGHT_OFFSET) uniform sampler2D u_light_offset;

const float TL_UPSAMPLE_CREDIBLE = 0.5;    // below it, the pixel is re-lit
const float TL_UPSAMPLE_DEPTH_RELATIVE = 0.01;
const float TL_UPSAMPLE_NORMAL_POWER = 16.0; // cos 10 degrees: 0.78, cos 30 degrees: 0.1
const float TL_UPSAMPLE_LOBE_POWER_MAX = 256.0;

// The weighted sums of the 4 texels (diffuse with its alpha, specular, Fresnel) and their weight.
// Depth and offset come by textureGather (the targets clamp to their edge, as the texel indices
// would); the light by texelFetch, weighed here. (A bilinear fetch where all 4 weights are 1 was
// slower on llvmpipe: it runs both sides of a branch its SIMD lanes disagree on; quads that are
// interior take tl_upsample_interior's bilinear fetch before any weight is computed.)
float tl_upsample_gather(vec4 rt0_f, vec3 n_f, float power, float z_f, vec2 dz, out vec4 ld, out vec3 ls, out vec3 lf)
{
    const float k = float(1 << TL_UPSAMPLE);
    ivec2 size = textureSize(u_light_depth, 0);
    vec2 r = gl_FragCoord.xy / k - 0.5; // texel centres at (i + 0.5) k in the frame's pixels
    vec2 base = floor(r), f = r - base;
    vec2 corner = (base + 1.0) / vec2(size);
    vec4 dg = textureGather(u_light_depth, corner), og = textureGather(u_light_offset, corner);
    float tol_z = TL_UPSAMPLE_DEPTH_RELATIVE * abs(z_f) + 0.5 * k * (abs(dz.x) + abs(dz.y));
    float w[4], total = 0.0;
    for (int j = 0; j < 4; j++) {
        ivec2 o = ivec2(j & 1, j >> 1);
        int g = o.y == 1 ? o.x : 3 - o.x; // textureGather's order: (0,1) (1,1) (1,0) (0,0)
        ivec2 q = clamp(ivec2(base) + o, ivec2(0), size - 1);
        float wb = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
        float d = dg[g];
        w[j] = 0.0;
        if (d == u_clear_depth) continue;
        uint off = uint(og[g] * 255.0 + 0.5) & 31u; // 32: the interior flag
        vec2 c = off == 16u ? (vec2(q) + 0.5) * k : vec2(q * (1 << TL_UPSAMPLE) + ivec2(off & 3u, off >> 2)) + 0.5; // lit there
        float predicted = z_f + dot(dz, c - gl_FragCoord.xy);
        float wz = clamp(1.0 - abs(tl_relight_linear_depth(d) - predicted) / tol_z, 0.0, 1.0);
        vec4 t = texelFetch(u_light_rt0, q, 0); // the pixel's own RT0 texel (a flat surface): weight 1
        float wn = tl_rt0_same_normal(t, rt0_f) ? 1.0 : pow(clamp(dot(tl_relight_rt0(t).xyz, n_f), 0.0, 1.0), power);
        w[j] = wb * wz * wn;
        total += w[j];
    }
    ld = vec4(0.0);
    ls = lf = vec3(0.0);
    for (int j = 0; j < 4; j++) {
        if (w[j] <= 0.0) continue;
        tl_light_texel_add(clamp(ivec2(base) + ivec2(j & 1, j >> 1), ivec2(0), size - 1), w[j], ld, ls, lf);
    }
    return total;
}

// The light of a pixel inside an interior quad (light_reduce.frag.glsl, flag 32: four texels on
// one plane with one normal) whose own normal is that one: the weights would all be 1, so one
// bilinear fetch per target, before any weight is computed (most pixels of flat surfaces).
bool tl_upsample_interior(vec4 rt0, out vec4 ld, out vec3 ls, out vec3 lf)
{
    const float k = float(1 << TL_UPSAMPLE);
    ivec2 size = textureSize(u_light_offset, 0);
    vec2 r = gl_FragCoord.xy / k - 0.5;
    ivec2 base = ivec2(floor(r));
    ld = vec4(0.0);
    ls = lf = vec3(0.0);
    if (any(lessThan(base, ivec2(0))) || any(greaterThanEqual(base + 1, size))) return false;
    uint flags = uint(texelFetch(u_light_offset, base, 0).r * 255.0 + 0.5);
    if ((flags & 32u) == 0u || !tl_rt0_same_normal(texelFetch(u_light_rt0, base, 0), rt0)) return false;
    vec2 uv = (r + 0.5) / vec2(size);
    ld = textureLod(u_light_diffuse, uv, 0.0);
#ifdef TL_SPECULAR_EXACT
    ls = textureLod(u_light_specular, uv, 0.0).rgb;
#ifdef TL_FRESNEL_SUMS
    lf = textureLod(u_light_fresnel, uv, 0.0).rgb;
#endif
#endif
    return true;
}

// The light at this pixel: upsampled, or re-lit where no reduced texel is credible (true). A
// re-lit pixel is counted (light.fixup) and re-lit here from its tile's lists or its object's: the
// same code for every re-lit pixel, so the frame's bytes never depend on which pixel's fragment ran
// first (a list of re-lit pixels shared by the frame did: its order was the order of atomic adds).
bool tl_upsample_light(float z_f, vec2 dz, bool glossy, out vec3 diffuse, out vec3 specular, out vec3 fresnel)
{
    vec4 rt0 = texelFetch(u_rt0, ivec2(gl_FragCoord.xy), 0), ng = vec4(0.0);
    vec4 ld;
    vec3 ls, lf;
    float total = 1.0;
    if (!tl_upsample_interior(rt0, ld, ls, lf)) {
        ng = tl_relight_rt0(rt0);
        // a specular material's lobe: cos(angle)^power falls as the lobe does (exp(-power angle^2 / 2))
        float power = glossy ? clamp(tl_gloss_to_specular_power(ng.w), TL_UPSAMPLE_NORMAL_POWER, TL_UPSAMPLE_LOBE_POWER_MAX)
                             : TL_UPSAMPLE_NORMAL_POWER;
        total = tl_upsample_gather(rt0, ng.xyz, power, z_f, dz, ld, ls, lf);
    }
    bool relit = total < TL_UPSAMPLE_CREDIBLE;
    if (relit) {
        atomicAdd(tl_fixup_counters.w, 1u); // the count only: nothing of the image depends on it
        tl_relight(ng.xyz, ng.w, z_f, ld, ls, lf);
    } else {
        float inv = 1.0 / total;
        ld *= inv;
        ls *= inv;
        lf *= inv;
    }
    tl_relight_finish(ld, ls, lf, relit, diffuse, specular, fresnel);
    return relit;
}

#endif
