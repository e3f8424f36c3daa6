// thinlight codec, GLSL mirror of src/codec (oct_core.h, rt0.c, gloss.c, albedo.c, depth.c).
// Every function performs the same IEEE operations in the same order as its C twin; `precise`
// forbids contraction into FMA, so that the parity test can demand identical bits.
// Included by pass shaders; requires GLSL 4.50.

#ifndef TL_CODEC_GLSL
#define TL_CODEC_GLSL

// Sign-not-zero from the sign bit: -0 gives -1 (plain sign() would give 0 and send (0,0,-1) to +Z).
float tl_sign_not_zero(float v)
{
    return (floatBitsToUint(v) >> 31) != 0u ? -1.0 : 1.0;
}

// Usable without sanitising: L1 norm in [2^-32, 2^60] (oct_core.h tl__oct_input_ok says why).
bool tl_oct_input_ok(vec3 n)
{
    precise float l1 = (abs(n.x) + abs(n.y)) + abs(n.z);
    return l1 >= 2.3283064365386963e-10 && l1 <= 1.152921504606847e18; // 2^-32, 2^60
}

void tl_normalize3(inout vec3 v)
{
    precise float len2 = (v.x * v.x + v.y * v.y) + v.z * v.z;
    precise float inv = 1.0 / sqrt(len2);
    v = vec3(v.x * inv, v.y * inv, v.z * inv);
}

// tl_normal_sanitize: NaN -> +Z, zero -> +Z, Inf components -> +-1 (finite ones 0), else scaled by
// the largest magnitude and normalised.
vec3 tl_normal_sanitize(vec3 n)
{
    if (isnan(n.x) || isnan(n.y) || isnan(n.z)) return vec3(0.0, 0.0, 1.0);
    float m = max(abs(n.x), max(abs(n.y), abs(n.z)));
    if (m == 0.0) return vec3(0.0, 0.0, 1.0);
    precise vec3 v;
    if (isinf(m)) {
        v = vec3(isinf(n.x) ? tl_sign_not_zero(n.x) : 0.0,
                 isinf(n.y) ? tl_sign_not_zero(n.y) : 0.0,
                 isinf(n.z) ? tl_sign_not_zero(n.z) : 0.0);
    } else {
        v = vec3(n.x / m, n.y / m, n.z / m);
    }
    tl_normalize3(v);
    return v;
}

vec2 tl_oct_project_raw(vec3 n)
{
    precise float l1 = (abs(n.x) + abs(n.y)) + abs(n.z);
    precise float u = n.x / l1;
    precise float v = n.y / l1;
    if (n.z < 0.0) {
        precise float fu = (1.0 - abs(v)) * tl_sign_not_zero(u);
        precise float fv = (1.0 - abs(u)) * tl_sign_not_zero(v);
        u = fu;
        v = fv;
    }
    return vec2(u, v);
}

vec3 tl_oct_unproject_raw(vec2 p)
{
    precise float u = p.x;
    precise float v = p.y;
    precise float w = (1.0 - abs(u)) - abs(v);
    if (w < 0.0) {
        precise float fu = (1.0 - abs(v)) * tl_sign_not_zero(u);
        precise float fv = (1.0 - abs(u)) * tl_sign_not_zero(v);
        u = fu;
        v = fv;
    }
    return vec3(u, v, w);
}

// The odd grid of oct_core.h: codes 0..top with top = 2^bits - 2, code k standing for
// (2k - top) / top; the centre is exactly 0 and the ends exactly -1 and +1.
uint tl_oct_top(uint bits)
{
    return (1u << bits) - 2u;
}

float tl_oct_dequant(uint k, uint top, float inv_top)
{
    precise float f = float(int(2u * k) - int(top)) * inv_top;
    return f;
}

uint tl_oct_quant(float p, float half_top)
{
    precise float q = (p + 1.0) * half_top;
    precise float r = q + 0.5;
    return uint(int(r));
}

vec3 tl_oct_input(vec3 n)
{
    return tl_oct_input_ok(n) ? n : tl_normal_sanitize(n);
}

