/* glTF test files, written at run time (nothing binary is committed): the three test scenes other
 * tests and the docs use (gltf_scenes.c), and the named good and bad cases that tests/io and
 * tests/input load (gltf_cases.c). Plain C; PNGs go through tl_image_write (thinlight/io.h). */
#ifndef TL_GLTF_FIXTURES_H
#define TL_GLTF_FIXTURES_H

#include <stddef.h>
#include <stdint.h>

/* How a file keeps its binary data. */
typedef enum tlf_storage {
    TLF_EXTERNAL = 0, /* name.gltf + name.bin + PNG files beside it */
    TLF_DATA_URI,     /* name.gltf alone: buffers and images as base64 data: URIs */
    TLF_GLB           /* name.glb alone: one BIN chunk holds the buffer and the images */
} tlf_storage;

/**
 * Writes the three test scenes into `dir` (which must exist):
 *  - textured_boxes.gltf (+ .bin, albedo/normal/metallic-roughness PNGs): a node hierarchy with
 *    TRS and matrix transforms, an instanced mesh, a two-primitive mesh, a perspective camera,
 *    no lights (the loader adds its default rig);
 *  - materials.glb: eight upright quads in a row facing +Z, one per material: metal, dielectric, half-metal, alpha MASK with
 *    a texture, alpha BLEND, double-sided emissive, a metallic-roughness texture, and glTF's
 *    default material; UVs as normalised 8 and 16-bit integers;
 *  - lights.gltf (data URIs only): a floor and a box lit by KHR_lights_punctual point (with and
 *    without range), spot (inside a moved parent) and directional lights; no camera.
 * Returns 0, or -1 after a message on stderr.
 */
int tl_test_write_gltf_scenes(const char *dir);

/* The scenes one by one, in any storage; `name` has no extension (it is added). */
int tlf_write_textured_boxes(const char *dir, const char *name, tlf_storage storage);
int tlf_write_materials(const char *dir, const char *name, tlf_storage storage);
int tlf_write_lights(const char *dir, const char *name, tlf_storage storage);

/**
 * Writes the named test case into `dir` and puts the path of the file to load into `path`.
 * Cases: see gltf_cases.c (tlf_case_names lists them). Returns 0, or -1 for an
 * unknown name or a write failure.
 */
int tlf_write_case(const char *dir, const char *name, char *path, size_t path_size);
/* NULL-terminated list of the case names. */
extern const char *const tlf_case_names[];

/* Helpers the tests use too. */
int tlf_mkdir_p(const char *dir);                        /* 0 when it exists afterwards */
void tlf_join(char *out, size_t size, const char *dir, const char *name);
int tlf_write_file(const char *path, const void *data, size_t size);
/* Reads a whole file with malloc; NULL on failure. */
unsigned char *tlf_read_file(const char *path, size_t *size);

#endif
