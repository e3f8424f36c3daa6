/* The renderer's public entry points: creation in the caller's context, scenes and lights,
 * application passes, re-planning, frames. The work is in the files below: plan.c (what a frame
 * is), graph.c (its GL objects), frame.c (running it), scene_upload.c, readback.c. */
#include <stdio.h>
#include <string.h>

#include "plan_internal.h"
#include "renderer_internal.h"
#include "scene_upload.h"

const char *tl_renderer_last_error(const tl_renderer *r) { return r ? r->log.last_error : "no renderer"; }

void tl_renderer_get_size(const tl_renderer *r, uint32_t *w, uint32_t *h)
{
    if (w) *w = r ? r->desc.width : 0;
    if (h) *h = r ? r->desc.height : 0;
}

tl_result tl_renderer_get_plan(const tl_renderer *r, tl_frame_plan *plan)
{
    if (!r || !plan || !r->has_scene) return TL_ERROR_INVALID_ARGUMENT;
    *plan = r->plan.pub;
    return TL_OK;
}

/* TL_ERROR_LIMIT when the plan's target memory is over desc.max_target_bytes. */
static tl_result tl__plan_budget(tl_renderer *r, const tl__plan *plan)
{
    const tl_frame_plan *p = &plan->pub;
    size_t need = (size_t)p->allocated_bytes_per_pixel * r->desc.width * r->desc.height;
    if (!r->desc.max_target_bytes || need <= r->desc.max_target_bytes) return TL_OK;
    return tl__fail(r, TL_ERROR_LIMIT,
                    "renderer: the targets of a %ux%u frame need %zu bytes (%.1f MiB, %u B/px), over max_target_bytes "
                    "%zu", r->desc.width, r->desc.height, need, (double)need / 1048576.0, p->allocated_bytes_per_pixel,
                    r->desc.max_target_bytes);
}

/* Re-plans from the options, the scene's features and the application passes; compiles the new
 * plan's GL objects when it differs (never per frame). Planning and the budget fail before
 * anything changes. */
static tl_result tl__replan(tl_renderer *r)
{
    tl__plan plan;
    tl_result res = tl__plan_build(&r->desc, &r->features, r->apps, r->app_count, &plan);
    if (res != TL_OK) return tl__fail(r, res, "renderer: planning the frame failed");
    if ((res = tl__plan_budget(r, &plan)) != TL_OK) return res;
    int same = r->pass_count && memcmp(&plan, &r->plan, sizeof plan) == 0;
    if (!same) {
        tl__queries_drain(r); /* the ring's frames refer to the old passes */
        r->plan = plan;
        res = tl__graph_compile(r);
    } else if (r->has_scene && !r->programs_ready) {
        res = tl__graph_programs(r);
    }
    if (res != TL_OK) return res;
    tl__scene_vao(r);
    return TL_OK;
}

/* ---- create / destroy ----------------------------------------------------------------------- */

static GLADapiproc tl__load_thunk(void *user, const char *name)
{
    tl_renderer *r = (tl_renderer *)user;
    return (GLADapiproc)r->desc.get_proc_address(r->desc.get_proc_address_user, name);
}

/* What one storage block may hold (GL's limit, or the descriptor's lower one; at most 4 GiB - 1,
 * since the shaders index with uint), and so how many lights of 64 bytes the renderer takes. */
static void tl__storage_limits(tl_renderer *r)
{
    GLint64 gl_max = 0;
    r->gl.GetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &gl_max);
    size_t m = gl_max > 0 ? (size_t)gl_max : (size_t)1 << 24; /* GL 4.3's minimum */
    if (m > UINT32_MAX) m = UINT32_MAX;
    if (r->desc.max_storage_block_bytes && r->desc.max_storage_block_bytes < m) m = r->desc.max_storage_block_bytes;
    r->storage_max = m;
    size_t lights = m / sizeof(tl__forward_light);
    r->max_lights = lights < TL_RENDERER_MAX_LIGHTS ? lights : TL_RENDERER_MAX_LIGHTS;
}

