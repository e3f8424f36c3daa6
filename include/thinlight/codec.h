/**
 * @file thinlight/codec.h
 * @brief Every encoding of the thin G-buffer, in pure C (no GL, no allocation, no global state).
 *
 * This is the single source of truth; shaders/codec.glsl mirrors it line for line and the parity
 * tests demand identical bits. Link thinlight::codec (libthinlight-codec) alone to use it without
 * any GL dependency; libthinlight contains it too.
 *
 * Conventions:
 * - Scalar functions take and return single values; batch functions (suffix _n) loop over caller
 *   arrays and give bit-identical results to the scalar ones.
 * - Bit budgets outside a function's documented range are clamped into it.
 * - No function returns NaN or Inf for any input, including NaN, Inf, zero and denormal inputs.
 */
#ifndef THINLIGHT_CODEC_H
#define THINLIGHT_CODEC_H

#include "thinlight/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------------------------
 * Unit vectors
 * ------------------------------------------------------------------------------------------- */

/** Smallest bits per component of the octahedral and other 2-component encodings. */
#define TL_OCT_MIN_BITS 8u
/** Largest bits per component of the octahedral and other 2-component encodings. */
#define TL_OCT_MAX_BITS 16u

/**
 * Makes any 3-vector usable as a direction: NaN anywhere gives +Z; a zero or all-denormal vector
 * is scaled exactly (no underflow) and a true zero gives +Z; infinite components become +-1 and
 * the finite ones 0. The result is unit length (within float rounding).
 */
TL_API void tl_normal_sanitize(const float in[3], float out[3]);

/**
 * Octahedral projection of a direction onto the square [-1,1]^2 without quantisation.
 * The lower hemisphere is folded with sign-not-zero taken from the sign *bit*, so that -0 and +0
 * stay distinct and (0,0,-1) maps to a corner (GLSL's plain sign() would send it to +Z).
 * Any input is accepted (it is sanitised first).
 */
TL_API void tl_oct_project(const float n[3], float p[2]);
/** Inverse of tl_oct_project: a point of [-1,1]^2 (clamped) to a unit vector. */
TL_API void tl_oct_unproject(const float p[2], float n[3]);

/**
 * Octahedral code with `bits` per component (TL_OCT_MIN_BITS..TL_OCT_MAX_BITS): u in the low
 * `bits` bits, v in the next `bits` bits. Each component lies on an odd grid of 2^bits - 1
 * levels: code k (0..2^bits - 2) stands for -1 + 2k / (2^bits - 2), so code 2^(bits-1) - 1 is
 * exactly 0 and the ends are exactly -1 and +1; +-X, +-Y, +-Z (and the zero vector, as +Z)
 * decode exactly. The code 2^bits - 1 is never produced and decodes like 2^bits - 2.
 * Plain rounding to the nearest code of each component.
 */
TL_API uint32_t tl_oct_encode(const float n[3], uint32_t bits);
/** Like tl_oct_encode, but returns the floor/ceil candidate (of 4) with the smallest angle. */
TL_API uint32_t tl_oct_encode_precise(const float n[3], uint32_t bits);
/** Decodes an octahedral code into a unit vector. */
TL_API void tl_oct_decode(uint32_t code, uint32_t bits, float n[3]);

/** Batch tl_oct_encode: `n` holds `count` xyz triples, `codes` receives `count` codes. */
TL_API void tl_oct_encode_n(const float *n, uint32_t *codes, size_t count, uint32_t bits);
/** Batch tl_oct_encode_precise: `n` holds `count` xyz triples, `codes` receives `count` codes. */
TL_API void tl_oct_encode_precise_n(const float *n, uint32_t *codes, size_t count, uint32_t bits);
/** Batch tl_oct_decode: `codes` holds `count` codes, `n` receives `count` xyz triples. */
TL_API void tl_oct_decode_n(const uint32_t *codes, float *n, size_t count, uint32_t bits);

/** Other 2-component unit-vector encodings, kept for comparison in the codec report. Lambert and
 *  stereographic quantise on the octahedral (odd) grid; spherical on its own unorm grid of
 *  2^bits levels per component. */
