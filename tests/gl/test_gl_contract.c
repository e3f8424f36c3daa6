/* The GL contract (docs/renderer.md, "The GL contract"): whatever state an application leaves in
 * the context, set_scene, render, render_to, the readbacks and apply_fxaa give the same bytes as
 * from a context in its initial state, and the pixel-store state and pixel buffers the application
 * set are still there afterwards. Each row of the table below dirties one piece of state; every row
 * is tried alone (so a failure names it) and all rows at once, in the light pre-pass with volumes
 * and tiles, fat and forward, with both depth formats. */
#include "tl_test.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl/gl.h"
#include "render_room.h"
#include "thinlight/context.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"

enum { W = 96, H = 64, OUT_W = 80, OUT_H = 48 };

/* What the application owns: objects its dirty state binds, and the framebuffer render_to draws into. */
typedef struct app_objects {
    GLuint sampler, program, vao, buffer, texture, out_tex, out_fbo;
} app_objects;

typedef struct dirty_row {
    const char *name;
    void (*set)(const GladGLContext *gl, const app_objects *o);
} dirty_row;

#define ROW(label, body)                                                                                               \
    static void dirty_##label(const GladGLContext *gl, const app_objects *o)                                          \
    {                                                                                                                  \
        (void)o;                                                                                                       \
        body;                                                                                                          \
    }
ROW(front_face, gl->FrontFace(GL_CW))
ROW(depth_range, gl->DepthRange(0.2, 0.8))
ROW(logic_op, { gl->Enable(GL_COLOR_LOGIC_OP); gl->LogicOp(GL_XOR); })
ROW(polygon_offset, { gl->Enable(GL_POLYGON_OFFSET_FILL); gl->PolygonOffset(8.0f, 64.0f); })
ROW(polygon_mode, gl->PolygonMode(GL_FRONT_AND_BACK, GL_LINE))
ROW(rasterizer_discard, gl->Enable(GL_RASTERIZER_DISCARD))
ROW(primitive_restart, { gl->Enable(GL_PRIMITIVE_RESTART); gl->PrimitiveRestartIndex(0); })
ROW(primitive_restart_fixed, gl->Enable(GL_PRIMITIVE_RESTART_FIXED_INDEX))
ROW(srgb_writes, gl->Enable(GL_FRAMEBUFFER_SRGB))
ROW(clip_distances, { for (GLenum i = 0; i < 8; i++) gl->Enable(GL_CLIP_DISTANCE0 + i); })
ROW(provoking_vertex, gl->ProvokingVertex(GL_FIRST_VERTEX_CONVENTION))
ROW(stencil_write_mask, gl->StencilMask(0))
ROW(stencil_test, { gl->Enable(GL_STENCIL_TEST); gl->StencilFunc(GL_NEVER, 1, 0xFF); })
ROW(dither_off, gl->Disable(GL_DITHER))
ROW(multisample, { gl->Enable(GL_SAMPLE_ALPHA_TO_COVERAGE); gl->Enable(GL_SAMPLE_MASK); gl->SampleMaski(0, 0);
                   gl->Enable(GL_SAMPLE_COVERAGE); gl->SampleCoverage(0.0f, GL_FALSE); gl->Enable(GL_SAMPLE_SHADING); })
ROW(samplers, { for (GLuint u = 0; u < 32; u++) gl->BindSampler(u, o->sampler); })
ROW(blend, { gl->Enable(GL_BLEND); gl->BlendEquation(GL_MAX); gl->BlendFunc(GL_ZERO, GL_ONE); })
ROW(depth_test, { gl->Enable(GL_DEPTH_TEST); gl->DepthFunc(GL_NEVER); gl->DepthMask(GL_FALSE); })
ROW(scissor, { gl->Enable(GL_SCISSOR_TEST); gl->Scissor(0, 0, 1, 1); })
ROW(color_mask, gl->ColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_FALSE))
ROW(cull_face, { gl->Enable(GL_CULL_FACE); gl->CullFace(GL_FRONT_AND_BACK); })
ROW(clip_control, gl->ClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE))
ROW(depth_clamp, gl->Enable(GL_DEPTH_CLAMP))
ROW(bindings, { gl->UseProgram(o->program); gl->BindVertexArray(o->vao);
                for (GLuint u = 0; u < 32; u++) gl->BindTextureUnit(u, o->texture);
                for (GLuint i = 0; i < 8; i++) { gl->BindBufferBase(GL_UNIFORM_BUFFER, i, o->buffer);
                                                 gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, i, o->buffer); } })
