/* The frame as a graph (issue 10): what a steady frame asks of GL (no uniform lookups, attachment
 * queries, compiles or waits), the GL state render_to promises, application passes, targets that
 * share memory, the plan's lifetimes over every mode and feature combination, statistics read
 * frames later, resizing. GL cases run on OSMesa through the public API; the counting loader
 * wraps the entry points the renderer loads. */
#include "tl_test.h"

#include "gl/gl.h"
#include "thinlight/context.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"

#include "gl_counter.h"
#include "render_fixture.h"

#define BIT(t) TL_TARGET_BIT(t)

/* A count of the GL call counter (gl_counter.h): N(Finish) is glFinish's. */
#define N(name) tl_test_gl_calls("gl" #name)

/* ---- shared set-up ------------------------------------------------------------------------------ */

static tl_scene *crypt(uint32_t lights)
{
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = lights, .detail = 1}, &s) == TL_OK);
    return s;
}

static GLADapiproc fixture_load(void *user, const char *name)
{
    return (GLADapiproc)tl_context_get_proc_address((tl_context *)user, name);
}

/* The test's own GL entry points (for state queries and the application pass). */
static int load_gl(GladGLContext *gl)
{
    char msg[256];
    if (tl__gl_load(gl, fixture_load, g_ctx, msg, sizeof msg) == TL_OK) return 1;
    fprintf(stderr, "glad: %s\n", msg);
    tl_test_failures++;
    return 0;
}

/* ---- a steady frame makes no lookups, queries, compiles or waits -------------------------------- */

/* The materials some non-empty object draws that are not alpha-blended (those go forward after the
 * opaque frame). */
static unsigned long opaque_materials_drawn(const tl_scene *s)
{
    unsigned long n = 0;
    for (size_t m = 0; m < s->material_count; m++) {
        int used = 0;
        for (size_t o = 0; o < s->object_count && !used; o++) used = s->objects[o].material == m && s->objects[o].index_count;
        n += used && !(s->materials[m].flags & TL_MATERIAL_ALPHA_BLEND);
    }
    return n;
}

TL_TEST(frame_graph_steady_frame_gl_calls)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_scene *s = crypt(64);
    if (!s) return;
    for (int run = 0; run < 2 * (TL_MODE_COUNT_ - 1); run++) { /* every mode, then with every effect on */
        int mode = TL_MODE_THIN_LPP + run % (TL_MODE_COUNT_ - 1), fx = run >= TL_MODE_COUNT_ - 1;
        tl_renderer_desc d = {.options.mode = (tl_render_mode)mode, .width = 160, .height = 90,
                              .get_proc_address = tl_test_gl_counting_loader};
        if (fx) {
            d.options.ssao.enabled = 1, d.options.ssao.method = TL_SSAO_DISC;
            d.options.fog.enabled = 1, d.options.fog.mode = TL_FOG_DISTANCE;
            d.options.dof.enabled = d.options.bloom.enabled = 1;
        }
        tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = d, .scene = s});
        if (!r) continue;
        TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK); /* warm: the first use of every object */
        TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
        tl_test_gl_counts_reset();
        TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
        char label[80];
        snprintf(label, sizeof label, "%s%s, steady frame without statistics", tl_render_mode_name((tl_render_mode)mode),
                 fx ? " with every effect" : "");
        tl_test_gl_counts_print(label);
        TL_CHECK_EQ_U(N(GetUniformLocation) + N(Uniform1i) + N(ProgramUniform1i) + N(ProgramUniform1f) +
                          N(ProgramUniformMatrix4fv), 0);
        TL_CHECK_EQ_U(N(GetNamedFramebufferAttachmentParameteriv) + N(GetFramebufferAttachmentParameteriv), 0);
        TL_CHECK_EQ_U(N(Finish), 0);
        TL_CHECK_EQ_U(N(CompileShader) + N(LinkProgram), 0);
        TL_CHECK_EQ_U(N(GetIntegerv) + N(GetError) + N(GetQueryObjectuiv) + N(GetQueryObjectui64v), 0);
        TL_CHECK_EQ_U(N(NamedBufferSubData) + N(BufferSubData), 0); /* per-frame data: the mapped ring */
        TL_CHECK_EQ_U(N(NamedBufferStorage) + N(NamedBufferData), 0); /* storage made once, grown only when short */
        TL_CHECK(N(DrawElementsInstancedBaseInstance) > 0);
        if (mode == TL_MODE_VISIBILITY) {
            /* vis-resolve: one indirect dispatch per opaque material the scene draws (its bucket's
             * tiles), whatever the effects; vis-classify and light-cull one dispatch each */
            TL_CHECK_EQ_U(N(DispatchComputeIndirect), opaque_materials_drawn(s));
            if (!fx) TL_CHECK_EQ_U(N(DispatchCompute), 2);
        } else {
            TL_CHECK_EQ_U(N(DispatchComputeIndirect), 0);
        }
        /* statistics read frames later: still no wait */
        tl_test_gl_counts_reset();
        tl_frame_stats st;
        for (int f = 0; f < 6; f++) TL_CHECK(tl_renderer_render(r, NULL, &st) == TL_OK);
        snprintf(label, sizeof label, "%s%s, 6 frames with ring statistics", tl_render_mode_name((tl_render_mode)mode),
                 fx ? " with every effect" : "");
        tl_test_gl_counts_print(label);
        TL_CHECK_EQ_U(N(Finish), 0);
        TL_CHECK_EQ_U(N(GetUniformLocation) + N(GetNamedFramebufferAttachmentParameteriv), 0);
        /* waiting is asked for: one glFinish */
        tl_test_gl_counts_reset();
        TL_CHECK(tl_renderer_wait(r, &st) == TL_OK);
        TL_CHECK_EQ_U(N(Finish), 1);
        TL_CHECK(st.gpu_valid && st.frame == 9);
        tl_renderer_destroy(r);
    }
    tl_scene_destroy(s);
}

