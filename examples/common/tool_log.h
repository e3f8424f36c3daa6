/* The tools' loggers (tool_log.c). */
#ifndef TL_TOOL_LOG_H
#define TL_TOOL_LOG_H

#include <stddef.h>
#include <stdint.h>

#include "thinlight/base.h"

/* Prints "TOOL: message" (errors) and "TOOL: warning: message" on stderr; `tool` must outlive it. */
tl_logger tl_tool_logger(const char *tool);

#define TL_TOOL_LOG_LINES 256

/* The same lines, each printed once: the bench makes many renderers of one scene and each would
 * warn alike, and a tool that prints a failed call's message after the logger did would print it
 * twice. Zeroed but for `tool`: ready. Lines past TL_TOOL_LOG_LINES distinct ones are printed
 * every time (never lost). */
typedef struct tl_tool_log {
    const char *tool;
    uint64_t printed[TL_TOOL_LOG_LINES]; /* hashes of the lines printed */
    size_t count;
    size_t repeats;                      /* lines left out because they were printed before */
} tl_tool_log;

/* One line through `log`: printed unless it was before; INFO is left out. */
void tl_tool_log_message(tl_tool_log *log, tl_log_level level, const char *message);
/* A formatted error line through `log`. */
void tl_tool_log_error(tl_tool_log *log, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* A logger that prints through `log`, which must outlive it. */
tl_logger tl_tool_log_logger(tl_tool_log *log);

#endif
