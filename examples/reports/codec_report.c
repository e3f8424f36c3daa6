/* thinlight-codec-report: measures every G-buffer encoding (error against its input, and encode
 * and decode time on this machine) and writes a table, JSON, an error-vs-time plot and,
 * optionally, the generated section of docs/precision.md. Contract: docs/tools.md. */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "thinlight/codec.h"
#include "thinlight/metrics.h"
#include "thinlight/version.h"

#include "test_images.h"
#include "tool_args.h"
#include "tool_util.h"

#ifndef TL_REPORT_COMPILER
#define TL_REPORT_COMPILER "unknown compiler"
#endif
#ifndef TL_REPORT_FLAGS
#define TL_REPORT_FLAGS ""
#endif
#ifndef TL_REPORT_BUILD_TYPE
#define TL_REPORT_BUILD_TYPE ""
#endif

#define TOOL "thinlight-codec-report"
#define PLOT_NAME "codec_error_vs_time"
#define DOC_BEGIN "<!-- codec-report:begin -->"
#define DOC_END "<!-- codec-report:end -->"
#define PLOT_MAX_BYTES (300u * 1024u)
#define MAX_RECORDS 64u
/* normal 25 (oct 10, oct even grid 6, others 9) + albedo 6 + depth 9 + gloss 2 */
#define VARIANT_COUNT 42u
_Static_assert(VARIANT_COUNT <= MAX_RECORDS, "records array too small");
#define EXIT_BAD_INPUT 1
#define EXIT_BAD_USAGE 2

static const char usage_text[] =
    "usage: " TOOL " [--json OUT.json] [--out DIR] [--quick] [--no-plot] [--doc FILE] [--help]\n"
    "\n"
    "Measures every thin G-buffer encoding: error against the input (mean, p99, max) and the\n"
    "median encode and decode time per element on this machine.\n"
    "\n"
    "  --json OUT.json  write the records as JSON\n"
    "  --out DIR        write the plot DIR/" PLOT_NAME ".png (and its gnuplot script and data);\n"
    "                   required unless --no-plot\n"
    "  --quick          fewer elements and repeats (a smoke run, a few seconds)\n"
    "  --no-plot        do not run gnuplot\n"
    "  --doc FILE       replace the text between " DOC_BEGIN " and\n"
    "                   " DOC_END " in FILE with generated tables, and copy the\n"
    "                   plot to the img/ directory beside FILE\n"
    "  --list-options   list every option and the values it takes, then exit\n"
    "  --help           this text\n"
    "\n"
    "This tool runs on the CPU only and makes no GL context: unlike the renderer tools it takes no\n"
    "--context, --device or --list-devices (they are refused as bad usage).\n"
    "\n"
    "Exit status: 0 success, 1 bad input (an unwritable path, a missing file), 2 bad usage.\n";

/* ---------------------------------------------------------------------------------------------
 * Records
 * ------------------------------------------------------------------------------------------- */

typedef enum record_kind { KIND_NORMAL, KIND_ALBEDO, KIND_DEPTH, KIND_GLOSS, KIND_COUNT } record_kind;

static const char *const kind_names[KIND_COUNT] = {"normal", "albedo", "depth", "gloss"};
static const char *const kind_units[KIND_COUNT] = {"deg", "8-bit steps", "relative", "relative power"};
static const char *const kind_titles[KIND_COUNT] = {
    "Normals: angle between input and decoded direction, degrees",
    "Albedo: largest channel error of a pixel, in 8-bit steps of sRGB",
    "Depth: relative view-space position error |p - p_exact| / |p_exact|",
    "Gloss: relative error of the specular power 2^(1 + 11 gloss)",
};

typedef struct record {
    char name[48];
    record_kind kind;
    uint32_t bits;
    double mean_error, p99_error, max_error;
    double ns_encode, ns_decode;
    char note[128];
    /* albedo only */
    double psnr_db, ciede2000_mean;
    double image_p99[TL_TEST_IMAGE_COUNT], image_max[TL_TEST_IMAGE_COUNT];
} record;

typedef struct report {
    record records[MAX_RECORDS];
    size_t count;
    tl_tool_progress progress;
    size_t elements; /* per timed run */
    size_t repeats;
    uint32_t image_size;
    int quick;
    char cpu[128];
    size_t cores;
    tl_stats *stats; /* scratch, heap: the histogram is 64 KiB */
    tl_stats *image_stats[TL_TEST_IMAGE_COUNT];
} report;

/* ---------------------------------------------------------------------------------------------
 * Small utilities
 * ------------------------------------------------------------------------------------------- */

#define fail_line(...) tl_tool_fail(TOOL, __VA_ARGS__)

