/* thinlight-viewer: a window on the renderer. The final view is rendered straight into the
 * window (tl_renderer_render_to); the debug, grid and split views read targets back and show the
 * image views.c builds, through the panel's draw list. Everything goes through the public API. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GLFW_INCLUDE_NONE
#include <GL/gl.h>
#include <GLFW/glfw3.h>

#include "args.h"
#include "input.h"
#include "session.h"
#include "thinlight/io.h"

typedef struct vw_run {
    vw_app app;
    vw_args args;
    vw_input input;
    GLFWwindow *window;
    GLuint texture;
    uint32_t tex_w, tex_h;
    int print_pending;   /* --print-targets: after the next frame */
    unsigned screenshots; /* P key: viewer-N.png */
    char title[160];      /* the window's title as last set */
} vw_run;

static tl_gl_function vw_proc(void *user, const char *name)
{
    (void)user;
    return (tl_gl_function)glfwGetProcAddress(name);
}

static void *vw_proc_ptr(const char *name) { return (void *)(uintptr_t)glfwGetProcAddress(name); }

/* The last measured frame of r (stats lag a frame or two behind): its GPU time and light scale,
 * which the dynamic light scale compares with its budget. */
static void vw_measured(vw_app *app, const tl_frame_stats *st)
{
    if (app->counted_r != app->r) { /* a new renderer numbers its frames from 1 again */
        app->counted_r = app->r;
        app->r_frames = 0;
        app->last_gpu_ms = 0.0;
    }
    app->frame_scale[++app->r_frames % 16] = app->applied_scale;
    if (!st->gpu_valid || !st->frame || st->frame > app->r_frames || app->r_frames - st->frame >= 16) return;
    app->last_gpu_ms = st->gpu_ms;
    app->last_gpu_scale = app->frame_scale[st->frame % 16];
}

static void vw_smooth(vw_timings *t, const tl_frame_stats *st)
{
    if (!st->gpu_valid || st->frame == t->last_frame) return;
    double a = t->valid ? 0.1 : 1.0;
    for (int p = 0; p < TL_PASS_COUNT; p++) {
        double v = st->pass_ms[p] > 0 ? st->pass_ms[p] : 0;
        t->pass_ms[p] += a * (v - t->pass_ms[p]);
    }
    t->gpu_ms += a * (st->gpu_ms - t->gpu_ms);
    t->cpu_ms += a * (st->cpu_ms - t->cpu_ms);
    t->covered = st->pass_fragments[TL_PASS_GBUFFER];
    if (!t->covered) t->covered = st->pass_fragments[TL_PASS_DEPTH_PREPASS];
    if (!t->covered) t->covered = st->pass_fragments[TL_PASS_FORWARD];
    t->last_frame = st->frame;
    t->valid = 1;
}

static void vw_upload(vw_run *run)
{
    vw_app *app = &run->app;
    glBindTexture(GL_TEXTURE_2D, run->texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (run->tex_w != app->width || run->tex_h != app->height) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, (GLsizei)app->width, (GLsizei)app->height, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, app->image);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        run->tex_w = app->width;
        run->tex_h = app->height;
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, (GLsizei)app->width, (GLsizei)app->height, GL_RGBA, GL_UNSIGNED_BYTE,
                        app->image);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
}

/* Renders the frame; 1 when the window already holds it (the final view, straight), 0 when
 * app->image does, -1 on failure. */
static int vw_render(vw_run *run, const tl_camera *cam, int need_image)
{
    vw_app *app = &run->app;
    tl_frame_stats st;
    memset(&st, 0, sizeof st);
    int direct = !need_image && !app->grid && !app->split_on && app->view == VW_VIEW_FINAL;
    tl_result res = direct ? tl_renderer_render_to(app->r, cam, &(tl_render_output){0}, &st)
                           : tl_renderer_render(app->r, cam, &st);
    if (res == TL_OK && app->fat) res = tl_renderer_render(app->fat, cam, NULL);
    if (res == TL_OK && app->split) res = tl_renderer_render(app->split, cam, NULL);
    if (res != TL_OK) return -1;
    vw_measured(app, &st);
    vw_smooth(&app->timings, &st);
    if (direct) return 1;
    if (vw_views_build(app, cam)) return -1;
    vw_upload(run);
    return 0;
}

