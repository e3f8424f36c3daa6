// High-dynamic-range images read as linear RGB floats through OpenImageIO (tl_image_read_rgb_float):
// environments for tl_renderer_set_environment. As image.cpp: only regular files, the size checked
// from the header before any pixel is read, errors as one line to the logger, OIIO's per-thread
// error left empty, memory from the caller's allocator.
#include <OpenImageIO/imageio.h>

#include <string>
#include <vector>

#include "core/alloc.h"
#include "core/log.h"
#include "io_file.h"
#include "thinlight/io.h"

namespace {

tl_result fail(const tl_logger &logger, tl_result r, const std::string &msg)
{
    return tl__logger_fail(&logger, r, "%s", msg.c_str());
}

std::string error_of(OIIO::ImageInput &in, const char *fallback)
{
    std::string e = in.geterror();
    OIIO::geterror();
    size_t nl = e.find('\n');
    if (nl != std::string::npos) e.resize(nl);
    return e.empty() ? fallback : e;
}

// The opened image's pixels as RGB floats into out (allocated with a).
tl_result read_rgb(OIIO::ImageInput &in, const OIIO::ImageSpec &spec, const tl_image_read_desc &d,
                   const tl_allocator &a, const std::string &name, tl_float_image *out)
{
    size_t max_pixels = d.max_pixels ? d.max_pixels : (size_t)1 << 26;
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1)
        return fail(d.logger, TL_ERROR_PARSE, name + ": not a 2D image");
    size_t w = (size_t)spec.width, h = (size_t)spec.height, nc = spec.nchannels >= 3 ? 3 : 1;
    if (w > 65536 || h > 65536 || w * h > max_pixels)
        return fail(d.logger, TL_ERROR_LIMIT, name + ": " + std::to_string(w) + "x" + std::to_string(h) +
                                                  " is over the limit of " + std::to_string(max_pixels) + " pixels");
    std::vector<float> px(w * h * nc);
    if (!in.read_image(0, 0, 0, (int)nc, OIIO::TypeDesc::FLOAT, px.data()))
        return fail(d.logger, TL_ERROR_PARSE, name + ": " + error_of(in, "cannot read its pixels"));
    float *rgb = static_cast<float *>(tl__alloc_array(&a, w * h * 3, sizeof(float)));
    if (!rgb) return fail(d.logger, TL_ERROR_OUT_OF_MEMORY, name + ": out of memory");
    for (size_t i = 0; i < w * h; i++)
        for (size_t c = 0; c < 3; c++) rgb[i * 3 + c] = px[i * nc + (nc == 3 ? c : 0)];
    out->width = (uint32_t)w;
    out->height = (uint32_t)h;
    out->rgb = rgb;
    out->allocator = a;
    return TL_OK;
}

tl_result read_file(const char *path, const tl_image_read_desc &d, const tl_allocator &a, tl_float_image *out)
{
    std::string name(path), why;
    tl_io::regular_file f; // a FIFO or a device named as the file never makes the read wait
    if (tl_io::open_regular(path, &f, &why) != TL_OK) return fail(d.logger, TL_ERROR_IO, name + ": " + why);
    auto in = OIIO::ImageInput::open(name);
    if (!in) {
        std::string e = OIIO::geterror();
        size_t nl = e.find('\n');
        if (nl != std::string::npos) e.resize(nl);
        return fail(d.logger, TL_ERROR_PARSE, name + ": " + (e.empty() ? "not an image OpenImageIO reads" : e));
    }
    tl_result r = read_rgb(*in, in->spec(), d, a, name, out);
    in->close();
    return r;
}

} // namespace

extern "C" tl_result tl_image_read_rgb_float(const char *path, const tl_image_read_desc *desc, tl_float_image *out)
{
    tl_image_read_desc d = desc ? *desc : tl_image_read_desc{};
    if (out) *out = tl_float_image{};
    if (!path || !out) return fail(d.logger, TL_ERROR_INVALID_ARGUMENT, "tl_image_read_rgb_float: NULL path or out");
    tl_allocator a;
    if (tl__allocator_resolve(&d.allocator, &a) != TL_OK)
        return fail(d.logger, TL_ERROR_INVALID_ARGUMENT, "tl_image_read_rgb_float: allocator needs both alloc and free");
    try {
        return read_file(path, d, a, out);
    } catch (const std::bad_alloc &) {
        return fail(d.logger, TL_ERROR_OUT_OF_MEMORY, std::string(path) + ": out of memory");
    } catch (const std::exception &ex) {
        return fail(d.logger, TL_ERROR_PARSE, std::string(path) + ": " + ex.what());
    } catch (...) {
        return fail(d.logger, TL_ERROR_PARSE, std::string(path) + ": unknown error");
    }
}

extern "C" void tl_float_image_free(tl_float_image *image)
{
    if (!image) return;
    if (image->rgb) tl__free(&image->allocator, image->rgb);
    *image = tl_float_image{};
}
