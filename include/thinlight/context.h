/**
 * @file thinlight/context.h
 * @brief OpenGL contexts: off-screen OSMesa (default, headless), EGL without a window (GPU
 * servers, or Mesa's surfaceless platform) or a GLFW window.
 *
 * Every back end gives OpenGL 4.5 core. The renderer never creates a context; applications and
 * tools use these (or their own) and load GL through tl_context_get_proc_address or, with the
 * shape the renderer and glad expect, tl_context_proc_loader.
 *
 * Errors as everywhere in thinlight: a tl_result, one line to the descriptor's logger, and, for
 * calls on a context, the same line in tl_context_last_error. A failed create has no object to
 * ask: its message goes to the descriptor's logger only (my_logger below, e.g. a function
 * printing `message` to stderr when `level` is TL_LOG_ERROR). The library itself prints nothing.
 *
 * @code
 * tl_context *ctx = NULL;
 * tl_context_desc desc = {.width = 256, .height = 256, .logger = my_logger};
 * if (tl_context_create(&desc, &ctx) != TL_OK) return 1; // the logger said why
 * @endcode
 *
 * A context is current on the thread that created it. A back end left out of the build
 * (THINLIGHT_WITH_OSMESA, THINLIGHT_WITH_EGL, THINLIGHT_WITH_GLFW) makes tl_context_create return
 * TL_ERROR_UNSUPPORTED; every function exists in every build.
 *
 * EGL contexts have no default framebuffer (no window, no pbuffer: the renderer draws into its own
 * targets). EGL displays are process-wide and shared with anything else in the process that uses
 * EGL, so thinlight initialises the displays it uses and never terminates them; EGL itself
 * releases them when the process exits.
 */
#ifndef THINLIGHT_CONTEXT_H
#define THINLIGHT_CONTEXT_H

#include <stdbool.h>
#include <stddef.h>

#include "thinlight/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/** An OpenGL context and its default framebuffer (an off-screen buffer, a window, or none). */
typedef struct tl_context tl_context;

/** Which platform layer makes the context. Names (tl_context_backend_name): "default",
 *  "osmesa", "glfw", "egl", "auto". */
typedef enum tl_context_backend {
    TL_CONTEXT_BACKEND_DEFAULT = 0, /**< OSMesa when built in, else EGL */
    TL_CONTEXT_BACKEND_OSMESA,      /**< off-screen software context (llvmpipe), no display */
    TL_CONTEXT_BACKEND_GLFW,        /**< a GLFW window; needs a display */
    /** EGL with no window: a device of EGL_EXT_platform_device (the way to a GPU on a server with
     *  no display, NVIDIA's driver included) or Mesa's surfaceless platform; see tl_egl_platform. */
    TL_CONTEXT_BACKEND_EGL,
    /** Headless, best first: the first EGL GPU device (one that is not Mesa's software
     *  rasteriser), then OSMesa, then EGL's surfaceless platform. egl_platform and egl_device are
     *  ignored; tl_context_get_backend tells which one was made. A step that runs out of memory
     *  ends the search (TL_ERROR_OUT_OF_MEMORY), rather than falling back to the next. */
    TL_CONTEXT_BACKEND_AUTO,
    TL_CONTEXT_BACKEND_COUNT_       /**< number of values (not a back end) */
} tl_context_backend;

/** Where an EGL context comes from (TL_CONTEXT_BACKEND_EGL). */
typedef enum tl_egl_platform {
    /** The first GPU device that tl_context_egl_devices lists (not Mesa's software one), else
     *  the surfaceless platform. */
    TL_EGL_PLATFORM_DEFAULT = 0,
    TL_EGL_PLATFORM_DEVICE,      /**< the device tl_context_desc.egl_device (EGL_EXT_platform_device) */
    /** EGL_MESA_platform_surfaceless: Mesa picks the GPU of a render node it can drive, else
     *  llvmpipe (always llvmpipe with LIBGL_ALWAYS_SOFTWARE=1). */
    TL_EGL_PLATFORM_SURFACELESS,
    TL_EGL_PLATFORM_COUNT_       /**< number of values (not a platform) */
} tl_egl_platform;

