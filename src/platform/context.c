/* tl_context: the back-end table, descriptor defaults, the AUTO order, dispatch, the strings read
 * at creation. */
#include "platform.h"

#define TL__DEFAULT_WIDTH 640u
#define TL__DEFAULT_HEIGHT 480u

#if defined(_WIN32)
#  define TL__GLAPIENTRY __stdcall
#else
#  define TL__GLAPIENTRY
#endif
#define TL__GL_RENDERER 0x1F01
#define TL__GL_VERSION 0x1F02
#define TL__GL_MAJOR_VERSION 0x821B
#define TL__GL_MINOR_VERSION 0x821C
typedef const unsigned char *(TL__GLAPIENTRY *tl__get_string_fn)(unsigned int name);
typedef void(TL__GLAPIENTRY *tl__get_integerv_fn)(unsigned int name, int *data);

#if defined(TL_HAVE_OSMESA)
#define TL__OSMESA_OPS &tl__osmesa_ops
#else
#define TL__OSMESA_OPS NULL
#endif
#if defined(TL_HAVE_GLFW)
#define TL__GLFW_OPS &tl__glfw_ops
#else
#define TL__GLFW_OPS NULL
#endif
#if defined(TL_HAVE_EGL)
#define TL__EGL_OPS &tl__egl_ops
#else
#define TL__EGL_OPS NULL
#endif

/* Each back end: its name for the tools, its name in messages, its functions (NULL when not built
 * into this library) and how to build it. DEFAULT and AUTO are resolved before any use. */
typedef struct tl__backend_entry {
    const char *name, *label;
    const tl__context_ops *ops;
    const char *how_to_build;
} tl__backend_entry;

static const tl__backend_entry tl__backends[TL_CONTEXT_BACKEND_COUNT_] = {
    [TL_CONTEXT_BACKEND_DEFAULT] = {"default", "default", NULL, NULL},
    [TL_CONTEXT_BACKEND_OSMESA] = {"osmesa", "OSMesa", TL__OSMESA_OPS,
                                   "configure with -DTHINLIGHT_WITH_OSMESA=ON and libosmesa6-dev"},
    [TL_CONTEXT_BACKEND_GLFW] = {"glfw", "GLFW", TL__GLFW_OPS, "configure with -DTHINLIGHT_WITH_GLFW=ON and libglfw3-dev"},
    [TL_CONTEXT_BACKEND_EGL] = {"egl", "EGL", TL__EGL_OPS, "configure with -DTHINLIGHT_WITH_EGL=ON and libegl-dev"},
    [TL_CONTEXT_BACKEND_AUTO] = {"auto", "auto", NULL, NULL},
};

/* AUTO, best first: an EGL GPU device, OSMesa, EGL's surfaceless platform. */
static const struct {
    tl_context_backend backend;
    tl_egl_platform egl_platform;
    bool egl_gpu_only;
    const char *label;
} tl__auto_steps[] = {
    {TL_CONTEXT_BACKEND_EGL, TL_EGL_PLATFORM_DEFAULT, true, "EGL GPU device"},
    {TL_CONTEXT_BACKEND_OSMESA, TL_EGL_PLATFORM_DEFAULT, false, "OSMesa"},
    {TL_CONTEXT_BACKEND_EGL, TL_EGL_PLATFORM_SURFACELESS, false, "EGL surfaceless"},
};

/* DEFAULT: OSMesa when built in, else EGL (headless either way). */
static tl_context_backend tl__resolve_default(tl_context_backend b)
{
    if (b != TL_CONTEXT_BACKEND_DEFAULT) return b;
    if (!tl__backends[TL_CONTEXT_BACKEND_OSMESA].ops && tl__backends[TL_CONTEXT_BACKEND_EGL].ops)
        return TL_CONTEXT_BACKEND_EGL;
    return TL_CONTEXT_BACKEND_OSMESA;
}