ROW(unpack_state, { gl->PixelStorei(GL_UNPACK_ROW_LENGTH, 7); gl->PixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
                    gl->PixelStorei(GL_UNPACK_SKIP_ROWS, 2); gl->PixelStorei(GL_UNPACK_ALIGNMENT, 8);
                    gl->PixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE); })
ROW(unpack_buffer, gl->BindBuffer(GL_PIXEL_UNPACK_BUFFER, o->buffer))
ROW(pack_state, { gl->PixelStorei(GL_PACK_ROW_LENGTH, 5); gl->PixelStorei(GL_PACK_SKIP_PIXELS, 1);
                  gl->PixelStorei(GL_PACK_SKIP_ROWS, 2); gl->PixelStorei(GL_PACK_ALIGNMENT, 8); })
ROW(pack_buffer, gl->BindBuffer(GL_PIXEL_PACK_BUFFER, o->buffer))
ROW(dispatch_indirect_buffer, gl->BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, o->buffer)) /* visibility's resolve */
#undef ROW

#define R(label) {#label, dirty_##label}
static const dirty_row g_rows[] = {
    R(front_face),    R(depth_range),  R(logic_op),     R(polygon_offset), R(polygon_mode),   R(rasterizer_discard),
    R(primitive_restart), R(primitive_restart_fixed), R(srgb_writes), R(clip_distances), R(provoking_vertex),
    R(stencil_write_mask), R(stencil_test), R(dither_off), R(multisample), R(samplers), R(blend), R(depth_test),
    R(scissor),       R(color_mask),   R(cull_face),    R(clip_control),   R(depth_clamp),    R(bindings),
    R(unpack_state),  R(unpack_buffer), R(pack_state),  R(pack_buffer),    R(dispatch_indirect_buffer),
};
#undef R
#define ROWS (sizeof g_rows / sizeof g_rows[0])