/* ---- statistics from the ring ------------------------------------------------------------------- */

TL_TEST(frame_graph_stats_ring_read_later)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_scene *s = crypt(16);
    if (!s) return;
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = {.width = 96, .height = 64}, .scene = s});
    if (!r) return;
    uint64_t last = 0;
    size_t reported = 0;
    for (uint64_t f = 1; f <= 12; f++) {
        tl_frame_stats st;
        TL_CHECK(tl_renderer_render(r, NULL, &st) == TL_OK);
        TL_CHECK(st.frame <= f && st.frame >= last); /* an earlier (or this) frame, never going back */
        TL_CHECK(st.frame == 0 || f - st.frame < 4);  /* at most a ring behind */
        TL_CHECK(st.cpu_ms > 0.0 || st.frame == 0);
        if (st.frame) {
            reported++;
            TL_CHECK(st.gpu_valid && st.pass_fragments[TL_PASS_GBUFFER] > 0);
        }
        last = st.frame;
    }
    TL_CHECK(reported > 0);
    tl_frame_stats st;
    TL_CHECK(tl_renderer_wait(r, &st) == TL_OK);
    TL_CHECK(st.frame == 12 && st.gpu_valid && st.wall_ms > 0.0);
    /* a frame without statistics issues no queries; waiting for it still gives its CPU figures */
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_wait(r, &st) == TL_OK);
    TL_CHECK(st.frame == 13 && !st.gpu_valid && st.draw_calls > 0);
    tl_renderer_destroy(r);
    tl_scene_destroy(s);
}

/* ---- the GL state render_to leaves -------------------------------------------------------------- */

static void scramble_state(const GladGLContext *gl, GLuint fbo, GLuint tex, GLuint vao, GLuint buf)
{
    const GLenum caps[] = {GL_BLEND, GL_DEPTH_TEST, GL_CULL_FACE, GL_DEPTH_CLAMP, GL_SCISSOR_TEST, GL_STENCIL_TEST};
    for (size_t i = 0; i < sizeof caps / sizeof caps[0]; i++) gl->Enable(caps[i]);
    gl->DepthMask(GL_FALSE);
    gl->ColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
    gl->ClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
    gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl->BindVertexArray(vao);
    gl->BindTextureUnit(3, tex);
    gl->BindTextureUnit(17, tex);
    gl->BindBufferBase(GL_UNIFORM_BUFFER, 1, buf);
    gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, buf);
    gl->Viewport(1, 2, 3, 4);
}

static void check_promised_state(const GladGLContext *gl, const GLint viewport[4], const char *label)
{
    GLint v = -1, vp[4] = {0};
    const GLenum caps[] = {GL_BLEND, GL_DEPTH_TEST, GL_CULL_FACE, GL_DEPTH_CLAMP, GL_SCISSOR_TEST, GL_STENCIL_TEST};
    size_t bad = 0;
    for (size_t i = 0; i < sizeof caps / sizeof caps[0]; i++) bad += gl->IsEnabled(caps[i]) != GL_FALSE;
    const GLenum zero[] = {GL_DRAW_FRAMEBUFFER_BINDING, GL_READ_FRAMEBUFFER_BINDING, GL_CURRENT_PROGRAM,
                           GL_VERTEX_ARRAY_BINDING};
    for (size_t i = 0; i < sizeof zero / sizeof zero[0]; i++) {
        gl->GetIntegerv(zero[i], &v);
        bad += v != 0;
    }
    GLboolean mask[4] = {0}, dmask = GL_FALSE;
    gl->GetBooleanv(GL_COLOR_WRITEMASK, mask);
    gl->GetBooleanv(GL_DEPTH_WRITEMASK, &dmask);
    bad += !mask[0] + !mask[1] + !mask[2] + !mask[3] + !dmask;
    gl->GetIntegerv(GL_CLIP_ORIGIN, &v);
    bad += v != GL_LOWER_LEFT;
    gl->GetIntegerv(GL_CLIP_DEPTH_MODE, &v);
    bad += v != GL_NEGATIVE_ONE_TO_ONE;
    for (GLuint u = 0; u <= 24; u++) {
        gl->ActiveTexture(GL_TEXTURE0 + u);
        gl->GetIntegerv(GL_TEXTURE_BINDING_2D, &v);
        bad += v != 0;
        gl->GetIntegerv(GL_SAMPLER_BINDING, &v);
        bad += v != 0;
    }
    gl->ActiveTexture(GL_TEXTURE0);
    for (GLuint i = 0; i < 5; i++) {
        gl->GetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, i, &v);
        bad += v != 0;
        gl->GetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, i, &v);
        bad += v != 0;
    }
    for (GLuint i = 0; i < 4; i++) {
        gl->GetIntegeri_v(GL_IMAGE_BINDING_NAME, i, &v);
        bad += v != 0;
    }
    gl->GetIntegerv(GL_VIEWPORT, vp);
    bad += memcmp(vp, viewport, sizeof vp) != 0;
    if (bad) fprintf(stderr, "%s: %zu state items differ from the promise\n", label, bad);
    TL_CHECK_EQ_U(bad, 0);
}

