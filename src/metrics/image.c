/* Error summaries between two images (or arrays), and relative error. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "thinlight/metrics.h"

#define TL__PSNR_MAX 999.0

/* Fills the derived fields from sums over `finite` pairs. PSNR is capped at 999 so a
 * near-identical pair never outscores an identical one; with no finite pair at all it is 0, so
 * an all-NaN image never reads as a perfect match. */
static void tl__image_error_finish(tl_image_error *out, double sum_sq, double sum_abs,
                                   double max_abs, size_t finite, double peak)
{
    if (finite == 0) {
        out->mse = out->mean_abs = out->max_abs = 0.0;
        out->psnr_db = 0.0;
        return;
    }
    out->mse = sum_sq / (double)finite;
    out->mean_abs = sum_abs / (double)finite;
    out->max_abs = max_abs;
    if (out->mse == 0.0) {
        out->psnr_db = TL__PSNR_MAX;
    } else {
        double psnr = 10.0 * log10(peak * peak / out->mse);
        out->psnr_db = psnr < TL__PSNR_MAX ? psnr : TL__PSNR_MAX;
    }
}

tl_result tl_image_compare(const float *a, const float *b, size_t count, double peak,
                           tl_image_error *out)
{
    if (out) memset(out, 0, sizeof *out);
    if (!a || !b || !out || count == 0 || !(peak > 0.0) || !isfinite(peak))
        return TL_ERROR_INVALID_ARGUMENT;
    /* Differences in double: float differences and their squares are exact or nearly so, and
     * the sums cannot overflow for any float input. */
    double sum_sq = 0.0, sum_abs = 0.0, max_abs = 0.0;
    size_t nonfinite = 0;
    for (size_t i = 0; i < count; i++) {
        double x = a[i], y = b[i];
        if (!isfinite(x) || !isfinite(y)) {
            nonfinite++;
            continue;
        }
        double d = fabs(x - y);
        sum_sq += d * d;
        sum_abs += d;
        if (d > max_abs) max_abs = d;
    }
    out->count = count;
    out->nonfinite = nonfinite;
    tl__image_error_finish(out, sum_sq, sum_abs, max_abs, count - nonfinite, peak);
    return TL_OK;
}

tl_result tl_image_compare_u8(const uint8_t *a, const uint8_t *b, size_t count, tl_image_error *out)
{
    if (out) memset(out, 0, sizeof *out);
    if (!a || !b || !out || count == 0) return TL_ERROR_INVALID_ARGUMENT;
    /* Exact integer sums: 255^2 per value overflows 64 bits only past 2.8e14 values. */
    uint64_t sum_sq = 0, sum_abs = 0;
    unsigned max_abs = 0;
    for (size_t i = 0; i < count; i++) {
        unsigned d = a[i] > b[i] ? (unsigned)(a[i] - b[i]) : (unsigned)(b[i] - a[i]);
        sum_sq += (uint64_t)d * d;
        sum_abs += d;
        if (d > max_abs) max_abs = d;
    }
    out->count = count;
    tl__image_error_finish(out, (double)sum_sq, (double)sum_abs, (double)max_abs, count, 255.0);
    return TL_OK;
}

double tl_relative_error(double a, double ref)
{
    if (isnan(a) || isnan(ref)) return NAN;
    if (a == ref) return 0.0; /* also both 0, and equal infinities */
    /* Division by 0 (or an overflowing quotient) reports the largest finite value rather than
     * Inf, so the result stays printable in JSON and summable in tl_stats. */
    if (isinf(ref)) return isinf(a) ? DBL_MAX : 1.0;
    double r = fabs(a - ref) / fabs(ref);
    return r < DBL_MAX ? r : DBL_MAX;
}