static tl__context_config tl__context_desc_defaults(const tl_context_desc *desc)
{
    static const tl_context_desc zero = {0};
    if (!desc) desc = &zero;
    tl__context_config c = {
        .backend = tl__resolve_default(desc->backend),
        .width = desc->width ? desc->width : TL__DEFAULT_WIDTH,
        .height = desc->height ? desc->height : TL__DEFAULT_HEIGHT,
        .major = desc->gl_major ? desc->gl_major : 4,
        .minor = desc->gl_major ? desc->gl_minor : 5,
        .exact_version = desc->exact_version,
        .debug = desc->debug,
        .visible = desc->visible,
        .title = desc->title ? desc->title : "thinlight",
        .egl_platform = desc->egl_platform,
        .egl_device = desc->egl_device,
        .allocator = desc->allocator,
        .logger = desc->logger,
    };
    return c;
}

/* Reads GL_RENDERER, GL_VERSION and the version numbers through the context's own loader. */
static void tl__read_strings(tl_context *ctx)
{
    tl__get_string_fn get_string = (tl__get_string_fn)tl_context_get_proc_address(ctx, "glGetString");
    tl__get_integerv_fn get_integerv =
        (tl__get_integerv_fn)tl_context_get_proc_address(ctx, "glGetIntegerv");
    const unsigned char *s;
    if (get_string && (s = get_string(TL__GL_RENDERER)) != NULL)
        snprintf(ctx->renderer, sizeof ctx->renderer, "%s", (const char *)s);
    if (get_string && (s = get_string(TL__GL_VERSION)) != NULL)
        snprintf(ctx->version, sizeof ctx->version, "%s", (const char *)s);
    if (get_integerv) {
        int major = 0, minor = 0;
        get_integerv(TL__GL_MAJOR_VERSION, &major);
        get_integerv(TL__GL_MINOR_VERSION, &minor);
        if (major > 0) {
            ctx->major = major;
            ctx->minor = minor;
        }
    }
}

/* One back end (not DEFAULT or AUTO) into ctx; why it failed in ctx->log. */
static tl_result tl__create_with(tl_context *ctx, const tl__context_config *cfg, tl_context_backend backend)
{
    const tl__backend_entry *b = &tl__backends[backend];
    if (!b->ops)
        return tl__log_fail(&ctx->log, TL_ERROR_UNSUPPORTED, "the %s back end is not built into this thinlight (%s)",
                            b->label, b->how_to_build);
    ctx->backend = backend;
    ctx->ops = b->ops;
    tl_result r = b->ops->create(ctx, cfg);
    if (r != TL_OK) ctx->ops = NULL;
    return r;
}

/* AUTO: the steps in order until one gives a context; otherwise every step's reason. Running
 * out of memory ends the search: it says nothing about the back end, and going on would hide a
 * GPU behind a software rasteriser. */
static tl_result tl__create_auto(tl_context *ctx, const tl__context_config *cfg)
{
    char reasons[sizeof ctx->log.last_error] = "";
    size_t used = 0;
    tl_result r = TL_ERROR_UNSUPPORTED;
    for (size_t i = 0; i < sizeof tl__auto_steps / sizeof tl__auto_steps[0]; i++) {
        tl__context_config step = *cfg;
        step.egl_platform = tl__auto_steps[i].egl_platform;
        step.egl_gpu_only = tl__auto_steps[i].egl_gpu_only;
        r = tl__create_with(ctx, &step, tl__auto_steps[i].backend);
        if (r == TL_OK) return TL_OK;
        if (used < sizeof reasons)
            used += (size_t)snprintf(reasons + used, sizeof reasons - used, "%s%s: %s", used ? "; " : "",
                                     tl__auto_steps[i].label, ctx->log.last_error);
        if (r == TL_ERROR_OUT_OF_MEMORY) break;
    }
    return tl__log_fail(&ctx->log, r, "%s", reasons);
}

