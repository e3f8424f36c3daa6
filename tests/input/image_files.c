/* Image files (include/thinlight/io.h): tl_image_read_rgba8 and tl_image_decode_rgba8 read back
 * what tl_image_write wrote, through the caller's allocator; bad input (not an image, truncated,
 * over the pixel limit, a FIFO, a device, a directory) is one error line and a result code,
 * never a wait or a crash; tl_image_write reports through its logger and leaves no file behind
 * on failure. */
#define _POSIX_C_SOURCE 200809L

#include <signal.h>
#include <stdint.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gltf_hostile.h"
#include "thinlight/io.h"
#include "tl_test.h"

#ifndef TL_IMAGE_TEST_DIR
#define TL_IMAGE_TEST_DIR "image_work"
#endif

static void work(const char *test, char *dir, size_t n)
{
    snprintf(dir, n, "%s/%s", TL_IMAGE_TEST_DIR, test);
    tlh_rmtree(dir);
    TL_CHECK(tlh_mkdirs(dir) == 0);
}

/* A w*h image with `ch` channels whose every pixel differs. */
static void pattern(uint8_t *px, uint32_t w, uint32_t h, uint32_t ch)
{
    for (size_t i = 0; i < (size_t)w * h * ch; i++) px[i] = (uint8_t)(i * 7u + i / 5u);
}

TL_TEST(image_png_round_trip_every_channel_count)
{
    char dir[1024];
    work("png_round_trip", dir, sizeof dir);
    uint8_t px[13 * 7 * 4];
    for (uint32_t ch = 1; ch <= 4; ch++) {
        char path[1100];
        snprintf(path, sizeof path, "%s/img%u.png", dir, ch);
        pattern(px, 13, 7, ch);
        tl_image_desc d = {.width = 13, .height = 7, .channels = ch};
        TL_CHECK(tl_image_write(path, &d, px) == TL_OK);
        tlh_counter count = {0};
        tl_image_read_desc rd = {.allocator = TLH_ALLOCATOR(&count)};
        tl_rgba8_image img;
        TL_CHECK(tl_image_read_rgba8(path, &rd, &img) == TL_OK);
        TL_CHECK(img.width == 13 && img.height == 7 && img.rgba != NULL);
        int same = img.rgba != NULL;
        for (size_t i = 0; same && i < 13 * 7; i++) {
            const uint8_t *s = px + i * ch, *o = img.rgba + 4 * i;
            uint8_t want[4] = {s[0], ch >= 3 ? s[1] : s[0], ch >= 3 ? s[2] : s[0],
                               ch == 4 ? s[3] : ch == 2 ? s[1] : 255};
            same = !memcmp(o, want, 4);
        }
        TL_CHECK(same);
        TL_CHECK(count.live_blocks == 1 && count.live == 13 * 7 * 4);
        /* decoding the file's bytes gives the same pixels */
        size_t n = 0;
        FILE *f = fopen(path, "rb");
        unsigned char bytes[8192];
        if (f) {
            n = fread(bytes, 1, sizeof bytes, f);
            fclose(f);
        }
        tl_rgba8_image mem;
        TL_CHECK(tl_image_decode_rgba8(bytes, n, NULL, &mem) == TL_OK);
        TL_CHECK(mem.width == 13 && mem.height == 7 && img.rgba && !memcmp(mem.rgba, img.rgba, 13 * 7 * 4));
        tl_rgba8_image_free(&mem);
        tl_rgba8_image_free(&img);
        TL_CHECK(img.rgba == NULL && count.live_blocks == 0);
    }
}