// Code layout as in C: u in the low `bits` bits, v above it.
uint tl_oct_encode(vec3 n, uint bits)
{
    vec3 v = tl_oct_input(n);
    uint top = tl_oct_top(bits);
    float half_top = 0.5 * float(top);
    vec2 p = tl_oct_project_raw(v);
    return tl_oct_quant(p.x, half_top) | (tl_oct_quant(p.y, half_top) << bits);
}

float tl_oct_candidate_error(vec3 n, float cu, float cv)
{
    vec3 d = tl_oct_unproject_raw(vec2(cu, cv));
    precise float ex = n.y * d.z - n.z * d.y;
    precise float ey = n.z * d.x - n.x * d.z;
    precise float ez = n.x * d.y - n.y * d.x;
    precise float e = (ex * ex + ey * ey) + ez * ez;
    precise float l = (d.x * d.x + d.y * d.y) + d.z * d.z;
    precise float r = e / l;
    return r;
}

uint tl_oct_encode_precise(vec3 n, uint bits)
{
    vec3 v = tl_oct_input(n);
    uint top = tl_oct_top(bits);
    float half_top = 0.5 * float(top);
    float inv_top = 1.0 / float(top);
    vec2 p = tl_oct_project_raw(v);
    precise float qu = (p.x + 1.0) * half_top;
    precise float qv = (p.y + 1.0) * half_top;
    uint u0 = min(uint(int(qu)), top - 1u);
    uint v0 = min(uint(int(qv)), top - 1u);
    // Per component, a = the plain-rounded code (always u0 or u0 + 1), b = the other one.
    uint ua = tl_oct_quant(p.x, half_top), va = tl_oct_quant(p.y, half_top);
    uint ub = (2u * u0 + 1u) - ua, vb = (2u * v0 + 1u) - va;
    float cua = tl_oct_dequant(ua, top, inv_top), cub = tl_oct_dequant(ub, top, inv_top);
    float cva = tl_oct_dequant(va, top, inv_top), cvb = tl_oct_dequant(vb, top, inv_top);
    // Fixed order, the plain-rounded candidate first; a later one wins only when strictly better
    // (exact ties on the square's outer edge keep the input's zero sign).
    float best = tl_oct_candidate_error(v, cua, cva);
    uint bu = ua, bv = va;
    float e = tl_oct_candidate_error(v, cub, cva);
    if (e < best) { best = e; bu = ub; bv = va; }
    e = tl_oct_candidate_error(v, cua, cvb);
    if (e < best) { best = e; bu = ua; bv = vb; }
    e = tl_oct_candidate_error(v, cub, cvb);
    if (e < best) { bu = ub; bv = vb; }
    return bu | (bv << bits);
}

// Components are clamped to the grid (the unused code 2^bits - 1 decodes as top).
vec3 tl_oct_decode(uint code, uint bits)
{
    uint mask = (1u << bits) - 1u;
    uint top = tl_oct_top(bits);
    float inv_top = 1.0 / float(top);
    float u = tl_oct_dequant(min(code & mask, top), top, inv_top);
    float v = tl_oct_dequant(min((code >> bits) & mask, top), top, inv_top);
    vec3 n = tl_oct_unproject_raw(vec2(u, v));
    tl_normalize3(n);
    return n;
}

// ---- gloss ---------------------------------------------------------------------------------

uint tl_gloss_encode(float gloss, uint bits)
{
    float g = gloss > 0.0 ? (gloss < 1.0 ? gloss : 1.0) : 0.0; // NaN -> 0, as in C
    precise float q = g * float((1u << bits) - 1u);
    precise float r = q + 0.5;
    return uint(r);
}

float tl_gloss_decode(uint code, uint bits)
{
    uint maxv = (1u << bits) - 1u;
    return float(min(code, maxv)) / float(maxv);
}

// Specular power 2^(1 + 11 g), the one gloss mapping (codec.h). The exponent is exact like C's
// (NaN -> 0 as in tl__clamp01, which GLSL clamp() leaves undefined); exp2 itself is only as
// accurate as the driver's (GLSL: 3 + 2|x| ULP), so this is the one function not bit-exact.
float tl_gloss_to_specular_power(float gloss)
{
    float g = gloss > 0.0 ? (gloss < 1.0 ? gloss : 1.0) : 0.0;
    precise float e = 1.0 + 11.0 * g;
    return exp2(e);
}