TL_TEST(frame_graph_render_to_state_promise)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    GladGLContext gl;
    if (!load_gl(&gl)) return;
    tl_scene *s = crypt(8);
    if (!s) return;
    GLuint tex = 0, fbo = 0, vao = 0, buf = 0, out_tex = 0, out_fbo = 0;
    gl.CreateTextures(GL_TEXTURE_2D, 1, &tex);
    gl.TextureStorage2D(tex, 1, GL_RGBA8, 4, 4);
    gl.CreateFramebuffers(1, &fbo);
    gl.NamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, tex, 0);
    gl.CreateVertexArrays(1, &vao);
    gl.CreateBuffers(1, &buf);
    gl.NamedBufferStorage(buf, 256, NULL, 0);
    gl.CreateTextures(GL_TEXTURE_2D, 1, &out_tex);
    gl.TextureStorage2D(out_tex, 1, GL_RGBA8, 200, 120);
    gl.CreateFramebuffers(1, &out_fbo);
    gl.NamedFramebufferTexture(out_fbo, GL_COLOR_ATTACHMENT0, out_tex, 0);
    const tl_depth_format depths[2] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};
    /* volumes; tiled with the fragment pass (D24) and the compute pass (reversed D32F): the storage
     * buffers and image units of the tiled passes are unbound too */
    for (int mode = TL_MODE_THIN_LPP; mode < TL_MODE_COUNT_; mode++)
        for (int k = 0; k < 4; k++) {
            int dz = k % 2;
            tl_light_strategy ls = k < 2 ? TL_LIGHT_STRATEGY_VOLUMES : TL_LIGHT_STRATEGY_TILED;
            tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
                .renderer = {.options.mode = (tl_render_mode)mode, .options.depth_format = depths[dz], .width = 96,
                             .height = 64, .options.light_strategy = ls,
                             .options.tiled_shading = dz ? TL_TILED_SHADING_COMPUTE : TL_TILED_SHADING_FRAGMENT},
                .scene = s});
            if (!r) continue;
            scramble_state(&gl, fbo, tex, vao, buf);
            tl_render_output o = {.framebuffer = out_fbo, .x = 7, .y = 9, .width = 150, .height = 100};
            TL_CHECK(tl_renderer_render_to(r, NULL, &o, NULL) == TL_OK);
            check_promised_state(&gl, (const GLint[4]){7, 9, 150, 100}, "render_to");
            scramble_state(&gl, fbo, tex, vao, buf);
            TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
            check_promised_state(&gl, (const GLint[4]){0, 0, 96, 64}, "render");
            TL_CHECK(tl_renderer_wait(r, NULL) == TL_OK);
            tl_renderer_destroy(r);
        }
    gl.DeleteFramebuffers(1, &fbo);
    gl.DeleteFramebuffers(1, &out_fbo);
    gl.DeleteTextures(1, &tex);
    gl.DeleteTextures(1, &out_tex);
    gl.DeleteVertexArrays(1, &vao);
    gl.DeleteBuffers(1, &buf);
    TL_CHECK_EQ_U(gl.GetError(), GL_NO_ERROR);
    tl_scene_destroy(s);
}

/* ---- application passes -------------------------------------------------------------------------- */

/* Multiplies HDR by exp(-k * distance) with blending (DST_COLOR, ZERO); background pixels keep 1. */
static const char *const tint_fs =
    "#version 450 core\n"
    "layout(binding = 0) uniform sampler2D u_depth;\n"
    "uniform vec4 u_params; // m[10], m[14], m[11], reversed\n"
    "uniform vec4 u_ray;    // m[0], m[5], m[8], m[9] and the size\n"
    "uniform vec2 u_size;\n"
    "uniform float u_clear;\n"
    "out vec4 o;\n"
    "void main() {\n"
    "    float d = texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r;\n"
    "    if (d == u_clear) { o = vec4(1.0); return; }\n"
    "    float zn = u_params.w > 0.5 ? d : 2.0 * d - 1.0;\n"
    "    float z = u_params.y / (u_params.z * zn - u_params.x);\n"
    "    vec2 ndc = gl_FragCoord.xy / u_size * 2.0 - 1.0;\n"
    "    vec3 p = vec3(-z * (ndc.x + u_ray.z) / u_ray.x, -z * (ndc.y + u_ray.w) / u_ray.y, z);\n"
    "    o = vec4(vec3(exp(-0.05 * length(p))), 1.0);\n"
    "}\n";