static tl_result tl__create_objects(tl_renderer *r)
{
    const GladGLContext *gl = &r->gl;
    GLint max_size = 0, ubo_align = 0, ssbo_align = 0;
    gl->GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    r->max_texture_size = max_size;
    if ((GLint)r->desc.width > max_size || (GLint)r->desc.height > max_size)
        return tl__fail(r, TL_ERROR_LIMIT, "renderer: %ux%u exceeds GL_MAX_TEXTURE_SIZE %d", r->desc.width,
                        r->desc.height, max_size);
    gl->GetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &ubo_align);
    gl->GetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &ssbo_align);
    r->ubo_align = ubo_align > 16 ? (size_t)ubo_align : 16;
    r->ssbo_align = ssbo_align > 16 ? (size_t)ssbo_align : 16;
    tl__storage_limits(r);
    r->state.reversed = r->desc.options.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED;
    tl__light_volumes_create(r);
    gl->CreateVertexArrays(1, &r->vao_empty);
    tl__gl_label(gl, GL_VERTEX_ARRAY, r->vao_empty, "vao.fullscreen");
    gl->CreateSamplers(1, &r->sampler_linear);
    tl__gl_label(gl, GL_SAMPLER, r->sampler_linear, "sampler.linear");
    gl->SamplerParameteri(r->sampler_linear, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl->SamplerParameteri(r->sampler_linear, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->SamplerParameteri(r->sampler_linear, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->SamplerParameteri(r->sampler_linear, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    tl__queries_create(r);
    /* until a scene arrives: the plan of an empty scene (tone map and FXAA targets) */
    tl_result res = tl__replan(r);
    GLenum e = gl->GetError();
    if (res == TL_OK && e != GL_NO_ERROR)
        res = tl__fail(r, TL_ERROR_GL, "renderer: %s while creating resources", tl__gl_error_string(e));
    return res;
}

tl_result tl_renderer_create(const tl_renderer_desc *desc, tl_renderer **out)
{
    if (!out) return TL_ERROR_INVALID_ARGUMENT;
    *out = NULL;
    if (!desc || !desc->get_proc_address)
        return tl__logger_fail(desc ? &desc->logger : NULL, TL_ERROR_INVALID_ARGUMENT,
                               "renderer: a descriptor with get_proc_address is required");
    tl_allocator a;
    if (tl__allocator_resolve(&desc->allocator, &a) != TL_OK)
        return tl__logger_fail(&desc->logger, TL_ERROR_INVALID_ARGUMENT,
                               "renderer: the allocator needs both alloc and free");
    tl_renderer_desc d;
    tl_result res = tl__renderer_desc_resolve(desc, &d);
    if (res != TL_OK)
        return tl__logger_fail(&desc->logger, res, "renderer: size %ux%u or an option is out of range (at most %u per side)",
                               d.width, d.height, TL__MAX_SIZE);
    tl_renderer *r = (tl_renderer *)tl__calloc(&a, 1, sizeof *r);
    if (!r) return tl__logger_fail(&desc->logger, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory");
    r->alloc = a;
    r->desc = d;
    r->options_given = desc->options;
    r->desc.allocator = a;
    r->log.logger = d.logger;
    tl__context_check_init(r);
    if (r->is_current && !tl__context_current(r)) { /* without a callback GL loading tells */
        tl__logger_fail(&d.logger, TL_ERROR_GL, "renderer: tl_renderer_create: no GL context is current on this thread "
                                                "(the renderer is created in the current context)");
        tl__free(&a, r);
        return TL_ERROR_GL;
    }
    char msg[512];
    res = tl__gl_load(&r->gl, tl__load_thunk, r, msg, sizeof msg);
    if (res != TL_OK) {
        tl__logger_fail(&d.logger, res, "renderer: %s", msg);
        tl__free(&a, r);
        return res;
    }
    res = tl__create_objects(r);
    if (res != TL_OK) {
        tl_renderer_destroy(r); /* the message went to the logger with tl__fail */
        return res;
    }
    *out = r;
    return TL_OK;
}

void tl_renderer_destroy(tl_renderer *r)
{
    if (!r) return;
    /* GL names mean other objects in another context: leave everything for a call that can */
    if (tl__need_context(r, "tl_renderer_destroy") != TL_OK) return;
    const GladGLContext *gl = &r->gl;
    tl__scene_release(r);
    tl__lights_release(r);
    tl__graph_release(r);
    tl__program_cache_destroy(r);
    tl__light_volumes_destroy(r);
    tl__queries_destroy(r);
    tl__stream_destroy(gl, &r->stream);
    if (r->vao_empty) gl->DeleteVertexArrays(1, &r->vao_empty);
    if (r->sampler_linear) gl->DeleteSamplers(1, &r->sampler_linear);
    tl_allocator a = r->alloc;
    tl__free(&a, r);
}

/* ---- scene, lights, size -------------------------------------------------------------------- */

/* The scene's camera, bounds and warnings replace the previous scene's. */
static void tl__scene_frame_take(tl_renderer *r, const tl__scene_frame *f)
{
    memcpy(r->bounds_min, f->bounds_min, sizeof r->bounds_min);
    memcpy(r->bounds_max, f->bounds_max, sizeof r->bounds_max);
    r->has_bounds = f->has_bounds;
    r->frame_camera = f->camera;
    r->warned = f->warning[0] ? TL__WARNED_NEAR : 0;
    if (f->warning[0]) tl__log_message(&r->log, TL_LOG_WARNING, "renderer: %s", f->warning);
}

tl_result tl_renderer_set_scene(tl_renderer *r, const tl_scene *s)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(r, "tl_renderer_set_scene");
    if (res != TL_OK) return res;
    if (!s) return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: no scene");
    tl__scene_frame frame;
    res = tl__scene_validate(r, s);
    if (res == TL_OK) res = tl__scene_camera(r, s, &frame);
    size_t kinds[TL__LIGHT_KINDS];
    if (res == TL_OK) res = tl__lights_store(r, s->lights, s->light_count, kinds);
    if (res != TL_OK) return res;
    tl__queries_drain(r);
    tl__scene_release(r);
    tl__pixel_store saved; /* textures upload with GL's unpack defaults; the application's come back */
    tl__pixel_store_enter(&r->gl, 1, &saved);
    res = tl__scene_upload(r, s);
    tl__pixel_store_leave(&r->gl, &saved);
    if (res != TL_OK) return res;
    tl__scene_frame_take(r, &frame);
    r->has_scene = 1;
    r->programs_ready = 0;
    if ((res = tl__replan(r)) != TL_OK) {
        r->has_scene = 0;
        return res;
    }
    GLenum e = r->gl.GetError();
    if (e != GL_NO_ERROR)
        return tl__fail(r, TL_ERROR_GL, "renderer: %s while uploading the scene", tl__gl_error_string(e));
    return TL_OK;
}

tl_result tl_renderer_set_lights(tl_renderer *r, const tl_light *lights, size_t count)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    size_t kinds[TL__LIGHT_KINDS];
    tl_result res = tl__need_context(r, "tl_renderer_set_lights");
    if (res == TL_OK) res = tl__lights_store(r, lights, count, kinds);
    if (res != TL_OK || !r->has_scene) return res;
    tl_scene_feature_set *f = &r->features;
    int changed = (f->point_lights > 0) != (kinds[0] > 0) || (f->spot_lights > 0) != (kinds[1] > 0) ||
                  (f->directional_lights > 0) != (kinds[2] > 0);
    f->point_lights = kinds[0];
    f->spot_lights = kinds[1];
    f->directional_lights = kinds[2];
    /* light types decide passes and programs: re-plan when they change */
    return changed ? tl__replan(r) : TL_OK;
}

tl_result tl_renderer_resize(tl_renderer *r, uint32_t width, uint32_t height)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result need = tl__need_context(r, "tl_renderer_resize");
    if (need != TL_OK) return need;
    tl_renderer_desc d = r->desc;
    d.width = width;
    d.height = height;
    GLint max_size = r->max_texture_size;
    if (!width || !height || width > TL__MAX_SIZE || height > TL__MAX_SIZE || (GLint)width > max_size ||
        (GLint)height > max_size)
        return tl__fail(r, width && height ? TL_ERROR_LIMIT : TL_ERROR_INVALID_ARGUMENT,
                        "renderer: size %ux%u outside 1..%d", width, height,
                        max_size < (GLint)TL__MAX_SIZE ? max_size : (int)TL__MAX_SIZE);
    if (width == r->desc.width && height == r->desc.height) return TL_OK;
    tl_renderer_desc old = r->desc;
    r->desc = d;
    tl_result res = tl__replan(r);
    /* refused before anything changed (the budget): the old size stays with the old plan */
    if (res != TL_OK && r->plan.pub.width == old.width && r->plan.pub.height == old.height) r->desc = old;
    return res;
}

/* ---- options ------------------------------------------------------------------------------- */

tl_result tl_renderer_set_options(tl_renderer *r, const tl_renderer_options *options)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(r, "tl_renderer_set_options");
    if (res != TL_OK) return res;
    if (!options) return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: set_options needs options");
    tl_renderer_desc d = r->desc;
    d.options = *options;
    if ((res = tl__renderer_desc_resolve(&d, &d)) != TL_OK)
        return tl__fail(r, res, "renderer: an option is out of range");
    tl_renderer_desc old = r->desc;
    r->desc = d;
    r->state.reversed = d.options.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED;
    res = tl__replan(r);
    if (res != TL_OK) { /* the old options, with the plan they had */
        r->desc = old;
        r->state.reversed = old.options.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED;
        tl__replan(r);
        return res;
    }
    r->options_given = *options;
    r->state.reversed = d.options.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED;
    tl__ambient_resolve(d.options.ambient, r->scene_ambient, r->ambient);
    return res;
}

