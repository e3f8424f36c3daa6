/* GL foundation on OSMesa: context, loader, embedded programs, targets, readback, timers. */
#include <stdint.h>
#include <string.h>

#include "gl/gl.h"
#include "thinlight/context.h"
#include "gl_fixture.h"
#include "tl_test.h"

typedef tl_gl_fixture gl_env;

static bool gl_open(gl_env *env) { return tl_gl_fixture_open(env, 64); }
static void gl_close(gl_env *env) { tl_gl_fixture_close(env); }

TL_TEST(gl_context_osmesa_core45)
{
    gl_env env;
    if (!gl_open(&env)) return;
    const GladGLContext *gl = &env.gl;
    tl_context_backend expected = TL_CONTEXT_BACKEND_DEFAULT;
    TL_CHECK(tl_test_context_backend(&expected));
    if (expected == TL_CONTEXT_BACKEND_DEFAULT) expected = TL_CONTEXT_BACKEND_OSMESA;
    if (expected != TL_CONTEXT_BACKEND_AUTO) TL_CHECK(tl_context_get_backend(env.ctx) == expected);
    GLint major = 0, minor = 0, mask = 0, max_tex = 0, max_rb = 0, max_draw = 0;
    gl->GetIntegerv(GL_MAJOR_VERSION, &major);
    gl->GetIntegerv(GL_MINOR_VERSION, &minor);
    gl->GetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
    gl->GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_tex);
    gl->GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_rb);
    gl->GetIntegerv(GL_MAX_DRAW_BUFFERS, &max_draw);
    TL_CHECK(major > 4 || (major == 4 && minor >= 5));
    TL_CHECK(gl->VERSION_4_5);
    TL_CHECK(mask & GL_CONTEXT_CORE_PROFILE_BIT);
    TL_CHECK(tl__gl_has_debug(gl));
    int cmaj = 0, cmin = 0;
    tl_context_gl_version(env.ctx, &cmaj, &cmin);
    TL_CHECK(cmaj == major && cmin == minor);
    TL_CHECK(strlen(tl_context_renderer_string(env.ctx)) > 0);
    TL_CHECK(strcmp(tl_context_version_string(env.ctx), (const char *)gl->GetString(GL_VERSION)) == 0);
    TL_CHECK(tl_context_swap(env.ctx) == TL_OK);
    TL_CHECK(tl_context_make_current(NULL) == TL_OK);
    TL_CHECK(tl_context_make_current(env.ctx) == TL_OK);
    uint32_t w = 0, h = 0;
    tl_context_get_size(env.ctx, &w, &h);
    TL_CHECK(w == 64 && h == 64);
    GLint ts_bits = -1, el_bits = -1;
    gl->GetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &ts_bits);
    gl->GetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &el_bits);
    printf("GL_RENDERER %s\nGL_VERSION %s\nGL_SHADING_LANGUAGE_VERSION %s\n",
           tl_context_renderer_string(env.ctx), tl_context_version_string(env.ctx),
           (const char *)gl->GetString(GL_SHADING_LANGUAGE_VERSION));
    printf("GL_MAX_TEXTURE_SIZE %d GL_MAX_RENDERBUFFER_SIZE %d GL_MAX_DRAW_BUFFERS %d\n",
           (int)max_tex, (int)max_rb, (int)max_draw);
    printf("timer bits: GL_TIMESTAMP %d GL_TIME_ELAPSED %d\n", (int)ts_bits, (int)el_bits);
    gl_close(&env);
}

static const char *const constant_defines[] = {
    "TL_CONSTANT_COLOR=vec4(0.25, -2.0, 1048576.0, 0.0078125)",
    "TL_FULLSCREEN_DEPTH 0.5",
};

