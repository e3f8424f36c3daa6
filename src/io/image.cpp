// Image files through OpenImageIO: tl_image_write, and PNG/JPEG reading through the decoder the
// glTF textures use (image_decode.h). Exceptions and OIIO error strings become a tl_result plus
// one line to the logger here (core/log.h, as every layer), and OIIO's per-thread error is left
// empty; nothing C++ crosses the C API. Memory comes from the caller's allocator (core/alloc.h).
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/alloc.h"
#include "core/log.h"
#include "image_decode.h"
#include "io_file.h"
#include "thinlight/file.h"
#include "thinlight/io.h"

namespace {

tl_result report(const tl_logger &logger, tl_result r, const std::string &msg)
{
    return tl__logger_fail(&logger, r, "%s", msg.c_str());
}

std::string extension_of(const std::string &path)
{
    size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    return path.substr(dot);
}

bool valid_layout(const tl_image_desc *d)
{
    return d->width && d->height && d->channels >= 1 && d->channels <= 4 && d->width <= 65536 && d->height <= 65536 &&
           (unsigned)d->type < TL_PIXEL_TYPE_COUNT_;
}

// Encodes the pixels into `bytes` with OIIO, in memory: no OIIO writer or codec library ever
// touches the disk (a full disk cannot reach libjpeg's error handler, which exits the process,
// nor libpng's writes, whose errors OIIO ignores). "" or the reason.
std::string encode(OIIO::ImageOutput *out, const tl_image_desc &desc, const void *pixels, std::vector<unsigned char> *bytes)
{
    OIIO::TypeDesc in_type = desc.type == TL_PIXEL_F32 ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
    OIIO::TypeDesc file_type = in_type;
    std::string format = out->format_name();
    if (format == "png" || format == "jpeg") file_type = OIIO::TypeDesc::UINT8;
    if (format == "openexr") file_type = desc.full_float && in_type == OIIO::TypeDesc::FLOAT ? OIIO::TypeDesc::FLOAT
                                                                                          : OIIO::TypeDesc::HALF;
    OIIO::ImageSpec spec((int)desc.width, (int)desc.height, (int)desc.channels, file_type);
    // The pixels are stored as given. Without this OIIO takes RGBA for premultiplied and divides
    // colour by alpha when it writes PNG (found by the test image_png_round_trip_*).
    spec.attribute("oiio:UnassociatedAlpha", 1);
    OIIO::Filesystem::IOVecOutput memory(*bytes);
    void *proxy = &memory;
    spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    if (!out->open("memory", spec)) return "cannot encode: " + out->geterror();
    size_t elem = desc.type == TL_PIXEL_F32 ? 4 : 1;
    OIIO::stride_t ystride = (OIIO::stride_t)(desc.width * desc.channels * elem);
    const char *base = static_cast<const char *>(pixels);
    if (desc.bottom_up) {
        base += (size_t)(desc.height - 1) * (size_t)ystride;
        ystride = -ystride;
    }
    bool ok = out->write_image(in_type, base, OIIO::AutoStride, ystride);
    std::string e = ok ? "" : out->geterror();
    ok = out->close() && ok;
    if (!ok) return "cannot encode: " + (e.empty() ? out->geterror() : e);
    if (bytes->empty()) return "the encoder produced no bytes";
    return "";
}

// What OIIO cannot write safely, before it is asked to: "" or the reason.
std::string refuse(const OIIO::ImageOutput &out, const tl_image_desc &desc)
{
    // Through memory only; a writer that cannot take an ioproxy would write the file itself.
    if (!out.supports("ioproxy"))
        return std::string("OIIO's ") + out.format_name() + " writer cannot encode into memory";
    // libjpeg ends the process (error_exit) on an image it cannot hold; OIIO installs no handler.
    bool jpeg = !std::strcmp(out.format_name(), "jpeg");
    if (jpeg && (desc.width > 65500 || desc.height > 65500)) return "JPEG holds at most 65500 pixels a side";
    return "";
}

} // namespace

extern "C" tl_result tl_image_write(const char *path, const tl_image_desc *desc, const void *pixels)
{
    tl_logger logger = desc ? desc->logger : tl_logger{};
    if (!path || !desc || !pixels || !valid_layout(desc))
        return report(logger, TL_ERROR_INVALID_ARGUMENT, "tl_image_write: invalid arguments");
    try {
        std::string target(path), ext = extension_of(target);
        if (ext.empty()) return report(logger, TL_ERROR_INVALID_ARGUMENT, target + ": no file extension");
        auto out = OIIO::ImageOutput::create(target);
        if (!out) {
            OIIO::geterror(); // said below; not left in OIIO's per-thread error for the application
            return report(logger, TL_ERROR_UNSUPPORTED, target + ": no writer for '" + ext + "'");
        }
        std::string why = refuse(*out, *desc);
        if (!why.empty()) return report(logger, TL_ERROR_UNSUPPORTED, target + ": " + why);
        std::vector<unsigned char> bytes;
        why = encode(out.get(), *desc, pixels, &bytes);
        if (!why.empty()) return report(logger, TL_ERROR_IO, target + ": " + why);
        // The one writer of every output (thinlight/file.h): whole or absent, regular files only.
        tl_file_write_desc fd = {logger};
        return tl_file_write(path, bytes.data(), bytes.size(), &fd);
    } catch (const std::bad_alloc &) {
        return report(logger, TL_ERROR_OUT_OF_MEMORY, std::string(path) + ": out of memory");
    } catch (const std::exception &ex) {
        return report(logger, TL_ERROR_IO, std::string(path) + ": " + ex.what());
    } catch (...) {
        return report(logger, TL_ERROR_IO, std::string(path) + ": unknown error");
    }
}

