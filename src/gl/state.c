/* The GL state cache (state.h). */
#include "gl/state.h"

#include <string.h>

void tl__state_enter(const GladGLContext *gl, tl__state *s, GLuint units)
{
    static const GLenum off[] = {GL_COLOR_LOGIC_OP,          GL_POLYGON_OFFSET_FILL,     GL_POLYGON_OFFSET_LINE,
                                 GL_POLYGON_OFFSET_POINT,    GL_RASTERIZER_DISCARD,      GL_PRIMITIVE_RESTART,
                                 GL_PRIMITIVE_RESTART_FIXED_INDEX, GL_SAMPLE_ALPHA_TO_COVERAGE,
                                 GL_SAMPLE_ALPHA_TO_ONE,     GL_SAMPLE_COVERAGE,         GL_SAMPLE_SHADING,
                                 GL_SAMPLE_MASK,             GL_FRAMEBUFFER_SRGB,        GL_POLYGON_SMOOTH,
                                 GL_CLIP_DISTANCE0,          GL_CLIP_DISTANCE1,          GL_CLIP_DISTANCE2,
                                 GL_CLIP_DISTANCE3,          GL_CLIP_DISTANCE4,          GL_CLIP_DISTANCE5,
                                 GL_CLIP_DISTANCE6,          GL_CLIP_DISTANCE7};
    for (size_t i = 0; i < sizeof off / sizeof off[0]; i++) gl->Disable(off[i]);
    gl->Enable(GL_DITHER);
    gl->Enable(GL_MULTISAMPLE);
    gl->FrontFace(GL_CCW);
    gl->DepthRange(0.0, 1.0);
    gl->PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    gl->ProvokingVertex(GL_LAST_VERTEX_CONVENTION);
    gl->StencilMask(0xFFFFFFFFu); /* depth-stencil clears obey it */
    gl->BlendEquation(GL_FUNC_ADD);
    if (units) gl->BindSamplers(0, (GLsizei)units, NULL);
    tl__state_invalidate(s);
}

void tl__state_invalidate(tl__state *s)
{
    int reversed = s->reversed;
    memset(s, 0, sizeof *s);
    s->reversed = reversed;
}

static GLenum tl__depth_func(tl__depth_test t, int reversed)
{
    switch (t) {
    case TL__DEPTH_LESS: return reversed ? GL_GREATER : GL_LESS;
    case TL__DEPTH_EQUAL: return GL_EQUAL;
    case TL__DEPTH_LEQUAL: return reversed ? GL_GEQUAL : GL_LEQUAL;
    case TL__DEPTH_GEQUAL: return reversed ? GL_LEQUAL : GL_GEQUAL;
    case TL__DEPTH_OFF: break;
    }
    return GL_ALWAYS;
}

static void tl__enable(const GladGLContext *gl, GLenum cap, int on)
{
    if (on) gl->Enable(cap);
    else gl->Disable(cap);
}

