/* A tl_logger for the tools: errors and warnings as one line each on stderr, prefixed with the
 * tool's name. */
#include <stdio.h>

#include "tool_log.h"

static void tl__tool_log(void *user, tl_log_level level, const char *message)
{
    if (level == TL_LOG_INFO) return;
    fprintf(stderr, "%s: %s%s\n", (const char *)user, level == TL_LOG_WARNING ? "warning: " : "", message);
}

tl_logger tl_tool_logger(const char *tool)
{
    return (tl_logger){tl__tool_log, (void *)(uintptr_t)tool};
}