static void *xcalloc(size_t count, size_t size)
{
    void *p = calloc(count ? count : 1, size ? size : 1);
    if (!p) fail_line("out of memory (%zu x %zu bytes)", count, size);
    return p;
}

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Deterministic inputs: splitmix64. */
static uint64_t splitmix64(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Uniform double in [0, 1). */
static double rand01(uint64_t *state) { return (double)(splitmix64(state) >> 11) * 0x1.0p-53; }

/* ---------------------------------------------------------------------------------------------
 * Machine description
 * ------------------------------------------------------------------------------------------- */

static const char *build_flags(void)
{
    const char *s = TL_REPORT_FLAGS;
    while (*s == ' ') s++;
    return s;
}

/* ---------------------------------------------------------------------------------------------
 * Progress
 * ------------------------------------------------------------------------------------------- */

static record *begin_record(report *r, record_kind kind, uint32_t bits, const char *fmt, ...)
{
    record *rec = &r->records[r->count];
    memset(rec, 0, sizeof *rec);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(rec->name, sizeof rec->name, fmt, ap);
    va_end(ap);
    rec->kind = kind;
    rec->bits = bits;
    tl_tool_progress_update(&r->progress, r->count, rec->name, 1);
    tl_stats_reset(r->stats);
    return rec;
}

static void end_record(report *r, record *rec)
{
    rec->mean_error = tl_stats_mean(r->stats);
    rec->p99_error = tl_stats_percentile(r->stats, 0.99);
    rec->max_error = r->stats->count ? r->stats->max : 0.0;
    r->count++;
}

/* ---------------------------------------------------------------------------------------------
 * Timing: each job runs `repeats` times over its whole batch; the median per element is kept.
 * ------------------------------------------------------------------------------------------- */

typedef void (*job_fn)(void *ctx);

static double time_per_element(job_fn fn, void *ctx, size_t elements, size_t repeats)
{
    double samples[64];
    if (repeats > 64) repeats = 64;
    fn(ctx); /* warm-up: first-touch page faults and cold caches are not the codec's cost */
    for (size_t i = 0; i < repeats; i++) {
        double t0 = now_ns();
        fn(ctx);
        samples[i] = (now_ns() - t0) / (double)elements;
    }
    qsort(samples, repeats, sizeof samples[0], cmp_double);
    return repeats % 2 ? samples[repeats / 2] : 0.5 * (samples[repeats / 2 - 1] + samples[repeats / 2]);
}

/* ---------------------------------------------------------------------------------------------
 * Normals
 * ------------------------------------------------------------------------------------------- */

typedef enum normal_method { NORMAL_OCT_PLAIN, NORMAL_OCT_PRECISE, NORMAL_OTHER } normal_method;

typedef struct normal_job {
    normal_method method;
    tl_normal_encoding encoding;
    uint32_t bits;
    const float *in;
    uint32_t *codes;
    float *out;
    size_t count;
} normal_job;

static void normal_encode(void *ctx)
{
    normal_job *j = ctx;
    if (j->method == NORMAL_OCT_PLAIN) tl_oct_encode_n(j->in, j->codes, j->count, j->bits);
    else if (j->method == NORMAL_OCT_PRECISE) tl_oct_encode_precise_n(j->in, j->codes, j->count, j->bits);
    else tl_normal_encode_n(j->encoding, j->in, j->codes, j->count, j->bits);
}

static void normal_decode(void *ctx)
{
    normal_job *j = ctx;
    if (j->method == NORMAL_OTHER) tl_normal_decode_n(j->encoding, j->codes, j->out, j->count, j->bits);
    else tl_oct_decode_n(j->codes, j->out, j->count, j->bits);
}

/* Worst error over the axis directions of the job's domain (+-X, +-Y, +Z, and -Z unless the
 * inputs are upper-hemisphere only): floors and walls are exactly such normals. */
static double axis_error(const normal_job *j, int upper_only)
{
    static const float axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    tl_normal_encoding e = j->method == NORMAL_OCT_PLAIN     ? TL_NORMAL_OCT
                           : j->method == NORMAL_OCT_PRECISE ? TL_NORMAL_OCT_PRECISE
                                                             : j->encoding;
    double worst = 0.0;
    for (int a = 0; a < (upper_only ? 5 : 6); a++) {
        float d[3];
        tl_normal_decode(e, tl_normal_encode(e, axes[a], j->bits), j->bits, d);
        worst = fmax(worst, tl_angle_deg(axes[a], d));
    }
    return worst;
}

static void measure_normal(report *r, normal_job *j, const char *name, const char *note, int upper_only)
{
    record *rec = begin_record(r, KIND_NORMAL, 2 * j->bits, "%s", name);
    double axes = axis_error(j, upper_only);
    if (axes == 0.0) snprintf(rec->note, sizeof rec->note, "%s; axes exact", note);
    else snprintf(rec->note, sizeof rec->note, "%s; axes %.3g deg", note, axes);
    rec->ns_encode = time_per_element(normal_encode, j, j->count, r->repeats);
    rec->ns_decode = time_per_element(normal_decode, j, j->count, r->repeats);
    for (size_t i = 0; i < j->count; i++) tl_stats_add(r->stats, tl_angle_deg(j->in + 3 * i, j->out + 3 * i));
    end_record(r, rec);
}

static int run_normals(report *r)
{
    static const uint32_t oct_bits[] = {8, 10, 12, 14, 16};
    static const uint32_t other_bits[] = {8, 12, 16};
    static const tl_normal_encoding others[] = {TL_NORMAL_SPHERICAL, TL_NORMAL_LAMBERT, TL_NORMAL_STEREOGRAPHIC};
    size_t n = r->elements;
    float *sphere = xcalloc(n * 3, sizeof(float));
    float *upper = xcalloc(n * 3, sizeof(float));
    uint32_t *codes = xcalloc(n, sizeof(uint32_t));
    float *out = xcalloc(n * 3, sizeof(float));
    int err = !sphere || !upper || !codes || !out;
    if (!err) {
        /* Uniform on the sphere: z uniform in [-1, 1], azimuth uniform. */
        uint64_t seed = 0x7468696E6C696768ull;
        for (size_t i = 0; i < n; i++) {
            double z = 2.0 * rand01(&seed) - 1.0, phi = 6.283185307179586 * rand01(&seed);
            double s = sqrt(fmax(0.0, 1.0 - z * z));
            sphere[3 * i] = (float)(s * cos(phi));
            sphere[3 * i + 1] = (float)(s * sin(phi));
            sphere[3 * i + 2] = (float)z;
            upper[3 * i] = sphere[3 * i];
            upper[3 * i + 1] = sphere[3 * i + 1];
            upper[3 * i + 2] = fabsf(sphere[3 * i + 2]);
        }
        for (size_t b = 0; b < sizeof oct_bits / sizeof oct_bits[0]; b++) {
            for (int precise = 0; precise < 2; precise++) {
                normal_job j = {precise ? NORMAL_OCT_PRECISE : NORMAL_OCT_PLAIN, TL_NORMAL_DEFAULT, oct_bits[b],
                                sphere, codes, out, n};
                char name[48];
                snprintf(name, sizeof name, "oct%u%s", (unsigned)oct_bits[b], precise ? "-precise" : "");
                measure_normal(r, &j, name, precise ? "best of 4 candidates" : "round to nearest", 0);
            }
        }
        /* The even grid (2^bits levels, no exact 0) the codec used before the odd one. */
        for (size_t b = 0; b < sizeof other_bits / sizeof other_bits[0]; b++) {
            for (int precise = 0; precise < 2; precise++) {
                normal_job j = {NORMAL_OTHER, precise ? TL_NORMAL_OCT_PRECISE_EVEN : TL_NORMAL_OCT_EVEN,
                                other_bits[b], sphere, codes, out, n};
                char name[48];
                snprintf(name, sizeof name, "oct%u%s-even", (unsigned)other_bits[b], precise ? "-precise" : "");
                measure_normal(r, &j, name, precise ? "best of 4, even grid" : "round to nearest, even grid", 0);
            }
        }
        for (size_t e = 0; e < sizeof others / sizeof others[0]; e++) {
            for (size_t b = 0; b < sizeof other_bits / sizeof other_bits[0]; b++) {
                int stereo = others[e] == TL_NORMAL_STEREOGRAPHIC;
                normal_job j = {NORMAL_OTHER, others[e], other_bits[b], stereo ? upper : sphere, codes, out, n};
                char name[48];
                snprintf(name, sizeof name, "%s%u%s", tl_normal_encoding_name(others[e]), (unsigned)other_bits[b],
                         stereo ? "-upper" : "");
                measure_normal(r, &j, name, stereo ? "upper hemisphere (z >= 0) inputs only" : "full sphere", stereo);
            }
        }
    }
    free(sphere);
    free(upper);
    free(codes);
    free(out);
    return err;
}

/* ---------------------------------------------------------------------------------------------
 * Albedo
 * ------------------------------------------------------------------------------------------- */

typedef struct albedo_job {
    tl_color_space space;
    tl_chroma_filter filter;
    uint32_t size;     /* every image is size x size */
    const float *src;  /* TL_TEST_IMAGE_COUNT images, 3 floats a pixel */
    uint8_t *yc;       /* 2 bytes a pixel */
    float *rgb;        /* reconstructed */
    tl_result result;  /* first failure, if any */
} albedo_job;

static void albedo_encode(void *ctx)
{
    albedo_job *j = ctx;
    size_t px = (size_t)j->size * j->size;
    for (size_t i = 0; i < TL_TEST_IMAGE_COUNT; i++) {
        tl_result res = tl_albedo_encode_image(j->space, j->src + i * px * 3, j->size, j->size, j->yc + i * px * 2);
        if (res != TL_OK && j->result == TL_OK) j->result = res;
    }
}

static void albedo_decode(void *ctx)
{
    albedo_job *j = ctx;
    size_t px = (size_t)j->size * j->size;
    for (size_t i = 0; i < TL_TEST_IMAGE_COUNT; i++) {
        tl_result res = tl_albedo_reconstruct(j->space, j->filter, j->yc + i * px * 2, j->size, j->size,
                                              j->rgb + i * px * 3);
        if (res != TL_OK && j->result == TL_OK) j->result = res;
    }
}

static int measure_albedo(report *r, albedo_job *j)
{
    record *rec = begin_record(r, KIND_ALBEDO, 16, "%s-%s", tl_color_space_name(j->space),
                               tl_chroma_filter_name(j->filter));
    size_t px = (size_t)j->size * j->size, total = px * TL_TEST_IMAGE_COUNT;
    rec->ns_encode = time_per_element(albedo_encode, j, total, r->repeats);
    rec->ns_decode = time_per_element(albedo_decode, j, total, r->repeats);
    if (j->result != TL_OK) {
        fail_line("%s: %s", rec->name, tl_result_string(j->result));
        return 1;
    }
    for (size_t im = 0; im < TL_TEST_IMAGE_COUNT; im++) {
        tl_stats_reset(r->image_stats[im]);
        for (size_t i = im * px; i < (im + 1) * px; i++) {
            double e = 0.0;
            for (size_t c = 0; c < 3; c++) e = fmax(e, fabs((double)j->rgb[3 * i + c] - (double)j->src[3 * i + c]));
            tl_stats_add(r->image_stats[im], e * 255.0);
        }
        tl_stats_merge(r->stats, r->image_stats[im]);
        rec->image_p99[im] = tl_stats_percentile(r->image_stats[im], 0.99);
        rec->image_max[im] = r->image_stats[im]->max;
    }
    tl_image_error ie;
    if (tl_image_compare(j->src, j->rgb, total * 3, 1.0, &ie) == TL_OK) rec->psnr_db = ie.psnr_db;
    /* CIEDE2000 on about 2 x 10^5 evenly spaced pixels: it costs far more than the codec. */
    size_t stride = total / 200000 + 1, samples = 0;
    double sum = 0.0;
    for (size_t i = 0; i < total; i += stride, samples++) {
        double a[3], b[3], la[3], lb[3];
        for (size_t c = 0; c < 3; c++) {
            a[c] = j->src[3 * i + c];
            b[c] = j->rgb[3 * i + c];
        }
        tl_srgb_to_lab(a, la);
        tl_srgb_to_lab(b, lb);
        sum += tl_ciede2000(la, lb);
    }
    rec->ciede2000_mean = samples ? sum / (double)samples : 0.0;
    snprintf(rec->note, sizeof rec->note, "PSNR %.2f dB; mean dE00 %.3f over 1 pixel in %zu", rec->psnr_db,
             rec->ciede2000_mean, stride);
    end_record(r, rec);
    return 0;
}

static int run_albedo(report *r)
{
    uint32_t size = r->image_size;
    size_t px = (size_t)size * size, total = px * TL_TEST_IMAGE_COUNT;
    float *src = xcalloc(total * 3, sizeof(float));
    uint8_t *yc = xcalloc(total * 2, 1);
    float *rgb = xcalloc(total * 3, sizeof(float));
    int err = !src || !yc || !rgb;
    if (!err) {
        for (size_t i = 0; i < TL_TEST_IMAGE_COUNT; i++) tl_test_image_generate((tl_test_image)i, size, size, src + i * px * 3);
        for (int s = TL_COLOR_SPACE_YCBCR; s <= TL_COLOR_SPACE_YCOCG && !err; s++) {
            for (int f = TL_CHROMA_FILTER_NEAREST; f <= TL_CHROMA_FILTER_EDGE && !err; f++) {
                albedo_job j = {(tl_color_space)s, (tl_chroma_filter)f, size, src, yc, rgb, TL_OK};
                err = measure_albedo(r, &j);
            }
        }
    }
    free(src);
    free(yc);
    free(rgb);
    return err;
}

/* ---------------------------------------------------------------------------------------------
 * Depth
 * ------------------------------------------------------------------------------------------- */

#define DEPTH_FOV_Y 1.0471975511965976 /* 60 degrees */
#define DEPTH_ASPECT (16.0 / 9.0)
#define DEPTH_NEAR 0.1

typedef struct depth_job {
    tl_projection proj;
    const float *distance;
    const float *ndc_xy;
    float *depth;     /* stored (quantised) window depth; D24 decodes its codes into it */
    uint32_t *codes;  /* D24 only */
    float *pos;
    size_t count;
} depth_job;

static void depth_encode(void *ctx)
{
    depth_job *j = ctx;
    tl_depth_format fmt = j->proj.format;
    if (fmt == TL_DEPTH_FORMAT_D24) {
        for (size_t i = 0; i < j->count; i++) j->depth[i] = tl_depth_window_from_distance(&j->proj, j->distance[i]);
        tl_depth_encode_d24_n(j->depth, j->codes, j->count);
    } else {
        for (size_t i = 0; i < j->count; i++)
            j->depth[i] = tl_depth_quantize(fmt, tl_depth_window_from_distance(&j->proj, j->distance[i]));
    }
}

static void depth_decode(void *ctx)
{
    depth_job *j = ctx;
    if (j->proj.format == TL_DEPTH_FORMAT_D24) tl_depth_decode_d24_n(j->codes, j->depth, j->count);
    tl_view_position_from_depth_n(&j->proj, j->ndc_xy, j->depth, j->pos, j->count);
}

static int measure_depth(report *r, depth_job *j, tl_depth_format fmt, double far_ratio, int infinite,
                         float *distance, double range)
{
    char ratio[16];
    snprintf(ratio, sizeof ratio, "%s", infinite ? "inf" : far_ratio >= 1e6 ? "1e7" : "1e4");
    record *rec = begin_record(r, KIND_DEPTH, fmt == TL_DEPTH_FORMAT_D24 ? 24 : 32, "%s-%s",
                               tl_depth_format_name(fmt), ratio);
    double near_z = DEPTH_NEAR, far_z = infinite ? INFINITY : DEPTH_NEAR * far_ratio;
    if (tl_projection_perspective(fmt, (float)DEPTH_FOV_Y, (float)DEPTH_ASPECT, (float)near_z, (float)far_z,
                                  &j->proj) != TL_OK) {
        fail_line("%s: tl_projection_perspective rejected near %g far %g", rec->name, near_z, far_z);
        return 1;
    }
    /* Distances log-uniform over [near, near * range]: equal weight to every octave. */
    uint64_t seed = 0x6465707468ull;
    for (size_t i = 0; i < j->count; i++) {
        float d = (float)(near_z * pow(range, rand01(&seed)));
        distance[i] = d < (float)near_z ? (float)near_z : d;
    }
    rec->ns_encode = time_per_element(depth_encode, j, j->count, r->repeats);
    rec->ns_decode = time_per_element(depth_decode, j, j->count, r->repeats);
    /* The exact position of the encoded point, in double, from the exact projection. */
    double f = 1.0 / tan(0.5 * DEPTH_FOV_Y);
    size_t nonfinite = 0;
    for (size_t i = 0; i < j->count; i++) {
        double d = distance[i];
        double ex = d * j->ndc_xy[2 * i] * DEPTH_ASPECT / f, ey = d * j->ndc_xy[2 * i + 1] / f, ez = -d;
        const float *p = j->pos + 3 * i;
        if (!(isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]))) {
            nonfinite++;
            continue;
        }
        double dx = p[0] - ex, dy = p[1] - ey, dz = p[2] - ez;
        tl_stats_add(r->stats, sqrt(dx * dx + dy * dy + dz * dz) / sqrt(ex * ex + ey * ey + ez * ez));
    }
    char far_text[32];
    snprintf(far_text, sizeof far_text, infinite ? "infinite" : "%g", far_z);
    int n = snprintf(rec->note, sizeof rec->note, "near %g, far %s; distances log-uniform in [%g, %g]%s", near_z,
                     far_text, near_z, near_z * range, fmt == TL_DEPTH_FORMAT_D24 ? "; decode includes unorm24 to float" : "");
    if (nonfinite && n > 0 && (size_t)n < sizeof rec->note)
        snprintf(rec->note + n, sizeof rec->note - (size_t)n, "; %zu non-finite positions excluded", nonfinite);
    end_record(r, rec);
    return 0;
}