/* The descriptor's checks that need no back end; TL_OK or the failure, logged. */
static tl_result tl__check_desc(const tl_context_desc *desc, const tl__context_config *cfg)
{
    const tl_logger *logger = &cfg->logger;
    if (desc && !desc->allocator.alloc != !desc->allocator.free)
        return tl__logger_fail(logger, TL_ERROR_INVALID_ARGUMENT,
                               "tl_context_create: the allocator needs both alloc and free, or neither");
    if ((unsigned)cfg->backend >= TL_CONTEXT_BACKEND_COUNT_)
        return tl__logger_fail(logger, TL_ERROR_INVALID_ARGUMENT, "tl_context_create: unknown back end %d",
                               (int)cfg->backend);
    if ((unsigned)cfg->egl_platform >= TL_EGL_PLATFORM_COUNT_)
        return tl__logger_fail(logger, TL_ERROR_INVALID_ARGUMENT, "tl_context_create: unknown EGL platform %d",
                               (int)cfg->egl_platform);
    if (cfg->major < 3 || (cfg->major == 3 && cfg->minor < 3) || cfg->minor < 0 || cfg->major > 4 ||
        cfg->minor > 9)
        return tl__logger_fail(logger, TL_ERROR_INVALID_ARGUMENT,
                               "tl_context_create: OpenGL %d.%d requested, core profiles are 3.3 to 4.6",
                               cfg->major, cfg->minor);
    if (cfg->width > 65536 || cfg->height > 65536)
        return tl__logger_fail(logger, TL_ERROR_LIMIT, "tl_context_create: %ux%u is beyond any back end's limit",
                               (unsigned)cfg->width, (unsigned)cfg->height);
    return TL_OK;
}

tl_result tl_context_create(const tl_context_desc *desc, tl_context **out)
{
    tl__context_config cfg = tl__context_desc_defaults(desc);
    if (out) *out = NULL;
    if (!out) return tl__logger_fail(&cfg.logger, TL_ERROR_INVALID_ARGUMENT, "tl_context_create: NULL output");
    tl_result r = tl__check_desc(desc, &cfg);
    if (r != TL_OK) return r;
    tl__allocator_resolve(&cfg.allocator, &cfg.allocator); /* tl__check_desc refused a half one */

    tl_context *ctx = tl__calloc(&cfg.allocator, 1, sizeof *ctx);
    if (!ctx) return tl__logger_fail(&cfg.logger, TL_ERROR_OUT_OF_MEMORY, "tl_context_create: out of memory");
    ctx->allocator = cfg.allocator;
    ctx->width = cfg.width;
    ctx->height = cfg.height;
    r = cfg.backend == TL_CONTEXT_BACKEND_AUTO ? tl__create_auto(ctx, &cfg) : tl__create_with(ctx, &cfg, cfg.backend);
    if (r != TL_OK) {
        /* one line for the whole create, to the desc's logger: there is no object to keep it */
        tl__logger_fail(&cfg.logger, r, "%s: %s", tl__backends[cfg.backend].label, ctx->log.last_error);
        tl__free(&cfg.allocator, ctx);
        return r;
    }
    ctx->log = (tl__log){.logger = cfg.logger}; /* no failure yet: the fallbacks tried do not count */
    tl__read_strings(ctx);
    *out = ctx;
    return TL_OK;
}

tl_result tl_context_make_current(tl_context *ctx)
{
    if (!ctx) {
        for (size_t b = 0; b < TL_CONTEXT_BACKEND_COUNT_; b++)
            if (tl__backends[b].ops) tl__backends[b].ops->release();
        return TL_OK;
    }
    return ctx->ops->make_current(ctx);
}

bool tl_context_is_current(const tl_context *ctx) { return ctx && ctx->ops->is_current(ctx); }

tl_gl_proc tl_context_get_proc_address(tl_context *ctx, const char *name)
{
    if (!ctx || !name) return NULL;
    return ctx->ops->proc(ctx, name);
}

tl_result tl_context_swap(tl_context *ctx)
{
    if (!ctx) return TL_ERROR_INVALID_ARGUMENT;
    /* OSMesa renders straight into its buffer; EGL has no default framebuffer */
    return ctx->ops->swap ? ctx->ops->swap(ctx) : TL_OK;
}

