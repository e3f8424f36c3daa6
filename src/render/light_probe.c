/* The ALU probe (tl_renderer_light_probe): the light function's cost per pixel-light pair at its
 * floor, timed on the device that renders, for the bench's roofline (docs/bandwidth.md, "Reading
 * the results"). shaders/light_probe.comp.glsl evaluates it for 8 lights held in registers. */
#include <math.h>
#include <string.h>

#include "renderer_internal.h"

#define TL__PROBE_LIGHTS 8
#define TL__PROBE_MIN_MS 4.0      /* the evaluations of a timed dispatch take at least this long */
#define TL__PROBE_MAX_ROUNDS 65536u

/* Up to 8 of the scene's local lights (spread over its list, repeated when fewer; a unit point
 * light when it has none), world space, each with a point inside its range and cone and a normal
 * halfway between the light and the eye (at the origin). */
static uint32_t tl__probe_lights(const tl__lights *ls, tl__light_record rec[TL__PROBE_LIGHTS],
                                 float surface[2 * TL__PROBE_LIGHTS][4])
{
    size_t local[TL__PROBE_LIGHTS], n = 0, total = 0;
    for (size_t i = 0; i < ls->count; i++) total += ls->lights[i].type != TL_LIGHT_DIRECTIONAL;
    for (size_t i = 0, seen = 0; i < ls->count && n < TL__PROBE_LIGHTS; i++) {
        if (ls->lights[i].type == TL_LIGHT_DIRECTIONAL) continue;
        if (seen++ * TL__PROBE_LIGHTS >= n * total) local[n++] = i; /* evenly over the list */
    }
    const tl_light fallback = {.type = TL_LIGHT_POINT, .position = {0.0f, 0.0f, -4.0f}, .radius = 4.0f,
                               .color = {1.0f, 1.0f, 1.0f}};
    for (int k = 0; k < TL__PROBE_LIGHTS; k++) {
        const tl_light *l = n ? &ls->lights[local[(size_t)k % n]] : &fallback;
        tl__light_record_fill(l, NULL, 0.0f, &rec[k]);
        const float *c = rec[k].position_radius, *d = rec[k].direction_cos_outer;
        float r = c[3], off[3] = {0.24f * r, -0.18f * r, 0.2f * r}; /* 0.36 r from a point light */
        if ((int)rec[k].color_type[3] == TL_LIGHT_SPOT)
            for (int a = 0; a < 3; a++) off[a] = 0.4f * r * d[a]; /* on the axis */
        float *p = surface[2 * k], *nn = surface[2 * k + 1], to_l[3], to_e[3];
        for (int a = 0; a < 3; a++) p[a] = c[a] + off[a], to_l[a] = -off[a], to_e[a] = -p[a];
        tl__vec3_normalize(to_l);
        tl__vec3_normalize(to_e);
        for (int a = 0; a < 3; a++) nn[a] = to_l[a] + to_e[a];
        tl__vec3_normalize(nn);
        if (nn[0] == 0.0f && nn[1] == 0.0f && nn[2] == 0.0f) memcpy(nn, to_l, sizeof to_l);
        p[3] = 1.0f;
        nn[3] = 0.5f; /* the gloss the lobe's shape comes from (the shader reads surface[1].w) */
    }
    return n ? (uint32_t)(n < TL__PROBE_LIGHTS ? n : TL__PROBE_LIGHTS) : 1u;
}

/* One dispatch of `rounds`, timed: GPU milliseconds between two timestamp queries (as the frame's
 * passes are timed), unless they saw less than half the wall clock around the dispatch and its
 * glFinish (llvmpipe runs a dispatch at the flush, outside both timestamps): then the wall clock. */
static double tl__probe_time(tl_renderer *r, const GLuint query[2], uint32_t invocations, uint32_t rounds,
                             GLuint program, int *gpu_timed)
{
    const GladGLContext *gl = &r->dev.gl;
    gl->ProgramUniform2ui(program, 0, invocations, rounds);
    gl->Finish();
    double t0 = tl__now_ms();
    if (query[0]) gl->QueryCounter(query[0], GL_TIMESTAMP);
    gl->DispatchCompute((invocations + 63) / 64, 1, 1);
    if (query[0]) gl->QueryCounter(query[1], GL_TIMESTAMP);
    gl->Finish();
    double wall = tl__now_ms() - t0;
    *gpu_timed = 0;
    if (!query[0]) return wall;
    GLuint64 begin = 0, end = 0;
    gl->GetQueryObjectui64v(query[0], GL_QUERY_RESULT, &begin);
    gl->GetQueryObjectui64v(query[1], GL_QUERY_RESULT, &end);
    GLuint64 mask = r->queries.timestamp_bits >= 64 ? ~(GLuint64)0 : (((GLuint64)1 << r->queries.timestamp_bits) - 1);
    double gpu = (double)((end - begin) & mask) * 1e-6;
    *gpu_timed = gpu >= 0.5 * wall;
    return *gpu_timed ? gpu : wall;
}

