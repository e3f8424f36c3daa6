/* One frame: the compiled passes of the plan in order (shared/DESIGN.md section 2). Per frame the
 * CPU culls objects and lights, writes the frame's uniform block, per-object records, light
 * instances and lists into the streaming buffer, then runs each pass: debug group, queries (only
 * when statistics were asked for), framebuffer, clears, state, texture bindings, execute. No
 * uniform lookups, attachment queries or waits: those happen when a plan is compiled, or when the
 * caller asks (waiting for the frames, synchronous statistics). */
#include <string.h>

#include "renderer_internal.h"
#include "targets.h"

static const float tl__zero[4] = {0, 0, 0, 0};

static void tl__clear(tl_renderer *r, const tl__compiled_pass *cp)
{
    const GladGLContext *gl = &r->gl;
    if (!cp->clear_count && !cp->clear_depth) return;
    tl__pipeline masks = r->state.known ? r->state.p : cp->decl->state; /* clears obey the write masks */
    masks.color_write = masks.depth_write = 1;
    tl__state_apply(gl, &r->state, &masks);
    for (uint8_t k = 0; k < cp->clear_count; k++) gl->ClearNamedFramebufferfv(cp->fbo, GL_COLOR, cp->clear_locations[k], tl__zero);
    if (cp->clear_depth) {
        float far = r->desc.options.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED ? 0.0f : 1.0f;
        gl->ClearNamedFramebufferfi(cp->fbo, GL_DEPTH_STENCIL, 0, far, 0);
    }
}

static void tl__run_app(tl_renderer *r, const tl__compiled_pass *cp, const tl_view_info *view)
{
    const GladGLContext *gl = &r->gl;
    tl_app_pass_context ctx;
    memset(&ctx, 0, sizeof ctx);
    ctx.view = view;
    ctx.framebuffer = cp->fbo;
    for (int t = 0; t < TL_TARGET_COUNT; t++) /* storage buffers: the tile headers (renderer.h) */
        if (cp->plan->reads & TL_TARGET_BIT(t))
            ctx.textures[t] = tl__targets[t].buffer ? r->tiles.headers : r->targets[t].texture;
    const tl__app_pass *a = &r->apps[cp->app];
    tl__state_program(gl, &r->state, 0);
    tl__state_vertex_array(gl, &r->state, 0);
    a->desc.execute(a->desc.user, &ctx);
    tl__state_invalidate(&r->state); /* the application may have changed anything */
    tl__stream_rebind(gl, &r->stream);
}

/* One pass: everything but its queries. `view` is NULL outside a frame (apply_fxaa). */
static void tl__pass_body(tl_renderer *r, const tl__compiled_pass *cp, const tl__pass_ctx *ctx,
                          const tl_render_output *out, const tl_view_info *view)
{
    const GladGLContext *gl = &r->gl;
    GLsizei w = (GLsizei)r->desc.width, h = (GLsizei)r->desc.height;
    if (cp->decl->compute) { /* no framebuffer, clears or raster state */
        for (uint8_t k = 0; k < cp->bind_count; k++) gl->BindTextureUnit(cp->units[k], cp->textures[k]);
        for (uint8_t k = 0; k < cp->image_count; k++)
            gl->BindImageTexture(cp->image_units[k], cp->image_textures[k], 0, GL_FALSE, 0, GL_READ_WRITE,
                                 cp->image_formats[k]);
        cp->def->execute(r, ctx);
        return;
    }
    if (ctx->to_caller) {
        tl__state_framebuffer(gl, &r->state, out->framebuffer);
        tl__state_viewport(gl, &r->state, (GLint)out->x, (GLint)out->y, out->width ? (GLsizei)out->width : w,
                           out->height ? (GLsizei)out->height : h);
    } else {
        tl__state_framebuffer(gl, &r->state, cp->fbo);
        tl__state_viewport(gl, &r->state, 0, 0, w, h);
        tl__clear(r, cp);
    }
    tl__state_apply(gl, &r->state, &cp->decl->state);
    for (uint8_t k = 0; k < cp->bind_count; k++) gl->BindTextureUnit(cp->units[k], cp->textures[k]);
    if (cp->app >= 0) tl__run_app(r, cp, view);
    else cp->def->execute(r, ctx);
}

