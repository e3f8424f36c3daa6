// Running tinygltf over the file's bytes. Before tinygltf sees them: the GLB header and chunk
// table, the JSON's nesting and parse cost (gltf_json_scan.cpp), and what tinygltf would trust
// (gltf_json_check.cpp). tinygltf reads external buffers through file callbacks that go to the
// load's tl_gltf_files (gltf_external.cpp) and remember failures, so a missing .bin is reported
// as TL_ERROR_IO with its own reason rather than as a parse error.
#include <cstring>

#include "gltf_internal.h"

namespace tl_gltf {
namespace {

uint32_t le32(const unsigned char *p) { return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24; }

struct fs_state {
    context *c;
    budget_hold *hold;
};

// tinygltf asks for "base_dir/uri" and then "./uri"; with an empty base_dir the first question
// is the URI itself, and the answer is always yes: whether the file can be read is the file
// callbacks' to say, when tinygltf reads it.
bool fs_exists(const std::string &file, void *) { return !file.empty(); }

// No "~" or environment expansion: URIs are what the file says, nothing more.
std::string fs_expand(const std::string &file, void *) { return file; }

// An external buffer (tinygltf has already percent-decoded the URI). Nothing may be thrown
// through tinygltf: failures are kept in the context and reported after it returns.
bool fs_read(std::vector<unsigned char> *out, std::string *err, const std::string &uri, void *user)
{
    fs_state &s = *static_cast<fs_state *>(user);
    context &c = *s.c;
    try {
        external_file file(c);
        tl_result r = TL_OK;
        std::string why;
        if (read_external(c, uri, &file, &r, &why)) {
            // The copy tinygltf keeps lives as long as the model.
            s.hold->add(file.size, "buffer '" + uri + "'");
            const unsigned char *b = static_cast<const unsigned char *>(file.data);
            out->assign(b, b + file.size);
            return true;
        }
        c.io_result = r;
        c.io_detail = why;
    } catch (const failure &f) {
        c.io_result = f.result;
        c.io_detail = f.message;
    } catch (...) {
        c.io_result = TL_ERROR_OUT_OF_MEMORY;
        c.io_detail = "buffer '" + uri + "': out of memory";
    }
    if (err) *err += c.io_detail;
    return false;
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
        size_t end = text.find_first_of("\r\n", start);
        if (end == std::string::npos) end = text.size();
        if (end > start) return text.substr(start, end - start);
        start = end + 1;
    }
    return "unknown error";
}

// The GLB header and chunk table, checked before tinygltf reads them (its BIN-chunk bound
// ignores the 8-byte chunk header, so a crafted length would read past the file). Returns the
// BIN chunk's size (0: none).
size_t check_glb(const unsigned char *b, size_t size)
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
    if (end == length) return 0;
    if (end + 8 > length) fail(TL_ERROR_PARSE, "GLB: truncated BIN chunk header");
    uint32_t bin_len = le32(b + end), bin_type = le32(b + end + 4);
    if (bin_type != 0x004E4942u) fail(TL_ERROR_PARSE, "GLB: the second chunk is not BIN");
    if (end + 8 + bin_len > length) fail(TL_ERROR_PARSE, "GLB: BIN chunk runs past the end of the file");
    return bin_len;
}

// Nesting and parse cost of the JSON text, before any parser runs.
void check_shape(const unsigned char *json, size_t size, size_t offset, budget_hold *hold)
{
    json_shape shape = scan_json(json, size);
    if (shape.depth > max_json_depth)
        fail(TL_ERROR_LIMIT, "JSON nested more than " + std::to_string(max_json_depth) + " levels deep (at byte " +
                                 std::to_string(offset + shape.deep_at) + ")");
    hold->add(json_parse_cost(shape), "parsing the JSON (" + std::to_string(shape.containers) + " objects and arrays, " +
                                          std::to_string(shape.members + shape.items) + " values, " +
                                          byte_size(shape.string_bytes) + " of strings)");
}

} // namespace

void parse_gltf(context &c, const unsigned char *data, size_t size, tinygltf::Model *model, budget_hold *hold)
{
    if (size == 0) fail(TL_ERROR_PARSE, "empty file");
    // tinygltf takes 32-bit lengths.
    if (size > 0xFFFFFFFFu) fail(TL_ERROR_LIMIT, "larger than 4 GiB");
    bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    size_t bin_size = glb ? check_glb(data, size) : 0;
    const unsigned char *json = glb ? data + 20 : data;
    size_t json_size = glb ? le32(data + 12) : size;
    check_shape(json, json_size, glb ? 20 : 0, hold);
    check_json(c, json, json_size, glb, bin_size, hold);

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keep_encoded, nullptr);
    fs_state fs{&c, hold};
    loader.SetFsCallbacks(tinygltf::FsCallbacks{fs_exists, fs_expand, fs_read, fs_write, &fs});
    std::string err, warnings;
    c.io_result = TL_OK;
    bool ok = glb ? loader.LoadBinaryFromMemory(model, &err, &warnings, data, (unsigned)size, "")
                  : loader.LoadASCIIFromString(model, &err, &warnings, reinterpret_cast<const char *>(data),
                                               (unsigned)size, "");
    if (!warnings.empty()) warn(c, warnings);
    if (!ok) {
        if (c.io_result != TL_OK) fail(c.io_result, c.io_detail);
        fail(TL_ERROR_PARSE, first_line(err));
    }
    // tinygltf may report problems in `err` and still succeed (it is lenient); they are warnings.
    if (!err.empty()) warn(c, err);
}

} // namespace tl_gltf
