/* A closed room (inward faces) with a box in it: the scene of the renderer tests in tests/gl and
 * tests/input, whose renderers come from render_fixture.h. */
#ifndef TL_RENDER_ROOM_H
#define TL_RENDER_ROOM_H

#include <stdint.h>

#include "render_fixture.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"

typedef struct test_scene {
    tl_vertex v[64];
    uint32_t idx[96];
    tl_object obj[2];
    tl_material mat[2];
    tl_light lights[4];
    tl_scene s;
} test_scene;

/* Room [-10,10] x [0,10] x [-10,10] seen from inside, plus a box [-1,1] x [0,2] x [-1,1]. */
void build_room(test_scene *t);


#endif
