/* One frame: the plan's passes in order (shared/DESIGN.md section 2), with a timer query and a
 * samples-passed query around each, and the bytes-moved estimate of docs/bandwidth.md. */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "renderer_internal.h"

static int tl__reversed(const tl_renderer *r) { return r->desc.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED; }

tl_result tl__setup_view(tl_renderer *r, const tl_camera *c, tl__view *v)
{
    float up[3] = {c->up[0], c->up[1], c->up[2]};
    if (up[0] == 0.0f && up[1] == 0.0f && up[2] == 0.0f) up[1] = 1.0f;
    float fov = c->fov_y > 0.0f ? c->fov_y : 1.0471976f;
    float near_z = c->near_z > 0.0f ? c->near_z : 0.1f;
    tl_result res = tl_projection_perspective(r->desc.depth_format, fov, (float)r->desc.width / (float)r->desc.height,
                                              near_z, c->far_z, &v->projection);
    if (res != TL_OK)
        return tl__fail(r, res, "renderer: invalid camera (fov %g, near %g, far %g)", (double)c->fov_y,
                        (double)c->near_z, (double)c->far_z);
    for (int k = 0; k < 3; k++)
        if (!isfinite(c->position[k]) || !isfinite(c->target[k]))
            return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: camera position or target is not finite");
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
    memcpy(v->eye, c->position, sizeof v->eye);
    v->near_z = near_z;
    return TL_OK;
}

static void tl__uniform_mat4(const GladGLContext *gl, GLuint p, const char *name, const tl__mat4 *m)
{
    gl->ProgramUniformMatrix4fv(p, gl->GetUniformLocation(p, name), 1, GL_FALSE, m->m);
}

/* ---- geometry passes ------------------------------------------------------------------------ */

typedef enum tl__draw_set { TL__DRAW_OPAQUE, TL__DRAW_TRANSPARENT } tl__draw_set;

static void tl__set_material(tl_renderer *r, GLuint p, const tl__gpu_material *mat)
{
    const GladGLContext *gl = &r->gl;
    const tl_material *m = &mat->m;
    gl->ProgramUniform3fv(p, gl->GetUniformLocation(p, "u_albedo"), 1, m->albedo);
    gl->ProgramUniform3fv(p, gl->GetUniformLocation(p, "u_specular"), 1, m->specular);
    gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_gloss"), m->gloss);
    gl->ProgramUniform3fv(p, gl->GetUniformLocation(p, "u_emissive"), 1, m->emissive);
    float alpha = (m->flags & (TL_MATERIAL_ALPHA_MASK | TL_MATERIAL_ALPHA_BLEND)) ? m->alpha : 1.0f;
    gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_alpha"), alpha);
    gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_alpha_cutoff"), m->alpha_cutoff);
    gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_metallic"), m->metallic);
    gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_roughness"), m->roughness);
    gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_normal_scale"), m->normal_scale);
    gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_occlusion_strength"), m->occlusion_strength);
    gl->ProgramUniform1i(p, gl->GetUniformLocation(p, "u_material_flags"), (GLint)m->flags);
    gl->ProgramUniform1i(p, gl->GetUniformLocation(p, "u_texture_mask"), mat->texture_mask);
    for (int k = 0; k < TL__MATERIAL_TEXTURES; k++)
        if (mat->textures[k]) gl->BindTextureUnit((GLuint)(TL__UNIT_ALBEDO + k), mat->textures[k]);
}

static void tl__program_common(tl_renderer *r, GLuint p, const tl__view *v)
{
    const GladGLContext *gl = &r->gl;
    gl->UseProgram(p);
    tl__uniform_mat4(gl, p, "u_view_proj", &v->view_proj);
    tl__uniform_mat4(gl, p, "u_view", &v->view);
    gl->ProgramUniform3fv(p, gl->GetUniformLocation(p, "u_ambient"), 1, r->ambient);
    static const char *const names[TL__MATERIAL_TEXTURES] = {"u_albedo_texture", "u_normal_texture", "u_mr_texture",
                                                             "u_emissive_texture", "u_occlusion_texture"};
    for (int k = 0; k < TL__MATERIAL_TEXTURES; k++)
        gl->ProgramUniform1i(p, gl->GetUniformLocation(p, names[k]), TL__UNIT_ALBEDO + k);
    gl->ProgramUniform1i(p, gl->GetUniformLocation(p, "u_light_diffuse"), 0);
    gl->ProgramUniform1i(p, gl->GetUniformLocation(p, "u_light_specular"), 1);
}

