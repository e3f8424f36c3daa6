/* Calls made where the renderer's GL context is not current (issue 25; renderer.h,
 * tl_renderer_desc.is_current): each fails with TL_ERROR_GL and a message saying so, changes
 * nothing, and the renderer draws the same frame afterwards on the right thread. Before, render,
 * wait and the reads returned TL_OK with nothing drawn or read, and set_scene failed with "size
 * 64x64 outside 1..0" after releasing its scene. Also render_to into framebuffers that do not
 * exist or are not complete. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl_counter.h"
#include "render_room.h"
#include "tl_test.h"

#define W 64
#define H 64

static void room_with_light(test_scene *t)
{
    build_room(t);
    t->lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {3, 6, -2}, .color = {60, 55, 50}, .radius = 30};
    t->s.light_count = 1;
    t->s.ambient[0] = t->s.ambient[1] = t->s.ambient[2] = 0.05f;
}

static uint8_t *output(tl_renderer *r)
{
    size_t size = (size_t)W * H * 4;
    uint8_t *px = malloc(size);
    if (px && (tl_renderer_render(r, NULL, NULL) != TL_OK || tl_renderer_read_output(r, px, &size) != TL_OK)) {
        free(px);
        px = NULL;
    }
    return px;
}

static void noop_pass(void *user, const tl_app_pass_context *ctx)
{
    (void)user;
    (void)ctx;
}

/* ---- a thread without the context ------------------------------------------------------------ */

typedef struct job {
    tl_renderer *r;
    const tl_scene *other;
    int own_context;   /* make another context current in the thread first */
    size_t refused, calls;
} job;

/* Every call that uses GL, each expected to fail with TL_ERROR_GL naming itself. */
static void wrong_thread_calls(job *j)
{
    tl_renderer *r = j->r;
    size_t size = (size_t)W * H * 4, fsize = (size_t)W * H * 16;
    uint8_t *px = calloc(size, 1), *px2 = calloc(size, 1);
    float *f = calloc(fsize, 1);
    tl_light light = {.type = TL_LIGHT_POINT, .position = {0, 5, 0}, .color = {1, 1, 1}, .radius = 5};
    tl_app_pass_desc pass = {.name = "late", .after = "lights", .writes = TL_TARGET_BIT(TL_TARGET_HDR),
                             .execute = noop_pass};
    if (!px || !px2 || !f) {
        tl_test_failures++;
        free(px), free(px2), free(f);
        return;
    }
    /* each call fails with TL_ERROR_GL, and its message names it */
    size_t refused = 0, calls = 0;
#define CALL(name, expr)                                                                                \
    do {                                                                                                \
        tl_result res_ = (expr);                                                                        \
        const char *why_ = tl_renderer_last_error(r);                                                   \
        int ok_ = res_ == TL_ERROR_GL &&                                                                \
                  strstr(why_, name ": the renderer's GL context is not current on this thread") != NULL; \
        if (!ok_) fprintf(stderr, "  %s: %s \"%s\"\n", name, tl_result_string(res_), why_);              \
        refused += (size_t)ok_;                                                                         \
        calls++;                                                                                        \
    } while (0)
    CALL("tl_renderer_render", tl_renderer_render(r, NULL, NULL));
    CALL("tl_renderer_render_to", tl_renderer_render_to(r, NULL, &(tl_render_output){0}, NULL));
    CALL("tl_renderer_wait", tl_renderer_wait(r, NULL));
    CALL("tl_renderer_read_output", tl_renderer_read_output(r, px, &size));
    CALL("tl_renderer_read_target", tl_renderer_read_target(r, TL_TARGET_HDR, f, &fsize));
    CALL("tl_renderer_apply_fxaa", tl_renderer_apply_fxaa(r, px, px2, &size));
    CALL("tl_renderer_set_scene", tl_renderer_set_scene(r, j->other));
    CALL("tl_renderer_set_lights", tl_renderer_set_lights(r, &light, 1));
    CALL("tl_renderer_resize", tl_renderer_resize(r, 32, 32));
    CALL("tl_renderer_add_pass", tl_renderer_add_pass(r, &pass));
    CALL("tl_renderer_remove_pass", tl_renderer_remove_pass(r, "late"));
    CALL("tl_renderer_set_options", tl_renderer_set_options(r, &(tl_renderer_options){.mode = TL_MODE_FAT}));
    static const float moved[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 2, 0, 0, 1};
    tl_object object = {.index_count = 3};
    uint32_t id = 0, first = 0;
    tl_vertex tri[3] = {{.position = {0, 0, 0}}, {.position = {1, 0, 0}}, {.position = {0, 1, 0}}};
    uint32_t tri_idx[3] = {0, 1, 2};
    CALL("tl_renderer_set_object_transform", tl_renderer_set_object_transform(r, 0, moved));
    CALL("tl_renderer_set_object_visible", tl_renderer_set_object_visible(r, 0, 0));
    CALL("tl_renderer_set_object", tl_renderer_set_object(r, 0, &object));
    CALL("tl_renderer_add_object", tl_renderer_add_object(r, &object, &id));
    CALL("tl_renderer_remove_object", tl_renderer_remove_object(r, 0));
    CALL("tl_renderer_add_geometry", tl_renderer_add_geometry(r, tri, 3, tri_idx, 3, &first));
    CALL("tl_renderer_set_material", tl_renderer_set_material(r, 0, &(tl_material){0}));
#undef CALL
    j->refused = refused;
    j->calls = calls;
    /* the size query of a read needs no GL */
    size_t ask = 0;
    TL_CHECK(tl_renderer_read_output(r, NULL, &ask) == TL_OK && ask == (size_t)W * H * 4);
    /* destroy frees nothing there (GL names mean other objects in another context): the caller
     * destroys it again where the context is current */
    if (j->refused == j->calls) tl_renderer_destroy(r);
    free(px), free(px2), free(f);
}

