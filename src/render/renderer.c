/* The renderer's public entry points: creation in the caller's context, scenes and lights, options,
 * application passes, re-planning, frames. The work is in the modules: device.c, scene_upload.c
 * (the scene on the GPU), lights.c, plan.c and graph.c (what a frame is, and its GL objects),
 * frame.c (running it), readback.c. */
#include <stdio.h>
#include <string.h>

#include "plan_internal.h"
#include "renderer_internal.h"

const char *tl_renderer_last_error(const tl_renderer *r) { return r ? r->dev.log.last_error : "no renderer"; }

void tl_renderer_get_size(const tl_renderer *r, uint32_t *w, uint32_t *h)
{
    if (w) *w = r ? r->desc.width : 0;
    if (h) *h = r ? r->desc.height : 0;
}

tl_result tl_renderer_get_plan(const tl_renderer *r, tl_frame_plan *plan)
{
    if (!r || !plan || !r->scene.loaded) return TL_ERROR_INVALID_ARGUMENT;
    *plan = r->graph.plan.pub;
    return TL_OK;
}

/* TL_ERROR_LIMIT when the plan's target memory is over desc.max_target_bytes. */
static tl_result tl__plan_budget(tl_renderer *r, const tl__plan *plan)
{
    const tl_frame_plan *p = &plan->pub;
    size_t need = (size_t)p->allocated_bytes_per_pixel * r->desc.width * r->desc.height;
    if (!r->desc.max_target_bytes || need <= r->desc.max_target_bytes) return TL_OK;
    return tl__fail(&r->dev, TL_ERROR_LIMIT,
                    "renderer: the targets of a %ux%u frame need %zu bytes (%.1f MiB, %u B/px), over max_target_bytes "
                    "%zu", r->desc.width, r->desc.height, need, (double)need / 1048576.0, p->allocated_bytes_per_pixel,
                    r->desc.max_target_bytes);
}

/* Logs each downgrade of the new plan `p` that the plan it replaces (`old`) did not make: once
 * when it appears, not per frame or per re-plan (docs/frame.md, "Downgrades"). */
static void tl__log_downgrades(tl__device *dev, const tl_frame_plan *p, const tl_frame_plan *old)
{
    for (size_t i = 0; i < p->downgrade_count; i++) {
        int known = 0;
        for (size_t k = 0; k < old->downgrade_count && !known; k++)
            known = memcmp(&p->downgrades[i], &old->downgrades[k], sizeof p->downgrades[i]) == 0;
        if (known) continue;
        char line[256];
        tl_plan_downgrade_format(&p->downgrades[i], line, sizeof line);
        tl__log_message(&dev->log, TL_LOG_WARNING, "renderer: %s", line);
    }
}

/* Re-plans from the options, the scene's features and the application passes; compiles the new
 * plan's GL objects when it differs (never per frame). Planning and the budget fail before
 * anything changes. */
static tl_result tl__replan(tl_renderer *r)
{
    tl__plan plan;
    tl__graph *g = &r->graph;
    tl_scene_feature_set f = r->scene.features;
    f.has_environment = r->env.loaded; /* the renderer's, not the scene's */
    tl_renderer_desc d = r->desc;
    d.options = r->given; /* as the caller gave them: the plan tells an option asked from its default */
    d.options.msaa = r->desc.options.msaa; /* but the samples the context's targets have (tl__msaa_for_context) */
    tl_result res = tl__plan_build(&d, &f, g->apps, g->app_count, &plan);
    if (res != TL_OK) return tl__fail(&r->dev, res, "renderer: planning the frame failed");
    if ((res = tl__plan_budget(r, &plan)) != TL_OK) return res;
    int same = g->pass_count && memcmp(&plan, &g->plan, sizeof plan) == 0;
    if (!same) {
        tl__log_downgrades(&r->dev, &plan.pub, &g->plan.pub);
        g->plan = plan;
        res = tl__graph_compile(&r->dev, g, r->scene.loaded);
        const tl_frame_plan *p = &g->plan.pub;
        if (res == TL_OK && (p->targets & TL_TARGET_BIT(TL_TARGET_LIGHT_LISTS)))
            res = tl__tiles_configure(&r->dev, &r->lights.tiles, p->tile_size, p->tiles_x, p->tiles_y);
        else if (res == TL_OK) /* no tiles in this plan: nothing kept for them */
            tl__tiles_release(&r->dev, &r->lights.tiles);
        if (res == TL_OK && (p->targets & TL_TARGET_BIT(TL_TARGET_LIGHT_FIXUP)))
            res = tl__fixup_configure(&r->dev, &r->lights.fixup);
        else if (res == TL_OK)
            tl__fixup_release(&r->dev, &r->lights.fixup);
    } else if (r->scene.loaded && !g->programs_ready) {
        res = tl__graph_programs(&r->dev, g);
    }
    if (res != TL_OK) return res;
    tl__scene_vao(&r->dev, &r->scene, g->plan.pub.vertex_attributes);
    return TL_OK;
}

