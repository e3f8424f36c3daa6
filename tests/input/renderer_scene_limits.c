/* The renderer's limits on what a scene and its lights may hold (docs/renderer-limits.md): counts
 * past 32-bit indices and GL sizes, index values and draw ranges outside the arrays, and more
 * lights than the light buffers hold. The renderer trusts an array to hold its count of elements,
 * not the count to be sane: these scenes have counts that lie about small arrays (or NULL ones),
 * so nothing here allocates gigabytes, and a refusal must come before any array is read (valgrind
 * and ASan would see it) or anything is allocated (a counting allocator). The light-count limit is
 * tested at the GL context's real value (GL_MAX_SHADER_STORAGE_BLOCK_SIZE); the limits of the tile
 * and forward light lists, which need hundreds of MiB at GL's value, with
 * tl_renderer_desc.max_storage_block_bytes lowering the same checks. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_room.h"
#include "tl_test.h"

typedef struct counted {
    size_t calls;
    char line[512];
} counted;

static void *counted_alloc(size_t size, void *user)
{
    ((counted *)user)->calls++;
    return malloc(size);
}

static void counted_free(void *ptr, void *user)
{
    (void)user;
    free(ptr);
}

static void keep_error(void *user, tl_log_level level, const char *message)
{
    if (level == TL_LOG_ERROR) snprintf(((counted *)user)->line, sizeof ((counted *)user)->line, "%s", message);
}

/* A renderer whose allocations `c` counts and whose last error it keeps; NULL when create fails (some
 * cases ask for that). */
static tl_renderer *counted_renderer(tl_renderer_desc d, counted *c)
{
    d.allocator = (tl_allocator){counted_alloc, counted_free, c};
    d.logger = (tl_logger){keep_error, c};
    d.options.synchronous_stats = 1;
    return tl_test_renderer(&(tl_test_renderer_desc){.renderer = d, .may_fail = true});
}

typedef void (*get_integer64_fn)(unsigned, int64_t *);

/* The context's GL_MAX_SHADER_STORAGE_BLOCK_SIZE, as the renderer takes it (at most 4 GiB - 1). */
static size_t gl_storage_block(void)
{
#define TL_GL_MAX_SHADER_STORAGE_BLOCK_SIZE_ 0x90DE
    get_integer64_fn get = (get_integer64_fn)tl_context_proc_loader(g_ctx, "glGetInteger64v");
    int64_t bytes = 0;
    if (get) get(TL_GL_MAX_SHADER_STORAGE_BLOCK_SIZE_, &bytes);
    return bytes > (int64_t)UINT32_MAX ? (size_t)UINT32_MAX : (size_t)bytes;
}

/* set_scene(s) is refused with `want` and a message holding `text`, allocating nothing; the
 * renderer's last error is that message, and its previous scene still renders. */
static void refused(tl_renderer *r, counted *c, const tl_scene *s, tl_result want, const char *text)
{
    size_t before = c->calls;
    c->line[0] = 0;
    tl_result res = tl_renderer_set_scene(r, s);
    if (res != want || !strstr(c->line, text)) fprintf(stderr, "  got %s: '%s' (want '%s')\n", tl_result_string(res), c->line, text);
    TL_CHECK(res == want);
    TL_CHECK(strstr(c->line, text) != NULL);
    TL_CHECK(strcmp(c->line, tl_renderer_last_error(r)) == 0);
    TL_CHECK_EQ_U(c->calls - before, 0);
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
}

