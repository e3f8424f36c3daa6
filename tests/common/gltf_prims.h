/* glTF files of one mesh whose primitives the test describes (mode, indices, vertex colours, two UV
 * sets), for the tests of strips, fans, points, lines, COLOR_0 and TEXCOORD_1 (tests/io, tests/gl).
 * Written at run time with the fixture writer (gltf_doc.h); nothing binary is committed. */
#ifndef TL_GLTF_PRIMS_H
#define TL_GLTF_PRIMS_H

#include <stddef.h>
#include <stdint.h>

/* One primitive: POSITION (float), optional NORMAL, u32 indices, COLOR_0 and both UV sets. */
typedef struct tlf_prim {
    int mode;                 /* glTF mode 0..6; -1 leaves "mode" out (triangles) */
    const float (*pos)[3];
    size_t nv;
    const float (*nrm)[3];    /* NULL: no NORMAL */
    const uint32_t *idx;      /* NULL: not indexed */
    size_t ni;
    const float (*color)[4];  /* NULL: no COLOR_0 */
    int color_components;     /* 3 or 4 */
    int color_type;           /* 5126 float, 5121 normalised u8, 5123 normalised u16 */
    const float (*uv0)[2];    /* NULL: no TEXCOORD_0 */
    const float (*uv1)[2];    /* NULL: no TEXCOORD_1 */
    int material;             /* index into `materials`, -1: none */
} tlf_prim;

/* dir/name.gltf (+ .bin): one node drawing one mesh of `count` primitives; `materials` is the JSON
 * array's content (may be "" for none), `more` further top-level members (images, textures,
 * samplers, cameras...; may be ""). Images named in `more` must already lie in dir. Returns 0, or
 * -1 after a message on stderr. */
int tlf_write_prims(const char *dir, const char *name, const tlf_prim *prims, size_t count, const char *materials,
                    const char *more, char *path, size_t path_size);

#endif
