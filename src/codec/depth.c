/* Depth: projections for the standard and reversed-Z conventions, D24 quantisation,
 * linearisation and view-space position from depth with the view-ray method. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "thinlight/codec.h"

static const char *const tl__depth_names[TL_DEPTH_FORMAT_COUNT_] = {"d24", "d24", "d32f", "d32f-reversed"};

const char *tl_depth_format_name(tl_depth_format format)
{
    return (unsigned)format < TL_DEPTH_FORMAT_COUNT_ ? tl__depth_names[format] : "unknown";
}

tl_result tl_depth_format_from_name(const char *name, tl_depth_format *format)
{
    for (int i = TL_DEPTH_FORMAT_D24; name && format && i < TL_DEPTH_FORMAT_COUNT_; i++)
        if (strcmp(name, tl__depth_names[i]) == 0) {
            *format = (tl_depth_format)i;
            return TL_OK;
        }
    return TL_ERROR_INVALID_ARGUMENT;
}

static int tl__reversed(const tl_projection *p) { return p->format == TL_DEPTH_FORMAT_D32F_REVERSED; }

/* +-Inf to +-FLT_MAX (finite values unchanged). */
static float tl__saturate(float v) { return v > FLT_MAX ? FLT_MAX : v < -FLT_MAX ? -FLT_MAX : v; }

tl_result tl_projection_perspective(tl_depth_format format, float fov_y, float aspect, float near_z, float far_z,
                                    tl_projection *out)
{
    if (!out || (unsigned)format >= TL_DEPTH_FORMAT_COUNT_) return TL_ERROR_INVALID_ARGUMENT;
    if (!(isfinite(fov_y) && fov_y > 0.0f && fov_y < 3.14159f) || !(isfinite(aspect) && aspect > 0.0f) ||
        !(isfinite(near_z) && near_z > 0.0f) || isnan(far_z))
        return TL_ERROR_INVALID_ARGUMENT;
    int infinite = !(far_z > 0.0f) || isinf(far_z);
    if (!infinite && !(far_z > near_z)) return TL_ERROR_INVALID_ARGUMENT;
    if (format == TL_DEPTH_FORMAT_DEFAULT) format = TL_DEPTH_FORMAT_D24;

    /* Built in double and rounded once, so the matrix is as exact as float allows. */
    double f = 1.0 / tan(0.5 * (double)fov_y), n = near_z, fa = far_z;
    memset(out, 0, sizeof *out);
    out->format = format;
    out->m[0] = (float)(f / aspect);
    out->m[5] = (float)f;
    out->m[11] = -1.0f;
    if (format == TL_DEPTH_FORMAT_D32F_REVERSED) { /* near -> 1, far -> 0, clip z in [0, w] */
        out->m[10] = infinite ? 0.0f : (float)(n / (fa - n));
        out->m[14] = infinite ? (float)n : (float)(fa * n / (fa - n));
    } else { /* OpenGL: near -> -1, far -> +1 */
        out->m[10] = infinite ? -1.0f : (float)((fa + n) / (n - fa));
        out->m[14] = infinite ? (float)(-2.0 * n) : (float)(2.0 * fa * n / (n - fa));
    }
    return TL_OK;
}

float tl_depth_window_from_distance(const tl_projection *proj, float distance)
{
    if (!proj) return 1.0f;
    float z = -distance;
    float clip_z = proj->m[10] * z + proj->m[14], clip_w = proj->m[11] * z;
    float ndc = clip_z / clip_w;
    float d = tl__reversed(proj) ? ndc : ndc * 0.5f + 0.5f;
    if (isnan(d)) return tl__reversed(proj) ? 0.0f : 1.0f;
    return d > 0.0f ? (d < 1.0f ? d : 1.0f) : 0.0f;
}

uint32_t tl_depth_encode_d24(float window_depth)
{
    double d = isnan(window_depth) ? 1.0 : window_depth > 0.0f ? (window_depth < 1.0f ? window_depth : 1.0) : 0.0;
    return (uint32_t)(d * 16777215.0 + 0.5);
}

float tl_depth_decode_d24(uint32_t code)
{
    return (float)((double)(code > 0xFFFFFFu ? 0xFFFFFFu : code) / 16777215.0);
}

void tl_depth_encode_d24_n(const float *window_depth, uint32_t *codes, size_t count)
{
    if (!window_depth || !codes) return;
    for (size_t i = 0; i < count; i++) codes[i] = tl_depth_encode_d24(window_depth[i]);
}

void tl_depth_decode_d24_n(const uint32_t *codes, float *window_depth, size_t count)
{
    if (!window_depth || !codes) return;
    for (size_t i = 0; i < count; i++) window_depth[i] = tl_depth_decode_d24(codes[i]);
}

float tl_depth_quantize(tl_depth_format format, float window_depth)
{
    if (format == TL_DEPTH_FORMAT_D24 || format == TL_DEPTH_FORMAT_DEFAULT)
        return tl_depth_decode_d24(tl_depth_encode_d24(window_depth));
    if (isnan(window_depth)) return format == TL_DEPTH_FORMAT_D32F_REVERSED ? 0.0f : 1.0f;
    return window_depth;
}

float tl_depth_linearize(const tl_projection *proj, float window_depth)
{
    if (!proj) return -FLT_MAX;
    float z_ndc = tl__reversed(proj) ? window_depth : 2.0f * window_depth - 1.0f;
    float a = proj->m[10], b = proj->m[14], c = proj->m[11];
    float z = b / (c * z_ndc - a);
    /* depth at (or numerically beyond) the infinite far plane: as far as float goes */
    if (!isfinite(z) || z > 0.0f) return -FLT_MAX;
    return z;
}

void tl_view_position_from_depth(const tl_projection *proj, float x_ndc, float y_ndc, float window_depth,
                                 float pos[3])
{
    if (!proj) {
        pos[0] = pos[1] = 0.0f;
        pos[2] = -FLT_MAX;
        return;
    }
    float z = tl_depth_linearize(proj, window_depth);
    /* A NaN coordinate counts as the centre line. */
    float dx = -((isnan(x_ndc) ? 0.0f : x_ndc) + proj->m[8]) / proj->m[0];
    float dy = -((isnan(y_ndc) ? 0.0f : y_ndc) + proj->m[9]) / proj->m[5];
    /* z is -FLT_MAX at (or beyond) the infinite far plane, so z * d overflows wherever |d| > 1
     * (any ray off the centre of a wide frustum): saturate like z itself. */
    pos[0] = tl__saturate(z * dx);
    pos[1] = tl__saturate(z * dy);
    pos[2] = z;
}

void tl_view_position_from_depth_n(const tl_projection *proj, const float *ndc_xy, const float *window_depth,
                                   float *pos, size_t count)
{
    if (!proj || !ndc_xy || !window_depth || !pos) return;
    for (size_t i = 0; i < count; i++)
        tl_view_position_from_depth(proj, ndc_xy[2 * i], ndc_xy[2 * i + 1], window_depth[i], pos + 3 * i);
}