TL_TEST(renderer_scene_counts_past_32_bits_refused_before_reading)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    static test_scene t;
    build_room(&t);
    counted c = {0};
    tl_renderer *r = counted_renderer((tl_renderer_desc){.width = 32, .height = 32}, &c);
    TL_CHECK(r != NULL);
    if (!r) return;
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
    tl_scene s = t.s;
    char want[128];
    s.vertex_count = (size_t)UINT32_MAX + 1; /* 64 real vertices */
    refused(r, &c, &s, TL_ERROR_LIMIT, "4294967296 vertices (indices are 32-bit) exceed the limit of 4294967295");
    s.vertex_count = SIZE_MAX / sizeof(tl_vertex) + 1; /* times 48 bytes wraps size_t */
    snprintf(want, sizeof want, "%zu vertices", s.vertex_count);
    refused(r, &c, &s, TL_ERROR_LIMIT, want);
    s = t.s;
    s.index_count = ((size_t)1 << 29) + 3;
    refused(r, &c, &s, TL_ERROR_LIMIT, "536870915 indices (a 2 GiB index buffer) exceed the limit of 536870912");
    s.index_count = SIZE_MAX; /* a multiple of 3; times 4 bytes wraps */
    refused(r, &c, &s, TL_ERROR_LIMIT, "indices (a 2 GiB index buffer)");
    s = t.s;
    s.object_count = (size_t)UINT32_MAX + 1;
    refused(r, &c, &s, TL_ERROR_LIMIT, "4294967296 objects exceed the limit of 4294967295");
    s.object_count = gl_storage_block() / 128 + 1; /* past the per-object storage block: 128 bytes an object */
    refused(r, &c, &s, TL_ERROR_LIMIT, "objects exceed the limit of");
    s = t.s;
    s.material_count = SIZE_MAX;
    refused(r, &c, &s, TL_ERROR_LIMIT, "materials exceed");
    s = t.s;
    s.texture_count = (size_t)UINT32_MAX + 1; /* texture i is map i + 1 in a uint32_t */
    s.textures = (tl_texture *)t.v;
    refused(r, &c, &s, TL_ERROR_LIMIT, "4294967296 textures (materials name texture i as map i + 1, a uint32_t) exceed "
                                       "the limit of 4294967295");
    s = t.s;
    s.light_count = SIZE_MAX;
    refused(r, &c, &s, TL_ERROR_LIMIT, "lights exceed the limit of");
    /* counts without arrays */
    s = t.s;
    s.vertices = NULL;
    refused(r, &c, &s, TL_ERROR_INVALID_ARGUMENT, "vertices but no array");
    s = t.s;
    s.objects = NULL;
    refused(r, &c, &s, TL_ERROR_INVALID_ARGUMENT, "2 objects but no array");
    s = t.s;
    s.index_count = t.s.index_count - 1; /* objects are checked against it (whole elements: per object) */
    refused(r, &c, &s, TL_ERROR_INVALID_ARGUMENT, "objects[1].first_index + index_count = ");
    tl_renderer_destroy(r);
}

TL_TEST(renderer_scene_indices_and_draw_ranges_outside_the_arrays_refused)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    static test_scene t;
    build_room(&t);
    counted c = {0};
    tl_renderer *r = counted_renderer((tl_renderer_desc){.width = 32, .height = 32}, &c);
    TL_CHECK(r != NULL);
    if (!r) return;
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
    char want[128];
    /* an index value equal to the vertex count, and the largest one */
    uint32_t keep = t.idx[5];
    t.idx[5] = (uint32_t)t.s.vertex_count;
    snprintf(want, sizeof want, "indices[5] = %zu: past the scene's %zu vertices (0..%zu)", t.s.vertex_count,
             t.s.vertex_count, t.s.vertex_count - 1);
    refused(r, &c, &t.s, TL_ERROR_INVALID_ARGUMENT, want);
    t.idx[5] = UINT32_MAX;
    refused(r, &c, &t.s, TL_ERROR_INVALID_ARGUMENT, "indices[5] = 4294967295: past the scene's");
    t.idx[5] = keep;
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
    /* draw ranges: past the end, one whose end wraps 32 bits, a material past the array */
    tl_object o = t.obj[1];
    t.obj[1].first_index = (uint32_t)t.s.index_count - 3;
    t.obj[1].index_count = 6;
    snprintf(want, sizeof want, "objects[1].first_index + index_count = %zu + 6 = %zu: past the scene's %zu indices",
             t.s.index_count - 3, t.s.index_count + 3, t.s.index_count);
    refused(r, &c, &t.s, TL_ERROR_INVALID_ARGUMENT, want);
    t.obj[1].first_index = UINT32_MAX - 2;
    t.obj[1].index_count = 6; /* first + count wraps to 3 in 32 bits */
    refused(r, &c, &t.s, TL_ERROR_INVALID_ARGUMENT, "objects[1].first_index + index_count = 4294967293 + 6 = 4294967299: past");
    t.obj[1] = o;
    t.obj[1].material = 2;
    refused(r, &c, &t.s, TL_ERROR_INVALID_ARGUMENT, "objects[1].material = 2: past the scene's 2 materials");
    t.obj[1] = o;
    t.obj[1].index_count -= 1;
    snprintf(want, sizeof want, "objects[1].index_count = %u: not whole triangles (a multiple of 3)", t.obj[1].index_count);
    refused(r, &c, &t.s, TL_ERROR_INVALID_ARGUMENT, want);
    t.obj[1] = o;
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK);
    tl_renderer_destroy(r);
}

/* ---- lights ------------------------------------------------------------------------------------ */

/* The renderer's light limit from the context's own GL_MAX_SHADER_STORAGE_BLOCK_SIZE. */
static size_t gl_light_limit(void)
{
    size_t lights = gl_storage_block() / 64u;
    return lights < TL_RENDERER_MAX_LIGHTS ? lights : TL_RENDERER_MAX_LIGHTS;
}

