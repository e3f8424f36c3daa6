/* Frame statistics without waiting: each measured frame's timer and samples-passed queries go into
 * a slot of a small ring with a copy of what reading them needs of the plan, and are read when
 * they are ready, a few frames later; only waiting for the frames (or synchronous statistics)
 * blocks, and a plan may change while frames are in flight. The bytes-moved estimate of
 * docs/bandwidth.md is derived from each pass's declared targets and state, not per pass kind. */
#define _POSIX_C_SOURCE 199309L
#include <string.h>
#include <time.h>

#include "stats.h"

double tl__now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

double tl__thread_cpu_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static void tl__label_queries(const GladGLContext *gl, const GLuint *q, size_t n, const char *label)
{
    for (size_t i = 0; i < n; i++) tl__gl_label(gl, GL_QUERY, q[i], label);
}

void tl__queries_create(tl__device *dev, tl__queries *r, tl__lights *lights)
{
    const GladGLContext *gl = &dev->gl;
    GLint bits = 0;
    gl->GetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &bits);
    r->timestamps = bits > 0;
    r->timestamp_bits = bits;
    r->lights = lights;
    for (int s = 0; s < TL__QUERY_RING; s++) {
        tl__query_slot *q = &r->ring[s];
        if (r->timestamps) gl->CreateQueries(GL_TIMESTAMP, 2 * TL_PLAN_MAX_PASSES, &q->time[0][0]);
        gl->CreateQueries(GL_SAMPLES_PASSED, TL__PASS_MAX_QUERIES * TL_PLAN_MAX_PASSES, &q->samples[0][0]);
        if (r->timestamps) tl__label_queries(gl, &q->time[0][0], 2 * TL_PLAN_MAX_PASSES, "query.pass_time");
        tl__label_queries(gl, &q->samples[0][0], TL__PASS_MAX_QUERIES * TL_PLAN_MAX_PASSES, "query.pass_samples");
    }
}

void tl__queries_destroy(tl__device *dev, tl__queries *r)
{
    const GladGLContext *gl = &dev->gl;
    for (int s = 0; s < TL__QUERY_RING; s++) {
        tl__query_slot *q = &r->ring[s];
        if (q->time[0][0]) gl->DeleteQueries(2 * TL_PLAN_MAX_PASSES, &q->time[0][0]);
        if (q->samples[0][0]) gl->DeleteQueries(TL__PASS_MAX_QUERIES * TL_PLAN_MAX_PASSES, &q->samples[0][0]);
    }
    memset(r->ring, 0, sizeof r->ring);
}

/* ---- bytes moved ----------------------------------------------------------------------------- */

static double tl__bpp(const tl__slot_plan *p, tl_target_set bits)
{
    double b = 0.0;
    for (int t = 0; t < TL_TARGET_COUNT; t++)
        if (bits & TL_TARGET_BIT(t)) b += p->target_bytes_per_pixel[t];
    return b;
}

static uint32_t tl__attribute_bytes(uint32_t attrs)
{
    return ((attrs & TL_ATTRIBUTE_POSITION) ? 12u : 0u) + ((attrs & TL_ATTRIBUTE_NORMAL) ? 12u : 0u) +
           ((attrs & TL_ATTRIBUTE_UV) ? 8u : 0u) + ((attrs & TL_ATTRIBUTE_TANGENT) ? 16u : 0u) + 4u /* object id */;
}

/* Clears (every pixel of each cleared target) + per fragment that passed the depth test: the depth
 * test's read (when depth is not also sampled) and write, the sampled targets (a 5-texel cross for
 * neighbourhood reads), the colour writes (twice when blended: read and write) + vertex fetch
 * (indices drawn x (4 + attribute bytes)) + light instances (52 B each). A compute pass counts
 * no samples: it is taken to read its samples and write its writes once for every pixel (its
 * invocations cover the frame). Texture and constant reads of materials are left out (caches
 * absorb them). */
static double tl__pass_bytes(const tl__slot_plan *p, const tl__pass_decl *d, double frags, size_t indices,
                             size_t instances)
{
    const tl_target_set depth_bit = TL_TARGET_BIT(d->depth_target);
    double pixels = (double)p->width * p->height, depth = p->target_bytes_per_pixel[d->depth_target];
    if (d->compute) frags = pixels;
    double per_frag = tl__bpp(p, d->samples) + 4.0 * tl__bpp(p, d->neighbourhood);
    if (d->state.depth_test && !(d->samples & depth_bit)) per_frag += depth;
    if (d->state.depth_write && (d->writes & depth_bit)) per_frag += depth;
    per_frag += tl__bpp(p, d->writes & ~depth_bit) * (d->state.blend ? 2.0 : 1.0);
    return pixels * tl__bpp(p, d->clears) + frags * per_frag +
           (double)indices * (4.0 + tl__attribute_bytes(p->vertex_attributes)) + (double)instances * sizeof(tl__light_record);
}

/* ---- reading a slot ---------------------------------------------------------------------------- */

