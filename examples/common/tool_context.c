/* The renderer tools' --context, --device and --list-devices (tool_gl.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tool_gl.h"
#include "tool_util.h"

#define TL_TOOL_MAX_DEVICES 64

/* Keeps the message of a failed call (a create call that fails has no object to ask). */
static void tl_tool__keep_error(void *user, tl_log_level level, const char *message)
{
    if (level == TL_LOG_ERROR) snprintf(user, 1024, "%s", message);
}

static const tl_opt tl_tool__context_opts[] = {
    {"--context", TL_OPT_TEXT, .id = 0},
    {"--device", TL_OPT_UINT, .id = 0, .lo = 0, .hi = TL_TOOL_MAX_DEVICES - 1},
    {"--list-devices", TL_OPT_FLAG, .id = 0},
};

const tl_opt_table tl_tool_context_option_table = TL_OPT_TABLE(tl_tool__context_opts);

int tl_tool_context_option(tl_tool_context_args *a, const tl_opt *o, const tl_opt_value *v)
{
    if (!tl_opt_in(o, tl_tool_context_option_table)) return 0;
    if (o == &tl_tool__context_opts[0]) a->context = v->text;
    else if (o == &tl_tool__context_opts[1]) {
        a->device_given = 1;
        a->device = (uint32_t)v->u[0];
    } else a->list_devices = 1;
    return 1;
}

static int tl_tool__check_device(const char *tool, uint32_t index)
{
    char why[1024] = "";
    size_t count = 0;
    tl_logger keep = {tl_tool__keep_error, why};
    if (tl_context_egl_devices(NULL, 0, &count, &keep) != TL_OK) {
        tl_tool_fail(tool, "--device %u: no EGL devices: %s", index, why);
        return 2;
    }
    if (index >= count) {
        tl_tool_fail(tool, "--device %u: EGL lists %zu device%s (see --list-devices)", index, count,
                     count == 1 ? "" : "s");
        return 2;
    }
    return 0;
}

int tl_tool_context_parse(const char *tool, const tl_tool_context_args *a, tl_tool_context_options *o)
{
    const char *context = a->context;
    memset(o, 0, sizeof *o);
    o->backend = TL_CONTEXT_BACKEND_AUTO;
    if (context && (tl_context_backend_from_name(context, &o->backend) != TL_OK ||
                    o->backend == TL_CONTEXT_BACKEND_DEFAULT)) {
        tl_tool_fail(tool, "--context wants auto, osmesa, egl or glfw, got '%s'", context);
        return 2;
    }
    if (!tl_context_backend_available(o->backend)) {
        tl_tool_fail(tool, "--context %s: this thinlight was built without that back end (THINLIGHT_WITH_%s=OFF)",
                     tl_context_backend_name(o->backend),
                     o->backend == TL_CONTEXT_BACKEND_OSMESA ? "OSMESA"
                     : o->backend == TL_CONTEXT_BACKEND_EGL  ? "EGL"
                     : o->backend == TL_CONTEXT_BACKEND_GLFW ? "GLFW"
                                                             : "OSMESA and THINLIGHT_WITH_EGL");
        return 2;
    }
    if (!a->device_given) return 0;
    if (o->backend != TL_CONTEXT_BACKEND_AUTO && o->backend != TL_CONTEXT_BACKEND_EGL) {
        tl_tool_fail(tool, "--device picks an EGL device: it goes with --context egl, not %s", context);
        return 2;
    }
    if (!tl_context_backend_available(TL_CONTEXT_BACKEND_EGL)) {
        tl_tool_fail(tool, "--device %u: this thinlight was built without the EGL back end (THINLIGHT_WITH_EGL=OFF)",
                     a->device);
        return 2;
    }
    o->backend = TL_CONTEXT_BACKEND_EGL;
    o->egl_platform = TL_EGL_PLATFORM_DEVICE;
    o->egl_device = a->device;
    return tl_tool__check_device(tool, a->device);
}

int tl_tool_context_open(const char *tool, const tl_tool_context_options *o, uint32_t width, uint32_t height,
                         tl_context **out)
{
    char why[1024] = "";
    tl_context_desc desc = {.backend = o->backend, .width = width, .height = height, .egl_platform = o->egl_platform,
                            .egl_device = o->egl_device, .logger = {tl_tool__keep_error, why}};
    if (tl_context_create(&desc, out) != TL_OK) {
        tl_tool_fail(tool, "no GL context (--context %s): %s", tl_context_backend_name(o->backend), why);
        return 1;
    }
    fprintf(stderr, "%s: context %s: %s; GL_RENDERER %s; GL_VERSION %s\n", tool,
            tl_context_backend_name(tl_context_get_backend(*out)), tl_context_platform_string(*out),
            tl_context_renderer_string(*out), tl_context_version_string(*out));
    return 0;
}

/* What --context auto takes, from the device list alone (no context is made). */
static void tl_tool__print_auto(const tl_egl_device *devices, size_t count)
{
    for (size_t i = 0; i < count; i++)
        if (!devices[i].software) {
            printf("--context auto takes EGL device %zu\n", i);
            return;
        }
    if (tl_context_backend_available(TL_CONTEXT_BACKEND_OSMESA))
        printf("--context auto takes OSMesa (no EGL GPU device)\n");
    else
        printf("--context auto takes EGL's surfaceless platform (no EGL GPU device, no OSMesa)\n");
}

int tl_tool_list_devices(const char *tool)
{
    tl_egl_device *devices = calloc(TL_TOOL_MAX_DEVICES, sizeof *devices);
    char why[1024] = "";
    size_t count = 0;
    tl_logger keep = {tl_tool__keep_error, why};
    if (!devices) {
        tl_tool_fail(tool, "out of memory");
        return 1;
    }
    if (tl_context_egl_devices(devices, TL_TOOL_MAX_DEVICES, &count, &keep) != TL_OK) {
        tl_tool_fail(tool, "no EGL devices: %s", why);
        free(devices);
        return 1;
    }
    if (count > TL_TOOL_MAX_DEVICES) count = TL_TOOL_MAX_DEVICES;
    printf("EGL devices: %zu\n", count);
    for (size_t i = 0; i < count; i++) {
        const tl_egl_device *d = &devices[i];
        const char *node = d->render_node[0] ? d->render_node : d->drm_device[0] ? d->drm_device : "no DRM node";
        printf("  %u: %s, %s; driver %s; vendor %s; renderer %s\n", (unsigned)d->index,
               d->software ? "software (Mesa's rasteriser, not a GPU)" : "GPU", node, d->driver[0] ? d->driver : "?",
               d->vendor[0] ? d->vendor : "?", d->renderer[0] ? d->renderer : "? (EGL does not say)");
    }
    tl_tool__print_auto(devices, count);
    free(devices);
    return 0;
}
