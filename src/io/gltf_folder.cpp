// What a path load reads by default: the glTF file itself, and external files in its folder and
// below, nothing else (docs/gltf.md, "External files"). A URI is refused without touching the
// file system when it has a scheme (file:, http:), is absolute or climbs above the folder with
// "..", so a message never tells whether something outside exists; what remains is resolved with
// realpath and must still lie inside the folder (a symbolic link may not lead out). Only regular
// files are opened, without blocking (io_file.h).
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "gltf_internal.h"
#include "io_file.h"

namespace tl_gltf {
namespace {

// RFC 3986: a scheme is a letter, then letters, digits, '+', '-' or '.', then ':'. A relative
// path cannot have a ':' in its first segment, so "c:x.bin" is a scheme too.
bool has_scheme(const std::string &u)
{
    size_t colon = u.find(':'), slash = u.find('/');
    return colon != std::string::npos && (slash == std::string::npos || colon < slash);
}

// Whether a relative path stays at or below its start, looking only at its segments.
bool stays_inside(const std::string &u)
{
    long depth = 0;
    size_t start = 0;
    while (start <= u.size()) {
        size_t end = u.find('/', start);
        if (end == std::string::npos) end = u.size();
        std::string seg = u.substr(start, end - start);
        if (seg == "..") {
            if (--depth < 0) return false;
        } else if (!seg.empty() && seg != ".") {
            depth++;
        }
        start = end + 1;
    }
    return true;
}

tl_result refuse(folder_reader &r, tl_result result, const std::string &reason, const char **why)
{
    r.why = reason;
    *why = r.why.c_str();
    return result;
}

// The checked path of `uri` inside the folder, or a refusal.
tl_result resolve(folder_reader &r, const std::string &u, std::string *resolved, const char **why)
{
    if (has_scheme(u)) return refuse(r, TL_ERROR_IO, "not a relative path (URI schemes such as file: are not read)", why);
    if (u[0] == '/') return refuse(r, TL_ERROR_IO, "an absolute path, outside the glTF file's folder", why);
    if (!stays_inside(u)) return refuse(r, TL_ERROR_IO, "outside the glTF file's folder", why);
    if (r.root.empty()) return refuse(r, TL_ERROR_IO, "the glTF file's folder cannot be resolved", why);
    std::string joined = r.root + "/" + u;
    char *real = realpath(joined.c_str(), nullptr);
    if (!real) return refuse(r, TL_ERROR_IO, errno == ENOENT ? "no such file" : std::strerror(errno), why);
    *resolved = real;
    std::free(real);
    std::string prefix = r.root == "/" ? r.root : r.root + "/";
    if (resolved->compare(0, prefix.size(), prefix) != 0)
        return refuse(r, TL_ERROR_IO, "outside the glTF file's folder (a symbolic link leads out)", why);
    return TL_OK;
}

tl_result folder_read(void *user, const char *uri, size_t max_size, void **data, size_t *size, const char **why)
{
    folder_reader &r = *static_cast<folder_reader *>(user);
    std::string path;
    tl_result res = resolve(r, uri, &path, why);
    if (res != TL_OK) return res;
    tl_io::regular_file f;
    std::string reason;
    if (tl_io::open_regular(path.c_str(), &f, &reason) != TL_OK) return refuse(r, TL_ERROR_IO, reason, why);
    if (f.size > max_size)
        return refuse(r, TL_ERROR_LIMIT,
                      byte_size(f.size) + ", more than the load's memory budget allows (" + byte_size(max_size) + " left)",
                      why);
    void *p = tl__alloc(&r.c->alloc, f.size);
    if (!p) return refuse(r, TL_ERROR_OUT_OF_MEMORY, "out of memory", why);
    if (tl_io::read_all(f, p, &reason) != TL_OK) {
        tl__free(&r.c->alloc, p);
        return refuse(r, TL_ERROR_IO, reason, why);
    }
    *data = p;
    *size = f.size;
    return TL_OK;
}

void folder_release(void *user, void *data, size_t)
{
    folder_reader &r = *static_cast<folder_reader *>(user);
    tl__free(&r.c->alloc, data);
}

} // namespace

tl_gltf_files folder_files(const context &c, const std::string &path, folder_reader *r)
{
    size_t slash = path.find_last_of('/');
    std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
    r->c = &c;
    char *real = realpath(dir.c_str(), nullptr);
    r->root = real ? real : "";
    std::free(real);
    return tl_gltf_files{folder_read, folder_release, r};
}

void read_main_file(const context &c, const std::string &path, file_bytes *out)
{
    tl_io::regular_file f;
    std::string why;
    if (tl_io::open_regular(path.c_str(), &f, &why) != TL_OK) fail(TL_ERROR_IO, "cannot read: " + why);
    // tinygltf takes 32-bit lengths.
    if (f.size > 0xFFFFFFFFu) fail(TL_ERROR_LIMIT, "larger than 4 GiB");
    out->data = static_cast<unsigned char *>(alloc_bytes(c, f.size, 1, "the file"));
    out->size = f.size;
    if (tl_io::read_all(f, out->data, &why) != TL_OK) fail(TL_ERROR_IO, "cannot read: " + why);
}

} // namespace tl_gltf