typedef enum tl_normal_encoding {
    TL_NORMAL_DEFAULT = 0,     /**< = TL_NORMAL_OCT_PRECISE */
    TL_NORMAL_OCT,             /**< octahedral, plain rounding */
    TL_NORMAL_OCT_PRECISE,     /**< octahedral, best of 4 candidates */
    TL_NORMAL_SPHERICAL,       /**< (azimuth, cos polar) on a uniform grid; full sphere */
    TL_NORMAL_LAMBERT,         /**< Lambert azimuthal equal-area ("spheremap"); full sphere */
    TL_NORMAL_STEREOGRAPHIC,   /**< stereographic from the south pole; upper hemisphere only,
                                    lower-hemisphere inputs are clamped to the equator */
    TL_NORMAL_OCT_EVEN,        /**< octahedral, plain rounding, on the even grid of 2^bits levels
                                    (k stands for -1 + 2k / (2^bits - 1); no exact 0, so the axes
                                    and +Z are never exact): the layout before the odd grid */
    TL_NORMAL_OCT_PRECISE_EVEN, /**< octahedral, best of 4 candidates, on the even grid */
    TL_NORMAL_ENCODING_COUNT_  /**< number of values (not an encoding) */
} tl_normal_encoding;

/** Stable short name of an encoding ("oct", "oct-precise", "spherical", ...). */
TL_API const char *tl_normal_encoding_name(tl_normal_encoding encoding);
/** Encodes with any of the encodings above; same code layout as tl_oct_encode. */
TL_API uint32_t tl_normal_encode(tl_normal_encoding encoding, const float n[3], uint32_t bits);
/** Decodes a code of tl_normal_encode into a unit vector. */
TL_API void tl_normal_decode(tl_normal_encoding encoding, uint32_t code, uint32_t bits, float n[3]);
/** Batch tl_normal_encode: `count` xyz triples to `count` codes. */
TL_API void tl_normal_encode_n(tl_normal_encoding encoding, const float *n, uint32_t *codes,
                               size_t count, uint32_t bits);
/** Batch tl_normal_decode: `count` codes to `count` xyz triples. */
TL_API void tl_normal_decode_n(tl_normal_encoding encoding, const uint32_t *codes, float *n,
                               size_t count, uint32_t bits);

/* ---------------------------------------------------------------------------------------------
 * Gloss
 * ------------------------------------------------------------------------------------------- */

/* Gloss 0 is the roughest surface; gloss 1 the smoothest. */
#define TL_GLOSS_MIN_POWER 2.0f    /**< Blinn-Phong exponent at gloss 0 */
#define TL_GLOSS_MAX_POWER 4096.0f /**< Blinn-Phong exponent at gloss 1 */

/**
 * The one gloss mapping: specular power = 2^(1 + 11 * gloss), so gloss in [0,1] covers
 * [2, 4096] with equal steps per doubling. Gloss is clamped to [0,1]; NaN counts as 0.
 */
TL_API float tl_gloss_to_specular_power(float gloss);
/** Inverse of tl_gloss_to_specular_power (power clamped to [2, 4096]). */
TL_API float tl_specular_power_to_gloss(float power);
/** Smallest GGX alpha of the gloss mapping, 2^-7: alpha^2 = 2^-14 is FP16's smallest normal number,
 *  and the peak of the lobe's weight, 1 / (4 alpha^2), equals the renderer's per-light clamp 4096. */
#define TL_GGX_MIN_ALPHA 0.0078125f

/**
 * The one gloss mapping of the GGX model: alpha = max((1 - gloss)^2, TL_GGX_MIN_ALPHA), i.e. gloss
 * is one minus the perceptual roughness, so a glTF material (stored as gloss = 1 - roughness)
 * gets glTF's alpha = roughness^2 (down to roughness sqrt(TL_GGX_MIN_ALPHA) = 0.088; every gloss
 * above 0.9116 is the smoothest lobe). Gloss is clamped to [0,1]; NaN counts as 0. Monotonic
 * non-increasing, alpha 1 at gloss 0.
 */
TL_API float tl_gloss_to_ggx_alpha(float gloss);
/** Inverse of tl_gloss_to_ggx_alpha over alpha in [TL_GGX_MIN_ALPHA, 1]: 1 - sqrt(alpha), with alpha
 *  clamped to [0, 1]; NaN means the smoothest (gloss 1). */
