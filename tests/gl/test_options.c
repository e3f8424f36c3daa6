/* Options at run time (tl_renderer_set_options): one renderer that changes its mode, light
 * strategy, depth format, lighting model, each effect and FXAA every frame renders the same bytes
 * as a renderer created with those options; a change re-uses what the renderer has (the scene, its
 * textures, programs built before, the application passes); and, printed rather than timed, what a
 * change costs the CPU against re-creating the renderer. */
#define _POSIX_C_SOURCE 199309L
#include "tl_test.h"

#include <time.h>

#include "gl/gl.h"
#include "gl_counter.h"
#include "render_fixture.h"
#include "thinlight/context.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"

/* ---- the scene, renderers, an application pass ------------------------------------------------- */

static tl_scene *crypt(uint32_t lights)
{
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = lights, .detail = 1}, &s) == TL_OK);
    return s;
}

static GladGLContext g_gl; /* the test's own entry points, for the application pass */

static GLADapiproc fixture_load(void *user, const char *name)
{
    return (GLADapiproc)tl_context_get_proc_address((tl_context *)user, name);
}

static int load_gl(void)
{
    char msg[256];
    if (g_gl.Scissor) return 1;
    if (tl__gl_load(&g_gl, fixture_load, g_ctx, msg, sizeof msg) == TL_OK) return 1;
    fprintf(stderr, "glad: %s\n", msg);
    tl_test_failures++;
    return 0;
}

/* Paints a square of HDR: an application pass that must survive every change of options. */
static void square_execute(void *user, const tl_app_pass_context *ctx)
{
    (void)user;
    g_gl.Enable(GL_SCISSOR_TEST);
    g_gl.Scissor(4, 4, 8, 8);
    g_gl.ClearColor(0.5f, 2.0f, 0.25f, 1.0f);
    g_gl.Clear(GL_COLOR_BUFFER_BIT);
    g_gl.Disable(GL_SCISSOR_TEST);
    (void)ctx;
}

static const tl_app_pass_desc k_square = {.name = "square", .after = "transparent", .writes = TL_TARGET_BIT(TL_TARGET_HDR),
                                          .execute = square_execute};

/* Every renderer here counts GL calls (gl_counter.h) and carries the square. */
static tl_renderer *renderer(const tl_renderer_options *o, uint32_t w, uint32_t h, const tl_scene *s)
{
    return tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = w, .height = h, .options = *o, .get_proc_address = tl_test_gl_counting_loader},
        .scene = s, .passes = &k_square, .pass_count = 1});
}

/* ---- the options a frame may change ------------------------------------------------------------ */

typedef struct option_case {
    const char *name;
    tl_renderer_options o;
} option_case;

