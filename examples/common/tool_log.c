/* The tools' loggers: errors and warnings as one line each on stderr, prefixed with the tool's
 * name; tl_tool_log prints each line once. */
#include <stdarg.h>
#include <stdio.h>

#include "tool_log.h"

static void tl__tool_print(const char *tool, tl_log_level level, const char *message)
{
    fprintf(stderr, "%s: %s%s\n", tool, level == TL_LOG_WARNING ? "warning: " : "", message);
}

static void tl__tool_log(void *user, tl_log_level level, const char *message)
{
    if (level != TL_LOG_INFO) tl__tool_print((const char *)user, level, message);
}

tl_logger tl_tool_logger(const char *tool)
{
    return (tl_logger){tl__tool_log, (void *)(uintptr_t)tool};
}

/* FNV-1a of the level and the text. */
static uint64_t tl__line_hash(tl_log_level level, const char *message)
{
    uint64_t h = 14695981039346656037ull ^ (uint64_t)level;
    for (const unsigned char *p = (const unsigned char *)message; *p; p++) h = (h ^ *p) * 1099511628211ull;
    return h;
}

void tl_tool_log_message(tl_tool_log *log, tl_log_level level, const char *message)
{
    if (level == TL_LOG_INFO) return;
    uint64_t h = tl__line_hash(level, message);
    for (size_t i = 0; i < log->count; i++)
        if (log->printed[i] == h) {
            log->repeats++;
            return;
        }
    if (log->count < TL_TOOL_LOG_LINES) log->printed[log->count++] = h;
    tl__tool_print(log->tool, level, message);
}

void tl_tool_log_error(tl_tool_log *log, const char *fmt, ...)
{
    char line[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    tl_tool_log_message(log, TL_LOG_ERROR, line);
}

static void tl__tool_log_once(void *user, tl_log_level level, const char *message)
{
    tl_tool_log_message((tl_tool_log *)user, level, message);
}

tl_logger tl_tool_log_logger(tl_tool_log *log) { return (tl_logger){tl__tool_log_once, log}; }
