/* Scenes of quads for the screen-space effects' tests (test_effects.c, ssao_reference.c): an open
 * floor, an inner corner, a wall facing the camera; and the pixel a world point falls in. */
#ifndef TL_EFFECTS_SCENES_H
#define TL_EFFECTS_SCENES_H

#include <stddef.h>
#include <stdint.h>

#include "thinlight/renderer.h"
#include "thinlight/scene.h"

typedef struct quads {
    tl_vertex v[32];
    uint32_t idx[48];
    tl_object obj[1];
    tl_material mat[1];
    tl_light light[1];
    tl_scene s;
    size_t nv, ni;
} quads;

/* Floor y = 0 over [-100, 100]^2, seen from (0, 2, 6). */
void plane_scene(quads *q);
/* Floor y = 0 and a wall z = -2 facing +z: an inner corner along y = 0, z = -2, seen from (0, 3, 6). */
void corner_scene(quads *q);
/* A wall z = -dist facing the camera at the origin, filling the view. */
void wall_scene(quads *q, float dist);

/* The pixel a world point falls in (camera and projection as the renderer builds them); 0 when it
 * is outside the image. */
int project(const tl_camera *c, uint32_t w, uint32_t h, const double p[3], int *x, int *y);

#endif
