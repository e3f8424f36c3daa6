/* The light pre-pass renderer: targets, programs, scene upload and the five passes of a frame
 * (shared/DESIGN.md section 2). Runs in the caller's current GL 4.5 core context. */
#define _POSIX_C_SOURCE 199309L
#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "gl/gl.h"
#include "light_volumes.h"
#include "math3d.h"
#include "thinlight/renderer.h"

enum { TL__LIGHT_KINDS = 3 }; /* point, spot, directional: index = type - 1 */

typedef struct tl__instance {
    float position_radius[4];
    float color[4];
    float direction_cos_outer[4];
    float cos_inner;
} tl__instance;

typedef struct tl__gpu_material {
    tl_material m;
    GLuint texture; /* 0: none */
} tl__gpu_material;

struct tl_renderer {
    tl_allocator alloc;
    tl_renderer_desc desc; /* defaults resolved */
    GladGLContext gl;
    char error[4096];

    tl__target targets[TL_TARGET_COUNT];
    GLuint fbo_gbuffer, fbo_lights, fbo_material, fbo_tonemap, fbo_output;
    GLuint prog_gbuffer, prog_material, prog_material_uv, prog_light[TL__LIGHT_KINDS], prog_tonemap, prog_fxaa;
    GLuint prog_luma; /* RGB -> RGB + luma, for tl_renderer_apply_fxaa */
    GLuint sampler_linear;

    GLuint vao_scene, vbo_scene, ibo_scene;
    tl_object *objects;
    size_t object_count;
    tl__gpu_material *materials;
    size_t material_count;
    GLuint *textures;
    size_t texture_count;
    tl_camera camera;
    float ambient[3];
    int has_scene;

    tl_light *lights;
    size_t light_count;
    tl__instance *instances; /* scratch for culled instances */
    GLuint vbo_instances[TL__LIGHT_KINDS];
    size_t instance_capacity[TL__LIGHT_KINDS];
    GLuint vao_light[TL__LIGHT_KINDS];
    GLuint vbo_volume[2], ibo_volume[2];
    uint32_t volume_index_count[2];

    tl__timer timers[TL_PASS_COUNT];
};

static const char *const tl__pass_names[TL_PASS_COUNT] = {"depth-prepass", "gbuffer", "lights", "material",
                                                          "forward", "transparent", "tonemap", "fxaa"};
static const char *const tl__target_names[TL_TARGET_COUNT] = {
    "depth", "rt0", "rt1", "light.diffuse", "light.specular", "fat.position", "fat.normal", "fat.albedo",
    "fat.material", "hdr", "ldr", "output"};

const char *tl_pass_name(tl_pass pass) { return (unsigned)pass < TL_PASS_COUNT ? tl__pass_names[pass] : "unknown"; }
const char *tl_target_name(tl_target_id t) { return (unsigned)t < TL_TARGET_COUNT ? tl__target_names[t] : "unknown"; }

static void *tl__default_alloc(size_t size, void *user) { (void)user; return malloc(size); }
static void tl__default_free(void *p, void *user) { (void)user; free(p); }

static void *tl__alloc(const tl_allocator *a, size_t size) { return size ? a->alloc(size, a->user) : NULL; }
static void tl__free(const tl_allocator *a, void *p) { if (p) a->free(p, a->user); }

const char *tl_renderer_last_error(const tl_renderer *r) { return r ? r->error : "no renderer"; }

void tl_renderer_get_size(const tl_renderer *r, uint32_t *w, uint32_t *h)
{
    if (w) *w = r ? r->desc.width : 0;
    if (h) *h = r ? r->desc.height : 0;
}

static void tl__desc_defaults(tl_renderer_desc *d)
{
    if (!d->width) d->width = 1280;
    if (!d->height) d->height = 720;
    if (d->depth_format == TL_DEPTH_FORMAT_DEFAULT) d->depth_format = TL_DEPTH_FORMAT_D24;
    if (d->rt0 == TL_RT0_DEFAULT) d->rt0 = TL_RT0_RGBA8;
    if (d->light_buffer == TL_LIGHT_BUFFER_DEFAULT) d->light_buffer = TL_LIGHT_BUFFER_EXACT;
    if (d->fxaa == TL_FXAA_DEFAULT) d->fxaa = TL_FXAA_29;
    if (d->fxaa_edge_threshold <= 0.0f) d->fxaa_edge_threshold = 0.166f;
    if (d->fxaa_edge_threshold_min <= 0.0f) d->fxaa_edge_threshold_min = 0.0833f;
    if (d->fxaa_subpix == 0.0f) d->fxaa_subpix = 0.75f;
    if (d->fxaa_subpix < 0.0f) d->fxaa_subpix = 0.0f;
    if (!(d->exposure > 0.0f)) d->exposure = 1.0f;
}

static int tl__reversed(const tl_renderer *r) { return r->desc.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED; }

/* ---- programs ------------------------------------------------------------------------------- */

static tl_result tl__build(tl_renderer *r, const char *label, const char *vs, const char *fs,
                           const char *const *defines, size_t define_count, GLuint *out)
{
    tl__program_desc pd = {0};
    pd.label = label;
    pd.stages[0] = (tl__shader_stage){GL_VERTEX_SHADER, vs, NULL};
    pd.stages[1] = (tl__shader_stage){GL_FRAGMENT_SHADER, fs, NULL};
    pd.defines = defines;
    pd.define_count = define_count;
    char log[2048];
    tl_result res = tl__program_build(&r->gl, &pd, out, log, sizeof log);
    if (res != TL_OK) {
        snprintf(r->error, sizeof r->error, "program %.64s: %.2047s", label, log);
        return res;
    }
    return TL_OK;
}