static int run_depth(report *r)
{
    static const tl_depth_format formats[] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F, TL_DEPTH_FORMAT_D32F_REVERSED};
    size_t n = r->elements;
    float *distance = xcalloc(n, sizeof(float));
    float *ndc = xcalloc(n * 2, sizeof(float));
    float *depth = xcalloc(n, sizeof(float));
    uint32_t *codes = xcalloc(n, sizeof(uint32_t));
    float *pos = xcalloc(n * 3, sizeof(float));
    int err = !distance || !ndc || !depth || !codes || !pos;
    if (!err) {
        /* Pixels anywhere on screen, so grazing rays at the corners are included. */
        uint64_t seed = 0x6E6463ull;
        for (size_t i = 0; i < 2 * n; i++) ndc[i] = (float)(2.0 * rand01(&seed) - 1.0);
        /* Finite far planes at 1:10^4 and 1:10^7, and an infinite one probed over 1:10^7. */
        static const double ratios[] = {1e4, 1e7, 0.0};
        for (size_t k = 0; k < 3 && !err; k++) {
            for (size_t fi = 0; fi < 3 && !err; fi++) {
                depth_job j;
                memset(&j, 0, sizeof j);
                j.distance = distance;
                j.ndc_xy = ndc;
                j.depth = depth;
                j.codes = codes;
                j.pos = pos;
                j.count = n;
                int infinite = ratios[k] == 0.0;
                err = measure_depth(r, &j, formats[fi], ratios[k], infinite, distance, infinite ? 1e7 : ratios[k]);
            }
        }
    }
    free(distance);
    free(ndc);
    free(depth);
    free(codes);
    free(pos);
    return err;
}

