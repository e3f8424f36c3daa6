// glTF images to RGBA8 pixels owned by the caller's allocator and counted against the load's
// budget, through the shared PNG/JPEG decoder (image_decode.h): every image a material uses is
// decoded and charged on its own, even when several images share the same bytes.
#include "gltf_internal.h"
#include "image_decode.h"

namespace tl_gltf {
namespace {

struct budget_sink final : tl_io::pixel_sink {
    const context &c;
    const std::string &what;
    uint8_t *px = nullptr;
    size_t bytes = 0;
    budget_hold hold;
    budget_sink(const context &ctx, const std::string &w) : c(ctx), what(w), hold(ctx) {}
    ~budget_sink() { free_bytes(c, px, bytes); }
    // A progressive JPEG's coefficients live in libjpeg's heap during the decode: counted too.
    bool working(size_t n) override
    {
        hold.add(n, what + " (the JPEG decoder's coefficients)");
        return true;
    }
    uint8_t *pixels(size_t width, size_t height) override
    {
        px = static_cast<uint8_t *>(alloc_bytes(c, width * height, 4, what + " (" + std::to_string(width) + "x" +
                                                                       std::to_string(height) + " pixels)"));
        bytes = width * height * 4;
        return px;
    }
};

} // namespace

bool decode_image_memory(const context &c, const unsigned char *data, size_t size, const std::string &mime,
                         const std::string &what, decoded_image *out, std::string *why)
{
    budget_sink sink(c, what);
    tl_io::decoded_size got;
    switch (tl_io::decode_rgba8(data, size, mime, c.max_texture_pixels, what, sink, &got, why)) {
    case tl_io::decode_status::ok: break;
    case tl_io::decode_status::too_large: fail(TL_ERROR_LIMIT, what + ": " + *why + " (max_texture_pixels)");
    case tl_io::decode_status::no_memory: fail(TL_ERROR_OUT_OF_MEMORY, what + ": out of memory");
    default: return false;
    }
    out->width = got.width;
    out->height = got.height;
    out->rgba = sink.px;
    sink.px = nullptr;
    return true;
}

} // namespace tl_gltf
