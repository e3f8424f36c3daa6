/* make_gltf_scenes DIR: writes the three glTF test scenes (gltf_fixtures.h) for other tests, the
 * docs and manual renders. */
#include <stdio.h>

#include "gltf_fixtures.h"

int main(int argc, char **argv)
{
    if (argc != 2 || argv[1][0] == '-') {
        fprintf(stderr, "usage: make_gltf_scenes DIR\n"
                        "writes textured_boxes.gltf, materials.glb and lights.gltf (and their files) into DIR\n");
        return 2;
    }
    return tl_test_write_gltf_scenes(argv[1]) == 0 ? 0 : 1;
}
