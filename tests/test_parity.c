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
 * reassociates sums (YCoCg luma differs in ~1/3 of the colours), which these cases catch. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "gl/gl.h"
#include "thinlight/codec.h"
#include "thinlight/context.h"
#include "gl_fixture.h"
#include "tl_test.h"

/* ---- operations (must match the #if chain in the shader below) ------------------------------ */

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

static const char parity_shader[] =
    "#include \"codec.glsl\"\n"
    "layout(local_size_x = 64) in;\n"
    "layout(std430, binding = 0) readonly buffer tl_parity_in_f { float in_f[]; };\n"
    "layout(std430, binding = 1) readonly buffer tl_parity_in_u { uint in_u[]; };\n"
    "layout(std430, binding = 2) writeonly buffer tl_parity_out { uint out_u[]; };\n"
    "uniform uint u_count;\n"
    "uniform uint u_bits;\n"
    "uniform uint u_space;\n"
    "uniform vec4 u_depth; // m[10], m[14], m[11], reversed (1) or not (0)\n"
    "uniform vec4 u_ray;   // m[0], m[5], m[8], m[9]\n"
    "vec3 in3(uint i) { return vec3(in_f[3u * i], in_f[3u * i + 1u], in_f[3u * i + 2u]); }\n"
    "vec4 in4(uint i) { return vec4(in_f[4u * i], in_f[4u * i + 1u], in_f[4u * i + 2u], in_f[4u * i + 3u]); }\n"
    "void out3(uint i, vec3 v) { out_u[3u * i] = floatBitsToUint(v.x); out_u[3u * i + 1u] = floatBitsToUint(v.y);\n"
    "                            out_u[3u * i + 2u] = floatBitsToUint(v.z); }\n"
    "void out4(uint i, uvec4 v) { out_u[4u * i] = v.x; out_u[4u * i + 1u] = v.y; out_u[4u * i + 2u] = v.z;\n"
    "                             out_u[4u * i + 3u] = v.w; }\n"
    "void main()\n"
    "{\n"
    "    uint i = gl_GlobalInvocationID.x;\n"
    "    if (i >= u_count) return;\n"
    "#if TL_PARITY_OP == 1\n"
    "    out_u[i] = tl_oct_encode(in3(i), u_bits);\n"
    "#elif TL_PARITY_OP == 2\n"
    "    out_u[i] = tl_oct_encode_precise(in3(i), u_bits);\n"
    "#elif TL_PARITY_OP == 3\n"
    "    out3(i, tl_oct_decode(in_u[i], u_bits));\n"
    "#elif TL_PARITY_OP == 4\n"
    "    out3(i, tl_normal_sanitize(in3(i)));\n"
    "#elif TL_PARITY_OP == 5\n"
    "    vec4 a = in4(i);\n"
    "    out4(i, tl_rt0_encode_rgba8(a.xyz, a.w));\n"
    "#elif TL_PARITY_OP == 6\n"
    "    uint t = in_u[i];\n"
    "    out4(i, floatBitsToUint(tl_rt0_decode_rgba8(uvec4(t & 0xFFu, (t >> 8) & 0xFFu, (t >> 16) & 0xFFu, t >> 24))));\n"
    "#elif TL_PARITY_OP == 7\n"
    "    vec4 a = in4(i);\n"
    "    out_u[i] = tl_rt0_encode_rgb10a2(a.xyz, a.w, in_u[i]);\n"
    "#elif TL_PARITY_OP == 8\n"
    "    out4(i, floatBitsToUint(tl_rt0_decode_rgb10a2(in_u[i])));\n"
    "#elif TL_PARITY_OP == 9\n"
    "    out_u[i] = tl_gloss_encode(in_f[i], u_bits);\n"
    "#elif TL_PARITY_OP == 10\n"
    "    out_u[i] = floatBitsToUint(tl_gloss_decode(in_u[i], u_bits));\n"
    "#elif TL_PARITY_OP == 11\n"
    "    out_u[i] = floatBitsToUint(tl_gloss_to_specular_power(in_f[i]));\n"
    "#elif TL_PARITY_OP == 12\n"
    "    out3(i, tl_rgb_to_luma_chroma(u_space, in3(i)));\n"
    "#elif TL_PARITY_OP == 13\n"
    "    out3(i, tl_luma_chroma_to_rgb(u_space, in3(i)));\n"
    "#elif TL_PARITY_OP == 14\n"
    "    uvec2 b = tl_albedo_encode_pixel(u_space, in3(i), uvec2(in_u[2u * i], in_u[2u * i + 1u]));\n"
    "    out_u[2u * i] = b.x;\n"
    "    out_u[2u * i + 1u] = b.y;\n"
    "#elif TL_PARITY_OP == 15\n"
    "    uint k = 10u * i;\n"
    "    ivec4 nl = ivec4(in_u[k + 1u], in_u[k + 2u], in_u[k + 3u], in_u[k + 4u]);\n"
    "    ivec4 nc = ivec4(in_u[k + 5u], in_u[k + 6u], in_u[k + 7u], in_u[k + 8u]);\n"
    "    out_u[i] = floatBitsToUint(tl_albedo_edge_chroma(int(in_u[k]), nl, nc, int(in_u[k + 9u])));\n"
    "#elif TL_PARITY_OP == 16\n"
    "    out_u[i] = floatBitsToUint(tl_depth_linearize(in_f[i], u_depth.x, u_depth.y, u_depth.z, u_depth.w > 0.5));\n"
    "#elif TL_PARITY_OP == 17\n"
    "    vec3 a = in3(i);\n"
    "    float z = tl_depth_linearize(a.z, u_depth.x, u_depth.y, u_depth.z, u_depth.w > 0.5);\n"
    "    out3(i, tl_view_position(z, a.xy, u_ray));\n"
    "#else\n"
    "#error unknown TL_PARITY_OP\n"
    "#endif\n"
    "}\n";

/* ---- GL plumbing ---------------------------------------------------------------------------- */

typedef struct parity_env {
    tl_gl_fixture f;
    GLuint buffers[3]; /* in_f, in_u, out */
} parity_env;

typedef struct parity_params {
    uint32_t bits, space;
    float depth[4], ray[4];
} parity_params;

static bool env_open(parity_env *env)
{
    memset(env, 0, sizeof *env);
    if (!tl_gl_fixture_open(&env->f, 16)) return false;
    env->f.gl.CreateBuffers(3, env->buffers);
    return true;
}

static void env_close(parity_env *env)
{
    env->f.gl.DeleteBuffers(3, env->buffers);
    tl_gl_fixture_close(&env->f);
}

/* Runs operation `op` over `count` items; `out` receives `out_words` uint32 words. Returns false
 * (after a failed check) when the program does not build or GL reports an error. */
