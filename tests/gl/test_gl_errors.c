/* GL error discipline (render_fixture.h, gl_debug.c): a GL error inside a pass fails the running
 * case with a line naming that pass; a clean frame reports none; every GL object the renderer
 * creates carries a debug label, so that a capture reads like the plan. */
#include <stdint.h>
#include <string.h>

#include "render_room.h"
#include "tl_test.h"

typedef void (*enable_fn)(unsigned int cap);
typedef unsigned int (*get_error_fn)(void);

typedef struct gl_fns {
    enable_fn enable;
} gl_fns;

/* The application pass: one invalid enum, as a buggy pass would make. */
static void provoke(void *user, const tl_app_pass_context *ctx)
{
    (void)ctx;
    ((const gl_fns *)user)->enable(0xDEADu); /* GL_INVALID_ENUM */
}

static void drain_gl_errors(void)
{
    get_error_fn get_error = (get_error_fn)tl_context_proc_loader(g_ctx, "glGetError");
    for (int i = 0; i < 16 && get_error && get_error() != 0; i++) {
    }
}

static tl_renderer *room_renderer(test_scene *t)
{
    build_room(t);
    return tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = 64, .height = 48, .options = {.depth_format = TL_DEPTH_FORMAT_D24, .fxaa = TL_FXAA_OFF}},
        .scene = &t->s, .readable = true});
}

TL_TEST(gl_error_in_app_pass_fails_naming_the_pass)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    TL_CHECK(tl_test_gl_debug_active());
    static test_scene t;
    tl_renderer *r = room_renderer(&t);
    if (!r) return;
    tl_test_gl_errors seen;
    tl_test_gl_errors_capture(&seen); /* a clean frame: nothing */
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK_EQ_U(seen.count, 0);
    gl_fns fns = {(enable_fn)tl_context_proc_loader(g_ctx, "glEnable")};
    tl_app_pass_desc ap = {.name = "provoke-error", .after = "lights", .writes = TL_TARGET_BIT(TL_TARGET_HDR),
                           .execute = provoke, .user = &fns};
    TL_CHECK(fns.enable && tl_renderer_add_pass(r, &ap) == TL_OK);
    /* captured: exactly one error, named after the pass it happened in */
    tl_test_gl_errors_capture(&seen);
    tl_result res = tl_renderer_render(r, NULL, NULL);
    TL_CHECK(res == TL_OK || res == TL_ERROR_GL); /* the frame's own glGetError may see it too */
    tl_test_gl_errors_capture(NULL);
    drain_gl_errors();
    TL_CHECK_EQ_U(seen.count, 1);
    TL_CHECK(strstr(seen.first, "GL error in pass 'provoke-error'") != NULL);
    /* not captured: the running case fails (counted here, then taken back) with that line */
    int before = tl_test_failures;
    tl_renderer_render(r, NULL, NULL);
    drain_gl_errors();
    int failed = tl_test_failures - before;
    tl_test_failures = before;
    TL_CHECK(failed == 1);
    TL_CHECK(strstr(tl_test_gl_last_error(), "GL error in pass 'provoke-error'") != NULL);
    /* outside the renderer's passes the line says so */
    tl_test_gl_errors_capture(&seen);
    if (fns.enable) fns.enable(0xDEADu);
    tl_test_gl_errors_capture(NULL);
    drain_gl_errors();
    TL_CHECK(seen.count == 1 && strstr(seen.first, "outside any pass") != NULL);
    /* the pass removed, frames are clean again */
    TL_CHECK(tl_renderer_remove_pass(r, "provoke-error") == TL_OK);
    tl_test_gl_errors_capture(&seen);
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    tl_test_gl_errors_capture(NULL);
    TL_CHECK_EQ_U(seen.count, 0);
    tl_renderer_destroy(r);
}

/* ---- labels -------------------------------------------------------------------------------- */

typedef unsigned char (*is_fn)(unsigned int name);
typedef void (*get_label_fn)(unsigned int identifier, unsigned int name, int size, int *length, char *label);

/* Every live object of one kind among names 1..max has a label; how many were live. */
static unsigned check_labels(const char *is_name, unsigned int identifier, const char *kind, unsigned max)
{
    is_fn is = (is_fn)tl_context_proc_loader(g_ctx, is_name);
    get_label_fn get_label = (get_label_fn)tl_context_proc_loader(g_ctx, "glGetObjectLabel");
    TL_CHECK(is && get_label);
    if (!is || !get_label) return 0;
    unsigned live = 0;
    for (unsigned name = 1; name <= max; name++) {
        if (!is(name)) continue;
        live++;
        char label[256] = "";
        int length = 0;
        get_label(identifier, name, (int)sizeof label, &length, label);
        if (length == 0) fprintf(stderr, "%s %u has no label\n", kind, name);
        TL_CHECK(length > 0);
    }
    return live;
}

TL_TEST(gl_objects_of_the_renderer_all_labelled)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    static test_scene t;
    /* tiled lighting and forward too, so that their buffers exist */
    const tl_renderer_desc descs[3] = {
        {.width = 64, .height = 48},
        {.width = 64, .height = 48, .options.light_strategy = TL_LIGHT_STRATEGY_TILED},
        {.width = 64, .height = 48, .options.mode = TL_MODE_FORWARD, .options.fxaa = TL_FXAA_12},
    };
    for (int i = 0; i < 3; i++) {
        build_room(&t);
        tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = descs[i], .scene = &t.s, .readable = true});
        if (!r) continue;
        TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
        unsigned live = 0;
        live += check_labels("glIsBuffer", 0x82E0 /* GL_BUFFER */, "buffer", 512);
        live += check_labels("glIsTexture", 0x1702 /* GL_TEXTURE */, "texture", 512);
        live += check_labels("glIsFramebuffer", 0x8D40 /* GL_FRAMEBUFFER */, "framebuffer", 512);
        live += check_labels("glIsProgram", 0x82E2 /* GL_PROGRAM */, "program", 512);
        live += check_labels("glIsVertexArray", 0x8074 /* GL_VERTEX_ARRAY */, "vertex array", 512);
        live += check_labels("glIsSampler", 0x82E6 /* GL_SAMPLER */, "sampler", 512);
        live += check_labels("glIsQuery", 0x82E3 /* GL_QUERY */, "query", 2048);
        TL_CHECK(live > 20); /* the enumeration saw the renderer's objects */
        tl_renderer_destroy(r);
    }
}