static void tl__run(tl_renderer *r, const tl__compiled_pass *cp, tl__frame_record *rec, size_t index,
                    const tl_render_output *out, const tl__view *v, tl__query_slot *slot)
{
    const GladGLContext *gl = &r->gl;
    int own = cp->def && cp->def->query_count;
    tl__pass_ctx ctx = {cp, v, rec, index, slot && own ? slot->samples[index] : NULL, out && cp->writes_output};
    tl__gl_debug_push(gl, cp->plan->name);
    if (slot && r->timestamps) gl->QueryCounter(slot->time[index][0], GL_TIMESTAMP);
    if (slot && !own) gl->BeginQuery(GL_SAMPLES_PASSED, slot->samples[index][0]);
    tl__pass_body(r, cp, &ctx, out, v ? &v->info : NULL);
    if (slot && !own) gl->EndQuery(GL_SAMPLES_PASSED);
    if (slot && r->timestamps) gl->QueryCounter(slot->time[index][1], GL_TIMESTAMP);
    tl__gl_debug_pop(gl);
}

void tl__run_pass(tl_renderer *r, const tl__compiled_pass *cp, tl__frame_record *rec, size_t index,
                  const tl_render_output *out)
{
    tl__run(r, cp, rec, index, out, NULL, NULL);
}

/* ---- per-frame data ---------------------------------------------------------------------------- */

static tl_result tl__prepare(tl_renderer *r, const tl__view *v, tl__frame_record *rec)
{
    for (size_t i = 0; i < r->pass_count; i++) {
        const tl__pass_def *def = r->passes[i].def;
        if (!def || !def->prepare) continue;
        int seen = 0; /* a step several passes share runs once */
        for (size_t j = 0; j < i; j++) seen |= r->passes[j].def && r->passes[j].def->prepare == def->prepare;
        if (seen) continue;
        tl_result res = def->prepare(r, v, rec);
        if (res != TL_OK) return res;
    }
    return TL_OK;
}

static tl_result tl__upload(tl_renderer *r, const tl__view *v, tl__frame_record *rec, int with_lists)
{
    const GladGLContext *gl = &r->gl;
    size_t nobj = r->object_count ? r->object_count : 1;
    size_t need = rec->stream_bytes + sizeof(tl__frame_ubo) + r->ubo_align + nobj * sizeof(tl__object_gpu) + r->ssbo_align;
    if (tl__stream_begin(gl, &r->stream, need, "buffer.frame") != TL_OK)
        return tl__fail(r, TL_ERROR_GL, "renderer: could not map the per-frame buffer (%zu bytes)", need);
    size_t fo = 0, oo = 0;
    tl__frame_ubo *u = (tl__frame_ubo *)tl__stream_reserve(&r->stream, sizeof *u, r->ubo_align, &fo);
    tl__object_gpu *o = (tl__object_gpu *)tl__stream_reserve(&r->stream, nobj * sizeof *o, r->ssbo_align, &oo);
    tl__frame_ubo_fill(r, v, u);
    if (r->object_count) tl__objects_fill(r, v, with_lists, o);
    else memset(o, 0, sizeof *o);
    tl__stream_bind_range(gl, &r->stream, GL_UNIFORM_BUFFER, TL__UBO_FRAME, fo, sizeof *u);
    tl__stream_bind_range(gl, &r->stream, GL_SHADER_STORAGE_BUFFER, TL__SSBO_OBJECTS, oo, nobj * sizeof *o);
    for (size_t i = 0; i < r->pass_count; i++) {
        const tl__pass_def *def = r->passes[i].def;
        if (!def || !def->upload) continue;
        int seen = 0;
        for (size_t j = 0; j < i; j++) seen |= r->passes[j].def && r->passes[j].def->upload == def->upload;
        if (!seen) def->upload(r);
    }
    return TL_OK;
}

