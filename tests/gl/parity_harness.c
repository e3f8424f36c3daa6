/* The GLSL/C parity harness (parity.h): one compute program per operation, run over SSBOs;
 * bit-for-bit comparison; the input sets. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "parity.h"

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
bool env_open(parity_env *env)
{
    memset(env, 0, sizeof *env);
    if (!tl_gl_fixture_open(&env->f, 16)) return false;
    env->f.gl.CreateBuffers(3, env->buffers);
    return true;
}

void env_close(parity_env *env)
{
    env->f.gl.DeleteBuffers(3, env->buffers);
    tl_gl_fixture_close(&env->f);
}

/* Runs operation `op` over `count` items; `out` receives `out_words` uint32 words. Returns false
 * (after a failed check) when the program does not build or GL reports an error. */
bool run_op(parity_env *env, int op, const parity_params *pp, uint32_t count, const float *in_f,
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

uint32_t f2u(float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    return u;
}

float u2f(uint32_t u)
{
    float f;
    memcpy(&f, &u, 4);
    return f;
}

/* Distance in units in the last place between two floats (0 for identical bits; +0 and -0 are
 * 0 apart). */
uint64_t ulp_distance(uint32_t a, uint32_t b)
{
    int64_t oa = (a & 0x80000000u) ? -(int64_t)(a & 0x7FFFFFFFu) : (int64_t)a;
    int64_t ob = (b & 0x80000000u) ? -(int64_t)(b & 0x7FFFFFFFu) : (int64_t)b;
    return (uint64_t)(oa > ob ? oa - ob : ob - oa);
}

/* Growable float / uint arrays for building input sets. */
void fpush(fvec *a, float x)
{
    if (a->n == a->cap) {
        a->cap = a->cap ? 2 * a->cap : 1024;
        a->v = realloc(a->v, a->cap * sizeof *a->v);
        if (!a->v) abort();
    }
    a->v[a->n++] = x;
}

void fpush3(fvec *a, float x, float y, float z)
{
    fpush(a, x);
    fpush(a, y);
    fpush(a, z);
}
void upush(uvec *a, uint32_t x)
{
    if (a->n == a->cap) {
        a->cap = a->cap ? 2 * a->cap : 1024;
        a->v = realloc(a->v, a->cap * sizeof *a->v);
        if (!a->v) abort();
    }
    a->v[a->n++] = x;
}

uint32_t *xmalloc_u32(size_t n)
{
    uint32_t *p = malloc((n ? n : 1) * sizeof *p);
    if (!p) abort();
    return p;
}
size_t compare_words(const char *what, const uint32_t *expect, const uint32_t *got, size_t items,
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

void describe_xyz(size_t i, const void *ctx)
{
    const float *v = (const float *)ctx + 3 * i;
    fprintf(stderr, " for (%a, %a, %a)", (double)v[0], (double)v[1], (double)v[2]);
}

void describe_f(size_t i, const void *ctx)
{
    fprintf(stderr, " for %a", (double)((const float *)ctx)[i]);
}

void describe_u(size_t i, const void *ctx)
{
    fprintf(stderr, " for 0x%08x", ((const uint32_t *)ctx)[i]);
}

/* ---- input sets ----------------------------------------------------------------------------- */
void random_directions(fvec *a, uint64_t seed, size_t count)
{
    tl_rng rng = {seed};
    for (size_t i = 0; i < count; i++) {
        float v[3];
        tl_rng_direction(&rng, v);
        fpush3(a, v[0], v[1], v[2]);
    }
}

/* Every extreme input of docs/stability.md for normals. */
void extreme_normals(fvec *a)
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
