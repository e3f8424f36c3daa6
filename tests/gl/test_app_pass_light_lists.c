/* An application pass that declares TL_TARGET_LIGHT_LISTS as a read gets the tile headers' storage
 * buffer (renderer.h, tl_app_pass_context.textures): the light-cull pass's per-tile counts, which
 * a viewer draws as lights per tile. The headers it reads inside the frame must agree with the
 * counters the renderer reports for that frame. */
#include <stdlib.h>
#include <string.h>

#include "tl_test.h"

#include "gl/gl.h"
#include "thinlight/context.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"

#include "render_fixture.h"

#define BIT(t) TL_TARGET_BIT(t)

typedef struct lists_pass {
    const GladGLContext *gl;
    unsigned calls;
    uint32_t name;     /* what textures[TL_TARGET_LIGHT_LISTS] held */
    int is_buffer;
    GLint64 size;      /* the buffer's size in bytes */
    uint32_t *headers; /* a copy of the headers read inside the pass */
    size_t tiles;
} lists_pass;

static void lists_execute(void *user, const tl_app_pass_context *ctx)
{
    lists_pass *p = (lists_pass *)user;
    const GladGLContext *gl = p->gl;
    p->calls++;
    p->name = ctx->textures[TL_TARGET_LIGHT_LISTS];
    p->is_buffer = p->name && gl->IsBuffer(p->name);
    if (!p->is_buffer) return;
    gl->GetNamedBufferParameteri64v(p->name, GL_BUFFER_SIZE, &p->size);
    size_t bytes = 16 + 8 * p->tiles;
    if ((size_t)p->size < bytes) return;
    gl->MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl->GetNamedBufferSubData(p->name, 0, (GLsizeiptr)bytes, p->headers); /* a test may wait */
}

static GLADapiproc fixture_load(void *user, const char *name)
{
    return (GLADapiproc)tl_context_get_proc_address((tl_context *)user, name);
}

static tl_renderer *make_renderer(tl_light_strategy strategy, tl_render_mode mode, const tl_scene *s)
{
    tl_renderer_desc d = {.mode = mode, .light_strategy = strategy, .width = 160, .height = 96,
                          .get_proc_address = tl_context_proc_loader, .get_proc_address_user = g_ctx,
                          .logger = tl_test_logger};
    tl_renderer *r = NULL;
    TL_CHECK(tl_renderer_create(&d, &r) == TL_OK);
    if (r) TL_CHECK(tl_renderer_set_scene(r, s) == TL_OK);
    return r;
}

/* Tiled, in every mode (Forward+ included): the pass sees a buffer of the documented layout, every
 * count is at most the scene's local lights, and the counts of tiles that kept their lists add up to
 * the entries the frame's statistics report. With light volumes there are no lists: the name is 0. */
TL_TEST(app_pass_reads_tile_light_lists)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    GladGLContext gl;
    char msg[256];
    if (tl__gl_load(&gl, fixture_load, g_ctx, msg, sizeof msg) != TL_OK) {
        fprintf(stderr, "glad: %s\n", msg);
        tl_test_failures++;
        return;
    }
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 48, .detail = 1}, &s) == TL_OK);
    if (!s) return;
    size_t local = 0;
    for (size_t i = 0; i < s->light_count; i++) local += s->lights[i].type != TL_LIGHT_DIRECTIONAL;
    for (int mode = TL_MODE_THIN_LPP; mode < TL_MODE_COUNT_; mode++) {
        tl_renderer *r = make_renderer(TL_LIGHT_STRATEGY_TILED, (tl_render_mode)mode, s);
        if (!r) continue;
        tl_frame_plan plan;
        TL_CHECK(tl_renderer_get_plan(r, &plan) == TL_OK);
        lists_pass p = {.gl = &gl, .tiles = (size_t)plan.tiles_x * plan.tiles_y};
        p.headers = calloc(4 + 2 * p.tiles, sizeof *p.headers);
        tl_app_pass_desc ap = {.name = "lists", .before = "tonemap", .reads = BIT(TL_TARGET_LIGHT_LISTS),
                               .writes = BIT(TL_TARGET_HDR), .execute = lists_execute, .user = &p};
        TL_CHECK(p.headers && p.tiles > 0 && tl_renderer_add_pass(r, &ap) == TL_OK);
        tl_frame_stats st;
        TL_CHECK(tl_renderer_render(r, NULL, &st) == TL_OK); /* with statistics: the counters are read back */
        TL_CHECK(tl_renderer_wait(r, &st) == TL_OK);
        TL_CHECK(p.calls == 1 && p.is_buffer && (size_t)p.size >= 16 + 8 * p.tiles);
        uint64_t sum = 0;
        size_t lit = 0, overflowed = 0, bad = 0;
        for (size_t t = 0; p.is_buffer && t < p.tiles; t++) {
            uint32_t first = p.headers[4 + 2 * t], count = p.headers[4 + 2 * t + 1];
            bad += count > local;
            if (first == 0xFFFFFFFFu) overflowed++;
            else sum += count;
            lit += count > 0;
        }
        printf("%s: %zu tiles, %zu with lights, %zu overflowed, %llu entries (stats %llu)\n",
               tl_render_mode_name((tl_render_mode)mode), p.tiles, lit, overflowed, (unsigned long long)sum,
               (unsigned long long)st.light_list_entries);
        TL_CHECK_EQ_U(bad, 0);
        TL_CHECK(lit > 0);
        TL_CHECK_EQ_U(overflowed, st.tile_overflows);
        if (!overflowed) TL_CHECK_EQ_U(sum, st.light_list_entries);
        TL_CHECK_EQ_U(p.headers[0], st.light_list_entries);
        free(p.headers);
        tl_renderer_destroy(r);
    }
    /* light volumes: the plan has no lists, the read is dropped and the name is 0 */
    tl_renderer *r = make_renderer(TL_LIGHT_STRATEGY_VOLUMES, TL_MODE_THIN_LPP, s);
    if (r) {
        lists_pass p = {.gl = &gl, .name = 1};
        tl_app_pass_desc ap = {.name = "lists", .before = "tonemap", .reads = BIT(TL_TARGET_LIGHT_LISTS),
                               .writes = BIT(TL_TARGET_HDR), .execute = lists_execute, .user = &p};
        TL_CHECK(tl_renderer_add_pass(r, &ap) == TL_OK);
        TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
        TL_CHECK(p.calls == 1 && p.name == 0);
        tl_renderer_destroy(r);
    }
    tl_scene_destroy(s);
}
