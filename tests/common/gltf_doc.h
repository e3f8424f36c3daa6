/* The glTF fixture writer's internals, shared by its parts: growable bytes and the document
 * builder (gltf_doc.c), geometry and the test images (gltf_scenes.c); the named cases are in
 * gltf_cases.c. The public side is gltf_fixtures.h. */
#ifndef TL_GLTF_DOC_H
#define TL_GLTF_DOC_H

#include <stddef.h>
#include <stdint.h>

#include "gltf_fixtures.h"
#include "thinlight/base.h"

/* ---- growable bytes (gltf_doc.c) ------------------------------------------------------------ */

typedef struct tlf_buf {
    unsigned char *p;
    size_t n, cap;
    int oom;
} tlf_buf;

void buf_printf(tlf_buf *b, const char *fmt, ...);
const char *buf_str(tlf_buf *b);
void buf_free(tlf_buf *b);

/* A tl_logger function: error lines on stderr ("gltf fixtures: ..."). */
void tlf_log_stderr(void *user, tl_log_level level, const char *message);
int write_png(const char *dir, const char *name, uint32_t w, uint32_t h, const uint8_t *rgba);

/* ---- the document (gltf_doc.c) -------------------------------------------------------------- */

#define TLF_MAX_IMAGES 8

typedef struct tlf_doc {
    const char *dir;
    tlf_buf bin;       /* buffer 0 */
    tlf_buf views;     /* bufferViews JSON, comma separated */
    tlf_buf accessors; /* accessors JSON */
    size_t view_count, accessor_count;
    struct {
        char file[64]; /* in dir */
        char mime[32];
    } images[TLF_MAX_IMAGES];
    size_t image_count;
} tlf_doc;

enum { F32 = 5126, U8 = 5121, U16 = 5123, U32 = 5125 };

int doc_view(tlf_doc *d, const void *data, size_t n);
void doc_raw_accessor(tlf_doc *d, const char *json);
/* A tightly packed accessor over its own view; float VEC3 gets the min/max glTF requires for
 * POSITION. Returns the accessor index. */
int doc_accessor(tlf_doc *d, const void *data, size_t count, int ct, const char *type, int normalized);
/* An image from a file already in dir; its index in "images". */
int doc_image(tlf_doc *d, const char *file, const char *mime);
void doc_free(tlf_doc *d);
/* Writes dir/name.gltf or dir/name.glb with the document's buffer, views, accessors and images
 * plus `members` (more top-level JSON members, without braces; may be ""). Sets `path`. */
int doc_write(const tlf_doc *d, const char *name, tlf_storage storage, const char *members, char *path, size_t path_size);

/* ---- geometry and images (gltf_scenes.c) ---------------------------------------------------- */

typedef struct tlf_mesh {
    float pos[24][3];
    float nrm[24][3];
    float uv[24][2];
    uint16_t idx[36];
    size_t nv, ni;
} tlf_mesh;

/* An axis-aligned box of half size h around c: 4 vertices per face, counter-clockwise from
 * outside, UVs glTF-style (v grows against the face's second axis, so tangents have w = -1). */
void make_box(tlf_mesh *m, const float c[3], float h);
/* A horizontal quad facing +Y: centre (cx, y, cz), half size h; UV (0,0) at (-x, -z). */
void make_quad(tlf_mesh *m, float cx, float y, float cz, float h);
/* POSITION, NORMAL, TEXCOORD_0 (float) and u16 indices; returns the first accessor index. */
int add_mesh(tlf_doc *d, const tlf_mesh *m);
/* 4x4: two-colour checker (albedo), flat normal map, metallic-roughness (G 128, B 255), and an
 * alpha ramp. */
int write_images(const char *dir);

#endif