static void *wrong_thread(void *arg)
{
    job *j = (job *)arg;
    tl_context *other = NULL;
    if (j->own_context) {
        tl_context_desc d = {.backend = TL_CONTEXT_BACKEND_OSMESA, .width = 16, .height = 16};
        if (tl_context_create(&d, &other) != TL_OK) {
            fprintf(stderr, "  no second OSMesa context\n");
            tl_test_failures++;
            return NULL;
        }
    }
    wrong_thread_calls(j);
    tl_context_destroy(other);
    return NULL;
}

static void calls_from_another_thread(int own_context)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = W, .height = H, .options = {.depth_format = TL_DEPTH_FORMAT_D24, .fxaa = TL_FXAA_29}},
        .readable = true});
    static test_scene t, u;
    room_with_light(&t);
    room_with_light(&u);
    u.lights[0].color[0] = 1.0f; /* another scene: refused anyway */
    TL_CHECK(r && tl_renderer_set_scene(r, &t.s) == TL_OK);
    if (!r) return;
    uint8_t *before = output(r);
    job j = {.r = r, .other = &u.s, .own_context = own_context};
    pthread_t th;
    TL_CHECK(pthread_create(&th, NULL, wrong_thread, &j) == 0);
    pthread_join(th, NULL);
    printf("  %s: %zu of %zu calls refused with TL_ERROR_GL\n", own_context ? "another context current" : "no context",
           j.refused, j.calls);
    TL_CHECK(j.calls > 0 && j.refused == j.calls);
    uint32_t w = 0, h = 0;
    tl_renderer_get_size(r, &w, &h);
    TL_CHECK(w == W && h == H);
    uint8_t *after = output(r);
    TL_CHECK(before && after && memcmp(before, after, (size_t)W * H * 4) == 0);
    tl_frame_plan plan;
    TL_CHECK(tl_renderer_get_plan(r, &plan) == TL_OK && plan.light_types == (1u << TL_LIGHT_POINT));
    TL_CHECK(tl_renderer_remove_pass(r, "late") == TL_ERROR_INVALID_ARGUMENT); /* never added */
    free(before);
    free(after);
    tl_renderer_destroy(r);
}