/* ---------------------------------------------------------------------------------------------
 * Gloss
 * ------------------------------------------------------------------------------------------- */

typedef struct gloss_job {
    uint32_t bits;
    const float *in;
    uint32_t *codes;
    float *out;
    size_t count;
} gloss_job;

static void gloss_encode(void *ctx)
{
    gloss_job *j = ctx;
    for (size_t i = 0; i < j->count; i++) j->codes[i] = tl_gloss_encode(j->in[i], j->bits);
}

static void gloss_decode(void *ctx)
{
    gloss_job *j = ctx;
    for (size_t i = 0; i < j->count; i++) j->out[i] = tl_gloss_decode(j->codes[i], j->bits);
}

static int run_gloss(report *r)
{
    static const uint32_t bits[] = {8, 10};
    size_t n = r->elements;
    float *in = xcalloc(n, sizeof(float));
    uint32_t *codes = xcalloc(n, sizeof(uint32_t));
    float *out = xcalloc(n, sizeof(float));
    int err = !in || !codes || !out;
    if (!err) {
        uint64_t seed = 0x676C6F7373ull;
        for (size_t i = 0; i < n; i++) in[i] = (float)rand01(&seed);
        for (size_t b = 0; b < sizeof bits / sizeof bits[0]; b++) {
            gloss_job j = {bits[b], in, codes, out, n};
            record *rec = begin_record(r, KIND_GLOSS, bits[b], "gloss%u", (unsigned)bits[b]);
            snprintf(rec->note, sizeof rec->note, "gloss uniform in [0,1]; power 2..4096");
            rec->ns_encode = time_per_element(gloss_encode, &j, n, r->repeats);
            rec->ns_decode = time_per_element(gloss_decode, &j, n, r->repeats);
            /* The mapping evaluated in double on both sides isolates the quantisation. */
            for (size_t i = 0; i < n; i++) {
                double exact = exp2(1.0 + 11.0 * (double)in[i]), got = exp2(1.0 + 11.0 * (double)out[i]);
                tl_stats_add(r->stats, fabs(got - exact) / exact);
            }
            end_record(r, rec);
        }
    }
    free(in);
    free(codes);
    free(out);
    return err;
}