/* GL's initial state for everything a row touches (what a new context has). */
static void clean_state(const GladGLContext *gl)
{
    static const GLenum off[] = {GL_COLOR_LOGIC_OP, GL_POLYGON_OFFSET_FILL, GL_RASTERIZER_DISCARD, GL_PRIMITIVE_RESTART,
                                 GL_PRIMITIVE_RESTART_FIXED_INDEX, GL_FRAMEBUFFER_SRGB, GL_STENCIL_TEST,
                                 GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_MASK, GL_SAMPLE_COVERAGE, GL_SAMPLE_SHADING,
                                 GL_BLEND, GL_DEPTH_TEST, GL_SCISSOR_TEST, GL_CULL_FACE, GL_DEPTH_CLAMP};
    for (size_t i = 0; i < sizeof off / sizeof off[0]; i++) gl->Disable(off[i]);
    for (GLenum i = 0; i < 8; i++) gl->Disable(GL_CLIP_DISTANCE0 + i);
    gl->Enable(GL_DITHER);
    gl->FrontFace(GL_CCW);
    gl->DepthRange(0.0, 1.0);
    gl->LogicOp(GL_COPY);
    gl->PolygonOffset(0.0f, 0.0f);
    gl->PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    gl->PrimitiveRestartIndex(0);
    gl->ProvokingVertex(GL_LAST_VERTEX_CONVENTION);
    gl->StencilMask(0xFFFFFFFFu);
    gl->StencilFunc(GL_ALWAYS, 0, 0xFFFFFFFFu);
    gl->SampleMaski(0, 0xFFFFFFFFu);
    gl->SampleCoverage(1.0f, GL_FALSE);
    gl->BindSamplers(0, 32, NULL);
    gl->BlendEquation(GL_FUNC_ADD);
    gl->BlendFunc(GL_ONE, GL_ZERO);
    gl->DepthFunc(GL_LESS);
    gl->DepthMask(GL_TRUE);
    gl->Scissor(0, 0, W, H);
    gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl->CullFace(GL_BACK);
    gl->ClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    gl->UseProgram(0);
    gl->BindVertexArray(0);
    gl->BindTextures(0, 32, NULL);
    gl->BindBuffersBase(GL_UNIFORM_BUFFER, 0, 8, NULL);
    gl->BindBuffersBase(GL_SHADER_STORAGE_BUFFER, 0, 8, NULL);
    static const GLenum store[] = {GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_ROWS, GL_UNPACK_LSB_FIRST,
                                   GL_PACK_ROW_LENGTH,   GL_PACK_SKIP_PIXELS,   GL_PACK_SKIP_ROWS};
    for (size_t i = 0; i < sizeof store / sizeof store[0]; i++) gl->PixelStorei(store[i], 0);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl->PixelStorei(GL_PACK_ALIGNMENT, 4);
    gl->BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    gl->BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    gl->BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

static GLADapiproc fixture_load(void *user, const char *name)
{
    return (GLADapiproc)tl_context_get_proc_address((tl_context *)user, name);
}

/* The room with a textured box (so that set_scene uploads a texture), point and spot lights and a
 * directional light. */
typedef struct contract_scene {
    test_scene t;
    tl_texture tex;
    uint8_t pixels[16 * 16 * 4];
} contract_scene;

static void build_scene(contract_scene *c)
{
    build_room(&c->t);
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            uint8_t *p = &c->pixels[4 * (16 * y + x)];
            p[0] = (uint8_t)(16 * x);
            p[1] = (uint8_t)(255 - 16 * y);
            p[2] = ((x ^ y) & 4) ? 230 : 40;
            p[3] = 255;
        }
    c->tex = (tl_texture){.width = 16, .height = 16, .rgba = c->pixels};
    c->t.s.textures = &c->tex;
    c->t.s.texture_count = 1;
    c->t.mat[1].albedo_map = TL_TEXTURE_MAP(0);
    c->t.lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {-4, 2, -2}, .direction = {0, -1, 0},
                                .color = {3, 1, 1}, .radius = 9.0f};
    c->t.lights[1] = (tl_light){.type = TL_LIGHT_POINT, .position = {3, 1.5f, 3}, .direction = {0, -1, 0},
                                .color = {1, 3, 1}, .radius = 8.0f};
    c->t.lights[2] = (tl_light){.type = TL_LIGHT_SPOT, .position = {0, 9, 0}, .direction = {0, -1, 0},
                                .color = {2, 2, 4}, .radius = 12.0f, .cos_inner = 0.95f, .cos_outer = 0.8f};
    c->t.lights[3] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {0.3f, -1, -0.2f},
                                .color = {0.3f, 0.3f, 0.35f}};
    c->t.s.light_count = 4;
}

/* Everything the renderer gives back for one frame: the output, HDR, the image render_to drew into
 * the application's framebuffer and apply_fxaa's result. */
typedef struct frame_bytes {
    uint8_t out[W * H * 4];
    float hdr[W * H * 4];
    uint8_t app[OUT_W * OUT_H * 4];
    uint8_t fxaa[W * H * 4];
} frame_bytes;

/* set_scene, render, read_output, read_target(HDR), render_to the application's framebuffer and
 * apply_fxaa with the state `row` dirtied before each call (NULL: clean); 1 when every call
 * succeeded. The application's framebuffer is read back with clean state. */
