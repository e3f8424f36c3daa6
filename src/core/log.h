/* The one error channel of every layer (render, platform, scene, io; docs/getting-started.md,
 * "Errors, logging and memory"): a failing call returns its tl_result, records one line (which
 * file, which limit, which pass) as its object's last error and sends it to the logger of the
 * descriptor the object was made with; a call with no object to keep it (a failing create, a
 * load) sends the line to its descriptor's logger only. Nothing else is written anywhere: no
 * stderr, no global or thread-local error. Every message is made one line here (line breaks
 * inside become spaces) and cut at TL__LOG_MESSAGE_SIZE - 1 bytes. */
#ifndef TL_CORE_LOG_H
#define TL_CORE_LOG_H

#include <stddef.h>

#include "thinlight/base.h"

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__)
#  define TL__PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#  define TL__PRINTF_LIKE(f, a)
#endif

#define TL__LOG_MESSAGE_SIZE TL_LOG_LINE_MAX /* the public bound (base.h) */

typedef struct tl__log {
    tl_logger logger;                    /* zeroed: silent */
    char last_error[TL__LOG_MESSAGE_SIZE]; /* "" when no call has failed */
} tl__log;

/* Records the message as the last error, logs it as TL_LOG_ERROR and returns `result`. */
tl_result tl__log_fail(tl__log *log, tl_result result, const char *fmt, ...) TL__PRINTF_LIKE(3, 4);
/* Sends a warning or information line to the logger only. */
void tl__log_message(const tl__log *log, tl_log_level level, const char *fmt, ...) TL__PRINTF_LIKE(3, 4);
/* For calls that have no object (a failing create, a load): logs an error line, returns `result`.
 * `logger` may be NULL or zeroed (silent). */
tl_result tl__logger_fail(const tl_logger *logger, tl_result result, const char *fmt, ...) TL__PRINTF_LIKE(3, 4);
/* A warning or information line for calls that have no object; `logger` may be NULL or zeroed. */
void tl__logger_message(const tl_logger *logger, tl_log_level level, const char *fmt, ...) TL__PRINTF_LIKE(3, 4);

#ifdef __cplusplus
}
#endif
#endif