static bool run_op(parity_env *env, int op, const parity_params *pp, uint32_t count, const float *in_f,
                   size_t nf, const uint32_t *in_u, size_t nu, uint32_t *out, size_t out_words)
{
    const GladGLContext *gl = &env->f.gl;
    char define[32];
    snprintf(define, sizeof define, "TL_PARITY_OP=%d", op);
    const char *defines[1] = {define};
    static char log[16384];
    GLuint prog = 0;
    tl_result r = tl__program_build(
        gl,
        &(tl__program_desc){.label = "test.parity",
                            .stages = {{GL_COMPUTE_SHADER, "parity.comp.glsl", parity_shader}},
                            .defines = defines,
                            .define_count = 1},
        &prog, log, sizeof log);
    if (r != TL_OK) fprintf(stderr, "parity op %d: %s\n", op, log);
    TL_CHECK(r == TL_OK);
    if (r != TL_OK) return false;

    /* Zero-sized SSBOs are not allowed: every buffer holds at least 16 bytes. */
    static const uint32_t pad[4];
    gl->NamedBufferData(env->buffers[0], (GLsizeiptr)(nf ? nf * 4 : 16), nf ? (const void *)in_f : pad,
                        GL_STATIC_DRAW);
    gl->NamedBufferData(env->buffers[1], (GLsizeiptr)(nu ? nu * 4 : 16), nu ? (const void *)in_u : pad,
                        GL_STATIC_DRAW);
    gl->NamedBufferData(env->buffers[2], (GLsizeiptr)(out_words * 4), NULL, GL_DYNAMIC_READ);
    const uint32_t sentinel = 0xDEADBEEFu; /* words the shader failed to write stay visible */
    gl->ClearNamedBufferData(env->buffers[2], GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &sentinel);
    for (GLuint b = 0; b < 3; b++) gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, b, env->buffers[b]);

    gl->UseProgram(prog);
    gl->Uniform1ui(gl->GetUniformLocation(prog, "u_count"), count);
    gl->Uniform1ui(gl->GetUniformLocation(prog, "u_bits"), pp ? pp->bits : 0u);
    gl->Uniform1ui(gl->GetUniformLocation(prog, "u_space"), pp ? pp->space : 0u);
    static const float zero4[4];
    gl->Uniform4fv(gl->GetUniformLocation(prog, "u_depth"), 1, pp ? pp->depth : zero4);
    gl->Uniform4fv(gl->GetUniformLocation(prog, "u_ray"), 1, pp ? pp->ray : zero4);
    gl->DispatchCompute((count + 63u) / 64u, 1, 1);
    gl->MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl->GetNamedBufferSubData(env->buffers[2], 0, (GLsizeiptr)(out_words * 4), out);
    gl->UseProgram(0);
    gl->DeleteProgram(prog);
    GLenum err = gl->GetError();
    if (err != GL_NO_ERROR) fprintf(stderr, "parity op %d: %s\n", op, tl__gl_error_string(err));
    TL_CHECK_EQ_U(err, GL_NO_ERROR);
    return err == GL_NO_ERROR;
}

/* ---- helpers -------------------------------------------------------------------------------- */

static uint32_t f2u(float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    return u;
}

static float u2f(uint32_t u)
{
    float f;
    memcpy(&f, &u, 4);
    return f;
}

/* Distance in units in the last place between two floats (0 for identical bits; +0 and -0 are
 * 0 apart). */
static uint64_t ulp_distance(uint32_t a, uint32_t b)
{
    int64_t oa = (a & 0x80000000u) ? -(int64_t)(a & 0x7FFFFFFFu) : (int64_t)a;
    int64_t ob = (b & 0x80000000u) ? -(int64_t)(b & 0x7FFFFFFFu) : (int64_t)b;
    return (uint64_t)(oa > ob ? oa - ob : ob - oa);
}

/* Growable float / uint arrays for building input sets. */
typedef struct fvec {
    float *v;
    size_t n, cap;
} fvec;

static void fpush(fvec *a, float x)
{
    if (a->n == a->cap) {
        a->cap = a->cap ? 2 * a->cap : 1024;
        a->v = realloc(a->v, a->cap * sizeof *a->v);
        if (!a->v) abort();
    }
    a->v[a->n++] = x;
}

static void fpush3(fvec *a, float x, float y, float z)
{
    fpush(a, x);
    fpush(a, y);
    fpush(a, z);
}

typedef struct uvec {
    uint32_t *v;
    size_t n, cap;
} uvec;

static void upush(uvec *a, uint32_t x)
{
    if (a->n == a->cap) {
        a->cap = a->cap ? 2 * a->cap : 1024;
        a->v = realloc(a->v, a->cap * sizeof *a->v);
        if (!a->v) abort();
    }
    a->v[a->n++] = x;
}

static uint32_t *xmalloc_u32(size_t n)
{
    uint32_t *p = malloc((n ? n : 1) * sizeof *p);
    if (!p) abort();
    return p;
}

/* Compares `items` groups of `per_item` words bit for bit; prints the first few mismatches with
 * `describe` and one summary line. Returns the number of items that differ. */
typedef void (*describe_fn)(size_t item, const void *ctx);

static size_t compare_words(const char *what, const uint32_t *expect, const uint32_t *got, size_t items,
                            size_t per_item, describe_fn describe, const void *ctx)
{
    size_t bad = 0;
    for (size_t i = 0; i < items; i++) {
        if (memcmp(expect + i * per_item, got + i * per_item, per_item * 4) == 0) continue;
        if (bad++ < 6) {
            fprintf(stderr, "%s: item %zu: C", what, i);
            for (size_t k = 0; k < per_item; k++) fprintf(stderr, " %08x", expect[i * per_item + k]);
            fprintf(stderr, " GLSL");
            for (size_t k = 0; k < per_item; k++) fprintf(stderr, " %08x", got[i * per_item + k]);
            if (describe) describe(i, ctx);
            fprintf(stderr, "\n");
        }
    }
    printf("%-40s %8zu inputs compared, %zu differ\n", what, items, bad);
    return bad;
}

static void describe_xyz(size_t i, const void *ctx)
{
    const float *v = (const float *)ctx + 3 * i;
    fprintf(stderr, " for (%a, %a, %a)", (double)v[0], (double)v[1], (double)v[2]);
}

static void describe_f(size_t i, const void *ctx)
{
    fprintf(stderr, " for %a", (double)((const float *)ctx)[i]);
}

static void describe_u(size_t i, const void *ctx)
{
    fprintf(stderr, " for 0x%08x", ((const uint32_t *)ctx)[i]);
}

/* ---- input sets ----------------------------------------------------------------------------- */

#define RANDOM_COUNT 131072u /* >= 10^5 */

static void random_directions(fvec *a, uint64_t seed, size_t count)
{
    tl_rng rng = {seed};
    for (size_t i = 0; i < count; i++) {
        float v[3];
        tl_rng_direction(&rng, v);
        fpush3(a, v[0], v[1], v[2]);
    }
}

