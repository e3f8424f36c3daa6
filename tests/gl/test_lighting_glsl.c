/* The GLSL lighting functions (shaders/lighting.glsl) against the double-precision reference
 * (tests/reference/lighting_ref.c), each function in a compute shader on OSMesa over random and
 * extreme inputs, read back.
 *
 * Tolerance, derived from float precision as a backward error: the shader's float result must lie
 * within the spread of the double reference over inputs perturbed by k units in the last place of
 * float (each input alone, both ways; to first order the sum of |df/dx_i| k ulp(x_i)), plus c ulps
 * of the result. The ulp of a component of a 3-vector (positions, directions) is that of the
 * vector's length: float vector arithmetic rounds relative to the vector, not to each component. A float evaluation whose every operation rounds once (2.5 ULP for GLSL's division,
 * a few for its sqrt, inversesqrt and transcendentals) is the exact result of inputs a few ULP
 * away, with k bounded by the number of roundings on an input's path to the result: k = 8 for the
 * single-formula functions, 32 for the whole light terms (about 30 operations from the positions
 * to a weight), 2 for the products of the resolve step. Results below 2^-64 count as 0 (such a
 * weight cannot reach the FP16 light buffer even times the largest colour: 2^-24 / 65504 is about
 * 2^-40). GLSL leaves the precision of atan to the implementation, so the sphere irradiance
 * (which subtracts terms of similar size where the horizon cuts the sphere) also gets the
 * propagated error of its two atan calls, measured first on the same implementation: twice the
 * largest error times |d E / d atan| of each. The gloss mapping must be bit-exact
 * (codec parity). Every output must be finite, and the extreme cases of docs/stability.md for
 * the GGX model must give finite, non-negative weights within the per-light clamp. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "gl/gl.h"
#include "gl_fixture.h"
#include "lighting_ref.h"
#include "thinlight/codec.h"
#include "tl_test.h"

/* ---- operations ----------------------------------------------------------------------------- */

enum {
    OP_GLOSS_ALPHA = 1, /* gloss -> alpha */
    OP_GGX_D,           /* n, h, alpha -> D */
    OP_GGX_VIS,         /* nl, nv, alpha -> Vis */
    OP_FRESNEL,         /* vh -> s */
    OP_SPHERE_IRR,      /* cos_beta, d2, radius -> E */
    OP_SPHERE_DIR,      /* to_light, r, radius -> direction (fallback +Z) */
    OP_SPHERE_NORM,     /* alpha, radius, d -> (alpha / alpha')^2 */
    OP_GGX_TERMS,       /* light scene (LIGHT_FLOATS) -> diffuse, S1, S2 */
    OP_BP_TERMS,        /* light scene -> diffuse, specular (today's tl_light_terms) */
    OP_RESOLVE,         /* f0, s1, s2, nv -> F0 S1 + S2, Fresnel(n.v) (S1 + S2) */
    OP_TRIG,            /* y, q, x -> acos(y), atan(q, x): the built-ins' own error */
    OP_COUNT
};

/* p(3) n(3) v(3) alpha-or-power light_pos(3) range radius direction(3) cos_inner cos_outer type */
#define LIGHT_FLOATS 21

static const uint32_t op_in[OP_COUNT] = {0, 1, 7, 3, 1, 3, 7, 3, LIGHT_FLOATS, LIGHT_FLOATS, 10, 3};
static const uint32_t op_out[OP_COUNT] = {0, 1, 1, 1, 1, 1, 3, 1, 3, 2, 6, 2};
static const char *const op_name[OP_COUNT] = {"",          "gloss_to_ggx_alpha", "ggx_d",          "ggx_vis",
                                              "fresnel_weight", "sphere_irradiance", "sphere_specular_dir",
                                              "sphere_normalization", "ggx_light_terms", "light_terms (Blinn-Phong)",
                                              "ggx_specular_resolve", "acos, atan"};

