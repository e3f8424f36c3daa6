// The few things tinygltf 2.7 trusts in a file, checked before it runs (gltf_internal.h,
// check_json). Integers are read as tinygltf reads them: indices through int (GetInt), sizes and
// offsets as unsigned integers only.
#include <nlohmann/json.hpp>

#include "gltf_internal.h"

namespace tl_gltf {
namespace {

using json = nlohmann::json;

// tinygltf's GetInt: any JSON integer, cast to int.
bool get_int(const json &o, const char *key, int *out)
{
    auto it = o.find(key);
    if (it == o.end() || !it->is_number_integer()) return false;
    *out = (int)it->get<int64_t>();
    return true;
}

// tinygltf's ParseUnsignedProperty: unsigned JSON integers only.
bool get_size(const json &o, const char *key, size_t *out)
{
    auto it = o.find(key);
    if (it == o.end() || !it->is_number_unsigned()) return false;
    *out = it->get<size_t>();
    return true;
}

const json *array_of(const json &root, const char *key)
{
    auto it = root.find(key);
    return it != root.end() && it->is_array() ? &*it : nullptr;
}

// In a GLB, tinygltf gives every buffer without a URI (or with an empty one, or not a string) a copy of the BIN chunk; the
// specification lets only buffers[0] refer to it.
void check_buffers(const json &root, bool glb, size_t bin_size, budget_hold *hold)
{
    const json *buffers = array_of(root, "buffers");
    if (!glb || !buffers) return;
    for (size_t i = 0; i < buffers->size(); i++) {
        const json &b = (*buffers)[i];
        if (!b.is_object()) return; // tinygltf's error
        auto uri = b.find("uri");
        if (uri != b.end() && uri->is_string() && !uri->get_ref<const std::string &>().empty()) continue;
        if (i > 0)
            fail(TL_ERROR_PARSE, element("buffers", i) + ": no uri (only buffers[0] may refer to the GLB's BIN chunk)");
        size_t length = 0;
        if (get_size(b, "byteLength", &length) && length <= bin_size)
            hold->add(length, "buffers[0] (the GLB's BIN chunk)");
    }
}

// tinygltf passes &buffer.data[view.byteOffset] to the image loader for every image with a
// buffer view, without checking the offset.
void check_image_views(const json &root)
{
    const json *images = array_of(root, "images"), *views = array_of(root, "bufferViews"),
               *buffers = array_of(root, "buffers");
    if (!images) return;
    for (size_t i = 0; i < images->size(); i++) {
        const json &img = (*images)[i];
        int view = -1, buffer = -1;
        if (!img.is_object() || !get_int(img, "bufferView", &view)) continue;
        if (!views || view < 0 || (size_t)view >= views->size() || !(*views)[(size_t)view].is_object()) continue;
        const json &v = (*views)[(size_t)view];
        if (!get_int(v, "buffer", &buffer) || !buffers || buffer < 0 || (size_t)buffer >= buffers->size()) continue;
        const json &b = (*buffers)[(size_t)buffer];
        size_t offset = 0, length = 0;
        get_size(v, "byteOffset", &offset);
        if (!b.is_object() || !get_size(b, "byteLength", &length)) continue; // tinygltf's error
        if (offset >= length)
            fail(TL_ERROR_PARSE, element("images", i) + ": " + element("bufferViews", (size_t)view) + " starts at byte " +
                                     std::to_string(offset) + ", outside its buffer (" + std::to_string(length) +
                                     " bytes)");
    }
}

} // namespace

void check_json(const context &, const unsigned char *text, size_t size, bool glb, size_t bin_size, budget_hold *hold)
{
    // No exceptions (allow_exceptions = false): a malformed text is discarded, for tinygltf to
    // report in its words. nlohmann's parser and destructor do not recurse.
    json root = json::parse(text, text + size, nullptr, false);
    if (root.is_discarded() || !root.is_object()) return;
    check_buffers(root, glb, bin_size, hold);
    check_image_views(root);
}

} // namespace tl_gltf
