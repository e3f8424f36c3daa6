/* EGL back end: a core-profile context current with no surface at all
 * (EGL_KHR_surfaceless_context) on a display of the device platform (EGL_EXT_platform_device:
 * GPU servers, NVIDIA's driver included) or of Mesa's surfaceless platform. No window and no
 * pbuffer: the renderer draws into its own framebuffers. Extension entry points and GL functions
 * come from eglGetProcAddress (core GL too: EGL 1.5, EGL_KHR_client_get_all_proc_addresses).
 * Displays are never terminated: they are process-wide and may be shared (see context.h). */
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "platform.h"

/* Tokens of extensions that older eglext.h may lack. */
#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif
#ifndef EGL_DRM_RENDER_NODE_FILE_EXT
#define EGL_DRM_RENDER_NODE_FILE_EXT 0x3377
#endif
#ifndef EGL_RENDERER_EXT
#define EGL_RENDERER_EXT 0x335F
#endif
#ifndef EGL_DRIVER_NAME_EXT
#define EGL_DRIVER_NAME_EXT 0x335E
#endif

#define TL__EGL_MAX_DEVICES 64

typedef const char *(*tl__egl_driver_name_fn)(EGLDisplay display); /* EGL_MESA_query_driver */

/* The client extensions' entry points (NULL when the client lacks the extension). */
typedef struct tl__egl_api {
    const char *client_extensions;
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display;
    PFNEGLQUERYDEVICESEXTPROC query_devices;           /* EGL_EXT_device_enumeration */
    PFNEGLQUERYDEVICESTRINGEXTPROC query_device_string; /* EGL_EXT_device_query */
    bool platform_device, platform_surfaceless;
} tl__egl_api;

typedef struct tl__egl {
    EGLDisplay display;
    EGLContext context;
} tl__egl;