/* Every extreme input of DESIGN.md section 5 for normals. */
static void extreme_normals(fvec *a)
{
    const float inf = INFINITY, nan = NAN, dmin = 0x1.0p-149f, dmax = 0x1.fffffcp-127f;
    /* A systematic cross product of special component values (poles, axes, +-0, the 45 degree
     * diagonals, denormals, the smallest normal, huge values, Inf, NaN). */
    const float s[] = {0.0f,  -0.0f, 1.0f,  -1.0f, 0.5f,   -0.5f,   dmin,    -dmin,    dmax,
                       -dmax, FLT_MIN, -FLT_MIN, 1e30f, -1e30f, FLT_MAX, -FLT_MAX, inf, -inf, nan, -nan};
    const size_t ns = sizeof s / sizeof s[0];
    for (size_t i = 0; i < ns; i++)
        for (size_t j = 0; j < ns; j++)
            for (size_t k = 0; k < ns; k++) fpush3(a, s[i], s[j], s[k]);
    /* Signalling NaN and NaN with payloads. */
    const float snan = u2f(0x7F800001u), qnanp = u2f(0xFFC12345u);
    fpush3(a, snan, 0.0f, 1.0f);
    fpush3(a, 0.0f, qnanp, -1.0f);
    fpush3(a, 1.0f, 1.0f, snan);
    /* The fold |x| + |y| = 1 with z = +0 and z = -0, in all four quadrants, with and without a
     * ULP off (|x| or |y| nudged up or down; z = +-denormal-min, +-FLT_MIN and +-1 ULP of 1e-7). */
    tl_rng rng = {0xF01Du};
    for (int k = 0; k <= 256; k++) {
        float x = (float)k / 256.0f;
        if (k > 0 && k < 256 && (k & 7) == 3) x = (float)tl_rng_unit(&rng);
        float y = 1.0f - x;
        const float zs[] = {0.0f, -0.0f, dmin, -dmin, FLT_MIN, -FLT_MIN, 1e-7f, -1e-7f};
        for (int q = 0; q < 4; q++) {
            float sx = (q & 1) ? -x : x, sy = (q & 2) ? -y : y;
            for (size_t zi = 0; zi < sizeof zs / sizeof zs[0]; zi++) {
                float z = zs[zi];
                fpush3(a, sx, sy, z);
                fpush3(a, nextafterf(sx, inf), sy, z);
                fpush3(a, nextafterf(sx, -inf), sy, z);
                fpush3(a, sx, nextafterf(sy, inf), z);
                fpush3(a, sx, nextafterf(sy, -inf), z);
            }
            /* the same fold point as a unit (L2) vector */
            float l = sqrtf(sx * sx + sy * sy);
            if (l > 0.0f) {
                fpush3(a, sx / l, sy / l, 0.0f);
                fpush3(a, sx / l, sy / l, -0.0f);
            }
        }
    }
    /* Poles with signed zeros, a ULP off the poles. */
    const float z1[] = {1.0f, -1.0f};
    for (int zi = 0; zi < 2; zi++)
        for (int sx = 0; sx < 2; sx++)
            for (int sy = 0; sy < 2; sy++) {
                float x = sx ? -0.0f : 0.0f, y = sy ? -0.0f : 0.0f;
                fpush3(a, x, y, z1[zi]);
                fpush3(a, x, y, nextafterf(z1[zi], 0.0f));
                fpush3(a, sx ? -dmin : dmin, sy ? -dmin : dmin, z1[zi]);
                fpush3(a, sx ? -0x1.0p-24f : 0x1.0p-24f, y, z1[zi]);
            }
    /* Non-unit lengths: random directions scaled to 1e-30, 1e30, to either side of the
     * tl__oct_input_ok range [2^-32, 2^60] (the L1 norm), and to denormal lengths. */
    const float scales[] = {1e-30f, 1e30f, 1e-20f, 1e20f, 1e-38f, 1e-40f, 1e-44f, 3e38f};
    for (int i = 0; i < 64; i++) {
        float v[3];
        tl_rng_direction(&rng, v);
        for (size_t si = 0; si < sizeof scales / sizeof scales[0]; si++)
            fpush3(a, v[0] * scales[si], v[1] * scales[si], v[2] * scales[si]);
        float l1 = (fabsf(v[0]) + fabsf(v[1])) + fabsf(v[2]);
        const float bounds[] = {0x1.0p-32f, 0x1.0p60f};
        for (int b = 0; b < 2; b++) {
            float sc = bounds[b] / l1;
            for (int d = -2; d <= 2; d++) {
                float t = sc;
                for (int s2 = 0; s2 < (d < 0 ? -d : d); s2++) t = nextafterf(t, d < 0 ? 0.0f : inf);
                fpush3(a, v[0] * t, v[1] * t, v[2] * t);
            }
        }
    }
    /* Random directions at random power-of-two scales from 2^-149 to 2^127. */
    for (int i = 0; i < 4096; i++) {
        float v[3];
        tl_rng_direction(&rng, v);
        int e = -149 + (int)(tl_rng_u64(&rng) % 277u);
        fpush3(a, ldexpf(v[0], e), ldexpf(v[1], e), ldexpf(v[2], e));
    }
}

/* ---- normals: oct encode / encode_precise / decode ------------------------------------------ */

static void parity_oct_encode_set(const char *name, const float *v, size_t count, uint32_t bits, bool precise)
{
    parity_env env;
    if (!env_open(&env)) return;
    uint32_t *expect = xmalloc_u32(count), *got = xmalloc_u32(count);
    if (precise)
        for (size_t i = 0; i < count; i++) expect[i] = tl_oct_encode_precise(v + 3 * i, bits);
    else
        for (size_t i = 0; i < count; i++) expect[i] = tl_oct_encode(v + 3 * i, bits);
    parity_params pp = {.bits = bits};
    if (run_op(&env, precise ? OP_OCT_ENCODE_PRECISE : OP_OCT_ENCODE, &pp, (uint32_t)count, v, 3 * count,
               NULL, 0, got, count)) {
        char what[64];
        snprintf(what, sizeof what, "%s oct%u %s", name, bits, precise ? "encode_precise" : "encode");
        TL_CHECK_EQ_U(compare_words(what, expect, got, count, 1, describe_xyz, v), 0);
    }
    free(expect);
    free(got);
    env_close(&env);
}

static void parity_oct_random_encode(uint32_t bits, bool precise)
{
    fvec a = {0};
    random_directions(&a, 0x0C7000u + bits, RANDOM_COUNT);
    parity_oct_encode_set("random", a.v, a.n / 3, bits, precise);
    free(a.v);
}

static void parity_oct8_encode(void) { parity_oct_random_encode(8, false); }
static void parity_oct10_encode(void) { parity_oct_random_encode(10, false); }
static void parity_oct12_encode(void) { parity_oct_random_encode(12, false); }
static void parity_oct16_encode(void) { parity_oct_random_encode(16, false); }
static void parity_oct8_encode_precise(void) { parity_oct_random_encode(8, true); }
static void parity_oct10_encode_precise(void) { parity_oct_random_encode(10, true); }
static void parity_oct12_encode_precise(void) { parity_oct_random_encode(12, true); }
static void parity_oct16_encode_precise(void) { parity_oct_random_encode(16, true); }

static void parity_oct_decode_codes(uint32_t bits, const uint32_t *codes, size_t count)
{
    parity_env env;
    if (!env_open(&env)) return;
    uint32_t *expect = xmalloc_u32(3 * count), *got = xmalloc_u32(3 * count);
    for (size_t i = 0; i < count; i++) {
        float n[3];
        tl_oct_decode(codes[i], bits, n);
        for (int k = 0; k < 3; k++) expect[3 * i + k] = f2u(n[k]);
    }
    parity_params pp = {.bits = bits};
    if (run_op(&env, OP_OCT_DECODE, &pp, (uint32_t)count, NULL, 0, codes, count, got, 3 * count)) {
        char what[64];
        snprintf(what, sizeof what, "oct%u decode", bits);
        TL_CHECK_EQ_U(compare_words(what, expect, got, count, 3, describe_u, codes), 0);
    }
    free(expect);
    free(got);
    env_close(&env);
}

/* Every code of the budget when it has at most 2^20, else random codes plus the square's edges
 * and corners; codes carry random garbage above bit 2*bits (decode ignores it). */
static void parity_oct_decode(uint32_t bits)
{
    uvec c = {0};
    uint32_t max = (1u << bits) - 1u;
    tl_rng rng = {0xDEC0DEu + bits};
    if (bits <= 10) {
        for (uint32_t k = 0; k <= (max << bits | max); k++) upush(&c, k);
    } else {
        for (uint32_t i = 0; i < RANDOM_COUNT; i++) upush(&c, (uint32_t)tl_rng_u64(&rng));
        const uint32_t edge[] = {0, 1, max / 2, max / 2 + 1, max - 1, max};
        for (size_t i = 0; i < 6; i++)
            for (size_t j = 0; j < 6; j++) upush(&c, edge[i] | edge[j] << bits);
        for (uint32_t k = 0; k <= max; k += 7) {
            upush(&c, k);
            upush(&c, k | max << bits);
            upush(&c, k << bits);
            upush(&c, max | k << bits);
        }
    }
    if (bits < 16)
        for (size_t i = 0; i < c.n; i += 5) c.v[i] |= (uint32_t)tl_rng_u64(&rng) << (2 * bits);
    parity_oct_decode_codes(bits, c.v, c.n);
    free(c.v);
}

