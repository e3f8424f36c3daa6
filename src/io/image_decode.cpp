// PNG and JPEG from memory to RGBA8 (image_decode.h). The header is checked before anything is
// allocated: the size limit, and for PNG that every chunk lies inside the data and that the
// compressed pixels could hold the image (deflate expands at most 1032 times), so a tiny file
// that claims to be huge costs nothing.
#include "image_decode.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cstring>

namespace tl_io {
namespace {

// OIIO's reader for the bytes, recognised by their signature first (a glTF mimeType is
// sometimes wrong), then by the mimeType. A reader is always named: OIIO's open-by-file-name
// falls back to trying every reader in turn, and in OIIO 2.4 some of those crash on an
// in-memory proxy they do not expect.
const char *format_of(const unsigned char *d, size_t n, const std::string &mime)
{
    if (n >= 8 && std::memcmp(d, "\x89PNG\r\n\x1a\n", 8) == 0) return "png";
    if (n >= 3 && d[0] == 0xFF && d[1] == 0xD8 && d[2] == 0xFF) return "jpeg";
    if (n >= 8) return nullptr; // a signature we know not to read
    if (mime == "image/png") return "png";
    if (mime == "image/jpeg") return "jpeg";
    return nullptr;
}

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

// Header checks before any allocation: the limit, then whether the data can hold the pixels.
decode_status check_png(const unsigned char *d, size_t n, size_t max_pixels, std::string *why)
{
    png_header h;
    if (!png_chunks(d, n, &h, why)) return decode_status::corrupt;
    if (h.width == 0 || h.height == 0 || h.bits_per_pixel == 0 || h.bits_per_pixel > 64) {
        *why = "PNG: invalid IHDR";
        return decode_status::corrupt;
    }
    if (h.width > 65536 || h.height > 65536 || (uint64_t)h.width * h.height > max_pixels) {
        *why = std::to_string(h.width) + "x" + std::to_string(h.height) + " exceeds the limit of " +
               std::to_string(max_pixels) + " pixels";
        return decode_status::too_large;
    }
    uint64_t raw = ((uint64_t)h.width * h.height * h.bits_per_pixel + 7) / 8;
    if (raw > 1032 * (uint64_t)h.idat_bytes + 1024) {
        *why = "PNG: " + std::to_string(h.idat_bytes) + " bytes of IDAT cannot hold " + std::to_string(h.width) + "x" +
               std::to_string(h.height) + " pixels";
        return decode_status::corrupt;
    }
    return decode_status::ok;
}

std::string error_of(OIIO::ImageInput &in, const char *fallback)
{
    std::string e = in.geterror();
    for (char &ch : e)
        if (ch == '\n' || ch == '\r') ch = ' ';
    while (!e.empty() && e.back() == ' ') e.pop_back();
    return e.empty() ? std::string(fallback) : e;
}

// `ch` channels a pixel, packed at the start of `px`, widened in place to RGBA (from the last
// pixel back, so that no pixel is overwritten before it is read).
void widen(uint8_t *px, size_t count, int ch)
{
    for (size_t i = count; i-- > 0;) {
        const uint8_t *s = px + i * (size_t)ch;
        uint8_t v[4] = {s[0], ch > 1 ? s[1] : s[0], ch > 2 ? s[2] : s[0], ch > 3 ? s[3] : (uint8_t)255};
        if (ch == 2) v[1] = v[2] = s[0], v[3] = s[1];
        std::memcpy(px + 4 * i, v, 4);
    }
}

// The pixels as 8-bit values, `ch` a pixel, packed, read one row at a time: OIIO 2.4's
// read_image converts through a buffer of 64 MiB whatever the image's size (found by valgrind's
// heap totals: 233 MB allocated to load a scene with three small textures), read_scanline
// through one row (or none, when the file's format is already 8-bit).
bool read_packed(OIIO::ImageInput &in, const OIIO::ImageSpec &spec, uint8_t *px, std::string *why)
{
    size_t row = (size_t)spec.width * (size_t)spec.nchannels;
    for (int y = 0; y < spec.height; y++)
        if (!in.read_scanline(spec.y + y, 0, OIIO::TypeDesc::UINT8, px + (size_t)y * row,
                              (OIIO::stride_t)spec.nchannels)) {
            *why = error_of(in, "cannot decode the pixels");
            return false;
        }
    return true;
}

decode_status read_pixels(OIIO::ImageInput &in, const OIIO::ImageSpec &spec, size_t max_pixels, pixel_sink &sink,
                          decoded_size *out, std::string *why)
{
    if (spec.width <= 0 || spec.height <= 0 || spec.depth != 1 || spec.nchannels <= 0 || spec.nchannels > 4) {
        *why = "unsupported image layout";
        return decode_status::corrupt;
    }
    size_t w = (size_t)spec.width, h = (size_t)spec.height;
    if (w > 65536 || h > 65536 || w * h > max_pixels) {
        *why = std::to_string(w) + "x" + std::to_string(h) + " exceeds the limit of " + std::to_string(max_pixels) +
               " pixels";
        return decode_status::too_large;
    }
    uint8_t *px = sink.pixels(w, h);
    if (!px) {
        *why = "out of memory";
        return decode_status::no_memory;
    }
    if (!read_packed(in, spec, px, why)) return decode_status::corrupt;
    widen(px, w * h, spec.nchannels);
    out->width = (uint32_t)w;
    out->height = (uint32_t)h;
    return decode_status::ok;
}

} // namespace

decode_status decode_rgba8(const unsigned char *data, size_t size, const std::string &mime, size_t max_pixels,
                           const std::string &name, pixel_sink &sink, decoded_size *out, std::string *why)
{
    const char *format = data && size ? format_of(data, size, mime) : nullptr;
    if (!format) {
        *why = "not a PNG or JPEG image" + (mime.empty() ? std::string() : " (mimeType " + mime + ")");
        return decode_status::unsupported;
    }
    if (std::strcmp(format, "png") == 0) {
        decode_status s = check_png(data, size, max_pixels, why);
        if (s != decode_status::ok) return s;
    }
    // The proxy outlives the reader, which may still touch it when it closes.
    OIIO::Filesystem::IOMemReader proxy(data, size);
    auto in = OIIO::ImageInput::create(format);
    if (!in || !in->supports("ioproxy")) {
        *why = std::string("no reader for ") + format + " images in memory";
        return decode_status::unsupported;
    }
    in->set_ioproxy(&proxy);
    // Straight (unassociated) alpha, as glTF colour textures carry it; OIIO would premultiply PNG.
    OIIO::ImageSpec config, spec;
    config.attribute("oiio:UnassociatedAlpha", 1);
    if (!in->open(name, spec, config)) {
        *why = error_of(*in, std::strcmp(format, "png") == 0 ? "cannot decode as PNG" : "cannot decode as JPEG");
        return decode_status::corrupt;
    }
    return read_pixels(*in, spec, max_pixels, sink, out, why);
}

} // namespace tl_io