TL_TEST(gl_program_embedded_include)
{
    TL_CHECK(tl__shader_source("fullscreen.vert.glsl") != NULL);
    TL_CHECK(tl__shader_source("fullscreen.glsl") != NULL);
    TL_CHECK(tl__shader_source("no_such_file.glsl") == NULL);
    TL_CHECK(tl__shader_source(NULL) == NULL);
    gl_env env;
    if (!gl_open(&env)) return;
    const GladGLContext *gl = &env.gl;
    char log[4096];

    /* Uniform permutation: fullscreen.vert.glsl #includes fullscreen.glsl. */
    GLuint prog = 0;
    tl_result r = tl__program_build(
        gl,
        &(tl__program_desc){.label = "test.constant_uniform",
                            .stages = {{GL_VERTEX_SHADER, "fullscreen.vert.glsl", NULL},
                                       {GL_FRAGMENT_SHADER, "constant_color.frag.glsl", NULL}}},
        &prog, log, sizeof log);
    if (r != TL_OK) fprintf(stderr, "%s\n", log);
    TL_CHECK(r == TL_OK && prog != 0);
    TL_CHECK(gl->GetUniformLocation(prog, "u_color") >= 0);
    gl->DeleteProgram(prog);

    /* Define permutation: the uniform is compiled out. */
    r = tl__program_build(
        gl,
        &(tl__program_desc){.label = "test.constant_define",
                            .stages = {{GL_VERTEX_SHADER, "fullscreen.vert.glsl", NULL},
                                       {GL_FRAGMENT_SHADER, "constant_color.frag.glsl", NULL}},
                            .defines = constant_defines,
                            .define_count = 2},
        &prog, log, sizeof log);
    if (r != TL_OK) fprintf(stderr, "%s\n", log);
    TL_CHECK(r == TL_OK && prog != 0);
    TL_CHECK(gl->GetUniformLocation(prog, "u_color") == -1);
    char label[64] = "";
    GLsizei n = 0;
    gl->GetObjectLabel(GL_PROGRAM, prog, sizeof label, &n, label);
    TL_CHECK(strcmp(label, "test.constant_define") == 0);
    gl->DeleteProgram(prog);

    /* A compile error in an inline stage that includes an embedded file: result, log, no program,
     * and the line number refers to the stage's own line (after the include). */
    r = tl__program_build(
        gl,
        &(tl__program_desc){
            .label = "test.broken",
            .stages = {{GL_VERTEX_SHADER, "fullscreen.vert.glsl", NULL},
                       {GL_FRAGMENT_SHADER, "broken.frag",
                        "#include \"fullscreen.glsl\" // helper\n"
                        "out vec4 o;\n"
                        "void main() { o = vec4(undefined_symbol_xyz); }\n"}}},
        &prog, log, sizeof log);
    printf("compile error log:\n%s\n", log);
    TL_CHECK(r == TL_ERROR_GL);
    TL_CHECK(prog == 0);
    TL_CHECK(strstr(log, "broken.frag") != NULL);
    TL_CHECK(strstr(log, "undefined_symbol_xyz") != NULL);
    TL_CHECK(strstr(log, "0:3(") != NULL); /* Mesa writes "0:3(NN): error: ..." */

    /* An error inside the included file is reported against its source-string number. */
    r = tl__program_build(
        gl,
        &(tl__program_desc){
            .stages = {{GL_VERTEX_SHADER, "inline.vert",
                        "#define tl_fullscreen_position(i) broken_in_include\n"
                        "#include \"fullscreen.glsl\"\n"
                        "void main() { gl_Position = vec4(0.0); }\n"}}},
        &prog, log, sizeof log);
    printf("include error log:\n%s\n", log);
    TL_CHECK(r == TL_ERROR_GL);
    TL_CHECK(strstr(log, "= fullscreen.glsl") != NULL);

    /* Missing include, malformed include, unknown stage file, bad define. */
    r = tl__program_build(gl,
                          &(tl__program_desc){.stages = {{GL_FRAGMENT_SHADER, "x.frag",
                                                          "\n#include \"codec_missing.glsl\"\n"}}},
                          &prog, log, sizeof log);
    TL_CHECK(r == TL_ERROR_PARSE);
    TL_CHECK(strstr(log, "x.frag:2") != NULL && strstr(log, "codec_missing.glsl") != NULL);
    r = tl__program_build(
        gl, &(tl__program_desc){.stages = {{GL_FRAGMENT_SHADER, "y.frag", "#include <a.glsl>\n"}}},
        &prog, log, sizeof log);
    TL_CHECK(r == TL_ERROR_PARSE);
    r = tl__program_build(gl,
                          &(tl__program_desc){.stages = {{GL_FRAGMENT_SHADER, "nope.frag.glsl", NULL}}},
                          &prog, log, sizeof log);
    TL_CHECK(r == TL_ERROR_INVALID_ARGUMENT);
    static const char *const bad_define[] = {"1BAD=2"};
    r = tl__program_build(gl,
                          &(tl__program_desc){.stages = {{GL_VERTEX_SHADER, "fullscreen.vert.glsl", NULL}},
                                              .defines = bad_define,
                                              .define_count = 1},
                          &prog, log, sizeof log);
    TL_CHECK(r == TL_ERROR_INVALID_ARGUMENT);
    r = tl__program_build(gl, &(tl__program_desc){0}, &prog, log, sizeof log);
    TL_CHECK(r == TL_ERROR_INVALID_ARGUMENT);
    /* A NULL log is allowed. */
    r = tl__program_build(gl, &(tl__program_desc){0}, &prog, NULL, 0);
    TL_CHECK(r == TL_ERROR_INVALID_ARGUMENT);
    gl_close(&env);
}