/* ---- create / destroy ----------------------------------------------------------------------- */

/* options.msaa against the context: refused past its sample counts, and a count its targets cannot
 * have exactly made the one they get (llvmpipe has only 4: 2 gives 4), said once (`say`), so that
 * the plan, every shader's sample loop and every target count the samples the targets have. */
static tl_result tl__msaa_for_context(tl_renderer *r, tl_renderer_options *o, const char *call, int say)
{
    uint32_t asked = o->msaa, real = tl__device_samples(&r->dev, asked);
    if (real == asked) return TL_OK;
    if (!real) {
        char counts[96] = "0", *at = counts + 1;
        uint32_t last = 1;
        for (uint32_t n = 2; n < 32u; n++) /* "0, 1, 2 or 4" */
            if (r->dev.lim.sample_counts & (1u << n)) {
                at += snprintf(at, (size_t)(counts + sizeof counts - at), ", %u", last);
                last = n;
            }
        snprintf(at, (size_t)(counts + sizeof counts - at), " or %u", last);
        return tl__fail(&r->dev, TL_ERROR_UNSUPPORTED,
                        "renderer: %soptions.msaa = %u is out of range for this context (%s: the sample counts its "
                        "multisampled target formats have)", call, asked, counts);
    }
    if (say)
        tl__log_message(&r->dev.log, TL_LOG_WARNING,
                        "renderer: %soptions.msaa = %u: this context's multisampled targets have no %u-sample form; "
                        "the frame uses %u samples, the next count it has (tl_frame_plan.msaa)", call, asked, asked, real);
    o->msaa = real;
    return TL_OK;
}

