/* The environment file of the renderer tools (tool_environment.h). */
#include "tool_environment.h"

#include <stdio.h>
#include <stdlib.h>

#include "thinlight/io.h"

#if TL_TOOL_WITH_IO
#define tl__env_image_free tl_float_image_free
#else
static void tl__env_image_free(tl_float_image *img)
{
    (void)img;
}
#endif

const char tl_tool_environment_help[] =
    "  --environment FILE    equirectangular HDR image (.hdr, .exr; twice as wide as high) drawn as the sky\n"
    "                        and lighting every material (diffuse from SH, specular split sum); or a cube:\n"
    "                        its six faces in a row, +X -X +Y -Y +Z -Z (six times as wide as high)\n";

static const tl_opt env_opts[] = {
    {"--environment", TL_OPT_TEXT, .id = 0},
};

const tl_opt_table tl_tool_environment_option_table = TL_OPT_TABLE(env_opts);

int tl_tool_environment_apply(tl_tool_environment *e, const tl_opt *o, const tl_opt_value *v)
{
    if (!tl_opt_in(o, tl_tool_environment_option_table)) return 0;
    e->path = v->text;
    return 1;
}

static void tl__env_log(void *user, tl_log_level level, const char *message)
{
    (void)level;
    snprintf((char *)user, 256, "%s", message);
}

#if TL_TOOL_WITH_IO
static int tl__env_read(const char *tool, const char *path, tl_float_image *img)
{
    char why[256] = "cannot read it";
    tl_image_read_desc d = {.logger = {tl__env_log, why}};
    if (tl_image_read_rgb_float(path, &d, img) == TL_OK) return 0;
    fprintf(stderr, "%s: --environment: %s\n", tool, why); /* the reader's line names the file */
    return 1;
}
#else
static int tl__env_read(const char *tool, const char *path, tl_float_image *img)
{
    (void)img;
    (void)tl__env_log;
    fprintf(stderr, "%s: --environment %s: this build has no image reading (THINLIGHT_WITH_IO off)\n", tool, path);
    return 1;
}
#endif

int tl_tool_environment_read(const char *tool, tl_tool_environment *e)
{
    if (!e->path) return 0;
    tl_float_image img;
    if (tl__env_read(tool, e->path, &img)) return 1;
    /* 2:1 equirectangular, or 6:1 a cube's faces side by side in GL's order (+X -X +Y -Y +Z -Z) */
    if (img.height < 1 || (img.width != 6 * img.height && (img.height < 2 || img.width != 2 * img.height))) {
        fprintf(stderr,
                "%s: --environment %s: %ux%u is neither equirectangular (twice as wide as high) nor a cube's six "
                "faces in a row (six times as wide as high)\n",
                tool, e->path, (unsigned)img.width, (unsigned)img.height);
        tl__env_image_free(&img);
        return 1;
    }
    size_t n = (size_t)img.width * img.height * 3;
    e->rgb = malloc(n * sizeof *e->rgb);
    if (!e->rgb) {
        fprintf(stderr, "%s: --environment %s: out of memory\n", tool, e->path);
        tl__env_image_free(&img);
        return 1;
    }
    for (size_t i = 0; i < n; i++) e->rgb[i] = img.rgb[i];
    e->width = img.width;
    e->height = img.height;
    tl__env_image_free(&img);
    return 0;
}

int tl_tool_environment_set(const char *tool, const tl_tool_environment *e, tl_renderer *r)
{
    if (!e->rgb) return 0;
    tl_environment_desc d = {.rgb = e->rgb, .width = e->width, .height = e->height};
    if (e->width == 6 * e->height) { /* a cube's faces in a row (tl_environment_cube_desc) */
        tl_environment_cube_desc c;
        for (uint32_t f = 0; f < 6; f++)
            c.faces[f] = (tl_environment_face){.rgb = e->rgb + (size_t)f * e->height * 3u, .width = e->height,
                                               .height = e->height, .row_floats = e->width * 3u};
        if (tl_renderer_set_environment_cube(r, &c) == TL_OK) return 0;
    } else if (tl_renderer_set_environment(r, &d) == TL_OK) {
        return 0;
    }
    fprintf(stderr, "%s: --environment %s: %s\n", tool, e->path, tl_renderer_last_error(r));
    return 1;
}

void tl_tool_environment_free(tl_tool_environment *e)
{
    free(e->rgb);
    e->rgb = NULL;
}
