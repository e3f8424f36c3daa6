// A look at the JSON text before any parser sees it: how deep it nests and how much a parser may
// allocate for it. tinygltf converts extras and extensions recursively, and nlohmann-json copies
// and prints recursively, so a file nested thousands deep would run them out of stack; and a
// few bytes of JSON ("{}," makes a 2 KiB tinygltf::Material) can ask for a lot of memory. One
// pass, no allocation, no recursion.
#include <cstring>

#include "gltf_internal.h"

namespace tl_gltf {

json_shape scan_json(const unsigned char *t, size_t n)
{
    json_shape s;
    bool is_array[max_json_depth + 2] = {false}; // by depth, 1 = the root
    size_t depth = 0, string_start = 0, string_end = 0;
    bool in_string = false, key_is_materials = false, in_materials = false;
    for (size_t i = 0; i < n; i++) {
        unsigned char ch = t[i];
        if (in_string) {
            if (ch == '\\') i++; // the escaped character cannot end the string
            else if (ch == '"') in_string = false, string_end = i;
            s.string_bytes++;
            continue;
        }
        switch (ch) {
        case '"':
            in_string = true;
            string_start = i + 1;
            break;
        case '{':
        case '[':
            s.containers++;
            if (++depth > s.depth) s.depth = depth;
            if (depth > max_json_depth) {
                s.deep_at = i;
                return s;
            }
            is_array[depth] = ch == '[';
            if (depth == 2) in_materials = key_is_materials && ch == '[';
            // An object in an array that is a member of the root object: one tinygltf struct.
            if (ch == '{' && depth == 3 && is_array[2] && !is_array[1]) (in_materials ? s.materials : s.elements)++;
            break;
        case '}':
        case ']':
            if (depth) depth--;
            break;
        case ',': s.items++; break;
        case ':':
            s.members++;
            // a member of the root object: is it "materials" (the largest tinygltf struct)?
            if (depth == 1)
                key_is_materials = string_end == string_start + 9 && std::memcmp(t + string_start, "materials", 9) == 0;
            break;
        default: break;
        }
    }
    return s;
}

size_t json_parse_cost(const json_shape &s)
{
    // Upper estimates per token for nlohmann's DOM and tinygltf's model together, with vector
    // growth (a vector holds up to twice its elements while it grows). Measured against peak RSS
    // on 64-bit libstdc++, nlohmann-json 3.11, tinygltf 2.7 (estimate / real): 300000 empty
    // materials 1.4, 300000 empty nodes 3.0, 100000 cameras 2.9, 2 million zeros in extras 1.8,
    // a 50 MB string 1.4, a 40 MB data URI 1.2.
    //  - a container: its map or vector in the DOM, and a tinygltf::Value when it sits in extras;
    //  - an object member: a map node with its key and value, and again in a Value;
    //  - an array item: a slot in the vector and a Value (152 bytes), both growing;
    //  - an element of a top-level array: the tinygltf struct it becomes, twice for growth
    //    (Material 2144 bytes, the others at most 920: Camera);
    //  - string bytes: the DOM, tinygltf's copy (uri, name), a data URI decoded twice, and ours.
    const double cost = 4096.0 + 256.0 * (double)s.containers + 384.0 * (double)s.members + 320.0 * (double)s.items +
                        2048.0 * (double)s.elements + 4608.0 * (double)s.materials + 5.0 * (double)s.string_bytes;
    return cost >= (double)SIZE_MAX ? SIZE_MAX : (size_t)cost;
}

} // namespace tl_gltf
