/* make_gltf_scenes DIR [CASE...]: writes the three glTF test scenes (gltf_fixtures.h) for other
 * tests, the docs and manual renders; with case names, those cases of tlf_write_case instead (the
 * shadow scenes of the tools' tests: shadow_spot, shadow_spot_cast, ...). */
#include <stdio.h>

#include "gltf_fixtures.h"

int main(int argc, char **argv)
{
    if (argc < 2 || argv[1][0] == '-') {
        fprintf(stderr, "usage: make_gltf_scenes DIR [CASE...]\n"
                        "writes textured_boxes.gltf, materials.glb and lights.gltf (and their files) into DIR,\n"
                        "or the named test cases (gltf_fixtures.h, tlf_write_case)\n");
        return 2;
    }
    if (argc == 2) return tl_test_write_gltf_scenes(argv[1]) == 0 ? 0 : 1;
    if (tlf_mkdir_p(argv[1])) {
        fprintf(stderr, "make_gltf_scenes: cannot create %s\n", argv[1]);
        return 1;
    }
    for (int i = 2; i < argc; i++) {
        char path[1024];
        if (tlf_write_case(argv[1], argv[i], path, sizeof path)) return 1; /* the reason is printed */
    }
    return 0;
}