#define SSAO_ON {.enabled = 1, .method = TL_SSAO_DISC}
static const option_case k_cases[] = {
    {"defaults", {0}},
    {"forward", {.mode = TL_MODE_FORWARD}},
    {"fat tiled", {.mode = TL_MODE_FAT, .light_strategy = TL_LIGHT_STRATEGY_TILED}},
    {"thin-deferred volumes", {.mode = TL_MODE_THIN_DEFERRED, .light_strategy = TL_LIGHT_STRATEGY_VOLUMES}},
    {"thin-lpp tiled", {.light_strategy = TL_LIGHT_STRATEGY_TILED}},
    {"reversed z", {.depth_format = TL_DEPTH_FORMAT_D32F_REVERSED}},
    {"forward+ reversed z", {.mode = TL_MODE_FORWARD, .light_strategy = TL_LIGHT_STRATEGY_TILED,
                             .depth_format = TL_DEPTH_FORMAT_D32F_REVERSED}},
    {"d32f", {.depth_format = TL_DEPTH_FORMAT_D32F}},
    {"ggx", {.lighting = TL_LIGHTING_GGX}},
    {"ggx n.v, compact", {.lighting = TL_LIGHTING_GGX, .fresnel = TL_FRESNEL_NV, .light_buffer = TL_LIGHT_BUFFER_COMPACT}},
    {"fat ggx", {.mode = TL_MODE_FAT, .lighting = TL_LIGHTING_GGX}},
    {"rgb10a2, r11g11b10f, tiles of 8, compute", {.rt0 = TL_RT0_RGB10A2, .light_format = TL_LIGHT_FORMAT_R11G11B10F,
                                                  .light_strategy = TL_LIGHT_STRATEGY_TILED, .tile_size = 8,
                                                  .tiled_shading = TL_TILED_SHADING_COMPUTE}},
    {"ssao", {.ssao = SSAO_ON}},
    {"ssao hemisphere, forward", {.mode = TL_MODE_FORWARD, .ssao = {.enabled = 1, .method = TL_SSAO_HEMISPHERE, .diffuse = 1}}},
    {"fog", {.fog = {.enabled = 1, .mode = TL_FOG_DISTANCE, .color = {0.1f, 0.1f, 0.12f}}}},
    {"height fog, fat", {.mode = TL_MODE_FAT, .fog = {.enabled = 1, .mode = TL_FOG_HEIGHT, .density = 0.2f}}},
    {"depth of field", {.dof = {.enabled = 1, .aperture = 0.02f}}},
    {"bloom", {.bloom = {.enabled = 1, .threshold = 0.2f}}},
    {"bloom, 3 levels", {.bloom = {.enabled = 1, .threshold = 0.2f, .levels = 3}}},
    {"reflections", {.ssr = {.enabled = 1}}},
    {"reflections, thin-deferred", {.mode = TL_MODE_THIN_DEFERRED, .ssr = {.enabled = 1}}},
    {"vignette", {.vignette = {.enabled = 1, .strength = 0.7f}}},
    {"fxaa off", {.fxaa = TL_FXAA_OFF}},
    {"fxaa 12", {.fxaa = TL_FXAA_12, .fxaa_subpix = -1}},
    {"fxaa 39, exposure 2", {.fxaa = TL_FXAA_39, .exposure = 2.0f}},
    {"ambient off, full-screen lights", {.ambient = {-1, -1, -1}, .fullscreen_lights = 1}},
    {"forward without pre-pass", {.mode = TL_MODE_FORWARD, .forward_depth_prepass = TL_SWITCH_OFF}},
    {"visibility", {.mode = TL_MODE_VISIBILITY}},
    {"visibility, ssao, reflections, reversed z", {.mode = TL_MODE_VISIBILITY, .depth_format = TL_DEPTH_FORMAT_D32F_REVERSED,
                                                   .ssao = SSAO_ON, .ssr = {.enabled = 1}}},
    {"every effect", {.ssao = SSAO_ON, .fog = {.enabled = 1, .mode = TL_FOG_DISTANCE}, .dof = {.enabled = 1}, .bloom = {.enabled = 1},
                      .ssr = {.enabled = 1}, .vignette = {.enabled = 1}, .fxaa = TL_FXAA_OFF}},
    {"every effect, fat, reversed z", {.mode = TL_MODE_FAT, .depth_format = TL_DEPTH_FORMAT_D32F_REVERSED,
                                       .ssao = SSAO_ON, .fog = {.enabled = 1, .mode = TL_FOG_DISTANCE}, .dof = {.enabled = 1},
                                       .bloom = {.enabled = 1}, .ssr = {.enabled = 1}}},
    {"no planning", {.planning = TL_SWITCH_OFF}},
    {"defaults again", {0}},
};
#define CASES (sizeof k_cases / sizeof k_cases[0])

static int render_read(tl_renderer *r, uint8_t *out, size_t n)
{
    size_t size = n;
    return tl_renderer_render(r, NULL, NULL) == TL_OK && tl_renderer_read_output(r, out, &size) == TL_OK;
}

/* One renderer through every case, each once per frame, in order and then in another order; each
 * frame against a renderer created with that case's options. */
