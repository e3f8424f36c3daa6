/* A loaded glTF and an application's own objects in one renderer: the file's scene is set whole,
 * then the application adds a texture, a material that maps it, a box and an object of its own,
 * and gives the file's lights with one of its own. It renders headless, writes the frame and checks
 * that both show. ./gltf_and_own_objects scene.gltf [out.png] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <thinlight/context.h>
#include <thinlight/io.h>
#include <thinlight/renderer.h>
#include <thinlight/scene.h>

enum { W = 320, H = 180 };

/* A unit box (24 vertices with normals and UVs, 36 indices), counter-clockwise seen from outside. */
static void unit_box(tl_vertex v[24], uint32_t idx[36])
{
    for (int f = 0; f < 6; f++) {
        int a = f / 2, b = (a + 1) % 3, c = (a + 2) % 3;
        float s = f % 2 ? -1.0f : 1.0f, u[4] = {-1, 1, 1, -1}, w[4] = {-1, -1, 1, 1};
        for (int i = 0; i < 4; i++) {
            tl_vertex *x = &v[f * 4 + i];
            memset(x, 0, sizeof *x);
            x->position[a] = 0.5f * s;
            x->position[b] = 0.5f * u[i];
            x->position[c] = 0.5f * w[i] * s;
            x->normal[a] = s;
            x->uv[0] = 0.5f + 0.5f * u[i];
            x->uv[1] = 0.5f + 0.5f * w[i];
        }
        const uint32_t q[6] = {0, 1, 2, 0, 2, 3};
        for (int i = 0; i < 6; i++) idx[f * 6 + i] = (uint32_t)(f * 4) + q[i];
    }
}

/* Renders with `camera` and reads the frame (RGBA8, rows bottom to top). */
static tl_result frame(tl_renderer *r, const tl_camera *camera, uint8_t *rgba)
{
    size_t size = (size_t)W * H * 4;
    tl_result res = tl_renderer_render(r, camera, NULL);
    return res == TL_OK ? tl_renderer_read_output(r, rgba, &size) : res;
}

/* Pixels that differ between two frames; `red` and `blue` count those whose colour in `a` is mostly red or blue. */
static size_t changed(const uint8_t *a, const uint8_t *b, size_t *red, size_t *blue)
{
    size_t n = 0;
    for (size_t i = 0; i < (size_t)W * H * 4; i += 4) {
        if (!memcmp(a + i, b + i, 4)) continue;
        n++;
        *red += a[i] > 2 * a[i + 1] && a[i] > 2 * a[i + 2];
        *blue += a[i + 2] > 2 * a[i] && a[i + 2] > 2 * a[i + 1];
    }
    return n;
}

