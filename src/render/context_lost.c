/* A renderer whose own tl_context was destroyed before it (context_check.c) still frees its memory
 * in tl_renderer_destroy: the modules' release steps run as always over a GL table whose deletions
 * do nothing (the objects went with the context) and whose other entries are NULL, so no module
 * needs a second, memory-only release, and a release step that starts calling anything else shows
 * up at once in the test that destroys the context first. */
#include <string.h>

#include "device.h"

static void GLAD_API_PTR tl__lost_names(GLsizei n, const GLuint *names)
{
    (void)n;
    (void)names;
}
static void GLAD_API_PTR tl__lost_sync(GLsync sync) { (void)sync; }
static void GLAD_API_PTR tl__lost_program(GLuint program) { (void)program; }
static void GLAD_API_PTR tl__lost_end_query(GLenum target) { (void)target; }

void tl__device_lose(tl__device *dev)
{
    GladGLContext *gl = &dev->gl;
    memset(gl, 0, sizeof *gl);
    gl->DeleteBuffers = gl->DeleteFramebuffers = gl->DeleteQueries = gl->DeleteSamplers = gl->DeleteTextures =
        gl->DeleteVertexArrays = tl__lost_names;
    gl->DeleteSync = tl__lost_sync;
    gl->DeleteProgram = tl__lost_program;
    gl->EndQuery = tl__lost_end_query;
}
