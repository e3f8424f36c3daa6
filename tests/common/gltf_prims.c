/* tlf_write_prims (gltf_prims.h): a mesh of the test's primitives through the document writer. */
#include "gltf_prims.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_doc.h"

/* COLOR_0 in its component type: floats as they are, integers normalised (rounded). */
static int color_accessor(tlf_doc *d, const tlf_prim *p)
{
    size_t nc = p->color_components == 3 ? 3 : 4, n = p->nv * nc;
    int ct = p->color_type ? p->color_type : F32;
    float *f = malloc(n * sizeof *f);
    uint16_t *s = malloc(n * sizeof *s);
    uint8_t *b = malloc(n);
    int a = -1;
    if (f && s && b) {
        for (size_t i = 0; i < p->nv; i++)
            for (size_t k = 0; k < nc; k++) {
                float v = p->color[i][k];
                f[i * nc + k] = v;
                s[i * nc + k] = (uint16_t)(v * 65535.0f + 0.5f);
                b[i * nc + k] = (uint8_t)(v * 255.0f + 0.5f);
            }
        const void *data = ct == U8 ? (const void *)b : ct == U16 ? (const void *)s : (const void *)f;
        a = doc_accessor(d, data, p->nv, ct, nc == 3 ? "VEC3" : "VEC4", ct != F32);
    }
    free(f);
    free(s);
    free(b);
    return a;
}

static void prim_json(tlf_doc *d, const tlf_prim *p, tlf_buf *out)
{
    buf_printf(out, "{\"attributes\":{\"POSITION\":%d", doc_accessor(d, p->pos, p->nv, F32, "VEC3", 0));
    if (p->nrm) buf_printf(out, ",\"NORMAL\":%d", doc_accessor(d, p->nrm, p->nv, F32, "VEC3", 0));
    if (p->uv0) buf_printf(out, ",\"TEXCOORD_0\":%d", doc_accessor(d, p->uv0, p->nv, F32, "VEC2", 0));
    if (p->uv1) buf_printf(out, ",\"TEXCOORD_1\":%d", doc_accessor(d, p->uv1, p->nv, F32, "VEC2", 0));
    if (p->color) buf_printf(out, ",\"COLOR_0\":%d", color_accessor(d, p));
    buf_printf(out, "}");
    if (p->idx) buf_printf(out, ",\"indices\":%d", doc_accessor(d, p->idx, p->ni, U32, "SCALAR", 0));
    if (p->mode >= 0) buf_printf(out, ",\"mode\":%d", p->mode);
    if (p->material >= 0) buf_printf(out, ",\"material\":%d", p->material);
    buf_printf(out, "}");
}

int tlf_write_prims(const char *dir, const char *name, const tlf_prim *prims, size_t count, const char *materials,
                    const char *more, char *path, size_t path_size)
{
    tlf_doc d = {.dir = dir};
    tlf_buf json = {0};
    buf_printf(&json, "\"meshes\":[{\"primitives\":[");
    for (size_t i = 0; i < count; i++) {
        if (i) buf_printf(&json, ",");
        prim_json(&d, &prims[i], &json);
    }
    buf_printf(&json, "]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0");
    if (materials && *materials) buf_printf(&json, ",\"materials\":[%s]", materials);
    if (more && *more) buf_printf(&json, ",%s", more);
    int rc = json.oom ? -1 : doc_write(&d, name, TLF_EXTERNAL, buf_str(&json), path, path_size);
    if (rc) fprintf(stderr, "gltf fixtures: cannot write %s\n", name);
    buf_free(&json);
    doc_free(&d);
    return rc;
}
