/* libFuzzer target: tl_image_decode_rgba8 on arbitrary bytes (PNG and JPEG through OpenImageIO,
 * libpng and libjpeg). Properties: a result code, pixels exactly on success with the size the
 * result says, one-line messages, nothing leaked through the allocator. A PNG is decoded twice:
 * as it is, and with every chunk's CRC recomputed, because libpng rejects a chunk whose CRC is
 * wrong before it looks inside, so most mutations would never reach the decoder otherwise (and
 * libpng is not instrumented: coverage cannot guide the fuzzer to a valid CRC). */
#include <stdlib.h>
#include <string.h>

#include "fuzz_common.h"
#include "thinlight/io.h"

static void decode_once(const uint8_t *data, size_t size)
{
    fuzz_counter count = {0};
    tl_image_read_desc d = {
        .allocator = {fuzz_alloc, fuzz_free, &count},
        .logger = {fuzz_log, NULL},
        .max_pixels = (size_t)1 << 20,
        .name = "fuzz",
    };
    tl_rgba8_image img;
    memset(&img, 0xAB, sizeof img); /* must be zeroed on failure */
    tl_result r = tl_image_decode_rgba8(data, size, &d, &img);
    FUZZ_REQUIRE((unsigned)r < TL_RESULT_COUNT_);
    FUZZ_REQUIRE((r == TL_OK) == (img.rgba != NULL));
    if (r == TL_OK) {
        FUZZ_REQUIRE(img.width > 0 && img.height > 0 && (size_t)img.width * img.height <= d.max_pixels);
        /* every byte of the size returned is readable (AddressSanitizer checks the sum) */
        size_t n = (size_t)img.width * img.height * 4;
        volatile unsigned sum = 0;
        for (size_t i = 0; i < n; i++) sum += img.rgba[i];
        (void)sum;
    } else {
        FUZZ_REQUIRE(img.width == 0 && img.height == 0);
    }
    tl_rgba8_image_free(&img);
    FUZZ_REQUIRE(count.live == 0);
}

static uint32_t crc32_of(const uint8_t *p, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xFFFFFFFFu;
}

/* A copy of the PNG with each whole chunk's CRC recomputed; NULL when nothing changes. */
static uint8_t *fixed_crcs(const uint8_t *data, size_t size)
{
    if (size < 8 || memcmp(data, "\x89PNG\r\n\x1a\n", 8) != 0) return NULL;
    uint8_t *b = malloc(size);
    if (!b) return NULL;
    memcpy(b, data, size);
    int changed = 0;
    for (size_t at = 8; size - at >= 12;) {
        uint32_t len = (uint32_t)b[at] << 24 | (uint32_t)b[at + 1] << 16 | (uint32_t)b[at + 2] << 8 | b[at + 3];
        if (len > size - at - 12) break;
        uint32_t crc = crc32_of(b + at + 4, (size_t)len + 4);
        uint8_t *c = b + at + 8 + len;
        uint8_t want[4] = {(uint8_t)(crc >> 24), (uint8_t)(crc >> 16), (uint8_t)(crc >> 8), (uint8_t)crc};
        if (memcmp(c, want, 4) != 0) {
            memcpy(c, want, 4);
            changed = 1;
        }
        at += 12 + (size_t)len;
    }
    if (!changed) {
        free(b);
        return NULL;
    }
    return b;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    decode_once(data, size);
    uint8_t *fixed = fixed_crcs(data, size);
    if (fixed) decode_once(fixed, size);
    free(fixed);
    return 0;
}
