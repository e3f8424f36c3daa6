/* The renderer object: creation in the caller's context, plan access, read-back and the FXAA
 * entry point. Scene upload is in scene_upload.c, the frame in frame.c, planning in plan.c. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "light_volumes.h"
#include "renderer_internal.h"

static void *tl__default_alloc(size_t size, void *user) { (void)user; return malloc(size); }
static void tl__default_free(void *p, void *user) { (void)user; free(p); }

void *tl__alloc(const tl_allocator *a, size_t size) { return size ? a->alloc(size, a->user) : NULL; }
void tl__free(const tl_allocator *a, void *p) { if (p) a->free(p, a->user); }

tl_result tl__fail(tl_renderer *r, tl_result res, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->error, sizeof r->error, fmt, ap);
    va_end(ap);
    if (r->desc.logger.fn) r->desc.logger.fn(r->desc.logger.user, TL_LOG_ERROR, r->error);
    return res;
}

const char *tl_renderer_last_error(const tl_renderer *r) { return r ? r->error : "no renderer"; }

void tl_renderer_get_size(const tl_renderer *r, uint32_t *w, uint32_t *h)
{
    if (w) *w = r ? r->desc.width : 0;
    if (h) *h = r ? r->desc.height : 0;
}

tl_result tl_renderer_get_plan(const tl_renderer *r, tl_frame_plan *plan)
{
    if (!r || !plan || !r->has_scene) return TL_ERROR_INVALID_ARGUMENT;
    *plan = r->plan;
    return TL_OK;
}

/* ---- light volumes -------------------------------------------------------------------------- */

static void tl__create_light_vaos(tl_renderer *r)
{
    const GladGLContext *gl = &r->gl;
    tl__volume_mesh mesh;
    for (int v = 0; v < 2; v++) {
        if (v == 0) tl__sphere_volume(&mesh); else tl__cone_volume(&mesh);
        gl->CreateBuffers(1, &r->vbo_volume[v]);
        gl->NamedBufferStorage(r->vbo_volume[v], (GLsizeiptr)(mesh.vertex_count * 12u), mesh.vertices, 0);
        gl->CreateBuffers(1, &r->ibo_volume[v]);
        gl->NamedBufferStorage(r->ibo_volume[v], (GLsizeiptr)(mesh.index_count * 4u), mesh.indices, 0);
        r->volume_index_count[v] = mesh.index_count;
    }
    gl->CreateBuffers(TL__LIGHT_KINDS, r->vbo_instances);
    gl->CreateVertexArrays(TL__LIGHT_KINDS, r->vao_light);
    for (int k = 0; k < TL__LIGHT_KINDS; k++) {
        GLuint vao = r->vao_light[k];
        if (k < 2) {
            gl->VertexArrayVertexBuffer(vao, 0, r->vbo_volume[k], 0, 12);
            gl->VertexArrayElementBuffer(vao, r->ibo_volume[k]);
            gl->EnableVertexArrayAttrib(vao, 0);
            gl->VertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
            gl->VertexArrayAttribBinding(vao, 0, 0);
        }
        gl->VertexArrayBindingDivisor(vao, 1, 1);
        const GLuint offs[4] = {offsetof(tl__instance, position_radius), offsetof(tl__instance, color),
                                offsetof(tl__instance, direction_cos_outer), offsetof(tl__instance, cos_inner)};
        for (GLuint a = 0; a < 4; a++) {
            gl->EnableVertexArrayAttrib(vao, a + 1);
            gl->VertexArrayAttribFormat(vao, a + 1, a == 3 ? 1 : 4, GL_FLOAT, GL_FALSE, offs[a]);
            gl->VertexArrayAttribBinding(vao, a + 1, 1);
        }
        static const char *const names[TL__LIGHT_KINDS] = {"vao.lights.point", "vao.lights.spot", "vao.lights.directional"};
        tl__gl_label(gl, GL_VERTEX_ARRAY, vao, names[k]);
    }
    gl->CreateVertexArrays(1, &r->vao_empty);
    tl__gl_label(gl, GL_VERTEX_ARRAY, r->vao_empty, "vao.fullscreen");
}

/* ---- create / destroy ----------------------------------------------------------------------- */

static GLADapiproc tl__load_thunk(void *user, const char *name)
{
    tl_renderer *r = (tl_renderer *)user;
    return (GLADapiproc)r->desc.get_proc_address(r->desc.get_proc_address_user, name);
}