static tl_result tl__create_objects(tl_renderer *r, const tl_renderer_desc *desc)
{
    tl_result res = tl__device_init(&r->dev, desc);
    if (res == TL_OK) res = tl__msaa_for_context(r, &r->desc.options, "", 1);
    if (res != TL_OK) return res;
    r->dev.state.reversed = r->desc.options.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED;
    tl__light_volumes_create(&r->dev, &r->lights);
    tl__queries_create(&r->dev, &r->queries, &r->lights.tiles, &r->lights.fixup);
    /* until a scene arrives: the plan of an empty scene (tone map and FXAA targets) */
    res = tl__replan(r);
    GLenum e = r->dev.gl.GetError();
    if (res == TL_OK && e != GL_NO_ERROR)
        res = tl__fail(&r->dev, TL_ERROR_GL, "renderer: %s while creating resources", tl__gl_error_string(e));
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
    tl__why why = {""};
    tl_result res = tl__renderer_desc_resolve(desc, &d, &why);
    if (res != TL_OK) return tl__logger_fail(&desc->logger, res, "renderer: %s", why.text);
    tl_renderer *r = (tl_renderer *)tl__calloc(&a, 1, sizeof *r);
    if (!r) return tl__logger_fail(&desc->logger, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory");
    r->desc = d;
    r->desc.allocator = a;
    r->given = desc->options;
    r->dev.alloc = a;
    r->dev.log.logger = d.logger;
    r->dev.get_proc_address = d.get_proc_address;
    r->dev.get_proc_address_user = d.get_proc_address_user;
    tl__context_check_init(&r->dev, d.is_current);
    if ((r->dev.is_current || r->dev.own_context) && !tl__context_current(&r->dev)) { /* else GL loading tells */
        tl__logger_fail(&d.logger, TL_ERROR_GL, "renderer: tl_renderer_create: no GL context is current on this thread "
                                                "(the renderer is created in the current context)");
        tl__context_check_release(&r->dev);
        tl__free(&a, r);
        return TL_ERROR_GL;
    }
    if ((res = tl__device_load(&r->dev)) != TL_OK) {
        tl__context_check_release(&r->dev);
        tl__free(&a, r); /* no GL: nothing to free in it (the message went to the logger) */
        return res;
    }
    if ((res = tl__create_objects(r, &d)) != TL_OK) {
        tl_renderer_destroy(r); /* the message went to the logger with tl__fail */
        return res;
    }
    *out = r;
    return TL_OK;
}

void tl_renderer_destroy(tl_renderer *r)
{
    if (!r) return;
    if (tl__context_gone(&r->dev)) tl__device_lose(&r->dev); /* its GL objects went with it: memory only */
    /* GL names mean other objects in another context: leave everything for a call that can */
    else if (tl__need_context(&r->dev, "tl_renderer_destroy") != TL_OK) return;
    tl__scene_release(&r->dev, &r->scene);
    tl__lights_release(&r->dev, &r->lights);
    tl__shadows_release(&r->dev, &r->shadows);
    tl__environment_release(&r->dev, &r->env);
    tl__graph_release(&r->dev, &r->graph);
    tl__queries_destroy(&r->dev, &r->queries);
    tl__device_release(&r->dev);
    tl__context_check_release(&r->dev);
    tl_allocator a = r->dev.alloc;
    tl__free(&a, r);
}

/* ---- scene, lights, size -------------------------------------------------------------------- */

tl_result tl_renderer_set_scene(tl_renderer *r, const tl_scene *s)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl__device *dev = &r->dev;
    tl_result res = tl__need_context(dev, "tl_renderer_set_scene");
    if (res != TL_OK) return res;
    if (!s) return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: no scene");
    tl__scene_frame frame;
    res = tl__scene_validate(dev, s);
    if (res == TL_OK) res = tl__scene_camera(dev, s, r->desc.options.depth_format, &frame);
    if (res == TL_OK) res = tl__lights_store(dev, &r->lights, s->lights, s->light_count);
    if (res != TL_OK) return res;
    tl__scene_release(dev, &r->scene);
    tl__pixel_store saved; /* textures upload with GL's unpack defaults; the application's come back */
    tl__pixel_store_enter(&dev->gl, 1, &saved);
    res = tl__scene_upload(dev, &r->scene, s);
    tl__pixel_store_leave(&dev->gl, &saved);
    if (res == TL_OK) res = tl__lights_objects(dev, &r->lights, s->object_count);
    if (res != TL_OK) {
        tl__scene_release(dev, &r->scene);
        return res;
    }
    tl__scene_take_frame(dev, &r->scene, &frame);
    tl__ambient_resolve(r->desc.options.ambient, r->scene.ambient, r->ambient);
    r->graph.programs_ready = 0;
    if ((res = tl__replan(r)) != TL_OK) {
        r->scene.loaded = 0;
        return res;
    }
    GLenum e = dev->gl.GetError();
    if (e != GL_NO_ERROR)
        return tl__fail(dev, TL_ERROR_GL, "renderer: %s while uploading the scene", tl__gl_error_string(e));
    return TL_OK;
}

tl_result tl_renderer_set_lights(tl_renderer *r, const tl_light *lights, size_t count)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    size_t before[TL__LIGHT_KINDS];
    memcpy(before, r->lights.kinds, sizeof before);
    tl_result res = tl__need_context(&r->dev, "tl_renderer_set_lights");
    if (res == TL_OK) res = tl__lights_store(&r->dev, &r->lights, lights, count);
    if (res != TL_OK || !r->scene.loaded) return res;
    const size_t *kinds = r->lights.kinds;
    tl_scene_feature_set *f = &r->scene.features;
    int changed = (before[0] > 0) != (kinds[0] > 0) || (before[1] > 0) != (kinds[1] > 0) ||
                  (before[2] > 0) != (kinds[2] > 0);
    f->point_lights = kinds[0];
    f->spot_lights = kinds[1];
    f->directional_lights = kinds[2];
    size_t shadows_before = f->shadow_lights;
    f->shadow_lights = 0;
    for (size_t i = 0; i < r->lights.count; i++) f->shadow_lights += r->lights.lights[i].shadow != 0;
    changed |= f->shadow_lights != shadows_before; /* the plan reports the count */
    /* light types decide passes and programs: re-plan when they change */
    return changed ? tl__replan(r) : TL_OK;
}