TL_TEST(renderer_calls_from_a_thread_without_the_context_fail_and_keep_the_scene)
{
    calls_from_another_thread(0);
}

TL_TEST(renderer_calls_from_a_thread_with_another_context_fail_and_keep_the_scene)
{
    calls_from_another_thread(1);
}

/* ---- an application's own loader: the check when the thread changes --------------------------- */

/* The counting loader is not tl_context_proc_loader, as an application with its own context has. */
#define IS_VERTEX_ARRAY_CALLS tl_test_gl_calls("glIsVertexArray")

static void *app_thread(void *arg)
{
    tl_renderer *r = (tl_renderer *)arg;
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_ERROR_GL);
    TL_CHECK(strstr(tl_renderer_last_error(r), "not current on this thread") != NULL);
    return NULL;
}

typedef struct moved {
    tl_renderer *r;
    int rendered;
} moved;

static void *moved_thread(void *arg)
{
    moved *m = (moved *)arg;
    if (tl_context_make_current(g_ctx) != TL_OK) return NULL;
    for (int i = 0; i < 3; i++) m->rendered += tl_renderer_render(m->r, NULL, NULL) == TL_OK;
    tl_renderer_wait(m->r, NULL);
    tl_context_make_current(NULL);
    return NULL;
}

/* Without is_current and without tl_context_proc_loader the renderer asks GL once when a call
 * comes from another thread than the last one that had the context (a steady frame asks
 * nothing); on a thread with no context the answer is no. */
TL_TEST(renderer_application_context_checked_when_the_thread_changes)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    static test_scene t;
    room_with_light(&t);
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = W, .height = H, .get_proc_address = tl_test_gl_counting_loader}, .scene = &t.s});
    if (!r) return;
    tl_test_gl_counts_reset();
    for (int i = 0; i < 3; i++) TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    unsigned long steady = IS_VERTEX_ARRAY_CALLS;
    pthread_t th;
    TL_CHECK(pthread_create(&th, NULL, app_thread, r) == 0);
    pthread_join(th, NULL);
    unsigned long other = IS_VERTEX_ARRAY_CALLS - steady;
    for (int i = 0; i < 3; i++) TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    unsigned long back = IS_VERTEX_ARRAY_CALLS - steady - other;
    printf("  glIsVertexArray: %lu in 3 steady frames, %lu on the other thread, %lu in 3 frames back on the first\n",
           steady, other, back);
    /* the context moves to another thread (released here, made current there): one query there */
    TL_CHECK(tl_context_make_current(NULL) == TL_OK);
    moved m = {r, 0};
    TL_CHECK(pthread_create(&th, NULL, moved_thread, &m) == 0);
    pthread_join(th, NULL);
    TL_CHECK(tl_context_make_current(g_ctx) == TL_OK);
    printf("  context moved to another thread: %d of 3 frames there rendered, glIsVertexArray %lu more\n", m.rendered,
           IS_VERTEX_ARRAY_CALLS - steady - other - back);
    TL_CHECK(m.rendered == 3);
    TL_CHECK_EQ_U(IS_VERTEX_ARRAY_CALLS - steady - other - back, 1);
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK); /* back here: one more */
    TL_CHECK_EQ_U(IS_VERTEX_ARRAY_CALLS - steady - other - back, 2);
    TL_CHECK_EQ_U(steady, 0);
    TL_CHECK_EQ_U(other, 1);
    TL_CHECK_EQ_U(back, 0); /* the other thread never had it: the first is still trusted */
    tl_renderer_destroy(r);
}

/* ---- render_to's framebuffer -------------------------------------------------------------------- */

/* The framebuffer queries render_to makes, through the counting loader. */
#define FB_QUERIES (tl_test_gl_calls("glIsFramebuffer") + tl_test_gl_calls("glCheckNamedFramebufferStatus"))

