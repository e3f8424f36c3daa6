/* GLFW back end: a window with a core-profile context.
 *
 * glfwInit/glfwTerminate and the window hints are process-global. thinlight counts the contexts
 * it created under a mutex: the first initialises GLFW, the last terminates it, and hints are
 * reset and set under the same lock. GLFW itself demands that init, terminate and window
 * creation happen on the main thread; the lock does not lift that rule. Errors are read with
 * glfwGetError (per thread), so no global error callback is installed. */
#include <threads.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "platform.h"

typedef struct tl__glfw {
    GLFWwindow *window;
} tl__glfw;

static once_flag tl__glfw_once = ONCE_FLAG_INIT;
static mtx_t tl__glfw_lock;
static int tl__glfw_lock_ok;
static size_t tl__glfw_users; /* thinlight contexts alive; guarded by tl__glfw_lock */

static void tl__glfw_init_lock(void) { tl__glfw_lock_ok = mtx_init(&tl__glfw_lock, mtx_plain) == thrd_success; }

static const char *tl__glfw_error(void)
{
    const char *description = NULL;
    int code = glfwGetError(&description);
    if (code == GLFW_NO_ERROR || !description) return "no GLFW error reported";
    return description;
}

static GLFWwindow *tl__glfw_try(const tl__context_config *cfg, int major, int minor)
{
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, major);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, minor);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, cfg->debug ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, cfg->visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    glfwWindowHint(GLFW_STENCIL_BITS, 8);
    return glfwCreateWindow((int)cfg->width, (int)cfg->height, cfg->title, NULL, NULL);
}

static tl_result tl__glfw_create(tl_context *ctx, const tl__context_config *cfg)
{
    static const int fallbacks[][2] = TL__CONTEXT_FALLBACKS;
    call_once(&tl__glfw_once, tl__glfw_init_lock);
    if (!tl__glfw_lock_ok)
        return tl__log_fail(&ctx->log, TL_ERROR_OUT_OF_MEMORY, "could not create the mutex guarding glfwInit");
    tl__glfw *g = tl__calloc(&ctx->allocator, 1, sizeof *g);
    if (!g) return tl__log_fail(&ctx->log, TL_ERROR_OUT_OF_MEMORY, "out of memory");

    mtx_lock(&tl__glfw_lock);
    if (tl__glfw_users == 0 && !glfwInit()) {
        tl_result r = tl__log_fail(&ctx->log, TL_ERROR_GL, "glfwInit failed: %s", tl__glfw_error());
        mtx_unlock(&tl__glfw_lock);
        tl__free(&ctx->allocator, g);
        return r;
    }
    tl__glfw_users++;

    int major = cfg->major, minor = cfg->minor;
    g->window = tl__glfw_try(cfg, major, minor);
    const char *first_error = g->window ? NULL : tl__glfw_error();
    char first[256] = "";
    if (first_error) snprintf(first, sizeof first, "%s", first_error);
    for (size_t i = 0; !g->window && !cfg->exact_version && i < sizeof fallbacks / sizeof fallbacks[0];
         i++) {
        int fa = fallbacks[i][0], fi = fallbacks[i][1];
        if (fa > cfg->major || (fa == cfg->major && fi >= cfg->minor)) continue;
        major = fa;
        minor = fi;
        g->window = tl__glfw_try(cfg, major, minor);
    }
    glfwDefaultWindowHints();
    if (!g->window) {
        tl_result r = tl__log_fail(&ctx->log, TL_ERROR_GL, "glfwCreateWindow refused OpenGL %d.%d core%s: %s",
                                   cfg->major, cfg->minor,
                                   cfg->exact_version ? "" : " and every core version down to 3.3", first);
        glfwGetError(NULL); /* the last fallback's error is not left behind for the application */
        if (--tl__glfw_users == 0) glfwTerminate();
        mtx_unlock(&tl__glfw_lock);
        tl__free(&ctx->allocator, g);
        return r;
    }
    mtx_unlock(&tl__glfw_lock);

    glfwMakeContextCurrent(g->window);
    ctx->impl = g;
    ctx->major = major;
    ctx->minor = minor;
    snprintf(ctx->platform, sizeof ctx->platform, "GLFW window");
    return TL_OK;
}

static tl_result tl__glfw_make_current(tl_context *ctx)
{
    tl__glfw *g = ctx->impl;
    glfwMakeContextCurrent(g->window);
    if (glfwGetCurrentContext() != g->window)
        return tl__log_fail(&ctx->log, TL_ERROR_GL, "glfwMakeContextCurrent failed: %s", tl__glfw_error());
    return TL_OK;
}

static bool tl__glfw_is_current(const tl_context *ctx)
{
    const tl__glfw *g = ctx->impl;
    return glfwGetCurrentContext() == g->window;
}

static void tl__glfw_release(void)
{
    /* Only meaningful while GLFW is initialised by us; the count is read under the lock. */
    call_once(&tl__glfw_once, tl__glfw_init_lock);
    if (!tl__glfw_lock_ok) return;
    mtx_lock(&tl__glfw_lock);
    if (tl__glfw_users > 0) glfwMakeContextCurrent(NULL);
    mtx_unlock(&tl__glfw_lock);
}

static tl_gl_proc tl__glfw_proc(tl_context *ctx, const char *name)
{
    (void)ctx;
    return (tl_gl_proc)glfwGetProcAddress(name);
}

static tl_result tl__glfw_swap(tl_context *ctx)
{
    tl__glfw *g = ctx->impl;
    glfwSwapBuffers(g->window);
    return TL_OK;
}

static void tl__glfw_size(const tl_context *ctx, uint32_t *width, uint32_t *height)
{
    const tl__glfw *g = ctx->impl;
    int w = 0, h = 0;
    glfwGetFramebufferSize(g->window, &w, &h);
    if (width) *width = (uint32_t)(w > 0 ? w : 0);
    if (height) *height = (uint32_t)(h > 0 ? h : 0);
}

static void tl__glfw_destroy(tl_context *ctx)
{
    tl__glfw *g = ctx->impl;
    if (!g) return;
    if (glfwGetCurrentContext() == g->window) glfwMakeContextCurrent(NULL);
    glfwDestroyWindow(g->window);
    tl__free(&ctx->allocator, g);
    ctx->impl = NULL;
    mtx_lock(&tl__glfw_lock);
    if (--tl__glfw_users == 0) glfwTerminate();
    mtx_unlock(&tl__glfw_lock);
}

const tl__context_ops tl__glfw_ops = {
    .create = tl__glfw_create,
    .make_current = tl__glfw_make_current,
    .is_current = tl__glfw_is_current,
    .release = tl__glfw_release,
    .proc = tl__glfw_proc,
    .swap = tl__glfw_swap,
    .size = tl__glfw_size,
    .destroy = tl__glfw_destroy,
};