TL_TEST(gl_render_target_bytes)
{
    TL_CHECK_EQ_U(tl__format_bytes_per_pixel(GL_RGBA16F), 8);
    TL_CHECK_EQ_U(tl__format_bytes_per_pixel(GL_DEPTH24_STENCIL8), 4);
    TL_CHECK_EQ_U(tl__format_bytes_per_pixel(GL_RGB10_A2), 4);
    TL_CHECK_EQ_U(tl__format_bytes_per_pixel(GL_RGBA32F), 16);
    TL_CHECK_EQ_U(tl__format_bytes_per_pixel(GL_RGBA8), 4);
    TL_CHECK_EQ_U(tl__format_bytes_per_pixel(GL_RGB), 0);
    gl_env env;
    if (!gl_open(&env)) return;
    const GladGLContext *gl = &env.gl;
    char msg[256];
    static const struct {
        GLenum format;
        const char *label;
        size_t bpp;
    } cases[] = {
        {GL_RGBA16F, "test.light", 8},
        {GL_DEPTH24_STENCIL8, "test.depth", 4},
        {GL_RGB10_A2, "test.rt0", 4},
        {GL_RGBA32F, "test.position", 16},
    };
    tl__target t[4];
    for (size_t i = 0; i < 4; i++) {
        tl_result r = tl__target_create(
            gl, &(tl__target_desc){cases[i].label, cases[i].format, 64, 32, 1}, &t[i], msg, sizeof msg);
        if (r != TL_OK) fprintf(stderr, "%s\n", msg);
        TL_CHECK(r == TL_OK && t[i].texture != 0);
        TL_CHECK_EQ_U(t[i].bytes, (size_t)64 * 32 * cases[i].bpp);
        char label[64] = "";
        gl->GetObjectLabel(GL_TEXTURE, t[i].texture, sizeof label, NULL, label);
        TL_CHECK(strcmp(label, cases[i].label) == 0);
    }
    TL_CHECK_EQ_U(t[0].bytes, 64 * 32 * 8);

    const tl__target *colors[] = {&t[0], &t[2], &t[3]};
    GLuint fbo = 0;
    tl_result r = tl__framebuffer_create(gl, "test.fbo", colors, 3, &t[1], &fbo, msg, sizeof msg);
    if (r != TL_OK) fprintf(stderr, "%s\n", msg);
    TL_CHECK(r == TL_OK && fbo != 0);
    TL_CHECK_EQ_U(gl->CheckNamedFramebufferStatus(fbo, GL_DRAW_FRAMEBUFFER), GL_FRAMEBUFFER_COMPLETE);
    tl__framebuffer_destroy(gl, &fbo);
    TL_CHECK(fbo == 0);
    /* Depth-only framebuffer. */
    r = tl__framebuffer_create(gl, "test.depth_only", NULL, 0, &t[1], &fbo, msg, sizeof msg);
    TL_CHECK(r == TL_OK);
    tl__framebuffer_destroy(gl, &fbo);

    /* Misuse: depth target as a colour, mismatched sizes, unknown format, too large. */
    const tl__target *wrong[] = {&t[1]};
    TL_CHECK(tl__framebuffer_create(gl, "bad", wrong, 1, NULL, &fbo, msg, sizeof msg) ==
             TL_ERROR_INVALID_ARGUMENT);
    tl__target small;
    TL_CHECK(tl__target_create(gl, &(tl__target_desc){"small", GL_RGBA8, 8, 8, 1}, &small, msg,
                               sizeof msg) == TL_OK);
    TL_CHECK_EQ_U(small.bytes, 8 * 8 * 4);
    const tl__target *mixed[] = {&t[0], &small};
    TL_CHECK(tl__framebuffer_create(gl, "bad", mixed, 2, NULL, &fbo, msg, sizeof msg) ==
             TL_ERROR_INVALID_ARGUMENT);
    tl__target bad;
    TL_CHECK(tl__target_create(gl, &(tl__target_desc){"bad", GL_RGB, 8, 8, 1}, &bad, msg, sizeof msg) ==
             TL_ERROR_UNSUPPORTED);
    TL_CHECK(bad.texture == 0);
    GLint max_tex = 0;
    gl->GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_tex);
    TL_CHECK(tl__target_create(gl, &(tl__target_desc){"huge", GL_RGBA8, (uint32_t)max_tex + 1, 1, 1},
                               &bad, msg, sizeof msg) == TL_ERROR_LIMIT);
    printf("too large: %s\n", msg);
    TL_CHECK(tl__target_create(gl, &(tl__target_desc){"empty", GL_RGBA8, 0, 1, 1}, &bad, msg,
                               sizeof msg) == TL_ERROR_INVALID_ARGUMENT);

    tl__target_destroy(gl, &small);
    for (size_t i = 0; i < 4; i++) tl__target_destroy(gl, &t[i]);
    TL_CHECK(t[0].texture == 0 && t[0].bytes == 0);
    gl_close(&env);
}

