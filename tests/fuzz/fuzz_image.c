/* libFuzzer target: tl_image_decode_rgba8 on arbitrary bytes (PNG and JPEG through OpenImageIO,
 * libpng and libjpeg). Properties: a result code, pixels exactly on success with the size the
 * result says, one-line messages, nothing leaked through the allocator. */
#include <string.h>

#include "fuzz_common.h"
#include "thinlight/io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
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
        /* every byte is readable (ASan) and written: sum them */
        size_t n = (size_t)img.width * img.height * 4;
        volatile unsigned sum = 0;
        for (size_t i = 0; i < n; i++) sum += img.rgba[i];
        (void)sum;
    } else {
        FUZZ_REQUIRE(img.width == 0 && img.height == 0);
    }
    tl_rgba8_image_free(&img);
    FUZZ_REQUIRE(count.live == 0);
    return 0;
}
