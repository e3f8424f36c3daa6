/* The renderer tools' image and glTF io (tool_gl.h): io.h when this build has it
 * (TL_TOOL_WITH_IO=1, set by examples/CMakeLists.txt from THINLIGHT_WITH_IO), else one line saying
 * what is missing. */
#include <stdio.h>

#include "tool_gl.h"
#include "tool_log.h"
#include "tool_util.h"

const char tl_tool_no_io_images[] = "image output (PNG, EXR) needs a thinlight built with THINLIGHT_WITH_IO=ON";

int tl_tool_have_io(void) { return TL_TOOL_WITH_IO; }

#if TL_TOOL_WITH_IO

int tl_tool_write_image(const char *tool, const char *path, const tl_image_desc *desc, const void *pixels)
{
    tl_image_desc d = *desc;
    d.logger = tl_tool_logger(tool); /* the writer's one line ("PATH: reason") is the tool's */
    return tl_image_write(path, &d, pixels) == TL_OK ? 0 : 1;
}

/* Where the loader's error line goes: the caller's buffer. */
typedef struct tool_error_buffer {
    char *text;
    size_t size;
} tool_error_buffer;

static void tool_keep_error(void *user, tl_log_level level, const char *message)
{
    const tool_error_buffer *b = (const tool_error_buffer *)user;
    if (level == TL_LOG_ERROR && b->size) snprintf(b->text, b->size, "%s", message);
}

tl_result tl_tool_load_gltf(const char *path, uint32_t extra_lights, uint64_t seed, tl_scene **out, char *error,
                            size_t error_size)
{
    tool_error_buffer b = {error, error_size};
    if (error_size) error[0] = '\0';
    tl_gltf_options o = {.extra_lights = extra_lights, .seed = seed, .logger = {tool_keep_error, &b}};
    return tl_scene_load_gltf(path, &o, out);
}

#else

int tl_tool_write_image(const char *tool, const char *path, const tl_image_desc *desc, const void *pixels)
{
    (void)desc;
    (void)pixels;
    tl_tool_fail(tool, "cannot write %s: %s", path, tl_tool_no_io_images);
    return 1;
}

tl_result tl_tool_load_gltf(const char *path, uint32_t extra_lights, uint64_t seed, tl_scene **out, char *error,
                            size_t error_size)
{
    (void)extra_lights;
    (void)seed;
    *out = NULL;
    snprintf(error, error_size, "%s: loading glTF needs a thinlight built with THINLIGHT_WITH_IO=ON (use the "
                                "built-in scene 'default')", path);
    return TL_ERROR_UNSUPPORTED;
}

#endif