void tl__context_link_add(tl_context *ctx, tl__context_link *link)
{
    link->context = ctx;
    link->prev = NULL;
    link->next = ctx->dependants;
    if (ctx->dependants) ctx->dependants->prev = link;
    ctx->dependants = link;
}

void tl__context_link_remove(tl__context_link *link)
{
    if (!link->context) return;
    if (link->prev) link->prev->next = link->next;
    else link->context->dependants = link->next;
    if (link->next) link->next->prev = link->prev;
    link->context = NULL;
    link->prev = link->next = NULL;
}

void tl_context_destroy(tl_context *ctx)
{
    if (!ctx) return;
    while (ctx->dependants) tl__context_link_remove(ctx->dependants); /* each learns it is gone */
    ctx->ops->destroy(ctx);
    tl_allocator allocator = ctx->allocator;
    tl__free(&allocator, ctx);
}

tl_gl_proc tl_context_proc_loader(void *ctx, const char *name)
{
    return tl_context_get_proc_address(ctx, name);
}

const char *tl_context_last_error(const tl_context *ctx) { return ctx ? ctx->log.last_error : ""; }

const char *tl_context_renderer_string(const tl_context *ctx) { return ctx ? ctx->renderer : ""; }

const char *tl_context_version_string(const tl_context *ctx) { return ctx ? ctx->version : ""; }

const char *tl_context_platform_string(const tl_context *ctx) { return ctx ? ctx->platform : ""; }

void tl_context_gl_version(const tl_context *ctx, int *major, int *minor)
{
    if (major) *major = ctx ? ctx->major : 0;
    if (minor) *minor = ctx ? ctx->minor : 0;
}

tl_context_backend tl_context_get_backend(const tl_context *ctx)
{
    return ctx ? ctx->backend : TL_CONTEXT_BACKEND_DEFAULT;
}

void tl_context_get_size(const tl_context *ctx, uint32_t *width, uint32_t *height)
{
    if (ctx && ctx->ops->size) {
        ctx->ops->size(ctx, width, height);
        return;
    }
    if (width) *width = ctx ? ctx->width : 0;
    if (height) *height = ctx ? ctx->height : 0;
}

const char *tl_context_backend_name(tl_context_backend backend)
{
    return (unsigned)backend < TL_CONTEXT_BACKEND_COUNT_ ? tl__backends[backend].name : "unknown";
}

tl_result tl_context_backend_from_name(const char *name, tl_context_backend *backend)
{
    for (size_t b = 0; name && backend && b < TL_CONTEXT_BACKEND_COUNT_; b++)
        if (strcmp(name, tl__backends[b].name) == 0) {
            *backend = (tl_context_backend)b;
            return TL_OK;
        }
    return TL_ERROR_INVALID_ARGUMENT;
}

bool tl_context_backend_available(tl_context_backend backend)
{
    if (backend == TL_CONTEXT_BACKEND_AUTO)
        return tl__backends[TL_CONTEXT_BACKEND_OSMESA].ops || tl__backends[TL_CONTEXT_BACKEND_EGL].ops;
    backend = tl__resolve_default(backend);
    return (unsigned)backend < TL_CONTEXT_BACKEND_COUNT_ && tl__backends[backend].ops;
}

tl_result tl_context_egl_devices(tl_egl_device *devices, size_t capacity, size_t *count, const tl_logger *logger)
{
    if (!count) return tl__logger_fail(logger, TL_ERROR_INVALID_ARGUMENT, "tl_context_egl_devices: NULL count");
#if defined(TL_HAVE_EGL)
    return tl__egl_devices(devices, capacity, count, logger);
#else
    (void)devices;
    (void)capacity;
    *count = 0;
    return tl__logger_fail(logger, TL_ERROR_UNSUPPORTED,
                           "tl_context_egl_devices: the EGL back end is not built into this thinlight (configure "
                           "with -DTHINLIGHT_WITH_EGL=ON and libegl-dev)");
#endif
}
