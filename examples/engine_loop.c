/* An engine's frame loop around thinlight: its own scene from zeroed structs, 200 moving lights,
 * objects moved, hidden, added and removed, options changed every frame, an application pass, a
 * resize, and the engine's own GL state left in the context. Nothing is created twice.
 * ./engine_loop [out.png] */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <thinlight/context.h>
#include <thinlight/io.h>
#include <thinlight/renderer.h>
#include <thinlight/scene.h>

enum { BOXES = 12, LIGHTS = 200, FRAMES = 48 };

/* GL entry points of the engine's own (any loader does: glfwGetProcAddress, glad, ...). */
typedef void (*gl_enum_fn)(unsigned int);
typedef void (*gl_range_fn)(double, double);
typedef void (*gl_rect_fn)(int, int, int, int);
typedef void (*gl_color_fn)(float, float, float, float);
static gl_enum_fn gl_enable, gl_disable, gl_front_face, gl_clear;
static gl_range_fn gl_depth_range;
static gl_rect_fn gl_scissor;
static gl_color_fn gl_clear_color;

/* An application pass: a marker drawn into HDR before the tone map, with the engine's GL. */
static void marker(void *user, const tl_app_pass_context *ctx)
{
    (void)user;
    gl_enable(0x0C11 /* GL_SCISSOR_TEST */);
    gl_scissor(8, 8, 24, 24);
    gl_clear_color(4.0f, 2.0f, 0.5f, 1.0f);
    gl_clear(0x4000 /* GL_COLOR_BUFFER_BIT */);
    gl_disable(0x0C11);
    (void)ctx;
}

/* A unit box (24 vertices, 36 indices) appended at v + *nv, idx + *ni. */
static void add_box(tl_vertex *v, uint32_t *idx, uint32_t *nv, uint32_t *ni)
{
    for (int f = 0; f < 6; f++) {
        int a = f / 2, b = (a + 1) % 3, c = (a + 2) % 3;
        float s = f % 2 ? -1.0f : 1.0f, u[4] = {-1, 1, 1, -1}, w[4] = {-1, -1, 1, 1};
        for (int i = 0; i < 4; i++) {
            tl_vertex *x = &v[*nv + i];
            x->position[a] = 0.5f * s;
            x->position[b] = 0.5f * u[i];
            x->position[c] = 0.5f * w[i] * s; /* counter-clockwise seen from outside */
            x->normal[a] = s;
        }
        const uint32_t q[6] = {0, 1, 2, 0, 2, 3};
        for (int i = 0; i < 6; i++) idx[*ni + i] = *nv + q[i];
        *nv += 4;
        *ni += 6;
    }
}