/* The fastest of three dispatches of `rounds`. */
static double tl__probe_best(tl_renderer *r, const GLuint query[2], uint32_t invocations, uint32_t rounds,
                             GLuint program, int *timed)
{
    double best = INFINITY;
    for (int i = 0; i < 3; i++) {
        int t;
        double ms = tl__probe_time(r, query, invocations, rounds, program, &t);
        if (ms < best) best = ms, *timed = t;
    }
    return best;
}

/* The dispatch without evaluations (0 rounds: the lights loaded, the launch, the wait), then rounds
 * until the evaluations take TL__PROBE_MIN_MS beyond it; their time over their pairs. */
static void tl__probe_run(tl_renderer *r, const GLuint query[2], uint32_t invocations, GLuint program,
                          tl_light_probe_result *out)
{
    int timed;
    tl__probe_time(r, query, invocations, 1, program, &timed); /* compiled at the first dispatch */
    double base = tl__probe_best(r, query, invocations, 0, program, &timed);
    uint32_t rounds = 1;
    double ms = tl__probe_best(r, query, invocations, rounds, program, &timed) - base;
    while (ms < TL__PROBE_MIN_MS && rounds < TL__PROBE_MAX_ROUNDS) {
        double grow = ms > 0.0 ? ceil(1.5 * TL__PROBE_MIN_MS / ms) : 16.0;
        rounds = grow * rounds > TL__PROBE_MAX_ROUNDS ? TL__PROBE_MAX_ROUNDS : (uint32_t)(grow * rounds);
        ms = tl__probe_best(r, query, invocations, rounds, program, &timed) - base;
    }
    out->gpu_timed = timed;
    out->ms = ms;
    out->pairs = (uint64_t)invocations * rounds * TL__PROBE_LIGHTS;
    out->ns_per_pair = ms * 1e6 / (double)out->pairs;
}

tl_result tl_renderer_light_probe(tl_renderer *r, tl_light_probe_result *out)
{
    if (!r || !out) return r ? tl__fail(&r->dev, TL_ERROR_INVALID_ARGUMENT, "renderer: the light probe: NULL output")
                             : TL_ERROR_INVALID_ARGUMENT;
    memset(out, 0, sizeof *out);
    tl_result res = tl__need_context(&r->dev, "tl_renderer_light_probe");
    if (res != TL_OK) return res;
    static const tl__program_src src = {"light.probe", NULL, NULL, "light_probe.comp.glsl"};
    tl__perm key;
    memset(&key, 0, sizeof key);
    if (r->graph.plan.pub.lighting == TL_LIGHTING_GGX) tl__perm_flag(&key, TL__F_GGX);
    GLuint program = 0;
    if ((res = tl__program_get(&r->dev, "light.probe", &src, &key, NULL, &program)) != TL_OK) return res;
    tl__light_record rec[TL__PROBE_LIGHTS];
    float surface[2 * TL__PROBE_LIGHTS][4];
    out->lights = tl__probe_lights(&r->lights, rec, surface);
    const GladGLContext *gl = &r->dev.gl;
    GLuint buffers[3], query[2] = {0, 0};
    gl->CreateBuffers(3, buffers);
    gl->NamedBufferStorage(buffers[0], sizeof rec, rec, 0);
    gl->NamedBufferStorage(buffers[1], sizeof surface, surface, 0);
    gl->NamedBufferStorage(buffers[2], 16, NULL, 0);
    if (r->queries.timestamps) gl->CreateQueries(GL_TIMESTAMP, 2, query);
    tl__state_enter(gl, &r->dev.state, TL__TEXTURE_UNITS_USED);
    tl__state_program(gl, &r->dev.state, program);
    gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, TL__SSBO_LIGHTS, buffers[0]);
    gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, TL__SSBO_FORWARD_INDICES, buffers[1]);
    gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, TL__SSBO_OBJECTS, buffers[2]);
    uint64_t pixels = (uint64_t)r->desc.width * r->desc.height;
    uint32_t invocations = pixels < 4096u ? 4096u : pixels > (1u << 24) ? (1u << 24) : (uint32_t)pixels;
    tl__probe_run(r, query, invocations, program, out);
    tl__state_reset(gl, &r->dev.state, TL__TEXTURE_UNITS_USED, TL__BUFFER_BINDINGS_USED, TL__IMAGE_UNITS_USED);
    if (query[0]) gl->DeleteQueries(2, query);
    gl->DeleteBuffers(3, buffers);
    GLenum e = gl->GetError();
    if (e != GL_NO_ERROR) return tl__fail(&r->dev, TL_ERROR_GL, "renderer: %s in the light probe", tl__gl_error_string(e));
    if (!(out->ns_per_pair > 0.0) || !isfinite(out->ns_per_pair))
        return tl__fail(&r->dev, TL_ERROR_GL, "renderer: the light probe timed %g ms for %llu pairs", out->ms,
                        (unsigned long long)out->pairs);
    return TL_OK;
}
