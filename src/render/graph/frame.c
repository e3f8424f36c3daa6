/* One frame: the compiled passes of the plan in order (docs/frame.md). Per frame the
 * CPU culls the scene's objects, has the lights module prepare what the plan's passes declared,
 * writes the frame's uniform block, per-object records and light data into the streaming buffer,
 * then runs each pass: debug group, queries (only when statistics were asked for), framebuffer,
 * clears, state, texture bindings, and its execute step with what it declared (tl__pass_ctx). No
 * uniform lookups, attachment queries or waits: those happen when a plan is compiled, or when the
 * caller asks (waiting for the frames, synchronous statistics). */
#include <string.h>

#include "renderer_internal.h"

static const float tl__zero[4] = {0, 0, 0, 0};

static void tl__clear(tl_renderer *r, const tl__compiled_pass *cp)
{
    tl__device *dev = &r->dev;
    if (!cp->clear_count && !cp->clear_depth) return;
    tl__pipeline masks = dev->state.known ? dev->state.p : cp->decl->state; /* clears obey the write masks */
    masks.color_write = masks.depth_write = 1;
    tl__state_apply(&dev->gl, &dev->state, &masks);
    static const GLuint zero_uint[4] = {0, 0, 0, 0};
    for (uint8_t k = 0; k < cp->clear_count; k++) {
        if (cp->clear_uint & (1u << k)) dev->gl.ClearNamedFramebufferuiv(cp->fbo, GL_COLOR, cp->clear_locations[k], zero_uint);
        else dev->gl.ClearNamedFramebufferfv(cp->fbo, GL_COLOR, cp->clear_locations[k], tl__zero);
    }
    if (cp->clear_depth) {
        float far = r->desc.options.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED ? 0.0f : 1.0f;
        dev->gl.ClearNamedFramebufferfi(cp->fbo, GL_DEPTH_STENCIL, 0, far, 0);
    }
}

static void tl__run_app(tl_renderer *r, const tl__compiled_pass *cp, const tl_view_info *view)
{
    tl__device *dev = &r->dev;
    tl_app_pass_context ctx;
    memset(&ctx, 0, sizeof ctx);
    ctx.view = view;
    ctx.framebuffer = cp->fbo;
    const tl__graph *g = &r->graph;
    for (int t = 0; t < TL_TARGET_COUNT; t++) /* storage buffers: the tile headers (renderer.h) */
        if (cp->plan->reads & TL_TARGET_BIT(t))
            ctx.textures[t] = !g->plan.targets[t]->buffer_bytes ? g->targets[t].texture
                                                                 : tl__lights_buffer(&r->lights, (tl_target_id)t);
    const tl__app_pass *a = &g->apps[cp->app];
    tl__state_program(&dev->gl, &dev->state, 0);
    tl__state_vertex_array(&dev->gl, &dev->state, 0);
    a->desc.execute(a->desc.user, &ctx);
    tl__state_invalidate(&dev->state); /* the application may have changed anything */
    tl__stream_rebind(&dev->gl, &dev->stream);
}

/* What a built-in pass's execute step gets: what its declaration resolved to, and the services its
 * definition asked for. */
static void tl__pass_ctx_make(tl_renderer *r, const tl__compiled_pass *cp, const GLuint *queries, int to_caller,
                              tl__pass_out *out, tl_frame_stats *st, tl__pass_ctx *ctx)
{
    memset(ctx, 0, sizeof *ctx);
    ctx->gl = &r->dev.gl;
    ctx->state = &r->dev.state;
    ctx->programs = cp->programs;
    ctx->pipeline = &cp->decl->state;
    ctx->fbo = cp->fbo;
    ctx->level_count = cp->level_count;
    ctx->level_fbos = cp->level_fbos;
    ctx->level_textures = cp->level_textures;
    ctx->level_width = cp->level_width;
    ctx->level_height = cp->level_height;
    ctx->write_count = cp->write_count;
    ctx->write_fbos = cp->write_fbos;
    ctx->write_textures = cp->write_textures;
    ctx->width = r->desc.width;
    ctx->height = r->desc.height;
    ctx->light_shift = tl__light_shift(&r->desc.options);
    ctx->gbuffer_samples = tl__gbuffer_samples(&r->desc.options) > 1u ? r->graph.samples : 1u;
    ctx->fullscreen_vao = r->dev.vao_empty;
    ctx->linear_sampler = r->dev.sampler_linear;
    ctx->unit_of = cp->unit_of;
    ctx->params = cp->def->options_size ? (const char *)&r->desc.options + cp->def->options_offset : NULL;
    ctx->queries = queries;
    ctx->to_caller = to_caller;
    ctx->frame = r->frame_index;
    ctx->out = out;
    if (cp->def->services & TL__PASS_SCENE) ctx->scene = &r->scene;
    if (cp->def->services & TL__PASS_LIGHTS) ctx->lights = &r->lights;
    if (cp->def->services & TL__PASS_SHADOWS) {
        ctx->shadows = &r->shadows;
        ctx->device = &r->dev;
        ctx->stats = st;
    }
}