static int run_frame(const GladGLContext *gl, tl_renderer *r, const tl_scene *s, const app_objects *o,
                     const dirty_row *row, int all, frame_bytes *f)
{
#define DIRTY()                                                                                                        \
    do {                                                                                                               \
        clean_state(gl);                                                                                               \
        for (size_t k = 0; k < ROWS; k++)                                                                              \
            if (all || &g_rows[k] == row) g_rows[k].set(gl, o);                                                        \
    } while (0)
    int ok = 1;
    DIRTY();
    ok &= tl_renderer_set_scene(r, s) == TL_OK;
    DIRTY();
    ok &= tl_renderer_render(r, NULL, NULL) == TL_OK;
    DIRTY();
    ok &= tl_renderer_read_output(r, f->out, &(size_t){sizeof f->out}) == TL_OK;
    DIRTY();
    ok &= tl_renderer_read_target(r, TL_TARGET_HDR, f->hdr, &(size_t){sizeof f->hdr}) == TL_OK;
    clean_state(gl);
    gl->ClearNamedFramebufferfv(o->out_fbo, GL_COLOR, 0, (const float[4]){0.1f, 0.2f, 0.3f, 1.0f});
    DIRTY();
    tl_render_output out = {.framebuffer = o->out_fbo, .x = 4, .y = 3, .width = OUT_W - 8, .height = OUT_H - 6};
    ok &= tl_renderer_render_to(r, NULL, &out, NULL) == TL_OK;
    clean_state(gl);
    gl->GetTextureImage(o->out_tex, 0, GL_RGBA, GL_UNSIGNED_BYTE, (GLsizei)sizeof f->app, f->app);
    DIRTY();
    ok &= tl_renderer_apply_fxaa(r, f->out, f->fxaa, &(size_t){sizeof f->fxaa}) == TL_OK;
    clean_state(gl);
    return ok;
#undef DIRTY
}

/* Bytes that differ between two frames, by part. */
static size_t frame_diff(const frame_bytes *a, const frame_bytes *b, const char *label)
{
    size_t d[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < sizeof a->out; i++) d[0] += a->out[i] != b->out[i];
    for (size_t i = 0; i < W * H * 4; i++) d[1] += memcmp(&a->hdr[i], &b->hdr[i], sizeof(float)) != 0;
    for (size_t i = 0; i < sizeof a->app; i++) d[2] += a->app[i] != b->app[i];
    for (size_t i = 0; i < sizeof a->fxaa; i++) d[3] += a->fxaa[i] != b->fxaa[i];
    size_t total = d[0] + d[1] + d[2] + d[3];
    if (total)
        fprintf(stderr, "%s: %zu output bytes, %zu HDR values, %zu render_to bytes, %zu apply_fxaa bytes differ\n",
                label, d[0], d[1], d[2], d[3]);
    return total;
}

