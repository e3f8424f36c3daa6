// PNG and JPEG headers checked before decoding (image_check.h). One pass over the chunks or
// markers, no allocation.
#include "image_check.h"

#include <cstdint>
#include <cstring>

namespace tl_io {
namespace {

uint32_t be32(const unsigned char *p) { return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3]; }

// What the PNG's chunks say, read without decoding anything.
struct png_header {
    uint32_t width = 0, height = 0;
    unsigned bits_per_pixel = 0;
    size_t idat_bytes = 0;
};

// Every chunk lies inside the data, up to IEND, and IHDR comes first. OIIO 2.4's PNG reader
// leaks (libpng longjmps over a std::string) when libpng asks for bytes past the end, so
// truncated PNGs are refused here; corrupt data inside whole chunks is libpng's to reject.
bool png_chunks(const unsigned char *d, size_t n, png_header *h, std::string *why)
{
    size_t at = 8;
    bool ihdr = false;
    while (n >= at && n - at >= 12) {
        uint32_t len = be32(d + at);
        const unsigned char *type = d + at + 4;
        if (len > n - at - 12) break;
        if (!ihdr) {
            static const unsigned channels[7] = {1, 0, 3, 1, 2, 0, 4}; // by colour type
            if (std::memcmp(type, "IHDR", 4) != 0 || len != 13 || type[13] > 6 || !channels[type[13]]) {
                *why = "PNG: no valid IHDR chunk first";
                return false;
            }
            h->width = be32(type + 4);
            h->height = be32(type + 8);
            h->bits_per_pixel = channels[type[13]] * type[12];
            ihdr = true;
        }
        if (std::memcmp(type, "IDAT", 4) == 0) h->idat_bytes += len;
        at += 12 + (size_t)len;
        if (std::memcmp(type, "IEND", 4) == 0) return true;
    }
    *why = "truncated PNG";
    return false;
}

uint32_t be16(const unsigned char *p) { return (uint32_t)p[0] << 8 | p[1]; }

std::string dims(uint32_t w, uint32_t h) { return std::to_string(w) + "x" + std::to_string(h); }

decode_status over_limit(uint32_t w, uint32_t h, size_t max_pixels, std::string *why)
{
    if (w <= 65536 && h <= 65536 && (uint64_t)w * h <= max_pixels) return decode_status::ok;
    *why = dims(w, h) + " exceeds the limit of " + std::to_string(max_pixels) + " pixels";
    return decode_status::too_large;
}

// What the JPEG's first frame header says.
struct jpeg_frame {
    uint32_t width = 0, height = 0, components = 0;
    unsigned sof = 0; // the SOFn marker's second byte
};

// SOF0..SOF15 without DHT (C4), JPG (C8) and DAC (CC).
bool is_sof(unsigned m) { return m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC; }

// Follows the marker segments from SOI to the first SOFn, as libjpeg does.
bool find_frame(const unsigned char *d, size_t n, jpeg_frame *f, std::string *why)
{
    size_t at = 2;
    while (at < n) {
        if (d[at] != 0xFF) break;
        while (at < n && d[at] == 0xFF) at++; // fill bytes
        if (at >= n) break;
        unsigned m = d[at++];
        if (m == 0x01 || (m >= 0xD0 && m <= 0xD7)) continue; // no length
        if (m == 0xD9 || m == 0xDA || n - at < 2) break;    // EOI or a scan before any frame
        size_t len = be16(d + at);
        if (len < 2 || len > n - at) break;
        if (is_sof(m)) {
            if (len < 8) break;
            f->height = be16(d + at + 3);
            f->width = be16(d + at + 5);
            f->components = d[at + 7];
            f->sof = m;
            return true;
        }
        at += len;
    }
    *why = "JPEG: no frame header";
    return false;
}

} // namespace

decode_status check_png(const unsigned char *d, size_t n, size_t max_pixels, std::string *why)
{
    png_header h;
    if (!png_chunks(d, n, &h, why)) return decode_status::corrupt;
    if (h.width == 0 || h.height == 0 || h.bits_per_pixel == 0 || h.bits_per_pixel > 64) {
        *why = "PNG: invalid IHDR";
        return decode_status::corrupt;
    }
    decode_status s = over_limit(h.width, h.height, max_pixels, why);
    if (s != decode_status::ok) return s;
    uint64_t raw = ((uint64_t)h.width * h.height * h.bits_per_pixel + 7) / 8;
    if (raw > 1032 * (uint64_t)h.idat_bytes + 1024) {
        *why = "PNG: " + std::to_string(h.idat_bytes) + " bytes of IDAT cannot hold " + std::to_string(h.width) + "x" +
               std::to_string(h.height) + " pixels";
        return decode_status::corrupt;
    }
    return decode_status::ok;
}


decode_status check_jpeg(const unsigned char *d, size_t n, size_t max_pixels, size_t *working, std::string *why)
{
    jpeg_frame f;
    *working = 0;
    if (!find_frame(d, n, &f, why)) return decode_status::corrupt;
    if (f.sof >= 0xC9) {
        *why = "arithmetic-coded JPEG is not supported";
        return decode_status::unsupported;
    }
    if (f.width == 0 || f.height == 0 || f.components == 0 || f.components > 4) {
        *why = "JPEG: invalid frame header (" + dims(f.width, f.height) + ", " + std::to_string(f.components) +
               " components)";
        return decode_status::corrupt;
    }
    decode_status s = over_limit(f.width, f.height, max_pixels, why);
    if (s != decode_status::ok) return s;
    uint64_t pixels = (uint64_t)f.width * f.height;
    if (pixels > 8192 * (uint64_t)n) {
        *why = "JPEG: " + std::to_string(n) + " bytes cannot hold " + dims(f.width, f.height) + " pixels";
        return decode_status::corrupt;
    }
    // Progressive (SOF2, SOF6): libjpeg keeps every coefficient, 2 bytes each, of every block.
    if (f.sof == 0xC2 || f.sof == 0xC6) *working = (size_t)(pixels * f.components * 2);
    return decode_status::ok;
}

} // namespace tl_io