static void parity_oct8_decode_all_codes(void) { parity_oct_decode(8); }
static void parity_oct10_decode_all_codes(void) { parity_oct_decode(10); }
static void parity_oct12_decode(void) { parity_oct_decode(12); }
static void parity_oct16_decode(void) { parity_oct_decode(16); }

/* Extreme inputs at every budget, both encoders, and tl_normal_sanitize itself. */
static void parity_oct_extreme_cases(void)
{
    fvec a = {0};
    extreme_normals(&a);
    size_t count = a.n / 3;
    static const uint32_t budgets[] = {8, 10, 12, 16};
    for (size_t b = 0; b < 4; b++) {
        parity_oct_encode_set("extreme", a.v, count, budgets[b], false);
        parity_oct_encode_set("extreme", a.v, count, budgets[b], true);
    }
    parity_env env;
    if (env_open(&env)) {
        uint32_t *expect = xmalloc_u32(3 * count), *got = xmalloc_u32(3 * count);
        for (size_t i = 0; i < count; i++) {
            float n[3];
            tl_normal_sanitize(a.v + 3 * i, n);
            for (int k = 0; k < 3; k++) expect[3 * i + k] = f2u(n[k]);
        }
        if (run_op(&env, OP_NORMAL_SANITIZE, NULL, (uint32_t)count, a.v, a.n, NULL, 0, got, 3 * count))
            TL_CHECK_EQ_U(compare_words("extreme normal_sanitize", expect, got, count, 3, describe_xyz, a.v),
                          0);
        free(expect);
        free(got);
        env_close(&env);
    }
    free(a.v);
}

/* The odd grid in GLSL: the axes (every signed zero) encoded by the shader, both encoders, every
 * budget, decode in the shader to exactly the axis; -Z to exactly (0, 0, -1). */
static void parity_oct_axes_exact(void)
{
    static const float axes[7][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, 0, 0}};
    static const float expect[7][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, 0, 1}};
    fvec a = {0};
    for (int k = 0; k < 7; k++)
        for (int s = 0; s < 8; s++) /* every sign of every zero component */
            fpush3(&a, axes[k][0] == 0.0f && (s & 1) ? -0.0f : axes[k][0], axes[k][1] == 0.0f && (s & 2) ? -0.0f : axes[k][1],
                   axes[k][2] == 0.0f && (s & 4) ? -0.0f : axes[k][2]);
    size_t count = a.n / 3, bad = 0;
    parity_env env;
    if (!env_open(&env)) return;
    uint32_t *codes = xmalloc_u32(count), *dec = xmalloc_u32(3 * count);
    for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits++)
        for (int p = 0; p < 2; p++) {
            parity_params pp = {.bits = bits};
            if (!run_op(&env, p ? OP_OCT_ENCODE_PRECISE : OP_OCT_ENCODE, &pp, (uint32_t)count, a.v, a.n, NULL, 0,
                        codes, count) ||
                !run_op(&env, OP_OCT_DECODE, &pp, (uint32_t)count, NULL, 0, codes, count, dec, 3 * count))
                continue;
            for (size_t i = 0; i < count; i++) {
                const float *e = expect[i / 8];
                int ok = u2f(dec[3 * i]) == e[0] && u2f(dec[3 * i + 1]) == e[1] && u2f(dec[3 * i + 2]) == e[2];
                if (!ok && bad++ < 6)
                    fprintf(stderr, "oct%u %s: (%g, %g, %g) -> 0x%x -> (%a, %a, %a)\n", bits, p ? "precise" : "plain",
                            (double)a.v[3 * i], (double)a.v[3 * i + 1], (double)a.v[3 * i + 2], codes[i],
                            (double)u2f(dec[3 * i]), (double)u2f(dec[3 * i + 1]), (double)u2f(dec[3 * i + 2]));
            }
        }
    printf("%-40s %8zu axis inputs x 9 budgets x 2 encoders, %zu not exact\n", "GLSL oct axes", count, bad);
    TL_CHECK_EQ_U(bad, 0);
    free(codes);
    free(dec);
    free(a.v);
    env_close(&env);
}

/* ---- RT0 ------------------------------------------------------------------------------------ */

/* Random directions with gloss in [-0.25, 1.25], then every extreme normal with a few special
 * glosses (0, 1, out of range, NaN, Inf). */
static void rt0_inputs(fvec *a, uint64_t seed)
{
    tl_rng rng = {seed};
    for (uint32_t i = 0; i < RANDOM_COUNT; i++) {
        float v[3];
        tl_rng_direction(&rng, v);
        fpush3(a, v[0], v[1], v[2]);
        fpush(a, (float)(1.5 * tl_rng_unit(&rng) - 0.25));
    }
    fvec e = {0};
    extreme_normals(&e);
    const float glosses[] = {0.0f, 1.0f, 0.5f, -0.0f, -1.0f, 2.0f, NAN, INFINITY, -INFINITY, 0x1.0p-149f};
    for (size_t i = 0; i < e.n / 3; i++) {
        fpush3(a, e.v[3 * i], e.v[3 * i + 1], e.v[3 * i + 2]);
        fpush(a, glosses[i % (sizeof glosses / sizeof glosses[0])]);
    }
    free(e.v);
}

static void describe_xyzg(size_t i, const void *ctx)
{
    const float *v = (const float *)ctx + 4 * i;
    fprintf(stderr, " for (%a, %a, %a) gloss %a", (double)v[0], (double)v[1], (double)v[2], (double)v[3]);
}

static void parity_rt0_rgba8(void)
{
    parity_env env;
    if (!env_open(&env)) return;
    fvec a = {0};
    rt0_inputs(&a, 0x47A8u);
    size_t count = a.n / 4;
    uint32_t *expect = xmalloc_u32(4 * count), *got = xmalloc_u32(4 * count);
    for (size_t i = 0; i < count; i++) {
        uint8_t t[4];
        tl_rt0_encode_rgba8(a.v + 4 * i, a.v[4 * i + 3], t);
        for (int k = 0; k < 4; k++) expect[4 * i + k] = t[k];
    }
    if (run_op(&env, OP_RT0_RGBA8_ENCODE, NULL, (uint32_t)count, a.v, a.n, NULL, 0, got, 4 * count))
        TL_CHECK_EQ_U(compare_words("rt0_encode_rgba8 bytes", expect, got, count, 4, describe_xyzg, a.v),
                      0);
    /* Decode: every texel the encoder produced plus random texels (the 12-bit decode core is
     * also covered by parity_oct12_decode). */
    uvec t = {0};
    tl_rng rng = {0x47A9u};
    for (size_t i = 0; i < count; i++)
        upush(&t, expect[4 * i] | expect[4 * i + 1] << 8 | expect[4 * i + 2] << 16 | expect[4 * i + 3] << 24);
    for (uint32_t i = 0; i < RANDOM_COUNT; i++) upush(&t, (uint32_t)tl_rng_u64(&rng));
    upush(&t, 0u);
    upush(&t, 0xFFFFFFFFu);
    uint32_t *dexp = xmalloc_u32(4 * t.n), *dgot = xmalloc_u32(4 * t.n);
    for (size_t i = 0; i < t.n; i++) {
        uint8_t b[4] = {(uint8_t)t.v[i], (uint8_t)(t.v[i] >> 8), (uint8_t)(t.v[i] >> 16), (uint8_t)(t.v[i] >> 24)};
        float n[3], g;
        tl_rt0_decode_rgba8(b, n, &g);
        for (int k = 0; k < 3; k++) dexp[4 * i + k] = f2u(n[k]);
        dexp[4 * i + 3] = f2u(g);
    }
    if (run_op(&env, OP_RT0_RGBA8_DECODE, NULL, (uint32_t)t.n, NULL, 0, t.v, t.n, dgot, 4 * t.n))
        TL_CHECK_EQ_U(compare_words("rt0_decode_rgba8", dexp, dgot, t.n, 4, describe_u, t.v), 0);
    free(dexp);
    free(dgot);
    free(t.v);
    free(expect);
    free(got);
    free(a.v);
    env_close(&env);
}