static const char shader[] =
    "#include \"codec.glsl\"\n"
    "#include \"lighting.glsl\"\n"
    "layout(local_size_x = 64) in;\n"
    "layout(std430, binding = 0) readonly buffer tl_in { float in_f[]; };\n"
    "layout(std430, binding = 1) writeonly buffer tl_out { float out_f[]; };\n"
    "uniform uint u_count;\n"
    "float a(uint i, uint k) { return in_f[uint(TL_IN) * i + k]; }\n"
    "vec3 a3(uint i, uint k) { return vec3(a(i, k), a(i, k + 1u), a(i, k + 2u)); }\n"
    "void put(uint i, uint k, float x) { out_f[uint(TL_OUT) * i + k] = x; }\n"
    "void put3(uint i, vec3 x) { put(i, 0u, x.x); put(i, 1u, x.y); put(i, 2u, x.z); }\n"
    "void main()\n"
    "{\n"
    "    uint i = gl_GlobalInvocationID.x;\n"
    "    if (i >= u_count) return;\n"
    "#if TL_OP == 1\n"
    "    put(i, 0u, tl_gloss_to_ggx_alpha(a(i, 0u)));\n"
    "#elif TL_OP == 2\n"
    "    put(i, 0u, tl_ggx_d(a3(i, 0u), a3(i, 3u), a(i, 6u)));\n"
    "#elif TL_OP == 3\n"
    "    put(i, 0u, tl_ggx_vis(a(i, 0u), a(i, 1u), a(i, 2u)));\n"
    "#elif TL_OP == 4\n"
    "    put(i, 0u, tl_fresnel_weight(a(i, 0u)));\n"
    "#elif TL_OP == 5\n"
    "    put(i, 0u, tl_sphere_irradiance(a(i, 0u), a(i, 1u), a(i, 2u)));\n"
    "#elif TL_OP == 6\n"
    "    put3(i, tl_sphere_specular_dir(a3(i, 0u), a3(i, 3u), a(i, 6u), vec3(0.0, 0.0, 1.0)));\n"
    "#elif TL_OP == 7\n"
    "    put(i, 0u, tl_sphere_normalization(a(i, 0u), a(i, 1u), a(i, 2u)));\n"
    "#elif TL_OP == 8\n"
    "    put3(i, tl_ggx_light_terms(int(a(i, 20u)), a3(i, 0u), a3(i, 3u), a3(i, 6u), a(i, 9u), a3(i, 10u), a(i, 13u),\n"
    "                               a(i, 14u), a3(i, 15u), a(i, 18u), a(i, 19u)));\n"
    "#elif TL_OP == 9\n"
    "    vec2 t = tl_light_terms(int(a(i, 20u)), a3(i, 0u), a3(i, 3u), a3(i, 6u), a(i, 9u), a3(i, 10u), a(i, 13u),\n"
    "                            a3(i, 15u), a(i, 18u), a(i, 19u));\n"
    "    put(i, 0u, t.x);\n"
    "    put(i, 1u, t.y);\n"
    "#elif TL_OP == 10\n"
    "    vec3 f0 = a3(i, 0u), s1 = a3(i, 3u), s2 = a3(i, 6u);\n"
    "    put3(i, tl_ggx_specular_resolve(f0, s1, s2));\n"
    "    vec3 c = tl_ggx_specular_resolve_nv(f0, s1 + s2, a(i, 9u));\n"
    "    put(i, 3u, c.x); put(i, 4u, c.y); put(i, 5u, c.z);\n"
    "#elif TL_OP == 11\n"
    "    put(i, 0u, acos(a(i, 0u)));\n"
    "    put(i, 1u, atan(a(i, 1u), a(i, 2u)));\n"
    "#endif\n"
    "}\n";

/* Runs `op` over `count` items of op_in[op] floats; `out` receives count * op_out[op] floats. */
static bool run_op(tl_gl_fixture *f, int op, const float *in, size_t count, float *out)
{
    const GladGLContext *gl = &f->gl;
    char d0[32], d1[32], d2[32];
    snprintf(d0, sizeof d0, "TL_OP=%d", op);
    snprintf(d1, sizeof d1, "TL_IN=%u", (unsigned)op_in[op]);
    snprintf(d2, sizeof d2, "TL_OUT=%u", (unsigned)op_out[op]);
    const char *defines[3] = {d0, d1, d2};
    static char log[16384];
    GLuint prog = 0, buf[2];
    tl_result r = tl__program_build(gl,
                                    &(tl__program_desc){.label = "test.lighting",
                                                        .stages = {{GL_COMPUTE_SHADER, "lighting.comp.glsl", shader}},
                                                        .defines = defines,
                                                        .define_count = 3},
                                    &prog, log, sizeof log);
    if (r != TL_OK) fprintf(stderr, "op %s: %s\n", op_name[op], log);
    TL_CHECK(r == TL_OK);
    if (r != TL_OK) return false;
    gl->CreateBuffers(2, buf);
    gl->NamedBufferData(buf[0], (GLsizeiptr)(count * op_in[op] * 4), in, GL_STATIC_DRAW);
    gl->NamedBufferData(buf[1], (GLsizeiptr)(count * op_out[op] * 4), NULL, GL_DYNAMIC_READ);
    const float sentinel = NAN;
    gl->ClearNamedBufferData(buf[1], GL_R32F, GL_RED, GL_FLOAT, &sentinel);
    gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf[0]);
    gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buf[1]);
    gl->UseProgram(prog);
    gl->Uniform1ui(gl->GetUniformLocation(prog, "u_count"), (GLuint)count);
    gl->DispatchCompute((GLuint)((count + 63) / 64), 1, 1);
    gl->MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl->GetNamedBufferSubData(buf[1], 0, (GLsizeiptr)(count * op_out[op] * 4), out);
    gl->UseProgram(0);
    gl->DeleteProgram(prog);
    gl->DeleteBuffers(2, buf);
    GLenum err = gl->GetError();
    TL_CHECK_EQ_U(err, GL_NO_ERROR);
    return err == GL_NO_ERROR;
}

