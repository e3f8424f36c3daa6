// Image files through OpenImageIO. Exceptions and OIIO error strings become tl_result plus a
// message here; nothing C++ crosses the C API.
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <unistd.h>

#include "thinlight/io.h"

namespace {

tl_result fail(char *error, size_t size, tl_result r, const std::string &msg)
{
    if (error && size) std::snprintf(error, size, "%s", msg.c_str());
    return r;
}

std::string extension_of(const std::string &path)
{
    size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    return path.substr(dot);
}

} // namespace

extern "C" tl_result tl_image_write(const char *path, const tl_image_desc *desc, const void *pixels, char *error,
                                    size_t error_size)
{
    if (!path || !desc || !pixels || !desc->width || !desc->height || desc->channels < 1 || desc->channels > 4 ||
        desc->width > 65536 || desc->height > 65536 || (unsigned)desc->type >= TL_PIXEL_TYPE_COUNT_)
        return fail(error, error_size, TL_ERROR_INVALID_ARGUMENT, "image write: invalid arguments");
    try {
        std::string target(path), ext = extension_of(target);
        if (ext.empty()) return fail(error, error_size, TL_ERROR_INVALID_ARGUMENT, target + ": no file extension");
        // The temporary keeps the extension so that OIIO picks the same writer.
        std::string tmp = target + ".tmp" + std::to_string(static_cast<long>(getpid())) + ext;
        auto out = OIIO::ImageOutput::create(target);
        if (!out) return fail(error, error_size, TL_ERROR_UNSUPPORTED, target + ": no writer for '" + ext + "'");
        OIIO::TypeDesc in_type = desc->type == TL_PIXEL_F32 ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
        OIIO::TypeDesc file_type = in_type;
        if (ext == ".png" || ext == ".jpg" || ext == ".jpeg") file_type = OIIO::TypeDesc::UINT8;
        if (ext == ".exr") file_type = OIIO::TypeDesc::HALF;
        OIIO::ImageSpec spec((int)desc->width, (int)desc->height, (int)desc->channels, file_type);
        if (!out->open(tmp, spec)) {
            std::string e = out->geterror();
            return fail(error, error_size, TL_ERROR_IO, target + ": cannot write: " + e);
        }
        size_t elem = desc->type == TL_PIXEL_F32 ? 4 : 1;
        OIIO::stride_t ystride = (OIIO::stride_t)(desc->width * desc->channels * elem);
        const char *base = static_cast<const char *>(pixels);
        if (desc->bottom_up) {
            base += (size_t)(desc->height - 1) * (size_t)ystride;
            ystride = -ystride;
        }
        bool ok = out->write_image(in_type, base, OIIO::AutoStride, ystride);
        std::string e = ok ? "" : out->geterror();
        ok = out->close() && ok;
        if (!ok) {
            std::remove(tmp.c_str());
            return fail(error, error_size, TL_ERROR_IO, target + ": write failed: " + e);
        }
        if (std::rename(tmp.c_str(), target.c_str()) != 0) {
            std::remove(tmp.c_str());
            return fail(error, error_size, TL_ERROR_IO, target + ": cannot rename the temporary file into place");
        }
        return TL_OK;
    } catch (const std::exception &ex) {
        return fail(error, error_size, TL_ERROR_IO, std::string(path) + ": " + ex.what());
    } catch (...) {
        return fail(error, error_size, TL_ERROR_IO, std::string(path) + ": unknown error");
    }
}

extern "C" tl_result tl_image_read_rgba8(const char *path, size_t max_pixels, uint32_t *width, uint32_t *height,
                                         uint8_t **rgba, char *error, size_t error_size)
{
    if (!path || !width || !height || !rgba) return fail(error, error_size, TL_ERROR_INVALID_ARGUMENT, "image read: invalid arguments");
    *rgba = nullptr;
    *width = *height = 0;
    if (!max_pixels) max_pixels = (size_t)1 << 26;
    try {
        auto in = OIIO::ImageInput::open(path);
        if (!in) return fail(error, error_size, TL_ERROR_IO, std::string(path) + ": cannot open: " + OIIO::geterror());
        const OIIO::ImageSpec &spec = in->spec();
        if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth != 1)
            return fail(error, error_size, TL_ERROR_UNSUPPORTED, std::string(path) + ": unsupported image layout");
        size_t n = (size_t)spec.width * (size_t)spec.height;
        if ((size_t)spec.width > 65536 || (size_t)spec.height > 65536 || n > max_pixels)
            return fail(error, error_size, TL_ERROR_LIMIT,
                        std::string(path) + ": " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                            " exceeds the pixel limit");
        int ch = spec.nchannels;
        std::unique_ptr<uint8_t[]> tmp(new uint8_t[n * (size_t)ch]);
        if (!in->read_image(0, 0, 0, ch, OIIO::TypeDesc::UINT8, tmp.get()))
            return fail(error, error_size, TL_ERROR_PARSE, std::string(path) + ": " + in->geterror());
        uint8_t *out = static_cast<uint8_t *>(std::malloc(n * 4));
        if (!out) return fail(error, error_size, TL_ERROR_OUT_OF_MEMORY, std::string(path) + ": out of memory");
        for (size_t i = 0; i < n; i++) {
            const uint8_t *s = tmp.get() + i * (size_t)ch;
            uint8_t *d = out + i * 4;
            if (ch >= 3) {
                d[0] = s[0]; d[1] = s[1]; d[2] = s[2];
                d[3] = ch >= 4 ? s[3] : 255;
            } else {
                d[0] = d[1] = d[2] = s[0];
                d[3] = ch == 2 ? s[1] : 255;
            }
        }
        *rgba = out;
        *width = (uint32_t)spec.width;
        *height = (uint32_t)spec.height;
        return TL_OK;
    } catch (const std::exception &ex) {
        return fail(error, error_size, TL_ERROR_IO, std::string(path) + ": " + ex.what());
    }
}

extern "C" void tl_image_free(void *pixels) { std::free(pixels); }