/* ---------------------------------------------------------------------------------------------
 * Output: table, JSON, plot, doc
 * ------------------------------------------------------------------------------------------- */

static void print_header(FILE *f, const report *r, const char *prefix)
{
    fprintf(f, "%sthinlight %s codec report%s\n", prefix, tl_version_string(), r->quick ? " (--quick)" : "");
    fprintf(f, "%smachine : %s, %zu cores\n", prefix, r->cpu, r->cores);
    fprintf(f, "%scompiler: %s\n", prefix, TL_REPORT_COMPILER);
    fprintf(f, "%sflags   : %s (%s)\n", prefix, build_flags(), TL_REPORT_BUILD_TYPE);
    fprintf(f, "%sbatch   : %zu elements (albedo: 5 images of %ux%u), median of %zu runs\n", prefix, r->elements,
            (unsigned)r->image_size, (unsigned)r->image_size, r->repeats);
}

static void print_table(const report *r)
{
    print_header(stdout, r, "");
    printf("\n%-22s %-6s %4s %-14s %10s %10s %10s %8s %8s  %s\n", "name", "kind", "bits", "error_unit", "mean",
           "p99", "max", "ns_enc", "ns_dec", "note");
    for (size_t i = 0; i < r->count; i++) {
        const record *rec = &r->records[i];
        printf("%-22s %-6s %4u %-14s %10.3g %10.3g %10.3g %8.2f %8.2f  %s\n", rec->name, kind_names[rec->kind],
               (unsigned)rec->bits, kind_units[rec->kind], rec->mean_error, rec->p99_error, rec->max_error,
               rec->ns_encode, rec->ns_decode, rec->note);
    }
    fflush(stdout);
}

static int write_json(FILE *f, const void *ctx)
{
    const report *r = ctx;
    char machine[192];
    snprintf(machine, sizeof machine, "%s, %zu cores", r->cpu, r->cores);
    fputs("{\n  \"tool\": \"" TOOL "\",\n  \"version\": ", f);
    tl_tool_json_string(f, tl_version_string());
    fputs(",\n  \"machine\": ", f);
    tl_tool_json_string(f, machine);
    fputs(",\n  \"cpu\": ", f);
    tl_tool_json_string(f, r->cpu);
    fprintf(f, ",\n  \"cores\": %zu,\n  \"compiler\": ", r->cores);
    tl_tool_json_string(f, TL_REPORT_COMPILER);
    fputs(",\n  \"flags\": ", f);
    tl_tool_json_string(f, build_flags());
    fputs(",\n  \"build_type\": ", f);
    tl_tool_json_string(f, TL_REPORT_BUILD_TYPE);
    fprintf(f, ",\n  \"quick\": %s,\n  \"elements_per_run\": %zu,\n  \"repeats\": %zu,\n  \"variants\": [",
            r->quick ? "true" : "false", r->elements, r->repeats);
    for (size_t i = 0; i < r->count; i++) {
        const record *rec = &r->records[i];
        fputs(i ? ",\n    {" : "\n    {", f);
        fputs("\"name\": ", f);
        tl_tool_json_string(f, rec->name);
        fprintf(f, ", \"kind\": \"%s\", \"bits\": %u, \"error_unit\": \"%s\",\n     \"mean_error\": ",
                kind_names[rec->kind], (unsigned)rec->bits, kind_units[rec->kind]);
        tl_tool_json_number(f, rec->mean_error);
        fputs(", \"p99_error\": ", f);
        tl_tool_json_number(f, rec->p99_error);
        fputs(", \"max_error\": ", f);
        tl_tool_json_number(f, rec->max_error);
        fputs(", \"ns_encode\": ", f);
        tl_tool_json_number(f, rec->ns_encode);
        fputs(", \"ns_decode\": ", f);
        tl_tool_json_number(f, rec->ns_decode);
        if (rec->kind == KIND_ALBEDO) {
            fputs(",\n     \"psnr_db\": ", f);
            tl_tool_json_number(f, rec->psnr_db);
            fputs(", \"ciede2000_mean\": ", f);
            tl_tool_json_number(f, rec->ciede2000_mean);
            fputs(", \"per_image\": {", f);
            for (size_t im = 0; im < TL_TEST_IMAGE_COUNT; im++) {
                fprintf(f, "%s\"%s\": {\"p99_error\": ", im ? ", " : "", tl_test_image_name((tl_test_image)im));
                tl_tool_json_number(f, rec->image_p99[im]);
                fputs(", \"max_error\": ", f);
                tl_tool_json_number(f, rec->image_max[im]);
                fputc('}', f);
            }
            fputc('}', f);
        }
        fputs(",\n     \"note\": ", f);
        tl_tool_json_string(f, rec->note);
        fputc('}', f);
    }
    fputs("\n  ]\n}\n", f);
    return 0;
}

/* The plot: one panel per kind, x = encode + decode ns, y = p99 on a log axis with a bar from the
 * mean to the max, colour = encoding family. Labels are placed greedily so that they do not
 * overlap (a leader line joins a moved label to its point); that needs fixed axis ranges, so the
 * ranges are chosen here rather than by gnuplot's autoscale. */

/* Approximate size of one 8-point label character and line as a fraction of a panel's plot area
 * at the terminal size below. */
#define PLOT_CHAR_W 0.0105
#define PLOT_LINE_H 0.038
#define PLOT_GAP 0.012

typedef struct plot_panel {
    double x_max;         /* x range is [0, x_max] */
    double y_lo, y_hi;    /* decades: y range is [10^y_lo, 10^y_hi] */
} plot_panel;

typedef struct plot_label {
    double x, y;          /* where the label text starts (left aligned), data coordinates */
    double lead_x, lead_y; /* start of the leader line, NaN when the label sits beside its point */
} plot_label;

typedef struct plot_layout {
    const report *r;
    plot_panel panels[KIND_COUNT];
    plot_label labels[MAX_RECORDS];
} plot_layout;

static double plot_floor(double v) { return v > 1e-12 ? v : 1e-12; }

static int family_of(const record *rec)
{
    static const char *const families[] = {"oct", "spherical", "lambert", "stereographic", "ycbcr", "ycocg",
                                           "d24", "d32f-reversed", "d32f", "gloss"};
    for (int i = 0; i < (int)(sizeof families / sizeof families[0]); i++) {
        size_t n = strlen(families[i]);
        if (strncmp(rec->name, families[i], n) == 0) {
            if (i == 0 && strstr(rec->name, "even")) return strstr(rec->name, "precise") ? 13 : 12;
            if (i == 0 && strstr(rec->name, "precise")) return 11;
            return i + 1;
        }
    }
    return 0;
}