/* ---- the reference of each operation ---------------------------------------------------------- */

static void normalize(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0.0)
        for (int i = 0; i < 3; i++) v[i] /= l;
}

static void light_of(const double *x, tl_ref_light *l)
{
    memset(l, 0, sizeof *l);
    l->type = (tl_ref_light_type)(int)x[20];
    for (int i = 0; i < 3; i++) {
        l->position[i] = x[10 + i];
        l->direction[i] = x[15 + i];
    }
    l->range = x[13];
    l->source_radius = x[14];
    l->cos_inner = x[18];
    l->cos_outer = x[19];
}

static void ref_op(int op, const double *x, double *y)
{
    tl_ref_light l;
    switch (op) {
    case OP_GGX_D: {
        double n[3] = {x[0], x[1], x[2]}, h[3] = {x[3], x[4], x[5]};
        normalize(n);
        normalize(h);
        y[0] = tl_ref_ggx_d(n[0] * h[0] + n[1] * h[1] + n[2] * h[2], x[6]);
        break;
    }
    case OP_GGX_VIS: y[0] = tl_ref_ggx_vis(x[0], x[1], x[2]); break;
    case OP_FRESNEL: y[0] = tl_ref_fresnel_weight(x[0]); break;
    case OP_SPHERE_IRR: y[0] = tl_ref_sphere_irradiance(x[0], x[1], x[2]); break;
    case OP_SPHERE_DIR: {
        static const double fallback[3] = {0.0, 0.0, 1.0};
        tl_ref_sphere_specular_dir(x, x + 3, x[6], fallback, y);
        break;
    }
    case OP_SPHERE_NORM: y[0] = tl_ref_sphere_normalization(x[0], x[1], x[2]); break;
    case OP_GGX_TERMS: light_of(x, &l); tl_ref_ggx_terms(&l, x, x + 3, x + 6, x[9], y); break;
    case OP_BP_TERMS: light_of(x, &l); tl_ref_blinn_phong_terms(&l, x, x + 3, x + 6, x[9], y); break;
    case OP_RESOLVE: {
        double s = tl_ref_fresnel_weight(x[9]);
        for (int i = 0; i < 3; i++) {
            y[i] = x[i] * x[3 + i] + x[6 + i];
            y[3 + i] = (x[i] * (1.0 - s) + s) * (x[3 + i] + x[6 + i]);
        }
        break;
    }
    default: break;
    }
}

/* Index of the first component of the 3-vector input i belongs to, or -1 for a scalar input. */
static int vector_start(int op, uint32_t i)
{
    static const int terms[LIGHT_FLOATS] = {0, 0, 0, 3, 3, 3, 6, 6, 6, -1, 10, 10, 10, -1, -1, 15, 15, 15, -1, -1, -1};
    switch (op) {
    case OP_GGX_D:
    case OP_SPHERE_DIR: return i < 6 ? (int)(i / 3 * 3) : -1;
    case OP_GGX_TERMS:
    case OP_BP_TERMS: return terms[i];
    default: return -1;
    }
}

/* The magnitude whose float ulp input i may be off by. */
static double input_scale(int op, const double *x, uint32_t i)
{
    int v = vector_start(op, i);
    return v < 0 ? x[i] : sqrt(x[v] * x[v] + x[v + 1] * x[v + 1] + x[v + 2] * x[v + 2]);
}

