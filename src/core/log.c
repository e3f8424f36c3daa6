/* Last errors and loggers (log.h). */
#include "core/log.h"

#include <stdarg.h>
#include <stdio.h>

tl_result tl__log_fail(tl__log *log, tl_result result, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(log->last_error, sizeof log->last_error, fmt, ap);
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
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    log->logger.fn(log->logger.user, level, line);
}

tl_result tl__logger_fail(const tl_logger *logger, tl_result result, const char *fmt, ...)
{
    if (!logger || !logger->fn) return result;
    char line[TL__LOG_MESSAGE_SIZE];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    logger->fn(logger->user, TL_LOG_ERROR, line);
    return result;
}
