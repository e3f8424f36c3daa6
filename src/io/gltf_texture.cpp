// glTF textures to scene textures: each glTF image is decoded at most once, only when a material
// uses it. A missing or undecodable image is a warning and map 0, no texture (the material keeps
// its flat colour); a broken reference in the JSON is an error.
#include <cstring>

#include "gltf_internal.h"
#include "scene/validate.h"

namespace tl_gltf {
namespace {

// URIs are percent-encoded (RFC 3986); file names are not.
std::string percent_decode(const std::string &s)
{
    auto hex = [](char ch) -> int {
        if (ch >= '0' && ch <= '9') return ch - '0';
        if (ch >= 'a' && ch <= 'f') return ch - 'a' + 10;
        if (ch >= 'A' && ch <= 'F') return ch - 'A' + 10;
        return -1;
    };
    std::string out;
    for (size_t i = 0; i < s.size(); i++) {
        if (s[i] == '%' && i + 2 < s.size() && hex(s[i + 1]) >= 0 && hex(s[i + 2]) >= 0) {
            out += (char)(hex(s[i + 1]) * 16 + hex(s[i + 2]));
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

std::string one_line(std::string s)
{
    for (char &ch : s)
        if (ch == '\n' || ch == '\r') ch = ' ';
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

void set_name(tl_texture *t, const std::string &name)
{
    std::strncpy(t->name, name.c_str(), sizeof t->name - 1);
    t->name[sizeof t->name - 1] = '\0';
}

// Decodes image `ii`; false with `why` when it is missing or cannot be decoded.
bool decode_gltf_image(const context &c, const tinygltf::Model &m, size_t ii, decoded_image *out, std::string *why)
{
    const tinygltf::Image &img = m.images[ii];
    const std::string name = element("images", ii);
    if (img.bufferView >= 0) {
        if ((size_t)img.bufferView >= m.bufferViews.size())
            fail(TL_ERROR_PARSE, name + ": bufferView " + std::to_string(img.bufferView) + " out of range");
        const tinygltf::BufferView &bv = m.bufferViews[(size_t)img.bufferView];
        if (bv.buffer < 0 || (size_t)bv.buffer >= m.buffers.size())
            fail(TL_ERROR_PARSE, element("bufferViews", (size_t)img.bufferView) + ": buffer out of range");
        const std::vector<unsigned char> &data = m.buffers[(size_t)bv.buffer].data;
        if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
            fail(TL_ERROR_PARSE, element("bufferViews", (size_t)img.bufferView) + ": lies outside its buffer");
        return decode_image_memory(c, data.data() + bv.byteOffset, bv.byteLength, img.mimeType, name, out, why);
    }
    if (img.as_is && !img.image.empty()) // a data URI, kept encoded by the parser
        return decode_image_memory(c, img.image.data(), img.image.size(), img.mimeType, name, out, why);
    if (img.uri.empty()) {
        *why = "no image data";
        return false;
    }
    if (img.uri.compare(0, 5, "data:") == 0) {
        *why = "unsupported data URI type";
        return false;
    }
    // An external file, through the load's file callbacks (by default: the glTF file's folder).
    external_file file(c);
    tl_result result = TL_OK;
    if (!read_external(c, percent_decode(img.uri), &file, &result, why)) return false;
    return decode_image_memory(c, static_cast<const unsigned char *>(file.data), file.size, img.mimeType, name, out,
                               why);
}

} // namespace

texture_table::~texture_table()
{
    for (tl_texture &t : textures) free_bytes(*c, t.rgba, (size_t)t.width * t.height * 4);
}

uint32_t texture_for(const context &c, const tinygltf::Model &m, texture_table *t, int index, const std::string &what)
{
    if (index < 0) return 0;
    if ((size_t)index >= m.textures.size())
        fail(TL_ERROR_PARSE, what + ": texture " + std::to_string(index) + " out of range (" +
                                 std::to_string(m.textures.size()) + " textures)");
    const tinygltf::Texture &tex = m.textures[(size_t)index];
    if (tex.source < 0) {
        // e.g. only an extension's source (KTX2, WebP) that we do not read
        warn(c, element("textures", (size_t)index) + ": no image source we can read; using the flat colour");
        return 0;
    }
    if ((size_t)tex.source >= m.images.size())
        fail(TL_ERROR_PARSE, element("textures", (size_t)index) + ": source " + std::to_string(tex.source) +
                                 " out of range (" + std::to_string(m.images.size()) + " images)");
    size_t ii = (size_t)tex.source;
    if (t->image_slot.size() != m.images.size()) t->image_slot.assign(m.images.size(), image_unset);
    if (t->image_slot[ii] != image_unset) return t->image_slot[ii];

    t->textures.reserve(t->textures.size() + 1); // so that push_back below cannot throw and leak
    decoded_image d;
    std::string why;
    if (!decode_gltf_image(c, m, ii, &d, &why)) {
        warn(c, element("images", ii) + ": " + one_line(why) + "; using the flat colour");
        t->image_slot[ii] = 0;
        return 0;
    }
    tl_texture out = {};
    out.width = d.width;
    out.height = d.height;
    out.rgba = d.rgba;
    const tinygltf::Image &img = m.images[ii];
    set_name(&out, !img.name.empty() ? img.name : (!img.uri.empty() && img.uri.compare(0, 5, "data:") != 0)
                                                      ? img.uri
                                                      : element("images", ii));
    // What every GL 4.5 renderer takes (scene/validate.h, as tl_renderer_set_scene checks it)
    char msg[TL__CHECK_MESSAGE_SIZE];
    if (tl__texture_check(&out, element("images", ii).c_str(), TL__GL45_MAX_TEXTURE_SIZE, msg, sizeof msg) != TL_OK) {
        free_bytes(c, out.rgba, (size_t)out.width * out.height * 4);
        warn(c, std::string(msg) + "; using the flat colour");
        t->image_slot[ii] = 0;
        return 0;
    }
    t->textures.push_back(out);
    t->image_slot[ii] = TL_TEXTURE_MAP(t->textures.size() - 1);
    return t->image_slot[ii];
}

} // namespace tl_gltf
