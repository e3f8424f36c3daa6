// Failures, warnings and allocation for the glTF adapter: the pieces every other gltf_*.cpp uses.
#include <cstring>

#include "gltf_internal.h"

namespace tl_gltf {

void fail(tl_result result, const std::string &message) { throw failure{result, message}; }

void warn(const context &c, const std::string &message)
{
    if (!c.logger.fn) return;
    // The logger takes one line per call; tinygltf's warnings can hold several.
    size_t start = 0;
    while (start <= message.size()) {
        size_t end = message.find('\n', start);
        if (end == std::string::npos) end = message.size();
        if (end > start) {
            std::string line = c.path + ": " + message.substr(start, end - start);
            c.logger.fn(c.logger.user, TL_LOG_WARNING, line.c_str());
        }
        start = end + 1;
    }
}

std::string element(const char *array, size_t index) { return std::string(array) + "[" + std::to_string(index) + "]"; }

std::string join_path(const std::string &dir, const std::string &file)
{
    if (dir.empty()) return file;
    return dir.back() == '/' ? dir + file : dir + "/" + file;
}

void *alloc_bytes(const context &c, size_t count, size_t size, const char *what)
{
    if (size != 0 && count > std::numeric_limits<size_t>::max() / size)
        fail(TL_ERROR_OUT_OF_MEMORY, std::string(what) + ": size overflows");
    size_t bytes = count * size;
    void *p = c.alloc.alloc(bytes ? bytes : 1, c.alloc.user);
    if (!p) fail(TL_ERROR_OUT_OF_MEMORY, std::string(what) + ": out of memory (" + std::to_string(bytes) + " bytes)");
    return p;
}

void free_bytes(const context &c, void *ptr)
{
    if (ptr) c.alloc.free(ptr, c.alloc.user);
}

} // namespace tl_gltf