/* ---- scene updates (scene_update.c) --------------------------------------------------------- */

tl_result tl_renderer_set_environment(tl_renderer *r, const tl_environment_desc *desc)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_set_environment");
    if (res != TL_OK) return res;
    int had = r->env.loaded;
    if ((res = tl__environment_set(&r->dev, &r->env, desc)) != TL_OK) return res;
    /* the sky pass and the shading passes' TL_IBL come and go with it */
    return had != r->env.loaded ? tl__replan(r) : TL_OK;
}

/* After an update: the lights' per-object lists as long as the objects' slots, a new plan when the
 * scene's features changed. */
static tl_result tl__updated(tl_renderer *r, tl_result res, int replan)
{
    if (res != TL_OK) return res;
    if (r->lights.fwd_objects < r->scene.object_capacity &&
        (res = tl__lights_objects(&r->dev, &r->lights, r->scene.object_capacity)) != TL_OK)
        return res;
    return replan ? tl__replan(r) : TL_OK;
}

tl_result tl_renderer_set_object_transform(tl_renderer *r, uint32_t object, const float transform[16])
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_set_object_transform");
    return res != TL_OK ? res : tl__scene_set_transform(&r->dev, &r->scene, object, transform);
}

tl_result tl_renderer_set_object_visible(tl_renderer *r, uint32_t object, int visible)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_set_object_visible");
    return res != TL_OK ? res : tl__scene_set_visible(&r->dev, &r->scene, object, visible);
}

tl_result tl_renderer_set_object(tl_renderer *r, uint32_t object, const tl_object *desc)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    int replan = 0;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_set_object");
    if (res == TL_OK) res = tl__scene_set_object(&r->dev, &r->scene, object, desc, &replan);
    return tl__updated(r, res, replan);
}

tl_result tl_renderer_add_object(tl_renderer *r, const tl_object *desc, uint32_t *object)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    int replan = 0;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_add_object");
    if (res == TL_OK) res = tl__scene_add_object(&r->dev, &r->scene, desc, object, &replan);
    return tl__updated(r, res, replan);
}

tl_result tl_renderer_remove_object(tl_renderer *r, uint32_t object)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    int replan = 0;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_remove_object");
    if (res == TL_OK) res = tl__scene_remove_object(&r->dev, &r->scene, object, &replan);
    return tl__updated(r, res, replan);
}

tl_result tl_renderer_add_geometry(tl_renderer *r, const tl_vertex *vertices, size_t vertex_count,
                                   const uint32_t *indices, size_t index_count, uint32_t *first_index)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_add_geometry");
    if (res == TL_OK)
        res = tl__scene_add_geometry(&r->dev, &r->scene, vertices, vertex_count, indices, index_count, first_index);
    return res;
}

tl_result tl_renderer_set_material(tl_renderer *r, uint32_t index, const tl_material *material)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    int replan = 0;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_set_material");
    if (res == TL_OK) res = tl__scene_set_material(&r->dev, &r->scene, index, material, &replan);
    return tl__updated(r, res, replan);
}

tl_result tl_renderer_add_material(tl_renderer *r, const tl_material *material, uint32_t *index)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    int replan = 0;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_add_material");
    if (res == TL_OK) res = tl__scene_add_material(&r->dev, &r->scene, material, index, &replan);
    return tl__updated(r, res, replan);
}

tl_result tl_renderer_add_texture(tl_renderer *r, const tl_texture *texture, uint32_t *index)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_add_texture");
    if (res != TL_OK) return res;
    tl__pixel_store saved; /* uploaded with GL's unpack defaults; the application's come back */
    tl__pixel_store_enter(&r->dev.gl, 1, &saved);
    res = tl__scene_add_texture(&r->dev, &r->scene, texture, index);
    tl__pixel_store_leave(&r->dev.gl, &saved);
    return res;
}

