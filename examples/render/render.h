/* thinlight-render's command line (render_args.c), used by render.c. */
#ifndef TL_RENDER_TOOL_H
#define TL_RENDER_TOOL_H

#include "thinlight/renderer.h"
#include "thinlight/scene.h"
#include "tool_budget.h"
#include "tool_environment.h"
#include "tool_gl.h"

#define RENDER_TOOL "thinlight-render"

typedef struct render_args {
    const char *scene, *out, *dump;
    tl_renderer_desc rd;
    tl_default_scene_desc sd;
    uint32_t frames;
    int stats, plan, zero_points, zero_spots, hdr_out;
    int shadow_move; /* 1: a casting local light moves every frame, 2: an object near it does */
    tl_tool_context_args context_args;
    tl_tool_context_options ctx;
    tl_tool_budgets budgets;
    tl_tool_environment env; /* --background, --environment (tool_environment.h) */
} render_args;

/* argv into `a`: 0; -1 after --help or --list-options (printed); or 2 after one line on stderr. */
int render_parse_args(int argc, char **argv, render_args *a);

#endif
