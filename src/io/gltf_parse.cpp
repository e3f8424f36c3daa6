// Reading the file and running tinygltf over it. We read the main file ourselves (I/O errors are
// ours to name, GLB headers are checked before tinygltf trusts them) and give tinygltf file
// callbacks that only look next to the glTF file and remember failures, so a missing .bin is
// reported as TL_ERROR_IO rather than a parse error.
#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "gltf_internal.h"

namespace tl_gltf {
namespace {

uint32_t le32(const unsigned char *p) { return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24; }

bool is_regular_file(const std::string &path)
{
    struct stat st;
    return stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

// tinygltf searches base_dir and then ".": accepting only files under base_dir keeps a stray
// file of the same name in the working directory from standing in for a missing one.
bool fs_exists(const std::string &file, void *user)
{
    context &c = *static_cast<context *>(user);
    std::string prefix = join_path(c.base_dir, "");
    bool under_base = prefix.empty() || file.compare(0, prefix.size(), prefix) == 0;
    if (under_base && is_regular_file(file)) return true;
    if (under_base && !c.io_failed) {
        c.io_failed = true;
        c.io_detail = file + ": no such file";
    }
    return false;
}

// No "~" or environment expansion: URIs are relative paths, nothing more.
std::string fs_expand(const std::string &file, void *) { return file; }

bool fs_read(std::vector<unsigned char> *out, std::string *err, const std::string &file, void *user)
{
    context &c = *static_cast<context *>(user);
    FILE *f = std::fopen(file.c_str(), "rb");
    bool ok = f != nullptr;
    if (ok) {
        unsigned char chunk[65536];
        size_t n;
        while ((n = std::fread(chunk, 1, sizeof chunk, f)) > 0) out->insert(out->end(), chunk, chunk + n);
        ok = !std::ferror(f);
        std::fclose(f);
    }
    if (!ok) {
        c.io_failed = true;
        c.io_detail = file + ": " + std::strerror(errno);
        if (err) *err += c.io_detail;
    }
    return ok;
}

bool fs_write(std::string *err, const std::string &, const std::vector<unsigned char> &, void *)
{
    if (err) *err += "writing is not supported";
    return false;
}

// Keeps images encoded: data-URI bytes are copied (they exist only during this call), buffer
// view images are read later from the buffer after a range check, external files are not read
// here at all (TINYGLTF_NO_EXTERNAL_IMAGE). Decoding waits until a material uses the image.
bool keep_encoded(tinygltf::Image *image, const int, std::string *, std::string *, int, int, const unsigned char *bytes,
                  int size, void *)
{
    if (image->bufferView >= 0) return true;
    if (bytes && size > 0) image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// The first non-empty line of a tinygltf error text.
std::string first_line(const std::string &text)
{
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (end > start) return text.substr(start, end - start);
        start = end + 1;
    }
    return "unknown error";
}

// The GLB header and chunk table, checked before tinygltf reads them (its BIN-chunk bound
// ignores the 8-byte chunk header, so a crafted length would read past the file).
void check_glb(const unsigned char *b, size_t size)
{
    if (size < 20) fail(TL_ERROR_PARSE, "GLB: truncated header (" + std::to_string(size) + " bytes)");
    uint32_t version = le32(b + 4), length = le32(b + 8), json_len = le32(b + 12), json_type = le32(b + 16);
    if (version != 2) fail(TL_ERROR_UNSUPPORTED, "GLB: version " + std::to_string(version) + " (only 2 is supported)");
    if (length > size)
        fail(TL_ERROR_PARSE, "GLB: truncated (header says " + std::to_string(length) + " bytes, the file has " +
                                 std::to_string(size) + ")");
    if (length < size) fail(TL_ERROR_PARSE, "GLB: length " + std::to_string(length) + " is not the file size " + std::to_string(size));
    if (json_type != 0x4E4F534Au || json_len == 0) fail(TL_ERROR_PARSE, "GLB: the first chunk is not JSON");
    uint64_t end = 20ull + json_len;
    if (end > length) fail(TL_ERROR_PARSE, "GLB: JSON chunk runs past the end of the file");
    if (end == length) return;
    if (end + 8 > length) fail(TL_ERROR_PARSE, "GLB: truncated BIN chunk header");
    uint32_t bin_len = le32(b + end), bin_type = le32(b + end + 4);
    if (bin_type != 0x004E4942u) fail(TL_ERROR_PARSE, "GLB: the second chunk is not BIN");
    if (end + 8 + bin_len > length) fail(TL_ERROR_PARSE, "GLB: BIN chunk runs past the end of the file");
}

// The main file's bytes, through the caller's allocator.
struct file_bytes {
    const context &c;
    unsigned char *data = nullptr;
    size_t size = 0;
    explicit file_bytes(const context &ctx) : c(ctx) {}
    ~file_bytes() { free_bytes(c, data); }
};

void read_main_file(const context &c, file_bytes *out)
{
    FILE *f = std::fopen(c.path.c_str(), "rb");
    if (!f) fail(TL_ERROR_IO, std::string("cannot open: ") + std::strerror(errno));
    long size = -1;
    if (std::fseek(f, 0, SEEK_END) == 0) size = std::ftell(f);
    if (size < 0 || std::fseek(f, 0, SEEK_SET) != 0) {
        std::fclose(f);
        fail(TL_ERROR_IO, "cannot determine the file size (not a regular file?)");
    }
    // tinygltf takes 32-bit lengths.
    if ((unsigned long)size > 0xFFFFFFFFul) {
        std::fclose(f);
        fail(TL_ERROR_LIMIT, "larger than 4 GiB");
    }
    try {
        out->data = static_cast<unsigned char *>(alloc_bytes(c, (size_t)size, 1, "reading the file"));
    } catch (...) {
        std::fclose(f);
        throw;
    }
    out->size = std::fread(out->data, 1, (size_t)size, f);
    bool ok = out->size == (size_t)size && !std::ferror(f);
    std::fclose(f);
    if (!ok) fail(TL_ERROR_IO, "read error");
}

} // namespace

void parse_file(context &c, tinygltf::Model *model)
{
    file_bytes file(c);
    read_main_file(c, &file);
    if (file.size == 0) fail(TL_ERROR_PARSE, "empty file");
    bool glb = file.size >= 4 && std::memcmp(file.data, "glTF", 4) == 0;
    if (glb) check_glb(file.data, file.size);

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keep_encoded, nullptr);
    loader.SetFsCallbacks(tinygltf::FsCallbacks{fs_exists, fs_expand, fs_read, fs_write, &c});
    std::string err, warnings;
    c.io_failed = false;
    bool ok = glb ? loader.LoadBinaryFromMemory(model, &err, &warnings, file.data, (unsigned)file.size, c.base_dir)
                  : loader.LoadASCIIFromString(model, &err, &warnings, reinterpret_cast<const char *>(file.data),
                                               (unsigned)file.size, c.base_dir);
    if (!warnings.empty()) warn(c, warnings);
    if (!ok) {
        if (c.io_failed) fail(TL_ERROR_IO, c.io_detail);
        fail(TL_ERROR_PARSE, first_line(err));
    }
    // tinygltf may report problems in `err` and still succeed (it is lenient); they are warnings.
    if (!err.empty()) warn(c, err);
}

} // namespace tl_gltf
