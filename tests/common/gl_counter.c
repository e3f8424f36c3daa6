/* The GL call counter (gl_counter.h). */
#include "gl_counter.h"

#include <stdio.h>
#include <string.h>

#include <glad/gl.h>

#include "thinlight/context.h"
#include "tl_test.h"

static unsigned long g_uploads;
static unsigned long long g_upload_bytes;

/* A buffer call that sends `size` bytes when `sends` (storage or data without contents sends none). */
static void tl_test_gl_upload(int sends, GLsizeiptr size)
{
    if (!sends) return;
    g_uploads++;
    g_upload_bytes += (unsigned long long)size;
}

/* A wrapped entry point: where the real one goes, the thunk handed out instead, and its count. */
#define TL_COUNTED(ret, name, params, args)                                                        \
    static ret(GLAD_API_PTR *real_##name) params;                                                  \
    static unsigned long n_##name;                                                                 \
    static ret GLAD_API_PTR count_##name params                                                    \
    {                                                                                              \
        n_##name++;                                                                                \
        return real_##name args;                                                                   \
    }
/* The same for a void entry point; `upload` runs before the real call. */
#define TL_COUNTED_VOID(name, params, args, upload)                                                \
    static void(GLAD_API_PTR *real_##name) params;                                                 \
    static unsigned long n_##name;                                                                 \
    static void GLAD_API_PTR count_##name params                                                   \
    {                                                                                              \
        n_##name++;                                                                                \
        upload;                                                                                    \
        real_##name args;                                                                          \
    }

TL_COUNTED(GLint, GetUniformLocation, (GLuint p, const GLchar *n), (p, n))
TL_COUNTED(GLenum, GetError, (void), ())
TL_COUNTED(GLboolean, IsVertexArray, (GLuint a), (a))
TL_COUNTED(GLboolean, IsFramebuffer, (GLuint f), (f))
TL_COUNTED(GLenum, CheckNamedFramebufferStatus, (GLuint f, GLenum t), (f, t))
TL_COUNTED_VOID(GetNamedFramebufferAttachmentParameteriv, (GLuint f, GLenum a, GLenum p, GLint *v), (f, a, p, v), )
TL_COUNTED_VOID(GetFramebufferAttachmentParameteriv, (GLenum t, GLenum a, GLenum p, GLint *v), (t, a, p, v), )
TL_COUNTED_VOID(Finish, (void), (), )
TL_COUNTED_VOID(CompileShader, (GLuint s), (s), )
TL_COUNTED_VOID(LinkProgram, (GLuint p), (p), )
TL_COUNTED_VOID(GetIntegerv, (GLenum e, GLint *v), (e, v), )
TL_COUNTED_VOID(GetQueryObjectuiv, (GLuint q, GLenum e, GLuint *v), (q, e, v), )
TL_COUNTED_VOID(GetQueryObjectui64v, (GLuint q, GLenum e, GLuint64 *v), (q, e, v), )
TL_COUNTED_VOID(ProgramUniform1i, (GLuint p, GLint l, GLint v), (p, l, v), )
TL_COUNTED_VOID(ProgramUniform1f, (GLuint p, GLint l, GLfloat v), (p, l, v), )
TL_COUNTED_VOID(ProgramUniformMatrix4fv, (GLuint p, GLint l, GLsizei c, GLboolean t, const GLfloat *v),
                (p, l, c, t, v), )
TL_COUNTED_VOID(Uniform1i, (GLint l, GLint v), (l, v), )
TL_COUNTED_VOID(DrawElementsInstancedBaseInstance, (GLenum m, GLsizei c, GLenum t, const void *i, GLsizei n, GLuint b),
                (m, c, t, i, n, b), )
TL_COUNTED_VOID(DispatchCompute, (GLuint x, GLuint y, GLuint z), (x, y, z), )
TL_COUNTED_VOID(DispatchComputeIndirect, (GLintptr o), (o), )
TL_COUNTED_VOID(TextureSubImage2D,
                (GLuint t, GLint l, GLint x, GLint y, GLsizei w, GLsizei h, GLenum f, GLenum ty, const void *p),
                (t, l, x, y, w, h, f, ty, p), )
TL_COUNTED_VOID(GenerateTextureMipmap, (GLuint t), (t), )
TL_COUNTED_VOID(NamedBufferStorage, (GLuint b, GLsizeiptr s, const void *d, GLbitfield f), (b, s, d, f),
                tl_test_gl_upload(d != NULL, s))
TL_COUNTED_VOID(NamedBufferData, (GLuint b, GLsizeiptr s, const void *d, GLenum u), (b, s, d, u),
                tl_test_gl_upload(d != NULL, s))
TL_COUNTED_VOID(NamedBufferSubData, (GLuint b, GLintptr o, GLsizeiptr s, const void *d), (b, o, s, d),
                tl_test_gl_upload(1, s))
TL_COUNTED_VOID(BufferSubData, (GLenum t, GLintptr o, GLsizeiptr s, const void *d), (t, o, s, d),
                tl_test_gl_upload(1, s))

typedef struct tl_counted {
    const char *name;
    void *real_slot; /* the variable the real entry point goes into */
    tl_gl_function thunk;
    unsigned long *count;
} tl_counted;

#define TL_ENTRY(name) {"gl" #name, (void *)&real_##name, (tl_gl_function)count_##name, &n_##name}
static const tl_counted g_counted[] = {
    TL_ENTRY(GetUniformLocation), TL_ENTRY(GetError), TL_ENTRY(IsVertexArray), TL_ENTRY(IsFramebuffer),
    TL_ENTRY(CheckNamedFramebufferStatus), TL_ENTRY(GetNamedFramebufferAttachmentParameteriv),
    TL_ENTRY(GetFramebufferAttachmentParameteriv), TL_ENTRY(Finish), TL_ENTRY(CompileShader), TL_ENTRY(LinkProgram),
    TL_ENTRY(GetIntegerv), TL_ENTRY(GetQueryObjectuiv), TL_ENTRY(GetQueryObjectui64v), TL_ENTRY(ProgramUniform1i),
    TL_ENTRY(ProgramUniform1f), TL_ENTRY(ProgramUniformMatrix4fv), TL_ENTRY(Uniform1i),
    TL_ENTRY(DrawElementsInstancedBaseInstance), TL_ENTRY(DispatchCompute), TL_ENTRY(DispatchComputeIndirect),
    TL_ENTRY(TextureSubImage2D), TL_ENTRY(GenerateTextureMipmap),
    TL_ENTRY(NamedBufferStorage), TL_ENTRY(NamedBufferData), TL_ENTRY(NamedBufferSubData), TL_ENTRY(BufferSubData),
};
#define TL_COUNTED_N (sizeof g_counted / sizeof g_counted[0])

tl_gl_function tl_test_gl_counting_loader(void *ctx, const char *name)
{
    tl_gl_function real = tl_context_proc_loader(ctx, name);
    for (size_t i = 0; real && i < TL_COUNTED_N; i++)
        if (strcmp(name, g_counted[i].name) == 0) {
            memcpy(g_counted[i].real_slot, &real, sizeof real); /* same representation for every function pointer */
            return g_counted[i].thunk;
        }
    return real;
}

void tl_test_gl_counts_reset(void)
{
    for (size_t i = 0; i < TL_COUNTED_N; i++) *g_counted[i].count = 0;
    g_uploads = 0;
    g_upload_bytes = 0;
}

unsigned long tl_test_gl_calls(const char *name)
{
    for (size_t i = 0; i < TL_COUNTED_N; i++)
        if (strcmp(name, g_counted[i].name) == 0) return *g_counted[i].count;
    fprintf(stderr, "gl_counter: %s is not counted (gl_counter.c lists what is)\n", name);
    tl_test_failures++;
    return 0;
}

unsigned long tl_test_gl_uploads(void) { return g_uploads; }

unsigned long long tl_test_gl_upload_bytes(void) { return g_upload_bytes; }

void tl_test_gl_counts_print(const char *label)
{
    printf("%s:", label);
    for (size_t i = 0; i < TL_COUNTED_N; i++)
        if (*g_counted[i].count) printf(" %s %lu", g_counted[i].name + 2, *g_counted[i].count);
    printf("\n");
}
