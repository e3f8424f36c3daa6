// Depth of field (docs/effects.md): circle of confusion c(z) = min(aperture |z - f| / z, largest)
// x image height (pixels), z linear depth, f the focus distance; a gather over a golden-angle
// spiral of the largest radius R. A tap at distance r counts where its disc reaches the centre,
// clamp(c - r + 0.5, 0, 1), with the share of its energy one pixel receives,
// (pi R^2 / n) / max(pi c^2, 1); taps behind the centre use min(c_tap, c_centre), so a sharp pixel
// keeps blurred background off it, and a sharp foreground tap (small c) reaches no blurred pixel
// farther than its own disc. A pixel no other tap reaches keeps its colour exactly.
#include "effects.glsl"

layout(std140, binding = TL_UBO_PASS) uniform tl_dof_block {
    vec4 u_dof; // focus distance, aperture, largest CoC (fractions of the height), 0
};

in vec2 v_uv;
layout(binding = TL_UNIT_HDR) uniform sampler2D u_hdr;
layout(location = TL_OUT_DOF) out vec4 o_dof;

float tl_coc(float z, float height)
{
    float f = u_dof.x, c = isinf(z) ? u_dof.y : u_dof.y * abs(z - f) / max(z, 1e-30);
    return min(c, u_dof.z) * height;
}

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy), size = textureSize(u_hdr, 0);
    float height = float(size.y), big = u_dof.z * height;
    vec4 c0 = texelFetch(u_hdr, px, 0);
    float z0 = tl_fx_linear_depth(px), coc0 = tl_coc(z0, height);
    float w0 = 1.0 / max(3.14159265 * coc0 * coc0, 1.0), area = 3.14159265 * big * big / float(TL_DOF_SAMPLES);
    vec3 sum = vec3(0.0);
    float wsum = 0.0, turn = 6.2831853 * tl_fx_noise(gl_FragCoord.xy);
    for (int i = 0; i < TL_DOF_SAMPLES; i++) {
        float f = (float(i) + 0.5) / float(TL_DOF_SAMPLES), a = float(i) * 2.39996323 + turn;
        ivec2 q = px + ivec2(round(vec2(cos(a), sin(a)) * sqrt(f) * big));
        if (q == px || any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
        float r = length(vec2(q - px)), zq = tl_fx_linear_depth(q), cq = tl_coc(zq, height);
        float c = zq < z0 ? cq : min(cq, coc0);
        float w = clamp(c - r + 0.5, 0.0, 1.0) * area / max(3.14159265 * c * c, 1.0);
        vec3 col = texelFetch(u_hdr, q, 0).rgb;
        if (w > 0.0 && !any(isnan(col)) && !any(isinf(col))) {
            sum += w * col;
            wsum += w;
        }
    }
    // alpha: the circle of confusion's radius in pixels (tl_renderer_read_target(TL_TARGET_DOF))
    o_dof = vec4(wsum > 0.0 ? (c0.rgb * w0 + sum) / (w0 + wsum) : c0.rgb, coc0);
}