void tl_renderer_get_options(const tl_renderer *r, tl_renderer_options *options)
{
    if (!options) return;
    if (r) *options = r->options_given;
    else memset(options, 0, sizeof *options);
}

/* ---- application passes ---------------------------------------------------------------------- */

static tl_result tl__app_check(tl_renderer *r, const tl_app_pass_desc *d, int *anchor)
{
    const uint32_t writable = TL_TARGET_BIT(TL_TARGET_HDR) | TL_TARGET_BIT(TL_TARGET_OUTPUT);
    const uint32_t all = TL_TARGET_BIT(TL_TARGET_COUNT) - 1u;
    if (!d->name || !d->name[0] || strlen(d->name) > 31 || !d->execute)
        return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: an application pass needs a name (1..31 characters) and execute");
    for (size_t i = 0; i < r->app_count; i++)
        if (strcmp(r->apps[i].name, d->name) == 0)
            return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: an application pass \"%s\" exists already", d->name);
    if (r->app_count == TL_MAX_APP_PASSES)
        return tl__fail(r, TL_ERROR_LIMIT, "renderer: at most %d application passes", TL_MAX_APP_PASSES);
    if (!d->writes || (d->writes & ~writable) || (d->reads & ~all) || (d->reads & d->writes))
        return tl__fail(r, TL_ERROR_INVALID_ARGUMENT,
                        "renderer: application pass \"%s\" may write only hdr and output, and not read what it writes", d->name);
    if (!d->after == !d->before)
        return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: application pass \"%s\" needs exactly one of after and before",
                        d->name);
    *anchor = tl__pass_table_find(d->after ? d->after : d->before);
    if (*anchor < 0)
        return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: application pass \"%s\": no pass \"%s\"", d->name,
                        d->after ? d->after : d->before);
    return TL_OK;
}