/* Inputs that are not perturbed: the light type, and for the light terms nothing else. */
static int perturbable(int op, uint32_t k) { return !((op == OP_GGX_TERMS || op == OP_BP_TERMS) && k == 20); }

/* Largest absolute errors of GLSL's acos (on [-1, 1]; reported, the shader avoids it) and
 * atan(q, x) (q >= 0, both signs of x), measured. */
typedef struct trig_errors {
    double acos, atan;
} trig_errors;

static trig_errors trig;

/* The built-ins' propagated error in the sphere irradiance E(cos_beta, d2, radius), where the
 * horizon cuts the sphere: E = ((cos atan(sy, y) - x q) s + atan(q, x)) / (pi r^2). */
static double sphere_trig_tolerance(double cos_beta, double d2, double radius)
{
    double r2 = radius * radius, s = r2 / d2;
    if (!(cos_beta * cos_beta < s)) return 0.0;
    return 2.0 * (fabs(cos_beta) * s + 1.0) * trig.atan / (TL_REF_PI * r2);
}

/* The same for the diffuse weight of the light terms (window x irradiance at the clamped
 * distance). */
static double terms_trig_tolerance(const double *x)
{
    if ((int)x[20] == 3 || x[14] <= 0.0) return 0.0;
    double d[3] = {x[10] - x[0], x[11] - x[1], x[12] - x[2]}, d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    double dist = sqrt(d2), m = 0.01 * x[13], r2 = x[14] * x[14];
    if (!(dist > 1e-6)) return 0.0;
    double cb = (x[3] * d[0] + x[4] * d[1] + x[5] * d[2]) / dist;
    double d2c = fmax(d2, fmax(r2 / TL_REF_SPHERE_MAX_SIN2, m * m));
    return tl_ref_window(dist, x[13]) * sphere_trig_tolerance(cb, d2c, x[14]);
}

/* Tolerances per operation: k ulps of each input, c ulps of the result (file comment). */
static void op_ulps(int op, double *k, double *c)
{
    *k = op == OP_GGX_TERMS || op == OP_BP_TERMS ? 32.0 : op == OP_RESOLVE ? 2.0 : 8.0;
    *c = 16.0;
}

/* ---- comparison -------------------------------------------------------------------------------- */

typedef struct op_result {
    size_t items, bad, nonfinite;
    double worst_ratio; /* largest |glsl - ref| / tolerance */
    double worst_rel;   /* largest |glsl - ref| / |ref| among results of at least 1 % of the largest */
} op_result;

static double fulp(double x) { return ldexp(1.0, ilogb(fmax(fabs(x), FLT_MIN)) - 23); }

/* Tolerance of output j of item x (doubles of the float inputs). */
static void tolerance(int op, const double *x, const double *y, double *tol)
{
    uint32_t n = op_in[op], m = op_out[op];
    double k, c, xp[LIGHT_FLOATS], yp[8], ym[8];
    op_ulps(op, &k, &c);
    for (uint32_t j = 0; j < m; j++) tol[j] = c * fulp(y[j]) + 0x1.0p-64;
    if (op == OP_SPHERE_IRR) tol[0] += sphere_trig_tolerance(x[0], x[1], x[2]);
    if (op == OP_GGX_TERMS) tol[0] += terms_trig_tolerance(x);
    for (uint32_t i = 0; i < n; i++) {
        double scale = input_scale(op, x, i);
        if (!perturbable(op, i) || scale == 0.0) continue;
        memcpy(xp, x, n * sizeof *x);
        xp[i] = x[i] + k * fulp(scale);
        ref_op(op, xp, yp);
        xp[i] = x[i] - k * fulp(scale);
        ref_op(op, xp, ym);
        for (uint32_t j = 0; j < m; j++) tol[j] += fmax(fabs(yp[j] - y[j]), fabs(ym[j] - y[j]));
    }
}

static void inputs_of(int op, const float *in, size_t it, double *x)
{
    for (uint32_t i = 0; i < op_in[op]; i++) x[i] = in[it * op_in[op] + i];
}

static double largest_result(int op, const float *in, size_t count)
{
    double big = 0.0;
    for (size_t it = 0; it < count; it++) {
        double x[LIGHT_FLOATS], y[8];
        inputs_of(op, in, it, x);
        ref_op(op, x, y);
        for (uint32_t j = 0; j < op_out[op]; j++) big = fmax(big, fabs(y[j]));
    }
    return big;
}