static const char *const tint_vs =
    "#version 450 core\n"
    "void main() { gl_Position = vec4(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0, 0.0, 1.0); }\n";

typedef struct tint_pass {
    GladGLContext *gl;
    GLuint program, vao;
    unsigned calls;
    uint32_t textures_seen;
    GLint framebuffer_seen;
    tl_view_info view; /* as the pass saw it */
} tint_pass;

static GLuint compile(const GladGLContext *gl, GLenum type, const char *src)
{
    GLuint sh = gl->CreateShader(type);
    gl->ShaderSource(sh, 1, &src, NULL);
    gl->CompileShader(sh);
    GLint ok = 0;
    gl->GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    TL_CHECK(ok);
    return sh;
}

static void tint_execute(void *user, const tl_app_pass_context *ctx)
{
    tint_pass *t = (tint_pass *)user;
    const GladGLContext *gl = t->gl;
    t->calls++;
    for (int k = 0; k < TL_TARGET_COUNT; k++)
        if (ctx->textures[k]) t->textures_seen |= BIT(k);
    gl->GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &t->framebuffer_seen);
    const tl_view_info *v = ctx->view;
    t->view = *v;
    gl->UseProgram(t->program);
    gl->Uniform4f(gl->GetUniformLocation(t->program, "u_params"), v->projection[10], v->projection[14], v->projection[11],
                  v->reversed_z ? 1.0f : 0.0f);
    gl->Uniform4f(gl->GetUniformLocation(t->program, "u_ray"), v->projection[0], v->projection[5], v->projection[8],
                  v->projection[9]);
    gl->Uniform2f(gl->GetUniformLocation(t->program, "u_size"), (float)v->width, (float)v->height);
    gl->Uniform1f(gl->GetUniformLocation(t->program, "u_clear"), v->reversed_z ? 0.0f : 1.0f);
    gl->BindTextureUnit(0, ctx->textures[TL_TARGET_DEPTH]);
    gl->Enable(GL_BLEND);
    gl->BlendFunc(GL_DST_COLOR, GL_ZERO);
    gl->BindVertexArray(t->vao);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    gl->Disable(GL_BLEND);
    gl->BindVertexArray(0);
    gl->UseProgram(0);
}

static float *read_hdr(tl_renderer *r, size_t n)
{
    float *p = malloc(n * 4 * sizeof *p);
    size_t size = n * 4 * sizeof *p;
    TL_CHECK(p && tl_renderer_read_target(r, TL_TARGET_HDR, p, &size) == TL_OK);
    return p;
}

/* An application pass before tone mapping tints HDR by linear depth: HDR with the pass equals HDR
 * without it times exp(-0.05 distance) at every pixel, within FP16 rounding (the product is rounded
 * once to half: relative 2^-11, plus the tint's own float error). */
