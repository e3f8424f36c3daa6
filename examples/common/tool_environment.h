/* The environment file of the renderer tools (--environment FILE.hdr|.exr; --background and
 * --environment-intensity are renderer options, tool_options.h): its path, the file read before any
 * context is made (a missing or corrupt file, or one of the wrong shape, is one line and exit 1),
 * and set on the renderer. Not part of the library. */
#ifndef TL_TOOL_ENVIRONMENT_H
#define TL_TOOL_ENVIRONMENT_H

#include "thinlight/renderer.h"
#include "tool_args.h"

typedef struct tl_tool_environment {
    const char *path;     /* --environment, or NULL */
    float *rgb;           /* its pixels once read (tl_tool_environment_read), malloc'd */
    uint32_t width, height;
} tl_tool_environment;

extern const char tl_tool_environment_help[];
extern const tl_opt_table tl_tool_environment_option_table;

/* A parsed option: 1 when it is --environment (its path kept in e), 0 when it is not. */
int tl_tool_environment_apply(tl_tool_environment *e, const tl_opt *o, const tl_opt_value *v);
/* Reads e->path (nothing without one): 0, or 1 after one line naming the file and the problem. */
int tl_tool_environment_read(const char *tool, tl_tool_environment *e);
/* Sets the read environment on r (nothing without one): 0, or 1 after one line. */
int tl_tool_environment_set(const char *tool, const tl_tool_environment *e, tl_renderer *r);
void tl_tool_environment_free(tl_tool_environment *e);

#endif