static op_result compare(int op, const float *in, const float *out, size_t count)
{
    op_result r = {count, 0, 0, 0.0, 0.0};
    uint32_t n = op_in[op], m = op_out[op];
    double floor_rel = 0.01 * largest_result(op, in, count);
    for (size_t it = 0; it < count; it++) {
        double x[LIGHT_FLOATS], y[8], tol[8];
        inputs_of(op, in, it, x);
        ref_op(op, x, y);
        tolerance(op, x, y, tol);
        int bad = 0;
        for (uint32_t j = 0; j < m; j++) {
            double g = out[it * m + j], e = fabs(g - y[j]);
            if (!isfinite(g)) {
                r.nonfinite++;
                bad = 1;
                continue;
            }
            r.worst_ratio = fmax(r.worst_ratio, e / tol[j]);
            if (fabs(y[j]) >= floor_rel) r.worst_rel = fmax(r.worst_rel, e / fabs(y[j]));
            bad |= e > tol[j];
        }
        if (bad && r.bad++ < 4) {
            fprintf(stderr, "  %s item %zu:", op_name[op], it);
            for (uint32_t i = 0; i < n; i++) fprintf(stderr, " %a", x[i]);
            fprintf(stderr, "\n    ->");
            for (uint32_t j = 0; j < m; j++) fprintf(stderr, " GLSL %.9g ref %.9g tol %.3g;", out[it * m + j], y[j], tol[j]);
            fprintf(stderr, "\n");
        }
    }
    printf("  %-28s %7zu items: %zu beyond tolerance, %zu non-finite; largest error %.3g of the tolerance; "
           "relative error %.3g (results >= 1 %% of the largest)\n",
           op_name[op], r.items, r.bad, r.nonfinite, r.worst_ratio, r.worst_rel);
    return r;
}

/* ---- inputs ------------------------------------------------------------------------------------ */

typedef struct fbuf {
    float *v;
    size_t n, cap;
} fbuf;

static void push(fbuf *b, float x)
{
    if (b->n == b->cap) {
        b->cap = b->cap ? 2 * b->cap : 4096;
        b->v = realloc(b->v, b->cap * sizeof *b->v);
        if (!b->v) abort();
    }
    b->v[b->n++] = x;
}

static void push3(fbuf *b, const float v[3])
{
    for (int i = 0; i < 3; i++) push(b, v[i]);
}

static float uni(tl_rng *r, double lo, double hi) { return (float)(lo + (hi - lo) * tl_rng_unit(r)); }

static float rand_alpha(tl_rng *r)
{
    /* log-uniform over [TL_GGX_MIN_ALPHA, 1], the ends included now and then */
    uint64_t u = tl_rng_u64(r) % 16;
    return u == 0 ? TL_GGX_MIN_ALPHA : u == 1 ? 1.0f : (float)exp2(-7.0 * tl_rng_unit(r));
}

/* A unit float vector, and one near it (angle up to `spread` radians). */
static void near_dir(tl_rng *r, const float n[3], double spread, float out[3])
{
    float d[3];
    tl_rng_direction(r, d);
    double s = spread * tl_rng_unit(r), v[3];
    for (int i = 0; i < 3; i++) v[i] = n[i] + s * d[i];
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int i = 0; i < 3; i++) out[i] = (float)(v[i] / l);
}

#define RANDOM_ITEMS 100000

static void inputs_d(fbuf *b, tl_rng *r)
{
    for (int i = 0; i < RANDOM_ITEMS; i++) {
        float n[3], h[3], a = rand_alpha(r);
        tl_rng_direction(r, n);
        near_dir(r, n, i % 4 == 0 ? 2.0 : 3.0 * a, h);
        if (i % 97 == 0) memcpy(h, n, sizeof h); /* the peak itself */
        push3(b, n);
        push3(b, h);
        push(b, a);
    }
}

