// Checks of a PNG or JPEG header before any decoder runs (src/io only; image_decode.cpp): the
// pixel limit, and whether the data could hold the pixels the header promises, so that a few
// bytes claiming a huge image are refused before libpng or libjpeg allocate for it.
#ifndef TL_IMAGE_CHECK_H
#define TL_IMAGE_CHECK_H

#include <cstddef>
#include <string>

#include "image_decode.h"

namespace tl_io {

// Every chunk inside the data up to IEND, IHDR first and valid, the size within max_pixels and
// 65536 per side, and enough IDAT bytes for the pixels (deflate expands at most 1032 times).
decode_status check_png(const unsigned char *d, size_t n, size_t max_pixels, std::string *why);

// The first frame header (SOFn): Huffman-coded (arithmetic coding is not supported), the size
// within max_pixels and 65536 per side, and enough bytes for the pixels (a complete JPEG codes
// every 8x8 block of every component in at least one bit; 8192 pixels a byte leaves a margin of
// four over the worst sampling). *working: what libjpeg will allocate for a progressive image's
// coefficients (0 for a baseline one), to be counted before it is opened.
decode_status check_jpeg(const unsigned char *d, size_t n, size_t max_pixels, size_t *working, std::string *why);

} // namespace tl_io

#endif