tl_result tl_renderer_get_object(tl_renderer *r, uint32_t object, tl_object *desc, int *visible)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__scene_object_id(&r->dev, &r->scene, object, "get_object");
    if (res != TL_OK) return res;
    if (desc) *desc = r->scene.objects[object];
    if (visible) *visible = !(r->scene.object_state[object] & TL__OBJECT_HIDDEN);
    return TL_OK;
}

tl_result tl_renderer_resize(tl_renderer *r, uint32_t width, uint32_t height)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result need = tl__need_context(&r->dev, "tl_renderer_resize");
    if (need != TL_OK) return need;
    GLint max_size = r->dev.lim.max_texture_size;
    if (!width || !height || width > TL__MAX_SIZE || height > TL__MAX_SIZE || (GLint)width > max_size ||
        (GLint)height > max_size)
        return tl__fail(&r->dev, width && height ? TL_ERROR_LIMIT : TL_ERROR_INVALID_ARGUMENT,
                        "renderer: size %ux%u outside 1..%d", width, height,
                        max_size < (GLint)TL__MAX_SIZE ? max_size : (int)TL__MAX_SIZE);
    if (width == r->desc.width && height == r->desc.height) return TL_OK;
    uint32_t old_w = r->desc.width, old_h = r->desc.height;
    int drawn = r->output_drawn;
    r->output_drawn = 0; /* the output target is re-made at the new size: nothing drawn in it */
    r->desc.width = width;
    r->desc.height = height;
    tl_result res = tl__replan(r);
    /* refused before anything changed (the budget): the old size stays with the old plan */
    const tl_frame_plan *p = &r->graph.plan.pub;
    if (res != TL_OK && p->width == old_w && p->height == old_h) {
        r->desc.width = old_w;
        r->desc.height = old_h;
        r->output_drawn = drawn;
    }
    return res;
}

/* ---- options ------------------------------------------------------------------------------- */

/* The options of `d` in effect: the depth comparisons and the ambient term follow them. */
static void tl__options_take(tl_renderer *r, const tl_renderer_desc *d)
{
    r->desc = *d;
    r->dev.state.reversed = d->options.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED;
    tl__ambient_resolve(d->options.ambient, r->scene.ambient, r->ambient);
}

tl_result tl_renderer_set_options(tl_renderer *r, const tl_renderer_options *options)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_set_options");
    if (res != TL_OK) return res;
    if (!options) return tl__fail(&r->dev, TL_ERROR_INVALID_ARGUMENT, "renderer: set_options needs options");
    tl_renderer_desc d = r->desc, old = r->desc;
    tl__why why = {""};
    if ((res = tl__options_resolve(options, &d.options, &why)) != TL_OK)
        return tl__fail(&r->dev, res, "renderer: set_options: %s", why.text);
    if ((res = tl__msaa_for_context(r, &d.options, "set_options: ", options->msaa != r->given.msaa)) != TL_OK) return res;
    tl_renderer_options given = r->given;
    tl__options_take(r, &d);
    r->given = *options;
    if ((res = tl__replan(r)) != TL_OK) { /* the old options, with the plan they had */
        tl__options_take(r, &old);
        r->given = given;
        tl__replan(r);
        return res;
    }
    return TL_OK;
}

void tl_renderer_get_options(const tl_renderer *r, tl_renderer_options *options)
{
    if (!options) return;
    if (r) *options = r->given;
    else memset(options, 0, sizeof *options);
}

/* ---- application passes ---------------------------------------------------------------------- */