TL_API float tl_ggx_alpha_to_gloss(float alpha);
/** Unsigned-normalised quantisation of gloss to `bits` (1..16): round(clamp(g) * (2^bits - 1)). */
TL_API uint32_t tl_gloss_encode(float gloss, uint32_t bits);
/** Inverse of tl_gloss_encode: code / (2^bits - 1), codes above 2^bits - 1 clamped. */
TL_API float tl_gloss_decode(uint32_t code, uint32_t bits);

/* ---------------------------------------------------------------------------------------------
 * RT0: normal + gloss
 * ------------------------------------------------------------------------------------------- */

/**
 * RGBA8 layout: precise octahedral 2x12 bits plus 8-bit gloss.
 *   R = u[11:4], G = v[11:4], B = u[3:0] << 4 | v[3:0], A = gloss8.
 * The texel is returned as bytes R, G, B, A.
 */
TL_API void tl_rt0_encode_rgba8(const float n[3], float gloss, uint8_t texel[4]);
/** Decodes an RGBA8 RT0 texel into a unit normal and gloss. */
TL_API void tl_rt0_decode_rgba8(const uint8_t texel[4], float n[3], float *gloss);
/** Batch tl_rt0_encode_rgba8: `count` xyz triples and glosses to `count` * 4 bytes. */
TL_API void tl_rt0_encode_rgba8_n(const float *n, const float *gloss, uint8_t *texels, size_t count);
/** Batch tl_rt0_decode_rgba8: `count` * 4 bytes to `count` xyz triples and glosses. */
TL_API void tl_rt0_decode_rgba8_n(const uint8_t *texels, float *n, float *gloss, size_t count);

/**
 * RGB10A2 layout (GL_UNSIGNED_INT_2_10_10_10_REV order, R in the low bits): precise octahedral
 * 2x10 bits, 10-bit gloss and 2 flag bits.
 *   bits 0-9 u, 10-19 v, 20-29 gloss10, 30-31 flags.
 */
TL_API uint32_t tl_rt0_encode_rgb10a2(const float n[3], float gloss, uint32_t flags);
/** Decodes an RGB10A2 RT0 texel into a unit normal, gloss and the 2 flag bits. */
TL_API void tl_rt0_decode_rgb10a2(uint32_t texel, float n[3], float *gloss, uint32_t *flags);

/* ---------------------------------------------------------------------------------------------
 * Albedo: luma + checkerboarded chroma
 * ------------------------------------------------------------------------------------------- */

/** How albedo is split into luma and two chroma channels. */
typedef enum tl_color_space {
    TL_COLOR_SPACE_DEFAULT = 0, /**< = TL_COLOR_SPACE_YCBCR */
    TL_COLOR_SPACE_YCBCR,       /**< BT.601 full range: Y, Cb, Cr with 0.5 chroma offset */
    TL_COLOR_SPACE_YCOCG,       /**< Y = R/4 + G/2 + B/4, Co = (R - B)/2, Cg = G/2 - (R + B)/4 */
    TL_COLOR_SPACE_COUNT_       /**< number of values (not a colour space) */
} tl_color_space;

/** How the chroma a pixel does not store is rebuilt from its neighbours. */
typedef enum tl_chroma_filter {
    TL_CHROMA_FILTER_DEFAULT = 0, /**< = TL_CHROMA_FILTER_EDGE */
    TL_CHROMA_FILTER_NEAREST,     /**< the left neighbour (or the first in-image neighbour) */
    TL_CHROMA_FILTER_BILINEAR,    /**< mean of the in-image 4-neighbours */
    TL_CHROMA_FILTER_EDGE,        /**< luma-similarity weights; the most similar neighbour when
                                       no neighbour is similar */
    TL_CHROMA_FILTER_COUNT_       /**< number of values (not a filter) */
} tl_chroma_filter;

/** Luma difference (in [0,1] units) beyond which the edge filter ignores a neighbour. */
#define TL_CHROMA_EDGE_THRESHOLD (30.0f / 255.0f)

/** Stable short name of a colour space ("ycbcr", "ycocg"; DEFAULT gives its value's name,
 *  "unknown" for values out of range). */
TL_API const char *tl_color_space_name(tl_color_space space);
/** Stable short name of a chroma filter ("nearest", "bilinear", "edge"; DEFAULT gives its
 *  value's name, "unknown" for values out of range). */
TL_API const char *tl_chroma_filter_name(tl_chroma_filter filter);