/* Draws the full-screen triangle with `prog` into a fresh 16x8 RGBA32F target, reads it back. */
static bool draw_fullscreen(const GladGLContext *gl, GLuint prog, float *pixels)
{
    char msg[256];
    tl__target t;
    if (tl__target_create(gl, &(tl__target_desc){"test.readback", GL_RGBA32F, 16, 8, 1}, &t, msg,
                          sizeof msg) != TL_OK) {
        fprintf(stderr, "%s\n", msg);
        return false;
    }
    const tl__target *colors[] = {&t};
    GLuint fbo = 0, vao = 0;
    tl_result r = tl__framebuffer_create(gl, "test.readback", colors, 1, NULL, &fbo, msg, sizeof msg);
    TL_CHECK(r == TL_OK);
    gl->CreateVertexArrays(1, &vao);
    tl__gl_debug_push(gl, "test.fullscreen");
    gl->BindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
    gl->Viewport(0, 0, 16, 8);
    const float clear[4] = {-1.0f, -1.0f, -1.0f, -1.0f};
    gl->ClearNamedFramebufferfv(fbo, GL_COLOR, 0, clear);
    gl->UseProgram(prog);
    gl->BindVertexArray(vao);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    gl->BindVertexArray(0);
    gl->UseProgram(0);
    gl->BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    tl__gl_debug_pop(gl);
    r = tl__target_read(gl, &t, 0, 0, pixels, 16 * 8 * 4 * sizeof(float), msg, sizeof msg);
    TL_CHECK(r == TL_OK);
    /* A buffer that is too small is refused, not overrun. */
    TL_CHECK(tl__target_read(gl, &t, 0, 0, pixels, 16, msg, sizeof msg) == TL_ERROR_LIMIT);
    gl->DeleteVertexArrays(1, &vao);
    tl__framebuffer_destroy(gl, &fbo);
    tl__target_destroy(gl, &t);
    return r == TL_OK;
}

static size_t count_mismatches(const float *pixels, const float expect[4])
{
    size_t bad = 0;
    for (size_t i = 0; i < 16 * 8; i++)
        bad += memcmp(&pixels[i * 4], expect, 4 * sizeof(float)) != 0;
    return bad;
}