/* render_to into a name that is no framebuffer, or one without attachments, is
 * TL_ERROR_INVALID_ARGUMENT naming it (before: TL_OK, and GL_INVALID_OPERATION in the frame); a
 * complete one is checked once, not every frame. */
TL_TEST(renderer_render_to_missing_or_incomplete_framebuffer_refused)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    static test_scene t;
    room_with_light(&t);
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = W, .height = H, .get_proc_address = tl_test_gl_counting_loader}, .scene = &t.s});
    if (!r) return;
    typedef void (*create_t)(int, unsigned *);
    typedef void (*create_tex_t)(unsigned, int, unsigned *);
    typedef void (*storage_t)(unsigned, int, unsigned, int, int);
    typedef void (*attach_t)(unsigned, unsigned, unsigned, int);
    typedef void (*del_t)(int, const unsigned *);
    create_t create_fb = (create_t)tl_context_get_proc_address(g_ctx, "glCreateFramebuffers");
    create_tex_t create_tex = (create_tex_t)tl_context_get_proc_address(g_ctx, "glCreateTextures");
    storage_t storage = (storage_t)tl_context_get_proc_address(g_ctx, "glTextureStorage2D");
    attach_t attach = (attach_t)tl_context_get_proc_address(g_ctx, "glNamedFramebufferTexture");
    del_t del_fb = (del_t)tl_context_get_proc_address(g_ctx, "glDeleteFramebuffers");
    del_t del_tex = (del_t)tl_context_get_proc_address(g_ctx, "glDeleteTextures");
    TL_CHECK(create_fb && create_tex && storage && attach && del_fb && del_tex);
    if (!create_fb || !create_tex || !storage || !attach || !del_fb || !del_tex) return;
    unsigned empty = 0, complete = 0, tex = 0;
    create_fb(1, &empty);
    create_fb(1, &complete);
    create_tex(0x0DE1 /* GL_TEXTURE_2D */, 1, &tex);
    storage(tex, 1, 0x8058 /* GL_RGBA8 */, W, H);
    attach(complete, 0x8CE0 /* GL_COLOR_ATTACHMENT0 */, tex, 0);
    tl_render_output o = {.framebuffer = 4242};
    TL_CHECK(tl_renderer_render_to(r, NULL, &o, NULL) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(strstr(tl_renderer_last_error(r), "render_to: framebuffer 4242 is not a framebuffer object") != NULL);
    o.framebuffer = empty;
    TL_CHECK(tl_renderer_render_to(r, NULL, &o, NULL) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(strstr(tl_renderer_last_error(r), "is not complete (GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT)") != NULL);
    printf("  \"%s\"\n", tl_renderer_last_error(r));
    o.framebuffer = complete;
    tl_test_gl_counts_reset();
    TL_CHECK(tl_renderer_render_to(r, NULL, &o, NULL) == TL_OK);
    unsigned long first = FB_QUERIES;
    for (int i = 0; i < 3; i++) TL_CHECK(tl_renderer_render_to(r, NULL, &o, NULL) == TL_OK);
    o.framebuffer = 0; /* OSMesa's default framebuffer is complete */
    TL_CHECK(tl_renderer_render_to(r, NULL, &o, NULL) == TL_OK);
    printf("  framebuffer queries: %lu for the first frame into a framebuffer, %lu for 3 more\n", first,
           FB_QUERIES - first - 1);
    TL_CHECK_EQ_U(first, 2);
    TL_CHECK_EQ_U(FB_QUERIES, 3); /* and one for framebuffer 0 */
    TL_CHECK(tl_renderer_wait(r, NULL) == TL_OK);
    del_fb(1, &empty);
    del_fb(1, &complete);
    del_tex(1, &tex);
    tl_renderer_destroy(r);
}

/* ---- the context destroyed before the renderer -------------------------------------------------- */

typedef struct lines {
    int errors;
    char last[512];
} lines;

static void keep_line(void *user, tl_log_level level, const char *message)
{
    lines *l = (lines *)user;
    if (level != TL_LOG_ERROR) return;
    l->errors++;
    snprintf(l->last, sizeof l->last, "%s", message);
}

/* A renderer on its own tl_context with every module holding memory (scene, tiles, the light
 * fix-up, shadows, an environment, statistics), whose context is destroyed first: every call that
 * needs GL is refused with one line saying the context was destroyed, and destroy frees the memory
 * without a GL call (the objects went with the context; ASan and LSan see neither a freed read nor
 * a leak). Before, the context check read the freed tl_context: render and destroy crashed. */
TL_TEST(renderer_context_destroyed_first_calls_refused_destroy_frees)
{
    tl_context *ctx = NULL;
    tl_context_desc cd = {.backend = TL_CONTEXT_BACKEND_OSMESA, .width = W, .height = H, .logger = tl_test_logger};
    TL_CHECK(tl_context_create(&cd, &ctx) == TL_OK);
    if (!ctx) return;
    lines log = {0};
    tl_renderer_desc d = {.width = W, .height = H, .get_proc_address = tl_context_proc_loader,
                          .get_proc_address_user = ctx, .logger = {keep_line, &log}};
    d.options.light_strategy = TL_LIGHT_STRATEGY_TILED;
    d.options.light_scale = 0.5f;
    tl_renderer *r = NULL;
    TL_CHECK(tl_renderer_create(&d, &r) == TL_OK);
    static test_scene t;
    room_with_light(&t);
    t.lights[0].shadow = 1;
    static float sky[8 * 4 * 3];
    for (size_t i = 0; i < sizeof sky / sizeof sky[0]; i++) sky[i] = 0.2f;
    tl_frame_stats st;
    int ok = r && tl_renderer_set_scene(r, &t.s) == TL_OK &&
             tl_renderer_set_environment(r, &(tl_environment_desc){sky, 8, 4}) == TL_OK &&
             tl_renderer_render(r, NULL, &st) == TL_OK && tl_renderer_wait(r, NULL) == TL_OK;
    TL_CHECK(ok);
    tl_frame_plan plan;
    TL_CHECK(r && tl_renderer_get_plan(r, &plan) == TL_OK && plan.shadow_lights == 1 &&
             (plan.targets & TL_TARGET_BIT(TL_TARGET_LIGHT_FIXUP)));
    tl_context_destroy(ctx);
    if (!r) return;
    uint8_t px[W * H * 4];
    size_t size = sizeof px, refused = 0, calls = 0;
#define GONE(name, expr)                                                                                \
    do {                                                                                                \
        int before_ = log.errors;                                                                       \
        tl_result res_ = (expr);                                                                        \
        int ok_ = res_ == TL_ERROR_GL && log.errors == before_ + 1 &&                                  \
                  strstr(log.last, name ": the renderer's context was destroyed (tl_context_destroy) before " \
                                   "the renderer") != NULL;                                             \
        if (!ok_) fprintf(stderr, "  %s: %s \"%s\"\n", name, tl_result_string(res_), log.last);          \
        refused += (size_t)ok_;                                                                         \
        calls++;                                                                                        \
    } while (0)
    GONE("tl_renderer_render", tl_renderer_render(r, NULL, NULL));
    GONE("tl_renderer_read_output", tl_renderer_read_output(r, px, &size));
    GONE("tl_renderer_set_options", tl_renderer_set_options(r, &(tl_renderer_options){.mode = TL_MODE_FAT}));
    GONE("tl_renderer_resize", tl_renderer_resize(r, 32, 32));
    GONE("tl_renderer_wait", tl_renderer_wait(r, NULL));
#undef GONE
    printf("  %zu of %zu calls refused after the context went, one line each: \"%s\"\n", refused, calls, log.last);
    TL_CHECK(calls > 0 && refused == calls);
    tl_renderer_destroy(r); /* frees; no GL call, no freed read */
    printf("  destroyed without its context\n");
    if (g_ctx) TL_CHECK(tl_context_make_current(g_ctx) == TL_OK);
}
