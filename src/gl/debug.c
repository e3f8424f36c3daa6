/* KHR_debug object labels and debug groups, no-ops where the context lacks them. */
#include <string.h>

#include "gl.h"

bool tl__gl_has_debug(const GladGLContext *gl)
{
    return gl && (gl->VERSION_4_3 || gl->KHR_debug) && gl->ObjectLabel && gl->PushDebugGroup &&
           gl->PopDebugGroup;
}

/* Names are clamped to 255 characters without asking the context: 256 is the spec's minimum
 * GL_MAX_LABEL_LENGTH, every driver allows at least that for debug messages, and a query per
 * push would stall threaded drivers every pass of every frame. */
static GLsizei tl__clamped_length(const char *text)
{
    size_t n = strlen(text);
    return (GLsizei)(n > 255 ? 255 : n);
}

void tl__gl_label(const GladGLContext *gl, GLenum identifier, GLuint name, const char *label)
{
    if (!tl__gl_has_debug(gl) || !label || !label[0] || name == 0) return;
    gl->ObjectLabel(identifier, name, tl__clamped_length(label), label);
}

void tl__gl_debug_push(const GladGLContext *gl, const char *name)
{
    if (!tl__gl_has_debug(gl)) return;
    if (!name) name = "";
    gl->PushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0,
                       tl__clamped_length(name), name);
}

void tl__gl_debug_pop(const GladGLContext *gl)
{
    if (!tl__gl_has_debug(gl)) return;
    gl->PopDebugGroup();
}
