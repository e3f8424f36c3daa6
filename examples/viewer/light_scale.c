/* The light scale the viewer renders thin-lpp with: the one chosen (--light-scale, the R key, the
 * panel) or, with the dynamic light scale on (--dynamic-light-scale, Shift+R), a lower one while the
 * camera moves. The rule (docs/viewer.md):
 *   - a frame whose camera differs from the last frame's is a moving frame;
 *   - the first moving frame lowers the scale to 1/2, or straight to 1/4 when the last measured
 *     frame took longer than the budget (--light-budget-ms, default 33.3 ms: 30 frames a second);
 *   - a later moving frame steps from 1/2 down to 1/4 when the last measured frame (rendered at 1/2)
 *     is still over the budget; it never steps back up while the camera moves, so the scale does
 *     not flicker between two sizes;
 *   - after VW_STILL_SECONDS of frames without motion, and at least VW_STILL_FRAMES of them, the
 *     chosen scale comes back;
 *   - the scale used is never above the chosen one.
 * Pure: no GL, no GLFW; main.c calls vw_light_scale_step once a frame before rendering. */
#include <string.h>

#include "viewer.h"

#define VW_STILL_SECONDS 0.25
#define VW_STILL_FRAMES 3u

/* The light scales the renderer takes (its row of the option registry: powers of two) and the
 * divisor of the smallest (4: 1/4). */
static const tl_option_info *vw_scales(void) { return tl_option_find("light_scale"); }
static uint32_t vw_lowest_divisor(void)
{
    const tl_option_info *f = vw_scales();
    return f && f->min > 0.0 ? (uint32_t)(1.0 / f->min + 0.5) : 1u;
}

float vw_light_scale_used(const vw_app *app)
{
    float chosen = app->desc.options.light_scale > 0.0f ? app->desc.options.light_scale : 1.0f;
    float low = app->dyn.on && app->dyn.divisor ? 1.0f / (float)app->dyn.divisor : 1.0f;
    return low < chosen ? low : chosen;
}

int vw_light_scale_step(vw_app *app, const tl_camera *cam, float dt)
{
    vw_dynamic *d = &app->dyn;
    int moved = d->have_last && memcmp(cam, &d->last_cam, sizeof *cam) != 0;
    d->last_cam = *cam;
    d->have_last = 1;
    d->moving = moved;
    if (!d->on) {
        d->divisor = 0;
        return 0;
    }
    int over = app->last_gpu_ms > d->budget_ms;
    if (moved) {
        d->still_s = 0.0;
        d->still_frames = 0;
        uint32_t lowest = vw_lowest_divisor();
        if (!d->divisor) d->divisor = over ? lowest : 2u;
        else if (d->divisor == 2u && over && app->last_gpu_scale <= 0.5f) d->divisor = lowest;
    } else if (d->divisor) {
        d->still_s += dt;
        d->still_frames++;
        if (d->still_s >= VW_STILL_SECONDS - 1e-6 && d->still_frames >= VW_STILL_FRAMES) d->divisor = 0;
    }
    return vw_light_scale_used(app) != app->applied_scale;
}

const char *vw_light_scale_name(float scale)
{
    static const char *const names[] = {"1", "1/2", "1/4", "1/8", "1/16"};
    unsigned k = 0;
    while (k + 1 < sizeof names / sizeof names[0] && scale <= 0.75f / (float)(1u << k)) k++;
    return names[k];
}

/* The next scale down, from the smallest back to the largest (R: 1, 1/2, 1/4). */
void vw_light_scale_cycle(vw_app *app)
{
    const tl_option_info *f = vw_scales();
    float s = app->desc.options.light_scale > 0.0f ? app->desc.options.light_scale : 1.0f;
    float next = s * 0.5f;
    app->desc.options.light_scale = f && next < (float)f->min ? (float)f->max : next;
    app->rebuild = 1;
}

void vw_light_scale_toggle_dynamic(vw_app *app)
{
    app->dyn.on = !app->dyn.on;
    app->dyn.divisor = 0;
    app->rebuild = 1;
}
