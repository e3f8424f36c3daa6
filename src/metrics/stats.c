/* Running statistics over non-negative errors, with a log-spaced histogram for percentiles. */
#include <math.h>
#include <string.h>

#include "thinlight/metrics.h"

#define TL__SUBS TL_STATS_BINS_PER_OCTAVE
#define TL__LAST_BIN (TL_STATS_BINS - 1)

/* Lower edge of sub-bin j (0..TL__SUBS) within an octave, as a factor in [1, 2]. Binning and
 * percentile estimation both use these exact doubles, so a value always lies inside the edges
 * its bin is estimated from. */
static double tl__sub_edge(int j)
{
    if (j <= 0) return 1.0;
    if (j >= TL__SUBS) return 2.0;
    return exp2((double)j / TL__SUBS);
}

/* Bin of a non-negative, non-NaN value: 0 below 2^OCTAVE_MIN, the last bin from 2^OCTAVE_MAX
 * (Inf included), otherwise 1 + octave * TL__SUBS + sub-bin. */
static size_t tl__bin(double v)
{
    if (!(v >= ldexp(1.0, TL_STATS_OCTAVE_MIN))) return 0;
    if (v >= ldexp(1.0, TL_STATS_OCTAVE_MAX)) return TL__LAST_BIN;
    int e;
    double m2 = 2.0 * frexp(v, &e); /* v = m2 * 2^(e-1), m2 in [1, 2) */
    double x = log2(m2) * TL__SUBS;
    int j = (int)x;
    if (j > TL__SUBS - 1) j = TL__SUBS - 1;
    /* log2 is not exact; next to an edge, settle the bin against the edge itself. */
    double frac = x - j;
    if (frac < 1e-6 && j > 0 && m2 < tl__sub_edge(j)) j--;
    else if (frac > 1.0 - 1e-6 && j < TL__SUBS - 1 && m2 >= tl__sub_edge(j + 1)) j++;
    return 1 + (size_t)(e - 1 - TL_STATS_OCTAVE_MIN) * TL__SUBS + (size_t)j;
}

void tl_stats_reset(tl_stats *s)
{
    if (s) memset(s, 0, sizeof *s);
}

void tl_stats_add(tl_stats *s, double value)
{
    if (!s) return;
    if (!(value >= 0.0)) { /* negative or NaN */
        s->rejected++;
        return;
    }
    /* Seed min and max from the first value, so a zero-initialised struct works as well. */
    if (s->count == 0) {
        s->min = s->max = value;
    } else {
        if (value < s->min) s->min = value;
        if (value > s->max) s->max = value;
    }
    s->count++;
    s->sum += value;
    s->bins[tl__bin(value)]++;
}

void tl_stats_add_n(tl_stats *s, const double *values, size_t count)
{
    if (!s || !values) return;
    for (size_t i = 0; i < count; i++) tl_stats_add(s, values[i]);
}

void tl_stats_merge(tl_stats *s, const tl_stats *other)
{
    if (!s || !other || s == other) return;
    s->rejected += other->rejected;
    if (other->count == 0) return;
    if (s->count == 0) {
        s->min = other->min;
        s->max = other->max;
    } else {
        if (other->min < s->min) s->min = other->min;
        if (other->max > s->max) s->max = other->max;
    }
    s->count += other->count;
    s->sum += other->sum;
    for (size_t i = 0; i < TL_STATS_BINS; i++) s->bins[i] += other->bins[i];
}

double tl_stats_mean(const tl_stats *s)
{
    if (!s || s->count == 0) return 0.0;
    return s->sum / (double)s->count;
}

double tl_stats_percentile(const tl_stats *s, double p)
{
    if (!s || s->count == 0) return 0.0;
    if (isnan(p)) return NAN;
    if (p <= 0.0) return s->min;
    if (p >= 1.0) return s->max;
    /* Nearest rank: the k-th smallest value, k = ceil(p n) in [1, n]. */
    double kd = ceil(p * (double)s->count);
    uint64_t k = kd < 1.0 ? 1 : kd >= (double)s->count ? s->count : (uint64_t)kd;
    uint64_t before = 0;
    size_t i = 0;
    while (i < TL__LAST_BIN && before + s->bins[i] < k) before += s->bins[i++];
    /* Place the rank inside its bin (mid-point rule), geometrically in the log-spaced bins. */
    double f = s->bins[i] ? ((double)(k - before) - 0.5) / (double)s->bins[i] : 0.5;
    double est;
    if (i == 0) {
        double hi = ldexp(1.0, TL_STATS_OCTAVE_MIN);
        est = s->min + f * ((s->max < hi ? s->max : hi) - s->min);
    } else if (i == TL__LAST_BIN) {
        /* Unbounded above: interpolate up to the largest value seen; with Inf among the
         * values, report Inf (an error summary should not understate). */
        double lo = ldexp(1.0, TL_STATS_OCTAVE_MAX);
        if (s->min > lo) lo = s->min;
        est = isinf(s->max) ? s->max : lo * pow(s->max / lo, f);
    } else {
        size_t b = i - 1;
        int octave = (int)(b / TL__SUBS) + TL_STATS_OCTAVE_MIN, j = (int)(b % TL__SUBS);
        double lo = ldexp(tl__sub_edge(j), octave), hi = ldexp(tl__sub_edge(j + 1), octave);
        est = lo * exp2(f / TL__SUBS);
        if (est > hi) est = hi;
        if (est < lo) est = lo;
    }
    if (est < s->min) est = s->min;
    if (est > s->max) est = s->max;
    return est;
}