/* Draws the visible objects of one set with program p. Transparent objects are sorted far to near. */
static void tl__draw_objects(tl_renderer *r, const tl__view *v, GLuint p, tl__draw_set set, int forward,
                             tl_frame_stats *st, size_t *indices_drawn)
{
    const GladGLContext *gl = &r->gl;
    gl->BindVertexArray(r->vao_scene);
    tl__program_common(r, p, v);
    size_t n = 0;
    for (size_t i = 0; i < r->object_count; i++) {
        const tl_object *o = &r->objects[i];
        int blend = (r->materials[o->material].m.flags & TL_MATERIAL_ALPHA_BLEND) != 0;
        if (blend != (set == TL__DRAW_TRANSPARENT) || !o->index_count) continue;
        if (!tl__box_visible((float(*)[4])v->planes, o->bounds_min, o->bounds_max)) continue;
        r->draw_order[n] = (uint32_t)i;
        if (set == TL__DRAW_TRANSPARENT) {
            float c[3], d2 = 0.0f;
            for (int k = 0; k < 3; k++) {
                c[k] = 0.5f * (o->bounds_min[k] + o->bounds_max[k]) - v->eye[k];
                d2 += c[k] * c[k];
            }
            r->draw_keys[n] = d2;
        }
        n++;
    }
    if (set == TL__DRAW_TRANSPARENT) { /* insertion sort, far to near: few transparent objects */
        for (size_t i = 1; i < n; i++) {
            uint32_t oi = r->draw_order[i];
            float k = r->draw_keys[i];
            size_t j = i;
            for (; j > 0 && r->draw_keys[j - 1] < k; j--) {
                r->draw_order[j] = r->draw_order[j - 1];
                r->draw_keys[j] = r->draw_keys[j - 1];
            }
            r->draw_order[j] = oi;
            r->draw_keys[j] = k;
        }
    }
    GLint loc_model = gl->GetUniformLocation(p, "u_model"), loc_nm = gl->GetUniformLocation(p, "u_normal_view");
    GLint loc_first = gl->GetUniformLocation(p, "u_light_first"), loc_count = gl->GetUniformLocation(p, "u_light_count");
    uint32_t last_material = UINT32_MAX;
    for (size_t j = 0; j < n; j++) {
        uint32_t i = r->draw_order[j];
        const tl_object *o = &r->objects[i];
        const tl__gpu_material *mat = &r->materials[o->material];
        tl__mat4 model;
        memcpy(model.m, o->transform, sizeof model.m);
        tl__mat4 mv = tl__mat4_mul(&v->view, &model);
        float nm[9];
        tl__normal_matrix(&mv, nm);
        gl->ProgramUniformMatrix4fv(p, loc_model, 1, GL_FALSE, model.m);
        gl->ProgramUniformMatrix3fv(p, loc_nm, 1, GL_FALSE, nm);
        if (o->material != last_material) {
            tl__set_material(r, p, mat);
            last_material = o->material;
        }
        if (forward) {
            gl->ProgramUniform1ui(p, loc_first, r->fwd_first[i]);
            gl->ProgramUniform1ui(p, loc_count, r->fwd_count[i]);
        }
        if (mat->m.flags & TL_MATERIAL_DOUBLE_SIDED) gl->Disable(GL_CULL_FACE);
        else gl->Enable(GL_CULL_FACE);
        gl->DrawElements(GL_TRIANGLES, (GLsizei)o->index_count, GL_UNSIGNED_INT,
                         (const void *)(uintptr_t)(o->first_index * 4u));
        if (indices_drawn) *indices_drawn += o->index_count;
        st->draw_calls++;
        if (set == TL__DRAW_OPAQUE && (r->prog[TL_PASS_GBUFFER] == p || r->prog[TL_PASS_FORWARD] == p))
            st->objects_drawn++;
    }
    gl->Disable(GL_CULL_FACE);
}