TL_TEST(options_every_frame_same_bytes_as_created)
{
    if (!ensure_context() || !load_gl()) { tl_test_failures++; return; }
    const uint32_t w = 160, h = 90;
    const size_t n = (size_t)w * h * 4;
    tl_scene *s = crypt(40);
    uint8_t *a = malloc(n), *b = malloc(n);
    tl_renderer *r = s ? renderer(&k_cases[0].o, w, h, s) : NULL;
    for (size_t step = 0; r && a && b && step < 2 * CASES; step++) {
        size_t k = step < CASES ? step : (step - CASES) * 7 % CASES; /* 7 is prime to the count */
        const option_case *c = &k_cases[k];
        TL_CHECK(tl_renderer_set_options(r, &c->o) == TL_OK);
        tl_renderer *fresh = renderer(&c->o, w, h, s);
        if (!fresh) continue;
        if (render_read(r, a, n) && render_read(fresh, b, n)) {
            size_t diff = 0, translucent = 0;
            for (size_t i = 0; i < n; i++) diff += a[i] != b[i];
            for (size_t i = 3; i < n; i += 4) translucent += a[i] != 255; /* the output is opaque */
            if (diff) fprintf(stderr, "%s: %zu bytes differ from a renderer created with its options\n", c->name, diff);
            if (translucent) fprintf(stderr, "%s: %zu pixels of the output have alpha below 255\n", c->name, translucent);
            TL_CHECK_EQ_U(diff, 0);
            TL_CHECK_EQ_U(translucent, 0);
        } else {
            TL_CHECK(!"render");
        }
        tl_frame_plan p;
        TL_CHECK(tl_renderer_get_plan(r, &p) == TL_OK);
        int has_app = 0;
        for (size_t i = 0; i < p.pass_count; i++) has_app |= strcmp(p.passes[i].name, "square") == 0;
        TL_CHECK(has_app);
        tl_renderer_options got;
        tl_renderer_get_options(r, &got);
        TL_CHECK(memcmp(&got, &c->o, sizeof got) == 0);
        tl_renderer_destroy(fresh);
    }
    tl_renderer_destroy(r);
    free(a);
    free(b);
    tl_scene_destroy(s);
}

/* A change uploads nothing of the scene, and a change back builds no program. */
TL_TEST(options_change_keeps_scene_and_programs)
{
    if (!ensure_context() || !load_gl()) { tl_test_failures++; return; }
    tl_scene *s = crypt(40);
    tl_renderer *r = s ? renderer(&k_cases[0].o, 96, 54, s) : NULL;
    for (int round = 0; r && round < 2; round++)
        for (size_t k = 0; k < CASES; k++) {
            tl_test_gl_counts_reset();
            TL_CHECK(tl_renderer_set_options(r, &k_cases[k].o) == TL_OK);
            TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
            unsigned long uploads = tl_test_gl_calls("glTextureSubImage2D"),
                          mipmaps = tl_test_gl_calls("glGenerateTextureMipmap"), links = tl_test_gl_calls("glLinkProgram");
            if (uploads || mipmaps || (round && links))
                fprintf(stderr, "%s, round %d: %lu texture uploads, %lu mipmaps, %lu programs linked\n", k_cases[k].name,
                        round, uploads, mipmaps, links);
            TL_CHECK_EQ_U(uploads + mipmaps, 0);
            if (round) TL_CHECK_EQ_U(links, 0);
        }
    tl_renderer_destroy(r);
    tl_scene_destroy(s);
}

/* Refused options leave the renderer as it was. */
TL_TEST(options_out_of_range_keep_the_renderer)
{
    if (!ensure_context() || !load_gl()) { tl_test_failures++; return; }
    tl_scene *s = crypt(8);
    tl_renderer_options fog = {.fog = {.enabled = 1, .mode = TL_FOG_DISTANCE}};
    tl_renderer *r = s ? renderer(&fog, 64, 36, s) : NULL;
    const size_t n = 64 * 36 * 4;
    uint8_t *a = malloc(n), *b = malloc(n);
    const tl_renderer_options bad[] = {{.mode = TL_MODE_COUNT_},      {.tile_size = 12},
                                       {.ssao = {.enabled = 1, .method = TL_SSAO_DISC, .samples = 65}},
                                       {.bloom = {.enabled = 1, .levels = 9}},
                                       {.light_buffer = TL_LIGHT_BUFFER_COMPACT, .light_format = TL_LIGHT_FORMAT_R11G11B10F}};
    if (r && a && b && render_read(r, a, n)) {
        for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
            TL_CHECK(tl_renderer_set_options(r, &bad[i]) == TL_ERROR_INVALID_ARGUMENT);
            TL_CHECK(strlen(tl_renderer_last_error(r)) > 0);
        }
        TL_CHECK(tl_renderer_set_options(r, NULL) == TL_ERROR_INVALID_ARGUMENT);
        tl_renderer_options got;
        tl_renderer_get_options(r, &got);
        TL_CHECK(memcmp(&got, &fog, sizeof got) == 0);
        TL_CHECK(render_read(r, b, n) && memcmp(a, b, n) == 0);
    }
    tl_renderer_destroy(r);
    free(a);
    free(b);
    tl_scene_destroy(s);
}

/* ---- what a change costs (printed, not asserted: the machine's load decides the figures) ------- */

static double thread_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(double *v, size_t n)
{
    qsort(v, n, sizeof *v, cmp_double);
    return n ? v[n / 2] : 0.0;
}

