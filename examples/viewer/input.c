/* Keys and mouse (the list is in args.c's --help): GLFW callbacks installed before ImGui's, which
 * chains to them; nothing here acts while the panel has the mouse or the keyboard. */
#include <GLFW/glfw3.h>

#include "input.h"
#include "session.h"

static vw_input *vw_get(GLFWwindow *w) { return (vw_input *)glfwGetWindowUserPointer(w); }

static void vw_set_view(vw_app *app, vw_view v)
{
    app->view = v;
    app->grid = 0;
    app->split_on = 0;
    vw_update_view(app);
}

static void vw_cycle_strategy(vw_app *app)
{
    tl_renderer_options *o = &app->desc.options;
    o->light_strategy = (tl_light_strategy)((o->light_strategy + 1) % TL_LIGHT_STRATEGY_COUNT_);
    app->rebuild = 1;
}

static void vw_key_view(vw_app *app, int key, int mods)
{
    if (key == GLFW_KEY_V) {
        int step = (mods & GLFW_MOD_SHIFT) ? VW_VIEW_COUNT - 1 : 1;
        vw_set_view(app, (vw_view)((app->view + step) % VW_VIEW_COUNT));
    } else if (key == GLFW_KEY_0) {
        vw_set_view(app, VW_VIEW_FINAL);
    } else if (key == GLFW_KEY_G) {
        app->grid = !app->grid;
        app->split_on = 0;
        vw_update_view(app);
    } else if (key == GLFW_KEY_X) {
        app->split_on = !app->split_on;
        app->grid = 0;
        vw_update_view(app);
    }
}

static void vw_key_settings(vw_app *app, int key, int mods)
{
    if (key >= GLFW_KEY_1 && key <= GLFW_KEY_5) { /* thin-lpp, thin-deferred, fat, forward, visibility */
        app->desc.options.mode = (tl_render_mode)(TL_MODE_THIN_LPP + (key - GLFW_KEY_1));
        app->rebuild = 1;
    } else if (key == GLFW_KEY_T) {
        vw_cycle_strategy(app);
    } else if (key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD) {
        vw_scale_lights(app, 1);
    } else if (key == GLFW_KEY_MINUS || key == GLFW_KEY_KP_SUBTRACT) {
        vw_scale_lights(app, 0);
    } else if (key == GLFW_KEY_R) {
        if (mods & GLFW_MOD_SHIFT) vw_light_scale_toggle_dynamic(app);
        else vw_light_scale_cycle(app);
    } else if (key == GLFW_KEY_M) {
        vw_aa_cycle(app);
    } else if (key == GLFW_KEY_L) {
        app->animate = !app->animate;
    } else if (key == GLFW_KEY_LEFT_BRACKET || key == GLFW_KEY_RIGHT_BRACKET) {
        float e = app->desc.options.exposure > 0 ? app->desc.options.exposure : 1.0f;
        app->desc.options.exposure = key == GLFW_KEY_RIGHT_BRACKET ? e * 1.25f : e / 1.25f;
        app->rebuild = 1;
    }
}

static void vw_on_key(GLFWwindow *w, int key, int scancode, int action, int mods)
{
    (void)scancode;
    vw_input *in = vw_get(w);
    vw_app *app = in->app;
    if (action != GLFW_PRESS || vw_ui_wants_keyboard()) return;
    if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(w, GLFW_TRUE);
    else if (key == GLFW_KEY_F) vw_camera_set_mode(&app->cam, app->cam.mode == VW_CAMERA_FLY ? VW_CAMERA_ORBIT : VW_CAMERA_FLY);
    else if (key == GLFW_KEY_C) vw_camera_from_scene(&app->cam, &app->scene->camera, app->extent);
    else if (key == GLFW_KEY_H || key == GLFW_KEY_F1) app->show_panel = !app->show_panel;
    else if (key == GLFW_KEY_P || key == GLFW_KEY_F12) app->screenshot_request = 1;
    else {
        vw_key_view(app, key, mods);
        vw_key_settings(app, key, mods);
    }
}

static void vw_on_button(GLFWwindow *w, int button, int action, int mods)
{
    (void)mods;
    vw_input *in = vw_get(w);
    int down = action == GLFW_PRESS && !vw_ui_wants_mouse();
    if (button == GLFW_MOUSE_BUTTON_LEFT) in->left = down;
    if (button == GLFW_MOUSE_BUTTON_RIGHT) in->right = down;
    glfwGetCursorPos(w, &in->x, &in->y);
}

static void vw_on_cursor(GLFWwindow *w, double x, double y)
{
    vw_input *in = vw_get(w);
    float dx = (float)(x - in->x), dy = (float)(y - in->y);
    in->x = x;
    in->y = y;
    vw_camera *c = &in->app->cam;
    if (in->left && c->mode == VW_CAMERA_ORBIT) vw_camera_orbit(c, dx, dy);
    else if (in->left || in->right) vw_camera_look(c, dx, dy);
}

static void vw_on_scroll(GLFWwindow *w, double dx, double dy)
{
    (void)dx;
    if (!vw_ui_wants_mouse()) vw_camera_zoom(&vw_get(w)->app->cam, (float)dy);
}

static void vw_on_size(GLFWwindow *w, int width, int height)
{
    vw_input *in = vw_get(w);
    if (width > 0 && height > 0) {
        in->pending_w = (uint32_t)width;
        in->pending_h = (uint32_t)height;
    }
}

void vw_input_install(vw_input *in, GLFWwindow *w)
{
    glfwSetWindowUserPointer(w, in);
    glfwSetKeyCallback(w, vw_on_key);
    glfwSetMouseButtonCallback(w, vw_on_button);
    glfwSetCursorPosCallback(w, vw_on_cursor);
    glfwSetScrollCallback(w, vw_on_scroll);
    glfwSetFramebufferSizeCallback(w, vw_on_size);
}

/* WASD QE, held: flying moves the eye (and switches to the fly camera). */
void vw_input_poll(vw_input *in, GLFWwindow *w, float dt)
{
    static const int keys[6] = {GLFW_KEY_D, GLFW_KEY_A, GLFW_KEY_E, GLFW_KEY_Q, GLFW_KEY_W, GLFW_KEY_S};
    if (vw_ui_wants_keyboard()) return;
    float move[3] = {0, 0, 0};
    int any = 0;
    for (int k = 0; k < 6; k++)
        if (glfwGetKey(w, keys[k]) == GLFW_PRESS) {
            move[k / 2] += (k & 1) ? -1.0f : 1.0f;
            any = 1;
        }
    if (!any) return;
    vw_camera *c = &in->app->cam;
    vw_camera_set_mode(c, VW_CAMERA_FLY);
    int fast = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
    vw_camera_fly(c, move, fast ? dt * 4.0f : dt);
}