/* ---- light volumes -------------------------------------------------------------------------- */

/* Culls lights against the frustum and uploads the visible ones of each type as instances: first
 * the volumes the camera is outside of (drawn by their front faces, so lights hidden behind the
 * scene cost nothing), then those that contain the camera or cross the near plane (back faces). */
static void tl__upload_instances(tl_renderer *r, const tl__view *v, size_t counts[TL__LIGHT_KINDS],
                                 size_t outside[TL__LIGHT_KINDS])
{
    const GladGLContext *gl = &r->gl;
    size_t base[TL__LIGHT_KINDS] = {0}, n = 0;
    for (int k = 0; k < TL__LIGHT_KINDS; k++) {
        base[k] = n;
        counts[k] = outside[k] = 0;
        for (int pass = 0; pass < 2; pass++)
            for (size_t i = 0; i < r->light_count; i++) {
                const tl_light *l = &r->lights[i];
                int type = l->type == TL_LIGHT_DEFAULT ? TL_LIGHT_POINT : (int)l->type;
                if (type - 1 != k) continue;
                int is_outside = 0;
                if (type != TL_LIGHT_DIRECTIONAL) {
                    if (l->radius <= 0.0f || !tl__sphere_visible((float(*)[4])v->planes, l->position, l->radius * 1.2f))
                        continue;
                    /* bounding sphere of the volume mesh (sphere: < 1.2 r; cone: apex to base rim) */
                    float co = l->cos_outer > 0.05f ? l->cos_outer : 0.05f;
                    float bound = type == TL_LIGHT_SPOT ? l->radius * 1.2f / co : l->radius * 1.2f;
                    float d2 = 0.0f;
                    for (int a = 0; a < 3; a++) d2 += (l->position[a] - v->eye[a]) * (l->position[a] - v->eye[a]);
                    float margin = bound + 4.0f * v->near_z;
                    is_outside = !r->desc.fullscreen_lights && d2 > margin * margin;
                }
                if (is_outside != (pass == 0)) continue;
                tl__instance *in = &r->instances[n++];
                float dir[3] = {l->direction[0], l->direction[1], l->direction[2]};
                tl__vec3_normalize(dir);
                if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f) dir[1] = -1.0f;
                memcpy(in->position_radius, l->position, sizeof(float) * 3);
                in->position_radius[3] = l->radius;
                memcpy(in->color, l->color, sizeof(float) * 3);
                in->color[3] = 0.0f;
                memcpy(in->direction_cos_outer, dir, sizeof dir);
                in->direction_cos_outer[3] = type == TL_LIGHT_SPOT ? l->cos_outer : -1.0f;
                in->cos_inner = type == TL_LIGHT_SPOT ? l->cos_inner : 1.0f;
                counts[k]++;
                outside[k] += (size_t)is_outside;
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

static void tl__set_gbuffer_read_uniforms(tl_renderer *r, GLuint p, const tl__view *v)
{
    const GladGLContext *gl = &r->gl;
    const float *m = v->projection.m;
    gl->UseProgram(p);
    gl->ProgramUniform4f(p, gl->GetUniformLocation(p, "u_depth_params"), m[10], m[14], m[11], tl__reversed(r) ? 1.0f : 0.0f);
    gl->ProgramUniform4f(p, gl->GetUniformLocation(p, "u_ray_params"), m[0], m[5], m[8], m[9]);
    gl->ProgramUniform2f(p, gl->GetUniformLocation(p, "u_inv_size"), 1.0f / (float)r->desc.width,
                         1.0f / (float)r->desc.height);
    gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_clear_depth"), v->clear_depth);
    static const char *const samplers[] = {"u_depth", "u_rt0", "u_rt1", "u_fat_position", "u_fat_normal",
                                           "u_fat_albedo", "u_fat_material"};
    for (int i = 0; i < 7; i++) gl->ProgramUniform1i(p, gl->GetUniformLocation(p, samplers[i]), i);
    tl__uniform_mat4(gl, p, "u_view", &v->view);
    tl__uniform_mat4(gl, p, "u_view_proj", &v->view_proj);
}

static void tl__lights_pass(tl_renderer *r, const tl__view *v, tl_frame_stats *st)
{
    const GladGLContext *gl = &r->gl;
    int rev = tl__reversed(r);
    const tl_target_id inputs[7] = {TL_TARGET_DEPTH,        TL_TARGET_RT0,        TL_TARGET_RT1,
                                    TL_TARGET_FAT_POSITION, TL_TARGET_FAT_NORMAL, TL_TARGET_FAT_ALBEDO,
                                    TL_TARGET_FAT_MATERIAL};
    for (int i = 0; i < 7; i++)
        if (r->targets[inputs[i]].texture) gl->BindTextureUnit((GLuint)i, r->targets[inputs[i]].texture);
    gl->DepthMask(GL_FALSE);
    gl->Enable(GL_BLEND);
    gl->BlendFunc(GL_ONE, GL_ONE);
    gl->BlendEquation(GL_FUNC_ADD);
    size_t counts[TL__LIGHT_KINDS], outside[TL__LIGHT_KINDS];
    tl__upload_instances(r, v, counts, outside);
    for (int k = 0; k < TL__LIGHT_KINDS; k++) {
        st->lights_drawn[k + 1] = (uint32_t)counts[k];
        GLuint p = r->prog_light[k];
        if (!counts[k] || !p) continue;
        tl__set_gbuffer_read_uniforms(r, p, v);
        gl->BindVertexArray(r->vao_light[k]);
        gl->BeginQuery(GL_SAMPLES_PASSED, r->light_queries[k]);
        if (k == 2 || r->desc.fullscreen_lights) {
            gl->Disable(GL_DEPTH_TEST);
            gl->Disable(GL_CULL_FACE);
            gl->DrawArraysInstanced(GL_TRIANGLES, 0, 3, (GLsizei)counts[k]);
            st->draw_calls++;
        } else {
            /* depth clamp keeps volumes cut by the far plane; outside volumes: front faces in front
             * of the scene; inside ones: back faces behind it (survive the near plane) */
            gl->Enable(GL_DEPTH_TEST);
            gl->Enable(GL_DEPTH_CLAMP);
            gl->Enable(GL_CULL_FACE);
            GLsizei nidx = (GLsizei)r->volume_index_count[k];
            if (outside[k]) {
                gl->DepthFunc(rev ? GL_GEQUAL : GL_LEQUAL);
                gl->CullFace(GL_BACK);
                gl->DrawElementsInstancedBaseInstance(GL_TRIANGLES, nidx, GL_UNSIGNED_INT, NULL, (GLsizei)outside[k], 0);
                st->draw_calls++;
            }
            if (counts[k] > outside[k]) {
                gl->DepthFunc(rev ? GL_LEQUAL : GL_GEQUAL);
                gl->CullFace(GL_FRONT);
                gl->DrawElementsInstancedBaseInstance(GL_TRIANGLES, nidx, GL_UNSIGNED_INT, NULL,
                                                      (GLsizei)(counts[k] - outside[k]), (GLuint)outside[k]);
                st->draw_calls++;
            }
            gl->Disable(GL_DEPTH_CLAMP);
            gl->CullFace(GL_BACK);
            gl->Disable(GL_CULL_FACE);
        }
        gl->EndQuery(GL_SAMPLES_PASSED);
    }
    gl->Disable(GL_BLEND);
}

/* ---- full-screen passes --------------------------------------------------------------------- */

static void tl__fxaa_draw(tl_renderer *r, GLuint fbo, GLint x, GLint y, GLsizei w, GLsizei h)
{
    const GladGLContext *gl = &r->gl;
    GLuint p = r->prog[TL_PASS_FXAA];
    gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl->Viewport(x, y, w, h);
    gl->UseProgram(p);
    gl->BindVertexArray(r->vao_empty);
    gl->BindTextureUnit(0, r->targets[TL_TARGET_LDR].texture);
    gl->BindSampler(0, r->sampler_linear);
    gl->ProgramUniform1i(p, gl->GetUniformLocation(p, "u_ldr"), 0);
    gl->ProgramUniform2f(p, gl->GetUniformLocation(p, "u_rcp_size"), 1.0f / (float)r->desc.width,
                         1.0f / (float)r->desc.height);
    gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_edge_threshold"), r->desc.fxaa_edge_threshold);
    gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_edge_threshold_min"), r->desc.fxaa_edge_threshold_min);
    gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_subpix"), r->desc.fxaa_subpix);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    gl->BindSampler(0, 0);
}

void tl__fxaa_image(tl_renderer *r)
{
    tl__fxaa_draw(r, r->fbo[TL_PASS_FXAA], 0, 0, (GLsizei)r->desc.width, (GLsizei)r->desc.height);
}

static double tl__now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

/* ---- bytes moved (docs/bandwidth.md) -------------------------------------------------------- */

static double tl__bpp(const tl_renderer *r, uint32_t bits)
{
    double b = 0.0;
    for (int t = 0; t < TL_TARGET_COUNT; t++)
        if (bits & (1u << t)) b += r->plan.target_bytes_per_pixel[t];
    return b;
}

static uint32_t tl__attribute_bytes(uint32_t attrs)
{
    return ((attrs & TL_ATTRIBUTE_POSITION) ? 12u : 0u) + ((attrs & TL_ATTRIBUTE_NORMAL) ? 12u : 0u) +
           ((attrs & TL_ATTRIBUTE_UV) ? 8u : 0u) + ((attrs & TL_ATTRIBUTE_TANGENT) ? 16u : 0u);
}

/* Per pass: fragments that passed the depth test x (depth read [+ write] + colour targets read and
 * written, blended targets twice) + clears + vertex fetch (indices drawn x (4 + attribute bytes))
 * + light instances (52 B each). Texture and constant reads are left out (caches absorb them). */
static void tl__estimate_bytes(tl_renderer *r, tl_frame_stats *st, const size_t indices[TL_PASS_COUNT])
{
    double pixels = (double)r->desc.width * r->desc.height;
    double depth = r->plan.target_bytes_per_pixel[TL_TARGET_DEPTH];
    double vtx = 4.0 + tl__attribute_bytes(r->plan.vertex_attributes);
    for (size_t i = 0; i < r->plan.pass_count; i++) {
        const tl_plan_pass *pp = &r->plan.passes[i];
        double frags = (double)st->pass_fragments[pp->pass];
        uint32_t colour_writes = pp->writes & ~1u, colour_reads = pp->reads & ~1u;
        double b = 0.0;
        switch (pp->pass) {
        case TL_PASS_DEPTH_PREPASS:
            b = pixels * depth + frags * 2.0 * depth + (double)indices[pp->pass] * vtx;
            break;
        case TL_PASS_GBUFFER:
        case TL_PASS_FORWARD:
            b = pixels * tl__bpp(r, pp->writes) + frags * (2.0 * depth + tl__bpp(r, colour_writes)) +
                (double)indices[pp->pass] * vtx;
            break;
        case TL_PASS_MATERIAL:
            b = pixels * tl__bpp(r, colour_writes) + frags * (depth + tl__bpp(r, colour_reads) + tl__bpp(r, colour_writes)) +
                (double)indices[pp->pass] * vtx;
            break;
        case TL_PASS_TRANSPARENT:
            b = frags * (depth + 2.0 * tl__bpp(r, colour_writes)) + (double)indices[pp->pass] * vtx;
            break;
        case TL_PASS_LIGHTS: {
            double in = tl__bpp(r, pp->reads);
            if (pp->reads & (1u << TL_TARGET_RT1)) in += 4.0 * r->plan.target_bytes_per_pixel[TL_TARGET_RT1];
            double clear = r->plan.mode == TL_MODE_THIN_LPP ? pixels * tl__bpp(r, pp->writes) : 0.0;
            size_t inst = 0;
            for (int k = 0; k < TL_LIGHT_TYPE_COUNT_; k++) inst += st->lights_drawn[k];
            b = clear + frags * (in + 2.0 * tl__bpp(r, pp->writes)) + (double)inst * sizeof(tl__instance);
            break;
        }
        case TL_PASS_TONEMAP:
        case TL_PASS_FXAA: b = pixels * (tl__bpp(r, pp->reads) + tl__bpp(r, pp->writes)); break;
        case TL_PASS_COUNT: break;
        }
        st->pass_bytes[pp->pass] = b;
        st->bytes_moved += b;
    }
}

/* ---- the frame ------------------------------------------------------------------------------ */

static void tl__begin(tl_renderer *r, tl_pass pass)
{
    tl__gl_debug_push(&r->gl, tl_pass_name(pass));
    tl__timer_begin(&r->gl, &r->timers[pass]);
    if (pass != TL_PASS_LIGHTS) r->gl.BeginQuery(GL_SAMPLES_PASSED, r->queries[pass]);
}

static void tl__end(tl_renderer *r, tl_pass pass)
{
    if (pass != TL_PASS_LIGHTS) r->gl.EndQuery(GL_SAMPLES_PASSED);
    tl__timer_end(&r->gl, &r->timers[pass]);
    tl__gl_debug_pop(&r->gl);
}

static int tl__has_pass(const tl_renderer *r, tl_pass pass)
{
    for (size_t i = 0; i < r->plan.pass_count; i++)
        if (r->plan.passes[i].pass == pass) return 1;
    return 0;
}

static tl_result tl__frame(tl_renderer *r, const tl_camera *camera, const tl_render_output *out, tl_frame_stats *stats)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    if (!r->has_scene) return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: no scene (call tl_renderer_set_scene first)");
    tl_frame_stats st;
    memset(&st, 0, sizeof st);
    tl__view v;
    tl_result res = tl__setup_view(r, camera ? camera : &r->camera, &v);
    if (res != TL_OK) return res;
    const GladGLContext *gl = &r->gl;
    double t0 = tl__now_ms();
    GLsizei w = (GLsizei)r->desc.width, h = (GLsizei)r->desc.height;
    int rev = tl__reversed(r);
    size_t indices[TL_PASS_COUNT] = {0};
    while (gl->GetError() != GL_NO_ERROR) {} /* errors from the caller's code are not ours */

    gl->Viewport(0, 0, w, h);
    if (rev) gl->ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    gl->Disable(GL_BLEND);
    gl->Disable(GL_STENCIL_TEST);
    gl->Disable(GL_SCISSOR_TEST);
    gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const float zero[4] = {0, 0, 0, 0};
    GLenum depth_less = rev ? GL_GREATER : GL_LESS;

    if (tl__has_pass(r, TL_PASS_FORWARD) || tl__has_pass(r, TL_PASS_TRANSPARENT)) {
        res = tl__forward_lists(r, &v, &st.forward_light_pairs);
        if (res != TL_OK) return res;
    }

    for (size_t pi = 0; pi < r->plan.pass_count; pi++) {
        const tl_plan_pass *pp = &r->plan.passes[pi];
        tl_pass pass = pp->pass;
        GLuint fbo = r->fbo[pass];
        tl__begin(r, pass);
        switch (pass) {
        case TL_PASS_DEPTH_PREPASS:
            gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
            gl->ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            gl->Enable(GL_DEPTH_TEST);
            gl->DepthMask(GL_TRUE);
            gl->DepthFunc(depth_less);
            gl->ClearNamedFramebufferfi(fbo, GL_DEPTH_STENCIL, 0, v.clear_depth, 0);
            tl__draw_objects(r, &v, r->prog[pass], TL__DRAW_OPAQUE, 0, &st, &indices[pass]);
            gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            break;
        case TL_PASS_GBUFFER:
            gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
            gl->Enable(GL_DEPTH_TEST);
            gl->DepthMask(GL_TRUE);
            gl->DepthFunc(depth_less);
            for (int c = 0; c < TL__FRAMEBUFFER_MAX_COLORS; c++) {
                GLint type = GL_NONE;
                gl->GetNamedFramebufferAttachmentParameteriv(fbo, GL_COLOR_ATTACHMENT0 + (GLenum)c,
                                                             GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
                if (type == GL_NONE) break;
                gl->ClearNamedFramebufferfv(fbo, GL_COLOR, c, zero);
            }
            gl->ClearNamedFramebufferfi(fbo, GL_DEPTH_STENCIL, 0, v.clear_depth, 0);
            tl__draw_objects(r, &v, r->prog[pass], TL__DRAW_OPAQUE, 0, &st, &indices[pass]);
            break;
        case TL_PASS_LIGHTS:
            gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
            if (r->plan.mode == TL_MODE_THIN_LPP) {
                gl->ClearNamedFramebufferfv(fbo, GL_COLOR, 0, zero);
                if (pp->writes & (1u << TL_TARGET_LIGHT_SPECULAR)) gl->ClearNamedFramebufferfv(fbo, GL_COLOR, 1, zero);
            }
            tl__lights_pass(r, &v, &st);
            break;
        case TL_PASS_MATERIAL:
            gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
            gl->ClearNamedFramebufferfv(fbo, GL_COLOR, 0, zero);
            gl->Enable(GL_DEPTH_TEST);
            gl->DepthFunc(GL_EQUAL);
            gl->DepthMask(GL_FALSE);
            if (r->targets[TL_TARGET_LIGHT_DIFFUSE].texture)
                gl->BindTextureUnit(0, r->targets[TL_TARGET_LIGHT_DIFFUSE].texture);
            if (r->targets[TL_TARGET_LIGHT_SPECULAR].texture)
                gl->BindTextureUnit(1, r->targets[TL_TARGET_LIGHT_SPECULAR].texture);
            tl__draw_objects(r, &v, r->prog[pass], TL__DRAW_OPAQUE, 0, &st, &indices[pass]);
            break;
        case TL_PASS_FORWARD: {
            int prepass = tl__has_pass(r, TL_PASS_DEPTH_PREPASS);
            gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
            gl->ClearNamedFramebufferfv(fbo, GL_COLOR, 0, zero);
            gl->Enable(GL_DEPTH_TEST);
            if (prepass) {
                gl->DepthFunc(GL_EQUAL);
                gl->DepthMask(GL_FALSE);
            } else {
                gl->ClearNamedFramebufferfi(fbo, GL_DEPTH_STENCIL, 0, v.clear_depth, 0);
                gl->DepthFunc(depth_less);
                gl->DepthMask(GL_TRUE);
            }
            tl__draw_objects(r, &v, r->prog[pass], TL__DRAW_OPAQUE, 1, &st, &indices[pass]);
            break;
        }
        case TL_PASS_TRANSPARENT:
            gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
            gl->Enable(GL_DEPTH_TEST);
            gl->DepthFunc(depth_less);
            gl->DepthMask(GL_FALSE);
            gl->Enable(GL_BLEND);
            gl->BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
            gl->BlendEquation(GL_FUNC_ADD);
            tl__draw_objects(r, &v, r->prog[pass], TL__DRAW_TRANSPARENT, 1, &st, &indices[pass]);
            gl->Disable(GL_BLEND);
            break;
        case TL_PASS_TONEMAP: {
            if (rev) gl->ClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
            gl->Disable(GL_DEPTH_TEST);
            gl->DepthMask(GL_TRUE);
            GLuint p = r->prog[pass];
            int last = pi + 1 == r->plan.pass_count;
            if (last && out) {
                gl->BindFramebuffer(GL_FRAMEBUFFER, out->framebuffer);
                gl->Viewport((GLint)out->x, (GLint)out->y, out->width ? (GLsizei)out->width : w,
                             out->height ? (GLsizei)out->height : h);
            } else {
                gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
            }
            gl->UseProgram(p);
            gl->BindVertexArray(r->vao_empty);
            gl->BindTextureUnit(0, r->targets[TL_TARGET_HDR].texture);
            gl->ProgramUniform1i(p, gl->GetUniformLocation(p, "u_hdr"), 0);
            gl->ProgramUniform1f(p, gl->GetUniformLocation(p, "u_exposure"), r->desc.exposure);
            if (last && out) gl->BindSampler(0, r->sampler_linear); /* the caller's size may differ */
            gl->DrawArrays(GL_TRIANGLES, 0, 3);
            gl->BindSampler(0, 0);
            gl->Viewport(0, 0, w, h);
            break;
        }
        case TL_PASS_FXAA:
            if (out)
                tl__fxaa_draw(r, out->framebuffer, (GLint)out->x, (GLint)out->y,
                              out->width ? (GLsizei)out->width : w, out->height ? (GLsizei)out->height : h);
            else
                tl__fxaa_image(r);
            gl->Viewport(0, 0, w, h);
            break;
        case TL_PASS_COUNT: break;
        }
        tl__end(r, pass);
    }

    gl->BindVertexArray(0);
    gl->UseProgram(0);
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl->DepthMask(GL_TRUE);
    gl->Finish();
    st.cpu_ms = tl__now_ms() - t0;
    for (size_t i = 0; i < r->plan.pass_count; i++) {
        tl_pass p = r->plan.passes[i].pass;
        uint64_t ns = 0;
        st.pass_ms[p] = tl__timer_read(gl, &r->timers[p], true, NULL, &ns) == TL_OK ? (double)ns * 1e-6 : -1.0;
        if (st.pass_ms[p] > 0.0) st.gpu_ms += st.pass_ms[p];
        if (p == TL_PASS_LIGHTS) {
            for (int k = 0; k < TL__LIGHT_KINDS; k++) {
                GLuint64 q = 0;
                if (st.lights_drawn[k + 1] && r->prog_light[k])
                    gl->GetQueryObjectui64v(r->light_queries[k], GL_QUERY_RESULT, &q);
                st.light_fragments[k + 1] = q;
                st.pass_fragments[p] += q;
            }
        } else {
            GLuint64 q = 0;
            gl->GetQueryObjectui64v(r->queries[p], GL_QUERY_RESULT, &q);
            st.pass_fragments[p] = q;
        }
    }
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        st.target_bytes[t] = r->targets[t].bytes;
        st.total_target_bytes += r->targets[t].bytes;
    }
    st.gbuffer_bytes = st.target_bytes[TL_TARGET_DEPTH] + st.target_bytes[TL_TARGET_RT0] + st.target_bytes[TL_TARGET_RT1] +
                       st.target_bytes[TL_TARGET_FAT_POSITION] + st.target_bytes[TL_TARGET_FAT_NORMAL] +
                       st.target_bytes[TL_TARGET_FAT_ALBEDO] + st.target_bytes[TL_TARGET_FAT_MATERIAL];
    st.light_buffer_bytes = st.target_bytes[TL_TARGET_LIGHT_DIFFUSE] + st.target_bytes[TL_TARGET_LIGHT_SPECULAR];
    st.programs_compiled = r->programs_compiled;
    tl__estimate_bytes(r, &st, indices);
    if (stats) *stats = st;
    GLenum e = gl->GetError();
    if (e != GL_NO_ERROR) return tl__fail(r, TL_ERROR_GL, "renderer: %s during the frame", tl__gl_error_string(e));
    return TL_OK;
}

tl_result tl_renderer_render(tl_renderer *r, const tl_camera *camera, tl_frame_stats *stats)
{
    return tl__frame(r, camera, NULL, stats);
}

tl_result tl_renderer_render_to(tl_renderer *r, const tl_camera *camera, const tl_render_output *output,
                                tl_frame_stats *stats)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    if (!output) return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: render_to needs an output");
    return tl__frame(r, camera, output, stats);
}