typedef struct cost_case {
    const char *kind;
    tl_renderer_options a, b;
} cost_case;

static const cost_case k_costs[] = {
    {"mode (thin-lpp <-> fat)", {0}, {.mode = TL_MODE_FAT}},
    {"mode (thin-lpp <-> forward)", {0}, {.mode = TL_MODE_FORWARD}},
    {"light strategy (volumes <-> tiled)", {.light_strategy = TL_LIGHT_STRATEGY_VOLUMES},
     {.light_strategy = TL_LIGHT_STRATEGY_TILED}},
    {"depth format (D24 <-> reversed D32F)", {0}, {.depth_format = TL_DEPTH_FORMAT_D32F_REVERSED}},
    {"lighting (Blinn-Phong <-> GGX)", {.lighting = TL_LIGHTING_BLINN_PHONG}, {.lighting = TL_LIGHTING_GGX}},
    {"SSAO off <-> on", {0}, {.ssao = SSAO_ON}},
    {"fog off <-> on", {0}, {.fog = {.enabled = 1, .mode = TL_FOG_DISTANCE}}},
    {"depth of field off <-> on", {0}, {.dof = {.enabled = 1}}},
    {"bloom off <-> on", {0}, {.bloom = {.enabled = 1}}},
    {"reflections off <-> on", {0}, {.ssr = {.enabled = 1}}},
    {"vignette off <-> on", {0}, {.vignette = {.enabled = 1}}},
    {"FXAA 29 <-> off", {0}, {.fxaa = TL_FXAA_OFF}},
    {"FXAA 29 <-> 39", {0}, {.fxaa = TL_FXAA_39}},
    {"exposure 1 <-> 2", {0}, {.exposure = 2.0f}},
};

/* For each kind of option: re-creating the renderer (create, set_scene, add_pass, one frame), the
 * first change to B (its programs built) with its frame, and later changes between A and B with
 * their frames less a steady frame's CPU time: medians of the calling thread's CPU clock. */
TL_TEST_FULL(options_change_cost_printed)
{
    if (!ensure_context() || !load_gl()) { tl_test_failures++; return; }
    enum { W = 640, H = 360, ROUNDS = 3 };
    tl_scene *s = crypt(64);
    if (!s) return;
    printf("option change, crypt (64 point lights), %dx%d, CPU ms of the calling thread (medians of %d)\n", W, H, ROUNDS);
    printf("%-38s %10s %12s %12s %10s\n", "kind", "re-create", "first change", "later change", "steady");
    for (size_t k = 0; k < sizeof k_costs / sizeof k_costs[0]; k++) {
        const cost_case *c = &k_costs[k];
        double recreate[ROUNDS], change[2 * ROUNDS], steady[2 * ROUNDS];
        for (int i = 0; i < ROUNDS; i++) {
            double t0 = thread_ms();
            tl_renderer *fresh = renderer(&c->b, W, H, s);
            TL_CHECK(fresh && tl_renderer_render(fresh, NULL, NULL) == TL_OK);
            recreate[i] = thread_ms() - t0;
            tl_renderer_wait(fresh, NULL);
            tl_renderer_destroy(fresh);
        }
        tl_renderer *r = renderer(&c->a, W, H, s);
        if (!r) continue;
        TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
        tl_renderer_wait(r, NULL);
        double t0 = thread_ms();
        TL_CHECK(tl_renderer_set_options(r, &c->b) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK);
        double first = thread_ms() - t0;
        for (int i = 0; i < 2 * ROUNDS; i++) {
            tl_renderer_wait(r, NULL);
            const tl_renderer_options *to = (i & 1) ? &c->b : &c->a;
            t0 = thread_ms();
            TL_CHECK(tl_renderer_set_options(r, to) == TL_OK && tl_renderer_render(r, NULL, NULL) == TL_OK);
            double with_change = thread_ms() - t0;
            tl_renderer_wait(r, NULL);
            t0 = thread_ms();
            TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
            steady[i] = thread_ms() - t0;
            change[i] = with_change - steady[i];
        }
        tl_renderer_wait(r, NULL);
        tl_renderer_destroy(r);
        double st = median(steady, 2 * ROUNDS);
        printf("%-38s %10.2f %12.2f %12.2f %10.2f\n", c->kind, median(recreate, ROUNDS), first - st,
               median(change, 2 * ROUNDS), st);
    }
    tl_scene_destroy(s);
}