static tl_result tl__build_programs(tl_renderer *r)
{
    const char *rt0 = r->desc.rt0 == TL_RT0_RGB10A2 ? "TL_RT0_RGB10A2" : "TL_RT0_RGBA8";
    const char *spec = r->desc.light_buffer == TL_LIGHT_BUFFER_EXACT ? "TL_SPECULAR_EXACT" : "TL_SPECULAR_COMPACT";
    tl_result res;
    const char *gdefs[] = {rt0};
    if ((res = tl__build(r, "gbuffer", "gbuffer.vert.glsl", "gbuffer.frag.glsl", gdefs, 1, &r->prog_gbuffer))) return res;
    const char *mdefs[] = {spec, "TL_HAS_UV"};
    if ((res = tl__build(r, "material", "gbuffer.vert.glsl", "material.frag.glsl", mdefs, 1, &r->prog_material))) return res;
    if ((res = tl__build(r, "material.uv", "gbuffer.vert.glsl", "material.frag.glsl", mdefs, 2, &r->prog_material_uv)))
        return res;
    static const char *const type_defs[TL__LIGHT_KINDS] = {"TL_LIGHT_TYPE=1", "TL_LIGHT_TYPE=2", "TL_LIGHT_TYPE=3"};
    static const char *const labels[TL__LIGHT_KINDS] = {"lights.point", "lights.spot", "lights.directional"};
    for (int k = 0; k < TL__LIGHT_KINDS; k++) {
        const char *ldefs[] = {type_defs[k], rt0, spec, "TL_LIGHT_FULLSCREEN"};
        size_t nd = r->desc.fullscreen_lights ? 4 : 3;
        if ((res = tl__build(r, labels[k], "light.vert.glsl", "light.frag.glsl", ldefs, nd, &r->prog_light[k]))) return res;
    }
    if ((res = tl__build(r, "luma", "fullscreen.vert.glsl", "luma.frag.glsl", NULL, 0, &r->prog_luma))) return res;
    if ((res = tl__build(r, "tonemap", "fullscreen.vert.glsl", "tonemap.frag.glsl", NULL, 0, &r->prog_tonemap))) return res;
    const char *fdefs[2];
    size_t nf = 0;
    fdefs[nf++] = r->desc.fxaa == TL_FXAA_12 ? "TL_FXAA_STEPS=5" : "TL_FXAA_STEPS=12";
    if (r->desc.fxaa == TL_FXAA_39) fdefs[nf++] = "TL_FXAA_FINE";
    return tl__build(r, "fxaa", "fullscreen.vert.glsl", "fxaa.frag.glsl", fdefs, nf, &r->prog_fxaa);
}

/* ---- targets -------------------------------------------------------------------------------- */

static tl_result tl__make_target(tl_renderer *r, tl_target_id id, GLenum format)
{
    char label[64], msg[256];
    snprintf(label, sizeof label, "target.%s", tl__target_names[id]);
    tl__target_desc td = {label, format, r->desc.width, r->desc.height};
    tl_result res = tl__target_create(&r->gl, &td, &r->targets[id], msg, sizeof msg);
    if (res != TL_OK) snprintf(r->error, sizeof r->error, "%s: %s", label, msg);
    return res;
}

static tl_result tl__make_fbo(tl_renderer *r, const char *label, const tl_target_id *colors, size_t n, int depth,
                              GLuint *out)
{
    const tl__target *c[4];
    for (size_t i = 0; i < n; i++) c[i] = &r->targets[colors[i]];
    char msg[256];
    tl_result res = tl__framebuffer_create(&r->gl, label, c, n, depth ? &r->targets[TL_TARGET_DEPTH] : NULL, out, msg,
                                           sizeof msg);
    if (res != TL_OK) snprintf(r->error, sizeof r->error, "framebuffer %s: %s", label, msg);
    return res;
}

/* Allocates exactly what the light pre-pass frame reads: no RT1 (the material pass samples
 * materials itself), a specular target only for the exact light-buffer layout. */
