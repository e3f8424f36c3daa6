/* The viewer's scene and renderers: loading the crypt or a glTF file, the renderers the current
 * settings and view need (made once, then given new options with tl_renderer_set_options),
 * animating the lights. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "session.h"
#include "thinlight/io.h"

/* Each line once (a change of settings plans the frames again, and a scene is set again on every
 * change of the light count: their warnings would repeat); an error also for the panel. */
static void vw_log(void *user, tl_log_level level, const char *message)
{
    vw_app *app = (vw_app *)user;
    if (!app) {
        tl_logger plain = tl_tool_logger("thinlight-viewer");
        plain.fn(plain.user, level, message);
        return;
    }
    tl_tool_log_message(&app->log, level, message);
    if (level == TL_LOG_ERROR) snprintf(app->status, sizeof app->status, "%s", message);
}

tl_logger vw_logger(vw_app *app) { return (tl_logger){.fn = vw_log, .user = app}; }

static void vw_bounds(vw_app *app)
{
    const tl_scene *s = app->scene;
    float d2 = 0;
    for (int i = 0; i < 3; i++) {
        float e = s->bounds_max[i] - s->bounds_min[i];
        app->center[i] = 0.5f * (s->bounds_max[i] + s->bounds_min[i]);
        d2 += e * e;
    }
    app->extent = sqrtf(d2);
}

int vw_load_scene(vw_app *app)
{
    tl_scene *s = NULL;
    tl_result res;
    if (app->scene_path && strcmp(app->scene_path, "showcase") == 0) { /* the material models' spheres */
        res = tl_scene_create_showcase(&(tl_showcase_scene_desc){.point_lights = app->crypt.point_lights}, &s);
    } else if (app->scene_path) {
        tl_gltf_options o = {.logger = vw_logger(app), .extra_lights = app->gltf_extra_lights,
                             .shadow_lights = app->crypt.shadows ? TL_SHADOW_DEFAULT_MAX_LIGHTS : 0};
        tl_tool_budget_gltf(&app->budgets, &o);
        res = tl_scene_load_gltf(app->scene_path, &o, &s);
    } else {
        res = tl_scene_create_default(&app->crypt, &s);
        if (res != TL_OK) fprintf(stderr, "thinlight-viewer: the crypt: %s\n", tl_result_string(res));
    }
    if (res != TL_OK) return -1;
    tl_light *copy = malloc((s->light_count ? s->light_count : 1) * sizeof *copy);
    if (!copy) { tl_scene_destroy(s); return -1; }
    if (s->light_count) memcpy(copy, s->lights, s->light_count * sizeof *copy);
    tl_scene_destroy(app->scene);
    free(app->base_lights);
    app->scene = s;
    app->base_lights = copy;
    app->light_count = s->light_count;
    vw_bounds(app);
    return 0;
}

void vw_destroy_renderers(vw_app *app)
{
    tl_renderer_destroy(app->r);
    tl_renderer_destroy(app->fat);
    tl_renderer_destroy(app->split);
    app->r = app->fat = app->split = NULL;
}

/* The panel's options for a renderer in a role: its mode, what it must keep for the views. */
static tl_renderer_options vw_options(const vw_app *app, tl_render_mode mode, tl_target_set keep)
{
    tl_renderer_options o = app->desc.options;
    o.mode = mode;
    o.keep_targets = keep;
    o.light_scale = vw_light_scale_used(app); /* the chosen one, or lower while the camera moves */
    o.shadow_debug = keep && vw_shadow_debug_wanted(app); /* the main renderer, for the shadow views */
    return o;
}

static tl_renderer *vw_make(vw_app *app, tl_render_mode mode, tl_target_set keep)
{
    tl_renderer_desc d = app->desc;
    d.options = vw_options(app, mode, keep);
    d.width = app->width;
    d.height = app->height;
    d.logger = vw_logger(app);
    tl_renderer *r = NULL;
    if (tl_renderer_create(&d, &r) != TL_OK) return NULL;
    if (tl_renderer_set_scene(r, app->scene) != TL_OK ||
        (app->env && tl_tool_environment_set("thinlight-viewer", app->env, r))) {
        tl_renderer_destroy(r);
        return NULL;
    }
    return r;
}

/* The renderer of a role: made when it is wanted and missing, destroyed when it is not wanted, and
 * otherwise given the options (the scene, its lights and the tile pass stay). */