TL_TEST(frame_graph_app_pass_tints_hdr)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    GladGLContext gl;
    if (!load_gl(&gl)) return;
    tl_scene *s = crypt(16);
    if (!s) return;
    tint_pass t = {.gl = &gl};
    GLuint vs = compile(&gl, GL_VERTEX_SHADER, tint_vs), fs = compile(&gl, GL_FRAGMENT_SHADER, tint_fs);
    t.program = gl.CreateProgram();
    gl.AttachShader(t.program, vs);
    gl.AttachShader(t.program, fs);
    gl.LinkProgram(t.program);
    gl.DeleteShader(vs);
    gl.DeleteShader(fs);
    gl.CreateVertexArrays(1, &t.vao);
    const uint32_t w = 128, h = 72;
    const size_t n = (size_t)w * h;
    const tl_depth_format depths[2] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};
    for (int mode = TL_MODE_THIN_LPP; mode < TL_MODE_COUNT_; mode++)
        for (int dz = 0; dz < 2; dz++) {
            tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
                .renderer = {.options.mode = (tl_render_mode)mode, .options.depth_format = depths[dz], .width = w,
                             .height = h, .options.keep_targets = BIT(TL_TARGET_HDR) | BIT(TL_TARGET_DEPTH)},
                .scene = s});
            if (!r) continue;
            TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
            float *plain = read_hdr(r, n);
            tl_app_pass_desc ap = {.name = "tint-by-depth", .before = "tonemap", .reads = BIT(TL_TARGET_DEPTH),
                                   .writes = BIT(TL_TARGET_HDR), .execute = tint_execute, .user = &t};
            TL_CHECK(tl_renderer_add_pass(r, &ap) == TL_OK);
            tl_frame_plan p;
            TL_CHECK(tl_renderer_get_plan(r, &p) == TL_OK);
            size_t at = p.pass_count;
            for (size_t i = 0; i < p.pass_count; i++)
                if (p.passes[i].pass == TL_PASS_COUNT && !strcmp(p.passes[i].name, "tint-by-depth")) at = i;
            TL_CHECK(at + 1 < p.pass_count && p.passes[at + 1].pass == TL_PASS_TONEMAP);
            t.calls = 0;
            t.textures_seen = 0;
            TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
            TL_CHECK(t.calls == 1 && t.textures_seen == BIT(TL_TARGET_DEPTH) && t.framebuffer_seen != 0);
            float *tinted = read_hdr(r, n), *depth = malloc(n * 4 * sizeof *depth);
            size_t size = n * 4 * sizeof *depth, bad = 0, dimmed = 0;
            TL_CHECK(tl_renderer_read_target(r, TL_TARGET_DEPTH, depth, &size) == TL_OK);
            const float *m = t.view.projection;
            for (size_t i = 0; i < n; i++) {
                float d = depth[4 * i];
                int background = d == (dz ? 0.0f : 1.0f);
                /* the shader's tint at this depth, and at one depth step either side: the texel the
                 * shader fetched may convert to float a step away from the read-back, and near the
                 * far plane one D24 step moves the distance by centimetres */
                double step = dz ? fabs(nextafterf(d, 2.0f) - d) : 0x1.0p-24, lo = 1.0, hi = 0.0;
                for (int k = -1; k <= 1; k++) {
                    double dk = d + k * step, zn = dz ? dk : 2.0 * dk - 1.0, z = m[14] / (m[11] * zn - m[10]);
                    double nx = ((double)(i % w) + 0.5) / w * 2.0 - 1.0, ny = ((double)(i / w) + 0.5) / h * 2.0 - 1.0;
                    double px = -z * (nx + m[8]) / m[0], py = -z * (ny + m[9]) / m[5];
                    double fk = background ? 1.0 : exp(-0.05 * sqrt(px * px + py * py + z * z));
                    lo = fmin(lo, fk);
                    hi = fmax(hi, fk);
                }
                for (int c = 0; c < 3; c++) {
                    double p0 = plain[4 * i + c], got = tinted[4 * i + c];
                    /* blending into an FP16 target rounds the tint to FP16 and then the product:
                     * two roundings of half an FP16 step (2^-11 relative) each */
                    double tol = (0x1.0p-10 + 1e-5) * p0 * hi + 1e-7;
                    if (got < p0 * lo - tol || got > p0 * hi + tol) bad++;
                    dimmed += got < p0 * 0.999;
                }
            }
            printf("%s %s: %zu channels dimmed, %zu off the expected tint\n", tl_render_mode_name((tl_render_mode)mode),
                   dz ? "D32F reversed" : "D24", dimmed, bad);
            TL_CHECK_EQ_U(bad, 0);
            TL_CHECK(dimmed > n);
            /* removed: the frame is the plain one again */
            TL_CHECK(tl_renderer_remove_pass(r, "tint-by-depth") == TL_OK);
            TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
            float *again = read_hdr(r, n);
            TL_CHECK(again && memcmp(again, plain, n * 4 * sizeof *again) == 0);
            free(again);
            free(plain);
            free(tinted);
            free(depth);
            tl_renderer_destroy(r);
        }
    gl.DeleteProgram(t.program);
    gl.DeleteVertexArrays(1, &t.vao);
    tl_scene_destroy(s);
}

static void nothing(void *user, const tl_app_pass_context *ctx)
{
    (void)user;
    (void)ctx;
}

