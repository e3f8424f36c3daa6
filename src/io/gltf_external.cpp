// External buffers and images through the load's tl_gltf_files: one place that calls the
// application's (or the default folder's) read and release, counts the bytes against the budget,
// and words the failure.
#include <cstring>

#include "gltf_internal.h"

namespace tl_gltf {
namespace {

// A URI for a message: one line, control characters shown as '?', at most 200 bytes.
std::string printable(const std::string &uri)
{
    std::string s = uri.size() > 200 ? uri.substr(0, 200) + "..." : uri;
    for (char &ch : s)
        if ((unsigned char)ch < 0x20 || ch == 0x7F) ch = '?';
    return "'" + s + "'";
}

} // namespace

external_file::~external_file()
{
    if (!data) return;
    if (c.files.release) c.files.release(c.files.user, data, size);
    uncharge(c, size);
}

bool read_external(const context &c, const std::string &uri, external_file *out, tl_result *result, std::string *why)
{
    *result = TL_ERROR_IO;
    if (uri.empty() || uri.find('\0') != std::string::npos) {
        *why = printable(uri) + ": not a file name (empty, or a NUL byte)";
        return false;
    }
    if (!c.files.read) {
        *why = printable(uri) + ": external files cannot be read here (no tl_gltf_files given)";
        return false;
    }
    void *data = nullptr;
    size_t size = 0;
    const char *reason = nullptr;
    tl_result r = c.files.read(c.files.user, uri.c_str(), budget_left(c), &data, &size, &reason);
    if (r == TL_OK && !data && size) r = TL_ERROR_IO;
    if (r != TL_OK) {
        if (data && c.files.release) c.files.release(c.files.user, data, size);
        *result = r;
        *why = printable(uri) + ": " + (reason && *reason ? std::string(reason) : std::string(tl_result_string(r)));
        for (char &ch : *why)
            if (ch == '\n' || ch == '\r') ch = ' ';
        // Memory is never a reason to carry on without the file (a missing image is).
        if (r == TL_ERROR_OUT_OF_MEMORY || r == TL_ERROR_LIMIT) fail(r, *why);
        return false;
    }
    try {
        charge(c, size, printable(uri));
    } catch (...) {
        if (data && c.files.release) c.files.release(c.files.user, data, size);
        throw;
    }
    out->data = data;
    out->size = size;
    return true;
}

} // namespace tl_gltf