namespace {

// Pixels from the caller's allocator, owned here until handed over.
struct allocator_sink final : tl_io::pixel_sink {
    tl_allocator a;
    uint8_t *px = nullptr;
    explicit allocator_sink(const tl_allocator &alloc) : a(alloc) {}
    ~allocator_sink()
    {
        tl__free(&a, px);
    }
    uint8_t *pixels(size_t width, size_t height) override
    {
        px = static_cast<uint8_t *>(tl__alloc_array(&a, width * height, 4));
        return px;
    }
};

tl_result decode(const unsigned char *data, size_t size, const tl_image_read_desc &d, const std::string &name,
                 tl_rgba8_image *out)
{
    tl_allocator a;
    tl__allocator_resolve(&d.allocator, &a); // begin_read refused a half allocator
    allocator_sink sink(a);
    tl_io::decoded_size got;
    std::string why;
    size_t max_pixels = d.max_pixels ? d.max_pixels : (size_t)1 << 26;
    switch (tl_io::decode_rgba8(data, size, "", max_pixels, name, sink, &got, &why)) {
    case tl_io::decode_status::ok: break;
    case tl_io::decode_status::unsupported: return report(d.logger, TL_ERROR_UNSUPPORTED, name + ": " + why);
    case tl_io::decode_status::too_large: return report(d.logger, TL_ERROR_LIMIT, name + ": " + why);
    case tl_io::decode_status::no_memory: return report(d.logger, TL_ERROR_OUT_OF_MEMORY, name + ": out of memory");
    default: return report(d.logger, TL_ERROR_PARSE, name + ": " + why);
    }
    out->width = got.width;
    out->height = got.height;
    out->rgba = sink.px;
    out->allocator = a;
    sink.px = nullptr;
    return TL_OK;
}

// Checks shared by both readers; the resolved options into *d.
tl_result begin_read(const char *fn, const tl_image_read_desc *desc, tl_rgba8_image *out, tl_image_read_desc *d)
{
    *d = desc ? *desc : tl_image_read_desc{};
    if (out) *out = tl_rgba8_image{};
    if (!out) return report(d->logger, TL_ERROR_INVALID_ARGUMENT, std::string(fn) + ": NULL out");
    tl_allocator resolved;
    if (tl__allocator_resolve(&d->allocator, &resolved) != TL_OK)
        return report(d->logger, TL_ERROR_INVALID_ARGUMENT, std::string(fn) + ": allocator needs both alloc and free");
    return TL_OK;
}

} // namespace

extern "C" tl_result tl_image_decode_rgba8(const void *data, size_t size, const tl_image_read_desc *desc,
                                           tl_rgba8_image *out)
{
    tl_image_read_desc d;
    tl_result r = begin_read("tl_image_decode_rgba8", desc, out, &d);
    if (r != TL_OK) return r;
    if (!data && size) return report(d.logger, TL_ERROR_INVALID_ARGUMENT, "tl_image_decode_rgba8: NULL data");
    std::string name = d.name ? d.name : "image";
    try {
        return decode(static_cast<const unsigned char *>(data), size, d, name, out);
    } catch (const std::bad_alloc &) {
        return report(d.logger, TL_ERROR_OUT_OF_MEMORY, name + ": out of memory");
    } catch (const std::exception &ex) {
        return report(d.logger, TL_ERROR_PARSE, name + ": " + ex.what());
    } catch (...) {
        return report(d.logger, TL_ERROR_PARSE, name + ": unknown error");
    }
}

extern "C" tl_result tl_image_read_rgba8(const char *path, const tl_image_read_desc *desc, tl_rgba8_image *out)
{
    tl_image_read_desc d;
    tl_result r = begin_read("tl_image_read_rgba8", desc, out, &d);
    if (r != TL_OK) return r;
    if (!path) return report(d.logger, TL_ERROR_INVALID_ARGUMENT, "tl_image_read_rgba8: NULL path");
    std::string name(path);
    void *bytes = nullptr;
    tl_allocator a;
    tl__allocator_resolve(&d.allocator, &a);
    try {
        tl_io::regular_file f;
        std::string why;
        if (tl_io::open_regular(path, &f, &why) != TL_OK) return report(d.logger, TL_ERROR_IO, name + ": " + why);
        if (f.size > ((size_t)1 << 30)) return report(d.logger, TL_ERROR_LIMIT, name + ": larger than 1 GiB");
        bytes = tl__alloc(&a, f.size);
        if (!bytes) return report(d.logger, TL_ERROR_OUT_OF_MEMORY, name + ": out of memory");
        r = tl_io::read_all(f, bytes, &why) == TL_OK
                ? decode(static_cast<const unsigned char *>(bytes), f.size, d, name, out)
                : report(d.logger, TL_ERROR_IO, name + ": " + why);
    } catch (const std::bad_alloc &) {
        r = report(d.logger, TL_ERROR_OUT_OF_MEMORY, name + ": out of memory");
    } catch (const std::exception &ex) {
        r = report(d.logger, TL_ERROR_PARSE, name + ": " + ex.what());
    } catch (...) {
        r = report(d.logger, TL_ERROR_PARSE, name + ": unknown error");
    }
    tl__free(&a, bytes);
    return r;
}

extern "C" void tl_rgba8_image_free(tl_rgba8_image *image)
{
    if (!image) return;
    if (image->rgba) tl__free(&image->allocator, image->rgba);
    *image = tl_rgba8_image{};
}