/* A pass's parameter block into the frame's stream, bound at TL_UBO_PASS while it runs. */
static void tl__pass_params(tl_renderer *r, const tl__pass_def *def, const tl__view *v)
{
    tl__device *dev = &r->dev;
    size_t offset = 0;
    void *block = tl__stream_reserve(&dev->stream, def->params_size, dev->lim.ubo_align, &offset);
    if (!block) return; /* the frame reserved room for every pass's block (tl__params_bytes) */
    def->params(&r->desc.options, v, block);
    dev->gl.BindBufferRange(GL_UNIFORM_BUFFER, TL__UBO_PASS, dev->stream.buffer, (GLintptr)offset,
                            (GLsizeiptr)def->params_size);
}

size_t tl__params_bytes(const tl_renderer *r, const tl__compiled_pass *cp, size_t count)
{
    size_t bytes = 0;
    for (size_t i = 0; i < count; i++)
        if (cp[i].def && cp[i].def->params_size) bytes += cp[i].def->params_size + r->dev.lim.ubo_align;
    return bytes;
}

/* One pass: everything but its queries. `v` is NULL outside a frame (apply_fxaa). */
static void tl__pass_body(tl_renderer *r, const tl__compiled_pass *cp, const GLuint *queries,
                          const tl_render_output *out, const tl__view *v, tl__pass_out *po, tl_frame_stats *st)
{
    tl__device *dev = &r->dev;
    const GladGLContext *gl = &dev->gl;
    GLsizei w = (GLsizei)r->desc.width, h = (GLsizei)r->desc.height;
    int to_caller = out && cp->writes_output;
    tl__pass_ctx ctx;
    if (cp->app < 0) tl__pass_ctx_make(r, cp, queries, to_caller, po, st, &ctx);
    if (cp->app < 0 && cp->def->params_size) tl__pass_params(r, cp->def, v);
    if (cp->decl->compute) { /* no framebuffer, clears or raster state */
        for (uint8_t k = 0; k < cp->bind_count; k++) gl->BindTextureUnit(k, cp->textures[k]);
        for (uint8_t k = 0; k < cp->image_count; k++)
            gl->BindImageTexture(k, cp->image_textures[k], 0, GL_FALSE, 0, GL_READ_WRITE, cp->image_formats[k]);
        cp->def->execute(&ctx);
        return;
    }
    if (to_caller) {
        tl__state_framebuffer(gl, &dev->state, out->framebuffer);
        tl__state_viewport(gl, &dev->state, (GLint)out->x, (GLint)out->y, out->width ? (GLsizei)out->width : w,
                           out->height ? (GLsizei)out->height : h);
    } else {
        tl__state_framebuffer(gl, &dev->state, cp->fbo);
        tl__state_viewport(gl, &dev->state, 0, 0, cp->fb_width ? (GLsizei)cp->fb_width : w,
                           cp->fb_height ? (GLsizei)cp->fb_height : h);
        tl__clear(r, cp);
    }
    tl__state_apply(gl, &dev->state, &cp->decl->state);
    for (uint8_t k = 0; k < cp->bind_count; k++) gl->BindTextureUnit(k, cp->textures[k]);
    if (cp->app >= 0) tl__run_app(r, cp, v ? &v->info : NULL);
    else cp->def->execute(&ctx);
}