/* n tiny point lights in the view of the room's camera, in mid-air: each is in the frustum (so
 * every light reaches the light buffers and the cull), none lights a surface. */
static tl_light *air_lights(size_t n)
{
    tl_light *l = (tl_light *)calloc(n ? n : 1, sizeof *l);
    for (size_t i = 0; l && i < n; i++)
        l[i] = (tl_light){.type = TL_LIGHT_POINT,
                          .position = {-0.5f + (float)(i % 1024) / 1024.0f, 2.5f + (float)(i / 1024 % 1024) / 2048.0f, 5},
                          .direction = {0, -1, 0}, .color = {1, 1, 1}, .radius = 1e-3f};
    return l;
}

TL_TEST(renderer_lights_at_the_gl_limit_taken_one_past_refused)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    size_t limit = gl_light_limit();
    printf("  light limit: %zu (GL_MAX_SHADER_STORAGE_BLOCK_SIZE / 64, at most %u)\n", limit, TL_RENDERER_MAX_LIGHTS);
    TL_CHECK(limit >= 262144); /* GL's minimum storage block, 16 MiB */
    static test_scene t;
    build_room(&t);
    tl_light *lights = air_lights(limit + 1);
    TL_CHECK(lights != NULL);
    if (!lights) return;
    counted c = {0};
    tl_renderer *r = counted_renderer((tl_renderer_desc){.width = 16, .height = 16,
                                                          .options.light_strategy = TL_LIGHT_STRATEGY_TILED}, &c);
    TL_CHECK(r != NULL);
    if (r) {
        t.s.light_count = 0;
        TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
        /* at the limit: stored, culled into 64 chunks, drawn */
        TL_CHECK(tl_renderer_set_lights(r, lights, limit) == TL_OK);
        tl_frame_stats st;
        TL_CHECK(tl_renderer_render(r, NULL, &st) == TL_OK);
        TL_CHECK_EQ_U(st.lights_drawn[TL_LIGHT_POINT], limit);
        /* one past: refused before the array is read or anything allocated; the lights stay */
        size_t before = c.calls;
        TL_CHECK(tl_renderer_set_lights(r, lights, limit + 1) == TL_ERROR_LIMIT);
        TL_CHECK_EQ_U(c.calls - before, 0);
        char want[96];
        snprintf(want, sizeof want, "%zu lights exceed the limit of %zu", limit + 1, limit);
        TL_CHECK(strstr(c.line, want) != NULL && strcmp(c.line, tl_renderer_last_error(r)) == 0);
        TL_CHECK(tl_renderer_render(r, NULL, &st) == TL_OK);
        TL_CHECK_EQ_U(st.lights_drawn[TL_LIGHT_POINT], limit);
        /* the same through a scene */
        t.s.lights = lights;
        t.s.light_count = limit + 1;
        TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_ERROR_LIMIT && strstr(c.line, want) != NULL);
        tl_renderer_destroy(r);
    }
    free(lights);
}

/* A renderer whose storage blocks hold `bytes` (0: GL's), on the lit room. */
static tl_renderer *block_renderer(tl_renderer_desc d, size_t bytes, counted *c)
{
    d.max_storage_block_bytes = bytes;
    d.options.keep_targets = TL_TARGETS_ALL;
    return counted_renderer(d, c);
}

TL_TEST(renderer_storage_block_lowered_limits_lights_and_tile_headers)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    static test_scene t;
    build_room(&t);
    t.lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {0, 5, 0}, .direction = {0, -1, 0},
                             .color = {4, 4, 4}, .radius = 12};
    t.s.light_count = 1;
    counted c = {0};
    /* 100 lights of 64 bytes */
    tl_renderer *r = block_renderer((tl_renderer_desc){.width = 32, .height = 32}, 6400, &c);
    TL_CHECK(r != NULL);
    if (!r) return;
    tl_light *lights = air_lights(101);
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
    TL_CHECK(tl_renderer_set_lights(r, lights, 100) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_set_lights(r, lights, 101) == TL_ERROR_LIMIT);
    TL_CHECK(strstr(c.line, "101 lights exceed the limit of 100 (TL_RENDERER_MAX_LIGHTS, or a storage block of 6400 bytes") != NULL);
    tl_renderer_destroy(r);
    free(lights);
    /* the tile headers: 16 bytes of counters and 8 a tile; exactly that fits, a byte less does not */
    tl_renderer_desc d = {.width = 320, .height = 240, .options.light_strategy = TL_LIGHT_STRATEGY_TILED};
    r = block_renderer(d, 0, &c);
    TL_CHECK(r != NULL && tl_renderer_set_scene(r, &t.s) == TL_OK);
    tl_frame_plan p = {0};
    if (r) tl_renderer_get_plan(r, &p);
    tl_renderer_destroy(r);
    size_t tiles = (size_t)p.tiles_x * p.tiles_y, need = 16 + 8 * tiles;
    TL_CHECK(tiles > 8);
    r = block_renderer(d, need, &c);
    TL_CHECK(r != NULL && tl_renderer_set_scene(r, &t.s) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK);
    tl_renderer_destroy(r);
    r = block_renderer(d, need - 1, &c);
    TL_CHECK(r != NULL);
    if (!r) return;
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_ERROR_LIMIT);
    char want[160];
    snprintf(want, sizeof want, "tiled light lists of %ux%u tiles for 1 chunks of 16384 lights need %zu bytes, over the "
             "storage block of %zu bytes", p.tiles_x, p.tiles_y, need, need - 1);
    TL_CHECK(strstr(c.line, want) != NULL);
    tl_renderer_destroy(r);
}