static tl_result tl__app_check(tl_renderer *r, const tl_app_pass_desc *d, int *anchor)
{
    const uint32_t writable = TL_TARGET_BIT(TL_TARGET_HDR) | TL_TARGET_BIT(TL_TARGET_OUTPUT);
    const uint32_t all = TL_TARGET_BIT(TL_TARGET_COUNT) - 1u;
    tl__device *dev = &r->dev;
    const tl__graph *g = &r->graph;
    if (!d->name || !d->name[0] || strlen(d->name) > 31 || !d->execute)
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT,
                        "renderer: an application pass needs a name (1..31 characters) and execute");
    for (size_t i = 0; i < g->app_count; i++)
        if (strcmp(g->apps[i].name, d->name) == 0)
            return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: an application pass \"%s\" exists already",
                            d->name);
    if (g->app_count == TL_MAX_APP_PASSES)
        return tl__fail(dev, TL_ERROR_LIMIT, "renderer: at most %d application passes", TL_MAX_APP_PASSES);
    if (!d->writes || (d->writes & ~writable) || (d->reads & ~all) || (d->reads & d->writes))
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT,
                        "renderer: application pass \"%s\" may write only hdr and output, and not read what it writes",
                        d->name);
    if (!d->after == !d->before)
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT,
                        "renderer: application pass \"%s\" needs exactly one of after and before", d->name);
    *anchor = tl__pass_table_find(d->after ? d->after : d->before);
    if (*anchor < 0)
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: application pass \"%s\": no pass \"%s\"", d->name,
                        d->after ? d->after : d->before);
    return TL_OK;
}

tl_result tl_renderer_add_pass(tl_renderer *r, const tl_app_pass_desc *desc)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_add_pass");
    if (res != TL_OK) return res;
    if (!desc) return tl__fail(&r->dev, TL_ERROR_INVALID_ARGUMENT, "renderer: no application pass");
    int anchor = -1;
    res = tl__app_check(r, desc, &anchor);
    if (res != TL_OK) return res;
    tl__graph *g = &r->graph;
    tl__app_pass *a = &g->apps[g->app_count++];
    memset(a, 0, sizeof *a);
    a->desc = *desc;
    snprintf(a->name, sizeof a->name, "%s", desc->name);
    a->desc.name = a->name;
    a->desc.after = a->desc.before = NULL;
    a->anchor = anchor;
    a->after = desc->after != NULL;
    res = tl__replan(r);
    if (res != TL_OK) g->app_count--; /* not added (over the target budget, say) */
    return res;
}

tl_result tl_renderer_remove_pass(tl_renderer *r, const char *name)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_remove_pass");
    if (res != TL_OK) return res;
    tl__graph *g = &r->graph;
    for (size_t i = 0; name && i < g->app_count; i++)
        if (strcmp(g->apps[i].name, name) == 0) {
            memmove(&g->apps[i], &g->apps[i + 1], (g->app_count - i - 1) * sizeof g->apps[0]);
            g->app_count--;
            for (size_t k = i; k < g->app_count; k++) g->apps[k].desc.name = g->apps[k].name;
            return tl__replan(r);
        }
    return tl__fail(&r->dev, TL_ERROR_INVALID_ARGUMENT, "renderer: no application pass \"%s\"", name ? name : "(null)");
}

/* ---- frames ---------------------------------------------------------------------------------- */

static tl_result tl__need_scene(tl_renderer *r)
{
    if (r->scene.loaded) return TL_OK;
    return tl__fail(&r->dev, TL_ERROR_INVALID_ARGUMENT, "renderer: no scene (call tl_renderer_set_scene first)");
}

tl_result tl_renderer_render(tl_renderer *r, const tl_camera *camera, tl_frame_stats *stats)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_render");
    if (res == TL_OK) res = tl__need_scene(r);
    if (res == TL_OK) res = tl__frame(r, camera, NULL, stats);
    if (res == TL_OK) r->output_drawn = 1;
    return res;
}

tl_result tl_renderer_render_to(tl_renderer *r, const tl_camera *camera, const tl_render_output *output,
                                tl_frame_stats *stats)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_render_to");
    if (res != TL_OK) return res;
    if (!output) return tl__fail(&r->dev, TL_ERROR_INVALID_ARGUMENT, "renderer: render_to needs an output");
    res = tl__need_scene(r);
    if (res == TL_OK) res = tl__output_check(&r->dev, output);
    return res == TL_OK ? tl__frame(r, camera, output, stats) : res;
}

tl_result tl_renderer_wait(tl_renderer *r, tl_frame_stats *stats)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__need_context(&r->dev, "tl_renderer_wait");
    return res == TL_OK ? tl__frame_wait(r, stats) : res;
}