/**
 * Converts an RGB colour (each channel in [0,1], typically sRGB-encoded albedo) to luma and two
 * chroma channels in [0,1] (chroma offset by 0.5), and back. Inputs are clamped to [0,1]; NaN
 * counts as 0. The inverse clamps its RGB output to [0,1].
 */
TL_API void tl_rgb_to_luma_chroma(tl_color_space space, const float rgb[3], float ycc[3]);
/** Inverse of tl_rgb_to_luma_chroma; the RGB output is clamped to [0,1]. */
TL_API void tl_luma_chroma_to_rgb(tl_color_space space, const float ycc[3], float rgb[3]);

/** Which chroma a pixel stores: 0 (Cb or Co) when (x + y) is even, 1 (Cr or Cg) when odd. */
static inline uint32_t tl_chroma_parity(uint32_t x, uint32_t y) { return (x + y) & 1u; }

/**
 * Encodes one pixel into two bytes: [0] = Y8, [1] = the chroma selected by tl_chroma_parity.
 * Rounding is to nearest, with 8-bit unsigned-normalised values.
 */
TL_API void tl_albedo_encode_pixel(tl_color_space space, const float rgb[3], uint32_t x, uint32_t y,
                                   uint8_t out[2]);
/** Encodes a w*h image of RGB floats (row-major, 3 floats a pixel) into w*h*2 bytes. */
TL_API tl_result tl_albedo_encode_image(tl_color_space space, const float *rgb, uint32_t w, uint32_t h,
                                        uint8_t *yc);
/**
 * Rebuilds RGB (w*h*3 floats in [0,1]) from an encoded w*h*2 image by reconstructing each pixel's
 * missing chroma from its 4 neighbours, which all store it. Neighbours outside the image are
 * mirrored back in (x = -1 reads x = 1, which has the same parity); a neighbour that is still
 * outside (images one pixel wide or high) is not used, and a pixel with no usable neighbour
 * (a 1x1 image) gets neutral chroma 0.5. Returns TL_ERROR_INVALID_ARGUMENT for NULL buffers, a
 * zero size, or w*h*3 overflowing size_t.
 */
TL_API tl_result tl_albedo_reconstruct(tl_color_space space, tl_chroma_filter filter, const uint8_t *yc,
                                       uint32_t w, uint32_t h, float *rgb);
/** The missing chroma of pixel (x, y) alone, in [0,1]; the building block of tl_albedo_reconstruct. */
TL_API float tl_albedo_missing_chroma(tl_chroma_filter filter, const uint8_t *yc, uint32_t w, uint32_t h,
                                      uint32_t x, uint32_t y);

/** sRGB transfer function (IEC 61966-2-1), exact piecewise form; input clamped to [0,1]. */
TL_API float tl_srgb_to_linear(float c);
/** Inverse sRGB transfer function (IEC 61966-2-1), exact piecewise form; input clamped to [0,1]. */
TL_API float tl_linear_to_srgb(float c);

/* ---------------------------------------------------------------------------------------------
 * Depth and position
 * ------------------------------------------------------------------------------------------- */

/** How depth is stored, and which clip-space convention the projection uses. */
typedef enum tl_depth_format {
    TL_DEPTH_FORMAT_DEFAULT = 0,   /**< = TL_DEPTH_FORMAT_D24 */
    TL_DEPTH_FORMAT_D24,           /**< 24-bit unorm window depth, GL [-1,1] clip range */
    TL_DEPTH_FORMAT_D32F,          /**< float window depth, GL [-1,1] clip range */
    TL_DEPTH_FORMAT_D32F_REVERSED, /**< float, reversed Z with a [0,1] clip range
                                        (glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)) */
    TL_DEPTH_FORMAT_COUNT_         /**< number of values (not a format) */
} tl_depth_format;

/** Stable short name of a depth format ("d24", "d32f", "d32f-reversed"; DEFAULT gives its
 *  value's name, "unknown" for values out of range). */
TL_API const char *tl_depth_format_name(tl_depth_format format);
/** Parses a name of tl_depth_format_name ("d24" gives TL_DEPTH_FORMAT_D24); TL_ERROR_INVALID_ARGUMENT
 *  for anything else. */
TL_API tl_result tl_depth_format_from_name(const char *name, tl_depth_format *format);

