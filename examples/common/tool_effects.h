/* The screen-space effect options the tools share (docs/effects.md): --ssao, --fog, --dof, --bloom, --ssr and their
 * parameters, into a tl_renderer_desc. Not part of the library. */
#ifndef TL_TOOL_EFFECTS_H
#define TL_TOOL_EFFECTS_H

#include "thinlight/renderer.h"

/* Help lines for the options. */
extern const char tl_tool_effects_help[];

/* One option: 0 when `opt` is not an effect option, 1 when it was a flag (value unused), 2 when
 * it took `value` (NULL: missing), -1 after printing "TOOL: message" for a bad value. */
int tl_tool_effect_option(const char *tool, tl_renderer_desc *d, const char *opt, const char *value);

#endif