TL_TEST(image_jpeg_reads_within_its_error)
{
    char dir[1024], path[1100];
    work("jpeg", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/grey.jpg", dir);
    uint8_t grey[16 * 16 * 3];
    memset(grey, 100, sizeof grey);
    tl_image_desc d = {.width = 16, .height = 16, .channels = 3};
    TL_CHECK(tl_image_write(path, &d, grey) == TL_OK);
    tl_rgba8_image img;
    TL_CHECK(tl_image_read_rgba8(path, NULL, &img) == TL_OK && img.width == 16);
    for (size_t i = 0; img.rgba && i < 16 * 16; i++) {
        TL_CHECK_LE(abs((int)img.rgba[4 * i] - 100), 2); /* a flat image survives JPEG to +-2 */
        TL_CHECK(img.rgba[4 * i + 3] == 255);
    }
    tl_rgba8_image_free(&img);
}

/* Reads `path` and expects `want` with one error line containing `needle`. */
static void expect_read(const char *path, tl_result want, const char *needle)
{
    tlh_log log = {0};
    tlh_counter count = {0};
    tl_image_read_desc d = {.allocator = TLH_ALLOCATOR(&count), .logger = TLH_LOGGER(&log), .max_pixels = 1024};
    tl_rgba8_image img;
    memset(&img, 0x5A, sizeof img);
    alarm(30); /* a FIFO that blocked would fail here */
    tl_result r = tl_image_read_rgba8(path, &d, &img);
    alarm(0);
    if (r != want || !strstr(log.error, needle)) fprintf(stderr, "%s: %s (%s)\n", path, tl_result_string(r), log.error);
    TL_CHECK(r == want);
    TL_CHECK(strstr(log.error, needle) != NULL && log.errors == 1 && log.multiline == 0);
    TL_CHECK(img.rgba == NULL && img.width == 0 && img.height == 0);
    TL_CHECK(count.live_blocks == 0);
}

TL_TEST(image_bad_files_one_line_each)
{
    char dir[1024], path[1100];
    work("bad", dir, sizeof dir);
    uint8_t px[64 * 64 * 4];
    pattern(px, 64, 64, 4);
    size_t n = 0;
    unsigned char *png = tlh_png(64, 64, px, &n); /* 4096 pixels: over the limit of 1024 */
    snprintf(path, sizeof path, "%s/big.png", dir);
    TL_CHECK(png && tlh_write(path, png, n) == 0);
    expect_read(path, TL_ERROR_LIMIT, "64x64 exceeds the limit of 1024 pixels");
    snprintf(path, sizeof path, "%s/cut.png", dir);
    TL_CHECK(png && tlh_write(path, png, n / 2) == 0);
    expect_read(path, TL_ERROR_PARSE, "truncated PNG");
    free(png);
    png = tlh_png_header(30, 30, 1, &n); /* 3600 bytes of pixels promised by 1 byte */
    snprintf(path, sizeof path, "%s/short.png", dir);
    TL_CHECK(png && tlh_write(path, png, n) == 0);
    expect_read(path, TL_ERROR_PARSE, "cannot hold 30x30 pixels");
    free(png);
    snprintf(path, sizeof path, "%s/text.png", dir);
    TL_CHECK(tlh_write(path, "not an image at all", 19) == 0);
    expect_read(path, TL_ERROR_UNSUPPORTED, "not a PNG or JPEG image");
    snprintf(path, sizeof path, "%s/fifo.png", dir);
    TL_CHECK(mkfifo(path, 0600) == 0);
    expect_read(path, TL_ERROR_IO, "not a regular file");
    expect_read("/dev/zero", TL_ERROR_IO, "not a regular file");
    expect_read(dir, TL_ERROR_IO, "a directory");
    snprintf(path, sizeof path, "%s/missing.png", dir);
    expect_read(path, TL_ERROR_IO, "missing.png: no such file");
}

/* A JPEG of `sof` (C0 baseline, C2 progressive, C9 arithmetic) claiming w x h, 1 component, with
 * `pad` bytes of scan data: only the headers a decoder looks at first. */
static size_t jpeg_header(unsigned char *out, unsigned sof, uint32_t w, uint32_t h, size_t pad)
{
    static const unsigned char soi_app[] = {0xFF, 0xD8, 0xFF, 0xE0, 0x00, 0x10, 'J', 'F', 'I', 'F', 0, 1, 1, 0, 0, 1, 0, 1, 0, 0};
    size_t n = sizeof soi_app;
    memcpy(out, soi_app, n);
    unsigned char sofseg[] = {0xFF, (unsigned char)sof, 0x00, 0x0B, 8, (unsigned char)(h >> 8), (unsigned char)h,
                              (unsigned char)(w >> 8), (unsigned char)w, 1, 1, 0x11, 0};
    memcpy(out + n, sofseg, sizeof sofseg);
    n += sizeof sofseg;
    memset(out + n, 0, pad);
    n += pad;
    out[n++] = 0xFF;
    out[n++] = 0xD9;
    return n;
}

/* JPEG headers are checked before libjpeg sees them: before, a 127-byte progressive JPEG
 * claiming 65281x263 made libjpeg allocate 34 MB of coefficients inside OpenImageIO's open
 * (found by fuzz_image; tests/fuzz/regressions/image). */
TL_TEST(image_jpeg_header_checked_before_decoding)
{
    unsigned char b[8192];
    tlh_counter count = {0};
    tlh_log log = {0};
    tl_image_read_desc d = {.allocator = TLH_ALLOCATOR(&count), .logger = TLH_LOGGER(&log)};
    tl_rgba8_image img;
    size_t n = jpeg_header(b, 0xC2, 263, 65281, 60);
    TL_CHECK(tl_image_decode_rgba8(b, n, &d, &img) == TL_ERROR_PARSE);
    TL_CHECK(strstr(log.error, "cannot hold 263x65281 pixels") != NULL);
    n = jpeg_header(b, 0xC0, 30000, 30000, 60); /* over the default 2^26 pixels */
    TL_CHECK(tl_image_decode_rgba8(b, n, &d, &img) == TL_ERROR_LIMIT && strstr(log.error, "30000x30000"));
    n = jpeg_header(b, 0xC9, 8, 8, 60);
    TL_CHECK(tl_image_decode_rgba8(b, n, &d, &img) == TL_ERROR_UNSUPPORTED && strstr(log.error, "arithmetic"));
    n = jpeg_header(b, 0xC0, 0, 8, 60);
    TL_CHECK(tl_image_decode_rgba8(b, n, &d, &img) == TL_ERROR_PARSE && strstr(log.error, "invalid frame header"));
    memcpy(b, "\xFF\xD8\xFF\xD9", 4); /* no frame at all */
    TL_CHECK(tl_image_decode_rgba8(b, 4, &d, &img) == TL_ERROR_PARSE && strstr(log.error, "no frame header"));
    TL_CHECK(count.largest == 0 && log.multiline == 0); /* nothing was allocated for pixels */
}

TL_TEST(image_bad_arguments)
{
    tl_rgba8_image img;
    tlh_log log = {0};
    tl_image_read_desc d = {.logger = TLH_LOGGER(&log)};
    TL_CHECK(tl_image_decode_rgba8(NULL, 4, &d, &img) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_image_decode_rgba8("abc", 3, &d, NULL) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_image_read_rgba8(NULL, &d, &img) == TL_ERROR_INVALID_ARGUMENT);
    tl_image_read_desc half = {.allocator = {tlh_alloc, NULL, NULL}, .logger = TLH_LOGGER(&log)};
    TL_CHECK(tl_image_decode_rgba8("abc", 3, &half, &img) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(log.errors == 4 && log.multiline == 0);
    TL_CHECK(tl_image_decode_rgba8("", 0, NULL, &img) == TL_ERROR_UNSUPPORTED); /* silent without a logger */
    tl_rgba8_image_free(NULL);
    tl_rgba8_image_free(&img);
    /* the allocator failing */
    tlh_counter count = {.fail_above = 1};
    uint8_t px[4] = {1, 2, 3, 4};
    size_t n = 0;
    unsigned char *png = tlh_png(1, 1, px, &n);
    tl_image_read_desc oom = {.allocator = TLH_ALLOCATOR(&count)};
    TL_CHECK(png && tl_image_decode_rgba8(png, n, &oom, &img) == TL_ERROR_OUT_OF_MEMORY && img.rgba == NULL);
    free(png);
}

TL_TEST(image_write_failures_logged_and_leave_nothing)
{
    char dir[1024], path[1100];
    work("write", dir, sizeof dir);
    uint8_t px[4] = {0};
    tlh_log log = {0};
    tl_image_desc d = {.width = 1, .height = 1, .channels = 4, .logger = TLH_LOGGER(&log)};
    snprintf(path, sizeof path, "%s/no/such/dir/x.png", dir);
    TL_CHECK(tl_image_write(path, &d, px) == TL_ERROR_IO);
    TL_CHECK(log.errors == 1 && strstr(log.error, "x.png") != NULL && log.multiline == 0);
    snprintf(path, sizeof path, "%s/x.unknown-format", dir);
    TL_CHECK(tl_image_write(path, &d, px) == TL_ERROR_UNSUPPORTED && log.errors == 2);
    snprintf(path, sizeof path, "%s/noext", dir);
    TL_CHECK(tl_image_write(path, &d, px) == TL_ERROR_INVALID_ARGUMENT && log.errors == 3);
    tl_image_desc zero = {.logger = TLH_LOGGER(&log)};
    TL_CHECK(tl_image_write(path, &zero, px) == TL_ERROR_INVALID_ARGUMENT && log.errors == 4);
    TL_CHECK(tl_image_write(path, NULL, px) == TL_ERROR_INVALID_ARGUMENT); /* no desc: no logger */
    /* nothing left in the folder: no temporary, no partial file */
    snprintf(path, sizeof path, "%s/ok.png", dir);
    TL_CHECK(tl_image_write(path, &d, px) == TL_OK);
    struct stat st;
    TL_CHECK(stat(path, &st) == 0 && st.st_size > 0);
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "test \"$(ls -A '%s')\" = ok.png", dir);
    TL_CHECK(system(cmd) == 0);
}