static void inputs_scalar(int op, fbuf *b, tl_rng *r)
{
    for (int i = 0; i < RANDOM_ITEMS; i++) {
        float a = rand_alpha(r);
        if (op == OP_GGX_VIS) {
            push(b, i % 50 == 0 ? 0.0f : uni(r, 0.0, 1.0));
            push(b, i % 70 == 0 ? 0.0f : i % 71 == 0 ? 1.0f : uni(r, 0.0, 1.0));
            push(b, a);
        } else if (op == OP_FRESNEL) {
            push(b, i < 4 ? (float)(i - 1) * 0.5f : uni(r, -0.1, 1.1));
        } else if (op == OP_SPHERE_NORM) {
            float d = uni(r, 0.01, 20.0);
            push(b, a);
            push(b, i % 10 == 0 ? 0.0f : uni(r, 0.0, 1.2) * d);
            push(b, d);
        } else { /* OP_SPHERE_IRR: the sphere from tiny to touching, every angle to the horizon */
            double s = i % 10 == 0 ? TL_REF_SPHERE_MAX_SIN2 : exp2(-14.0 * tl_rng_unit(r)) * TL_REF_SPHERE_MAX_SIN2;
            float radius = (float)exp2(8.0 * tl_rng_unit(r) - 4.0);
            double cb = i % 3 == 0 ? sqrt(s) * (2.0 * tl_rng_unit(r) - 1.0) : 2.0 * tl_rng_unit(r) - 1.0;
            push(b, (float)cb);
            push(b, (float)fmax(radius * (double)radius / s, radius * (double)radius / TL_REF_SPHERE_MAX_SIN2));
            push(b, radius);
        }
    }
}

static void inputs_dir(fbuf *b, tl_rng *r)
{
    for (int i = 0; i < RANDOM_ITEMS; i++) {
        float l[3], rr[3], d = uni(r, 0.1, 10.0);
        tl_rng_direction(r, l);
        tl_rng_direction(r, rr);
        for (int k = 0; k < 3; k++) l[k] *= d;
        push3(b, l);
        push3(b, rr);
        push(b, i % 8 == 0 ? 0.0f : uni(r, 0.0, 2.0) * d);
    }
}

/* A random light scene: a surface point in view (1..20 m), a normal mostly facing the viewer, a
 * light around it, every type, radius 0 to 1, range 1 to 20. */
static void scene(tl_rng *r, int ggx, float *x)
{
    float d[3];
    tl_rng_direction(r, d);
    float dist = uni(r, 1.0, 20.0);
    float p[3] = {d[0] * dist * 0.5f, d[1] * dist * 0.5f, -dist};
    double pl = sqrt((double)p[0] * p[0] + (double)p[1] * p[1] + (double)p[2] * p[2]);
    float v[3] = {(float)(-p[0] / pl), (float)(-p[1] / pl), (float)(-p[2] / pl)}, n[3];
    near_dir(r, v, 1.6, n);
    float range = uni(r, 1.0, 20.0), ld[3], dir[3];
    tl_rng_direction(r, ld);
    tl_rng_direction(r, dir);
    float ldist = uni(r, 0.0, 1.1) * range;
    memcpy(x, p, sizeof p);
    memcpy(x + 3, n, sizeof n);
    memcpy(x + 6, v, sizeof v);
    x[9] = ggx ? rand_alpha(r) : (float)tl_ref_specular_power(tl_rng_unit(r));
    for (int k = 0; k < 3; k++) x[10 + k] = p[k] + ld[k] * ldist;
    x[13] = range;
    x[14] = tl_rng_u64(r) % 3 == 0 ? 0.0f : uni(r, 0.0, 1.0);
    memcpy(x + 15, dir, sizeof dir);
    x[18] = uni(r, 0.8, 1.0);
    x[19] = x[18] - uni(r, 0.01, 0.3);
    x[20] = (float)(1 + (int)(tl_rng_u64(r) % 3));
}

static void inputs_terms(int op, fbuf *b, tl_rng *r)
{
    for (int i = 0; i < RANDOM_ITEMS; i++) {
        float x[LIGHT_FLOATS];
        scene(r, op == OP_GGX_TERMS, x);
        for (int k = 0; k < LIGHT_FLOATS; k++) push(b, x[k]);
    }
}

static void inputs_resolve(fbuf *b, tl_rng *r)
{
    for (int i = 0; i < RANDOM_ITEMS; i++) {
        for (int k = 0; k < 3; k++) push(b, uni(r, 0.0, 1.0));
        for (int k = 0; k < 6; k++) push(b, (float)exp2(20.0 * tl_rng_unit(r) - 10.0));
        push(b, uni(r, 0.0, 1.0));
    }
}

static void make_inputs(int op, fbuf *b)
{
    tl_rng r = {0x11647u + (uint64_t)op};
    if (op == OP_GGX_D) inputs_d(b, &r);
    else if (op == OP_SPHERE_DIR) inputs_dir(b, &r);
    else if (op == OP_GGX_TERMS || op == OP_BP_TERMS) inputs_terms(op, b, &r);
    else if (op == OP_RESOLVE) inputs_resolve(b, &r);
    else inputs_scalar(op, b, &r);
}

