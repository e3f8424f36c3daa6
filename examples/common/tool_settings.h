/* The renderer settings thinlight-render and thinlight-viewer share (--mode, --light-strategy,
 * --light-scale, --transparency, --depth, --rt0, --light-buffer, --light-format, --lighting, --fresnel, --ambient, --tile-size,
 * --tiled-shading, --fxaa, --exposure, --no-depth-prepass), into a tl_renderer_desc. Not part of
 * the library. */
#ifndef TL_TOOL_SETTINGS_H
#define TL_TOOL_SETTINGS_H

#include "thinlight/renderer.h"
#include "tool_args.h"

/* Help lines of the options (end with a newline). */
extern const char tl_tool_settings_help[];
/* The options, for a tool's parser (tool_args.h). */
extern const tl_opt_table tl_tool_settings_option_table;

/* A parsed option into `d`: 1 when `o` is one of tl_tool_settings_option_table, 0 when it is not,
 * 2 (bad usage) after one line for a name the library does not know. */
int tl_tool_settings_apply(const char *tool, tl_renderer_desc *d, const tl_opt *o, const tl_opt_value *v);

#endif
