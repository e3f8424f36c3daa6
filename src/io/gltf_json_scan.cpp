// A look at the JSON text before any parser sees it: how deep it nests and how much a parser may
// allocate for it. tinygltf converts extras and extensions recursively, and nlohmann-json copies
// and prints recursively, so a file nested thousands deep would run them out of stack; and a
// few bytes of JSON ("{}," makes a 2 KiB tinygltf::Material) can ask for a lot of memory. One
// pass, no allocation, no recursion.
#include "gltf_internal.h"

namespace tl_gltf {

json_shape scan_json(const unsigned char *t, size_t n)
{
    json_shape s;
    bool is_array[max_json_depth + 2] = {false}; // by depth, 1 = the root
    size_t depth = 0;
    bool in_string = false;
    for (size_t i = 0; i < n; i++) {
        unsigned char ch = t[i];
        if (in_string) {
            if (ch == '\\') i++; // the escaped character cannot end the string
            else if (ch == '"') in_string = false;
            s.string_bytes++;
            continue;
        }
        switch (ch) {
        case '"': in_string = true; break;
        case '{':
        case '[':
            s.containers++;
            if (++depth > s.depth) s.depth = depth;
            if (depth > max_json_depth) {
                s.deep_at = i;
                return s;
            }
            is_array[depth] = ch == '[';
            // An object in an array that is a member of the root object: one tinygltf struct.
            if (ch == '{' && depth == 3 && is_array[2] && !is_array[1]) s.elements++;
            break;
        case '}':
        case ']':
            if (depth) depth--;
            break;
        case ',': s.items++; break;
        case ':': s.members++; break;
        default: break;
        }
    }
    return s;
}

size_t json_parse_cost(const json_shape &s)
{
    // Upper estimates per token, for nlohmann's DOM and tinygltf's model together (measured on
    // 64-bit libstdc++ with nlohmann-json 3.11 and tinygltf 2.7; tests: gltf_limits_*):
    //  - a container: its map or vector in the DOM, and a tinygltf::Value when it sits in extras;
    //  - an object member: a map node with its key and value, and again in a Value;
    //  - an array item: a slot in the vector (with growth) and a Value;
    //  - an element of a top-level array: the tinygltf struct it becomes (Material: 2144 bytes);
    //  - string bytes: the DOM, tinygltf's copy (uri, name), and a data URI decoded twice.
    const double cost = 4096.0 + 256.0 * (double)s.containers + 384.0 * (double)s.members +
                        192.0 * (double)s.items + 2304.0 * (double)s.elements + 4.0 * (double)s.string_bytes;
    return cost >= (double)SIZE_MAX ? SIZE_MAX : (size_t)cost;
}

} // namespace tl_gltf