static void parity_rt0_rgb10a2(void)
{
    parity_env env;
    if (!env_open(&env)) return;
    fvec a = {0};
    rt0_inputs(&a, 0x10A2u);
    size_t count = a.n / 4;
    uvec flags = {0};
    tl_rng rng = {0x10A3u};
    for (size_t i = 0; i < count; i++) upush(&flags, (uint32_t)tl_rng_u64(&rng)); /* masked to 2 bits */
    uint32_t *expect = xmalloc_u32(count), *got = xmalloc_u32(count);
    for (size_t i = 0; i < count; i++) expect[i] = tl_rt0_encode_rgb10a2(a.v + 4 * i, a.v[4 * i + 3], flags.v[i]);
    if (run_op(&env, OP_RT0_RGB10A2_ENCODE, NULL, (uint32_t)count, a.v, a.n, flags.v, flags.n, got, count))
        TL_CHECK_EQ_U(compare_words("rt0_encode_rgb10a2 words", expect, got, count, 1, describe_xyzg, a.v),
                      0);
    /* Decode: the encoder's words and random words. */
    uvec t = {0};
    for (size_t i = 0; i < count; i++) upush(&t, expect[i]);
    for (uint32_t i = 0; i < RANDOM_COUNT; i++) upush(&t, (uint32_t)tl_rng_u64(&rng));
    uint32_t *dexp = xmalloc_u32(4 * t.n), *dgot = xmalloc_u32(4 * t.n);
    for (size_t i = 0; i < t.n; i++) {
        float n[3], g;
        uint32_t f;
        tl_rt0_decode_rgb10a2(t.v[i], n, &g, &f);
        for (int k = 0; k < 3; k++) dexp[4 * i + k] = f2u(n[k]);
        dexp[4 * i + 3] = f2u(g);
    }
    if (run_op(&env, OP_RT0_RGB10A2_DECODE, NULL, (uint32_t)t.n, NULL, 0, t.v, t.n, dgot, 4 * t.n))
        TL_CHECK_EQ_U(compare_words("rt0_decode_rgb10a2", dexp, dgot, t.n, 4, describe_u, t.v), 0);
    free(dexp);
    free(dgot);
    free(t.v);
    free(flags.v);
    free(expect);
    free(got);
    free(a.v);
    env_close(&env);
}

/* ---- gloss ---------------------------------------------------------------------------------- */

/* Random gloss in [-0.25, 1.25], every code's decoded value and the values half a step either
 * side (rounding ties), and special values. */
static void gloss_inputs(fvec *a, uint32_t bits)
{
    tl_rng rng = {0x6105u + bits};
    for (uint32_t i = 0; i < RANDOM_COUNT; i++) fpush(a, (float)(1.5 * tl_rng_unit(&rng) - 0.25));
    uint32_t max = (1u << bits) - 1u;
    for (uint32_t k = 0; k <= max; k++) {
        float g = (float)k / (float)max, h = 0.5f / (float)max;
        fpush(a, g);
        fpush(a, g + h);
        fpush(a, nextafterf(g + h, 0.0f));
        fpush(a, nextafterf(g + h, 2.0f));
    }
    const float special[] = {0.0f,     -0.0f, 1.0f,   nextafterf(1.0f, 0.0f), nextafterf(1.0f, 2.0f),
                             -1e-30f, 1e30f,  0x1.0p-149f, -0x1.0p-149f, FLT_MIN, INFINITY, -INFINITY,
                             NAN,      -NAN,  FLT_MAX};
    for (size_t i = 0; i < sizeof special / sizeof special[0]; i++) fpush(a, special[i]);
}

static void parity_gloss(uint32_t bits)
{
    parity_env env;
    if (!env_open(&env)) return;
    fvec a = {0};
    gloss_inputs(&a, bits);
    uint32_t *expect = xmalloc_u32(a.n), *got = xmalloc_u32(a.n);
    for (size_t i = 0; i < a.n; i++) expect[i] = tl_gloss_encode(a.v[i], bits);
    parity_params pp = {.bits = bits};
    char what[64];
    snprintf(what, sizeof what, "gloss%u encode", bits);
    if (run_op(&env, OP_GLOSS_ENCODE, &pp, (uint32_t)a.n, a.v, a.n, NULL, 0, got, a.n))
        TL_CHECK_EQ_U(compare_words(what, expect, got, a.n, 1, describe_f, a.v), 0);
    /* Decode every code, plus codes above the maximum (clamped). */
    uvec c = {0};
    for (uint32_t k = 0; k < (2u << bits) + 16u; k++) upush(&c, k);
    upush(&c, 0xFFFFFFFFu);
    uint32_t *dexp = xmalloc_u32(c.n), *dgot = xmalloc_u32(c.n);
    for (size_t i = 0; i < c.n; i++) dexp[i] = f2u(tl_gloss_decode(c.v[i], bits));
    snprintf(what, sizeof what, "gloss%u decode", bits);
    if (run_op(&env, OP_GLOSS_DECODE, &pp, (uint32_t)c.n, NULL, 0, c.v, c.n, dgot, c.n))
        TL_CHECK_EQ_U(compare_words(what, dexp, dgot, c.n, 1, describe_u, c.v), 0);
    free(dexp);
    free(dgot);
    free(c.v);
    free(expect);
    free(got);
    free(a.v);
    env_close(&env);
}

static void parity_gloss8(void) { parity_gloss(8); }
static void parity_gloss10(void) { parity_gloss(10); }

/* tl_gloss_to_specular_power is the one function that cannot be bit-identical: C calls glibc's
 * exp2f (about half an ULP, in effect correctly rounded), GLSL calls exp2, which GLSL 4.50
 * (section 4.7.1) only requires to within 3 + 2|x| ULP and llvmpipe evaluates as 2^int(x) times a
 * polynomial in frac(x). The exponent e = 1 + 11 g is computed identically on both sides (same
 * clamp, `precise`, no contraction), so every difference is exp2's own error.
 * Bound asserted: 4 ULP. Measured on llvmpipe (Mesa 22.3.6): at most 3 ULP, with about 40 % of
 * the inputs off by 1 to 3; the extra ULP is headroom for other llvmpipe builds. The portable
 * limit would be the specification's 3 + 2 * 12 = 27 ULP (e <= 12), but that is too loose to
 * notice an exponent that is itself a ULP off (which moves the power by 5 to 11 ULP at e >= 8).
 * A 3-ULP relative error in a Blinn-Phong exponent is invisible in shading (< 4e-7 relative).
 * Integer exponents (gloss 0 and 1, i.e. powers 2 and 4096 at the ends of the range, and the
 * k / 11 that hit an integer exactly) must match exactly. */