/* Whether the space-separated `list` holds the token `name`. */
static bool tl__egl_has(const char *list, const char *name)
{
    size_t n = strlen(name);
    for (const char *p = list; p && (p = strstr(p, name)) != NULL; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

static void tl__egl_copy(char *dst, size_t size, const char *src)
{
    snprintf(dst, size, "%s", src ? src : "");
}

static const char *tl__egl_error_name(EGLint e)
{
    static const struct {
        EGLint code;
        const char *name;
    } names[] = {
        {EGL_SUCCESS, "EGL_SUCCESS"},           {EGL_NOT_INITIALIZED, "EGL_NOT_INITIALIZED"},
        {EGL_BAD_ACCESS, "EGL_BAD_ACCESS"},     {EGL_BAD_ALLOC, "EGL_BAD_ALLOC"},
        {EGL_BAD_ATTRIBUTE, "EGL_BAD_ATTRIBUTE"}, {EGL_BAD_CONFIG, "EGL_BAD_CONFIG"},
        {EGL_BAD_CONTEXT, "EGL_BAD_CONTEXT"},   {EGL_BAD_CURRENT_SURFACE, "EGL_BAD_CURRENT_SURFACE"},
        {EGL_BAD_DISPLAY, "EGL_BAD_DISPLAY"},   {EGL_BAD_MATCH, "EGL_BAD_MATCH"},
        {EGL_BAD_PARAMETER, "EGL_BAD_PARAMETER"}, {EGL_BAD_SURFACE, "EGL_BAD_SURFACE"},
        {EGL_CONTEXT_LOST, "EGL_CONTEXT_LOST"},
    };
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (names[i].code == e) return names[i].name;
    return "an unknown EGL error";
}

/* The client's extensions; NULL, or the reason EGL cannot pick a platform at all. */
static const char *tl__egl_api_load(tl__egl_api *api)
{
    memset(api, 0, sizeof *api);
    api->client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!api->client_extensions || !tl__egl_has(api->client_extensions, "EGL_EXT_platform_base"))
        return "this EGL has no EGL_EXT_platform_base (no eglGetPlatformDisplayEXT): it cannot open a display "
               "without a window system";
    api->get_platform_display = (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (tl__egl_has(api->client_extensions, "EGL_EXT_device_enumeration") ||
        tl__egl_has(api->client_extensions, "EGL_EXT_device_base")) {
        api->query_devices = (PFNEGLQUERYDEVICESEXTPROC)eglGetProcAddress("eglQueryDevicesEXT");
        api->query_device_string = (PFNEGLQUERYDEVICESTRINGEXTPROC)eglGetProcAddress("eglQueryDeviceStringEXT");
    }
    api->platform_device = api->query_devices && api->query_device_string &&
                           tl__egl_has(api->client_extensions, "EGL_EXT_platform_device");
    api->platform_surfaceless = tl__egl_has(api->client_extensions, "EGL_MESA_platform_surfaceless");
    if (!api->get_platform_display) return "eglGetProcAddress found no eglGetPlatformDisplayEXT";
    return NULL;
}

/* Every device EGL lists (at most TL__EGL_MAX_DEVICES); 0 without device enumeration. */
static EGLint tl__egl_query_devices(const tl__egl_api *api, EGLDeviceEXT *devices)
{
    EGLint n = 0;
    if (!api->query_devices || !api->query_devices(TL__EGL_MAX_DEVICES, devices, &n)) return 0;
    return n < 0 ? 0 : n;
}

static bool tl__egl_device_is_software(const tl__egl_api *api, EGLDeviceEXT device)
{
    return tl__egl_has(api->query_device_string(device, EGL_EXTENSIONS), "EGL_MESA_device_software");
}

/* The display's EGL_VENDOR and Mesa driver name, into whichever of them is still "". */
static void tl__egl_display_names(EGLDisplay display, char *vendor, size_t vendor_size, char *driver,
                                  size_t driver_size)
{
    if (vendor && !vendor[0]) tl__egl_copy(vendor, vendor_size, eglQueryString(display, EGL_VENDOR));
    if (driver && !driver[0] && tl__egl_has(eglQueryString(display, EGL_EXTENSIONS), "EGL_MESA_query_driver")) {
        tl__egl_driver_name_fn name = (tl__egl_driver_name_fn)eglGetProcAddress("eglGetDisplayDriverName");
        if (name) tl__egl_copy(driver, driver_size, name(display));
    }
}

/* What EGL tells about `device` without a context; may initialise its display (never terminated). */
static void tl__egl_describe(const tl__egl_api *api, EGLDeviceEXT device, uint32_t index, tl_egl_device *out)
{
    memset(out, 0, sizeof *out);
    out->index = index;
    const char *ext = api->query_device_string(device, EGL_EXTENSIONS);
    out->software = tl__egl_has(ext, "EGL_MESA_device_software");
    if (tl__egl_has(ext, "EGL_EXT_device_drm"))
        tl__egl_copy(out->drm_device, sizeof out->drm_device, api->query_device_string(device, EGL_DRM_DEVICE_FILE_EXT));
    if (tl__egl_has(ext, "EGL_EXT_device_drm_render_node"))
        tl__egl_copy(out->render_node, sizeof out->render_node,
                     api->query_device_string(device, EGL_DRM_RENDER_NODE_FILE_EXT));
    if (tl__egl_has(ext, "EGL_EXT_device_query_name")) {
        tl__egl_copy(out->vendor, sizeof out->vendor, api->query_device_string(device, EGL_VENDOR));
        tl__egl_copy(out->renderer, sizeof out->renderer, api->query_device_string(device, EGL_RENDERER_EXT));
    }
    if (tl__egl_has(ext, "EGL_EXT_device_persistent_id"))
        tl__egl_copy(out->driver, sizeof out->driver, api->query_device_string(device, EGL_DRIVER_NAME_EXT));
    eglGetError(); /* a string the device does not have is not this call's failure */
    if ((!out->vendor[0] || !out->driver[0]) && api->platform_device) {
        EGLDisplay display = api->get_platform_display(EGL_PLATFORM_DEVICE_EXT, device, NULL);
        if (display != EGL_NO_DISPLAY && eglInitialize(display, NULL, NULL))
            tl__egl_display_names(display, out->vendor, sizeof out->vendor, out->driver, sizeof out->driver);
        eglGetError();
    }
}

tl_result tl__egl_devices(tl_egl_device *devices, size_t capacity, size_t *count, const tl_logger *logger)
{
    tl__egl_api api;
    *count = 0;
    const char *why = tl__egl_api_load(&api);
    if (!why && (!api.query_devices || !api.query_device_string))
        why = "this EGL lists no devices (no EGL_EXT_device_enumeration)";
    if (why) return tl__logger_fail(logger, TL_ERROR_UNSUPPORTED, "tl_context_egl_devices: %s", why);
    EGLDeviceEXT list[TL__EGL_MAX_DEVICES];
    EGLint n = tl__egl_query_devices(&api, list);
    *count = (size_t)n;
    for (EGLint i = 0; devices && i < n && (size_t)i < capacity; i++)
        tl__egl_describe(&api, list[i], (uint32_t)i, &devices[i]);
    return TL_OK;
}

/* The platform of cfg as a display (not yet initialised) and its description in ctx->platform. */
static tl_result tl__egl_pick_display(tl_context *ctx, const tl__context_config *cfg, const tl__egl_api *api,
                                      EGLDisplay *display)
{
    EGLDeviceEXT list[TL__EGL_MAX_DEVICES];
    EGLint n = api->platform_device ? tl__egl_query_devices(api, list) : 0;
    EGLint chosen = -1;
    if (cfg->egl_platform == TL_EGL_PLATFORM_DEVICE) {
        if (!api->platform_device)
            return tl__log_fail(&ctx->log, TL_ERROR_UNSUPPORTED,
                                "EGL device %u asked for, but this EGL has no device platform "
                                "(EGL_EXT_device_enumeration, EGL_EXT_platform_device)",
                                (unsigned)cfg->egl_device);
        if ((EGLint)cfg->egl_device >= n || cfg->egl_device >= TL__EGL_MAX_DEVICES)
            return tl__log_fail(&ctx->log, TL_ERROR_INVALID_ARGUMENT,
                                "there is no EGL device %u: EGL lists %d (0 to %d)", (unsigned)cfg->egl_device,
                                (int)n, (int)n - 1);
        chosen = (EGLint)cfg->egl_device;
    } else if (cfg->egl_platform == TL_EGL_PLATFORM_DEFAULT) {
        for (EGLint i = 0; chosen < 0 && i < n; i++)
            if (!tl__egl_device_is_software(api, list[i])) chosen = i;
        if (chosen < 0 && cfg->egl_gpu_only) {
            if (!api->platform_device)
                return tl__log_fail(&ctx->log, TL_ERROR_UNSUPPORTED,
                                    "this EGL has no device platform (EGL_EXT_platform_device)");
            return tl__log_fail(&ctx->log, TL_ERROR_UNSUPPORTED,
                                "EGL lists no GPU device (%d device%s, Mesa's software rasteriser)", (int)n,
                                n == 1 ? "" : "s");
        }
    }
    if (chosen >= 0) {
        tl_egl_device d;
        tl__egl_describe(api, list[chosen], (uint32_t)chosen, &d);
        snprintf(ctx->platform, sizeof ctx->platform, "EGL device %d%s%s", (int)chosen, d.render_node[0] ? " " : "",
                 d.render_node[0] ? d.render_node : d.drm_device[0] ? d.drm_device : "");
        *display = api->get_platform_display(EGL_PLATFORM_DEVICE_EXT, list[chosen], NULL);
    } else if (api->platform_surfaceless) {
        snprintf(ctx->platform, sizeof ctx->platform, "EGL surfaceless");
        *display = api->get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    } else {
        return tl__log_fail(&ctx->log, TL_ERROR_UNSUPPORTED,
                            "this EGL has neither a GPU device nor Mesa's surfaceless platform "
                            "(EGL_MESA_platform_surfaceless)");
    }
    if (*display == EGL_NO_DISPLAY)
        return tl__log_fail(&ctx->log, TL_ERROR_GL, "eglGetPlatformDisplayEXT gave no display for %s: %s",
                            ctx->platform, tl__egl_error_name(eglGetError()));
    return TL_OK;
}

/* Initialises the display and checks what a surfaceless desktop-GL context needs. */
static tl_result tl__egl_init_display(tl_context *ctx, EGLDisplay display, bool *egl15)
{
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor))
        return tl__log_fail(&ctx->log, TL_ERROR_GL, "eglInitialize failed on %s: %s", ctx->platform,
                            tl__egl_error_name(eglGetError()));
    const char *ext = eglQueryString(display, EGL_EXTENSIONS);
    const char *apis = eglQueryString(display, EGL_CLIENT_APIS);
    *egl15 = major > 1 || (major == 1 && minor >= 5);
    const char *missing = NULL;
    if (!apis || !strstr(apis, "OpenGL") || !eglBindAPI(EGL_OPENGL_API)) missing = "desktop OpenGL (EGL_OPENGL_API)";
    else if (!*egl15 && !tl__egl_has(ext, "EGL_KHR_create_context")) missing = "EGL_KHR_create_context";
    else if (!tl__egl_has(ext, "EGL_KHR_surfaceless_context")) missing = "EGL_KHR_surfaceless_context";
    if (missing)
        return tl__log_fail(&ctx->log, TL_ERROR_UNSUPPORTED, "%s (EGL %d.%d) lacks %s", ctx->platform, (int)major,
                            (int)minor, missing);
    char vendor[96] = "", driver[64] = "";
    tl__egl_display_names(display, vendor, sizeof vendor, driver, sizeof driver);
    size_t used = strlen(ctx->platform);
    snprintf(ctx->platform + used, sizeof ctx->platform - used, " (%s%s%s)", vendor[0] ? vendor : "unknown vendor",
             driver[0] ? ", driver " : "", driver);
    return TL_OK;
}

