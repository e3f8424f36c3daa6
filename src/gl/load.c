/* Loading the GL function table from the current context, error names. */
#include "gl.h"
#include "msg.h"

tl_result tl__gl_load(GladGLContext *gl, GLADuserptrloadfunc load, void *user, char *msg,
                      size_t msg_size)
{
    tl__msg(msg, msg_size, "%s", "");
    if (!gl || !load) {
        tl__msg(msg, msg_size, "tl__gl_load: NULL %s", gl ? "load function" : "context struct");
        return TL_ERROR_INVALID_ARGUMENT;
    }
    int version = gladLoadGLContextUserPtr(gl, load, user);
    if (version == 0) {
        tl__msg(msg, msg_size,
                "could not load OpenGL: glGetString(GL_VERSION) failed (is a context current on "
                "this thread?)");
        return TL_ERROR_GL;
    }
    int major = GLAD_VERSION_MAJOR(version), minor = GLAD_VERSION_MINOR(version);
    if (major < TL__GL_MIN_MAJOR || (major == TL__GL_MIN_MAJOR && minor < TL__GL_MIN_MINOR)) {
        const char *s = (const char *)gl->GetString(GL_VERSION);
        tl__msg(msg, msg_size, "OpenGL %d.%d required, the context offers %d.%d (\"%s\")",
                TL__GL_MIN_MAJOR, TL__GL_MIN_MINOR, major, minor, s ? s : "?");
        return TL_ERROR_UNSUPPORTED;
    }
    return TL_OK;
}

const char *tl__gl_error_string(GLenum error)
{
    switch (error) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    default: return "unknown GL error";
    }
}