#define GLOSS_POWER_MAX_ULP 4u

static void parity_gloss_specular_power(void)
{
    parity_env env;
    if (!env_open(&env)) return;
    fvec a = {0};
    gloss_inputs(&a, 10);
    for (uint32_t k = 0; k <= 255; k++) fpush(&a, (float)k / 255.0f);
    size_t first_exact = a.n;
    fpush(&a, 0.0f);
    fpush(&a, 1.0f);
    fpush(&a, -1.0f);
    fpush(&a, 2.0f);
    for (int k = 1; k < 11; k++) {
        float g = (float)k / 11.0f;
        if (1.0f + 11.0f * g == (float)(k + 1)) fpush(&a, g); /* exponent exactly an integer */
    }
    uint32_t *got = xmalloc_u32(a.n);
    if (run_op(&env, OP_GLOSS_POWER, NULL, (uint32_t)a.n, a.v, a.n, NULL, 0, got, a.n)) {
        uint64_t worst = 0;
        size_t worst_i = 0, differ = 0, exact_bad = 0, histogram[5] = {0};
        for (size_t i = 0; i < a.n; i++) {
            uint32_t e = f2u(tl_gloss_to_specular_power(a.v[i]));
            uint64_t d = ulp_distance(e, got[i]);
            differ += d != 0;
            histogram[d < 4 ? d : 4]++;
            if (d > worst) {
                worst = d;
                worst_i = i;
            }
            if (i >= first_exact && d != 0) {
                exact_bad++;
                fprintf(stderr, "gloss %a: C %a GLSL %a (integer exponent)\n", (double)a.v[i],
                        (double)u2f(e), (double)u2f(got[i]));
            }
        }
        printf("%-40s %8zu inputs, %zu differ, max %llu ULP (bound %u) at gloss %a\n",
               "gloss_to_specular_power", a.n, differ, (unsigned long long)worst, GLOSS_POWER_MAX_ULP,
               (double)a.v[worst_i]);
        printf("  ULP histogram: 0: %zu, 1: %zu, 2: %zu, 3: %zu, 4+: %zu\n", histogram[0], histogram[1],
               histogram[2], histogram[3], histogram[4]);
        TL_CHECK_LE(worst, GLOSS_POWER_MAX_ULP);
        TL_CHECK_EQ_U(exact_bad, 0);
    }
    free(got);
    free(a.v);
    env_close(&env);
}

/* ---- albedo --------------------------------------------------------------------------------- */

/* Random colours in [0,1]^3, all 4096 colours of the 16^3 grid k/15 (0 and 1 included), a few
 * out-of-range, denormal, Inf and NaN channels. */
static void colour_inputs(fvec *a)
{
    tl_rng rng = {0xC010u};
    for (uint32_t i = 0; i < RANDOM_COUNT; i++)
        fpush3(a, (float)tl_rng_unit(&rng), (float)tl_rng_unit(&rng), (float)tl_rng_unit(&rng));
    for (int r = 0; r < 16; r++)
        for (int g = 0; g < 16; g++)
            for (int b = 0; b < 16; b++) fpush3(a, (float)r / 15.0f, (float)g / 15.0f, (float)b / 15.0f);
    const float s[] = {0.0f, 1.0f, -0.0f, -0.5f, 1.5f, 0x1.0p-149f, INFINITY, -INFINITY, NAN};
    for (size_t i = 0; i < 9; i++)
        for (size_t j = 0; j < 9; j++)
            for (size_t k = 0; k < 9; k++) fpush3(a, s[i], s[j], s[k]);
}

static void parity_luma_chroma(tl_color_space space)
{
    parity_env env;
    if (!env_open(&env)) return;
    const char *name = tl_color_space_name(space);
    fvec a = {0};
    colour_inputs(&a);
    size_t count = a.n / 3;
    uint32_t *expect = xmalloc_u32(a.n), *got = xmalloc_u32(a.n);
    fvec ycc = {0};
    for (size_t i = 0; i < count; i++) {
        float y[3];
        tl_rgb_to_luma_chroma(space, a.v + 3 * i, y);
        for (int k = 0; k < 3; k++) expect[3 * i + k] = f2u(y[k]);
        if (i < RANDOM_COUNT + 4096) fpush3(&ycc, y[0], y[1], y[2]);
    }
    parity_params pp = {.space = (uint32_t)space};
    char what[64];
    snprintf(what, sizeof what, "rgb_to_luma_chroma %s", name);
    if (run_op(&env, OP_RGB_TO_YCC, &pp, (uint32_t)count, a.v, a.n, NULL, 0, got, a.n))
        TL_CHECK_EQ_U(compare_words(what, expect, got, count, 3, describe_xyz, a.v), 0);
    /* Inverse: the forward outputs of the random and grid colours, their 8-bit quantised
     * versions (what the G-buffer stores), random triples in [0,1]^3 (out-of-gamut, clamped)
     * and the special values. */
    size_t nfwd = ycc.n;
    for (size_t i = 0; i < nfwd; i++) fpush(&ycc, roundf(ycc.v[i] * 255.0f) / 255.0f);
    tl_rng rng = {0xC011u};
    for (uint32_t i = 0; i < 16384; i++) fpush(&ycc, (float)tl_rng_unit(&rng));
    for (size_t i = 3 * (RANDOM_COUNT + 4096); i < a.n; i++) fpush(&ycc, a.v[i]);
    size_t icount = ycc.n / 3;
    uint32_t *iexp = xmalloc_u32(ycc.n), *igot = xmalloc_u32(ycc.n);
    for (size_t i = 0; i < icount; i++) {
        float rgb[3];
        tl_luma_chroma_to_rgb(space, ycc.v + 3 * i, rgb);
        for (int k = 0; k < 3; k++) iexp[3 * i + k] = f2u(rgb[k]);
    }
    snprintf(what, sizeof what, "luma_chroma_to_rgb %s", name);
    if (run_op(&env, OP_YCC_TO_RGB, &pp, (uint32_t)icount, ycc.v, ycc.n, NULL, 0, igot, ycc.n))
        TL_CHECK_EQ_U(compare_words(what, iexp, igot, icount, 3, describe_xyz, ycc.v), 0);
    free(iexp);
    free(igot);
    free(ycc.v);
    free(expect);
    free(got);
    free(a.v);
    env_close(&env);
}

static void parity_luma_chroma_ycbcr(void) { parity_luma_chroma(TL_COLOR_SPACE_YCBCR); }
static void parity_luma_chroma_ycocg(void) { parity_luma_chroma(TL_COLOR_SPACE_YCOCG); }

static void parity_albedo(tl_color_space space)
{
    parity_env env;
    if (!env_open(&env)) return;
    fvec a = {0};
    colour_inputs(&a);
    size_t count = a.n / 3;
    uvec px = {0};
    tl_rng rng = {0xA1BEu};
    for (size_t i = 0; i < count; i++) {
        upush(&px, (uint32_t)(tl_rng_u64(&rng) & 0xFFFFu));
        upush(&px, (uint32_t)(tl_rng_u64(&rng) & 0xFFFFu));
    }
    uint32_t *expect = xmalloc_u32(2 * count), *got = xmalloc_u32(2 * count);
    for (size_t i = 0; i < count; i++) {
        uint8_t b[2];
        tl_albedo_encode_pixel(space, a.v + 3 * i, px.v[2 * i], px.v[2 * i + 1], b);
        expect[2 * i] = b[0];
        expect[2 * i + 1] = b[1];
    }
    parity_params pp = {.space = (uint32_t)space};
    char what[64];
    snprintf(what, sizeof what, "albedo_encode_pixel %s", tl_color_space_name(space));
    if (run_op(&env, OP_ALBEDO_ENCODE, &pp, (uint32_t)count, a.v, a.n, px.v, px.n, got, 2 * count))
        TL_CHECK_EQ_U(compare_words(what, expect, got, count, 2, describe_xyz, a.v), 0);
    free(expect);
    free(got);
    free(px.v);
    free(a.v);
    env_close(&env);
}