/* A config for the context: none with EGL_KHR_no_config_context, else any desktop-GL one. */
static bool tl__egl_config(EGLDisplay display, EGLConfig *config)
{
    if (tl__egl_has(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
        *config = (EGLConfig)0; /* EGL_NO_CONFIG_KHR */
        return true;
    }
    const EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_DONT_CARE, EGL_NONE};
    EGLint n = 0;
    return eglChooseConfig(display, attribs, config, 1, &n) && n == 1;
}

static EGLContext tl__egl_try(EGLDisplay display, EGLConfig config, int major, int minor, bool debug, bool egl15)
{
    EGLint attribs[] = {
        EGL_CONTEXT_MAJOR_VERSION_KHR, major,
        EGL_CONTEXT_MINOR_VERSION_KHR, minor,
        EGL_CONTEXT_OPENGL_PROFILE_MASK_KHR, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT_KHR,
        EGL_NONE, EGL_NONE, EGL_NONE,
    };
    if (debug) {
        attribs[6] = egl15 ? EGL_CONTEXT_OPENGL_DEBUG : EGL_CONTEXT_FLAGS_KHR;
        attribs[7] = egl15 ? EGL_TRUE : EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR;
    }
    return eglCreateContext(display, config, EGL_NO_CONTEXT, attribs);
}

