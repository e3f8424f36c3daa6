// Accessors: every reference and byte range is checked once, up front, so that reading elements
// afterwards needs no checks. tinygltf parses the numbers but validates none of these ranges.
#include <cstring>

#include "gltf_internal.h"

namespace tl_gltf {
namespace {

int component_size(int type)
{
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0; // INT and DOUBLE are not valid glTF vertex or index data
    }
}

const char *type_name(int type)
{
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    default: return "a matrix or unknown type";
    }
}

} // namespace

accessor_view get_accessor(const tinygltf::Model &m, int index, int type, bool indices, const std::string &role)
{
    if (index < 0 || (size_t)index >= m.accessors.size())
        fail(TL_ERROR_PARSE, role + ": accessor " + std::to_string(index) + " out of range (" +
                                 std::to_string(m.accessors.size()) + " accessors)");
    const tinygltf::Accessor &a = m.accessors[(size_t)index];
    const std::string name = element("accessors", (size_t)index);
    if (a.sparse.isSparse) fail(TL_ERROR_UNSUPPORTED, name + ": sparse accessors are not supported");
    if (a.type != type)
        fail(TL_ERROR_PARSE, name + ": type is " + type_name(a.type) + ", " + role + " needs " + type_name(type));
    int csize = component_size(a.componentType);
    if (csize == 0) fail(TL_ERROR_PARSE, name + ": unsupported componentType " + std::to_string(a.componentType));
    if (indices && a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT && a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(TL_ERROR_PARSE, name + ": indices must be unsigned 8, 16 or 32-bit integers");

    accessor_view v;
    v.index = index;
    v.count = a.count;
    v.component_type = a.componentType;
    v.components = tinygltf::GetNumComponentsInType((uint32_t)a.type);
    v.normalized = a.normalized;
    size_t elem = (size_t)csize * (size_t)v.components;
    v.stride = elem;
    if (a.bufferView < 0) return v; // no data: all zeros (the spec's "initialised to zero")

    if ((size_t)a.bufferView >= m.bufferViews.size())
        fail(TL_ERROR_PARSE, name + ": bufferView " + std::to_string(a.bufferView) + " out of range (" +
                                 std::to_string(m.bufferViews.size()) + " bufferViews)");
    const tinygltf::BufferView &bv = m.bufferViews[(size_t)a.bufferView];
    const std::string bv_name = element("bufferViews", (size_t)a.bufferView);
    if (bv.buffer < 0 || (size_t)bv.buffer >= m.buffers.size())
        fail(TL_ERROR_PARSE, bv_name + ": buffer " + std::to_string(bv.buffer) + " out of range (" +
                                 std::to_string(m.buffers.size()) + " buffers)");
    size_t buffer_size = m.buffers[(size_t)bv.buffer].data.size();
    if (bv.byteOffset > buffer_size || bv.byteLength > buffer_size - bv.byteOffset)
        fail(TL_ERROR_PARSE, bv_name + ": bytes " + std::to_string(bv.byteOffset) + " + " + std::to_string(bv.byteLength) +
                                 " lie outside buffers[" + std::to_string(bv.buffer) + "] (" +
                                 std::to_string(buffer_size) + " bytes)");
    if (bv.byteStride) {
        if (bv.byteStride < elem || bv.byteStride % (size_t)csize)
            fail(TL_ERROR_PARSE, bv_name + ": byteStride " + std::to_string(bv.byteStride) +
                                     " does not fit the elements of " + name);
        v.stride = bv.byteStride;
    }
    if (v.count) {
        // offset + stride * (count - 1) + elem <= byteLength, without overflow
        size_t avail = bv.byteLength;
        bool fits = a.byteOffset <= avail && elem <= avail - a.byteOffset &&
                    (v.count - 1) <= (avail - a.byteOffset - elem) / v.stride;
        if (!fits)
            fail(TL_ERROR_PARSE, name + ": " + std::to_string(v.count) + " elements from byte " +
                                     std::to_string(a.byteOffset) + " run past the end of " + bv_name + " (" +
                                     std::to_string(bv.byteLength) + " bytes)");
    }
    v.data = m.buffers[(size_t)bv.buffer].data.data() + bv.byteOffset + a.byteOffset;
    return v;
}

void read_floats(const accessor_view &v, size_t i, float *out)
{
    if (!v.data) {
        for (int k = 0; k < v.components; k++) out[k] = 0.0f;
        return;
    }
    const unsigned char *p = v.data + i * v.stride;
    for (int k = 0; k < v.components; k++) {
        float f = 0.0f;
        switch (v.component_type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: std::memcpy(&f, p + 4 * k, 4); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: f = p[k]; if (v.normalized) f /= 255.0f; break;
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            f = (float)(signed char)p[k];
            if (v.normalized) f = f / 127.0f < -1.0f ? -1.0f : f / 127.0f;
            break;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t s;
            std::memcpy(&s, p + 2 * k, 2);
            f = s;
            if (v.normalized) f /= 65535.0f;
            break;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t s;
            std::memcpy(&s, p + 2 * k, 2);
            f = s;
            if (v.normalized) f = f / 32767.0f < -1.0f ? -1.0f : f / 32767.0f;
            break;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            uint32_t u;
            std::memcpy(&u, p + 4 * k, 4);
            f = (float)u;
            break;
        }
        default: break;
        }
        out[k] = f;
    }
}

uint32_t read_index(const accessor_view &v, size_t i)
{
    if (!v.data) return 0;
    const unsigned char *p = v.data + i * v.stride;
    switch (v.component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t s;
        std::memcpy(&s, p, 2);
        return s;
    }
    default: {
        uint32_t u;
        std::memcpy(&u, p, 4);
        return u;
    }
    }
}

} // namespace tl_gltf
