/* GLSL/C parity: shaders/codec.glsl runs in a compute shader on OSMesa (llvmpipe) over the same
 * inputs as the C codec; encodes must give identical bits, decodes identical float bit patterns
 * (0 ULP). Inputs travel through std430 SSBOs, outputs come back as uint arrays (floats through
 * floatBitsToUint) via glGetNamedBufferSubData.
 *
 * Each operation is its own small compute program (TL_PARITY_OP selects it), so a mismatch
 * names the function. Oct functions get their bit budget from a uniform (the run-time path);
 * RT0 functions use the constant budgets inside codec.glsl (the constant-folded path the
 * G-buffer pass compiles).
 *
 * Exceptions to bit identity: only tl_gloss_to_specular_power (exp2 is approximate in GLSL; see
 * parity_gloss_specular_power for the bound). Everything else, the extreme inputs included, is
 * asserted bit-exact. That includes denormal, Inf and NaN inputs: GLSL 4.50 would allow a driver
 * to flush denormals and does not promise IEEE NaN behaviour, but llvmpipe's compute shaders keep
 * both (isnan(), ordered comparisons, denormal arithmetic), so there is nothing to excuse here; a
 * driver that did flush would fail parity_oct_extreme_cases and the RT0 cases on the denormal
 * inputs, which is a real divergence of the G-buffer, not noise. Without `precise`, llvmpipe
 * reassociates sums (YCoCg luma differs in ~1/3 of the colours), which these cases catch.
 *
 * This header is what the case files share (parity_harness.c: the compute program, running an
 * operation, comparing words, input sets); the cases are in parity_normals.c (oct, RT0),
 * parity_gloss.c, parity_albedo.c and parity_depth.c. */
#ifndef TL_PARITY_H
#define TL_PARITY_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "gl/gl.h"
#include "gl_fixture.h"
#include "thinlight/codec.h"
#include "tl_test.h"

/* ---- operations (must match the #if chain of the shader in parity_harness.c) --------------- */

enum {
    OP_OCT_ENCODE = 1,     /* in_f: xyz          out: code */
    OP_OCT_ENCODE_PRECISE, /* in_f: xyz          out: code */
    OP_OCT_DECODE,         /* in_u: code         out: xyz bits */
    OP_NORMAL_SANITIZE,    /* in_f: xyz          out: xyz bits */
    OP_RT0_RGBA8_ENCODE,   /* in_f: xyz gloss    out: R G B A bytes */
    OP_RT0_RGBA8_DECODE,   /* in_u: R G B A      out: xyz gloss bits */
    OP_RT0_RGB10A2_ENCODE, /* in_f: xyz gloss, in_u: flags   out: word */
    OP_RT0_RGB10A2_DECODE, /* in_u: word         out: xyz gloss bits */
    OP_GLOSS_ENCODE,       /* in_f: gloss        out: code */
    OP_GLOSS_DECODE,       /* in_u: code         out: gloss bits */
    OP_GLOSS_POWER,        /* in_f: gloss        out: power bits */
    OP_RGB_TO_YCC,         /* in_f: rgb          out: ycc bits */
    OP_YCC_TO_RGB,         /* in_f: ycc          out: rgb bits */
    OP_ALBEDO_ENCODE,      /* in_f: rgb, in_u: x y          out: 2 bytes */
    OP_EDGE_CHROMA,        /* in_u: luma nl[4] nc[4] count  out: chroma bits */
    OP_DEPTH_LINEARIZE,    /* in_f: window depth            out: z bits */
    OP_VIEW_POSITION,      /* in_f: x_ndc y_ndc depth       out: xyz bits */
};

/* ---- GL plumbing (parity_harness.c) ----------------------------------------------------------- */

typedef struct parity_env {
    tl_gl_fixture f;
    GLuint buffers[3]; /* in_f, in_u, out */
} parity_env;

typedef struct parity_params {
    uint32_t bits, space;
    float depth[4], ray[4];
} parity_params;

bool env_open(parity_env *env);
void env_close(parity_env *env);
/* Runs operation `op` over `count` items; `out` receives `out_words` uint32 words. Returns false
 * (after a failed check) when the program does not build or GL reports an error. */
bool run_op(parity_env *env, int op, const parity_params *pp, uint32_t count, const float *in_f,
            size_t nf, const uint32_t *in_u, size_t nu, uint32_t *out, size_t out_words);

/* ---- helpers (parity_harness.c) --------------------------------------------------------------- */

uint32_t f2u(float f);
float u2f(uint32_t u);
/* Distance in units in the last place between two floats (0 for identical bits; +0 and -0 are
 * 0 apart). */
uint64_t ulp_distance(uint32_t a, uint32_t b);

/* Growable float / uint arrays for building input sets. */
typedef struct fvec {
    float *v;
    size_t n, cap;
} fvec;
void fpush(fvec *a, float x);
void fpush3(fvec *a, float x, float y, float z);
typedef struct uvec {
    uint32_t *v;
    size_t n, cap;
} uvec;
void upush(uvec *a, uint32_t x);
uint32_t *xmalloc_u32(size_t n);

/* Compares `items` groups of `per_item` words bit for bit; prints the first few mismatches with
 * `describe` and one summary line. Returns the number of items that differ. */
typedef void (*describe_fn)(size_t item, const void *ctx);
size_t compare_words(const char *what, const uint32_t *expect, const uint32_t *got, size_t items, size_t per_item,
                     describe_fn describe, const void *ctx);
void describe_xyz(size_t i, const void *ctx);
void describe_f(size_t i, const void *ctx);
void describe_u(size_t i, const void *ctx);

/* ---- input sets (parity_harness.c) ------------------------------------------------------------ */

#define RANDOM_COUNT 131072u /* >= 10^5 */
void random_directions(fvec *a, uint64_t seed, size_t count);
/* Every extreme input of docs/stability.md for normals. */
void extreme_normals(fvec *a);

#endif