static void place(float m[16], float x, float y, float z, float angle, float scale)
{
    float c = cosf(angle) * scale, s = sinf(angle) * scale;
    float t[16] = {c, 0, -s, 0, 0, scale, 0, 0, s, 0, c, 0, x, y, z, 1};
    memcpy(m, t, sizeof t);
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "engine_loop.png";
    tl_last_error error = {0}; /* every call's failure line, whichever call it was */
    const tl_logger log = tl_last_error_logger(&error);
    uint32_t width = 320, height = 180;
    tl_context *ctx = NULL;
    tl_renderer *r = NULL;
    static uint8_t rgba[400 * 225 * 4];
    tl_result res = tl_context_create(&(tl_context_desc){.width = 400, .height = 225, .logger = log}, &ctx);
    if (res != TL_OK) return fprintf(stderr, "engine_loop: %s\n", error.message), 1;
    gl_enable = (gl_enum_fn)tl_context_get_proc_address(ctx, "glEnable");
    gl_disable = (gl_enum_fn)tl_context_get_proc_address(ctx, "glDisable");
    gl_front_face = (gl_enum_fn)tl_context_get_proc_address(ctx, "glFrontFace");
    gl_clear = (gl_enum_fn)tl_context_get_proc_address(ctx, "glClear");
    gl_depth_range = (gl_range_fn)tl_context_get_proc_address(ctx, "glDepthRange");
    gl_scissor = (gl_rect_fn)tl_context_get_proc_address(ctx, "glScissor");
    gl_clear_color = (gl_color_fn)tl_context_get_proc_address(ctx, "glClearColor");

    /* The scene: a floor and boxes, one mesh each; every field not named is its default. */
    tl_vertex v[48] = {0};
    uint32_t idx[72], nv = 0, ni = 0;
    add_box(v, idx, &nv, &ni);
    tl_material materials[4] = {{.albedo = {0.6f, 0.6f, 0.55f}},
                                {.albedo = {0.8f, 0.2f, 0.1f}, .specular = {0.3f, 0.3f, 0.3f}, .gloss = 0.6f},
                                {.albedo = {0.1f, 0.3f, 0.8f}, .flags = TL_MATERIAL_METALLIC_ROUGHNESS,
                                 .metallic = 1.0f, .roughness = 0.3f},
                                {.albedo = {0.9f, 0.9f, 0.2f}}};
    tl_object objects[1 + BOXES] = {{.index_count = 36}}; /* the floor: the box, flattened */
    place(objects[0].transform, 0, -0.05f, 0, 0, 1);
    objects[0].transform[0] = objects[0].transform[10] = 20.0f;
    objects[0].transform[5] = 0.1f;
    for (int i = 1; i <= BOXES; i++) objects[i] = (tl_object){.index_count = 36, .material = (uint32_t)(i % 3 + 1)};
    tl_light lights[LIGHTS];
    tl_scene scene = {.vertices = v, .vertex_count = nv, .indices = idx, .index_count = ni, .objects = objects,
                      .object_count = 1 + BOXES, .materials = materials, .material_count = 4, .lights = lights,
                      .ambient = {0.03f, 0.03f, 0.04f}, .camera = {.position = {0, 6, 11}, .target = {0, 0.5f, 0}}};
    tl_renderer_desc desc = {.width = width, .height = height, .get_proc_address = tl_context_proc_loader,
                             .get_proc_address_user = ctx, .logger = log};
    tl_app_pass_desc pass = {.name = "marker", .before = "tonemap", .writes = TL_TARGET_BIT(TL_TARGET_HDR),
                             .execute = marker};
    res = tl_renderer_create(&desc, &r);
    if (res == TL_OK) res = tl_renderer_set_scene(r, &scene); /* lights come every frame below */
    if (res == TL_OK) res = tl_renderer_add_pass(r, &pass);

    /* What the engine switches between frames: no renderer is created again for any of it. */
    const tl_renderer_options options[6] = {
        {0},
        {.mode = TL_MODE_FAT, .light_strategy = TL_LIGHT_STRATEGY_TILED},
        {.mode = TL_MODE_FORWARD, .lighting = TL_LIGHTING_GGX},
        {.mode = TL_MODE_THIN_DEFERRED, .ssao = {.enabled = 1, .method = TL_SSAO_DISC}, .bloom = {.enabled = 1}},
        {.depth_format = TL_DEPTH_FORMAT_D32F_REVERSED, .fog = {.enabled = 1, .mode = TL_FOG_DISTANCE}},
        {.light_strategy = TL_LIGHT_STRATEGY_TILED, .fxaa = TL_FXAA_OFF, .vignette = {.enabled = 1}},
    };
    uint32_t added = 0, programs_after_first_round = 0, rebuilt = 0;
    for (int f = 0; f < FRAMES && res == TL_OK; f++) {
        float t = 0.1f * (float)f;
        res = tl_renderer_set_options(r, &options[f % 6]);
        for (int i = 1; i <= BOXES && res == TL_OK; i++) { /* boxes circling: one record each */
            if (f > 20 && i == 7) continue;                /* removed at frame 20, below */
            float a = t + 6.2832f * (float)i / BOXES, m[16];
            place(m, 4.0f * cosf(a), 0.5f + 0.3f * (float)(i % 3), 4.0f * sinf(a), 2.0f * a, 0.6f + 0.1f * (float)(i % 4));
            res = tl_renderer_set_object_transform(r, (uint32_t)i, m);
        }
        for (int i = 0; i < LIGHTS; i++) { /* 200 lights on a moving ring */
            float a = t * 0.5f + 6.2832f * (float)i / LIGHTS;
            lights[i] = (tl_light){.position = {6.0f * cosf(a), 0.4f + 0.3f * (float)(i % 4), 6.0f * sinf(a)},
                                   .color = {0.02f + 0.02f * (float)(i % 3), 0.02f, 0.01f + 0.01f * (float)(i % 5)},
                                   .radius = 4.0f};
        }
        if (res == TL_OK) res = tl_renderer_set_lights(r, lights, LIGHTS);
        if (res == TL_OK && f % 8 == 4) res = tl_renderer_set_object_visible(r, 3, f % 16 != 4); /* blinking */
        if (res == TL_OK && f == 20) { /* a tall box added (an instance of the same mesh), one removed */
            tl_object tall = {.index_count = 36, .material = 3};
            place(tall.transform, 0, 1.0f, 0, 0.3f, 1);
            tall.transform[5] = 2.0f;
            res = tl_renderer_add_object(r, &tall, &added);
            if (res == TL_OK) res = tl_renderer_remove_object(r, 7);
        }
        if (res == TL_OK && f == 24) res = tl_renderer_resize(r, width = 400, height = 225); /* the window grew */
        /* the engine's own drawing leaves its state behind; the renderer sets what it depends on */
        gl_front_face(0x0900 /* GL_CW */);
        gl_depth_range(0.2, 0.8);
        gl_enable(0x0BF2 /* GL_COLOR_LOGIC_OP */);
        tl_frame_stats stats;
        if (res == TL_OK) res = tl_renderer_render(r, NULL, &stats);
        if (res == TL_OK && (f == 5 || f == FRAMES - 1)) res = tl_renderer_wait(r, &stats); /* this frame's figures */
        if (res == TL_OK && f == 5) programs_after_first_round = stats.programs_compiled;
        if (res == TL_OK && f == FRAMES - 1) rebuilt = stats.programs_compiled - programs_after_first_round;
    }
    size_t size = sizeof rgba;
    if (res == TL_OK) res = tl_renderer_read_output(r, rgba, &size);
    if (res == TL_OK)
        res = tl_image_write(path, &(tl_image_desc){.width = width, .height = height, .channels = 4, .bottom_up = 1,
                                                    .logger = log}, rgba);
    if (res == TL_OK)
        printf("wrote %s (%ux%u) after %d frames (object %u added); programs built after the first round of options: "
               "%u\n", path, width, height, FRAMES, added, rebuilt);
    else fprintf(stderr, "engine_loop: %s: %s\n", tl_result_string(res), error.message);
    tl_renderer_destroy(r);
    tl_context_destroy(ctx);
    return res == TL_OK && rebuilt == 0 ? 0 : 1;
}
