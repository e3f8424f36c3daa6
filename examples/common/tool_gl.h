/* Shared by the renderer tools (thinlight-render, thinlight-bench): the --context, --device and
 * --list-devices options and the context they make, and the image and glTF io, which a build
 * without THINLIGHT_WITH_IO (the GPU-server build, docs/gpu-servers.md) does not have: there the
 * io calls fail with one line saying so. Not part of the library. */
#ifndef TL_TOOL_GL_H
#define TL_TOOL_GL_H

#include <stddef.h>
#include <stdint.h>

#include "thinlight/context.h"
#include "thinlight/io.h"
#include "thinlight/scene.h"
#include "tool_args.h"
#include "tool_log.h"

/* ---- contexts ------------------------------------------------------------------------------ */

/* The help text of the options below, for the tools' usage texts (ends with a newline). */
#define TL_TOOL_CONTEXT_HELP                                                                     \
    "  --context C      auto (default), osmesa, egl or glfw: auto takes an EGL GPU device, else\n" \
    "                   OSMesa, else EGL's surfaceless platform; egl takes the first GPU device,\n" \
    "                   else the surfaceless platform\n"                                         \
    "  --device N       EGL device N of --list-devices (implies --context egl)\n"              \
    "  --list-devices   list the EGL devices and what --context auto would take, then exit\n"

/* The options, for a tool's parser (tool_args.h). */
extern const tl_opt_table tl_tool_context_option_table;

/* What the command line said: --context NAME (NULL: not given), --device N, --list-devices. */
typedef struct tl_tool_context_args {
    const char *context;
    int device_given;
    uint32_t device;
    int list_devices;
} tl_tool_context_args;

/* A parsed option into `a`: 1 when `o` is one of tl_tool_context_option_table, 0 otherwise. */
int tl_tool_context_option(tl_tool_context_args *a, const tl_opt *o, const tl_opt_value *v);

typedef struct tl_tool_context_options {
    tl_context_backend backend;
    tl_egl_platform egl_platform;
    uint32_t egl_device;
} tl_tool_context_options;

/* The values of --context and --device into `o`; 0, or 2 (bad usage) after one line on stderr:
 * an unknown back end, one not built in, a device that EGL does not list, --device with a back
 * end other than egl or auto. */
int tl_tool_context_parse(const char *tool, const tl_tool_context_args *a, tl_tool_context_options *o);

/* A width x height context as `o` says, current on this thread, and one line on stderr naming the
 * back end, the platform, GL_RENDERER and GL_VERSION; 0, or 1 after one line saying why not. */
int tl_tool_context_open(const char *tool, const tl_tool_context_options *o, uint32_t width, uint32_t height,
                         tl_context **out);

/* --list-devices: the EGL devices on stdout; 0, or 1 after one line on stderr (no EGL). */
int tl_tool_list_devices(const char *tool);

/* ---- io ------------------------------------------------------------------------------------ */

/* Whether this build has image and glTF io (THINLIGHT_WITH_IO). */
int tl_tool_have_io(void);
/* What an image output needs, for messages: "image output (PNG, EXR) needs a thinlight built
 * with THINLIGHT_WITH_IO=ON". */
extern const char tl_tool_no_io_images[];

/* Writes an image (tl_image_write); 0, or 1 after one line on stderr. */
int tl_tool_write_image(const char *tool, const char *path, const tl_image_desc *desc, const void *pixels);

/* Loads a glTF scene (tl_scene_load_gltf) with `options` (extra lights, seed, budgets; its logger
 * is replaced): the loader's warnings go to `log`, each once; on failure the reason (naming the
 * file) goes into `error` and the result is not TL_OK. */
tl_result tl_tool_load_gltf(const char *path, const tl_gltf_options *options, tl_tool_log *log, tl_scene **out,
                            char *error, size_t error_size);

#endif
