/* The tools' logger (tool_log.c). */
#ifndef TL_TOOL_LOG_H
#define TL_TOOL_LOG_H

#include <stdint.h>

#include "thinlight/base.h"

/* Prints "TOOL: message" (errors) and "TOOL: warning: message" on stderr; `tool` must outlive it. */
tl_logger tl_tool_logger(const char *tool);

#endif