static void parity_albedo_ycbcr(void) { parity_albedo(TL_COLOR_SPACE_YCBCR); }
static void parity_albedo_ycocg(void) { parity_albedo(TL_COLOR_SPACE_YCOCG); }

/* Same as the C's neighbour mirroring (albedo.c tl__mirror). */
static int mirror(int64_t c, uint32_t n, uint32_t *out)
{
    if (c < 0) c = -c;
    if (c >= (int64_t)n) c = 2 * ((int64_t)n - 1) - c;
    if (c < 0 || c >= (int64_t)n) return 0;
    *out = (uint32_t)c;
    return 1;
}

/* Appends the GLSL arguments for pixel (x, y): luma, nl[4], nc[4], count, with neighbours in the
 * C's order left, right, up (y - 1), down (y + 1), mirrored at the borders. */
static void edge_args(uvec *u, const uint8_t *yc, uint32_t w, uint32_t h, uint32_t x, uint32_t y)
{
    static const int dx[4] = {-1, 1, 0, 0}, dy[4] = {0, 0, -1, 1};
    uint32_t nl[4] = {0}, nc[4] = {0}, count = 0;
    for (int i = 0; i < 4; i++) {
        uint32_t mx, my;
        if (!mirror((int64_t)x + dx[i], w, &mx) || !mirror((int64_t)y + dy[i], h, &my)) continue;
        nl[count] = yc[2 * ((size_t)my * w + mx)];
        nc[count] = yc[2 * ((size_t)my * w + mx) + 1];
        count++;
    }
    upush(u, yc[2 * ((size_t)y * w + x)]);
    for (int i = 0; i < 4; i++) upush(u, nl[i]);
    for (int i = 0; i < 4; i++) upush(u, nc[i]);
    upush(u, count);
}

static void parity_albedo_edge_chroma(void)
{
    parity_env env;
    if (!env_open(&env)) return;
    /* A 96x96 image: 8x8 blocks of random base luma (hard edges between blocks) plus per-pixel
     * noise of up to +-40 (so luma differences straddle the 30/255 threshold), isolated
     * single-pixel features, flat runs (equal lumas: ties for the closest neighbour), random
     * chroma; then thin images (1 pixel wide or high: 2 neighbours; 1x1: none). */
    enum { W = 96, H = 96 };
    static uint8_t yc[W * H * 2];
    tl_rng rng = {0xED6Eu};
    uint8_t base[(W / 8) * (H / 8)];
    for (size_t i = 0; i < sizeof base; i++) base[i] = (uint8_t)(tl_rng_u64(&rng) & 0xFF);
    for (uint32_t y = 0; y < H; y++)
        for (uint32_t x = 0; x < W; x++) {
            int l = base[(y / 8) * (W / 8) + x / 8];
            uint64_t r = tl_rng_u64(&rng);
            if ((r & 15u) == 0) l = (int)((r >> 8) & 0xFF);              /* single-pixel feature */
            else if ((y / 8 + x / 8) % 3 != 0) l += (int)((r >> 16) % 81u) - 40; /* noise */
            yc[2 * (y * W + x)] = (uint8_t)(l < 0 ? 0 : l > 255 ? 255 : l);
            yc[2 * (y * W + x) + 1] = (uint8_t)(r >> 32);
        }
    uvec args = {0};
    fvec expect_f = {0};
    size_t interior = 0;
    for (uint32_t y = 0; y < H; y++)
        for (uint32_t x = 0; x < W; x++) {
            edge_args(&args, yc, W, H, x, y);
            fpush(&expect_f, tl_albedo_missing_chroma(TL_CHROMA_FILTER_EDGE, yc, W, H, x, y));
            interior += x > 0 && y > 0 && x + 1 < W && y + 1 < H;
        }
    /* Thin images taken from the first row / column (and a 1x1 one). */
    static uint8_t row[W * 2], col[H * 2];
    memcpy(row, yc, sizeof row);
    for (uint32_t y = 0; y < H; y++) memcpy(col + 2 * y, yc + 2 * (y * W), 2);
    for (uint32_t x = 0; x < W; x++) {
        edge_args(&args, row, W, 1, x, 0);
        fpush(&expect_f, tl_albedo_missing_chroma(TL_CHROMA_FILTER_EDGE, row, W, 1, x, 0));
    }
    for (uint32_t y = 0; y < H; y++) {
        edge_args(&args, col, 1, H, 0, y);
        fpush(&expect_f, tl_albedo_missing_chroma(TL_CHROMA_FILTER_EDGE, col, 1, H, 0, y));
    }
    edge_args(&args, yc, 1, 1, 0, 0);
    fpush(&expect_f, tl_albedo_missing_chroma(TL_CHROMA_FILTER_EDGE, yc, 1, 1, 0, 0));
    /* Every (centre, neighbour) luma difference class on a small synthetic set: 4 neighbours at
     * luma offsets from -40 to 40 around a centre, covering d = 0, 29, 30, 31 exactly. */
    static const int offs[] = {-40, -31, -30, -29, -15, -1, 0, 1, 15, 29, 30, 31, 40};
    for (size_t i = 0; i < 13; i++)
        for (size_t j = 0; j < 13; j++) {
            uint8_t img[3 * 3 * 2];
            for (int k = 0; k < 9; k++) {
                img[2 * k] = 128;
                img[2 * k + 1] = (uint8_t)(tl_rng_u64(&rng) & 0xFF);
            }
            img[2 * 3] = (uint8_t)(128 + offs[i]);     /* left */
            img[2 * 5] = (uint8_t)(128 + offs[j]);     /* right */
            img[2 * 1] = (uint8_t)(128 + offs[12 - i]); /* up */
            img[2 * 7] = (uint8_t)(128 + offs[(i + j) % 13]); /* down */
            edge_args(&args, img, 3, 3, 1, 1);
            fpush(&expect_f, tl_albedo_missing_chroma(TL_CHROMA_FILTER_EDGE, img, 3, 3, 1, 1));
        }
    size_t count = expect_f.n;
    uint32_t *expect = xmalloc_u32(count), *got = xmalloc_u32(count);
    for (size_t i = 0; i < count; i++) expect[i] = f2u(expect_f.v[i]);
    if (run_op(&env, OP_EDGE_CHROMA, NULL, (uint32_t)count, NULL, 0, args.v, args.n, got, count)) {
        printf("(%zu interior pixels of %dx%d, %zu border, thin-image and synthetic pixels)\n", interior, W, H,
               count - interior);
        TL_CHECK_EQ_U(compare_words("albedo_edge_chroma", expect, got, count, 1, NULL, NULL), 0);
    }
    free(expect);
    free(got);
    free(expect_f.v);
    free(args.v);
    env_close(&env);
}

/* ---- depth ---------------------------------------------------------------------------------- */

/* Window depths for one projection: uniform in [0,1], depths of log-uniform distances between
 * near / 2 and far * 2 (or 10^7 near for infinite far) as the GPU writes them, their D24
 * quantisation, and the ends (0, 1, a ULP inside, -0, just outside, NaN, Inf). */