TL_TEST(gl_fullscreen_readback)
{
    gl_env env;
    if (!gl_open(&env)) return;
    const GladGLContext *gl = &env.gl;
    char log[4096];
    static float pixels[16 * 8 * 4];

    /* Compile-time constant (define permutation). */
    GLuint prog = 0;
    tl_result r = tl__program_build(
        gl,
        &(tl__program_desc){.label = "test.constant_define",
                            .stages = {{GL_VERTEX_SHADER, "fullscreen.vert.glsl", NULL},
                                       {GL_FRAGMENT_SHADER, "constant_color.frag.glsl", NULL}},
                            .defines = constant_defines,
                            .define_count = 2},
        &prog, log, sizeof log);
    if (r != TL_OK) fprintf(stderr, "%s\n", log);
    TL_CHECK(r == TL_OK);
    if (r == TL_OK && draw_fullscreen(gl, prog, pixels)) {
        const float expect[4] = {0.25f, -2.0f, 1048576.0f, 0.0078125f};
        size_t bad = count_mismatches(pixels, expect);
        if (bad) fprintf(stderr, "first pixel %.9g %.9g %.9g %.9g\n", pixels[0], pixels[1],
                         pixels[2], pixels[3]);
        TL_CHECK_EQ_U(bad, 0);
    }
    gl->DeleteProgram(prog);

    /* Uniform: arbitrary float bits survive the RGBA32F path unchanged. */
    r = tl__program_build(
        gl,
        &(tl__program_desc){.label = "test.constant_uniform",
                            .stages = {{GL_VERTEX_SHADER, "fullscreen.vert.glsl", NULL},
                                       {GL_FRAGMENT_SHADER, "constant_color.frag.glsl", NULL}}},
        &prog, log, sizeof log);
    TL_CHECK(r == TL_OK);
    const float color[4] = {0.1f, -3.5f, 1.0e-20f, 123456.789f};
    gl->ProgramUniform4fv(prog, gl->GetUniformLocation(prog, "u_color"), 1, color);
    if (r == TL_OK && draw_fullscreen(gl, prog, pixels)) {
        size_t bad = count_mismatches(pixels, color);
        if (bad) fprintf(stderr, "first pixel %.9g %.9g %.9g %.9g\n", pixels[0], pixels[1],
                         pixels[2], pixels[3]);
        TL_CHECK_EQ_U(bad, 0);
    }
    gl->DeleteProgram(prog);
    gl_close(&env);
}

TL_TEST(gl_timer_query)
{
    gl_env env;
    if (!gl_open(&env)) return;
    const GladGLContext *gl = &env.gl;

    tl__timer t;
    TL_CHECK(tl__timer_create(gl, "test.timer", &t) == TL_OK);
    printf("timer mode %d, %d bits\n", (int)t.mode, (int)t.bits);
    uint64_t ns = UINT64_MAX;
    bool ready = true;
    TL_CHECK(tl__timer_read(gl, &t, true, &ready, &ns) ==
             (t.mode == TL__TIMER_NONE ? TL_ERROR_UNSUPPORTED : TL_ERROR_INVALID_ARGUMENT));
    TL_CHECK(!ready && ns == 0);

    tl__timer_begin(gl, &t);
    const float c[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    for (int i = 0; i < 16; i++) gl->ClearBufferfv(GL_COLOR, 0, c);
    tl__timer_end(gl, &t);
    tl_result r = tl__timer_read(gl, &t, true, &ready, &ns);
    if (t.mode == TL__TIMER_NONE) {
        TL_CHECK(r == TL_ERROR_UNSUPPORTED && !ready && ns == 0);
        printf("no timer bits: timing unsupported, degraded cleanly\n");
    } else {
        TL_CHECK(r == TL_OK && ready);
        printf("16 clears: %llu ns\n", (unsigned long long)ns);
        /* Non-waiting read of a finished query. */
        r = tl__timer_read(gl, &t, false, &ready, &ns);
        TL_CHECK(r == TL_OK);
        /* A second span on the same timer. */
        tl__timer_begin(gl, &t);
        tl__timer_end(gl, &t);
        TL_CHECK(tl__timer_read(gl, &t, true, &ready, &ns) == TL_OK && ready);
    }
    tl__timer_destroy(gl, &t);
    TL_CHECK(t.queries[0] == 0);

    /* A zeroed timer is the degraded one: calls are harmless and report unsupported. */
    tl__timer none = {0};
    tl__timer_begin(gl, &none);
    tl__timer_end(gl, &none);
    TL_CHECK(tl__timer_read(gl, &none, true, &ready, &ns) == TL_ERROR_UNSUPPORTED);
    TL_CHECK(!ready && ns == 0);
    tl__timer_destroy(gl, &none);

    /* Debug groups nest and pop cleanly. */
    tl__gl_debug_push(gl, "test.outer");
    tl__gl_debug_push(gl, "test.inner");
    tl__gl_debug_pop(gl);
    tl__gl_debug_pop(gl);
    gl_close(&env);
}