static tl_result tl__create_targets(tl_renderer *r)
{
    tl_result res;
    GLenum depth = tl__reversed(r) ? GL_DEPTH32F_STENCIL8 : GL_DEPTH24_STENCIL8;
    if ((res = tl__make_target(r, TL_TARGET_DEPTH, depth))) return res;
    if ((res = tl__make_target(r, TL_TARGET_RT0, r->desc.rt0 == TL_RT0_RGB10A2 ? GL_RGB10_A2 : GL_RGBA8))) return res;
    if ((res = tl__make_target(r, TL_TARGET_LIGHT_DIFFUSE, GL_RGBA16F))) return res;
    int exact = r->desc.light_buffer == TL_LIGHT_BUFFER_EXACT;
    if (exact && (res = tl__make_target(r, TL_TARGET_LIGHT_SPECULAR, GL_RGBA16F))) return res;
    if ((res = tl__make_target(r, TL_TARGET_HDR, GL_RGBA16F))) return res;
    if ((res = tl__make_target(r, TL_TARGET_LDR, GL_RGBA8))) return res;
    if ((res = tl__make_target(r, TL_TARGET_OUTPUT, GL_RGBA8))) return res;

    const tl_target_id g[] = {TL_TARGET_RT0}, l[] = {TL_TARGET_LIGHT_DIFFUSE, TL_TARGET_LIGHT_SPECULAR};
    const tl_target_id m[] = {TL_TARGET_HDR}, t[] = {TL_TARGET_LDR}, o[] = {TL_TARGET_OUTPUT};
    if ((res = tl__make_fbo(r, "fbo.gbuffer", g, 1, 1, &r->fbo_gbuffer))) return res;
    if ((res = tl__make_fbo(r, "fbo.lights", l, exact ? 2 : 1, 1, &r->fbo_lights))) return res;
    if ((res = tl__make_fbo(r, "fbo.material", m, 1, 1, &r->fbo_material))) return res;
    if ((res = tl__make_fbo(r, "fbo.tonemap", t, 1, 0, &r->fbo_tonemap))) return res;
    return tl__make_fbo(r, "fbo.output", o, 1, 0, &r->fbo_output);
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
    tl_renderer_desc d = *desc;
    tl__desc_defaults(&d);
    if (d.width > 16384 || d.height > 16384 || (unsigned)d.depth_format >= TL_DEPTH_FORMAT_COUNT_ ||
        (unsigned)d.rt0 >= TL_RT0_COUNT_ || (unsigned)d.light_buffer >= TL_LIGHT_BUFFER_COUNT_ ||
        (unsigned)d.fxaa >= TL_FXAA_COUNT_) {
        if (error && error_size)
            snprintf(error, error_size, "renderer: size %ux%u or an option is out of range (at most 16384 per side)",
                     d.width, d.height);
        return d.width > 16384 || d.height > 16384 ? TL_ERROR_LIMIT : TL_ERROR_INVALID_ARGUMENT;
    }
    tl_renderer *r = (tl_renderer *)tl__alloc(&a, sizeof *r);
    if (!r) return TL_ERROR_OUT_OF_MEMORY;
    memset(r, 0, sizeof *r);
    r->alloc = a;
    r->desc = d;
    r->desc.allocator = a;
    char msg[512];
    tl_result res = tl__gl_load(&r->gl, tl__load_thunk, r, msg, sizeof msg);
    if (res != TL_OK) {
        snprintf(r->error, sizeof r->error, "renderer: %s", msg);
    } else {
        GLint max_size = 0;
        r->gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
        if ((GLint)d.width > max_size || (GLint)d.height > max_size) {
            snprintf(r->error, sizeof r->error, "renderer: %ux%u exceeds GL_MAX_TEXTURE_SIZE %d", d.width, d.height,
                     max_size);
            res = TL_ERROR_LIMIT;
        }
    }
    if (res == TL_OK) res = tl__create_targets(r);
    if (res == TL_OK) res = tl__build_programs(r);
    if (res == TL_OK) {
        tl__create_light_vaos(r);
        r->gl.CreateSamplers(1, &r->sampler_linear);
        r->gl.SamplerParameteri(r->sampler_linear, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        r->gl.SamplerParameteri(r->sampler_linear, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        r->gl.SamplerParameteri(r->sampler_linear, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        r->gl.SamplerParameteri(r->sampler_linear, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        for (int p = 0; p < TL_PASS_COUNT; p++) tl__timer_create(&r->gl, tl__pass_names[p], &r->timers[p]);
        GLenum e = r->gl.GetError();
        if (e != GL_NO_ERROR) {
            snprintf(r->error, sizeof r->error, "renderer: %s while creating resources", tl__gl_error_string(e));
            res = TL_ERROR_GL;
        }
    }
    if (res != TL_OK) {
        if (error && error_size) snprintf(error, error_size, "%s", r->error);
        if (r->gl.DeleteProgram) tl_renderer_destroy(r); else tl__free(&a, r);
        return res;
    }
    *out = r;
    return TL_OK;
}

static void tl__release_scene(tl_renderer *r)
{
    const GladGLContext *gl = &r->gl;
    if (r->vao_scene) gl->DeleteVertexArrays(1, &r->vao_scene);
    if (r->vbo_scene) gl->DeleteBuffers(1, &r->vbo_scene);
    if (r->ibo_scene) gl->DeleteBuffers(1, &r->ibo_scene);
    if (r->textures) {
        gl->DeleteTextures((GLsizei)r->texture_count, r->textures);
        tl__free(&r->alloc, r->textures);
    }
    tl__free(&r->alloc, r->objects);
    tl__free(&r->alloc, r->materials);
    tl__free(&r->alloc, r->lights);
    tl__free(&r->alloc, r->instances);
    r->vao_scene = r->vbo_scene = r->ibo_scene = 0;
    r->textures = NULL;
    r->objects = NULL;
    r->materials = NULL;
    r->lights = NULL;
    r->instances = NULL;
    r->texture_count = r->object_count = r->material_count = r->light_count = 0;
    r->has_scene = 0;
}

void tl_renderer_destroy(tl_renderer *r)
{
    if (!r) return;
    const GladGLContext *gl = &r->gl;
    tl__release_scene(r);
    for (int t = 0; t < TL_TARGET_COUNT; t++) tl__target_destroy(gl, &r->targets[t]);
    GLuint *fbos[] = {&r->fbo_gbuffer, &r->fbo_lights, &r->fbo_material, &r->fbo_tonemap, &r->fbo_output};
    for (size_t i = 0; i < sizeof fbos / sizeof fbos[0]; i++) tl__framebuffer_destroy(gl, fbos[i]);
    GLuint progs[] = {r->prog_gbuffer, r->prog_material, r->prog_material_uv, r->prog_light[0], r->prog_light[1],
                      r->prog_light[2], r->prog_tonemap, r->prog_fxaa, r->prog_luma};
    for (size_t i = 0; i < sizeof progs / sizeof progs[0]; i++)
        if (progs[i]) gl->DeleteProgram(progs[i]);
    if (r->vao_light[0]) gl->DeleteVertexArrays(TL__LIGHT_KINDS, r->vao_light);
    if (r->vbo_instances[0]) gl->DeleteBuffers(TL__LIGHT_KINDS, r->vbo_instances);
    if (r->vbo_volume[0]) gl->DeleteBuffers(2, r->vbo_volume);
    if (r->ibo_volume[0]) gl->DeleteBuffers(2, r->ibo_volume);
    if (r->sampler_linear) gl->DeleteSamplers(1, &r->sampler_linear);
    for (int p = 0; p < TL_PASS_COUNT; p++) tl__timer_destroy(gl, &r->timers[p]);
    tl_allocator a = r->alloc;
    tl__free(&a, r);
}

/* ---- scene ---------------------------------------------------------------------------------- */

tl_result tl_renderer_set_lights(tl_renderer *r, const tl_light *lights, size_t count)
{
    if (!r || (count && !lights)) return TL_ERROR_INVALID_ARGUMENT;
    if (count > (size_t)1 << 20) {
        snprintf(r->error, sizeof r->error, "renderer: %zu lights exceed the limit of %u", count, 1u << 20);
        return TL_ERROR_LIMIT;
    }
    for (size_t i = 0; i < count; i++) {
        const tl_light *l = &lights[i];
        int bad = (unsigned)l->type >= TL_LIGHT_TYPE_COUNT_;
        for (int k = 0; k < 3; k++)
            bad |= !isfinite(l->position[k]) || !isfinite(l->direction[k]) || !isfinite(l->color[k]);
        if (l->type != TL_LIGHT_DIRECTIONAL) bad |= !(l->radius >= 0.0f) || !isfinite(l->radius);
        if (bad) {
            snprintf(r->error, sizeof r->error, "renderer: light %zu has a non-finite or invalid field", i);
            return TL_ERROR_INVALID_ARGUMENT;
        }
    }
    tl_light *copy = (tl_light *)tl__alloc(&r->alloc, count * sizeof *copy);
    tl__instance *inst = (tl__instance *)tl__alloc(&r->alloc, count * sizeof *inst);
    if (count && (!copy || !inst)) {
        tl__free(&r->alloc, copy);
        tl__free(&r->alloc, inst);
        snprintf(r->error, sizeof r->error, "renderer: out of memory for %zu lights", count);
        return TL_ERROR_OUT_OF_MEMORY;
    }
    if (count) memcpy(copy, lights, count * sizeof *copy);
    tl__free(&r->alloc, r->lights);
    tl__free(&r->alloc, r->instances);
    r->lights = copy;
    r->instances = inst;
    r->light_count = count;
    return TL_OK;
}

tl_result tl_renderer_set_scene(tl_renderer *r, const tl_scene *s)
{
    if (!r || !s) return TL_ERROR_INVALID_ARGUMENT;
    if ((s->vertex_count && !s->vertices) || (s->index_count && !s->indices) || (s->object_count && !s->objects) ||
        (s->material_count && !s->materials) || (s->texture_count && !s->textures) || s->index_count % 3 ||
        s->vertex_count > UINT32_MAX || s->index_count > ((size_t)1 << 31) / 4) {
        snprintf(r->error, sizeof r->error, "renderer: inconsistent scene arrays");
        return TL_ERROR_INVALID_ARGUMENT;
    }
    for (size_t i = 0; i < s->index_count; i++)
        if (s->indices[i] >= s->vertex_count) {
            snprintf(r->error, sizeof r->error, "renderer: index %zu (%u) is out of range (%zu vertices)", i,
                     s->indices[i], s->vertex_count);
            return TL_ERROR_INVALID_ARGUMENT;
        }
    for (size_t i = 0; i < s->object_count; i++) {
        const tl_object *o = &s->objects[i];
        if ((size_t)o->first_index + o->index_count > s->index_count || o->material >= s->material_count) {
            snprintf(r->error, sizeof r->error, "renderer: object %zu has an index range or material out of range", i);
            return TL_ERROR_INVALID_ARGUMENT;
        }
    }
    tl__release_scene(r);
    const GladGLContext *gl = &r->gl;
    tl_result res = tl_renderer_set_lights(r, s->lights, s->light_count);
    if (res != TL_OK) return res;
    r->objects = (tl_object *)tl__alloc(&r->alloc, s->object_count * sizeof *r->objects);
    r->materials = (tl__gpu_material *)tl__alloc(&r->alloc, s->material_count * sizeof *r->materials);
    r->textures = (GLuint *)tl__alloc(&r->alloc, s->texture_count * sizeof *r->textures);
    if ((s->object_count && !r->objects) || (s->material_count && !r->materials) || (s->texture_count && !r->textures)) {
        tl__release_scene(r);
        snprintf(r->error, sizeof r->error, "renderer: out of memory for the scene");
        return TL_ERROR_OUT_OF_MEMORY;
    }
    if (s->object_count) memcpy(r->objects, s->objects, s->object_count * sizeof *r->objects);
    r->object_count = s->object_count;
    r->texture_count = s->texture_count;
    for (size_t t = 0; t < s->texture_count; t++) {
        const tl_texture *tx = &s->textures[t];
        r->textures[t] = 0;
        if (!tx->rgba || !tx->width || !tx->height || tx->width > 16384 || tx->height > 16384) continue;
        GLuint id;
        gl->CreateTextures(GL_TEXTURE_2D, 1, &id);
        uint32_t levels = 1, m = tx->width > tx->height ? tx->width : tx->height;
        while (m >>= 1) levels++;
        gl->TextureStorage2D(id, (GLsizei)levels, GL_SRGB8_ALPHA8, (GLsizei)tx->width, (GLsizei)tx->height);
        gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
        gl->TextureSubImage2D(id, 0, 0, 0, (GLsizei)tx->width, (GLsizei)tx->height, GL_RGBA, GL_UNSIGNED_BYTE, tx->rgba);
        gl->GenerateTextureMipmap(id);
        gl->TextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        gl->TextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        gl->TextureParameteri(id, GL_TEXTURE_WRAP_S, GL_REPEAT);
        gl->TextureParameteri(id, GL_TEXTURE_WRAP_T, GL_REPEAT);
        tl__gl_label(gl, GL_TEXTURE, id, tx->name[0] ? tx->name : "texture");
        r->textures[t] = id;
    }
    for (size_t i = 0; i < s->material_count; i++) {
        r->materials[i].m = s->materials[i];
        uint32_t t = s->materials[i].albedo_texture;
        r->materials[i].texture = t < s->texture_count ? r->textures[t] : 0;
    }
    r->material_count = s->material_count;
    gl->CreateBuffers(1, &r->vbo_scene);
    gl->NamedBufferStorage(r->vbo_scene, (GLsizeiptr)(s->vertex_count * sizeof(tl_vertex)), s->vertices, 0);
    gl->CreateBuffers(1, &r->ibo_scene);
    gl->NamedBufferStorage(r->ibo_scene, (GLsizeiptr)(s->index_count * 4u), s->indices, 0);
    gl->CreateVertexArrays(1, &r->vao_scene);
    gl->VertexArrayVertexBuffer(r->vao_scene, 0, r->vbo_scene, 0, sizeof(tl_vertex));
    gl->VertexArrayElementBuffer(r->vao_scene, r->ibo_scene);
    const GLuint offs[3] = {offsetof(tl_vertex, position), offsetof(tl_vertex, normal), offsetof(tl_vertex, uv)};
    const GLint sizes[3] = {3, 3, 2};
    for (GLuint a = 0; a < 3; a++) {
        gl->EnableVertexArrayAttrib(r->vao_scene, a);
        gl->VertexArrayAttribFormat(r->vao_scene, a, sizes[a], GL_FLOAT, GL_FALSE, offs[a]);
        gl->VertexArrayAttribBinding(r->vao_scene, a, 0);
    }
    tl__gl_label(gl, GL_VERTEX_ARRAY, r->vao_scene, "vao.scene");
    r->camera = s->camera;
    memcpy(r->ambient, s->ambient, sizeof r->ambient);
    r->has_scene = 1;
    GLenum e = gl->GetError();
    if (e != GL_NO_ERROR) {
        snprintf(r->error, sizeof r->error, "renderer: %s while uploading the scene", tl__gl_error_string(e));
        return TL_ERROR_GL;
    }
    return TL_OK;
}

/* ---- the frame ------------------------------------------------------------------------------ */

typedef struct tl__view {
    tl__mat4 view, proj, view_proj;
    tl_projection projection;
    float planes[5][4];
    float clear_depth;
} tl__view;

static tl_result tl__setup_view(tl_renderer *r, const tl_camera *c, tl__view *v)
{
    float up[3] = {c->up[0], c->up[1], c->up[2]};
    if (up[0] == 0.0f && up[1] == 0.0f && up[2] == 0.0f) up[1] = 1.0f;
    float fov = c->fov_y > 0.0f ? c->fov_y : 1.0471976f;
    float near_z = c->near_z > 0.0f ? c->near_z : 0.1f;
    tl_result res = tl_projection_perspective(r->desc.depth_format, fov, (float)r->desc.width / (float)r->desc.height,
                                              near_z, c->far_z, &v->projection);
    if (res != TL_OK) {
        snprintf(r->error, sizeof r->error, "renderer: invalid camera (fov %g, near %g, far %g)", (double)c->fov_y,
                 (double)c->near_z, (double)c->far_z);
        return res;
    }
    for (int k = 0; k < 3; k++)
        if (!isfinite(c->position[k]) || !isfinite(c->target[k])) {
            snprintf(r->error, sizeof r->error, "renderer: camera position or target is not finite");
            return TL_ERROR_INVALID_ARGUMENT;
        }
    v->view = tl__mat4_look_at(c->position, c->target, up);
    memcpy(v->proj.m, v->projection.m, sizeof v->proj.m);
    v->view_proj = tl__mat4_mul(&v->proj, &v->view);
    tl__frustum_planes(&v->view_proj, v->planes);
    if (tl__reversed(r)) { /* [0,1] clip: the near plane is w - z >= 0 */
        const float *m = v->view_proj.m;
        for (int i = 0; i < 4; i++) v->planes[4][i] = m[i * 4 + 3] - m[i * 4 + 2];
        float l = sqrtf(v->planes[4][0] * v->planes[4][0] + v->planes[4][1] * v->planes[4][1] +
                        v->planes[4][2] * v->planes[4][2]);
        for (int i = 0; i < 4; i++) v->planes[4][i] /= l;
    }
    v->clear_depth = tl__reversed(r) ? 0.0f : 1.0f;
    return TL_OK;
}

static void tl__uniform_mat4(const GladGLContext *gl, GLuint p, const char *name, const tl__mat4 *m)
{
    gl->ProgramUniformMatrix4fv(p, gl->GetUniformLocation(p, name), 1, GL_FALSE, m->m);
}

static void tl__draw_objects(tl_renderer *r, const tl__view *v, int material_pass, tl_frame_stats *st)
{
    const GladGLContext *gl = &r->gl;
    gl->BindVertexArray(r->vao_scene);
    GLuint last = 0;
    for (size_t i = 0; i < r->object_count; i++) {
        const tl_object *o = &r->objects[i];
        if (!tl__box_visible((float(*)[4])v->planes, o->bounds_min, o->bounds_max)) continue;
        const tl__gpu_material *mat = &r->materials[o->material];
        GLuint p = r->prog_gbuffer;
        if (material_pass) p = mat->texture ? r->prog_material_uv : r->prog_material;
        if (p != last) {
            gl->UseProgram(p);
            tl__uniform_mat4(gl, p, "u_view_proj", &v->view_proj);
            last = p;
        }
        tl__mat4 model;
        memcpy(model.m, o->transform, sizeof model.m);
        tl__mat4 mv = tl__mat4_mul(&v->view, &model);
        float nm[9];
        tl__normal_matrix(&mv, nm);
        tl__uniform_mat4(gl, p, "u_model", &model);
        gl->ProgramUniformMatrix3fv(p, gl->GetUniformLocation(p, "u_normal_view"), 1, GL_FALSE, nm);
        if (!material_pass) {
            gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_gloss"), mat->m.gloss);
        } else {
            gl->ProgramUniform3fv(p, gl->GetUniformLocation(p, "u_albedo"), 1, mat->m.albedo);
            gl->ProgramUniform3fv(p, gl->GetUniformLocation(p, "u_specular"), 1, mat->m.specular);
            gl->ProgramUniform3fv(p, gl->GetUniformLocation(p, "u_emissive"), 1, mat->m.emissive);
            if (mat->texture) gl->BindTextureUnit(2, mat->texture);
        }
        gl->Disable(GL_CULL_FACE);
        if (!(mat->m.flags & TL_MATERIAL_DOUBLE_SIDED)) gl->Enable(GL_CULL_FACE);
        gl->DrawElements(GL_TRIANGLES, (GLsizei)o->index_count, GL_UNSIGNED_INT,
                         (const void *)(uintptr_t)(o->first_index * 4u));
        if (st) {
            st->draw_calls++;
            if (!material_pass) st->objects_drawn++;
        }
    }
    gl->Disable(GL_CULL_FACE);
}

static void tl__set_gbuffer_read_uniforms(tl_renderer *r, GLuint p, const tl__view *v)
{
    const GladGLContext *gl = &r->gl;
    const float *m = v->projection.m;
    gl->ProgramUniform4f(p, gl->GetUniformLocation(p, "u_depth_params"), m[10], m[14], m[11], tl__reversed(r) ? 1.0f : 0.0f);
    gl->ProgramUniform4f(p, gl->GetUniformLocation(p, "u_ray_params"), m[0], m[5], m[8], m[9]);
    gl->ProgramUniform2f(p, gl->GetUniformLocation(p, "u_inv_size"), 1.0f / (float)r->desc.width,
                         1.0f / (float)r->desc.height);
    gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_clear_depth"), v->clear_depth);
    gl->ProgramUniform1i(p, gl->GetUniformLocation(p, "u_depth"), 0);
    gl->ProgramUniform1i(p, gl->GetUniformLocation(p, "u_rt0"), 1);
    tl__uniform_mat4(gl, p, "u_view", &v->view);
    tl__uniform_mat4(gl, p, "u_view_proj", &v->view_proj);
}

/* Culls lights against the frustum and uploads the visible ones of each type as instances. */
static void tl__upload_instances(tl_renderer *r, const tl__view *v, size_t counts[TL__LIGHT_KINDS])
{
    const GladGLContext *gl = &r->gl;
    size_t base[TL__LIGHT_KINDS] = {0}, n = 0;
    for (int k = 0; k < TL__LIGHT_KINDS; k++) {
        base[k] = n;
        counts[k] = 0;
        for (size_t i = 0; i < r->light_count; i++) {
            const tl_light *l = &r->lights[i];
            int type = l->type == TL_LIGHT_DEFAULT ? TL_LIGHT_POINT : (int)l->type;
            if (type - 1 != k) continue;
            if (type != TL_LIGHT_DIRECTIONAL &&
                (l->radius <= 0.0f || !tl__sphere_visible((float(*)[4])v->planes, l->position, l->radius * 1.2f)))
                continue;
            tl__instance *in = &r->instances[n++];
            float dir[3] = {l->direction[0], l->direction[1], l->direction[2]};
            tl__vec3_normalize(dir);
            if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f) dir[1] = -1.0f;
            in->position_radius[0] = l->position[0];
            in->position_radius[1] = l->position[1];
            in->position_radius[2] = l->position[2];
            in->position_radius[3] = l->radius;
            in->color[0] = l->color[0];
            in->color[1] = l->color[1];
            in->color[2] = l->color[2];
            in->color[3] = 0.0f;
            memcpy(in->direction_cos_outer, dir, sizeof dir);
            in->direction_cos_outer[3] = type == TL_LIGHT_SPOT ? l->cos_outer : -1.0f;
            in->cos_inner = type == TL_LIGHT_SPOT ? l->cos_inner : 1.0f;
            counts[k]++;
        }
    }
    for (int k = 0; k < TL__LIGHT_KINDS; k++) {
        if (!counts[k]) continue;
        size_t bytes = counts[k] * sizeof(tl__instance);
        if (bytes > r->instance_capacity[k]) {
            /* immutable storage can't grow: replace the buffer and rebind it */
            gl->DeleteBuffers(1, &r->vbo_instances[k]);
            gl->CreateBuffers(1, &r->vbo_instances[k]);
            gl->NamedBufferStorage(r->vbo_instances[k], (GLsizeiptr)bytes, NULL, GL_DYNAMIC_STORAGE_BIT);
            r->instance_capacity[k] = bytes;
        }
        gl->NamedBufferSubData(r->vbo_instances[k], 0, (GLsizeiptr)bytes, &r->instances[base[k]]);
        gl->VertexArrayVertexBuffer(r->vao_light[k], 1, r->vbo_instances[k], 0, sizeof(tl__instance));
    }
}

static void tl__fxaa_pass(tl_renderer *r)
{
    const GladGLContext *gl = &r->gl;
    GLsizei w = (GLsizei)r->desc.width, h = (GLsizei)r->desc.height;
    gl->Viewport(0, 0, w, h);
    if (r->desc.fxaa == TL_FXAA_OFF) {
        gl->BlitNamedFramebuffer(r->fbo_tonemap, r->fbo_output, 0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        return;
    }
    GLuint p = r->prog_fxaa;
    gl->BindFramebuffer(GL_FRAMEBUFFER, r->fbo_output);
    gl->UseProgram(p);
    gl->BindVertexArray(r->vao_light[2]);
    gl->BindTextureUnit(0, r->targets[TL_TARGET_LDR].texture);
    gl->BindSampler(0, r->sampler_linear);
    gl->ProgramUniform1i(p, gl->GetUniformLocation(p, "u_ldr"), 0);
    gl->ProgramUniform2f(p, gl->GetUniformLocation(p, "u_rcp_size"), 1.0f / (float)w, 1.0f / (float)h);
    gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_edge_threshold"), r->desc.fxaa_edge_threshold);
    gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_edge_threshold_min"), r->desc.fxaa_edge_threshold_min);
    gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_subpix"), r->desc.fxaa_subpix);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    gl->BindSampler(0, 0);
}

static double tl__now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

tl_result tl_renderer_render(tl_renderer *r, const tl_camera *camera, tl_frame_stats *stats)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    if (!r->has_scene) {
        snprintf(r->error, sizeof r->error, "renderer: no scene (call tl_renderer_set_scene first)");
        return TL_ERROR_INVALID_ARGUMENT;
    }
    tl_frame_stats st;
    memset(&st, 0, sizeof st);
    tl__view v;
    tl_result res = tl__setup_view(r, camera ? camera : &r->camera, &v);
    if (res != TL_OK) return res;
    const GladGLContext *gl = &r->gl;
    double t0 = tl__now_ms();
    GLsizei w = (GLsizei)r->desc.width, h = (GLsizei)r->desc.height;
    int rev = tl__reversed(r);
    while (gl->GetError() != GL_NO_ERROR) {} /* errors from the caller's code are not ours */

    gl->Viewport(0, 0, w, h);
    if (rev) gl->ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    gl->Disable(GL_BLEND);
    gl->Disable(GL_STENCIL_TEST);
    gl->Disable(GL_SCISSOR_TEST);
    gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    /* 1: G-buffer */
    tl__gl_debug_push(gl, "gbuffer");
    tl__timer_begin(gl, &r->timers[TL_PASS_GBUFFER]);
    gl->BindFramebuffer(GL_FRAMEBUFFER, r->fbo_gbuffer);
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthMask(GL_TRUE);
    gl->DepthFunc(rev ? GL_GREATER : GL_LESS);
    const float zero[4] = {0, 0, 0, 0};
    gl->ClearNamedFramebufferfv(r->fbo_gbuffer, GL_COLOR, 0, zero);
    gl->ClearNamedFramebufferfi(r->fbo_gbuffer, GL_DEPTH_STENCIL, 0, v.clear_depth, 0);
    tl__draw_objects(r, &v, 0, &st);
    tl__timer_end(gl, &r->timers[TL_PASS_GBUFFER]);
    tl__gl_debug_pop(gl);

    /* 2: light accumulation: back faces of each volume where the scene lies in front of them;
     * depth clamp keeps volumes cut by the far plane, back faces survive a camera inside. */
    tl__gl_debug_push(gl, "lights");
    tl__timer_begin(gl, &r->timers[TL_PASS_LIGHTS]);
    gl->BindFramebuffer(GL_FRAMEBUFFER, r->fbo_lights);
    gl->ClearNamedFramebufferfv(r->fbo_lights, GL_COLOR, 0, zero);
    if (r->desc.light_buffer == TL_LIGHT_BUFFER_EXACT) gl->ClearNamedFramebufferfv(r->fbo_lights, GL_COLOR, 1, zero);
    gl->DepthMask(GL_FALSE);
    gl->Enable(GL_BLEND);
    gl->BlendFunc(GL_ONE, GL_ONE);
    gl->BlendEquation(GL_FUNC_ADD);
    gl->BindTextureUnit(0, r->targets[TL_TARGET_DEPTH].texture);
    gl->BindTextureUnit(1, r->targets[TL_TARGET_RT0].texture);
    size_t counts[TL__LIGHT_KINDS];
    tl__upload_instances(r, &v, counts);
    for (int k = 0; k < TL__LIGHT_KINDS; k++) {
        st.lights_drawn[k + 1] = (uint32_t)counts[k];
        if (!counts[k]) continue;
        GLuint p = r->prog_light[k];
        gl->UseProgram(p);
        tl__set_gbuffer_read_uniforms(r, p, &v);
        gl->BindVertexArray(r->vao_light[k]);
        if (k == 2 || r->desc.fullscreen_lights) {
            gl->Disable(GL_DEPTH_TEST);
            gl->Disable(GL_CULL_FACE);
            gl->DrawArraysInstanced(GL_TRIANGLES, 0, 3, (GLsizei)counts[k]);
        } else {
            gl->Enable(GL_DEPTH_TEST);
            gl->DepthFunc(rev ? GL_LEQUAL : GL_GEQUAL);
            gl->Enable(GL_DEPTH_CLAMP);
            gl->Enable(GL_CULL_FACE);
            gl->CullFace(GL_FRONT);
            gl->DrawElementsInstanced(GL_TRIANGLES, (GLsizei)r->volume_index_count[k], GL_UNSIGNED_INT, NULL,
                                      (GLsizei)counts[k]);
            gl->Disable(GL_DEPTH_CLAMP);
            gl->CullFace(GL_BACK);
            gl->Disable(GL_CULL_FACE);
        }
        st.draw_calls++;
    }
    gl->Disable(GL_BLEND);
    tl__timer_end(gl, &r->timers[TL_PASS_LIGHTS]);
    tl__gl_debug_pop(gl);

    /* 3: material pass, depth EQUAL against the G-buffer's depth */
    tl__gl_debug_push(gl, "material");
    tl__timer_begin(gl, &r->timers[TL_PASS_MATERIAL]);
    gl->BindFramebuffer(GL_FRAMEBUFFER, r->fbo_material);
    gl->ClearNamedFramebufferfv(r->fbo_material, GL_COLOR, 0, zero);
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_EQUAL);
    gl->DepthMask(GL_FALSE);
    gl->BindTextureUnit(0, r->targets[TL_TARGET_LIGHT_DIFFUSE].texture);
    gl->BindTextureUnit(1, r->targets[r->desc.light_buffer == TL_LIGHT_BUFFER_EXACT ? TL_TARGET_LIGHT_SPECULAR
                                                                                     : TL_TARGET_LIGHT_DIFFUSE].texture);
    GLuint mp[2] = {r->prog_material, r->prog_material_uv};
    for (int i = 0; i < 2; i++) {
        gl->ProgramUniform1i(mp[i], gl->GetUniformLocation(mp[i], "u_light_diffuse"), 0);
        gl->ProgramUniform1i(mp[i], gl->GetUniformLocation(mp[i], "u_light_specular"), 1);
        gl->ProgramUniform1i(mp[i], gl->GetUniformLocation(mp[i], "u_albedo_texture"), 2);
        gl->ProgramUniform3fv(mp[i], gl->GetUniformLocation(mp[i], "u_ambient"), 1, r->ambient);
    }
    tl__draw_objects(r, &v, 1, &st);
    gl->Disable(GL_DEPTH_TEST);
    tl__timer_end(gl, &r->timers[TL_PASS_MATERIAL]);
    tl__gl_debug_pop(gl);
    if (rev) gl->ClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);

    /* 4: tone map */
    tl__gl_debug_push(gl, "tonemap");
    tl__timer_begin(gl, &r->timers[TL_PASS_TONEMAP]);
    gl->BindFramebuffer(GL_FRAMEBUFFER, r->fbo_tonemap);
    gl->UseProgram(r->prog_tonemap);
    gl->BindTextureUnit(0, r->targets[TL_TARGET_HDR].texture);
    gl->ProgramUniform1i(r->prog_tonemap, gl->GetUniformLocation(r->prog_tonemap, "u_hdr"), 0);
    gl->ProgramUniform1f(r->prog_tonemap, gl->GetUniformLocation(r->prog_tonemap, "u_exposure"), r->desc.exposure);
    gl->BindVertexArray(r->vao_light[2]);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    tl__timer_end(gl, &r->timers[TL_PASS_TONEMAP]);
    tl__gl_debug_pop(gl);

    /* 5: FXAA (or a plain copy when off) */
    tl__gl_debug_push(gl, "fxaa");
    tl__timer_begin(gl, &r->timers[TL_PASS_FXAA]);
    tl__fxaa_pass(r);
    tl__timer_end(gl, &r->timers[TL_PASS_FXAA]);
    tl__gl_debug_pop(gl);

    gl->BindVertexArray(0);
    gl->UseProgram(0);
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl->DepthMask(GL_TRUE);
    gl->Finish();
    st.cpu_ms = tl__now_ms() - t0;
    for (int p = 0; p < TL_PASS_COUNT; p++) {
        uint64_t ns = 0;
        st.pass_ms[p] = tl__timer_read(gl, &r->timers[p], true, NULL, &ns) == TL_OK ? (double)ns * 1e-6 : -1.0;
        if (st.pass_ms[p] > 0.0) st.gpu_ms += st.pass_ms[p];
    }
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        st.target_bytes[t] = r->targets[t].bytes;
        st.total_target_bytes += r->targets[t].bytes;
    }
    st.gbuffer_bytes = st.target_bytes[TL_TARGET_DEPTH] + st.target_bytes[TL_TARGET_RT0] + st.target_bytes[TL_TARGET_RT1];
    st.light_buffer_bytes = st.target_bytes[TL_TARGET_LIGHT_DIFFUSE] + st.target_bytes[TL_TARGET_LIGHT_SPECULAR];
    if (stats) *stats = st;
    GLenum e = gl->GetError();
    if (e != GL_NO_ERROR) {
        snprintf(r->error, sizeof r->error, "renderer: %s during the frame", tl__gl_error_string(e));
        return TL_ERROR_GL;
    }
    return TL_OK;
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
    while (gl->GetError() != GL_NO_ERROR) {}
    /* the image goes into HDR-sized scratch (the output target), luma is added into LDR */
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl->TextureSubImage2D(r->targets[TL_TARGET_OUTPUT].texture, 0, 0, 0, (GLsizei)r->desc.width,
                          (GLsizei)r->desc.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    gl->Viewport(0, 0, (GLsizei)r->desc.width, (GLsizei)r->desc.height);
    gl->Disable(GL_DEPTH_TEST);
    gl->Disable(GL_BLEND);
    gl->Disable(GL_CULL_FACE);
    gl->BindFramebuffer(GL_FRAMEBUFFER, r->fbo_tonemap);
    gl->UseProgram(r->prog_luma);
    gl->BindVertexArray(r->vao_light[2]);
    gl->BindTextureUnit(0, r->targets[TL_TARGET_OUTPUT].texture);
    gl->ProgramUniform1i(r->prog_luma, gl->GetUniformLocation(r->prog_luma, "u_image"), 0);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    tl__fxaa_pass(r);
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
    if (res != TL_OK) snprintf(r->error, sizeof r->error, "renderer: reading %s: %s", tl__target_names[id], msg);
    return res;
}