static void depth_inputs(fvec *a, const tl_projection *p, float near_z, float far_z, uint64_t seed)
{
    tl_rng rng = {seed};
    double lo = log((double)near_z * 0.5), hi = log(far_z > 0.0f ? (double)far_z * 2.0 : (double)near_z * 1e7);
    for (uint32_t i = 0; i < 8192; i++) fpush(a, (float)tl_rng_unit(&rng));
    for (uint32_t i = 0; i < 8192; i++) {
        float d = tl_depth_window_from_distance(p, (float)exp(lo + (hi - lo) * tl_rng_unit(&rng)));
        fpush(a, d);
        fpush(a, tl_depth_quantize(TL_DEPTH_FORMAT_D24, d));
    }
    const float s[] = {0.0f, 1.0f, 0.5f, nextafterf(0.0f, 1.0f), nextafterf(1.0f, 0.0f), -0.0f, FLT_MIN,
                       nextafterf(1.0f, 2.0f), -0x1.0p-24f, 1.5f, -1.0f, NAN, INFINITY, -INFINITY,
                       tl_depth_window_from_distance(p, near_z), tl_depth_window_from_distance(p, far_z)};
    for (size_t i = 0; i < sizeof s / sizeof s[0]; i++) fpush(a, s[i]);
}

static void parity_depth(tl_depth_format format)
{
    parity_env env;
    if (!env_open(&env)) return;
    /* near/far ratios 1:10, 1:10^4, 1:10^7, an infinite far plane, and an off-centre copy
     * (m[8], m[9] nonzero, as a jittered or asymmetric frustum has). */
    const struct { float fov, aspect, near_z, far_z; bool off_centre; } cfg[] = {
        {1.0f, 16.0f / 9.0f, 0.5f, 5.0f, false},     {0.9f, 1.0f, 0.1f, 1000.0f, false},
        {1.2f, 1.5f, 0.01f, 1e5f, false},             {1.0f, 4.0f / 3.0f, 0.1f, 0.0f, false},
        {0.7f, 2.0f, 0.05f, 500.0f, true},            {1.4f, 0.5f, 0.2f, INFINITY, true},
    };
    const char *name = tl_depth_format_name(format);
    size_t total_lin = 0, total_pos = 0, bad = 0;
    for (size_t c = 0; c < sizeof cfg / sizeof cfg[0]; c++) {
        tl_projection p;
        TL_CHECK(tl_projection_perspective(format, cfg[c].fov, cfg[c].aspect, cfg[c].near_z, cfg[c].far_z, &p) ==
                 TL_OK);
        if (cfg[c].off_centre) {
            p.m[8] = 0.0625f;
            p.m[9] = -0.1875f;
        }
        parity_params pp = {.depth = {p.m[10], p.m[14], p.m[11], format == TL_DEPTH_FORMAT_D32F_REVERSED ? 1.0f : 0.0f},
                            .ray = {p.m[0], p.m[5], p.m[8], p.m[9]}};
        fvec d = {0};
        depth_inputs(&d, &p, cfg[c].near_z, cfg[c].far_z, 0xDE97u + c);
        uint32_t *expect = xmalloc_u32(d.n), *got = xmalloc_u32(d.n);
        for (size_t i = 0; i < d.n; i++) expect[i] = f2u(tl_depth_linearize(&p, d.v[i]));
        char what[64];
        snprintf(what, sizeof what, "depth_linearize %s #%zu", name, c);
        if (run_op(&env, OP_DEPTH_LINEARIZE, &pp, (uint32_t)d.n, d.v, d.n, NULL, 0, got, d.n))
            bad += compare_words(what, expect, got, d.n, 1, describe_f, d.v);
        total_lin += d.n;
        /* Positions: each depth with a random NDC point, plus the corners and centre. */
        fvec xyd = {0};
        tl_rng rng = {0x9050u + c};
        const float corner[] = {-1.0f, 0.0f, 1.0f};
        for (size_t i = 0; i < d.n; i++) {
            float x, y;
            if (i % 16 < 9) {
                x = corner[i % 3];
                y = corner[(i / 3) % 3];
            } else {
                x = (float)(2.0 * tl_rng_unit(&rng) - 1.0);
                y = (float)(2.0 * tl_rng_unit(&rng) - 1.0);
            }
            fpush3(&xyd, x, y, d.v[i]);
        }
        size_t n = d.n;
        uint32_t *pexp = xmalloc_u32(3 * n), *pgot = xmalloc_u32(3 * n);
        for (size_t i = 0; i < n; i++) {
            float pos[3];
            tl_view_position_from_depth(&p, xyd.v[3 * i], xyd.v[3 * i + 1], xyd.v[3 * i + 2], pos);
            for (int k = 0; k < 3; k++) pexp[3 * i + k] = f2u(pos[k]);
        }
        snprintf(what, sizeof what, "view_position %s #%zu", name, c);
        if (run_op(&env, OP_VIEW_POSITION, &pp, (uint32_t)n, xyd.v, xyd.n, NULL, 0, pgot, 3 * n))
            bad += compare_words(what, pexp, pgot, n, 3, describe_xyz, xyd.v);
        total_pos += n;
        free(pexp);
        free(pgot);
        free(xyd.v);
        free(expect);
        free(got);
        free(d.v);
    }
    printf("depth %s: %zu depths, %zu positions compared\n", name, total_lin, total_pos);
    TL_CHECK_EQ_U(bad, 0);
    env_close(&env);
}

static void parity_depth_d24(void) { parity_depth(TL_DEPTH_FORMAT_D24); }
static void parity_depth_d32f(void) { parity_depth(TL_DEPTH_FORMAT_D32F); }
static void parity_depth_reversed(void) { parity_depth(TL_DEPTH_FORMAT_D32F_REVERSED); }

static const tl_test_case cases[] = {
    {"parity_oct8_encode", parity_oct8_encode},
    {"parity_oct10_encode", parity_oct10_encode},
    {"parity_oct12_encode", parity_oct12_encode},
    {"parity_oct16_encode", parity_oct16_encode},
    {"parity_oct8_encode_precise", parity_oct8_encode_precise},
    {"parity_oct10_encode_precise", parity_oct10_encode_precise},
    {"parity_oct12_encode_precise", parity_oct12_encode_precise},
    {"parity_oct16_encode_precise", parity_oct16_encode_precise},
    {"parity_oct8_decode_all_codes", parity_oct8_decode_all_codes},
    {"parity_oct10_decode_all_codes", parity_oct10_decode_all_codes},
    {"parity_oct12_decode", parity_oct12_decode},
    {"parity_oct16_decode", parity_oct16_decode},
    {"parity_oct_extreme_cases", parity_oct_extreme_cases},
    {"parity_oct_axes_exact", parity_oct_axes_exact},
    {"parity_rt0_rgba8", parity_rt0_rgba8},
    {"parity_rt0_rgb10a2", parity_rt0_rgb10a2},
    {"parity_gloss8", parity_gloss8},
    {"parity_gloss10", parity_gloss10},
    {"parity_gloss_specular_power", parity_gloss_specular_power},
    {"parity_luma_chroma_ycbcr", parity_luma_chroma_ycbcr},
    {"parity_luma_chroma_ycocg", parity_luma_chroma_ycocg},
    {"parity_albedo_ycbcr", parity_albedo_ycbcr},
    {"parity_albedo_ycocg", parity_albedo_ycocg},
    {"parity_albedo_edge_chroma", parity_albedo_edge_chroma},
    {"parity_depth_d24", parity_depth_d24},
    {"parity_depth_d32f", parity_depth_d32f},
    {"parity_depth_reversed", parity_depth_reversed},
};

TL_TEST_MAIN(cases)