typedef struct box {
    double x0, y0, x1, y1;
} box;

static int boxes_overlap(box a, box b) { return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1; }

static void layout_plot(plot_layout *L)
{
    const report *r = L->r;
    for (int k = 0; k < KIND_COUNT; k++) {
        plot_panel *p = &L->panels[k];
        double x_max = 0.0, lo = INFINITY, hi = -INFINITY;
        size_t longest = 0;
        for (size_t i = 0; i < r->count; i++) {
            const record *rec = &r->records[i];
            if ((int)rec->kind != k) continue;
            x_max = fmax(x_max, rec->ns_encode + rec->ns_decode);
            lo = fmin(lo, log10(plot_floor(fmin(rec->mean_error, rec->p99_error))));
            hi = fmax(hi, log10(plot_floor(fmax(rec->max_error, rec->p99_error))));
            size_t n = strlen(rec->name);
            if (n > longest) longest = n;
        }
        if (!(x_max > 0.0)) x_max = 1.0;
        if (!isfinite(lo) || !isfinite(hi)) lo = -1.0, hi = 1.0;
        /* room on the right for the longest label of the rightmost point */
        p->x_max = x_max / fmax(0.5, 1.0 - PLOT_GAP - (double)longest * PLOT_CHAR_W - 0.02);
        p->y_lo = floor(lo - 0.2); /* no point or bar end right on a border */
        p->y_hi = ceil(hi + 0.2);
        if (p->y_hi - p->y_lo < 2.0) p->y_hi = p->y_lo + 2.0;

        /* Panel fractions of every point, then labels one by one. */
        box placed[2 * MAX_RECORDS];
        size_t n_placed = 0;
        double span = p->y_hi - p->y_lo;
        for (size_t i = 0; i < r->count; i++) {
            const record *rec = &r->records[i];
            if ((int)rec->kind != k) continue;
            double px = (rec->ns_encode + rec->ns_decode) / p->x_max;
            double py = (log10(plot_floor(rec->p99_error)) - p->y_lo) / span;
            placed[n_placed++] = (box){px - 0.006, py - 0.01, px + 0.006, py + 0.01};
        }
        for (size_t i = 0; i < r->count; i++) {
            const record *rec = &r->records[i];
            if ((int)rec->kind != k) continue;
            double px = (rec->ns_encode + rec->ns_decode) / p->x_max;
            double py = (log10(plot_floor(rec->p99_error)) - p->y_lo) / span;
            double w = (double)strlen(rec->name) * PLOT_CHAR_W;
            box best = {px + PLOT_GAP, py - PLOT_LINE_H / 2, px + PLOT_GAP + w, py + PLOT_LINE_H / 2};
            int moved = 0, left = 0;
            /* beside the point (right, then left), then stepping up and down a line at a time */
            for (int step = 0, found = 0; step < 13 && !found; step++) {
                for (int side = 0; side < 2 && !found; side++) {
                    int shift = (step + 1) / 2 * (step % 2 ? 1 : -1);
                    double x0 = side ? px - PLOT_GAP - w : px + PLOT_GAP;
                    double yc = py + shift * PLOT_LINE_H;
                    box b = {x0, yc - PLOT_LINE_H / 2, x0 + w, yc + PLOT_LINE_H / 2};
                    if (b.x0 < 0.0 || b.x1 > 1.0 || b.y0 < 0.0 || b.y1 > 1.0) continue;
                    int clash = 0;
                    for (size_t q = 0; q < n_placed && !clash; q++) clash = boxes_overlap(b, placed[q]);
                    if (clash) continue;
                    best = b;
                    moved = shift != 0;
                    left = side;
                    found = 1;
                }
            }
            if (n_placed < sizeof placed / sizeof placed[0]) placed[n_placed++] = best;
            plot_label *lab = &L->labels[i];
            double yc = 0.5 * (best.y0 + best.y1);
            lab->x = best.x0 * p->x_max;
            lab->y = pow(10.0, p->y_lo + yc * span);
            lab->lead_x = lab->lead_y = NAN;
            if (moved) {
                lab->lead_x = (left ? best.x1 : best.x0) * p->x_max;
                lab->lead_y = lab->y;
            }
        }
    }
}

static void plot_number(FILE *f, double v)
{
    if (isfinite(v)) fprintf(f, " %.6g", v);
    else fputs(" NaN", f);
}

static int write_plot_data(FILE *f, const void *ctx)
{
    const plot_layout *L = ((const tl_tool_plot *)ctx)->user;
    const report *r = L->r;
    fputs("# one block per kind: x=ns_encode+ns_decode p99 mean max family label_x label_y lead_x lead_y name\n", f);
    for (int k = 0; k < KIND_COUNT; k++) {
        if (k) fputs("\n\n", f);
        fprintf(f, "# %s\n", kind_names[k]);
        int any = 0;
        for (size_t i = 0; i < r->count; i++) {
            const record *rec = &r->records[i];
            const plot_label *lab = &L->labels[i];
            if ((int)rec->kind != k) continue;
            any = 1;
            fprintf(f, "%.4f", rec->ns_encode + rec->ns_decode);
            plot_number(f, plot_floor(rec->p99_error));
            plot_number(f, plot_floor(rec->mean_error));
            plot_number(f, plot_floor(rec->max_error));
            fprintf(f, " %d", family_of(rec));
            plot_number(f, lab->x);
            plot_number(f, lab->y);
            plot_number(f, lab->lead_x);
            plot_number(f, lab->lead_y);
            fprintf(f, " \"%s\"\n", rec->name);
        }
        if (!any) fputs("NaN NaN NaN NaN 0 NaN NaN NaN NaN \"\"\n", f);
    }
    return 0;
}

