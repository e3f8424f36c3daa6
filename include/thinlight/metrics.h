/**
 * @file thinlight/metrics.h
 * @brief Error measures for vectors, colours and images, and running statistics.
 *
 * Pure C: no GL, no allocation, no global state (part of thinlight::codec). Used by the tests,
 * the reports and the demo.
 */
#ifndef THINLIGHT_METRICS_H
#define THINLIGHT_METRICS_H

#include "thinlight/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Angle in degrees between two directions (need not be unit length), computed in double with
 *  atan2(|a x b|, a . b) so that tiny angles are exact. Zero or NaN vectors give 180. */
TL_API double tl_angle_deg(const float a[3], const float b[3]);

/** CIE L*a*b* (D65 white) of an sRGB-encoded colour with channels in [0,1]. */
TL_API void tl_srgb_to_lab(const double srgb[3], double lab[3]);
/** CIEDE2000 colour difference (kL = kC = kH = 1), as in Sharma, Wu and Dalal (2005). NULL gives NaN. */
TL_API double tl_ciede2000(const double lab1[3], const double lab2[3]);

/** Summary of the difference between two float images or arrays of `count` values. */
typedef struct tl_image_error {
    double mse;            /**< mean squared error over finite pairs */
    double psnr_db;        /**< 10 log10(peak^2 / mse), capped at 999 (mse == 0); 0 when no pair is finite */
    double mean_abs;       /**< mean absolute error over finite pairs */
    double max_abs;        /**< largest absolute error over finite pairs */
    size_t nonfinite;      /**< values where either side is NaN or Inf (excluded above) */
    size_t count;          /**< values compared, non-finite ones included */
} tl_image_error;

/** Compares `count` floats; `peak` (finite, > 0) is the signal's peak, 1 for [0,1] images. NULL, a
 *  zero count or a bad peak returns TL_ERROR_INVALID_ARGUMENT and zeroes `out`. */
TL_API tl_result tl_image_compare(const float *a, const float *b, size_t count, double peak,
                                  tl_image_error *out);
/** Same for 8-bit data (peak 255, errors in 8-bit steps). */
TL_API tl_result tl_image_compare_u8(const uint8_t *a, const uint8_t *b, size_t count, tl_image_error *out);

/** Relative error |a - ref| / |ref| in double; 0 when both are 0, DBL_MAX when ref is 0 and a is
 *  not (never Inf, so the value stays valid JSON); NaN inputs give NaN. */
TL_API double tl_relative_error(double a, double ref);

/* Running statistics: mean, max and percentiles from a log-spaced histogram held in the struct
 * (no allocation). Values are non-negative errors; negative and NaN values are counted in
 * `rejected` and otherwise ignored. Percentiles are exact to the bin width (1/64 of an octave,
 * about 1.1 %) and are clamped to [min, max] of the values seen. */
#define TL_STATS_OCTAVE_MIN (-64)  /**< smallest bin edge is 2^-64; smaller values (and 0) go in bin 0 */
#define TL_STATS_OCTAVE_MAX 64     /**< largest bin edge is 2^64; larger values go in the last bin */
#define TL_STATS_BINS_PER_OCTAVE 64 /**< histogram resolution: bins per doubling */
/** Number of histogram bins: the log-spaced ones plus one below and one above. */
#define TL_STATS_BINS ((TL_STATS_OCTAVE_MAX - TL_STATS_OCTAVE_MIN) * TL_STATS_BINS_PER_OCTAVE + 2)

/** Running statistics of non-negative values; zero-initialised it is empty and ready (no
 *  allocation: the histogram is inside, about 64 KiB). */
typedef struct tl_stats {
    uint64_t count;               /**< values accepted */
    uint64_t rejected;            /**< negative and NaN values seen (otherwise ignored) */
    double sum;                   /**< sum of the accepted values */
    double min;                   /**< smallest accepted value (0 when empty) */
    double max;                   /**< largest accepted value (0 when empty) */
    uint64_t bins[TL_STATS_BINS]; /**< log-spaced histogram of the accepted values */
} tl_stats;

/** Resets to empty (every field 0); a zero-initialised tl_stats is equally empty and ready. */
TL_API void tl_stats_reset(tl_stats *s);
/** Adds one value (negative or NaN: counted in `rejected` only). */
TL_API void tl_stats_add(tl_stats *s, double value);
/** Adds `count` values, as tl_stats_add one by one. */
TL_API void tl_stats_add_n(tl_stats *s, const double *values, size_t count);
/** Folds `other` into `s`. */
TL_API void tl_stats_merge(tl_stats *s, const tl_stats *other);
/** Mean of the accepted values (0 when empty). */
TL_API double tl_stats_mean(const tl_stats *s);
/** The p-quantile by nearest rank (p in [0,1], e.g. 0.99): exactly min at p <= 0 and max at
 *  p >= 1, 0 when empty, NaN for a NaN p. */
TL_API double tl_stats_percentile(const tl_stats *s, double p);

#ifdef __cplusplus
}
#endif
#endif
