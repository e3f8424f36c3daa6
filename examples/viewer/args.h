/* The viewer's command line. */
#ifndef THINLIGHT_VIEWER_ARGS_H
#define THINLIGHT_VIEWER_ARGS_H

#include <stdio.h>

#include "tool_budget.h"
#include "tool_environment.h"
#include "viewer.h"

typedef struct vw_args {
    const char *scene;           /* NULL: the crypt */
    uint32_t width, height;
    tl_renderer_desc desc;       /* the settings given */
    tl_tool_budgets budgets;     /* --max-target-memory, --max-load-memory, --max-texture-pixels */
    uint32_t lights;
    int lights_set;
    vw_view view;
    int grid, split, animate, no_panel, print_targets, screenshot_window;
    tl_render_mode split_mode;
    const char *screenshot;
    uint32_t frames;             /* 0: run until closed */
    uint32_t resize_w, resize_h; /* 0: no resize */
    int dynamic_light_scale;     /* --dynamic-light-scale */
    double light_budget_ms;      /* --light-budget-ms (default 33.3) */
    uint32_t move_first, move_count; /* --move-camera FIRST,COUNT: scripted orbit (tests); count 0: none */
    int print_frames;            /* --print-frames: one line per frame on stdout */
    int shadows;                 /* --shadows: the crypt's moonlight and braziers cast */
    tl_tool_environment env;     /* --background, --environment (tool_environment.h) */
} vw_args;

void vw_print_usage(FILE *f);
/** -1: go on; otherwise the exit status (0 after --help, 2 after one line on stderr). */
int vw_parse_args(int argc, char **argv, vw_args *a);

#endif