/* ---- cases ------------------------------------------------------------------------------------- */

/* Measures trig: acos over 2^20 + 1 points of [-1, 1] (and every float within 2^-12 of +-1),
 * atan(q, x) over |q / x| from 2^-40 to 2^40, both signs of x. */
static void measure_trig(tl_gl_fixture *f)
{
    fbuf in = {0};
    tl_rng r = {0x7516u};
    for (int i = 0; i <= (1 << 20); i++) {
        float y = (float)(2.0 * i / (1 << 20) - 1.0), q = (float)exp2(60.0 * tl_rng_unit(&r) - 30.0);
        push(&in, y);
        push(&in, q);
        push(&in, (float)(exp2(20.0 * tl_rng_unit(&r) - 10.0) * (i % 2 ? -1.0 : 1.0)));
    }
    for (float y = 1.0f; y > 1.0f - 0x1.0p-12f; y = nextafterf(y, 0.0f)) {
        float pair[2] = {y, -y};
        for (int k = 0; k < 2; k++) {
            push(&in, pair[k]);
            push(&in, 1.0f);
            push(&in, 1.0f);
        }
    }
    size_t count = in.n / 3;
    float *out = malloc(count * 2 * sizeof *out);
    if (!out) abort();
    trig = (trig_errors){0.0, 0.0};
    if (run_op(f, OP_TRIG, in.v, count, out))
        for (size_t i = 0; i < count; i++) {
            const float *x = in.v + 3 * i;
            trig.acos = fmax(trig.acos, fabs(out[2 * i] - acos(x[0])));
            trig.atan = fmax(trig.atan, fabs(out[2 * i + 1] - atan2(x[1], x[2])));
        }
    printf("  GLSL built-ins on this implementation: acos max error %.3g rad, atan %.3g rad (%zu inputs)\n", trig.acos,
           trig.atan, count);
    free(out);
    free(in.v);
}

static void check_op(int op)
{
    tl_gl_fixture f;
    if (!tl_gl_fixture_open(&f, 16)) return;
    if (op == OP_SPHERE_IRR || op == OP_GGX_TERMS) measure_trig(&f);
    fbuf in = {0};
    make_inputs(op, &in);
    size_t count = in.n / op_in[op];
    float *out = malloc(count * op_out[op] * sizeof *out);
    if (!out) abort();
    if (run_op(&f, op, in.v, count, out)) {
        op_result r = compare(op, in.v, out, count);
        TL_CHECK_EQ_U(r.bad, 0);
        TL_CHECK_EQ_U(r.nonfinite, 0);
    }
    free(out);
    free(in.v);
    tl_gl_fixture_close(&f);
}

TL_TEST(glsl_lighting_ggx_d_matches_reference) { check_op(OP_GGX_D); }
TL_TEST(glsl_lighting_ggx_vis_matches_reference) { check_op(OP_GGX_VIS); }
TL_TEST(glsl_lighting_fresnel_matches_reference) { check_op(OP_FRESNEL); }
TL_TEST(glsl_lighting_sphere_irradiance_matches_reference) { check_op(OP_SPHERE_IRR); }
TL_TEST(glsl_lighting_sphere_specular_dir_matches_reference) { check_op(OP_SPHERE_DIR); }
TL_TEST(glsl_lighting_sphere_normalization_matches_reference) { check_op(OP_SPHERE_NORM); }
TL_TEST(glsl_lighting_ggx_terms_match_reference) { check_op(OP_GGX_TERMS); }
TL_TEST(glsl_lighting_blinn_phong_terms_match_reference) { check_op(OP_BP_TERMS); }
TL_TEST(glsl_lighting_specular_resolve_matches_reference) { check_op(OP_RESOLVE); }

