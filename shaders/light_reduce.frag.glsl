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
    o_offset = vec4(float(planar ? 16 : (o.x | (o.y << 2))) / 255.0, 0.0, 0.0, 0.0);
}
