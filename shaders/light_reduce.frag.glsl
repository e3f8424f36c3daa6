// light_scale below 1 (docs/frame.md, "Light at reduced resolution"): one fragment per texel of the
// light buffer, over its 2^TL_LIGHT_SHIFT square block of the frame. A block whose depths lie on one
// plane (window depth is affine in screen space across a plane, and the block's distances are
// close) keeps the depth at its centre, where
// the upsample's bilinear weights place the texel, and the light is computed at that point of the
// surface. Any other block (a silhouette, a crease, a curved surface, the frame's last row or
// column) keeps its nearest sample (smallest depth; largest with reversed Z), so the light is
// computed on the front surface of a block a silhouette crosses, at that very pixel. The RT0 texel
// is the nearest sample's, never blended; light.offset says where the light was computed (the
// pixel x + 4 y in the block, or 16: the centre). The material pass's upsample rejects texels of
// another surface and re-lights the pixels that have no credible texel left.
#include "codec.glsl"
#include "frame.glsl"

layout(binding = TL_UNIT_DEPTH) uniform sampler2D u_depth;
layout(binding = TL_UNIT_RT0) uniform sampler2D u_rt0;

layout(location = TL_OUT_LIGHT_RT0) out vec4 o_rt0;
layout(location = TL_OUT_LIGHT_OFFSET) out vec4 o_offset;

const int TL_K = 1 << TL_LIGHT_SHIFT;

void main()
{
    ivec2 size = textureSize(u_depth, 0);
    ivec2 base = ivec2(gl_FragCoord.xy) * TL_K;
    bool reversed = u_depth_params.w > 0.5;
    float best = u_clear_depth, worst = reversed ? 1.0 : 0.0;
    ivec2 at = min(base, size - 1);
    float d[TL_K * TL_K];
    bool whole = all(lessThan(base + (TL_K - 1), size));
    for (int y = 0; y < TL_K; y++)
        for (int x = 0; x < TL_K; x++) {
            ivec2 q = base + ivec2(x, y);
            if (q.x >= size.x || q.y >= size.y) continue; // the last row and column of odd sizes
            float v = texelFetch(u_depth, q, 0).r;
            d[y * TL_K + x] = v;
            worst = reversed ? min(worst, v) : max(worst, v);
            if (reversed ? v > best : v < best) {
                best = v;
                at = q;
            }
        }
    // planar: every sample on the affine fit through the corners (within depth quantisation); a 2x2
    // block has only its corners, and two surfaces each constant along a column fit them too: there
    // the distances must also lie within 4 % of the nearest
    float z_near = tl_depth_linearize(best, u_depth_params.x, u_depth_params.y, u_depth_params.z, reversed);
    float z_far = tl_depth_linearize(worst, u_depth_params.x, u_depth_params.y, u_depth_params.z, reversed);
    bool planar = whole && best != u_clear_depth && (TL_K > 2 || abs(z_far - z_near) <= 0.04 * abs(z_near));
    float c00 = d[0], c10 = d[TL_K - 1], c01 = d[(TL_K - 1) * TL_K], c11 = d[TL_K * TL_K - 1];
    float gx = 0.5 * ((c10 - c00) + (c11 - c01)) / float(TL_K - 1);
    float gy = 0.5 * ((c01 - c00) + (c11 - c10)) / float(TL_K - 1);
    float centre = 0.25 * (c00 + c10 + c01 + c11);
    float eps = 4.0 / 16777216.0 + 1e-6 * abs(centre);
    for (int i = 0; planar && i < TL_K * TL_K; i++) {
        vec2 o = vec2(i % TL_K, i / TL_K) - 0.5 * float(TL_K - 1);
        if (d[i] == u_clear_depth || abs(d[i] - (centre + gx * o.x + gy * o.y)) > eps) planar = false;
    }
    gl_FragDepth = planar ? centre : best;
    o_rt0 = texelFetch(u_rt0, at, 0);
    ivec2 o = at - base;
    // The quad of this texel and its +x, +y and +x+y neighbours, as the upsample interpolates
    // between them: interior (flag 32) when the 2K x 2K samples of their four blocks lie on one
    // plane (the fit through the region's corners, as a block's) and the four kept RT0 texels hold
    // the same normal (their gloss may differ: a checkerboard of materials). Every pixel between those texels' centres lies on that plane: the upsample's depth
    // weights are all 1, and its normal weights are equal (its normalised weights: bilinear), so
    // it reads such a quad with one bilinear fetch per target, weighing nothing.
    bool interior = planar && all(lessThan(base + (2 * TL_K - 1), size));
    if (interior) {
        const int R = 2 * TL_K;
        float r[R * R];
        for (int y = 0; y < R; y++)
            for (int x = 0; x < R; x++) r[y * R + x] = texelFetch(u_depth, base + ivec2(x, y), 0).r;
        float q00 = r[0], q10 = r[R - 1], q01 = r[(R - 1) * R], q11 = r[R * R - 1];
        float hx = 0.5 * ((q10 - q00) + (q11 - q01)) / float(R - 1);
        float hy = 0.5 * ((q01 - q00) + (q11 - q10)) / float(R - 1);
        float qc = 0.25 * (q00 + q10 + q01 + q11);
        float qeps = 4.0 / 16777216.0 + 1e-6 * abs(qc);
        for (int i = 0; interior && i < R * R; i++) {
            vec2 p = vec2(i % R, i / R) - 0.5 * float(R - 1);
            if (r[i] == u_clear_depth || abs(r[i] - (qc + hx * p.x + hy * p.y)) > qeps) interior = false;
        }
        // each neighbour block's kept RT0 texel (its nearest sample, as above) against this one's
        for (int b = 1; interior && b < 4; b++) {
            ivec2 b0 = ivec2(b & 1, b >> 1) * TL_K, near = b0;
            for (int y = 0; y < TL_K; y++)
                for (int x = 0; x < TL_K; x++) {
                    float v = r[(b0.y + y) * R + b0.x + x], n = r[near.y * R + near.x];
                    if (reversed ? v > n : v < n) near = b0 + ivec2(x, y);
                }
            interior = tl_rt0_same_normal(texelFetch(u_rt0, base + near, 0), o_rt0);
        }
    }
    o_offset = vec4(float((planar ? 16 : (o.x | (o.y << 2))) | (interior ? 32 : 0)) / 255.0, 0.0, 0.0, 0.0);
}
