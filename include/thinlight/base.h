/* thinlight base definitions shared by every public header: export macro and result codes. */
#ifndef THINLIGHT_BASE_H
#define THINLIGHT_BASE_H

#include <stddef.h>
#include <stdint.h>

#if defined(TL_STATIC_DEFINE)
#  define TL_API
#elif defined(_WIN32)
#  if defined(TL_BUILDING_LIBRARY)
#    define TL_API __declspec(dllexport)
#  else
#    define TL_API __declspec(dllimport)
#  endif
#elif defined(__GNUC__)
#  define TL_API __attribute__((visibility("default")))
#else
#  define TL_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/** Result of every fallible call; 0 means success. */
typedef enum tl_result {
    TL_OK = 0,
    TL_ERROR_INVALID_ARGUMENT, /**< a NULL pointer, a size of zero or out of range, an unknown enum */
    TL_ERROR_OUT_OF_MEMORY,    /**< the allocator returned NULL */
    TL_ERROR_IO,               /**< a file could not be opened, read or written */
    TL_ERROR_PARSE,            /**< a file is malformed */
    TL_ERROR_UNSUPPORTED,      /**< valid input the library does not handle */
    TL_ERROR_LIMIT,            /**< a size or count beyond what the library or the context allows */
    TL_ERROR_GL,               /**< the GL context reported an error or lacks a capability */
    TL_RESULT_COUNT_
} tl_result;

/** Optional allocator; a zeroed one means malloc/free. */
typedef struct tl_allocator {
    void *(*alloc)(size_t size, void *user); /**< returns NULL on failure */
    void (*free)(void *ptr, void *user);
    void *user;
} tl_allocator;

typedef enum tl_log_level {
    TL_LOG_ERROR = 1, /**< the call fails; the message names the file, element or limit */
    TL_LOG_WARNING,   /**< a fallback was used (a missing texture became a flat colour, ...) */
    TL_LOG_INFO
} tl_log_level;

/** Optional logger: receives one line per message (no trailing newline). A zeroed logger is silent. */
typedef struct tl_logger {
    void (*fn)(void *user, tl_log_level level, const char *message);
    void *user;
} tl_logger;

/** A static, human-readable description of a result code (never NULL). */
TL_API const char *tl_result_string(tl_result result);

#ifdef __cplusplus
}
#endif
#endif
