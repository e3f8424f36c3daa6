// PNG and JPEG decoding from memory through OpenImageIO, shared by the image reader (image.cpp)
// and the glTF textures (gltf_image.cpp). src/io only.
#ifndef TL_IMAGE_DECODE_H
#define TL_IMAGE_DECODE_H

#include <cstddef>
#include <cstdint>
#include <string>

namespace tl_io {

// Where the pixels go: asked once, after the header was checked and before any pixel is decoded.
// Returns width * height * 4 bytes that the caller owns, or nullptr when out of memory; may throw.
// `working` is told first what the decoder itself will allocate beyond the pixels (a progressive
// JPEG's coefficients), for a caller that counts memory; false refuses it (out of memory).
struct pixel_sink {
    virtual uint8_t *pixels(size_t width, size_t height) = 0;
    virtual bool working(size_t bytes)
    {
        (void)bytes;
        return true;
    }

protected:
    ~pixel_sink() = default;
};

enum class decode_status {
    ok,
    unsupported, // neither PNG nor JPEG, or an arithmetic-coded JPEG
    corrupt,     // truncated or malformed, or a header that promises more than the data holds
    too_large,   // over max_pixels or 65536 per side
    no_memory,   // the sink returned nullptr
};

struct decoded_size {
    uint32_t width = 0, height = 0;
};

// Decodes `data` (PNG or JPEG by signature, then by `mime` for data too short to have one) into
// RGBA8 pixels from `sink`: grey, grey-alpha and RGB widened, alpha straight. `name` names the
// data in OpenImageIO's messages. Anything but ok sets *why (one line, without the name).
decode_status decode_rgba8(const unsigned char *data, size_t size, const std::string &mime, size_t max_pixels,
                           const std::string &name, pixel_sink &sink, decoded_size *out, std::string *why);

} // namespace tl_io

#endif