static void tl__apply_depth(const GladGLContext *gl, const tl__state *s, const tl__pipeline *p, int all)
{
    if (all || (p->depth_test != 0) != (s->p.depth_test != 0)) tl__enable(gl, GL_DEPTH_TEST, p->depth_test != 0);
    if (p->depth_test && (all || p->depth_test != s->p.depth_test))
        gl->DepthFunc(tl__depth_func((tl__depth_test)p->depth_test, s->reversed));
    if (all || p->depth_write != s->p.depth_write) gl->DepthMask(p->depth_write ? GL_TRUE : GL_FALSE);
    if (all || p->depth_clamp != s->p.depth_clamp) tl__enable(gl, GL_DEPTH_CLAMP, p->depth_clamp);
    if (all || p->clip_zero_one != s->p.clip_zero_one)
        gl->ClipControl(GL_LOWER_LEFT, p->clip_zero_one ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
}

static void tl__apply_blend(const GladGLContext *gl, const tl__state *s, const tl__pipeline *p, int all)
{
    if (all || (p->blend != 0) != (s->p.blend != 0)) tl__enable(gl, GL_BLEND, p->blend != 0);
    if (p->blend && (all || p->blend != s->p.blend)) {
        if (p->blend == TL__BLEND_ADD) gl->BlendFunc(GL_ONE, GL_ONE);
        else gl->BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        gl->BlendEquation(GL_FUNC_ADD);
    }
    if (all || p->color_write != s->p.color_write) {
        GLboolean c = p->color_write ? GL_TRUE : GL_FALSE;
        gl->ColorMask(c, c, c, c);
    }
}

void tl__state_cull(const GladGLContext *gl, tl__state *s, tl__cull cull)
{
    if (s->known && cull == s->p.cull) return;
    tl__enable(gl, GL_CULL_FACE, cull != TL__CULL_OFF);
    if (cull != TL__CULL_OFF && (!s->known || s->p.cull != cull)) gl->CullFace(cull == TL__CULL_FRONT ? GL_FRONT : GL_BACK);
    s->p.cull = (uint8_t)cull;
}

void tl__state_apply(const GladGLContext *gl, tl__state *s, const tl__pipeline *p)
{
    int all = !s->known;
    tl__apply_depth(gl, s, p, all);
    tl__apply_blend(gl, s, p, all);
    if (all) {
        gl->Disable(GL_SCISSOR_TEST);
        gl->Disable(GL_STENCIL_TEST);
    }
    tl__state_cull(gl, s, (tl__cull)p->cull);
    s->p = *p;
    if (all) { /* bindings are unknown too */
        s->program = s->vertex_array = s->framebuffer = (GLuint)-1;
        s->viewport[2] = -1;
    }
    s->known = 1;
}

void tl__state_program(const GladGLContext *gl, tl__state *s, GLuint program)
{
    if (s->known && s->program == program) return;
    gl->UseProgram(program);
    s->program = program;
}

void tl__state_vertex_array(const GladGLContext *gl, tl__state *s, GLuint vao)
{
    if (s->known && s->vertex_array == vao) return;
    gl->BindVertexArray(vao);
    s->vertex_array = vao;
}

void tl__state_framebuffer(const GladGLContext *gl, tl__state *s, GLuint fbo)
{
    if (s->known && s->framebuffer == fbo) return;
    gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
    s->framebuffer = fbo;
}

void tl__state_viewport(const GladGLContext *gl, tl__state *s, GLint x, GLint y, GLsizei w, GLsizei h)
{
    if (s->known && s->viewport[0] == x && s->viewport[1] == y && s->viewport[2] == w && s->viewport[3] == h) return;
    gl->Viewport(x, y, w, h);
    s->viewport[0] = x;
    s->viewport[1] = y;
    s->viewport[2] = w;
    s->viewport[3] = h;
}

void tl__state_reset(const GladGLContext *gl, tl__state *s, GLuint units, GLuint buffers, GLuint images)
{
    if (images) gl->BindImageTextures(0, (GLsizei)images, NULL);
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl->UseProgram(0);
    gl->BindVertexArray(0);
    if (units) {
        gl->BindTextures(0, (GLsizei)units, NULL);
        gl->BindSamplers(0, (GLsizei)units, NULL);
    }
    if (buffers) {
        gl->BindBuffersBase(GL_UNIFORM_BUFFER, 0, (GLsizei)buffers, NULL);
        gl->BindBuffersBase(GL_SHADER_STORAGE_BUFFER, 0, (GLsizei)buffers, NULL);
    }
    gl->BindBuffer(GL_UNIFORM_BUFFER, 0); /* the generic bindings too (BindBufferRange set them) */
    gl->BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    const GLenum caps[] = {GL_BLEND, GL_DEPTH_TEST, GL_CULL_FACE, GL_DEPTH_CLAMP, GL_SCISSOR_TEST, GL_STENCIL_TEST};
    for (size_t i = 0; i < sizeof caps / sizeof caps[0]; i++) gl->Disable(caps[i]);
    gl->DepthMask(GL_TRUE);
    gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl->ClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    tl__state_invalidate(s);
}

static const GLenum tl__pack_names[2][8] = {
    {GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST, GL_PACK_ROW_LENGTH, GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_ROWS,
     GL_PACK_SKIP_PIXELS, GL_PACK_SKIP_IMAGES, GL_PACK_ALIGNMENT},
    {GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_ROW_LENGTH, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_ROWS,
     GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_IMAGES, GL_UNPACK_ALIGNMENT}};

void tl__pixel_store_enter(const GladGLContext *gl, int unpack, tl__pixel_store *saved)
{
    unpack = unpack != 0;
    saved->unpack = unpack;
    for (int i = 0; i < 8; i++) {
        saved->values[i] = 0;
        gl->GetIntegerv(tl__pack_names[unpack][i], &saved->values[i]);
        gl->PixelStorei(tl__pack_names[unpack][i], i == 7 ? 1 : 0);
    }
    saved->buffer = 0;
    gl->GetIntegerv(unpack ? GL_PIXEL_UNPACK_BUFFER_BINDING : GL_PIXEL_PACK_BUFFER_BINDING, &saved->buffer);
    if (saved->buffer) gl->BindBuffer(unpack ? GL_PIXEL_UNPACK_BUFFER : GL_PIXEL_PACK_BUFFER, 0);
}

void tl__pixel_store_leave(const GladGLContext *gl, const tl__pixel_store *saved)
{
    for (int i = 0; i < 8; i++) gl->PixelStorei(tl__pack_names[saved->unpack][i], saved->values[i]);
    if (saved->buffer)
        gl->BindBuffer(saved->unpack ? GL_PIXEL_UNPACK_BUFFER : GL_PIXEL_PACK_BUFFER, (GLuint)saved->buffer);
}
