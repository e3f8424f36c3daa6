/* Last errors and loggers (log.h). */
#include "core/log.h"

#include <stdarg.h>
#include <stdio.h>

/* The logger contract (thinlight/base.h): one line, no trailing newline. Each run of line breaks
 * inside becomes one space (a path, a driver's or a parser's message may hold some); trailing
 * breaks and spaces go. */
static void tl__one_line(char *s)
{
    char *w = s;
    for (const char *r = s; *r;) {
        if (*r == '\n' || *r == '\r') {
            while (*r == '\n' || *r == '\r') r++;
            *w++ = ' ';
        } else {
            *w++ = *r++;
        }
    }
    while (w > s && (w[-1] == ' ' || w[-1] == '\t')) w--;
    *w = '\0';
}

static void tl__format(char *line, size_t size, const char *fmt, va_list ap)
{
    vsnprintf(line, size, fmt, ap);
    tl__one_line(line);
}

tl_result tl__log_fail(tl__log *log, tl_result result, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    tl__format(log->last_error, sizeof log->last_error, fmt, ap);
    va_end(ap);
    if (log->logger.fn) log->logger.fn(log->logger.user, TL_LOG_ERROR, log->last_error);
    return result;
}

void tl__log_message(const tl__log *log, tl_log_level level, const char *fmt, ...)
{
    if (!log->logger.fn) return;
    char line[TL__LOG_MESSAGE_SIZE];
    va_list ap;
    va_start(ap, fmt);
    tl__format(line, sizeof line, fmt, ap);
    va_end(ap);
    log->logger.fn(log->logger.user, level, line);
}

tl_result tl__logger_fail(const tl_logger *logger, tl_result result, const char *fmt, ...)
{
    if (!logger || !logger->fn) return result;
    char line[TL__LOG_MESSAGE_SIZE];
    va_list ap;
    va_start(ap, fmt);
    tl__format(line, sizeof line, fmt, ap);
    va_end(ap);
    logger->fn(logger->user, TL_LOG_ERROR, line);
    return result;
}

void tl__logger_message(const tl_logger *logger, tl_log_level level, const char *fmt, ...)
{
    if (!logger || !logger->fn) return;
    char line[TL__LOG_MESSAGE_SIZE];
    va_list ap;
    va_start(ap, fmt);
    tl__format(line, sizeof line, fmt, ap);
    va_end(ap);
    logger->fn(logger->user, level, line);
}

/* tl_last_error_logger's function: the error line kept in the caller's record, every line passed on. */
static void tl__keep_last_error(void *user, tl_log_level level, const char *message)
{
    tl_last_error *last = (tl_last_error *)user;
    if (level == TL_LOG_ERROR) {
        snprintf(last->message, sizeof last->message, "%s", message);
        last->count++;
    }
    if (last->next.fn) last->next.fn(last->next.user, level, message);
}

tl_logger tl_last_error_logger(tl_last_error *last)
{
    tl_logger logger = {0};
    if (last) {
        logger.fn = tl__keep_last_error;
        logger.user = last;
    }
    return logger;
}
