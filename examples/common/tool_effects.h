/* The screen-space effect options the tools share (docs/effects.md): --ssao, --fog, --dof, --bloom, --ssr and their
 * parameters, into a tl_renderer_desc. Not part of the library. */
#ifndef TL_TOOL_EFFECTS_H
#define TL_TOOL_EFFECTS_H

#include "thinlight/renderer.h"
#include "tool_args.h"

/* Help lines for the options. */
extern const char tl_tool_effects_help[];

/* The options, for a tool's parser (tool_args.h). */
extern const tl_opt_table tl_tool_effect_options;

/* A parsed option into `d`: 1 when `o` is one of tl_tool_effect_options, 0 otherwise. */
int tl_tool_effect_apply(tl_renderer_desc *d, const tl_opt *o, const tl_opt_value *v);

/* Turns on the effect of a flag ("--ssao", ...) with its defaults; 0 when `flag` is none. */
int tl_tool_effect_flag(tl_renderer_desc *d, const char *flag);

#endif