static void vw_print_targets(vw_run *run)
{
    vw_app *app = &run->app;
    tl_frame_stats st;
    if (tl_renderer_wait(app->r, &st) != TL_OK) return;
    printf("targets %ux%u: %u B/px sum, %u B/px peak, %u B/px allocated, %zu bytes total, %zu bytes allocated\n",
           app->width, app->height, app->plan.bytes_per_pixel, app->plan.peak_live_bytes_per_pixel,
           app->plan.allocated_bytes_per_pixel, st.total_target_bytes, st.allocated_target_bytes);
    fflush(stdout);
}

static int vw_write_png(const char *path, uint32_t w, uint32_t h, const uint8_t *rgba)
{
    tl_image_desc d = {.width = w, .height = h, .channels = 4, .type = TL_PIXEL_U8, .bottom_up = 1,
                       .logger = vw_logger(NULL)}; /* the logger prints the error line */
    return tl_image_write(path, &d, rgba) == TL_OK ? 0 : -1;
}

/* The window as shown, panel included (before the swap: the back buffer). */
static int vw_write_window(vw_run *run, const char *path)
{
    vw_app *app = &run->app;
    uint8_t *px = malloc((size_t)app->width * app->height * 4);
    if (!px) return -1;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, (GLsizei)app->width, (GLsizei)app->height, GL_RGBA, GL_UNSIGNED_BYTE, px);
    for (size_t i = 0; i < (size_t)app->width * app->height; i++) px[4 * i + 3] = 255;
    int res = vw_write_png(path, app->width, app->height, px);
    free(px);
    return res;
}

/* A screenshot due this frame: its path, or NULL. */
static const char *vw_screenshot_path(vw_run *run, uint32_t frame, char *buf, size_t size)
{
    if (run->args.screenshot && frame + 1 == run->args.frames) return run->args.screenshot;
    if (!run->app.screenshot_request) return NULL;
    snprintf(buf, size, "viewer-%u.png", run->screenshots++);
    return buf;
}

static void vw_apply_changes(vw_run *run)
{
    vw_app *app = &run->app;
    vw_input *in = &run->input;
    if (in->pending_w && (in->pending_w != app->width || in->pending_h != app->height)) {
        if (vw_resize(app, in->pending_w, in->pending_h)) fprintf(stderr, "thinlight-viewer: resize failed\n");
        run->print_pending = run->args.print_targets;
    }
    in->pending_w = in->pending_h = 0;
    if (app->rebuild) {
        if (vw_apply_settings(app)) fprintf(stderr, "thinlight-viewer: the new settings failed\n");
        run->print_pending = run->args.print_targets;
    }
}

/* The window's title: the mode and the light scale (thin-lpp), so they show without the panel. */
static void vw_title(vw_run *run)
{
    vw_app *app = &run->app;
    char title[160];
    if (app->desc.options.mode == TL_MODE_THIN_LPP)
        snprintf(title, sizeof title, "thinlight-viewer: thin-lpp, light scale %s%s%s",
                 vw_light_scale_name(app->applied_scale), app->dyn.on ? " (dynamic" : "",
                 app->dyn.on ? (app->dyn.divisor ? ", camera moving)" : ")") : "");
    else
        snprintf(title, sizeof title, "thinlight-viewer: %s", tl_render_mode_name(app->desc.options.mode));
    if (strcmp(title, run->title)) {
        snprintf(run->title, sizeof run->title, "%s", title);
        glfwSetWindowTitle(run->window, title);
    }
}

/* The camera's motion this frame: scripted (--move-camera), then the dynamic light scale's rule,
 * which may give the renderers a new scale (tl_renderer_set_options; none is made again). */