int main(int argc, char **argv)
{
    if (argc < 2) return fprintf(stderr, "usage: gltf_and_own_objects scene.gltf [out.png]\n"), 2;
    const char *out = argc > 2 ? argv[2] : "gltf_and_own_objects.png";
    tl_last_error error = {0};
    const tl_logger log = tl_last_error_logger(&error);
    tl_context *ctx = NULL;
    tl_scene *file = NULL;
    tl_renderer *r = NULL;
    tl_light *lights = NULL;
    static uint8_t both[W * H * 4], no_box[W * H * 4], no_file[W * H * 4];
    tl_result res = tl_context_create(&(tl_context_desc){.width = W, .height = H, .logger = log}, &ctx);
    if (res == TL_OK) res = tl_scene_load_gltf(argv[1], &(tl_gltf_options){.logger = log}, &file);
    if (res == TL_OK)
        res = tl_renderer_create(&(tl_renderer_desc){.width = W, .height = H, .get_proc_address = tl_context_proc_loader,
                                                     .get_proc_address_user = ctx, .logger = log},
                                 &r);
    if (res == TL_OK) res = tl_renderer_set_scene(r, file); /* the file's objects: ids 0 .. object_count - 1 */

    /* The application's own: a red and blue checker, a material mapping it, a box in front of the file's objects. */
    float c[3] = {0, 0, 0}, e = 0.0f;
    for (int k = 0; res == TL_OK && k < 3; k++) {
        c[k] = 0.5f * (file->bounds_min[k] + file->bounds_max[k]);
        e = fmaxf(e, file->bounds_max[k] - file->bounds_min[k]);
    }
    uint8_t checker[8 * 8 * 4];
    for (int i = 0; i < 64; i++) {
        int red = ((i % 8) / 2 + (i / 16)) % 2;
        memcpy(checker + 4 * i, (uint8_t[4]){red ? 230 : 20, 20, red ? 20 : 230, 255}, 4);
    }
    tl_texture texture = {.width = 8, .height = 8, .rgba = checker, .name = "checker"};
    uint32_t map = 0, material = 0, first = 0, box = 0;
    if (res == TL_OK) res = tl_renderer_add_texture(r, &texture, &map); /* the pixels are copied */
    if (res == TL_OK)
        res = tl_renderer_add_material(r, &(tl_material){.albedo = {1, 1, 1}, .albedo_map = TL_TEXTURE_MAP(map)},
                                       &material);
    tl_vertex v[24];
    uint32_t idx[36];
    unit_box(v, idx);
    if (res == TL_OK) res = tl_renderer_add_geometry(r, v, 24, idx, 36, &first);
    tl_object mine = {.first_index = first, .index_count = 36, .material = material};
    float size = 0.2f * e, at[3] = {c[0] - 0.25f * e, c[1] + 0.1f * e, c[2] + 0.25f * e};
    for (int k = 0; k < 3; k++) mine.transform[k * 5] = size; /* scale, then move */
    for (int k = 0; k < 3; k++) mine.transform[12 + k] = at[k];
    mine.transform[15] = 1.0f;
    if (res == TL_OK) res = tl_renderer_add_object(r, &mine, &box);

    /* The lights are one array: the file's and a point light of the application's above its box. */
    size_t n = res == TL_OK ? file->light_count : 0;
    lights = res == TL_OK ? calloc(n + 1, sizeof *lights) : NULL;
    if (res == TL_OK && !lights) res = TL_ERROR_OUT_OF_MEMORY;
    if (res == TL_OK) {
        if (n) memcpy(lights, file->lights, n * sizeof *lights);
        lights[n] = (tl_light){.position = {at[0], at[1] + size, at[2] + size}, .color = {4, 4, 4}, .radius = 2.0f * e};
        res = tl_renderer_set_lights(r, lights, n + 1);
    }

    /* Both show: hiding the box, then the file's objects, changes the pixels each covers. */
    tl_camera camera = {.position = {c[0] + 0.3f * e, c[1] + 0.5f * e, c[2] + 0.9f * e}, .target = {c[0], c[1], c[2]}};
    size_t red = 0, blue = 0, no = 0, box_pixels = 0, file_pixels = 0;
    if (res == TL_OK) res = frame(r, &camera, both);
    if (res == TL_OK) res = tl_renderer_set_object_visible(r, box, 0);
    if (res == TL_OK) res = frame(r, &camera, no_box);
    if (res == TL_OK) res = tl_renderer_set_object_visible(r, box, 1);
    for (uint32_t i = 0; res == TL_OK && i < file->object_count; i++) res = tl_renderer_set_object_visible(r, i, 0);
    if (res == TL_OK) res = frame(r, &camera, no_file);
    if (res == TL_OK) {
        box_pixels = changed(both, no_box, &red, &blue);
        file_pixels = changed(both, no_file, &no, &no);
        res = tl_image_write(out, &(tl_image_desc){.width = W, .height = H, .channels = 4, .bottom_up = 1, .logger = log},
                             both);
    }
    int shown = box_pixels > 0 && red > 0 && blue > 0 && file_pixels > 0;
    if (res == TL_OK)
        printf("wrote %s: the file's %zu objects cover %zu pixels, the application's box %zu (%zu red, %zu blue)\n", out,
               file->object_count, file_pixels, box_pixels, red, blue);
    else
        fprintf(stderr, "gltf_and_own_objects: %s: %s\n", tl_result_string(res), error.message);
    free(lights);
    tl_renderer_destroy(r);
    tl_scene_destroy(file);
    tl_context_destroy(ctx);
    return res == TL_OK && shown ? 0 : 1;
}