TL_TEST(frame_graph_app_pass_bad_input)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = {.width = 32, .height = 32}});
    if (!r) return;
    tl_app_pass_desc ok = {.name = "a", .after = "lights", .writes = BIT(TL_TARGET_HDR), .execute = nothing};
    tl_app_pass_desc d = ok;
    d.name = NULL;
    TL_CHECK(tl_renderer_add_pass(r, &d) == TL_ERROR_INVALID_ARGUMENT);
    d = ok;
    d.after = "no-such-pass";
    TL_CHECK(tl_renderer_add_pass(r, &d) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(strstr(tl_renderer_last_error(r), "no-such-pass") != NULL);
    d = ok;
    d.before = "tonemap"; /* both */
    TL_CHECK(tl_renderer_add_pass(r, &d) == TL_ERROR_INVALID_ARGUMENT);
    d = ok;
    d.writes = BIT(TL_TARGET_RT0);
    TL_CHECK(tl_renderer_add_pass(r, &d) == TL_ERROR_INVALID_ARGUMENT);
    d = ok;
    d.reads = BIT(TL_TARGET_HDR); /* reading what it writes: a feedback loop */
    TL_CHECK(tl_renderer_add_pass(r, &d) == TL_ERROR_INVALID_ARGUMENT);
    d = ok;
    d.execute = NULL;
    TL_CHECK(tl_renderer_add_pass(r, &d) == TL_ERROR_INVALID_ARGUMENT);
    char names[TL_MAX_APP_PASSES + 1][8];
    for (int i = 0; i <= TL_MAX_APP_PASSES; i++) {
        snprintf(names[i], sizeof names[i], "p%d", i);
        d = ok;
        d.name = names[i];
        TL_CHECK(tl_renderer_add_pass(r, &d) == (i < TL_MAX_APP_PASSES ? TL_OK : TL_ERROR_LIMIT));
    }
    d = ok;
    d.name = "p0";
    TL_CHECK(tl_renderer_add_pass(r, &d) == TL_ERROR_LIMIT || tl_renderer_add_pass(r, &d) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_renderer_remove_pass(r, "p3") == TL_OK);
    TL_CHECK(tl_renderer_add_pass(r, &d) == TL_ERROR_INVALID_ARGUMENT); /* duplicate name */
    TL_CHECK(tl_renderer_remove_pass(r, "p3") == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_renderer_remove_pass(r, NULL) == TL_ERROR_INVALID_ARGUMENT);
    tl_renderer_destroy(r);
}

/* ---- targets that share memory --------------------------------------------------------------- */

TL_TEST(frame_graph_shared_targets_readback)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_scene *s = crypt(16);
    if (!s) return;
    const uint32_t w = 120, h = 80;
    size_t n = (size_t)w * h, size = n * 4 * sizeof(float);
    tl_test_renderer_desc d = {.renderer = {.width = w, .height = h}, .scene = s};
    tl_renderer *shared = tl_test_renderer(&d);
    d.renderer.options.keep_targets = TL_TARGETS_ALL;
    tl_renderer *kept = tl_test_renderer(&d);
    if (!shared || !kept) return;
    tl_frame_plan ps, pk;
    TL_CHECK(tl_renderer_get_plan(shared, &ps) == TL_OK && tl_renderer_get_plan(kept, &pk) == TL_OK);
    /* thin-lpp: RT0 (G-buffer to lights) and LDR (tone map to FXAA) share one RGBA8 block */
    TL_CHECK(ps.target_info[TL_TARGET_RT0].block == ps.target_info[TL_TARGET_LDR].block);
    TL_CHECK_EQ_U(ps.bytes_per_pixel, 40);
    TL_CHECK_EQ_U(ps.allocated_bytes_per_pixel, 36);
    TL_CHECK_EQ_U(pk.allocated_bytes_per_pixel, pk.bytes_per_pixel);
    TL_CHECK(tl_renderer_render(shared, NULL, NULL) == TL_OK && tl_renderer_render(kept, NULL, NULL) == TL_OK);
    float *a = malloc(size), *b = malloc(size);
    size_t sz = size;
    TL_CHECK(tl_renderer_read_target(shared, TL_TARGET_RT0, a, &sz) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(strstr(tl_renderer_last_error(shared), "keep_targets") != NULL);
    /* the block's last user, and targets of their own, read back; with or without sharing the
     * same pixels */
    const tl_target_id readable[] = {TL_TARGET_LDR, TL_TARGET_HDR, TL_TARGET_DEPTH, TL_TARGET_LIGHT_DIFFUSE};
    for (size_t k = 0; k < sizeof readable / sizeof readable[0]; k++) {
        sz = size;
        TL_CHECK(tl_renderer_read_target(shared, readable[k], a, &sz) == TL_OK);
        sz = size;
        TL_CHECK(tl_renderer_read_target(kept, readable[k], b, &sz) == TL_OK);
        TL_CHECK(memcmp(a, b, size) == 0);
    }
    uint8_t *oa = malloc(n * 4), *ob = malloc(n * 4);
    size_t need = 0;
    TL_CHECK(tl_renderer_read_output(shared, NULL, &need) == TL_OK && need == n * 4); /* NULL asks */
    sz = need - 1;
    TL_CHECK(tl_renderer_read_output(shared, oa, &sz) == TL_ERROR_LIMIT && sz == need);
    TL_CHECK(tl_renderer_read_output(shared, oa, &need) == TL_OK);
    TL_CHECK(tl_renderer_read_output(kept, ob, &need) == TL_OK);
    TL_CHECK(memcmp(oa, ob, n * 4) == 0);
    need = 0;
    TL_CHECK(tl_renderer_read_target(kept, TL_TARGET_RT0, NULL, &need) == TL_OK && need == size);
    free(a);
    free(b);
    free(oa);
    free(ob);
    tl_renderer_destroy(shared);
    tl_renderer_destroy(kept);
    tl_scene_destroy(s);
}

/* ---- the plan's lifetimes, over every mode and feature combination ---------------------------- */

static int disjoint(const tl_plan_target *a, const tl_plan_target *b)
{
    return a->last_pass < b->first_pass || b->last_pass < a->first_pass;
}

