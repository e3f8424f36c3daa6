/* The memory budgets of the renderer tools (thinlight-render, thinlight-bench, thinlight-viewer):
 * the renderer's target memory (tl_renderer_desc.max_target_bytes) and the glTF load's memory and
 * texture size (tl_gltf_options.max_memory, max_texture_pixels), each with a default and an
 * option (docs/renderer-limits.md, "The tools' budgets"). Not part of the library. */
#ifndef TL_TOOL_BUDGET_H
#define TL_TOOL_BUDGET_H

#include <stddef.h>
#include <stdint.h>

#include "thinlight/io.h"
#include "thinlight/renderer.h"
#include "tool_args.h"

/* The default target budget of the tools: 2 GiB, enough for a 7680x4320 frame in every mode (fat:
 * 1.9 GiB) and for 3840x2160 with every effect on and every target kept (fat: 0.7 GiB), within a
 * small GPU's memory; a 16384x16384 frame (21 B/px or more: 5.2 GiB) is refused before anything
 * is allocated. */
#define TL_TOOL_DEFAULT_TARGET_BYTES ((uint64_t)2 << 30)

/* Zeroed: every default. */
typedef struct tl_tool_budgets {
    uint64_t target_bytes;   /* --max-target-memory: 0 = TL_TOOL_DEFAULT_TARGET_BYTES, UINT64_MAX = none */
    uint64_t load_bytes;     /* --max-load-memory: 0 = TL_GLTF_DEFAULT_MAX_MEMORY (512 MiB), UINT64_MAX = none */
    uint64_t texture_pixels; /* --max-texture-pixels: 0 = the loader's default, 2^26 (8192x8192) */
} tl_tool_budgets;

/* Help lines of the options (end with a newline). */
extern const char tl_tool_budget_help[];
/* The options, for a tool's parser (tool_args.h). */
extern const tl_opt_table tl_tool_budget_option_table;

/* A parsed option into `b`: 1 when `o` is one of tl_tool_budget_option_table, 0 otherwise. */
int tl_tool_budget_option(tl_tool_budgets *b, const tl_opt *o, const tl_opt_value *v);

/* The budgets into a renderer descriptor and glTF load options. */
void tl_tool_budget_renderer(const tl_tool_budgets *b, tl_renderer_desc *d);
void tl_tool_budget_gltf(const tl_tool_budgets *b, tl_gltf_options *o);

/* Whether the targets of a renderer made from `d` (its budget set) with `scene` fit the budget, from
 * the plan alone (no GL): 0, or 1 after one line "TOOL: WHAT: the targets of a WxH frame need ...,
 * over the target-memory budget of ... (--max-target-memory)"; `what` may be NULL. */
int tl_tool_budget_check(const char *tool, const char *what, const tl_renderer_desc *d, const tl_scene *scene);

#endif