tl_result tl_renderer_add_pass(tl_renderer *r, const tl_app_pass_desc *desc)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(r, "tl_renderer_add_pass");
    if (res != TL_OK) return res;
    if (!desc) return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: no application pass");
    int anchor = -1;
    res = tl__app_check(r, desc, &anchor);
    if (res != TL_OK) return res;
    tl__app_pass *a = &r->apps[r->app_count++];
    memset(a, 0, sizeof *a);
    a->desc = *desc;
    snprintf(a->name, sizeof a->name, "%s", desc->name);
    a->desc.name = a->name;
    a->desc.after = a->desc.before = NULL;
    a->anchor = anchor;
    a->after = desc->after != NULL;
    res = tl__replan(r);
    if (res != TL_OK) r->app_count--; /* not added (over the target budget, say) */
    return res;
}

tl_result tl_renderer_remove_pass(tl_renderer *r, const char *name)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(r, "tl_renderer_remove_pass");
    if (res != TL_OK) return res;
    for (size_t i = 0; name && i < r->app_count; i++)
        if (strcmp(r->apps[i].name, name) == 0) {
            memmove(&r->apps[i], &r->apps[i + 1], (r->app_count - i - 1) * sizeof r->apps[0]);
            r->app_count--;
            for (size_t k = i; k < r->app_count; k++) r->apps[k].desc.name = r->apps[k].name;
            return tl__replan(r);
        }
    return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: no application pass \"%s\"", name ? name : "(null)");
}

/* ---- frames ---------------------------------------------------------------------------------- */

static tl_result tl__need_scene(tl_renderer *r)
{
    if (r->has_scene) return TL_OK;
    return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: no scene (call tl_renderer_set_scene first)");
}

tl_result tl_renderer_render(tl_renderer *r, const tl_camera *camera, tl_frame_stats *stats)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(r, "tl_renderer_render");
    if (res == TL_OK) res = tl__need_scene(r);
    return res == TL_OK ? tl__frame(r, camera, NULL, stats) : res;
}

tl_result tl_renderer_render_to(tl_renderer *r, const tl_camera *camera, const tl_render_output *output,
                                tl_frame_stats *stats)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(r, "tl_renderer_render_to");
    if (res != TL_OK) return res;
    if (!output) return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: render_to needs an output");
    res = tl__need_scene(r);
    if (res == TL_OK) res = tl__output_check(r, output);
    return res == TL_OK ? tl__frame(r, camera, output, stats) : res;
}

tl_result tl_renderer_wait(tl_renderer *r, tl_frame_stats *stats)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(r, "tl_renderer_wait");
    return res == TL_OK ? tl__frame_wait(r, stats) : res;
}