static int vw_motion(vw_run *run, uint32_t frame, float dt, tl_camera *cam)
{
    vw_app *app = &run->app;
    const vw_args *a = &run->args;
    if (a->move_count && frame >= a->move_first && frame - a->move_first < a->move_count)
        vw_camera_orbit(&app->cam, 4.0f, 0.0f); /* as a 4-pixel drag to the right */
    vw_camera_get(&app->cam, cam);
    if (vw_light_scale_step(app, cam, dt) && vw_apply_settings(app)) {
        fprintf(stderr, "thinlight-viewer: light scale %s failed\n", vw_light_scale_name(vw_light_scale_used(app)));
        return 1;
    }
    vw_title(run);
    return 0;
}

static void vw_print_frame(vw_run *run, uint32_t frame)
{
    vw_app *app = &run->app;
    printf("frame %u: light-scale %g plan-scale %g moving %d dynamic %d gpu-ms %.3f\n", frame, app->applied_scale,
           app->plan.light_scale > 0.0f ? app->plan.light_scale : 1.0f, app->dyn.moving, app->dyn.on, app->last_gpu_ms);
    fflush(stdout);
}

/* One frame: input, lights, render, panel, screenshot, swap. 0, or the exit status. */
static int vw_frame(vw_run *run, uint32_t frame, float dt)
{
    vw_app *app = &run->app;
    char name[64];
    vw_apply_changes(run);
    if (!app->r) return 1;
    vw_input_poll(&run->input, run->window, dt);
    if (app->animate) {
        app->time += dt;
        if (vw_animate_lights(app)) return 1;
    }
    tl_camera cam;
    if (vw_motion(run, frame, dt, &cam)) return 1;
    const char *shot = vw_screenshot_path(run, frame, name, sizeof name);
    int window_shot = shot && run->args.screenshot_window && shot == run->args.screenshot;
    int direct = vw_render(run, &cam, shot && !window_shot);
    if (direct < 0) return 1;
    if (run->print_pending) vw_print_targets(run);
    run->print_pending = 0;
    if (run->args.print_frames) vw_print_frame(run, frame);
    glViewport(0, 0, (GLsizei)app->width, (GLsizei)app->height);
    if (!direct) { /* the image covers the window, but nothing of the last frame may show through */
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    vw_ui_frame(app, direct ? 0 : run->texture);
    vw_ui_render();
    int bad = 0;
    if (shot) {
        bad = window_shot ? vw_write_window(run, shot) : vw_write_png(shot, app->width, app->height, app->image);
        if (!bad) snprintf(app->status, sizeof app->status, "wrote %s", shot);
        app->screenshot_request = 0;
    }
    glfwSwapBuffers(run->window);
    return bad && run->args.screenshot ? 1 : 0;
}

static int vw_loop(vw_run *run)
{
    double last = glfwGetTime();
    for (uint32_t frame = 0; !glfwWindowShouldClose(run->window); frame++) {
        glfwPollEvents();
        double now = glfwGetTime();
        float dt = run->args.frames ? 1.0f / 30.0f : (float)(now - last); /* scripted runs: fixed steps */
        last = now;
        int status = vw_frame(run, frame, dt);
        if (status) return status;
        if (run->args.resize_w && frame == 1) glfwSetWindowSize(run->window, (int)run->args.resize_w, (int)run->args.resize_h);
        if (run->args.frames && frame + 1 >= run->args.frames) break;
    }
    return 0;
}

static void vw_settings(vw_run *run)
{
    vw_app *app = &run->app;
    const vw_args *a = &run->args;
    app->scene_path = a->scene;
    app->desc = a->desc;
    app->budgets = a->budgets;
    app->log.tool = "thinlight-viewer";
    tl_tool_budget_renderer(&app->budgets, &app->desc);
    app->desc.get_proc_address = vw_proc;
    /* the defaults, spelled out for the panel */
    if (!app->desc.options.mode) app->desc.options.mode = TL_MODE_THIN_LPP;
    if (!app->desc.options.depth_format) app->desc.options.depth_format = TL_DEPTH_FORMAT_D24;
    if (!app->desc.options.rt0) app->desc.options.rt0 = TL_RT0_RGBA8;
    if (!app->desc.options.light_buffer) app->desc.options.light_buffer = TL_LIGHT_BUFFER_EXACT;
    if (!app->desc.options.fxaa) app->desc.options.fxaa = TL_FXAA_29;
    if (!(app->desc.options.exposure > 0)) app->desc.options.exposure = 1.0f;
    if (!(app->desc.options.light_scale > 0)) app->desc.options.light_scale = 1.0f;
    app->dyn.on = a->dynamic_light_scale;
    app->dyn.budget_ms = a->light_budget_ms;
    if (a->scene) app->gltf_extra_lights = a->lights;
    else if (a->lights_set) app->crypt.point_lights = a->lights ? a->lights : 1;
    app->crypt.shadows = a->shadows;
    app->view = a->view;
    app->grid = a->grid;
    app->split_on = a->split;
    app->split_mode = a->split ? a->split_mode : TL_MODE_FAT;
    app->animate = a->animate;
    app->show_panel = !a->no_panel;
    app->diff_scale = 8.0f;
    run->input.app = app;
    run->print_pending = a->print_targets;
}

static GLFWwindow *vw_window(const vw_args *a)
{
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow *w = glfwCreateWindow((int)a->width, (int)a->height, "thinlight-viewer", NULL, NULL);
    if (!w) {
        const char *why = NULL;
        glfwGetError(&why);
        fprintf(stderr, "thinlight-viewer: no OpenGL 4.5 core window: %s\n", why ? why : "unknown reason");
        return NULL;
    }
    glfwMakeContextCurrent(w);
    glfwSwapInterval(a->frames ? 0 : 1);
    return w;
}

static int vw_start(vw_run *run)
{
    vw_app *app = &run->app;
    int fw, fh;
    glfwGetFramebufferSize(run->window, &fw, &fh);
    app->width = (uint32_t)fw;
    app->height = (uint32_t)fh;
    vw_camera_from_scene(&app->cam, &app->scene->camera, app->extent);
    if (vw_views_init(app, vw_proc_ptr)) {
        fprintf(stderr, "thinlight-viewer: the context lacks glMemoryBarrier or glGetNamedBufferSubData\n");
        return -1;
    }
    vw_input_install(&run->input, run->window);
    if (!vw_ui_init(run->window)) {
        fprintf(stderr, "thinlight-viewer: Dear ImGui did not start\n");
        return -1;
    }
    glGenTextures(1, &run->texture);
    return vw_make_renderers(app);
}

int main(int argc, char **argv)
{
    static vw_run run; /* large; zeroed */
    int status = vw_parse_args(argc, argv, &run.args);
    if (status >= 0) return status;
    vw_settings(&run);
    /* bad input fails before any window or display is needed */
    if (tl_tool_environment_read("thinlight-viewer", &run.args.env)) return 1;
    run.app.env = &run.args.env;
    if (vw_load_scene(&run.app)) {
        tl_tool_environment_free(&run.args.env);
        return 1;
    }
    if (!glfwInit()) {
        const char *why = NULL;
        glfwGetError(&why);
        fprintf(stderr, "thinlight-viewer: GLFW: %s\n", why ? why : "cannot initialise (no display?)");
        tl_tool_environment_free(&run.args.env);
        return 1;
    }
    run.window = vw_window(&run.args);
    status = !run.window || vw_start(&run) ? 1 : vw_loop(&run);
    if (run.window) {
        vw_destroy_renderers(&run.app);
        if (run.texture) glDeleteTextures(1, &run.texture);
        vw_ui_shutdown();
        glfwDestroyWindow(run.window);
    }
    vw_views_free(&run.app);
    tl_scene_destroy(run.app.scene);
    tl_tool_environment_free(&run.args.env);
    free(run.app.base_lights);
    free(run.app.plan_text);
    glfwTerminate();
    return status;
}