static int write_plot_script(FILE *f, const void *ctx)
{
    static const char *const colours[] = {"#7b3294", "#1a9850", "#e66101", "#8c510a", "#d7191c", "#2166ac",
                                          "#d7191c", "#1a9850", "#7b3294", "#2166ac", "#0571b0", "#bababa",
                                          "#878787"};
    const tl_tool_plot *plot = ctx;
    const plot_layout *L = plot->user;
    const report *r = L->r;
    fprintf(f,
            "# Generated by " TOOL ": codec error against encode + decode time, one panel per kind.\n"
            "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
            "  set terminal pngcairo size 1500,1100 font 'sans,10' noenhanced\n"
            "} else {\n"
            "  set terminal png size 1500,1100 noenhanced\n"
            "}\n"
            "%s\n"
            "set multiplot layout 2,2 title \"thinlight codec error vs time: point = p99, bar = mean..max"
            "  |  %s, %zu cores; %s %s\"\n"
            "set logscale y\n"
            "set format y '1e%%L'\n"
            "set grid xtics ytics\n"
            "set key off\n"
            "set xlabel 'ns per element, encode + decode (median of runs)'\n",
            plot->set_output, r->cpu, r->cores, TL_REPORT_COMPILER, build_flags());
    for (size_t c = 0; c < sizeof colours / sizeof colours[0]; c++)
        fprintf(f, "set linetype %zu lc rgb '%s' pt 7 ps 1.2 lw 1.2\n", c + 1, colours[c]);
    for (int k = 0; k < KIND_COUNT; k++) {
        const plot_panel *p = &L->panels[k];
        fprintf(f,
                "set title '%s'\n"
                "set ylabel '%s'\n"
                "set xrange [0:%.6g]\n"
                "set yrange [1e%d:1e%d]\n"
                "plot '" PLOT_NAME ".dat' index %d using 1:2:3:4:5 with yerrorbars lc variable, \\\n"
                "     '' index %d using 8:9:($1-$8):($2-$9):5 with vectors nohead dt 3 lc variable, \\\n"
                "     '' index %d using 6:7:10:5 with labels left font ',8' tc variable\n",
                kind_names[k], kind_units[k], p->x_max, (int)p->y_lo, (int)p->y_hi, k, k, k);
    }
    fputs("unset multiplot\nset output\n", f);
    return 0;
}

/* Writes DIR/codec_error_vs_time.{dat,gp} and runs gnuplot inside DIR to make the PNG. */
static int make_plot(const report *r, const char *dir)
{
    plot_layout *layout = xcalloc(1, sizeof *layout);
    if (!layout) return 1;
    layout->r = r;
    layout_plot(layout);
    tl_tool_plot p = {.tool = TOOL, .dir = dir, .name = PLOT_NAME, .data = write_plot_data,
                      .script = write_plot_script, .user = layout, .max_bytes = PLOT_MAX_BYTES};
    int err = tl_tool_make_plot(&p);
    free(layout);
    return err;
}

typedef struct doc_ctx {
    const report *r;
    const char *text;     /* the whole original file */
    size_t keep_head;     /* bytes up to and including the begin marker */
    const char *tail;     /* from the end marker on */
    int with_plot;
} doc_ctx;

static void doc_number(FILE *f, double v)
{
    if (v == 0.0) fputs("0", f);
    else fprintf(f, "%.3g", v);
}

static int write_doc(FILE *f, const void *ctx)
{
    const doc_ctx *d = ctx;
    const report *r = d->r;
    fwrite(d->text, 1, d->keep_head, f);
    fprintf(f, "\n<!-- Generated by %s; edit the tool, not this section. -->\n\n", TOOL);
    fprintf(f, "Measured on %s (%zu cores), %s, flags `%s` (%s build); %zu elements per run (albedo: the 5 "
               "test images at %ux%u), times are medians of %zu runs.%s\n",
            r->cpu, r->cores, TL_REPORT_COMPILER, build_flags(), TL_REPORT_BUILD_TYPE, r->elements,
            (unsigned)r->image_size, (unsigned)r->image_size, r->repeats, r->quick ? " Quick run (--quick)." : "");
    for (int k = 0; k < KIND_COUNT; k++) {
        fprintf(f, "\n#### %s\n\n", kind_titles[k]);
        if (k == KIND_ALBEDO)
            fputs("| variant | bits | mean | p99 | max | PSNR dB | mean ΔE00 | ns encode | ns decode |\n"
                  "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n", f);
        else
            fputs("| variant | bits | mean | p99 | max | ns encode | ns decode | note |\n"
                  "|---|---:|---:|---:|---:|---:|---:|---|\n", f);
        for (size_t i = 0; i < r->count; i++) {
            const record *rec = &r->records[i];
            if ((int)rec->kind != k) continue;
            fprintf(f, "| `%s` | %u | ", rec->name, (unsigned)rec->bits);
            doc_number(f, rec->mean_error);
            fputs(" | ", f);
            doc_number(f, rec->p99_error);
            fputs(" | ", f);
            doc_number(f, rec->max_error);
            if (k == KIND_ALBEDO)
                fprintf(f, " | %.2f | %.3f | %.2f | %.2f |\n", rec->psnr_db, rec->ciede2000_mean, rec->ns_encode,
                        rec->ns_decode);
            else
                fprintf(f, " | %.2f | %.2f | %s |\n", rec->ns_encode, rec->ns_decode, rec->note);
        }
        if (k == KIND_ALBEDO) {
            fputs("\nPer image, p99 / max in 8-bit steps:\n\n| variant |", f);
            for (size_t im = 0; im < TL_TEST_IMAGE_COUNT; im++) fprintf(f, " %s |", tl_test_image_name((tl_test_image)im));
            fputs("\n|---|", f);
            for (size_t im = 0; im < TL_TEST_IMAGE_COUNT; im++) fputs("---:|", f);
            fputc('\n', f);
            for (size_t i = 0; i < r->count; i++) {
                const record *rec = &r->records[i];
                if (rec->kind != KIND_ALBEDO) continue;
                fprintf(f, "| `%s` |", rec->name);
                for (size_t im = 0; im < TL_TEST_IMAGE_COUNT; im++) {
                    fputc(' ', f);
                    doc_number(f, rec->image_p99[im]);
                    fputs(" / ", f);
                    doc_number(f, rec->image_max[im]);
                    fputs(" |", f);
                }
                fputc('\n', f);
            }
        }
    }
    if (d->with_plot) fputs("\n![error vs time](img/" PLOT_NAME ".png)\n", f);
    else fputs("\n(The plot was not regenerated: the report ran with --no-plot.)\n", f);
    fputc('\n', f);
    fputs(d->tail, f);
    return 0;
}

static int doc_split(const char *path, const char *text, size_t *keep_head, const char **tail)
{
    return tl_tool_doc_split(TOOL, path, text, DOC_BEGIN, DOC_END, keep_head, tail);
}

/* ---------------------------------------------------------------------------------------------
 * main
 * ------------------------------------------------------------------------------------------- */

typedef struct options {
    const char *json, *out, *doc;
    int quick, no_plot, help;
} options;

enum { OPT_HELP, OPT_LIST, OPT_QUICK, OPT_NO_PLOT, OPT_JSON, OPT_OUT, OPT_DOC, OPT_GL };