/* HDR of one frame of the lit room (4 lights), or NULL. */
static float *room_hdr(tl_renderer *r, const tl_scene *s, tl_frame_stats *st)
{
    size_t size = 0;
    if (tl_renderer_set_scene(r, s) != TL_OK || tl_renderer_render(r, NULL, st) != TL_OK ||
        tl_renderer_read_target(r, TL_TARGET_HDR, NULL, &size) != TL_OK)
        return NULL;
    float *px = (float *)malloc(size);
    if (px && tl_renderer_read_target(r, TL_TARGET_HDR, px, &size) == TL_OK) return px;
    free(px);
    return NULL;
}

TL_TEST(renderer_tile_entries_clamped_to_the_storage_block_lose_no_light)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    static test_scene t;
    build_room(&t);
    for (int i = 0; i < 4; i++)
        t.lights[i] = (tl_light){.type = TL_LIGHT_POINT, .position = {-6.0f + 4.0f * (float)i, 4, -2},
                                 .direction = {0, -1, 0}, .color = {3, 2, 1}, .radius = 9};
    t.s.light_count = 4;
    tl_renderer_desc d = {.width = 96, .height = 64, .options.light_strategy = TL_LIGHT_STRATEGY_TILED};
    counted c = {0};
    tl_renderer *full = block_renderer(d, 0, &c), *small = NULL;
    tl_frame_stats a = {0}, b = {0};
    float *want = full ? room_hdr(full, &t.s, &a) : NULL;
    /* a block of 256 bytes: the 4 lights, the headers of 6x4 tiles (208 bytes), 64 entries */
    small = block_renderer(d, 256, &c);
    float *got = small ? room_hdr(small, &t.s, &b) : NULL;
    TL_CHECK(want != NULL && got != NULL);
    printf("  entries: %llu in full lists; clamped: %u of 24 tiles overflowed\n",
           (unsigned long long)a.light_list_entries, b.tile_overflows);
    TL_CHECK(a.light_list_entries > 64 && a.tile_overflows == 0); /* the full lists do not fit in 64 */
    TL_CHECK(b.tile_overflows > 0);
    double worst = 0.0;
    for (size_t i = 0; want && got && i < (size_t)96 * 64 * 4; i++) {
        double e = fabs((double)want[i] - got[i]) / (fabs((double)want[i]) + 1e-3);
        worst = e > worst ? e : worst;
    }
    printf("  largest relative difference, clamped lists vs full: %.3g\n", worst);
    TL_CHECK(worst <= 1e-3); /* the same lights, summed in the same order: FP16 rounding at most */
    /* a later frame does not grow the entries past the block */
    TL_CHECK(small && tl_renderer_render(small, NULL, &b) == TL_OK && b.tile_overflows > 0);
    free(want);
    free(got);
    tl_renderer_destroy(full);
    tl_renderer_destroy(small);
}

