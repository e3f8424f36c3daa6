/**
 * @file thinlight/base.h
 * @brief Definitions every public header shares: the export macro, result codes, the optional
 * allocator and logger.
 *
 * Conventions of the whole API: fallible calls return tl_result (TL_OK = 0) and write outputs
 * through out-parameters; every create call takes a descriptor whose zeroed fields mean
 * "default"; every *_create / *_load has its *_destroy / *_free; the library never aborts or
 * exits on bad input.
 */
#ifndef THINLIGHT_BASE_H
#define THINLIGHT_BASE_H

#include <stddef.h>
#include <stdint.h>

/**
 * @def TL_API
 * Marks a function of the public API. The libraries are built with hidden visibility, so only
 * TL_API names are exported from libthinlight.so and libthinlight-codec.so. Consumers of the
 * static libraries get TL_STATIC_DEFINE from the CMake targets (it only matters on Windows,
 * where TL_API is otherwise __declspec(dllimport)).
 */
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

/** Result of every fallible call; 0 means success. tl_result_string() names each code; the
 *  object or call that failed has a detailed message. */
typedef enum tl_result {
    TL_OK = 0,                 /**< success */
    TL_ERROR_INVALID_ARGUMENT, /**< a NULL pointer, a size of zero or out of range, an unknown enum */
    TL_ERROR_OUT_OF_MEMORY,    /**< the allocator returned NULL */
    TL_ERROR_IO,               /**< a file could not be opened, read or written */
    TL_ERROR_PARSE,            /**< a file is malformed */
    TL_ERROR_UNSUPPORTED,      /**< valid input the library does not handle, or a part not built in */
    TL_ERROR_LIMIT,            /**< a size or count beyond what the library or the context allows */
    TL_ERROR_GL,               /**< the GL context reported an error or lacks a capability */
    TL_RESULT_COUNT_           /**< number of codes (not a result) */
} tl_result;

/**
 * Optional allocator, in the descriptor of every call that allocates. A zeroed one means
 * malloc/free; otherwise both functions must be set (a half-set allocator is
 * TL_ERROR_INVALID_ARGUMENT). Memory is freed with the allocator it came from.
 */
typedef struct tl_allocator {
    /** Returns `size` bytes aligned for any object type (like malloc), or NULL on failure. */
    void *(*alloc)(size_t size, void *user);
    /** Frees memory from `alloc`; never called with NULL. */
    void (*free)(void *ptr, void *user);
    void *user; /**< passed to both functions */
} tl_allocator;

/** Severity of a message given to a tl_logger. */
typedef enum tl_log_level {
    TL_LOG_ERROR = 1, /**< the call fails; the message names the file, element or limit */
    TL_LOG_WARNING,   /**< a fallback was used (a missing texture became a flat colour, ...) */
    TL_LOG_INFO       /**< progress or facts worth knowing (a context version lower than asked) */
} tl_log_level;

/** Optional logger, in the descriptor of calls that can say more than a tl_result. A zeroed
 *  logger is silent. */
typedef struct tl_logger {
    /** Receives one line per message, without a trailing newline, on the thread of the call
     *  that logs; `message` is valid only during the call. */
    void (*fn)(void *user, tl_log_level level, const char *message);
    void *user; /**< passed to `fn` */
} tl_logger;

/** A static, human-readable description of a result code (never NULL; "unknown result" for a
 *  value that is not a tl_result). */
TL_API const char *tl_result_string(tl_result result);

/** Bytes of tl_last_error.message: a logged line is at most TL_LOG_LINE_MAX - 1 bytes. */
#define TL_LOG_LINE_MAX 1024

/**
 * The one place to read why any call failed: a caller-owned record that the logger made by
 * tl_last_error_logger() fills. Give that logger to every descriptor (tl_renderer_desc,
 * tl_context_desc, tl_gltf_options, tl_image_desc, tl_file_write_desc, ...): after any call fails,
 * `message` is that call's line, whichever layer it came from (docs/getting-started.md, "Errors,
 * logging and memory"). Zero it before use; it is written on the thread of the call that logs.
 */
typedef struct tl_last_error {
    char message[TL_LOG_LINE_MAX]; /**< the last TL_LOG_ERROR line received; "" before the first */
    uint64_t count;                /**< TL_LOG_ERROR lines received: a program tells a new failure from an old one */
    tl_logger next;                /**< every line (errors, warnings, information) is passed on to it; zeroed: none */
} tl_last_error;

/** A tl_logger that keeps each error line in `last` (and passes every line on to last->next).
 *  NULL gives a silent logger. */
TL_API tl_logger tl_last_error_logger(tl_last_error *last);

#ifdef __cplusplus
}
#endif
#endif
