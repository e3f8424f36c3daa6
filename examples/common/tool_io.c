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

/* Where the loader's lines go: the error into the caller's buffer, warnings to the tool's log. */
typedef struct tool_load_lines {
    char *error;
    size_t size;
    tl_tool_log *log;
} tool_load_lines;

static void tool_load_line(void *user, tl_log_level level, const char *message)
{
    const tool_load_lines *b = (const tool_load_lines *)user;
    if (level == TL_LOG_ERROR && b->size) snprintf(b->error, b->size, "%s", message);
    else if (level == TL_LOG_WARNING) tl_tool_log_message(b->log, level, message);
}

tl_result tl_tool_load_gltf(const char *path, const tl_gltf_options *options, tl_tool_log *log, tl_scene **out,
                            char *error, size_t error_size)
{
    tool_load_lines b = {error, error_size, log};
    if (error_size) error[0] = '\0';
    tl_gltf_options o = *options;
    o.logger = (tl_logger){tool_load_line, &b};
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

tl_result tl_tool_load_gltf(const char *path, const tl_gltf_options *options, tl_tool_log *log, tl_scene **out,
                            char *error, size_t error_size)
{
    (void)options;
    (void)log;
    *out = NULL;
    snprintf(error, error_size, "%s: loading glTF needs a thinlight built with THINLIGHT_WITH_IO=ON (use the "
                                "built-in scene 'default')", path);
    return TL_ERROR_UNSUPPORTED;
}

#endif