/* The GGX gloss mapping is codec: GLSL must give the C function's bits. */
TL_TEST(glsl_lighting_gloss_to_ggx_alpha_bit_exact)
{
    tl_gl_fixture f;
    if (!tl_gl_fixture_open(&f, 16)) return;
    fbuf in = {0};
    for (uint32_t k = 0; k <= 1023; k++) push(&in, (float)k / 1023.0f);
    tl_rng r = {0xA1FAu};
    for (int i = 0; i < RANDOM_ITEMS; i++) push(&in, uni(&r, -0.25, 1.25));
    const float special[] = {0.0f, -0.0f, 1.0f, NAN, -NAN, INFINITY, -INFINITY, FLT_MIN, 0x1.0p-149f, 0.91161165f,
                             nextafterf(1.0f, 0.0f)};
    for (size_t i = 0; i < sizeof special / sizeof special[0]; i++) push(&in, special[i]);
    float *out = malloc(in.n * sizeof *out);
    if (!out) abort();
    size_t differ = 0;
    if (run_op(&f, OP_GLOSS_ALPHA, in.v, in.n, out))
        for (size_t i = 0; i < in.n; i++) {
            float c = tl_gloss_to_ggx_alpha(in.v[i]);
            if (memcmp(&c, &out[i], 4) != 0 && differ++ < 4)
                fprintf(stderr, "  gloss %a: C %a GLSL %a\n", (double)in.v[i], (double)c, (double)out[i]);
        }
    printf("  %zu glosses: %zu differ from C in any bit\n", in.n, differ);
    TL_CHECK_EQ_U(differ, 0);
    free(out);
    free(in.v);
    tl_gl_fixture_close(&f);
}

/* docs/stability.md for the GGX model in GLSL: roughness at the floor and 1, n.v and n.l -> 0,
 * a light behind the surface, at the shaded point, a hair from it, source radius 0 and larger than
 * the distance, tiny and huge ranges: finite, non-negative, within the clamp (and the reference's
 * values where the reference is continuous, checked by the cases above). */
TL_TEST(glsl_lighting_ggx_extreme_cases_finite)
{
    const float views[][3] = {{0, 0, 1}, {1, 0, 0}, {0.99999994f, 0, 3e-4f}, {0, -1, 0}, {0.6f, 0, -0.8f}};
    const float offsets[][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {1, 0, 1e-7f}, {0, 0, 0}, {0, 0, 1e-30f},
                                {-1, 0, 1}, {0.3f, 0.4f, 1e-3f}, {100, 0, 1}};
    const float radii[] = {0.0f, 1e-6f, 0.5f, 1.0f, 3.0f, 1e3f}, ranges[] = {1e-3f, 2.0f, 1e6f};
    const float alphas[] = {TL_GGX_MIN_ALPHA, 1.0f, 0.25f};
    fbuf in = {0};
    for (size_t vi = 0; vi < 5; vi++)
        for (size_t oi = 0; oi < 9; oi++)
            for (size_t ri = 0; ri < 6; ri++)
                for (size_t gi = 0; gi < 9; gi++)
                    for (int type = 1; type <= 3; type++) {
                        float x[LIGHT_FLOATS] = {0, 0, -2, 0, 0, 1};
                        memcpy(x + 6, views[vi], sizeof views[vi]);
                        x[9] = alphas[gi / 3];
                        for (int k = 0; k < 3; k++) x[10 + k] = x[k] + offsets[oi][k];
                        x[13] = ranges[gi % 3];
                        x[14] = radii[ri];
                        x[17] = -1.0f;
                        x[18] = 0.95f;
                        x[19] = 0.8f;
                        x[20] = (float)type;
                        for (int k = 0; k < LIGHT_FLOATS; k++) push(&in, x[k]);
                    }
    size_t count = in.n / LIGHT_FLOATS, bad = 0;
    float *out = malloc(count * 3 * sizeof *out);
    tl_gl_fixture f;
    if (out && tl_gl_fixture_open(&f, 16)) {
        if (run_op(&f, OP_GGX_TERMS, in.v, count, out))
            for (size_t i = 0; i < count; i++) {
                const float *t = out + 3 * i;
                int ok = isfinite(t[0]) && isfinite(t[1]) && isfinite(t[2]) && t[0] >= 0.0f && t[1] >= 0.0f &&
                         t[2] >= 0.0f && t[0] <= 4096.0f && t[1] + t[2] <= 4096.0f * (1.0f + 0x1.0p-22f);
                if (!ok && bad++ < 4) fprintf(stderr, "  extreme item %zu: %g %g %g\n", i, t[0], t[1], t[2]);
            }
        tl_gl_fixture_close(&f);
    }
    printf("  %zu extreme GGX light configurations in GLSL: %zu non-finite, negative or over the clamp\n", count, bad);
    TL_CHECK_EQ_U(bad, 0);
    free(out);
    free(in.v);
}