// GGX alpha = max((1 - g)^2, 2^-7), the GGX model's gloss mapping (codec.h); bit-exact with C.
float tl_gloss_to_ggx_alpha(float gloss)
{
    float g = gloss > 0.0 ? (gloss < 1.0 ? gloss : 1.0) : 0.0;
    precise float r = 1.0 - g;
    precise float a = r * r;
    return a > 0.0078125 ? a : 0.0078125;
}

// ---- RT0 -----------------------------------------------------------------------------------

// RGBA8: R = u[11:4], G = v[11:4], B = u[3:0] << 4 | v[3:0], A = gloss8 (bytes as uint).
uvec4 tl_rt0_encode_rgba8(vec3 n, float gloss)
{
    uint code = tl_oct_encode_precise(n, 12u);
    uint u = code & 0xFFFu, v = code >> 12;
    return uvec4(u >> 4, v >> 4, ((u & 0xFu) << 4) | (v & 0xFu), tl_gloss_encode(gloss, 8u));
}

// Decodes bytes (as read back from an RGBA8 target: round(value * 255)).
vec4 tl_rt0_decode_rgba8(uvec4 t)
{
    uint u = (t.r << 4) | (t.b >> 4);
    uint v = (t.g << 4) | (t.b & 0xFu);
    return vec4(tl_oct_decode(u | (v << 12), 12u), tl_gloss_decode(t.a, 8u));
}

uvec4 tl_unorm8_bytes(vec4 c)
{
    return uvec4(c * 255.0 + 0.5);
}

// Two RT0 texels (as sampled) hold the same normal: its bits alone (rg with RGB10A2, rgb with
// RGBA8), whatever their gloss (the light scale's upsample: one surface, one normal).
bool tl_rt0_same_normal(vec4 a, vec4 b)
{
#ifdef TL_RT0_RGB10A2
    return a.rg == b.rg;
#else
    return a.rgb == b.rgb;
#endif
}

// RGB10A2: bits 0-9 u, 10-19 v, 20-29 gloss10, 30-31 flags.
uint tl_rt0_encode_rgb10a2(vec3 n, float gloss, uint flags)
{
    return tl_oct_encode_precise(n, 10u) | (tl_gloss_encode(gloss, 10u) << 20) | ((flags & 3u) << 30);
}

vec4 tl_rt0_decode_rgb10a2(uint t)
{
    return vec4(tl_oct_decode(t & 0xFFFFFu, 10u), tl_gloss_decode((t >> 20) & 0x3FFu, 10u));
}

// An RT0 texel as a pass samples it (UNORM, 0..1) -> normal and gloss, in the frame's packing.
vec4 tl_rt0_texel_decode(vec4 t)
{
#ifdef TL_RT0_RGB10A2
    uvec4 q = uvec4(t * vec4(1023.0, 1023.0, 1023.0, 3.0) + 0.5);
    return tl_rt0_decode_rgb10a2(q.x | (q.y << 10) | (q.z << 20) | (q.w << 30));
#else
    return tl_rt0_decode_rgba8(tl_unorm8_bytes(t));
#endif
}

// ---- albedo --------------------------------------------------------------------------------

float tl_clamp01(float v) { return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0; }

// BT.601 full range (space 1) or YCoCg (space 2); chroma offset by 0.5.
vec3 tl_rgb_to_luma_chroma(uint space, vec3 rgb)
{
    float r = tl_clamp01(rgb.r), g = tl_clamp01(rgb.g), b = tl_clamp01(rgb.b);
    if (space == 2u) {
        precise float y = (0.25 * r + 0.5 * g) + 0.25 * b;
        precise float co = 0.5 * (r - b) + 0.5;
        precise float cg = (0.5 * g - 0.25 * (r + b)) + 0.5;
        return vec3(y, co, cg);
    }
    precise float y = (0.299 * r + 0.587 * g) + 0.114 * b;
    precise float cb = (b - y) * (0.5 / 0.886) + 0.5;
    precise float cr = (r - y) * (0.5 / 0.701) + 0.5;
    return vec3(tl_clamp01(y), tl_clamp01(cb), tl_clamp01(cr)); // cyan's Cr rounds to -6e-8
}