static void tl__run(tl_renderer *r, const tl__compiled_pass *cp, tl__frame_record *rec, size_t index,
                    const tl_render_output *out, const tl__view *v, tl__query_slot *slot)
{
    tl__device *dev = &r->dev;
    const GladGLContext *gl = &dev->gl;
    int own = cp->def && cp->def->query_count;
    tl__pass_out po = {0};
    tl__gl_debug_push(gl, cp->plan->name);
    if (slot && r->queries.timestamps) gl->QueryCounter(slot->time[index][0], GL_TIMESTAMP);
    if (slot && !own) gl->BeginQuery(GL_SAMPLES_PASSED, slot->samples[index][0]);
    tl__pass_body(r, cp, slot && own ? slot->samples[index] : NULL, out, v, &po, &rec->st);
    if (slot && !own) gl->EndQuery(GL_SAMPLES_PASSED);
    if (slot && r->queries.timestamps) gl->QueryCounter(slot->time[index][1], GL_TIMESTAMP);
    tl__gl_debug_pop(gl);
    rec->st.draw_calls += po.draw_calls;
    rec->indices[index] += po.indices;
    rec->instances[index] += po.instances;
}

void tl__run_pass(tl_renderer *r, const tl__compiled_pass *cp, tl__frame_record *rec, size_t index)
{
    tl__run(r, cp, rec, index, NULL, NULL, NULL);
}

/* ---- per-frame data ---------------------------------------------------------------------------- */

/* The passes' CPU steps (tl__pass_def.prepare), then the lights' data they may add to. */
static tl_result tl__prepare(tl_renderer *r, const tl__view *v, tl__frame_record *rec)
{
    rec->st.objects_drawn = (uint32_t)tl__visibility(&r->scene, v);
    r->lights.shadow_slots = NULL;
    for (size_t i = 0; i < r->graph.pass_count; i++) {
        const tl__compiled_pass *cp = &r->graph.passes[i];
        if (cp->app >= 0 || !cp->def->prepare) continue;
        tl__pass_out po = {0};
        tl__pass_ctx ctx;
        tl__pass_ctx_make(r, cp, NULL, 0, &po, &rec->st, &ctx);
        tl_result res = cp->def->prepare(&ctx, v, &r->desc.options);
        if (res != TL_OK) return res;
    }
    return tl__lights_prepare(&r->dev, &r->lights, &r->scene, v, r->graph.light_data, r->desc.options.fullscreen_lights,
                              r->frame_index, &rec->st, &rec->stream_bytes);
}

static tl_result tl__upload(tl_renderer *r, const tl__view *v, tl__frame_record *rec)
{
    tl__device *dev = &r->dev;
    const GladGLContext *gl = &dev->gl;
    const tl__scene_gpu *g = &r->scene;
    unsigned needs = r->graph.light_data;
    size_t nobj = g->object_count ? g->object_count : 1;
    size_t need = rec->stream_bytes + sizeof(tl__frame_ubo) + dev->lim.ubo_align + nobj * sizeof(tl__object_gpu) +
                  dev->lim.ssbo_align + tl__params_bytes(r, r->graph.passes, r->graph.pass_count);
    if (tl__stream_begin(gl, &dev->stream, need, "buffer.frame") != TL_OK)
        return tl__fail(dev, TL_ERROR_GL, "renderer: could not map the per-frame buffer (%zu bytes)", need);
    size_t fo = 0, oo = 0;
    tl__frame_ubo *u = (tl__frame_ubo *)tl__stream_reserve(&dev->stream, sizeof *u, dev->lim.ubo_align, &fo);
    tl__object_gpu *o = (tl__object_gpu *)tl__stream_reserve(&dev->stream, nobj * sizeof *o, dev->lim.ssbo_align, &oo);
    uint32_t counts[3], tiles[4];
    tl__lights_frame_block(&r->lights, needs, counts, tiles);
    tl__frame_ubo_fill(&r->desc, v, r->ambient, tiles, counts, u);
    memcpy(u->sample_positions, r->graph.sample_positions, sizeof u->sample_positions);
    int lists = (needs & TL__LIGHTS_OBJECT_LISTS) != 0;
    if (g->object_count)
        tl__objects_fill(g, v, lists ? r->lights.fwd_first : NULL, lists ? r->lights.fwd_object_count : NULL, o);
    else memset(o, 0, sizeof *o);
    tl__stream_bind_range(gl, &dev->stream, GL_UNIFORM_BUFFER, TL__UBO_FRAME, fo, sizeof *u);
    tl__stream_bind_range(gl, &dev->stream, GL_SHADER_STORAGE_BUFFER, TL__SSBO_OBJECTS, oo, nobj * sizeof *o);
    tl__lights_upload(dev, &r->lights, needs);
    return TL_OK;
}

