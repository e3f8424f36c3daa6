/* Renders the built-in crypt headless (OSMesa) and writes it as a PNG: ./getting_started [out.png] */
#include <stdio.h>
#include <stdlib.h>

#include <thinlight/context.h>
#include <thinlight/io.h>
#include <thinlight/renderer.h>
#include <thinlight/scene.h>

/* A tl_logger: keeps the last error line in a caller's buffer of 256 bytes. */
static void keep_error(void *user, tl_log_level level, const char *message)
{
    if (level == TL_LOG_ERROR) snprintf((char *)user, 256, "%s", message);
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "crypt.png";
    const uint32_t width = 320, height = 180;
    char error[256] = "";
    tl_context *ctx = NULL;
    tl_scene *scene = NULL;
    tl_renderer *renderer = NULL;
    uint8_t *rgba = malloc((size_t)width * height * 4);

    /* An off-screen OpenGL 4.5 context, current on this thread; the renderer draws into it. */
    tl_result r = tl_context_create(&(tl_context_desc){.width = width, .height = height,
                                                       .logger = {keep_error, error}}, &ctx);
    if (r == TL_OK) r = tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 32}, &scene);
    if (r == TL_OK) /* a failing create reports through the logger: there is no renderer to ask */
        r = tl_renderer_create(&(tl_renderer_desc){.width = width, .height = height,
                                                   .get_proc_address = tl_context_proc_loader,
                                                   .get_proc_address_user = ctx,
                                                   .logger = {keep_error, error}},
                               &renderer);
    if (r == TL_OK) r = tl_renderer_set_scene(renderer, scene); /* upload; the scene may go now */
    if (r == TL_OK) r = tl_renderer_render(renderer, NULL, NULL); /* NULL: the scene's camera */
    size_t size = (size_t)width * height * 4; /* bytes; tl_renderer_read_output(renderer, NULL, &size) asks */
    if (r == TL_OK) r = rgba ? tl_renderer_read_output(renderer, rgba, &size) : TL_ERROR_OUT_OF_MEMORY;
    if (r != TL_OK && renderer) snprintf(error, sizeof error, "%s", tl_renderer_last_error(renderer));
    if (r == TL_OK) {
        tl_image_desc image = {.width = width, .height = height, .channels = 4, .bottom_up = 1,
                               .logger = {keep_error, error}};
        r = tl_image_write(path, &image, rgba); /* a failure's line goes to the logger */
    }
    if (r == TL_OK)
        printf("wrote %s (%ux%u)\n", path, (unsigned)width, (unsigned)height);
    else
        fprintf(stderr, "getting_started: %s: %s\n", tl_result_string(r), error);

    tl_renderer_destroy(renderer); /* every create has its destroy; NULL is fine */
    tl_scene_destroy(scene);
    tl_context_destroy(ctx);
    free(rgba);
    return r == TL_OK ? 0 : 1;
}