vec3 tl_luma_chroma_to_rgb(uint space, vec3 ycc)
{
    precise float y = isnan(ycc.x) ? 0.0 : ycc.x; // NaN: luma 0, neutral chroma, as in C
    precise float c1 = (isnan(ycc.y) ? 0.5 : ycc.y) - 0.5;
    precise float c2 = (isnan(ycc.z) ? 0.5 : ycc.z) - 0.5;
    precise float r, g, b;
    if (space == 2u) {
        precise float t = y - c2;
        g = y + c2;
        r = t + c1;
        b = t - c1;
    } else {
        r = y + 1.402 * c2;
        b = y + 1.772 * c1;
        g = ((y - 0.299 * r) - 0.114 * b) / 0.587;
    }
    return vec3(tl_clamp01(r), tl_clamp01(g), tl_clamp01(b));
}

uint tl_chroma_parity(uvec2 p) { return (p.x + p.y) & 1u; }

uint tl_unorm8(float v)
{
    precise float q = tl_clamp01(v) * 255.0;
    precise float r = q + 0.5;
    return uint(r);
}

// Two bytes: luma and the chroma selected by the pixel's parity.
uvec2 tl_albedo_encode_pixel(uint space, vec3 rgb, uvec2 pixel)
{
    vec3 ycc = tl_rgb_to_luma_chroma(space, rgb);
    return uvec2(tl_unorm8(ycc.x), tl_unorm8(tl_chroma_parity(pixel) == 0u ? ycc.y : ycc.z));
}

// Edge-directed weights of tl_albedo_missing_chroma (filter 3) from the centre luma byte and the
// four neighbours' (luma, chroma) bytes; count = how many neighbours are usable (in order).
float tl_albedo_edge_chroma(int luma, ivec4 nl, ivec4 nc, int count)
{
    if (count == 0) return 0.5;
    const float threshold = (30.0 / 255.0) * 255.0;
    precise float wsum = 0.0;
    precise float csum = 0.0;
    int closest = 0;
    for (int i = 0; i < count; i++) {
        int d = abs(nl[i] - luma);
        int dc = abs(nl[closest] - luma);
        if (d < dc) closest = i;
        precise float wgt = 1.0 - float(d) / threshold;
        if (wgt > 0.0) {
            wsum += wgt;
            csum += wgt * float(nc[i]);
        }
    }
    if (wsum <= 0.0) return float(nc[closest]) / 255.0;
    precise float den = wsum * 255.0;
    return csum / den;
}

// ---- depth ---------------------------------------------------------------------------------

// z_eye = b / (c * z_ndc - a), a = m[10], b = m[14], c = m[11]; reversed Z uses z_ndc = d.
float tl_depth_linearize(float window_depth, float a, float b, float c, bool reversed)
{
    precise float z_ndc = reversed ? window_depth : 2.0 * window_depth - 1.0;
    precise float den = c * z_ndc - a;
    precise float z = b / den;
    if (isinf(z) || isnan(z) || z > 0.0) return -3.4028234663852886e38;
    return z;
}

// View-ray method: d_eye = (-(x_ndc + m8) / m0, -(y_ndc + m9) / m5, 1), position = z_eye * d_eye.
// As in C: a NaN coordinate counts as the centre line, and z_eye * d saturates to +-FLT_MAX (z_eye
// is -FLT_MAX at the infinite far plane, so the product overflows wherever |d| > 1).
float tl_saturate_float(float v)
{
    return v > 3.4028234663852886e38 ? 3.4028234663852886e38 : (v < -3.4028234663852886e38 ? -3.4028234663852886e38 : v);
}

vec3 tl_view_position(float z_eye, vec2 ndc, vec4 m0_m5_m8_m9)
{
    float nx = isnan(ndc.x) ? 0.0 : ndc.x;
    float ny = isnan(ndc.y) ? 0.0 : ndc.y;
    precise float dx = -(nx + m0_m5_m8_m9.z) / m0_m5_m8_m9.x;
    precise float dy = -(ny + m0_m5_m8_m9.w) / m0_m5_m8_m9.y;
    precise float px = z_eye * dx;
    precise float py = z_eye * dy;
    return vec3(tl_saturate_float(px), tl_saturate_float(py), z_eye);
}

#endif
