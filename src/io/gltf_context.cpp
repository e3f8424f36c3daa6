// Failures, warnings, the memory budget and allocation for the glTF adapter: the pieces every
// other gltf_*.cpp uses.
#include <cstdio>
#include <cstring>

#include "gltf_internal.h"

namespace tl_gltf {

void fail(tl_result result, const std::string &message) { throw failure{result, message}; }

void warn(const context &c, const std::string &message)
{
    if (!c.logger.fn) return;
    // tinygltf's warnings can hold several, one a line: each is a warning of its own.
    size_t start = 0;
    while (start <= message.size()) {
        size_t end = message.find_first_of("\r\n", start);
        if (end == std::string::npos) end = message.size();
        if (end > start)
            tl__logger_message(&c.logger, TL_LOG_WARNING, "%s: %s", c.name.c_str(),
                               message.substr(start, end - start).c_str());
        start = end + 1;
    }
}

std::string element(const char *array, size_t index) { return std::string(array) + "[" + std::to_string(index) + "]"; }

std::string byte_size(size_t bytes)
{
    if (bytes < 10240) return std::to_string(bytes) + " bytes";
    char text[64];
    if (bytes < ((size_t)10 << 20))
        std::snprintf(text, sizeof text, "%.1f KiB", (double)bytes / 1024.0);
    else
        std::snprintf(text, sizeof text, "%.1f MiB", (double)bytes / (1024.0 * 1024.0));
    return text;
}

void charge(const context &c, size_t bytes, const std::string &what)
{
    if (bytes > c.budget - c.used)
        fail(TL_ERROR_LIMIT, what + ": " + byte_size(bytes) + " would exceed the load's memory budget of " +
                                 byte_size(c.budget) + " (max_memory; " + byte_size(c.used) + " in use)");
    c.used += bytes;
    if (c.used > c.peak) c.peak = c.used;
}

void uncharge(const context &c, size_t bytes) { c.used -= bytes < c.used ? bytes : c.used; }

size_t budget_left(const context &c) { return c.budget - c.used; }

void *alloc_bytes(const context &c, size_t count, size_t size, const std::string &what)
{
    if (size != 0 && count > std::numeric_limits<size_t>::max() / size)
        fail(TL_ERROR_LIMIT, what + ": " + std::to_string(count) + " elements of " + std::to_string(size) +
                                 " bytes overflow the address space");
    size_t bytes = count * size;
    charge(c, bytes, what);
    void *p = tl__alloc(&c.alloc, bytes);
    if (!p) {
        uncharge(c, bytes);
        fail(TL_ERROR_OUT_OF_MEMORY, what + ": out of memory (" + std::to_string(bytes) + " bytes)");
    }
    return p;
}

void free_bytes(const context &c, void *ptr, size_t bytes)
{
    if (!ptr) return;
    uncharge(c, bytes);
    tl__free(&c.alloc, ptr);
}

} // namespace tl_gltf