static int vw_role(vw_app *app, tl_renderer **r, int wanted, tl_render_mode mode, tl_target_set keep)
{
    if (!wanted) {
        tl_renderer_destroy(*r);
        *r = NULL;
        return 0;
    }
    if (!*r) return (*r = vw_make(app, mode, keep)) ? 0 : -1;
    tl_renderer_options o = vw_options(app, mode, keep);
    return tl_renderer_set_options(*r, &o) == TL_OK ? 0 : -1;
}

/* The debug views read targets back after the frame: those must not share memory. */
static int vw_needs_kept(const vw_app *app) { return app->grid || (!app->split_on && app->view != VW_VIEW_FINAL); }

static void vw_refresh_plan(vw_app *app)
{
    if (tl_renderer_get_plan(app->r, &app->plan) != TL_OK) return;
    size_t need = tl_frame_plan_format(&app->plan, NULL, 0) + 1;
    if (need > app->plan_text_size) {
        char *t = realloc(app->plan_text, need);
        if (!t) return;
        app->plan_text = t;
        app->plan_text_size = need;
    }
    tl_frame_plan_format(&app->plan, app->plan_text, app->plan_text_size);
}

int vw_apply_settings(vw_app *app)
{
    app->kept = vw_needs_kept(app);
    int fat_needed = !app->split_on && (app->grid || app->view == VW_VIEW_DIFF_FAT);
    app->applied_scale = vw_light_scale_used(app);
    int err = vw_role(app, &app->r, 1, app->desc.options.mode, app->kept ? TL_TARGETS_ALL : 0);
    if (!err) err = vw_role(app, &app->split, app->split_on, app->split_mode, 0);
    if (!err) err = vw_role(app, &app->fat, fat_needed, TL_MODE_FAT, 0);
    if (err) return -1;
    vw_views_app_passes(app, app->r);
    vw_refresh_plan(app);
    memset(&app->timings, 0, sizeof app->timings);
    app->rebuild = 0;
    return 0;
}

int vw_make_renderers(vw_app *app)
{
    vw_destroy_renderers(app);
    return vw_apply_settings(app);
}

/* After a view change: what must be kept and which helper renderers exist may change; none is made
 * again. */
int vw_update_view(vw_app *app) { return vw_apply_settings(app); }

int vw_resize(vw_app *app, uint32_t w, uint32_t h)
{
    app->width = w;
    app->height = h;
    tl_renderer *all[3] = {app->r, app->fat, app->split};
    for (int i = 0; i < 3; i++)
        if (all[i] && tl_renderer_resize(all[i], w, h) != TL_OK) return -1;
    vw_views_app_passes(app, app->r);
    vw_refresh_plan(app);
    return 0;
}

/* Each point and spot light circles its place (radius a third of its range, one turn in about
 * 6 s, phases spread by index); directional lights stay. */
int vw_animate_lights(vw_app *app)
{
    tl_light *l = app->scene->lights;
    for (size_t i = 0; i < app->light_count; i++) {
        l[i] = app->base_lights[i];
        if (l[i].type == TL_LIGHT_DIRECTIONAL) continue;
        float a = (float)app->time + (float)i * 2.39996f, rad = l[i].radius / 3.0f;
        l[i].position[0] += rad * cosf(a);
        l[i].position[2] += rad * sinf(a);
    }
    tl_renderer *all[3] = {app->r, app->fat, app->split};
    for (int i = 0; i < 3; i++)
        if (all[i] && tl_renderer_set_lights(all[i], l, app->light_count) != TL_OK) return -1;
    return 0;
}

/* x2 or /2 of the crypt's point lights, or of a glTF file's added lights (16 after none). */
int vw_scale_lights(vw_app *app, int up)
{
    uint32_t *n = app->scene_path ? &app->gltf_extra_lights : &app->crypt.point_lights;
    uint32_t now = *n ? *n : (app->scene_path ? 0 : 64);
    uint32_t next = up ? (now ? now * 2 : 16) : now / 2;
    if (next > 65536) next = 65536;
    if (!app->scene_path && !next) next = 1;
    *n = next;
    if (!app->scene_path) app->crypt.spot_lights = next >= 8 ? next / 8 : 0;
    if (vw_load_scene(app)) return -1;
    tl_renderer *all[3] = {app->r, app->fat, app->split};
    for (int i = 0; i < 3; i++) /* the same renderers, with the new scene */
        if (all[i] && tl_renderer_set_scene(all[i], app->scene) != TL_OK) return -1;
    return vw_apply_settings(app);
}
