/* Every io failure reports as every other layer does (docs/getting-started.md, "Errors, logging
 * and memory"): a result, exactly one error line to the logger (one line even when a path or a
 * name holds a newline), nothing printed on stderr, and nothing left in OpenImageIO's per-thread
 * error for the application to find. */
#define _POSIX_C_SOURCE 200809L

#include <stdint.h>
#include <stdlib.h>

#include "gltf_hostile.h"
#include "stderr_capture.h"
#include "thinlight/file.h"
#include "thinlight/io.h"
#include "tl_test.h"

#ifndef TL_IO_ERRORS_TEST_DIR
#define TL_IO_ERRORS_TEST_DIR "io_errors_work"
#endif

int tl_test_oiio_pending_error(char *out, size_t size); /* oiio_pending_error.cpp */

typedef struct io_case {
    const char *what;
    tl_result want;
    const char *needle; /* in the error line */
} io_case;

/* Runs case `i` with `logger`; `dir` is a folder of the test's own. */
static tl_result run_case(size_t i, const char *dir, tl_logger logger)
{
    static const uint8_t px[4] = {1, 2, 3, 4};
    char path[1200];
    tl_image_desc img = {.width = 1, .height = 1, .channels = 4, .logger = logger};
    tl_image_read_desc rd = {.logger = logger};
    tl_gltf_options go = {.logger = logger};
    tl_file_write_desc fw = {logger};
    tl_rgba8_image out;
    tl_scene *scene = NULL;
    tl_result r = TL_OK;
    switch (i) {
    case 0: return tl_image_write(NULL, &img, px);
    case 1: snprintf(path, sizeof path, "%s/x.unknown-format", dir); return tl_image_write(path, &img, px);
    case 2: snprintf(path, sizeof path, "%s/missing/x.png", dir); return tl_image_write(path, &img, px);
    case 3: snprintf(path, sizeof path, "%s/missing/two\nlines.png", dir); return tl_image_write(path, &img, px);
    case 4: snprintf(path, sizeof path, "%s/missing/two\nlines.bin", dir); return tl_file_write(path, px, 4, &fw);
    case 5: snprintf(path, sizeof path, "%s/two\nlines.png", dir); return tl_image_read_rgba8(path, &rd, &out);
    case 6: return tl_image_decode_rgba8("not an image", 12, &rd, &out);
    case 7: return tl_image_decode_rgba8("\x89PNG\r\n\x1a\n0123456789abcdef", 24, &rd, &out);
    case 8:
        rd.allocator = (tl_allocator){tlh_alloc, NULL, NULL};
        return tl_image_decode_rgba8("abc", 3, &rd, &out);
    case 9: snprintf(path, sizeof path, "%s/two\nlines.gltf", dir); r = tl_scene_load_gltf(path, &go, &scene); break;
    case 10:
        go.name = "two\nlines";
        r = tl_scene_parse_gltf("{\"asset\": {", 11, &go, &scene);
        break;
    case 11:
        go.allocator = (tl_allocator){tlh_alloc, NULL, NULL};
        r = tl_scene_parse_gltf("{}", 2, &go, &scene);
        break;
    }
    if (scene) tl_scene_destroy(scene);
    return r;
}

static const io_case io_cases[] = {
    {"tl_image_write, NULL path", TL_ERROR_INVALID_ARGUMENT, "tl_image_write"},
    {"tl_image_write, unknown extension", TL_ERROR_UNSUPPORTED, "x.unknown-format"},
    {"tl_image_write, missing folder", TL_ERROR_IO, "x.png"},
    {"tl_image_write, missing folder, a newline in the path", TL_ERROR_IO, "two lines.png"},
    {"tl_file_write, missing folder, a newline in the path", TL_ERROR_IO, "two lines.bin"},
    {"tl_image_read_rgba8, missing file, a newline in the path", TL_ERROR_IO, "two lines.png"},
    {"tl_image_decode_rgba8, not an image", TL_ERROR_UNSUPPORTED, "not a PNG or JPEG"},
    {"tl_image_decode_rgba8, truncated PNG", TL_ERROR_PARSE, "PNG"},
    {"tl_image_decode_rgba8, half an allocator", TL_ERROR_INVALID_ARGUMENT, "allocator"},
    {"tl_scene_load_gltf, missing file, a newline in the path", TL_ERROR_IO, "two lines.gltf"},
    {"tl_scene_parse_gltf, malformed JSON, a newline in the name", TL_ERROR_PARSE, "two lines"},
    {"tl_scene_parse_gltf, half an allocator", TL_ERROR_INVALID_ARGUMENT, "allocator"},
};

TL_TEST(io_failures_one_error_line_each_nothing_printed)
{
    char dir[1024];
    snprintf(dir, sizeof dir, "%s/one_line", TL_IO_ERRORS_TEST_DIR);
    tlh_rmtree(dir);
    TL_CHECK(tlh_mkdirs(dir) == 0);
    char pending[1024];
    tl_test_oiio_pending_error(pending, sizeof pending); /* start clean */
    for (size_t i = 0; i < sizeof io_cases / sizeof io_cases[0]; i++) {
        const io_case *c = &io_cases[i];
        tlh_log log = {0};
        tlc_stderr cap;
        tlc_stderr_begin(&cap);
        tl_result r = run_case(i, dir, TLH_LOGGER(&log));
        char printed[2048];
        long n = tlc_stderr_end(&cap, printed, sizeof printed);
        int oiio = tl_test_oiio_pending_error(pending, sizeof pending);
        int ok = r == c->want && log.errors == 1 && log.multiline == 0 && strstr(log.error, c->needle) && n == 0 &&
                 !oiio;
        printf("%-60s %-18s %d line%s%s: %s\n", c->what, tl_result_string(r), log.errors, log.errors == 1 ? "" : "s",
               log.multiline ? " (not one line)" : "", log.error);
        if (n) printf("    printed on stderr: %s\n", printed);
        if (oiio) printf("    left in OIIO::geterror(): %s\n", pending);
        TL_CHECK(ok);
    }
}
