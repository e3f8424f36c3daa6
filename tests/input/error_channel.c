/* The one error channel (docs/getting-started.md, "Errors, logging and memory"): one
 * tl_last_error_logger given to every descriptor holds, after any call fails, that call's line,
 * whichever layer made it: the renderer's, the context's, the glTF loader's, the image writer's
 * and reader's, the file writer's, the built-in scenes'. A program's one error check reads it; the renderer's own last error stays
 * about the renderer's calls (the stale line a program printed when it read that after a failed
 * tl_image_write). */
#include <stdio.h>
#include <string.h>

#include "render_room.h"
#include "thinlight/file.h"
#include "thinlight/io.h"
#include "tl_test.h"

#ifndef TL_ERROR_CHANNEL_TEST_DIR
#  define TL_ERROR_CHANNEL_TEST_DIR "."
#endif

/* What the record passed on to its `next` logger. */
typedef struct passed {
    unsigned errors, others;
    char last[TL_LOG_LINE_MAX];
} passed;

static void pass_on(void *user, tl_log_level level, const char *message)
{
    passed *p = user;
    if (level == TL_LOG_ERROR) p->errors++;
    else p->others++;
    snprintf(p->last, sizeof p->last, "%s", message);
}

/* The call failed with `want`, one more error line arrived, and it holds `text`. */
static int failed_with(const tl_last_error *e, uint64_t *seen, tl_result got, tl_result want, const char *text)
{
    int ok = got == want && e->count == *seen + 1 && strstr(e->message, text) != NULL;
    printf("%-9s %s -> \"%s\"\n", ok ? "ok" : "FAILED", tl_result_string(got), e->message);
    *seen = e->count;
    return ok;
}

TL_TEST(one_error_channel_renderer_loader_image_writer)
{
    if (!ensure_context()) return;
    passed p = {0};
    tl_last_error err = {.next = {pass_on, &p}};
    const tl_logger log = tl_last_error_logger(&err);
    uint64_t seen = 0;
    TL_CHECK(err.message[0] == '\0' && err.count == 0);

    /* the renderer: a call on the renderer, its line in the record and in its own last error */
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = {.width = 32, .height = 32, .logger = log}});
    if (!r) return;
    tl_renderer_options bad = {.mode = (tl_render_mode)99};
    TL_CHECK(failed_with(&err, &seen, tl_renderer_set_options(r, &bad), TL_ERROR_INVALID_ARGUMENT, "options.mode"));
    TL_CHECK(strcmp(tl_renderer_last_error(r), err.message) == 0);
    char renderer_line[TL_LOG_LINE_MAX];
    snprintf(renderer_line, sizeof renderer_line, "%s", err.message);

    /* the image writer: a folder that does not exist; the record now holds the writer's line */
    static const uint8_t px[4 * 4] = {0};
    const char *png = TL_ERROR_CHANNEL_TEST_DIR "/no such folder/out.png";
    tl_image_desc image = {.width = 2, .height = 2, .channels = 4, .logger = log};
    TL_CHECK(failed_with(&err, &seen, tl_image_write(png, &image, px), TL_ERROR_IO, "no such folder/out.png"));
    /* the renderer's own last error is still its own call's: what a program read before */
    printf("tl_renderer_last_error after the failed write: \"%s\"\n", tl_renderer_last_error(r));
    TL_CHECK(strcmp(tl_renderer_last_error(r), renderer_line) == 0);
    TL_CHECK(strstr(tl_renderer_last_error(r), "out.png") == NULL);

    /* the glTF loader, the file writer, the image reader, a context */
    tl_scene *s = NULL;
    const char *gltf = TL_ERROR_CHANNEL_TEST_DIR "/missing.gltf";
    TL_CHECK(failed_with(&err, &seen, tl_scene_load_gltf(gltf, &(tl_gltf_options){.logger = log}, &s), TL_ERROR_IO,
                         "missing.gltf"));
    TL_CHECK(s == NULL);
    const char *raw = TL_ERROR_CHANNEL_TEST_DIR "/no such folder/raw.bin";
    TL_CHECK(failed_with(&err, &seen, tl_file_write(raw, px, sizeof px, &(tl_file_write_desc){.logger = log}),
                         TL_ERROR_IO, "raw.bin"));
    tl_rgba8_image read = {0};
    TL_CHECK(failed_with(&err, &seen, tl_image_read_rgba8(png, &(tl_image_read_desc){.logger = log}, &read),
                         TL_ERROR_IO, "out.png"));
    tl_context *big = NULL;
    TL_CHECK(failed_with(&err, &seen,
                         tl_context_create(&(tl_context_desc){.backend = TL_CONTEXT_BACKEND_OSMESA, .width = 40000,
                                                              .height = 4, .logger = log},
                                           &big),
                         TL_ERROR_LIMIT, "40000"));
    TL_CHECK(big == NULL);
    TL_CHECK(tl_context_make_current(g_ctx) == TL_OK);

    /* the built-in scenes, which once had no logger */
    TL_CHECK(failed_with(&err, &seen, tl_scene_create_default(&(tl_default_scene_desc){.detail = 9, .logger = log}, &s),
                         TL_ERROR_INVALID_ARGUMENT, "detail = 9"));
    TL_CHECK(failed_with(&err, &seen,
                         tl_scene_create_showcase(&(tl_showcase_scene_desc){.point_lights = 70000, .logger = log}, &s),
                         TL_ERROR_LIMIT, "point_lights = 70000"));
    TL_CHECK(s == NULL);

    /* and the renderer again: the record follows the newest failure, whichever layer */
    TL_CHECK(failed_with(&err, &seen, tl_renderer_resize(r, 0, 32), TL_ERROR_INVALID_ARGUMENT, "0"));
    TL_CHECK(strcmp(tl_renderer_last_error(r), err.message) == 0);
    /* every line went on to `next` as it came */
    TL_CHECK_EQ_U(p.errors, (unsigned)err.count);
    TL_CHECK(strcmp(p.last, err.message) == 0);
    tl_renderer_destroy(r);

    /* a NULL record: a silent logger */
    tl_logger none = tl_last_error_logger(NULL);
    TL_CHECK(none.fn == NULL && none.user == NULL);
}