/* CPU figures every frame reports: what the targets occupy, what has been compiled. */
static void tl__record_targets(const tl_renderer *r, tl_frame_stats *st)
{
    const tl_frame_plan *p = &r->graph.plan.pub;
    size_t px = (size_t)p->width * p->height;
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        st->target_bytes[t] = (size_t)p->target_bytes_per_pixel[t] * px;
        st->total_target_bytes += st->target_bytes[t];
        if (!st->target_bytes[t]) continue;
        if (r->graph.plan.targets[t]->store == TL__STORE_LIGHT) st->light_buffer_bytes += st->target_bytes[t];
        else if (r->graph.plan.targets[t]->store == TL__STORE_GBUFFER) st->gbuffer_bytes += st->target_bytes[t];
    }
    st->allocated_target_bytes = (size_t)p->allocated_bytes_per_pixel * px;
    st->programs_compiled = r->dev.programs_compiled;
}

static tl_result tl__issue(tl_renderer *r, const tl__view *v, const tl_render_output *out, tl__frame_record *rec,
                           tl__query_slot *slot)
{
    tl__device *dev = &r->dev;
    const GladGLContext *gl = &dev->gl;
    tl_result res = tl__prepare(r, v, rec);
    if (res == TL_OK) res = tl__upload(r, v, rec);
    if (res != TL_OK) return res;
    tl__state_enter(gl, &dev->state, TL__TEXTURE_UNITS_USED);
    tl__environment_bind(gl, &r->env, &r->desc.options.environment);
    for (size_t i = 0; i < r->graph.pass_count; i++) tl__run(r, &r->graph.passes[i], rec, i, out, v, slot);
    tl__state_reset(gl, &dev->state, TL__TEXTURE_UNITS_USED, TL__BUFFER_BINDINGS_USED, TL__IMAGE_UNITS_USED);
    if (out) gl->Viewport((GLint)out->x, (GLint)out->y, out->width ? (GLsizei)out->width : (GLsizei)r->desc.width,
                          out->height ? (GLsizei)out->height : (GLsizei)r->desc.height);
    else gl->Viewport(0, 0, (GLsizei)r->desc.width, (GLsizei)r->desc.height);
    tl__stream_end(gl, &dev->stream);
    return TL_OK;
}

tl_result tl__frame_wait(tl_renderer *r, tl_frame_stats *stats)
{
    const GladGLContext *gl = &r->dev.gl;
    gl->Finish();
    double wall = r->frame_index ? tl__now_ms() - r->frame_start_ms : 0.0;
    tl__queries_drain(&r->dev, &r->queries);
    if (stats) {
        *stats = r->last_measured ? r->queries.ring[r->last_slot].rec.st : r->last.st;
        stats->wall_ms = wall;
    }
    GLenum e = gl->GetError();
    if (e != GL_NO_ERROR)
        return tl__fail(&r->dev, TL_ERROR_GL, "renderer: %s during the frames", tl__gl_error_string(e));
    return TL_OK;
}

tl_result tl__frame(tl_renderer *r, const tl_camera *camera, const tl_render_output *out, tl_frame_stats *stats)
{
    tl__view v;
    uint64_t frame = r->frame_index + 1;
    /* the clock of the effects that move (fog's noise) counts the frames before this one */
    tl_result res = tl__view_setup(&r->dev, &r->scene, &r->desc, camera ? camera : &r->scene.camera,
                                   camera ? "camera" : "scene.camera", r->frame_index, &v);
    if (res != TL_OK) return res;
    if (!r->graph.programs_ready && (res = tl__graph_programs(&r->dev, &r->graph)) != TL_OK) return res;
    double t0 = tl__now_ms(), c0 = tl__thread_cpu_ms();
    int measure = stats || r->desc.options.synchronous_stats;
    r->frame_index = frame;
    tl__query_slot *slot = measure ? tl__queries_slot(&r->dev, &r->queries, &r->graph, frame) : NULL;
    tl__frame_record *rec = slot ? &slot->rec : &r->last;
    memset(rec, 0, sizeof *rec);
    rec->st.frame = frame;
    r->frame_start_ms = t0;
    res = tl__issue(r, &v, out, rec, slot);
    if (res != TL_OK) return res;
    rec->st.cpu_ms = tl__thread_cpu_ms() - c0;
    tl__record_targets(r, &rec->st);
    r->last_measured = slot != NULL;
    if (slot) {
        slot->pending = 1;
        r->last_slot = (unsigned)(frame % TL__QUERY_RING);
    }
    if (r->desc.options.synchronous_stats) return tl__frame_wait(r, stats);
    if (stats && !tl__queries_newest(&r->dev, &r->queries, stats)) {
        memset(stats, 0, sizeof *stats);
    }
    return TL_OK;
}
