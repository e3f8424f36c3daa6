/* The viewer's scene and renderers (session.c). */
#ifndef THINLIGHT_VIEWER_SESSION_H
#define THINLIGHT_VIEWER_SESSION_H

#include "viewer.h"

tl_logger vw_logger(vw_app *app);
/** Loads the crypt (app->crypt) or app->scene_path; keeps the lights for animation. 0 or -1. */
int vw_load_scene(vw_app *app);
/** Makes the main renderer and the helpers the view needs (fat for the difference, the split
 *  view's second mode) at app->width x app->height. 0 or -1. */
int vw_make_renderers(vw_app *app);
/** The settings into the renderers: each is given its options (tl_renderer_set_options), and the
 *  helper renderers the view needs are made or destroyed; none is made again. 0 or -1. */
int vw_apply_settings(vw_app *app);
void vw_destroy_renderers(vw_app *app);
/** After app->view, grid or split_on changed. */
int vw_update_view(vw_app *app);
int vw_resize(vw_app *app, uint32_t w, uint32_t h);
int vw_animate_lights(vw_app *app);
int vw_scale_lights(vw_app *app, int up);

#endif