TL_TEST(renderer_forward_light_lists_over_the_storage_block_refused)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    static test_scene t;
    build_room(&t);
    /* a block of 17 objects of 128 bytes: 544 list entries, 34 lights; 17 objects that all draw the
     * box, every light reaching all of them: 32 lights make 544 entries, 33 make 561 */
    static tl_object objs[17];
    for (int i = 0; i < 17; i++) objs[i] = t.obj[1];
    t.s.objects = objs;
    t.s.object_count = 17;
    static tl_light lights[33];
    for (int i = 0; i < 33; i++) lights[i] = (tl_light){.type = TL_LIGHT_POINT, .position = {0, 5, 0},
                                                        .direction = {0, -1, 0}, .color = {0.1f, 0.1f, 0.1f},
                                                        .radius = 40};
    t.s.lights = lights;
    t.s.light_count = 32;
    counted c = {0};
    tl_renderer_desc d = {.width = 32, .height = 32, .options.mode = TL_MODE_FORWARD,
                          .options.light_strategy = TL_LIGHT_STRATEGY_VOLUMES};
    tl_renderer *r = block_renderer(d, 17 * 128, &c);
    TL_CHECK(r != NULL);
    if (!r) return;
    tl_frame_stats st;
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK && tl_renderer_render(r, NULL, &st) == TL_OK);
    TL_CHECK_EQ_U(st.forward_light_pairs, 544);
    TL_CHECK(tl_renderer_set_lights(r, lights, 33) == TL_OK);
    TL_CHECK(tl_renderer_render(r, NULL, &st) == TL_ERROR_LIMIT);
    TL_CHECK(strstr(c.line, "forward light lists need more than 544 entries (17 objects, 33 visible lights), over the "
                            "storage block of 2176 bytes") != NULL);
    TL_CHECK(tl_renderer_set_lights(r, lights, 32) == TL_OK && tl_renderer_render(r, NULL, &st) == TL_OK);
    /* one object more than the block holds is refused by set_scene */
    static tl_object more[18];
    for (int i = 0; i < 18; i++) more[i] = t.obj[1];
    t.s.objects = more;
    t.s.object_count = 18;
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_ERROR_LIMIT);
    TL_CHECK(strstr(c.line, "18 objects exceed the limit of 17 (a storage block of 2176 bytes at 128 bytes an object)") != NULL);
    tl_renderer_destroy(r);
}

TL_TEST(renderer_light_fields_and_negative_sizes_refused)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    static test_scene t;
    build_room(&t);
    counted c = {0};
    /* a negative size passed as uint32_t is 2^32 - n: over the limit, named */
    tl_renderer_desc d = {.width = (uint32_t)-1, .height = 32};
    TL_CHECK(counted_renderer(d, &c) == NULL && strstr(c.line, "4294967295x32") != NULL);
    tl_renderer *r = counted_renderer((tl_renderer_desc){.width = 32, .height = 32}, &c);
    TL_CHECK(r != NULL);
    if (!r) return;
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
    TL_CHECK(tl_renderer_resize(r, (uint32_t)-8, 32) == TL_ERROR_LIMIT && strstr(c.line, "4294967288x32") != NULL);
    /* each bad field of a light, alone: refused naming the light; the renderer keeps its lights */
    const tl_light good = {.type = TL_LIGHT_SPOT, .position = {0, 5, 0}, .direction = {0, -1, 0},
                           .color = {4, 4, 4}, .radius = 12, .cos_inner = 0.9f, .cos_outer = 0.8f,
                           .source_radius = 0.1f};
    tl_light bad[8];
    for (int i = 0; i < 8; i++) bad[i] = good;
    bad[0].radius = -1.0f;
    bad[1].radius = INFINITY;
    bad[2].radius = NAN;
    bad[3].color[1] = INFINITY;
    bad[4].direction[2] = NAN;
    bad[5].source_radius = -0.5f;
    bad[6].type = TL_LIGHT_TYPE_COUNT_;
    bad[7].position[0] = -INFINITY;
    static const char *const field[8] = {"lights[1].radius = -1", "lights[1].radius = inf", "lights[1].radius = nan",
                                         "lights[1].color = (4, inf, 4)", "lights[1].direction = (0, -1, nan)",
                                         "lights[1].source_radius = -0.5", "lights[1].type = 4",
                                         "lights[1].position = (-inf, 5, 0)"};
    tl_light two[2] = {good, good};
    for (int i = 0; i < 8; i++) {
        two[1] = bad[i];
        TL_CHECK(tl_renderer_set_lights(r, two, 2) == TL_ERROR_INVALID_ARGUMENT);
        if (!strstr(c.line, field[i])) fprintf(stderr, "  \"%s\", want \"%s\"\n", c.line, field[i]);
        TL_CHECK(strstr(c.line, field[i]) != NULL); /* the field named (scene/validate.h) */
    }
    TL_CHECK(tl_renderer_set_lights(r, two, 0) == TL_OK && tl_renderer_set_lights(r, NULL, 0) == TL_OK);
    TL_CHECK(tl_renderer_set_lights(r, NULL, 3) == TL_ERROR_INVALID_ARGUMENT && strstr(c.line, "3 lights but no array"));
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    tl_renderer_destroy(r);
}