/** What tl_context_create makes. Every field's zero is its default. */
typedef struct tl_context_desc {
    tl_context_backend backend; /**< 0: OSMesa when built in, else EGL */
    uint32_t width;             /**< default framebuffer / window width in pixels; 0: 640 */
    uint32_t height;            /**< default framebuffer / window height in pixels; 0: 480 */
    int gl_major;               /**< requested core version; 0: 4.5 (gl_minor is then ignored) */
    int gl_minor;               /**< requested core minor version (with a non-zero gl_major) */
    /** false (default): when the requested version cannot be created, try lower core versions
     *  (4.x down to 3.3) and report the one obtained via tl_context_gl_version; true: fail. */
    bool exact_version;
    bool debug;                 /**< request a debug context (GLFW, EGL; OSMesa ignores it) */
    bool visible;               /**< GLFW: show the window (default hidden) */
    const char *title;          /**< GLFW: window title, copied; NULL: "thinlight" */
    tl_egl_platform egl_platform; /**< EGL: which display; 0: a GPU device, else surfaceless */
    /** EGL with TL_EGL_PLATFORM_DEVICE: the device's index in tl_context_egl_devices' list
     *  (0: the first). An index beyond the list is TL_ERROR_INVALID_ARGUMENT. */
    uint32_t egl_device;
    /** Zeroed: malloc/free. Used for everything thinlight allocates for the context (the
     *  tl_context, each back end's state, the OSMesa colour buffer); the platform libraries
     *  (Mesa, EGL, GLFW) allocate with their own allocators. Give both functions or none. */
    tl_allocator allocator;
    /** Zeroed: silent. Receives every failure's message, one line each: a failed
     *  tl_context_create reports only here; failures of calls on a context are also kept for
     *  tl_context_last_error. */
    tl_logger logger;
} tl_context_desc;

/** What EGL tells about one of its devices (tl_context_egl_devices). Strings EGL does not
 *  provide are "" and long ones are cut. */
typedef struct tl_egl_device {
    uint32_t index;       /**< position in the list: the value of tl_context_desc.egl_device */
    /** Mesa's software rasteriser (EGL_MESA_device_software): llvmpipe, not a GPU. */
    bool software;
    char drm_device[128]; /**< EGL_DRM_DEVICE_FILE_EXT, e.g. "/dev/dri/card0" */
    char render_node[128]; /**< EGL_DRM_RENDER_NODE_FILE_EXT, e.g. "/dev/dri/renderD128" */
    /** The driver: EGL_DRIVER_NAME_EXT (EGL_EXT_device_persistent_id), else Mesa's
     *  eglGetDisplayDriverName (EGL_MESA_query_driver), e.g. "swrast", "iris", "nvidia". */
    char driver[64];
    /** EGL_VENDOR of the device (EGL_EXT_device_query_name), else of its display. */
    char vendor[128];
    /** EGL_RENDERER_EXT of the device (EGL_EXT_device_query_name), e.g. "NVIDIA H100". */
    char renderer[128];
} tl_egl_device;

/** A GL function pointer as returned by the platform's getprocaddress. */
typedef void (*tl_gl_proc)(void);

/**
 * Creates a context and makes it current on the calling thread. `desc` NULL means all defaults.
 *
 * @return TL_OK with *out set; TL_ERROR_INVALID_ARGUMENT for a NULL `out`, an unknown back end or
 *   EGL platform, an EGL device index beyond the list, a version outside 3.3 to 4.6 or an
 *   allocator with only one function; TL_ERROR_UNSUPPORTED for a back end not built into this
 *   library (or an EGL without the extensions it needs); TL_ERROR_GL when the platform refuses the
 *   context (no display, version unavailable); TL_ERROR_LIMIT for a size beyond the back end's
 *   maximum; TL_ERROR_OUT_OF_MEMORY. On failure *out is NULL and the message went to
 *   desc->logger (there is no object to keep it).
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

/** Whether `ctx` is current on the calling thread (false for NULL); as cheap as the platform's
 *  OSMesaGetCurrentContext, eglGetCurrentContext or glfwGetCurrentContext. A renderer loading GL
 *  through tl_context_proc_loader asks this before every call that uses GL. */
