// PNG and JPEG from memory to RGBA8 (image_decode.h). The header is checked first
// (image_check.cpp), so a tiny file that claims to be huge costs nothing; then OpenImageIO
// decodes through an in-memory IOProxy, one row at a time.
#include "image_decode.h"
#include "image_check.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <climits>
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
    // rows are read at spec.y + y: an origin (PNG's oFFs) whose last row is past INT_MAX cannot be read
    if (spec.y > INT_MAX - spec.height || spec.y < INT_MIN + spec.height) {
        *why = "image origin " + std::to_string(spec.y) + " puts its rows out of range";
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
    size_t working = 0; // what the decoder itself will allocate, beyond the pixels
    decode_status s = std::strcmp(format, "png") == 0 ? check_png(data, size, max_pixels, why)
                                                      : check_jpeg(data, size, max_pixels, &working, why);
    if (s != decode_status::ok) return s;
    if (working && !sink.working(working)) {
        *why = "out of memory";
        return decode_status::no_memory;
    }
    // The proxy outlives the reader, which may still touch it when it closes.
    OIIO::Filesystem::IOMemReader proxy(data, size);
    auto in = OIIO::ImageInput::create(format);
    if (!in) OIIO::geterror(); // said below; not left in OIIO's per-thread error for the application
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