static void check_plan_memory(const tl_frame_plan *p, int keep_all, size_t *bad)
{
    uint32_t blocks = 0;
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        const tl_plan_target *ti = &p->target_info[t];
        if (!(p->targets & BIT(t))) continue;
        *bad += ti->first_pass > ti->last_pass || ti->block >= p->block_count;
        *bad += !(p->passes[ti->first_pass].writes & BIT(t)); /* born by a write */
        *bad += !(p->blocks[ti->block].targets & BIT(t));
        for (int u = t + 1; u < TL_TARGET_COUNT; u++) {
            const tl_plan_target *tu = &p->target_info[u];
            if (!(p->targets & BIT(u)) || tu->block != ti->block) continue;
            *bad += !disjoint(ti, tu) || ti->bytes_per_pixel != tu->bytes_per_pixel || t == TL_TARGET_DEPTH || keep_all;
        }
    }
    for (size_t b = 0; b < p->block_count; b++) blocks += p->blocks[b].bytes_per_pixel;
    *bad += blocks != p->allocated_bytes_per_pixel;
    *bad += !(p->peak_live_bytes_per_pixel <= p->allocated_bytes_per_pixel &&
              p->allocated_bytes_per_pixel <= p->bytes_per_pixel);
    *bad += keep_all && p->allocated_bytes_per_pixel != p->bytes_per_pixel;
    /* every pass writes something a later pass reads, or the output */
    for (size_t i = 0; i < p->pass_count; i++) {
        tl_target_set later = BIT(TL_TARGET_OUTPUT);
        for (size_t j = i + 1; j < p->pass_count; j++) later |= p->passes[j].reads;
        *bad += !(p->passes[i].writes & later);
        *bad += (p->passes[i].clears & ~p->passes[i].writes) != 0;
    }
}

TL_TEST(frame_graph_plan_lifetimes_exhaustive)
{
    size_t bad = 0, plans = 0, shareable = 0, shared_somewhere = 0;
    for (int mode = TL_MODE_THIN_LPP; mode < TL_MODE_COUNT_; mode++)
        for (unsigned bits = 0; bits < 256; bits++)
            for (int variant = 0; variant < 4; variant++) {
                tl_scene_feature_set f = {.point_lights = bits & 1, .spot_lights = (bits >> 1) & 1,
                                          .directional_lights = (bits >> 2) & 1, .has_specular = (bits >> 3) & 1,
                                          .has_textures = (bits >> 4) & 1, .has_alpha_blend = (bits >> 5) & 1,
                                          .has_alpha_mask = (bits >> 6) & 1};
                tl_renderer_desc d = {.options.mode = (tl_render_mode)mode, .width = 64, .height = 32,
                                      .options.fxaa = (variant & 1) ? TL_FXAA_OFF : TL_FXAA_DEFAULT,
                                      .options.keep_targets = (variant & 2) ? TL_TARGETS_ALL : 0,
                                      .options.light_buffer = (bits >> 7) ? TL_LIGHT_BUFFER_COMPACT : TL_LIGHT_BUFFER_EXACT};
                tl_frame_plan p;
                TL_CHECK(tl_frame_plan_build(&d, &f, &p) == TL_OK);
                check_plan_memory(&p, (variant & 2) != 0, &bad);
                if (variant == 0) { /* FXAA on, nothing kept */
                    shareable++;
                    shared_somewhere += p.allocated_bytes_per_pixel < p.bytes_per_pixel;
                }
                plans++;
            }
    printf("%zu plans checked, %zu of %zu with FXAA and nothing kept share memory, %zu violations\n", plans,
           shared_somewhere, shareable, bad);
    TL_CHECK_EQ_U(bad, 0);
    TL_CHECK(shared_somewhere > shareable / 4);
    /* the figures docs/frame.md quotes: the crypt's features (every light type, specular, textures) */
    tl_scene_feature_set crypt_features = {.point_lights = 64, .spot_lights = 8, .directional_lights = 1,
                                           .has_specular = 1, .has_textures = 1};
    /* with tiles, the light lists add ceil((16 + 136 tiles) / pixels) = 1 B/px at 1280x720; visibility
     * always has them, and its material buckets' lists, ceil(64 (16 + 4 x 3,600 tiles) / pixels) = 2 B/px */
    const uint32_t sums[TL_MODE_COUNT_] = {0, 40, 28, 60, 20, 27}, allocated[TL_MODE_COUNT_] = {0, 36, 20, 60, 20, 23};
    for (int tiled = 0; tiled < 2; tiled++)
        for (int mode = TL_MODE_THIN_LPP; mode < TL_MODE_COUNT_; mode++) {
            tl_frame_plan p;
            tl_renderer_desc d = {.options.mode = (tl_render_mode)mode,
                                  .options.light_strategy = tiled ? TL_LIGHT_STRATEGY_TILED : TL_LIGHT_STRATEGY_VOLUMES};
            TL_CHECK(tl_frame_plan_build(&d, &crypt_features, &p) == TL_OK);
            printf("%-13s %-7s sum %2u B/px, allocated %2u B/px, most live at once %2u B/px\n",
                   tl_render_mode_name((tl_render_mode)mode), tiled ? "tiled" : "volumes", p.bytes_per_pixel,
                   p.allocated_bytes_per_pixel, p.peak_live_bytes_per_pixel);
            uint32_t lists = mode == TL_MODE_VISIBILITY ? 0u : (uint32_t)tiled;
            TL_CHECK_EQ_U(p.bytes_per_pixel, sums[mode] + lists);
            TL_CHECK_EQ_U(p.allocated_bytes_per_pixel, allocated[mode] + lists);
        }
}