TL_API bool tl_context_is_current(const tl_context *ctx);

/** The address of a GL function, NULL if unknown (or for a NULL argument). GLFW needs `ctx`
 *  current; OSMesa and EGL (eglGetProcAddress, core functions included) do not. */
TL_API tl_gl_proc tl_context_get_proc_address(tl_context *ctx, const char *name);

/**
 * tl_context_get_proc_address with the context passed as `void *`: the shape of a loader with a
 * user pointer, so that it can be given as it is to tl_renderer_desc.get_proc_address (with
 * get_proc_address_user = the context) or to glad's gladLoadGLContextUserPtr.
 */
TL_API tl_gl_proc tl_context_proc_loader(void *ctx, const char *name);

/** Presents the default framebuffer (GLFW); a no-op for OSMesa and EGL. TL_ERROR_INVALID_ARGUMENT
 *  for NULL. */
TL_API tl_result tl_context_swap(tl_context *ctx);

/** Destroys the context (releasing it first if current) with the allocator it was created
 *  with. NULL is allowed. */
TL_API void tl_context_destroy(tl_context *ctx);

/** The message of the last failure of a call on `ctx` (the line its logger received), kept until
 *  the next failure, as tl_renderer_last_error; "" when no call has failed, and for NULL (a
 *  failed tl_context_create reports through its descriptor's logger). Owned by the context. */
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

/** The back end in use (never DEFAULT or AUTO, except DEFAULT for a NULL context). */
TL_API tl_context_backend tl_context_get_backend(const tl_context *ctx);
/** Where the context came from, in words: "OSMesa", "GLFW window", "EGL device 1
 *  /dev/dri/renderD128 (NVIDIA, driver nvidia)", "EGL surfaceless (Mesa Project, driver
 *  swrast)"; "" for NULL. Owned by the context. */
TL_API const char *tl_context_platform_string(const tl_context *ctx);
/** The default framebuffer size in pixels (a GLFW window's current framebuffer size; for EGL,
 *  which has no default framebuffer, the size asked for); 0 x 0 for NULL. Either output may be
 *  NULL. */
TL_API void tl_context_get_size(const tl_context *ctx, uint32_t *width, uint32_t *height);

/** "default", "osmesa", "glfw", "egl", "auto" ("unknown" otherwise): the names the tools'
 *  --context option takes. */
TL_API const char *tl_context_backend_name(tl_context_backend backend);
/** Parses a name of tl_context_backend_name; TL_ERROR_INVALID_ARGUMENT for anything else (and
 *  for NULL arguments). */
TL_API tl_result tl_context_backend_from_name(const char *name, tl_context_backend *backend);
/** Whether `backend` is built into this library (AUTO: whether any headless one is; DEFAULT:
 *  whether the back end it stands for is). */
TL_API bool tl_context_backend_available(tl_context_backend backend);

/**
 * Lists the EGL devices (EGL_EXT_device_enumeration) in the order tl_context_desc.egl_device
 * counts them, without creating a context: at most `capacity` entries into `devices` (NULL asks
 * only for the count), and the number of devices into *count. Reading a device's driver or vendor
 * may initialise its EGL display (see the file comment). `logger` (may be NULL) receives the
 * failure's message.
 *
 * @return TL_OK; TL_ERROR_INVALID_ARGUMENT for a NULL `count`; TL_ERROR_UNSUPPORTED (with *count
 *   0) when the EGL back end is not built in or the EGL client lacks device enumeration.
 */
TL_API tl_result tl_context_egl_devices(tl_egl_device *devices, size_t capacity, size_t *count,
                                        const tl_logger *logger);

#ifdef __cplusplus
}
#endif
#endif