static const tl_opt report_opts[] = {
    {"--help", TL_OPT_FLAG, .id = OPT_HELP},
    {"-h", TL_OPT_FLAG, .id = OPT_HELP},
    {"--list-options", TL_OPT_FLAG, .id = OPT_LIST},
    {"--quick", TL_OPT_FLAG, .id = OPT_QUICK},
    {"--no-plot", TL_OPT_FLAG, .id = OPT_NO_PLOT},
    {"--json", TL_OPT_TEXT, .id = OPT_JSON},
    {"--out", TL_OPT_TEXT, .id = OPT_OUT},
    {"--doc", TL_OPT_TEXT, .id = OPT_DOC},
    /* the renderer tools' context options, refused by name */
    {"--context", TL_OPT_FLAG, .id = OPT_GL},
    {"--device", TL_OPT_FLAG, .id = OPT_GL},
    {"--list-devices", TL_OPT_FLAG, .id = OPT_GL},
};

/* argv into `o`: 0; -1 after --list-options (printed); or EXIT_BAD_USAGE after one line. */
static int parse_args(int argc, char **argv, options *o)
{
    memset(o, 0, sizeof *o);
    const tl_opt_table tables[] = {TL_OPT_TABLE(report_opts)};
    tl_opt_parser p;
    tl_opt_begin(&p, TOOL, argc, argv, tables, 1);
    const tl_opt *opt;
    tl_opt_value v;
    int rc;
    while ((rc = tl_opt_next(&p, &opt, &v)) == 1) {
        if (!opt) return tl_opt_usage(TOOL, "unexpected argument '%s'", v.text);
        switch (opt->id) {
        case OPT_HELP: o->help = 1; break;
        case OPT_LIST: tl_opt_list(stdout, tables, 1); return -1;
        case OPT_QUICK: o->quick = 1; break;
        case OPT_NO_PLOT: o->no_plot = 1; break;
        case OPT_JSON: o->json = v.text; break;
        case OPT_OUT: o->out = v.text; break;
        case OPT_DOC: o->doc = v.text; break;
        default: return tl_opt_usage(TOOL, "%s: this tool makes no GL context (it runs on the CPU only)", opt->name);
        }
    }
    if (rc) return EXIT_BAD_USAGE;
    if (!o->help && !o->out && !o->no_plot)
        return tl_opt_usage(TOOL, "--out DIR is required for the plot (or pass --no-plot)");
    return 0;
}

/* Everything that can fail for bad input is checked before the minutes of measuring. */
static int check_outputs(const options *o, char **doc_text)
{
    int e;
    if (o->out && (e = tl_tool_make_dirs(o->out)) != 0) {
        fail_line("cannot create output directory '%s': %s", o->out, strerror(e));
        return 1;
    }
    if (o->out) {
        char *probe = tl_tool_strf("%s/" PLOT_NAME ".png", o->out);
        e = probe ? tl_tool_check_output(TOOL, probe) : 1;
        if (!probe) fail_line("out of memory");
        free(probe);
        if (e) return 1;
    }
    if (o->json && tl_tool_check_output(TOOL, o->json)) return 1;
    if (!o->no_plot && !tl_tool_have_gnuplot()) {
        fail_line("gnuplot not found on PATH (install gnuplot-nox, or pass --no-plot)");
        return 1;
    }
    if (o->doc) { /* a regular file (checked first: a FIFO is never opened), readable, with markers */
        if (tl_tool_check_output(TOOL, o->doc)) return 1;
        *doc_text = tl_tool_read_file(o->doc, NULL);
        if (!*doc_text) {
            fail_line("cannot read '%s': %s", o->doc, strerror(errno));
            return 1;
        }
        size_t head;
        const char *tail;
        if (doc_split(o->doc, *doc_text, &head, &tail)) return 1;
        if (!o->no_plot) {
            char *dir = tl_tool_dir_of(o->doc), *img = dir ? tl_tool_strf("%s/img", dir) : NULL;
            e = img ? tl_tool_make_dirs(img) : ENOMEM;
            if (e) fail_line("cannot create image directory '%s': %s", img ? img : "img", strerror(e));
            free(dir);
            free(img);
            if (e) return 1;
        }
    }
    return 0;
}

static int update_doc(const report *r, const options *o, const char *text)
{
    doc_ctx d = {r, text, 0, NULL, !o->no_plot};
    if (doc_split(o->doc, text, &d.keep_head, &d.tail)) return 1;
    int err = 0;
    if (!o->no_plot) {
        char *dir = tl_tool_dir_of(o->doc);
        char *src = tl_tool_strf("%s/" PLOT_NAME ".png", o->out);
        char *dst = dir ? tl_tool_strf("%s/img/" PLOT_NAME ".png", dir) : NULL;
        err = src && dst ? tl_tool_copy_file(TOOL, src, dst) : 1;
        free(dir);
        free(src);
        free(dst);
    }
    return err || tl_tool_write_atomic(TOOL, o->doc, write_doc, &d);
}

int main(int argc, char **argv)
{
    options o;
    int rc = parse_args(argc, argv, &o);
    if (rc) return rc < 0 ? 0 : rc;
    if (o.help) {
        fputs(usage_text, stdout);
        return 0;
    }
    char *doc_text = NULL;
    report *r = NULL;
    rc = EXIT_BAD_INPUT;
    if (check_outputs(&o, &doc_text)) goto done;

    r = xcalloc(1, sizeof *r);
    if (!r) goto done;
    r->quick = o.quick;
    r->elements = o.quick ? 200000 : 1000000;
    r->repeats = o.quick ? 3 : 7;
    r->image_size = o.quick ? 200 : 512;
    tl_tool_progress_begin(&r->progress, VARIANT_COUNT);
    tl_tool_machine(r->cpu, sizeof r->cpu, &r->cores);
    r->stats = xcalloc(1, sizeof *r->stats);
    int alloc_failed = !r->stats;
    for (size_t i = 0; i < TL_TEST_IMAGE_COUNT; i++) {
        r->image_stats[i] = xcalloc(1, sizeof *r->image_stats[i]);
        alloc_failed |= !r->image_stats[i];
    }
    if (alloc_failed) goto done;

    if (run_normals(r) || run_albedo(r) || run_depth(r) || run_gloss(r)) goto done;
    tl_tool_progress_end(&r->progress);

    print_table(r);
    if (o.json && tl_tool_write_atomic(TOOL, o.json, write_json, r)) goto done;
    if (!o.no_plot && make_plot(r, o.out)) goto done;
    if (o.doc && update_doc(r, &o, doc_text)) goto done;
    rc = 0;
done:
    if (r) {
        free(r->stats);
        for (size_t i = 0; i < TL_TEST_IMAGE_COUNT; i++) free(r->image_stats[i]);
    }
    free(r);
    free(doc_text);
    return rc;
}
