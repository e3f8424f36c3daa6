/* Renders the built-in crypt headless (OSMesa) and writes it as a PNG: ./getting_started [out.png] */
#include <stdio.h>
#include <stdlib.h>

#include <thinlight/context.h>
#include <thinlight/io.h>
#include <thinlight/renderer.h>
#include <thinlight/scene.h>

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "crypt.png";
    const uint32_t width = 320, height = 180;
    tl_last_error error = {0}; /* the one place every call below reports its failure's line */
    const tl_logger log = tl_last_error_logger(&error);
    tl_context *ctx = NULL;
    tl_scene *scene = NULL;
    tl_renderer *renderer = NULL;
    uint8_t *rgba = malloc((size_t)width * height * 4);

    /* An off-screen OpenGL 4.5 context, current on this thread; the renderer draws into it. */
    tl_result r = tl_context_create(&(tl_context_desc){.width = width, .height = height, .logger = log}, &ctx);
    if (r == TL_OK)
        r = tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 32, .logger = log}, &scene);
    if (r == TL_OK)
        r = tl_renderer_create(&(tl_renderer_desc){.width = width, .height = height,
                                                   .get_proc_address = tl_context_proc_loader,
                                                   .get_proc_address_user = ctx, .logger = log},
                               &renderer);
    if (r == TL_OK) r = tl_renderer_set_scene(renderer, scene); /* upload; the scene may go now */
    if (r == TL_OK) r = tl_renderer_render(renderer, NULL, NULL); /* NULL: the scene's camera */
    size_t size = (size_t)width * height * 4; /* bytes; tl_renderer_read_output(renderer, NULL, &size) asks */
    if (r == TL_OK) r = rgba ? tl_renderer_read_output(renderer, rgba, &size) : TL_ERROR_OUT_OF_MEMORY;
    if (r == TL_OK) {
        tl_image_desc image = {.width = width, .height = height, .channels = 4, .bottom_up = 1, .logger = log};
        r = tl_image_write(path, &image, rgba);
    }
    if (r == TL_OK)
        printf("wrote %s (%ux%u)\n", path, (unsigned)width, (unsigned)height);
    else /* whichever call failed, the renderer's, the context's or the writer's, its line is here */
        fprintf(stderr, "getting_started: %s: %s\n", tl_result_string(r), error.message);

    tl_renderer_destroy(renderer); /* every create has its destroy; NULL is fine */
    tl_scene_destroy(scene);
    tl_context_destroy(ctx);
    free(rgba);
    return r == TL_OK ? 0 : 1;
}
