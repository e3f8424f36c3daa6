/* Renderer limits (docs/renderer-limits.md): the caller's target-memory budget, zero sizes, and an
 * allocator that fails at every k-th call during create, set_scene and render. Each is a result
 * code and one line, never a crash or a leak; targets over GL_MAX_TEXTURE_SIZE are
 * stability_largest_target's (tests/gl). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_room.h"
#include "tl_test.h"

typedef struct last_line {
    char text[512];
    int errors;
} last_line;

static void keep_line(void *user, tl_log_level level, const char *message)
{
    last_line *l = user;
    if (level != TL_LOG_ERROR) return;
    l->errors++;
    snprintf(l->text, sizeof l->text, "%s", message);
}

static tl_renderer_desc room_desc(uint32_t w, uint32_t h, last_line *log)
{
    return (tl_renderer_desc){.width = w, .height = h, .get_proc_address = tl_context_proc_loader,
                              .get_proc_address_user = g_ctx, .logger = {keep_line, log}};
}

/* Bytes of the targets the plan allocates: what max_target_bytes is compared with. */
static size_t plan_bytes(const tl_renderer *r)
{
    tl_frame_plan p;
    if (tl_renderer_get_plan(r, &p) != TL_OK) return 0;
    return (size_t)p.allocated_bytes_per_pixel * p.width * p.height;
}

/* The room with one point light: its plan needs a light buffer that the empty scene's does not. */
static void lit_room(test_scene *t)
{
    build_room(t);
    t->lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {0, 5, 0}, .direction = {0, -1, 0},
                              .color = {4, 4, 4}, .radius = 12};
    t->s.lights = t->lights;
    t->s.light_count = 1;
}

TL_TEST(renderer_target_budget_refused_naming_the_size)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    static test_scene t;
    lit_room(&t);
    last_line log = {0};
    /* the need, from an unbudgeted renderer of the same size and scene */
    tl_renderer *r = NULL;
    tl_renderer_desc d = room_desc(96, 64, &log);
    TL_CHECK(tl_renderer_create(&d, &r) == TL_OK && tl_renderer_set_scene(r, &t.s) == TL_OK);
    size_t need = r ? plan_bytes(r) : 0;
    tl_renderer_destroy(r);
    TL_CHECK(need > (size_t)96 * 64 * 8); /* a G-buffer and more */
    /* one byte short: create (the empty scene's plan needs less) works, set_scene is refused */
    d.max_target_bytes = need - 1;
    r = NULL;
    TL_CHECK(tl_renderer_create(&d, &r) == TL_OK);

    if (!r) return;
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_ERROR_LIMIT);
    char want[128];
    snprintf(want, sizeof want, "need %zu bytes", need);
    TL_CHECK(strstr(log.text, want) != NULL && strstr(log.text, "96x64") != NULL);
    snprintf(want, sizeof want, "over max_target_bytes %zu", need - 1);
    TL_CHECK(strstr(log.text, want) != NULL && strcmp(log.text, tl_renderer_last_error(r)) == 0);
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_ERROR_INVALID_ARGUMENT); /* no scene */
    tl_renderer_destroy(r);
    /* exactly the need: everything works; growing past it is refused and keeps the old size */
    d.max_target_bytes = need;
    r = NULL;
    TL_CHECK(tl_renderer_create(&d, &r) == TL_OK);
    if (!r) return;
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_resize(r, 97, 64) == TL_ERROR_LIMIT && strstr(log.text, "97x64") != NULL);
    uint32_t w = 0, h = 0;
    tl_renderer_get_size(r, &w, &h);
    TL_CHECK(w == 96 && h == 64 && plan_bytes(r) == need);
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_resize(r, 48, 32) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK);
    tl_renderer_destroy(r);
    /* a budget below even the empty plan: create fails, through the logger only */
    d.max_target_bytes = 1000;
    r = NULL;
    log.errors = 0;
    TL_CHECK(tl_renderer_create(&d, &r) == TL_ERROR_LIMIT && r == NULL && log.errors == 1);
    TL_CHECK(strstr(log.text, "over max_target_bytes 1000") != NULL);
}

