/**
 * @file thinlight/context.h
 * @brief OpenGL contexts: an off-screen OSMesa context (default, headless) or a GLFW window.
 *
 * Both give OpenGL 4.5 core. The renderer never creates a context; applications and tools use
 * these (or their own) and load GL through tl_context_get_proc_address or, with the shape the
 * renderer and glad expect, tl_context_proc_loader:
 *
 * @code
 * tl_context *ctx = NULL;
 * if (tl_context_create(&(tl_context_desc){ .width = 256, .height = 256 }, &ctx) != TL_OK)
 *     fprintf(stderr, "%s\n", tl_context_last_error(NULL));
 * @endcode
 *
 * A context is current on the thread that created it. A back end left out of the build
 * (THINLIGHT_WITH_OSMESA, THINLIGHT_WITH_GLFW) makes tl_context_create return
 * TL_ERROR_UNSUPPORTED; every function exists in every build.
 */
#ifndef THINLIGHT_CONTEXT_H
#define THINLIGHT_CONTEXT_H

#include <stdbool.h>

#include "thinlight/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/** An OpenGL context and its default framebuffer (an off-screen buffer or a window). */
typedef struct tl_context tl_context;

/** Which platform layer makes the context. */
typedef enum tl_context_backend {
    TL_CONTEXT_BACKEND_DEFAULT = 0, /**< = TL_CONTEXT_BACKEND_OSMESA */
    TL_CONTEXT_BACKEND_OSMESA,      /**< off-screen software context (llvmpipe), no display */
    TL_CONTEXT_BACKEND_GLFW,        /**< a GLFW window; needs a display */
    TL_CONTEXT_BACKEND_COUNT_       /**< number of values (not a back end) */
} tl_context_backend;

/** What tl_context_create makes. Every field's zero is its default. */
typedef struct tl_context_desc {
    tl_context_backend backend; /**< 0: OSMesa */
    uint32_t width;             /**< default framebuffer / window width in pixels; 0: 640 */
    uint32_t height;            /**< default framebuffer / window height in pixels; 0: 480 */
    int gl_major;               /**< requested core version; 0: 4.5 (gl_minor is then ignored) */
    int gl_minor;               /**< requested core minor version (with a non-zero gl_major) */
    /** false (default): when the requested version cannot be created, try lower core versions
     *  (4.x down to 3.3) and report the one obtained via tl_context_gl_version; true: fail. */
    bool exact_version;
    bool debug;                 /**< request a debug context (GLFW; OSMesa ignores it) */
    bool visible;               /**< GLFW: show the window (default hidden) */
    const char *title;          /**< GLFW: window title, copied; NULL: "thinlight" */
    /** Zeroed: malloc/free. Used for the tl_context and the OSMesa colour buffer; the platform
     *  libraries (Mesa, GLFW) allocate with their own allocators. Give both functions or none. */
    tl_allocator allocator;
    /** Zeroed: silent. Receives every failure's message (also kept for tl_context_last_error). */
    tl_logger logger;
} tl_context_desc;

/** A GL function pointer as returned by the platform's getprocaddress. */
typedef void (*tl_gl_proc)(void);

/**
 * Creates a context and makes it current on the calling thread. `desc` NULL means all defaults.
 *
 * @return TL_OK with *out set; TL_ERROR_INVALID_ARGUMENT for a NULL `out`, an unknown back end,
 *   a version outside 3.3 to 4.6 or an allocator with only one function; TL_ERROR_UNSUPPORTED for
 *   a back end not built into this library; TL_ERROR_GL when the platform refuses the context (no
 *   display, version unavailable); TL_ERROR_LIMIT for a size beyond the back end's maximum;
 *   TL_ERROR_OUT_OF_MEMORY. On failure *out is NULL and tl_context_last_error(NULL) says why.
 *
 * GLFW: glfwInit/glfwTerminate are process-global; this library counts its GLFW contexts under a
 * mutex, initialises GLFW with the first and terminates it with the last. GLFW requires both,
 * and window creation, on the main thread, and an application that also uses GLFW directly must
 * keep its own glfwInit alive across thinlight's contexts (or not mix the two).
 */
TL_API tl_result tl_context_create(const tl_context_desc *desc, tl_context **out);

/** Makes `ctx` current on the calling thread; NULL releases whichever thinlight back end is
 *  current. TL_ERROR_GL when the platform refuses (tl_context_last_error(ctx) says why). */
TL_API tl_result tl_context_make_current(tl_context *ctx);

/** The address of a GL function, NULL if unknown (or for a NULL argument). GLFW needs `ctx`
 *  current; OSMesa does not. */
TL_API tl_gl_proc tl_context_get_proc_address(tl_context *ctx, const char *name);

/**
 * tl_context_get_proc_address with the context passed as `void *`: the shape of a loader with a
 * user pointer, so that it can be given as it is to tl_renderer_desc.get_proc_address (with
 * get_proc_address_user = the context) or to glad's gladLoadGLContextUserPtr.
 */
TL_API tl_gl_proc tl_context_proc_loader(void *ctx, const char *name);

/** Presents the default framebuffer (GLFW); a no-op for OSMesa. TL_ERROR_INVALID_ARGUMENT for
 *  NULL. */
TL_API tl_result tl_context_swap(tl_context *ctx);

/** Destroys the context (releasing it first if current) with the allocator it was created
 *  with. NULL is allowed. */
TL_API void tl_context_destroy(tl_context *ctx);

/** A detailed message about the last failure of a call on `ctx`, or, for NULL, of the last
 *  tl_context_create on the calling thread; "" when there was none. Valid until the next call. */
TL_API const char *tl_context_last_error(const tl_context *ctx);

/** GL_RENDERER as read at creation, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"; "" for NULL.
 *  Owned by the context. */
TL_API const char *tl_context_renderer_string(const tl_context *ctx);
/** GL_VERSION as read at creation, e.g. "4.5 (Core Profile) Mesa 22.3.6"; "" for NULL. Owned by
 *  the context. */
TL_API const char *tl_context_version_string(const tl_context *ctx);

/** The core version obtained (may be below the request unless exact_version); 0.0 for NULL.
 *  Either output may be NULL. */
TL_API void tl_context_gl_version(const tl_context *ctx, int *major, int *minor);

/** The back end in use (never DEFAULT, except for a NULL context). */
TL_API tl_context_backend tl_context_get_backend(const tl_context *ctx);
/** The default framebuffer size in pixels (a GLFW window's current framebuffer size); 0 x 0 for
 *  NULL. Either output may be NULL. */
TL_API void tl_context_get_size(const tl_context *ctx, uint32_t *width, uint32_t *height);

#ifdef __cplusplus
}
#endif
#endif
