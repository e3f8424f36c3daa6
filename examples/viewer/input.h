/* Keys and mouse (input.c). */
#ifndef THINLIGHT_VIEWER_INPUT_H
#define THINLIGHT_VIEWER_INPUT_H

#include "viewer.h"

typedef struct GLFWwindow GLFWwindow;

typedef struct vw_input {
    vw_app *app;
    double x, y;                   /* the cursor */
    int left, right;               /* buttons held over the scene */
    uint32_t pending_w, pending_h; /* a new framebuffer size, 0 when none */
} vw_input;

void vw_input_install(vw_input *in, GLFWwindow *w);
void vw_input_poll(vw_input *in, GLFWwindow *w, float dt);

#endif
