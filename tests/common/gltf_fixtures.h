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

/* A shadow scene (tests of shadows from files): a 20 m floor facing +Y at y = 0 and a box of half
 * size TLF_SHADOW_BOX_HALF floating at y = TLF_SHADOW_BOX_Y above the origin, under a spot light at
 * y = TLF_SHADOW_SPOT_Y looking straight down (outer cone 0.6 rad, intensity 200 cd, range 20) or,
 * with `sun`, a directional light shining straight down (3 lux), seen by the file's camera from
 * (0, 7, 7) looking at the origin (yfov 0.8). `flag`: NULL, or the JSON value of the light's
 * "extras": {"thinlight_shadow": ...} ("true", "false", "\"yes\"", ...). */
#define TLF_SHADOW_BOX_Y 1.5f
#define TLF_SHADOW_BOX_HALF 0.5f
#define TLF_SHADOW_SPOT_Y 5.0f
int tlf_write_shadow_scene(const char *dir, const char *name, tlf_storage storage, int sun, const char *flag);

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