tl_result tl_renderer_create(const tl_renderer_desc *desc, tl_renderer **out, char *error, size_t error_size)
{
    if (error && error_size) error[0] = '\0';
    if (!out) return TL_ERROR_INVALID_ARGUMENT;
    *out = NULL;
    if (!desc || !desc->get_proc_address) {
        if (error && error_size) snprintf(error, error_size, "renderer: a descriptor with get_proc_address is required");
        return TL_ERROR_INVALID_ARGUMENT;
    }
    tl_allocator a = desc->allocator;
    if (!a.alloc || !a.free) {
        a.alloc = tl__default_alloc;
        a.free = tl__default_free;
    }
    tl_renderer_desc d;
    tl_result res = tl__renderer_desc_resolve(desc, &d);
    if (res != TL_OK) {
        char msg[160];
        snprintf(msg, sizeof msg, "renderer: size %ux%u or an option is out of range (at most %u per side)", d.width,
                 d.height, TL__MAX_SIZE);
        if (error && error_size) snprintf(error, error_size, "%s", msg);
        if (d.logger.fn) d.logger.fn(d.logger.user, TL_LOG_ERROR, msg);
        return res;
    }
    tl_renderer *r = (tl_renderer *)tl__alloc(&a, sizeof *r);
    if (!r) return TL_ERROR_OUT_OF_MEMORY;
    memset(r, 0, sizeof *r);
    r->alloc = a;
    r->desc = d;
    r->desc.allocator = a;
    char msg[512];
    res = tl__gl_load(&r->gl, tl__load_thunk, r, msg, sizeof msg);
    if (res != TL_OK) {
        tl__fail(r, res, "renderer: %s", msg);
    } else {
        GLint max_size = 0;
        r->gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
        if ((GLint)d.width > max_size || (GLint)d.height > max_size)
            res = tl__fail(r, TL_ERROR_LIMIT, "renderer: %ux%u exceeds GL_MAX_TEXTURE_SIZE %d", d.width, d.height,
                           max_size);
    }
    if (res == TL_OK) {
        tl__create_light_vaos(r);
        r->gl.CreateSamplers(1, &r->sampler_linear);
        r->gl.SamplerParameteri(r->sampler_linear, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        r->gl.SamplerParameteri(r->sampler_linear, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        r->gl.SamplerParameteri(r->sampler_linear, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        r->gl.SamplerParameteri(r->sampler_linear, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        for (int p = 0; p < TL_PASS_COUNT; p++) tl__timer_create(&r->gl, tl_pass_name((tl_pass)p), &r->timers[p]);
        r->gl.GenQueries(TL_PASS_COUNT, r->queries);
        r->gl.GenQueries(TL__LIGHT_KINDS, r->light_queries);
        /* until a scene arrives: the plan of an empty scene (tone map and FXAA targets) */
        res = tl__replan(r);
    }
    if (res == TL_OK) {
        GLenum e = r->gl.GetError();
        if (e != GL_NO_ERROR)
            res = tl__fail(r, TL_ERROR_GL, "renderer: %s while creating resources", tl__gl_error_string(e));
    }
    if (res != TL_OK) {
        if (error && error_size) snprintf(error, error_size, "%s", r->error);
        if (r->gl.DeleteProgram) tl_renderer_destroy(r); else tl__free(&a, r);
        return res;
    }
    *out = r;
    return TL_OK;
}

void tl_renderer_destroy(tl_renderer *r)
{
    if (!r) return;
    const GladGLContext *gl = &r->gl;
    tl__release_scene(r);
    tl__targets_destroy(r);
    tl__program_cache_destroy(r);
    if (r->vao_light[0]) gl->DeleteVertexArrays(TL__LIGHT_KINDS, r->vao_light);
    if (r->vao_empty) gl->DeleteVertexArrays(1, &r->vao_empty);
    if (r->vbo_instances[0]) gl->DeleteBuffers(TL__LIGHT_KINDS, r->vbo_instances);
    if (r->vbo_volume[0]) gl->DeleteBuffers(2, r->vbo_volume);
    if (r->ibo_volume[0]) gl->DeleteBuffers(2, r->ibo_volume);
    if (r->ssbo_lights) gl->DeleteBuffers(1, &r->ssbo_lights);
    if (r->ssbo_indices) gl->DeleteBuffers(1, &r->ssbo_indices);
    if (r->sampler_linear) gl->DeleteSamplers(1, &r->sampler_linear);
    if (r->queries[0]) gl->DeleteQueries(TL_PASS_COUNT, r->queries);
    if (r->light_queries[0]) gl->DeleteQueries(TL__LIGHT_KINDS, r->light_queries);
    for (int p = 0; p < TL_PASS_COUNT; p++) tl__timer_destroy(gl, &r->timers[p]);
    tl__free(&r->alloc, r->fwd_indices);
    tl_allocator a = r->alloc;
    tl__free(&a, r);
}

/* ---- readback ------------------------------------------------------------------------------- */

tl_result tl_renderer_apply_fxaa(tl_renderer *r, const uint8_t *rgba, uint8_t *out, size_t size)
{
    if (!r || !rgba || !out) return TL_ERROR_INVALID_ARGUMENT;
    const GladGLContext *gl = &r->gl;
    size_t need = (size_t)r->desc.width * r->desc.height * 4;
    if (size < need) {
        snprintf(r->error, sizeof r->error, "renderer: FXAA buffers of %zu bytes are too small (%zu needed)", size, need);
        return TL_ERROR_LIMIT;
    }
    if (!r->fbo_tonemap_ldr) return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: FXAA is off in this renderer");
    if (!r->prog[TL_PASS_FXAA] || !r->prog_luma) {
        tl_result pres = tl__plan_programs(r);
        if (pres != TL_OK) return pres;
    }
    while (gl->GetError() != GL_NO_ERROR) {}
    /* the image goes into HDR-sized scratch (the output target), luma is added into LDR */
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl->TextureSubImage2D(r->targets[TL_TARGET_OUTPUT].texture, 0, 0, 0, (GLsizei)r->desc.width,
                          (GLsizei)r->desc.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    gl->Viewport(0, 0, (GLsizei)r->desc.width, (GLsizei)r->desc.height);
    gl->Disable(GL_DEPTH_TEST);
    gl->Disable(GL_BLEND);
    gl->Disable(GL_CULL_FACE);
    gl->BindFramebuffer(GL_FRAMEBUFFER, r->fbo_tonemap_ldr);
    gl->UseProgram(r->prog_luma);
    gl->BindVertexArray(r->vao_empty);
    gl->BindTextureUnit(0, r->targets[TL_TARGET_OUTPUT].texture);
    gl->ProgramUniform1i(r->prog_luma, gl->GetUniformLocation(r->prog_luma, "u_image"), 0);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    tl__fxaa_image(r);
    gl->BindVertexArray(0);
    gl->UseProgram(0);
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    tl_result res = tl_renderer_read_output(r, out, size);
    GLenum e = gl->GetError();
    if (res == TL_OK && e != GL_NO_ERROR) {
        snprintf(r->error, sizeof r->error, "renderer: %s in FXAA", tl__gl_error_string(e));
        return TL_ERROR_GL;
    }
    return res;
}

tl_result tl_renderer_read_output(tl_renderer *r, uint8_t *rgba, size_t size)
{
    if (!r || !rgba) return TL_ERROR_INVALID_ARGUMENT;
    char msg[256];
    tl_result res = tl__target_read(&r->gl, &r->targets[TL_TARGET_OUTPUT], GL_RGBA, GL_UNSIGNED_BYTE, rgba, size, msg,
                                    sizeof msg);
    if (res != TL_OK) snprintf(r->error, sizeof r->error, "renderer: reading the output: %s", msg);
    return res;
}

tl_result tl_renderer_read_target(tl_renderer *r, tl_target_id id, float *rgba, size_t count)
{
    if (!r || !rgba || (unsigned)id >= TL_TARGET_COUNT || !r->targets[id].texture) return TL_ERROR_INVALID_ARGUMENT;
    size_t n = (size_t)r->desc.width * r->desc.height;
    if (count < n * 4) {
        snprintf(r->error, sizeof r->error, "renderer: buffer of %zu floats is too small (%zu needed)", count, n * 4);
        return TL_ERROR_LIMIT;
    }
    char msg[256];
    tl_result res;
    if (id == TL_TARGET_DEPTH) {
        /* depth into the upper quarter of the buffer, then spread out */
        float *d = rgba + n * 3;
        res = tl__target_read(&r->gl, &r->targets[id], GL_DEPTH_COMPONENT, GL_FLOAT, d, n * sizeof(float), msg, sizeof msg);
        if (res == TL_OK) {
            tl_projection pr;
            float fov = r->camera.fov_y > 0.0f ? r->camera.fov_y : 1.0471976f;
            tl_projection_perspective(r->desc.depth_format, fov, (float)r->desc.width / (float)r->desc.height,
                                      r->camera.near_z > 0.0f ? r->camera.near_z : 0.1f, r->camera.far_z, &pr);
            for (size_t i = 0; i < n; i++) {
                float dv = d[i];
                float lin = -tl_depth_linearize(&pr, dv);
                rgba[4 * i + 0] = dv;
                rgba[4 * i + 1] = lin;
                rgba[4 * i + 2] = 0.0f;
                rgba[4 * i + 3] = 1.0f;
            }
        }
    } else if (id == TL_TARGET_RT0) {
        uint8_t *bytes = (uint8_t *)tl__alloc(&r->alloc, n * 4);
        if (!bytes) return TL_ERROR_OUT_OF_MEMORY;
        int ten = r->desc.rt0 == TL_RT0_RGB10A2;
        res = tl__target_read(&r->gl, &r->targets[id], GL_RGBA, ten ? GL_UNSIGNED_INT_2_10_10_10_REV : GL_UNSIGNED_BYTE,
                              bytes, n * 4, msg, sizeof msg);
        for (size_t i = 0; res == TL_OK && i < n; i++) {
            float nv[3], g;
            if (ten) {
                uint32_t t;
                memcpy(&t, bytes + 4 * i, 4);
                tl_rt0_decode_rgb10a2(t, nv, &g, NULL);
            } else {
                tl_rt0_decode_rgba8(bytes + 4 * i, nv, &g);
            }
            rgba[4 * i + 0] = nv[0];
            rgba[4 * i + 1] = nv[1];
            rgba[4 * i + 2] = nv[2];
            rgba[4 * i + 3] = g;
        }
        tl__free(&r->alloc, bytes);
    } else {
        res = tl__target_read(&r->gl, &r->targets[id], GL_RGBA, GL_FLOAT, rgba, count * sizeof(float), msg, sizeof msg);
    }
    if (res != TL_OK) tl__fail(r, res, "renderer: reading %s: %s", tl_target_name(id), msg);
    return res;
}