/* The table names every public pass and target id once, names and ids convert both ways, and a
 * plan runs a pass once; the order is the table's, not the enum's (the vignette, appended to the
 * enum, runs before the tone map). */
TL_TEST(frame_graph_pass_table)
{
    for (int i = 0; i < TL_PASS_COUNT; i++) {
        tl_pass back = TL_PASS_COUNT;
        TL_CHECK(strcmp(tl_pass_name((tl_pass)i), "unknown") != 0);
        TL_CHECK(tl_pass_from_name(tl_pass_name((tl_pass)i), &back) == TL_OK && back == (tl_pass)i);
        for (int j = 0; j < i; j++) TL_CHECK(strcmp(tl_pass_name((tl_pass)i), tl_pass_name((tl_pass)j)) != 0);
    }
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        tl_target_id back = TL_TARGET_COUNT;
        TL_CHECK(tl_target_from_name(tl_target_name((tl_target_id)t), &back) == TL_OK && back == (tl_target_id)t);
    }
    TL_CHECK(strcmp(tl_pass_name(TL_PASS_COUNT), "unknown") == 0);
    TL_CHECK(tl_pass_from_name("no such pass", &(tl_pass){0}) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_target_from_name("unknown", &(tl_target_id){0}) == TL_ERROR_INVALID_ARGUMENT);
    tl_scene_feature_set f = {.point_lights = 1, .has_alpha_blend = 1};
    for (int mode = TL_MODE_THIN_LPP; mode < TL_MODE_COUNT_; mode++) {
        tl_frame_plan p;
        tl_renderer_desc d = {.options.mode = (tl_render_mode)mode, .options.vignette.enabled = 1};
        TL_CHECK(tl_frame_plan_build(&d, &f, &p) == TL_OK);
        size_t vignette = p.pass_count, tonemap = p.pass_count;
        for (size_t i = 0; i < p.pass_count; i++) {
            TL_CHECK(strcmp(p.passes[i].name, tl_pass_name(p.passes[i].pass)) == 0);
            for (size_t j = 0; j < i; j++) TL_CHECK(p.passes[j].pass != p.passes[i].pass);
            if (p.passes[i].pass == TL_PASS_VIGNETTE) vignette = i;
            if (p.passes[i].pass == TL_PASS_TONEMAP) tonemap = i;
        }
        TL_CHECK(vignette < tonemap && tonemap < p.pass_count && TL_PASS_VIGNETTE > TL_PASS_TONEMAP);
    }
}

/* ---- resizing ------------------------------------------------------------------------------------ */

TL_TEST(frame_graph_resize_reallocates)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_scene *s = crypt(8);
    if (!s) return;
    tl_renderer *r = tl_test_renderer(
        &(tl_test_renderer_desc){.renderer = {.width = 64, .height = 48, .options.synchronous_stats = 1}, .scene = s});
    if (!r) return;
    tl_frame_stats a, b;
    TL_CHECK(tl_renderer_render(r, NULL, &a) == TL_OK);
    TL_CHECK(tl_renderer_resize(r, 160, 90) == TL_OK);
    uint32_t w = 0, h = 0;
    tl_renderer_get_size(r, &w, &h);
    TL_CHECK(w == 160 && h == 90);
    TL_CHECK(tl_renderer_render(r, NULL, &b) == TL_OK);
    TL_CHECK_EQ_U(b.total_target_bytes * 64 * 48, a.total_target_bytes * 160 * 90);
    TL_CHECK_EQ_U(b.allocated_target_bytes * 64 * 48, a.allocated_target_bytes * 160 * 90);
    size_t need = 0;
    TL_CHECK(tl_renderer_read_output(r, NULL, &need) == TL_OK && need == (size_t)160 * 90 * 4);
    uint8_t *img = malloc(need);
    TL_CHECK(tl_renderer_read_output(r, img, &need) == TL_OK);
    size_t lit = 0;
    for (size_t i = 0; i < need; i += 4) lit += img[i] + img[i + 1] + img[i + 2] > 30;
    TL_CHECK(lit > need / 4 / 4);
    free(img);
    TL_CHECK(tl_renderer_resize(r, 0, 10) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_renderer_resize(r, 100000, 10) == TL_ERROR_LIMIT);
    tl_renderer_destroy(r);
    tl_scene_destroy(s);
}