static int tl__slot_ready(const tl__device *dev, const tl__queries *r, const tl__query_slot *q)
{
    const GladGLContext *gl = &dev->gl;
    size_t n = q->plan.pass_count;
    if (!n) return 1;
    GLuint a = GL_TRUE, b = GL_TRUE;
    if (r->timestamps) gl->GetQueryObjectuiv(q->time[n - 1][1], GL_QUERY_RESULT_AVAILABLE, &a);
    gl->GetQueryObjectuiv(q->samples[n - 1][0], GL_QUERY_RESULT_AVAILABLE, &b);
    return a && b;
}

static uint64_t tl__pass_queries(const tl__device *dev, const tl__query_slot *q, size_t i, uint64_t *results)
{
    const tl__pass_def *def = q->plan.def[i];
    size_t nq = def && def->query_count ? def->query_count : 1;
    uint64_t sum = 0;
    for (size_t k = 0; k < nq; k++) {
        GLuint64 v = 0;
        dev->gl.GetQueryObjectui64v(q->samples[i][k], GL_QUERY_RESULT, &v);
        results[k] = v;
        sum += v;
    }
    return sum;
}

/* Milliseconds between two timestamp queries. */
static double tl__span_ms(const tl__device *dev, const tl__queries *r, const GLuint q[2])
{
    GLuint64 begin = 0, end = 0;
    dev->gl.GetQueryObjectui64v(q[0], GL_QUERY_RESULT, &begin);
    dev->gl.GetQueryObjectui64v(q[1], GL_QUERY_RESULT, &end);
    GLuint64 mask = r->timestamp_bits >= 64 ? ~(GLuint64)0 : (((GLuint64)1 << r->timestamp_bits) - 1);
    return (double)((end - begin) & mask) * 1e-6;
}

static double tl__pass_ms(const tl__device *dev, const tl__queries *r, const tl__query_slot *q, size_t i)
{
    return r->timestamps ? tl__span_ms(dev, r, q->time[i]) : -1.0;
}

/* Reads a pending slot's results into its record (blocking when they are not ready). */
static void tl__slot_read(tl__device *dev, tl__queries *r, tl__query_slot *q)
{
    tl_frame_stats *st = &q->rec.st;
    const tl__slot_plan *p = &q->plan;
    for (size_t i = 0; i < p->pass_count; i++) {
        const tl__pass_def *def = p->def[i];
        uint64_t results[TL__PASS_MAX_QUERIES] = {0};
        uint64_t frags = tl__pass_queries(dev, q, i, results);
        double ms = tl__pass_ms(dev, r, q, i),
               bytes = tl__pass_bytes(p, &p->decl[i], (double)frags, q->rec.indices[i], q->rec.instances[i]);
        if (def && def->collect) def->collect(results, frags, (uint64_t)p->width * p->height, ms, st);
        if (p->app[i] >= 0) {
            st->app_pass_ms[p->app[i]] = ms;
        } else {
            st->pass_ms[def->id] = ms;
            st->pass_fragments[def->id] = frags;
            st->pass_bytes[def->id] = bytes;
        }
        if (ms > 0.0) st->gpu_ms += ms;
        st->bytes_moved += bytes;
    }
    tl__lights_read_counters(dev, r->lights, p->targets, p->width * p->height, st);
    st->gpu_valid = 1;
    q->pending = 0;
}

/* ---- the ring ---------------------------------------------------------------------------------- */

static void tl__slot_take_plan(tl__query_slot *q, const tl__graph *g)
{
    tl__slot_plan *p = &q->plan;
    const tl_frame_plan *fp = &g->plan.pub;
    p->pass_count = g->pass_count;
    for (size_t i = 0; i < g->pass_count; i++) {
        p->def[i] = g->passes[i].def;
        p->app[i] = (int8_t)g->passes[i].app;
        p->decl[i] = *g->passes[i].decl;
    }
    memcpy(p->target_bytes_per_pixel, fp->target_bytes_per_pixel, sizeof p->target_bytes_per_pixel);
    p->width = fp->width;
    p->height = fp->height;
    p->vertex_attributes = fp->vertex_attributes;
    p->targets = fp->targets;
}

tl__query_slot *tl__queries_slot(tl__device *dev, tl__queries *r, const tl__graph *g, uint64_t frame)
{
    tl__query_slot *q = &r->ring[frame % TL__QUERY_RING];
    if (q->pending) tl__slot_read(dev, r, q); /* a whole ring behind: the oldest frame must be read now */
    tl__slot_take_plan(q, g);
    return q;
}

int tl__queries_newest(tl__device *dev, tl__queries *r, tl_frame_stats *out)
{
    tl__query_slot *best = NULL;
    for (int s = 0; s < TL__QUERY_RING; s++) {
        tl__query_slot *q = &r->ring[s];
        if (q->pending && tl__slot_ready(dev, r, q)) tl__slot_read(dev, r, q);
        if (!q->pending && q->rec.st.gpu_valid && (!best || q->rec.st.frame > best->rec.st.frame)) best = q;
    }
    if (!best) return 0;
    *out = best->rec.st;
    return 1;
}

void tl__queries_drain(tl__device *dev, tl__queries *r)
{
    for (int s = 0; s < TL__QUERY_RING; s++)
        if (r->ring[s].pending) tl__slot_read(dev, r, &r->ring[s]);
}
