// Image decoding for glTF textures through OpenImageIO, from memory (GLB buffer views, data URIs,
// and files read into memory), straight into RGBA8 pixels owned by the caller's allocator. The
// size limit is checked on the header, before any pixel is decoded.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "gltf_internal.h"

namespace tl_gltf {
namespace {

// OIIO's reader for the bytes: glTF images are PNG or JPEG, recognised by their signature first
// (the optional mimeType is sometimes wrong), then by the mimeType. A reader is always named:
// OIIO's open-by-file-name falls back to trying every reader in turn, and in OIIO 2.4 some of
// those crash on an in-memory proxy they do not expect.
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

// Every PNG chunk lies inside the data, up to IEND. OIIO 2.4's PNG reader leaks (libpng
// longjmps over a std::string) when libpng asks for bytes past the end, so truncated PNGs are
// refused here; corrupt data inside whole chunks is libpng's to reject, cleanly.
bool png_intact(const unsigned char *d, size_t n)
{
    size_t at = 8;
    if (n < at) return false;
    while (n - at >= 12) {
        uint32_t len = be32(d + at);
        if (len > n - at - 12) return false;
        bool end = std::memcmp(d + at + 4, "IEND", 4) == 0;
        at += 12 + (size_t)len;
        if (end) return true;
    }
    return false;
}

struct bytes_guard {
    const context &c;
    uint8_t *p;
    ~bytes_guard() { free_bytes(c, p); }
};

// Reads the opened image into RGBA8 pixels owned by the context's allocator.
bool decode(const context &c, OIIO::ImageInput &in, const OIIO::ImageSpec &spec, const std::string &what,
            decoded_image *out, std::string *why)
{
    if (spec.width <= 0 || spec.height <= 0 || spec.depth != 1 || spec.nchannels <= 0) {
        *why = "unsupported image layout";
        return false;
    }
    size_t w = (size_t)spec.width, h = (size_t)spec.height;
    if (w > 65536 || h > 65536 || w * h > c.max_texture_pixels)
        fail(TL_ERROR_LIMIT, what + ": " + std::to_string(w) + "x" + std::to_string(h) + " exceeds the texture limit of " +
                                 std::to_string(c.max_texture_pixels) + " pixels");
    bytes_guard px{c, static_cast<uint8_t *>(alloc_bytes(c, w * h, 4, what.c_str()))};
    int ch = spec.nchannels < 4 ? spec.nchannels : 4;
    // Read straight into the RGBA slots (x stride 4) and widen grey / grey-alpha / RGB in place.
    if (!in.read_image(0, 0, 0, ch, OIIO::TypeDesc::UINT8, px.p, 4, (OIIO::stride_t)(4 * w))) {
        *why = in.geterror();
        if (why->empty()) *why = "cannot decode the pixels";
        return false;
    }
    for (size_t i = 0; i < w * h; i++) {
        uint8_t *d = px.p + 4 * i;
        if (ch == 1) {
            d[1] = d[2] = d[0];
            d[3] = 255;
        } else if (ch == 2) {
            d[3] = d[1];
            d[1] = d[2] = d[0];
        } else if (ch == 3) {
            d[3] = 255;
        }
    }
    out->width = (uint32_t)w;
    out->height = (uint32_t)h;
    out->rgba = px.p;
    px.p = nullptr;
    return true;
}

} // namespace

bool decode_image_memory(const context &c, const unsigned char *data, size_t size, const std::string &mime,
                         const std::string &what, decoded_image *out, std::string *why)
{
    const char *format = data && size ? format_of(data, size, mime) : nullptr;
    if (!format) {
        *why = "not a PNG or JPEG image" + (mime.empty() ? std::string() : " (mimeType " + mime + ")");
        return false;
    }
    if (std::strcmp(format, "png") == 0 && !png_intact(data, size)) {
        *why = "truncated PNG";
        return false;
    }
    // The proxy outlives the reader, which may still touch it when it closes.
    OIIO::Filesystem::IOMemReader proxy(data, size);
    auto in = OIIO::ImageInput::create(format);
    if (!in || !in->supports("ioproxy")) {
        *why = std::string("no reader for ") + format + " images in memory";
        return false;
    }
    in->set_ioproxy(&proxy);
    // glTF colour textures carry straight (unassociated) alpha; OIIO would premultiply PNG.
    OIIO::ImageSpec config, spec;
    config.attribute("oiio:UnassociatedAlpha", 1);
    if (!in->open(what, spec, config)) {
        *why = in->geterror();
        if (why->empty()) *why = std::string("cannot decode as ") + format;
        return false;
    }
    return decode(c, *in, spec, what, out, why);
}

bool decode_image_file(const context &c, const std::string &file, const std::string &what, decoded_image *out,
                       std::string *why)
{
    // Through memory, so that files and embedded images take the same, reader-named path.
    FILE *f = std::fopen(file.c_str(), "rb");
    if (!f) {
        *why = file + ": " + std::strerror(errno);
        return false;
    }
    long size = -1;
    if (std::fseek(f, 0, SEEK_END) == 0) size = std::ftell(f);
    if (size <= 0 || std::fseek(f, 0, SEEK_SET) != 0) {
        std::fclose(f);
        *why = file + ": empty or not a regular file";
        return false;
    }
    bytes_guard bytes{c, nullptr};
    try {
        bytes.p = static_cast<uint8_t *>(alloc_bytes(c, (size_t)size, 1, what.c_str()));
    } catch (...) {
        std::fclose(f);
        throw;
    }
    size_t got = std::fread(bytes.p, 1, (size_t)size, f);
    std::fclose(f);
    if (got != (size_t)size) {
        *why = file + ": read error";
        return false;
    }
    return decode_image_memory(c, bytes.p, got, "", what, out, why);
}

} // namespace tl_gltf