static void make_objects(const GladGLContext *gl, app_objects *o)
{
    memset(o, 0, sizeof *o);
    gl->CreateSamplers(1, &o->sampler);
    gl->SamplerParameteri(o->sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl->SamplerParameteri(o->sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl->SamplerParameteri(o->sampler, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
    gl->SamplerParameteri(o->sampler, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
    gl->SamplerParameterf(o->sampler, GL_TEXTURE_LOD_BIAS, 3.0f);
    static const char *const vs = "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n";
    static const char *const fs = "#version 450 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
    o->program = gl->CreateProgram();
    const char *const src[2] = {vs, fs};
    const GLenum type[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
    for (int i = 0; i < 2; i++) {
        GLuint sh = gl->CreateShader(type[i]);
        gl->ShaderSource(sh, 1, &src[i], NULL);
        gl->CompileShader(sh);
        gl->AttachShader(o->program, sh);
        gl->DeleteShader(sh);
    }
    gl->LinkProgram(o->program);
    GLint linked = 0;
    gl->GetProgramiv(o->program, GL_LINK_STATUS, &linked);
    TL_CHECK(linked);
    gl->CreateVertexArrays(1, &o->vao);
    gl->CreateBuffers(1, &o->buffer);
    gl->NamedBufferStorage(o->buffer, 1 << 20, NULL, 0);
    gl->CreateTextures(GL_TEXTURE_2D, 1, &o->texture);
    gl->TextureStorage2D(o->texture, 1, GL_RGBA8, 4, 4);
    gl->CreateTextures(GL_TEXTURE_2D, 1, &o->out_tex);
    gl->TextureStorage2D(o->out_tex, 1, GL_SRGB8_ALPHA8, OUT_W, OUT_H); /* sRGB writes would encode twice */
    gl->CreateFramebuffers(1, &o->out_fbo);
    gl->NamedFramebufferTexture(o->out_fbo, GL_COLOR_ATTACHMENT0, o->out_tex, 0);
}

static void free_objects(const GladGLContext *gl, const app_objects *o)
{
    gl->DeleteSamplers(1, &o->sampler);
    gl->DeleteProgram(o->program);
    gl->DeleteVertexArrays(1, &o->vao);
    gl->DeleteBuffers(1, &o->buffer);
    gl->DeleteTextures(1, &o->texture);
    gl->DeleteTextures(1, &o->out_tex);
    gl->DeleteFramebuffers(1, &o->out_fbo);
}

typedef struct contract_config {
    const char *name;
    tl_renderer_desc d;
} contract_config;

TL_TEST(gl_contract_dirty_state_same_bytes)
{
    if (!ensure_context()) {
        tl_test_failures++;
        return;
    }
    GladGLContext gl;
    char msg[256];
    if (tl__gl_load(&gl, fixture_load, g_ctx, msg, sizeof msg) != TL_OK) {
        fprintf(stderr, "glad: %s\n", msg);
        tl_test_failures++;
        return;
    }
    static contract_scene c;
    build_scene(&c);
    app_objects o;
    make_objects(&gl, &o);
    static frame_bytes clean, dirty;
    const contract_config configs[] = {
        {"thin-lpp volumes d24", {.options.mode = TL_MODE_THIN_LPP,
                                  .options.light_strategy = TL_LIGHT_STRATEGY_VOLUMES}},
        {"thin-lpp tiled compute d32f",
         {.options.mode = TL_MODE_THIN_LPP, .options.light_strategy = TL_LIGHT_STRATEGY_TILED,
          .options.tiled_shading = TL_TILED_SHADING_COMPUTE, .options.depth_format = TL_DEPTH_FORMAT_D32F_REVERSED}},
        {"fat tiled d24", {.options.mode = TL_MODE_FAT, .options.light_strategy = TL_LIGHT_STRATEGY_TILED}},
        {"forward d32f", {.options.mode = TL_MODE_FORWARD, .options.depth_format = TL_DEPTH_FORMAT_D32F_REVERSED}},
        /* unpack_state caught vis-classify's clear of its dispatches from client memory, which Mesa
         * read through the application's GL_UNPACK_* state: garbage counts, a frame that never ended */
        {"visibility d32f", {.options.mode = TL_MODE_VISIBILITY, .options.depth_format = TL_DEPTH_FORMAT_D32F_REVERSED}},
    };
    for (size_t k = 0; k < sizeof configs / sizeof configs[0]; k++) {
        tl_renderer_desc d = configs[k].d;
        d.width = W;
        d.height = H;
        d.options.keep_targets = TL_TARGET_BIT(TL_TARGET_HDR);
        tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = d});
        if (!r) continue;
        TL_CHECK(run_frame(&gl, r, &c.t.s, &o, NULL, 0, &clean));
        size_t lit = 0;
        for (size_t i = 0; i < W * H; i++) lit += clean.out[4 * i] + clean.out[4 * i + 1] + clean.out[4 * i + 2] > 24;
        TL_CHECK(lit > W * H / 2); /* the frame shows the room: a black frame would prove nothing */
        size_t rows_failed = 0;
        for (size_t i = 0; i <= ROWS; i++) {
            char label[128];
            snprintf(label, sizeof label, "%s, %s", configs[k].name, i < ROWS ? g_rows[i].name : "every row at once");
            TL_CHECK(run_frame(&gl, r, &c.t.s, &o, i < ROWS ? &g_rows[i] : NULL, i == ROWS, &dirty));
            rows_failed += frame_diff(&dirty, &clean, label) != 0;
        }
        printf("%s: %zu rows of %zu changed the image\n", configs[k].name, rows_failed, ROWS + 1);
        TL_CHECK_EQ_U(rows_failed, 0);
        tl_renderer_destroy(r);
    }
    free_objects(&gl, &o);
    TL_CHECK_EQ_U(gl.GetError(), GL_NO_ERROR);
}

/* The pixel-store state and pixel buffers an application set survive every call that transfers
 * pixels (set_scene uploads textures, readbacks and apply_fxaa move pixels), and render_to leaves
 * no buffer on the generic uniform and storage bindings. */
TL_TEST(gl_contract_pixel_store_survives)
{
    if (!ensure_context()) {
        tl_test_failures++;
        return;
    }
    GladGLContext gl;
    char msg[256];
    if (tl__gl_load(&gl, fixture_load, g_ctx, msg, sizeof msg) != TL_OK) {
        tl_test_failures++;
        return;
    }
    static contract_scene c;
    build_scene(&c);
    app_objects o;
    make_objects(&gl, &o);
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = W, .height = H, .options.keep_targets = TL_TARGET_BIT(TL_TARGET_HDR)}});
    static frame_bytes f;
    const GLenum names[] = {GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_ROWS, GL_UNPACK_ALIGNMENT,
                            GL_UNPACK_LSB_FIRST,  GL_PACK_ROW_LENGTH,    GL_PACK_SKIP_PIXELS, GL_PACK_SKIP_ROWS,
                            GL_PACK_ALIGNMENT,    GL_PIXEL_UNPACK_BUFFER_BINDING, GL_PIXEL_PACK_BUFFER_BINDING};
    const GLint want[] = {7, 3, 2, 8, GL_TRUE, 5, 1, 2, 8, (GLint)o.buffer, (GLint)o.buffer};
    for (int step = 0; r && step < 5; step++) {
        clean_state(&gl);
        dirty_unpack_state(&gl, &o);
        dirty_pack_state(&gl, &o);
        dirty_unpack_buffer(&gl, &o);
        dirty_pack_buffer(&gl, &o);
        tl_render_output out = {.framebuffer = o.out_fbo};
        switch (step) {
        case 0: TL_CHECK(tl_renderer_set_scene(r, &c.t.s) == TL_OK); break;
        case 1: TL_CHECK(tl_renderer_render_to(r, NULL, &out, NULL) == TL_OK); break;
        case 2: /* the output holds a frame of render's (render_to drew into the application's) */
            TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
            TL_CHECK(tl_renderer_read_output(r, f.out, &(size_t){sizeof f.out}) == TL_OK);
            break;
        case 3: TL_CHECK(tl_renderer_read_target(r, TL_TARGET_HDR, f.hdr, &(size_t){sizeof f.hdr}) == TL_OK); break;
        default: TL_CHECK(tl_renderer_apply_fxaa(r, f.out, f.fxaa, &(size_t){sizeof f.fxaa}) == TL_OK); break;
        }
        for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
            GLint v = -1;
            gl.GetIntegerv(names[i], &v);
            if (v != want[i]) fprintf(stderr, "step %d: state 0x%04x is %d, the application set %d\n", step, names[i], v, want[i]);
            TL_CHECK(v == want[i]);
        }
        if (step == 1) {
            GLint u = -1, s = -1;
            gl.GetIntegerv(GL_UNIFORM_BUFFER_BINDING, &u);
            gl.GetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &s);
            TL_CHECK(u == 0 && s == 0);
        }
    }
    clean_state(&gl);
    tl_renderer_destroy(r);
    free_objects(&gl, &o);
    TL_CHECK_EQ_U(gl.GetError(), GL_NO_ERROR);
}