/* The requested core version, else (unless exact_version) the best of the fallbacks. */
static tl_result tl__egl_make_context(tl_context *ctx, const tl__context_config *cfg, tl__egl *e, bool egl15)
{
    static const int fallbacks[][2] = TL__CONTEXT_FALLBACKS;
    EGLConfig config;
    if (!tl__egl_config(e->display, &config))
        return tl__log_fail(&ctx->log, TL_ERROR_UNSUPPORTED, "%s offers no desktop OpenGL config", ctx->platform);
    int major = cfg->major, minor = cfg->minor;
    e->context = tl__egl_try(e->display, config, major, minor, cfg->debug, egl15);
    EGLint first_error = e->context == EGL_NO_CONTEXT ? eglGetError() : EGL_SUCCESS;
    for (size_t i = 0; e->context == EGL_NO_CONTEXT && !cfg->exact_version && i < sizeof fallbacks / sizeof fallbacks[0];
         i++) {
        int fa = fallbacks[i][0], fi = fallbacks[i][1];
        if (fa > cfg->major || (fa == cfg->major && fi >= cfg->minor)) continue;
        major = fa;
        minor = fi;
        e->context = tl__egl_try(e->display, config, major, minor, cfg->debug, egl15);
    }
    if (e->context == EGL_NO_CONTEXT) {
        eglGetError(); /* the last fallback's error is not left behind for the application */
        return tl__log_fail(&ctx->log, TL_ERROR_GL, "eglCreateContext refused OpenGL %d.%d core%s on %s: %s",
                            cfg->major, cfg->minor, cfg->exact_version ? "" : " and every core version down to 3.3",
                            ctx->platform, tl__egl_error_name(first_error));
    }
    ctx->major = major;
    ctx->minor = minor;
    return TL_OK;
}

