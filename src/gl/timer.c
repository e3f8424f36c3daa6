/* GPU timer queries that degrade to "no timing" when the context has no timer bits. */
#include <string.h>

#include "gl.h"

tl_result tl__timer_create(const GladGLContext *gl, const char *label, tl__timer *out)
{
    if (out) memset(out, 0, sizeof *out);
    if (!gl || !out) return TL_ERROR_INVALID_ARGUMENT;
    GLint timestamp_bits = 0, elapsed_bits = 0;
    gl->GetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &timestamp_bits);
    gl->GetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &elapsed_bits);
    GLenum target;
    if (timestamp_bits > 0) {
        out->mode = TL__TIMER_TIMESTAMP;
        out->bits = timestamp_bits;
        target = GL_TIMESTAMP;
    } else if (elapsed_bits > 0) {
        out->mode = TL__TIMER_ELAPSED;
        out->bits = elapsed_bits;
        target = GL_TIME_ELAPSED;
    } else {
        return TL_OK; /* TL__TIMER_NONE */
    }
    GLsizei n = out->mode == TL__TIMER_TIMESTAMP ? 2 : 1;
    gl->CreateQueries(target, n, out->queries);
    if (!out->queries[0] || (n == 2 && !out->queries[1])) {
        gl->DeleteQueries(2, out->queries);
        memset(out, 0, sizeof *out);
        return TL_ERROR_GL;
    }
    for (GLsizei i = 0; i < n; i++) tl__gl_label(gl, GL_QUERY, out->queries[i], label);
    return TL_OK;
}

void tl__timer_begin(const GladGLContext *gl, tl__timer *t)
{
    if (!gl || !t || t->mode == TL__TIMER_NONE || t->state == 1) return;
    if (t->mode == TL__TIMER_TIMESTAMP)
        gl->QueryCounter(t->queries[0], GL_TIMESTAMP);
    else
        gl->BeginQuery(GL_TIME_ELAPSED, t->queries[0]);
    t->state = 1;
}

void tl__timer_end(const GladGLContext *gl, tl__timer *t)
{
    if (!gl || !t || t->mode == TL__TIMER_NONE || t->state != 1) return;
    if (t->mode == TL__TIMER_TIMESTAMP)
        gl->QueryCounter(t->queries[1], GL_TIMESTAMP);
    else
        gl->EndQuery(GL_TIME_ELAPSED);
    t->state = 2;
}

tl_result tl__timer_read(const GladGLContext *gl, tl__timer *t, bool wait, bool *out_ready,
                         uint64_t *out_ns)
{
    if (out_ready) *out_ready = false;
    if (out_ns) *out_ns = 0;
    if (!gl || !t) return TL_ERROR_INVALID_ARGUMENT;
    if (t->mode == TL__TIMER_NONE) return TL_ERROR_UNSUPPORTED;
    if (t->state != 2) return TL_ERROR_INVALID_ARGUMENT;
    GLuint last = t->mode == TL__TIMER_TIMESTAMP ? t->queries[1] : t->queries[0];
    if (!wait) {
        GLuint available = GL_FALSE;
        gl->GetQueryObjectuiv(last, GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) return TL_OK;
    }
    GLuint64 ns = 0;
    if (t->mode == TL__TIMER_TIMESTAMP) {
        GLuint64 begin = 0, end = 0;
        gl->GetQueryObjectui64v(t->queries[0], GL_QUERY_RESULT, &begin);
        gl->GetQueryObjectui64v(t->queries[1], GL_QUERY_RESULT, &end);
        /* Counters narrower than 64 bits wrap; the difference modulo 2^bits is still right. */
        GLuint64 mask = t->bits >= 64 ? ~(GLuint64)0 : (((GLuint64)1 << t->bits) - 1);
        ns = (end - begin) & mask;
    } else {
        gl->GetQueryObjectui64v(t->queries[0], GL_QUERY_RESULT, &ns);
    }
    if (out_ready) *out_ready = true;
    if (out_ns) *out_ns = (uint64_t)ns;
    return TL_OK;
}

void tl__timer_destroy(const GladGLContext *gl, tl__timer *t)
{
    if (!t) return;
    if (gl && t->mode != TL__TIMER_NONE) {
        if (t->state == 1 && t->mode == TL__TIMER_ELAPSED) gl->EndQuery(GL_TIME_ELAPSED);
        gl->DeleteQueries(t->mode == TL__TIMER_TIMESTAMP ? 2 : 1, t->queries);
    }
    memset(t, 0, sizeof *t);
}