/** A symmetric or off-centre perspective projection. far <= 0 or Inf means an infinite far plane. */
typedef struct tl_projection {
    float m[16];            /**< column-major, OpenGL conventions (view looks down -Z) */
    tl_depth_format format; /**< which depth convention m was built for */
} tl_projection;

/**
 * Builds the projection for a depth format: vertical field of view in radians, aspect w/h,
 * near > 0, far > near or <= 0 / Inf for infinite. Returns TL_ERROR_INVALID_ARGUMENT for
 * non-finite or non-positive fov, aspect or near, or far <= near (when finite).
 */
TL_API tl_result tl_projection_perspective(tl_depth_format format, float fov_y, float aspect, float near_z,
                                           float far_z, tl_projection *out);

/**
 * Window depth (what the depth buffer stores, before quantisation) of a point at view-space
 * z = -distance (distance > 0), computed as the GPU does in float: clip = m * p, ndc = z / w,
 * window = ndc * 0.5 + 0.5 (or ndc for reversed Z). Clamped to [0,1].
 */
TL_API float tl_depth_window_from_distance(const tl_projection *proj, float distance);
/** Quantises a window depth for storage: D24 rounds to 24 bits (returned as code / (2^24 - 1)),
 *  D32F formats return it unchanged. NaN gives 1 (far) for standard, 0 for reversed Z. */
TL_API float tl_depth_quantize(tl_depth_format format, float window_depth);
/** 24-bit unorm code of a window depth: round(clamp(d, 0, 1) * (2^24 - 1)); NaN gives the far
 *  plane's code. */
TL_API uint32_t tl_depth_encode_d24(float window_depth);
/** Window depth of a 24-bit code: code / (2^24 - 1), codes above 2^24 - 1 clamped. */
TL_API float tl_depth_decode_d24(uint32_t code);
/** Batch tl_depth_encode_d24 over `count` values. */
TL_API void tl_depth_encode_d24_n(const float *window_depth, uint32_t *codes, size_t count);
/** Batch tl_depth_decode_d24 over `count` values. */
TL_API void tl_depth_decode_d24_n(const uint32_t *codes, float *window_depth, size_t count);

/**
 * Linear view-space z (negative in front of the camera) from window depth:
 *   z_ndc = 2 d - 1 (or d for reversed Z), z_eye = b / (c * z_ndc - a)
 * with a = m[10], b = m[14], c = m[11]. Depth at the infinite far plane returns -FLT_MAX, never
 * Inf or NaN.
 */
TL_API float tl_depth_linearize(const tl_projection *proj, float window_depth);
/**
 * View-space position from window depth with the view-ray method: d_eye is the ray through the
 * pixel scaled to z = 1, d_eye = (-(x_ndc + m[8]) / m[0], -(y_ndc + m[9]) / m[5], 1), and the
 * position is z_eye * d_eye.
 */
TL_API void tl_view_position_from_depth(const tl_projection *proj, float x_ndc, float y_ndc,
                                        float window_depth, float pos[3]);
/** Batch tl_view_position_from_depth: `ndc_xy` holds `count` (x, y) pairs, `window_depth`
 *  `count` depths, and `pos` receives `count` xyz triples. */
TL_API void tl_view_position_from_depth_n(const tl_projection *proj, const float *ndc_xy,
                                          const float *window_depth, float *pos, size_t count);

/* ---------------------------------------------------------------------------------------------
 * Half float (light buffer)
 * ------------------------------------------------------------------------------------------- */

/** Largest finite binary16 value; tl_half_from_float saturates to it. */
#define TL_HALF_MAX 65504.0f

/**
 * IEEE binary16 from float, round to nearest even, including denormals. Saturating: values whose
 * magnitude rounds beyond TL_HALF_MAX (and +-Inf) become +-TL_HALF_MAX, and NaN becomes +0, so
 * no Inf or NaN is ever stored in the light buffer.
 */
TL_API uint16_t tl_half_from_float(float f);
/** Float from IEEE binary16, exact (denormals included; Inf and NaN as stored). */
TL_API float tl_half_to_float(uint16_t h);
/** Batch tl_half_from_float over `count` values. */
TL_API void tl_half_from_float_n(const float *f, uint16_t *h, size_t count);
/** Batch tl_half_to_float over `count` values. */
TL_API void tl_half_to_float_n(const uint16_t *h, float *f, size_t count);

#ifdef __cplusplus
}
#endif
#endif
