// Pass 5: FXAA in the manner of Lottes' FXAA 3.11 (quality): local contrast test, sub-pixel
// blend, edge orientation from second differences, search along the edge in growing steps, and a
// resample across the edge at the estimated position. Reads gamma-encoded luma from alpha and
// writes alpha = 1. Written for this project from the published description of the algorithm.
in vec2 v_uv;
#include "frame.glsl"

layout(std140, binding = TL_UBO_PASS) uniform tl_fxaa_block {
    float u_fxaa_subpix;
    float u_fxaa_edge_threshold;
    float u_fxaa_edge_threshold_min;
};

layout(binding = TL_UNIT_LDR) uniform sampler2D u_ldr; // bilinear filtering
#define u_rcp_size u_inv_size
#define u_edge_threshold u_fxaa_edge_threshold
#define u_edge_threshold_min u_fxaa_edge_threshold_min
#define u_subpix u_fxaa_subpix
layout(location = TL_OUT_OUTPUT) out vec4 o_color;

#ifndef TL_FXAA_STEPS
#define TL_FXAA_STEPS 12
#endif
#if TL_FXAA_STEPS == 5
const float TL_FXAA_STEP[5] = float[](1.0, 1.5, 2.0, 4.0, 12.0);
#elif defined(TL_FXAA_FINE)
const float TL_FXAA_STEP[12] = float[](1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.5, 2.0, 4.0, 8.0);
#else
const float TL_FXAA_STEP[12] = float[](1.0, 1.0, 1.0, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0);
#endif

float tl_luma(vec2 uv) { return textureLod(u_ldr, uv, 0.0).a; }
float tl_luma_at(vec2 uv, vec2 d) { return textureLod(u_ldr, uv + d * u_rcp_size, 0.0).a; }

void main()
{
    vec2 uv = v_uv; // not gl_FragCoord: the output may be a viewport inside a caller framebuffer
    vec4 center = textureLod(u_ldr, uv, 0.0);
    float lm = center.a;
    float ln = tl_luma_at(uv, vec2(0.0, 1.0)), ls = tl_luma_at(uv, vec2(0.0, -1.0));
    float le = tl_luma_at(uv, vec2(1.0, 0.0)), lw = tl_luma_at(uv, vec2(-1.0, 0.0));
    float lmax = max(max(max(ln, ls), max(le, lw)), lm);
    float lmin = min(min(min(ln, ls), min(le, lw)), lm);
    float range = lmax - lmin;
    if (range < max(u_edge_threshold_min, lmax * u_edge_threshold)) {
        o_color = vec4(center.rgb, 1.0);
        return;
    }
    float lne = tl_luma_at(uv, vec2(1.0, 1.0)), lnw = tl_luma_at(uv, vec2(-1.0, 1.0));
    float lse = tl_luma_at(uv, vec2(1.0, -1.0)), lsw = tl_luma_at(uv, vec2(-1.0, -1.0));

    // Sub-pixel aliasing: how far the centre stands out from its 3x3 low-pass.
    float lowpass = (2.0 * (ln + ls + le + lw) + (lne + lnw + lse + lsw)) / 12.0;
    float sa = clamp(abs(lowpass - lm) / range, 0.0, 1.0);
    float sb = (-2.0 * sa + 3.0) * sa * sa;
    float subpix = sb * sb * u_subpix;

    // Orientation: a horizontal edge varies vertically.
    float horz_edge = abs(lnw - 2.0 * lw + lsw) + 2.0 * abs(ln - 2.0 * lm + ls) + abs(lne - 2.0 * le + lse);
    float vert_edge = abs(lnw - 2.0 * ln + lne) + 2.0 * abs(lw - 2.0 * lm + le) + abs(lsw - 2.0 * ls + lse);
    bool horizontal = horz_edge >= vert_edge;

    float l_neg = horizontal ? ls : lw, l_pos = horizontal ? ln : le;
    float g_neg = abs(l_neg - lm), g_pos = abs(l_pos - lm);
    bool neg_steeper = g_neg >= g_pos;
    float step_len = horizontal ? u_rcp_size.y : u_rcp_size.x;
    float local_avg = 0.5 * ((neg_steeper ? l_neg : l_pos) + lm);
    float grad_scaled = 0.25 * max(g_neg, g_pos);
    if (neg_steeper) step_len = -step_len;

    // Walk both ways along the edge, half a pixel onto the edge, until the luma leaves its average.
    vec2 edge_uv = uv + (horizontal ? vec2(0.0, 0.5 * step_len) : vec2(0.5 * step_len, 0.0));
    vec2 along = horizontal ? vec2(u_rcp_size.x, 0.0) : vec2(0.0, u_rcp_size.y);
    vec2 uv1 = edge_uv - along, uv2 = edge_uv + along;
    float e1 = tl_luma(uv1) - local_avg, e2 = tl_luma(uv2) - local_avg;
    bool done1 = abs(e1) >= grad_scaled, done2 = abs(e2) >= grad_scaled;
    for (int i = 1; i < TL_FXAA_STEPS && !(done1 && done2); i++) {
        if (!done1) {
            uv1 -= along * TL_FXAA_STEP[i];
            e1 = tl_luma(uv1) - local_avg;
            done1 = abs(e1) >= grad_scaled;
        }
        if (!done2) {
            uv2 += along * TL_FXAA_STEP[i];
            e2 = tl_luma(uv2) - local_avg;
            done2 = abs(e2) >= grad_scaled;
        }
    }
    float d1 = horizontal ? uv.x - uv1.x : uv.y - uv1.y;
    float d2 = horizontal ? uv2.x - uv.x : uv2.y - uv.y;
    bool nearer1 = d1 < d2;
    float dist = min(d1, d2);
    float span = d1 + d2;
    float offset = 0.5 - dist / span;
    // Only blend when the edge end found lies on the side the centre's luma agrees with.
    bool centre_below = lm < local_avg;
    bool good = ((nearer1 ? e1 : e2) < 0.0) != centre_below;
    float final_offset = max(good ? offset : 0.0, subpix);
    vec2 final_uv = uv + (horizontal ? vec2(0.0, final_offset * step_len) : vec2(final_offset * step_len, 0.0));
    o_color = vec4(textureLod(u_ldr, final_uv, 0.0).rgb, 1.0);
}