static tl_result tl__egl_create(tl_context *ctx, const tl__context_config *cfg)
{
    tl__egl_api api;
    const char *why = tl__egl_api_load(&api);
    if (why) return tl__log_fail(&ctx->log, TL_ERROR_UNSUPPORTED, "%s", why);
    tl__egl *e = tl__calloc(&ctx->allocator, 1, sizeof *e);
    if (!e) return tl__log_fail(&ctx->log, TL_ERROR_OUT_OF_MEMORY, "out of memory");
    bool egl15 = false;
    tl_result r = tl__egl_pick_display(ctx, cfg, &api, &e->display);
    if (r == TL_OK) r = tl__egl_init_display(ctx, e->display, &egl15);
    if (r == TL_OK) r = tl__egl_make_context(ctx, cfg, e, egl15);
    if (r == TL_OK && !eglMakeCurrent(e->display, EGL_NO_SURFACE, EGL_NO_SURFACE, e->context)) {
        r = tl__log_fail(&ctx->log, TL_ERROR_GL, "eglMakeCurrent with no surface failed on %s: %s", ctx->platform,
                         tl__egl_error_name(eglGetError()));
        eglDestroyContext(e->display, e->context);
    }
    if (r != TL_OK) {
        ctx->platform[0] = '\0';
        tl__free(&ctx->allocator, e);
        return r;
    }
    ctx->impl = e;
    return TL_OK;
}

static tl_result tl__egl_make_current(tl_context *ctx)
{
    tl__egl *e = ctx->impl;
    if (!eglBindAPI(EGL_OPENGL_API) || !eglMakeCurrent(e->display, EGL_NO_SURFACE, EGL_NO_SURFACE, e->context))
        return tl__log_fail(&ctx->log, TL_ERROR_GL, "eglMakeCurrent failed: %s", tl__egl_error_name(eglGetError()));
    return TL_OK;
}

/* The current desktop-GL context is this one; the thread's bound API is left as it was. */
static bool tl__egl_is_current(const tl_context *ctx)
{
    const tl__egl *e = ctx->impl;
    EGLenum api = eglQueryAPI();
    bool current = eglBindAPI(EGL_OPENGL_API) && eglGetCurrentContext() == e->context;
    if (api != EGL_OPENGL_API && api != EGL_NONE) eglBindAPI(api);
    return current;
}

/* Releases the current desktop-GL EGL context, leaving the thread's bound API as it was. */
static void tl__egl_release(void)
{
    EGLenum api = eglQueryAPI();
    if (eglBindAPI(EGL_OPENGL_API) && eglGetCurrentContext() != EGL_NO_CONTEXT)
        eglMakeCurrent(eglGetCurrentDisplay(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (api != EGL_OPENGL_API && api != EGL_NONE) eglBindAPI(api);
}

static tl_gl_proc tl__egl_proc(tl_context *ctx, const char *name)
{
    (void)ctx;
    return (tl_gl_proc)eglGetProcAddress(name);
}

static void tl__egl_destroy(tl_context *ctx)
{
    tl__egl *e = ctx->impl;
    if (!e) return;
    EGLenum api = eglQueryAPI();
    if (eglBindAPI(EGL_OPENGL_API) && eglGetCurrentContext() == e->context)
        eglMakeCurrent(e->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (api != EGL_OPENGL_API && api != EGL_NONE) eglBindAPI(api);
    eglDestroyContext(e->display, e->context);
    tl__free(&ctx->allocator, e);
    ctx->impl = NULL;
}

const tl__context_ops tl__egl_ops = {
    .create = tl__egl_create,
    .make_current = tl__egl_make_current,
    .is_current = tl__egl_is_current,
    .release = tl__egl_release,
    .proc = tl__egl_proc,
    .swap = NULL,
    .size = NULL,
    .destroy = tl__egl_destroy,
};