TL_TEST(renderer_zero_sizes_default_or_refused)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    last_line log = {0};
    /* in a descriptor zero means the default, 1280x720, side by side */
    tl_renderer_desc d = room_desc(0, 0, &log);
    tl_renderer *r = NULL;
    TL_CHECK(tl_renderer_create(&d, &r) == TL_OK);
    uint32_t w = 0, h = 0;
    tl_renderer_get_size(r, &w, &h);
    TL_CHECK(w == 1280 && h == 720);
    tl_renderer_destroy(r);
    d = room_desc(0, 40, &log);
    r = NULL;
    TL_CHECK(tl_renderer_create(&d, &r) == TL_OK);
    tl_renderer_get_size(r, &w, &h);
    TL_CHECK(w == 1280 && h == 40);
    /* resizing to nothing is an argument error that changes nothing */
    TL_CHECK(tl_renderer_resize(r, 0, 40) == TL_ERROR_INVALID_ARGUMENT && strstr(log.text, "0x40") != NULL);
    TL_CHECK(tl_renderer_resize(r, 64, 0) == TL_ERROR_INVALID_ARGUMENT && strstr(log.text, "64x0") != NULL);
    TL_CHECK(tl_renderer_resize(r, 0, 0) == TL_ERROR_INVALID_ARGUMENT);
    tl_renderer_get_size(r, &w, &h);
    TL_CHECK(w == 1280 && h == 40);
    static test_scene t;
    build_room(&t);
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK);
    tl_renderer_destroy(r);
}

/* ---- an allocator failing at every k-th call --------------------------------------------------- */

typedef struct failing {
    size_t calls, fail_at;
    long live;
} failing;

static void *failing_alloc(size_t size, void *user)
{
    failing *f = user;
    if (++f->calls == f->fail_at) return NULL;
    void *p = malloc(size);
    if (p) f->live++;
    return p;
}

static void failing_free(void *ptr, void *user)
{
    failing *f = user;
    if (ptr) f->live--;
    free(ptr);
}

/* create + set_scene + render + destroy with allocation fail_at failing (0: none). Returns the
 * step that failed (0: none), checking that it failed as out of memory and that nothing leaked. */
static int run_failing(const tl_renderer_desc *base, const tl_scene *s, failing *f)
{
    last_line log = {0};
    tl_renderer_desc d = *base;
    d.allocator = (tl_allocator){failing_alloc, failing_free, f};
    d.logger = (tl_logger){keep_line, &log};
    d.get_proc_address = tl_context_proc_loader;
    d.get_proc_address_user = g_ctx;
    tl_renderer *r = NULL;
    tl_result res = tl_renderer_create(&d, &r);
    int step = res != TL_OK ? 1 : 0;
    if (!step && (res = tl_renderer_set_scene(r, s)) != TL_OK) step = 2;
    if (!step && (res = tl_renderer_render(r, NULL, NULL)) != TL_OK) step = 3;
    if (step == 1) TL_CHECK(r == NULL);
    tl_renderer_destroy(r);
    if (step && res != TL_ERROR_OUT_OF_MEMORY)
        fprintf(stderr, "  fail_at %zu: step %d gave %s (%s)\n", f->fail_at, step, tl_result_string(res), log.text);
    TL_CHECK(!step || res == TL_ERROR_OUT_OF_MEMORY);
    TL_CHECK(!step || log.errors >= 1);
    TL_CHECK(f->live == 0);
    return step;
}

TL_TEST(renderer_allocator_fails_at_every_call)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    static test_scene t;
    const tl_renderer_desc descs[3] = {
        {.width = 48, .height = 32},
        {.width = 48, .height = 32, .options.light_strategy = TL_LIGHT_STRATEGY_TILED},
        {.width = 48, .height = 32, .options.mode = TL_MODE_FORWARD},
    };
    lit_room(&t);
    for (int c = 0; c < 3; c++) {
        failing f = {0};
        TL_CHECK(run_failing(&descs[c], &t.s, &f) == 0);
        size_t total = f.calls;
        TL_CHECK(total >= 3);
        printf("  configuration %d: %zu allocations in create + set_scene + render\n", c, total);
        int steps_seen = 0;
        for (size_t k = 1; k <= total; k++) {
            failing fk = {.fail_at = k};
            int step = run_failing(&descs[c], &t.s, &fk);
            TL_CHECK(step != 0); /* the k-th call is inside the sequence, and its failure is reported */
            steps_seen |= 1 << step;
        }
        TL_CHECK(steps_seen & (1 << 1) && steps_seen & (1 << 2)); /* create and set_scene both allocate */
    }
}