/* CPU figures every frame reports: what the targets occupy, what has been compiled. */
static void tl__record_targets(const tl_renderer *r, tl_frame_stats *st)
{
    const tl_frame_plan *p = &r->plan.pub;
    size_t px = (size_t)p->width * p->height;
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        st->target_bytes[t] = (size_t)p->target_bytes_per_pixel[t] * px;
        st->total_target_bytes += st->target_bytes[t];
        if (tl__targets[t].store == TL__STORE_LIGHT) st->light_buffer_bytes += st->target_bytes[t];
        else if (tl__targets[t].store == TL__STORE_GBUFFER) st->gbuffer_bytes += st->target_bytes[t];
    }
    st->allocated_target_bytes = (size_t)p->allocated_bytes_per_pixel * px;
    st->programs_compiled = r->programs_compiled;
}

static tl_result tl__issue(tl_renderer *r, const tl__view *v, const tl_render_output *out, tl__frame_record *rec,
                           tl__query_slot *slot)
{
    const GladGLContext *gl = &r->gl;
    tl__visibility(r, v, rec);
    tl_result res = tl__prepare(r, v, rec);
    if (res == TL_OK) res = tl__upload(r, v, rec, r->object_lists);
    if (res != TL_OK) return res;
    tl__state_enter(gl, &r->state, TL__TEXTURE_UNITS_USED);
    for (size_t i = 0; i < r->pass_count; i++) tl__run(r, &r->passes[i], rec, i, out, v, slot);
    tl__state_reset(gl, &r->state, TL__TEXTURE_UNITS_USED, TL__BUFFER_BINDINGS_USED,
                    TL__IMAGE_UNITS_USED);
    if (out) gl->Viewport((GLint)out->x, (GLint)out->y, out->width ? (GLsizei)out->width : (GLsizei)r->desc.width,
                          out->height ? (GLsizei)out->height : (GLsizei)r->desc.height);
    else gl->Viewport(0, 0, (GLsizei)r->desc.width, (GLsizei)r->desc.height);
    tl__stream_end(gl, &r->stream);
    return TL_OK;
}

tl_result tl__frame_wait(tl_renderer *r, tl_frame_stats *stats)
{
    const GladGLContext *gl = &r->gl;
    gl->Finish();
    double wall = r->frame_index ? tl__now_ms() - r->frame_start_ms : 0.0;
    tl__queries_drain(r);
    if (stats) {
        *stats = r->last_measured ? r->ring[r->last_slot].rec.st : r->last.st;
        stats->wall_ms = wall;
    }
    GLenum e = gl->GetError();
    if (e != GL_NO_ERROR) return tl__fail(r, TL_ERROR_GL, "renderer: %s during the frames", tl__gl_error_string(e));
    return TL_OK;
}

tl_result tl__frame(tl_renderer *r, const tl_camera *camera, const tl_render_output *out, tl_frame_stats *stats)
{
    tl__view v;
    tl_result res = tl__view_setup(r, camera ? camera : &r->camera, camera ? "camera" : "scene.camera", &v);
    if (res != TL_OK) return res;
    if (!r->programs_ready && (res = tl__graph_programs(r)) != TL_OK) return res;
    double t0 = tl__now_ms(), c0 = tl__thread_cpu_ms();
    int measure = stats || r->desc.options.synchronous_stats;
    uint64_t frame = ++r->frame_index;
    tl__query_slot *slot = measure ? tl__queries_slot(r, frame) : NULL;
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
    if (stats && !tl__queries_newest(r, stats)) {
        memset(stats, 0, sizeof *stats);
    }
    return TL_OK;
}
