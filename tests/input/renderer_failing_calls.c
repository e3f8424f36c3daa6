/* An allocator that fails at every k-th call (k = 1 .. 8) through a renderer's whole life: create,
 * set_scene, frames, set_lights, resize. Every call either works or answers
 * TL_ERROR_OUT_OF_MEMORY with one error line (or, after a refused set_scene, that there is no
 * scene); nothing leaks; and once allocations succeed again the same renderer draws. The
 * failure at each single call of create + set_scene + render is renderer_limits.c's. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_room.h"
#include "tl_test.h"

typedef struct periodic {
    size_t calls, period, failures;
    long live;
    int on;
    int errors;
} periodic;

static void *periodic_alloc(size_t size, void *user)
{
    periodic *p = user;
    if (p->on && ++p->calls % p->period == 0) {
        p->failures++;
        return NULL;
    }
    void *m = malloc(size);
    if (m) p->live++;
    return m;
}

static void periodic_free(void *ptr, void *user)
{
    periodic *p = user;
    if (ptr) p->live--;
    free(ptr);
}

static void count_errors(void *user, tl_log_level level, const char *message)
{
    (void)message;
    if (level == TL_LOG_ERROR) ((periodic *)user)->errors++;
}

/* A call under failing allocations: TL_OK, or out of memory with its error line (or no scene). */
static int survived(periodic *p, tl_result res, int scene_may_be_gone)
{
    int errors = p->errors;
    p->errors = 0;
    if (res == TL_OK) return 1;
    int ok = (res == TL_ERROR_OUT_OF_MEMORY || (scene_may_be_gone && res == TL_ERROR_INVALID_ARGUMENT)) && errors >= 1;
    if (!ok) fprintf(stderr, "  period %zu: %s with %d error lines\n", p->period, tl_result_string(res), errors);
    TL_CHECK(ok);
    return 0;
}

static void life(const tl_renderer_desc *base, const tl_scene *s, size_t period)
{
    periodic p = {.period = period};
    tl_renderer_desc d = *base;
    d.allocator = (tl_allocator){periodic_alloc, periodic_free, &p};
    d.logger = (tl_logger){count_errors, &p};
    /* failures start after create (renderer_limits.c fails it) */
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = d});
    if (!r) return;
    p.errors = 0;
    p.on = 1;
    tl_light lights[3];
    memcpy(lights, s->lights, sizeof lights);
    lights[2] = lights[0];
    lights[2].position[0] = 3.0f;
    survived(&p, tl_renderer_set_scene(r, s), 0);
    survived(&p, tl_renderer_render(r, NULL, NULL), 1);
    survived(&p, tl_renderer_set_lights(r, lights, 3), 0);
    survived(&p, tl_renderer_render(r, NULL, NULL), 1);
    survived(&p, tl_renderer_resize(r, 40, 24), 0);
    survived(&p, tl_renderer_render(r, NULL, NULL), 1);
    survived(&p, tl_renderer_set_lights(r, lights, 1), 0);
    survived(&p, tl_renderer_render(r, NULL, NULL), 1);
    TL_CHECK(p.failures >= 1);
    p.on = 0;
    /* allocations work again: the same renderer takes the scene and draws */
    TL_CHECK(tl_renderer_set_scene(r, s) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_resize(r, 48, 32) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK);
    tl_renderer_destroy(r);
    TL_CHECK(p.live == 0);
}

TL_TEST(renderer_allocator_failing_every_kth_call_through_its_life)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    static test_scene t;
    build_room(&t);
    t.lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {0, 5, 0}, .direction = {0, -1, 0},
                             .color = {4, 4, 4}, .radius = 12};
    t.lights[1] = (tl_light){.type = TL_LIGHT_SPOT, .position = {2, 6, 2}, .direction = {0, -1, 0},
                             .color = {3, 3, 3}, .radius = 10, .cos_inner = 0.9f, .cos_outer = 0.8f};
    t.s.light_count = 2;
    const tl_renderer_desc descs[3] = {
        {.width = 48, .height = 32},
        {.width = 48, .height = 32, .options.light_strategy = TL_LIGHT_STRATEGY_TILED},
        {.width = 48, .height = 32, .options.mode = TL_MODE_FORWARD,
         .options.light_strategy = TL_LIGHT_STRATEGY_VOLUMES},
    };
    for (int c = 0; c < 3; c++)
        for (size_t k = 1; k <= 8; k++) life(&descs[c], &t.s, k);
}
