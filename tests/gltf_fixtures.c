/* glTF fixtures: a small document builder (one buffer, buffer views, accessors, images) that
 * writes .gltf with an external .bin, .gltf with data: URIs, or .glb; the three test scenes; and
 * the named good and bad cases tests/test_gltf.c loads. Everything is generated here at run
 * time, so no binary file is committed. */
#include "gltf_fixtures.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "thinlight/io.h"

/* ---- growable bytes ------------------------------------------------------------------------ */

typedef struct tlf_buf {
    unsigned char *p;
    size_t n, cap;
    int oom;
} tlf_buf;

static void buf_reserve(tlf_buf *b, size_t extra)
{
    if (b->oom || b->n + extra + 1 <= b->cap) return;
    size_t cap = b->cap ? b->cap : 256;
    while (cap < b->n + extra + 1) cap *= 2;
    unsigned char *p = realloc(b->p, cap);
    if (!p) {
        b->oom = 1;
        return;
    }
    b->p = p;
    b->cap = cap;
}

static void buf_put(tlf_buf *b, const void *d, size_t n)
{
    buf_reserve(b, n);
    if (b->oom) return;
    if (n) memcpy(b->p + b->n, d, n);
    b->n += n;
    b->p[b->n] = 0; /* always a C string too */
}

static void buf_pad(tlf_buf *b, size_t align, unsigned char byte)
{
    while (b->n % align) buf_put(b, &byte, 1);
}

static void buf_printf(tlf_buf *b, const char *fmt, ...)
{
    va_list ap, aq;
    va_start(ap, fmt);
    va_copy(aq, ap);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n > 0) {
        buf_reserve(b, (size_t)n);
        if (!b->oom) {
            vsnprintf((char *)b->p + b->n, (size_t)n + 1, fmt, aq);
            b->n += (size_t)n;
        }
    }
    va_end(aq);
}

static const char *buf_str(tlf_buf *b)
{
    buf_put(b, "", 0);
    return b->oom || !b->p ? "" : (const char *)b->p;
}

static void buf_free(tlf_buf *b)
{
    free(b->p);
    *b = (tlf_buf){0};
}

static void buf_base64(tlf_buf *b, const unsigned char *d, size_t n)
{
    static const char tab[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (size_t i = 0; i < n; i += 3) {
        unsigned v = (unsigned)d[i] << 16 | (i + 1 < n ? (unsigned)d[i + 1] << 8 : 0u) | (i + 2 < n ? d[i + 2] : 0u);
        char out[4] = {tab[v >> 18 & 63], tab[v >> 12 & 63], i + 1 < n ? tab[v >> 6 & 63] : '=', i + 2 < n ? tab[v & 63] : '='};
        buf_put(b, out, 4);
    }
}

/* ---- files ----------------------------------------------------------------------------------- */

void tlf_join(char *out, size_t size, const char *dir, const char *name)
{
    snprintf(out, size, "%s/%s", dir, name);
}

int tlf_mkdir_p(const char *dir)
{
    char tmp[1024];
    snprintf(tmp, sizeof tmp, "%s", dir);
    for (char *p = tmp + 1; *p; p++) {
        if (*p != '/') continue;
        *p = 0;
        mkdir(tmp, 0755);
        *p = '/';
    }
    if (mkdir(tmp, 0755) != 0 && errno != EEXIST) return -1;
    return 0;
}

int tlf_write_file(const char *path, const void *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (!f) {
        fprintf(stderr, "gltf fixtures: cannot write %s\n", path);
        return -1;
    }
    int ok = fwrite(data, 1, size, f) == size;
    ok = fclose(f) == 0 && ok;
    return ok ? 0 : -1;
}

unsigned char *tlf_read_file(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    tlf_buf b = {0};
    unsigned char chunk[4096];
    size_t n;
    while ((n = fread(chunk, 1, sizeof chunk, f)) > 0) buf_put(&b, chunk, n);
    fclose(f);
    if (b.oom) {
        buf_free(&b);
        return NULL;
    }
    *size = b.n;
    if (!b.p) return calloc(1, 1);
    return b.p;
}

static void log_stderr(void *user, tl_log_level level, const char *message)
{
    (void)user;
    if (level == TL_LOG_ERROR) fprintf(stderr, "gltf fixtures: %s\n", message);
}

static int write_png(const char *dir, const char *name, uint32_t w, uint32_t h, const uint8_t *rgba)
{
    char path[1024];
    tlf_join(path, sizeof path, dir, name);
    tl_image_desc d = {.width = w, .height = h, .channels = 4, .type = TL_PIXEL_U8, .logger = {log_stderr, NULL}};
    return tl_image_write(path, &d, rgba) == TL_OK ? 0 : -1;
}

/* ---- the document ---------------------------------------------------------------------------- */

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

static size_t component_bytes(int ct) { return ct == U8 ? 1 : ct == U16 ? 2 : 4; }
static size_t type_components(const char *t)
{
    return strcmp(t, "SCALAR") == 0 ? 1 : strcmp(t, "VEC2") == 0 ? 2 : strcmp(t, "VEC3") == 0 ? 3 : 4;
}

static int doc_view(tlf_doc *d, const void *data, size_t n)
{
    buf_pad(&d->bin, 4, 0);
    size_t off = d->bin.n;
    buf_put(&d->bin, data, n);
    buf_printf(&d->views, "%s{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}", d->view_count ? "," : "", off, n);
    return (int)d->view_count++;
}

static void doc_raw_accessor(tlf_doc *d, const char *json)
{
    buf_printf(&d->accessors, "%s%s", d->accessor_count ? "," : "", json);
    d->accessor_count++;
}

/* A tightly packed accessor over its own view; float VEC3 gets the min/max glTF requires for
 * POSITION. Returns the accessor index. */
static int doc_accessor(tlf_doc *d, const void *data, size_t count, int ct, const char *type, int normalized)
{
    size_t nc = type_components(type);
    int view = doc_view(d, data, count * nc * component_bytes(ct));
    tlf_buf a = {0};
    buf_printf(&a, "{\"bufferView\":%d,\"componentType\":%d,\"count\":%zu,\"type\":\"%s\"%s", view, ct, count, type,
               normalized ? ",\"normalized\":true" : "");
    const float *f = data;
    int finite = 1;
    for (size_t i = 0; ct == F32 && i < count * nc; i++) finite = finite && f[i] - f[i] == 0.0f;
    if (ct == F32 && nc == 3 && count && finite) { /* JSON has no NaN or Inf */
        float lo[3] = {f[0], f[1], f[2]}, hi[3] = {f[0], f[1], f[2]};
        for (size_t i = 1; i < count; i++)
            for (int k = 0; k < 3; k++) {
                float v = f[3 * i + (size_t)k];
                if (v < lo[k]) lo[k] = v;
                if (v > hi[k]) hi[k] = v;
            }
        buf_printf(&a, ",\"min\":[%.9g,%.9g,%.9g],\"max\":[%.9g,%.9g,%.9g]", lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    }
    buf_printf(&a, "}");
    doc_raw_accessor(d, buf_str(&a));
    buf_free(&a);
    return (int)d->accessor_count - 1;
}

/* An image from a file already in dir; its index in "images". */
static int doc_image(tlf_doc *d, const char *file, const char *mime)
{
    if (d->image_count == TLF_MAX_IMAGES) return -1;
    snprintf(d->images[d->image_count].file, sizeof d->images[0].file, "%s", file);
    snprintf(d->images[d->image_count].mime, sizeof d->images[0].mime, "%s", mime);
    return (int)d->image_count++;
}

static void doc_free(tlf_doc *d)
{
    buf_free(&d->bin);
    buf_free(&d->views);
    buf_free(&d->accessors);
}

static void put_u32(tlf_buf *b, uint32_t v)
{
    unsigned char le[4] = {(unsigned char)v, (unsigned char)(v >> 8), (unsigned char)(v >> 16), (unsigned char)(v >> 24)};
    buf_put(b, le, 4);
}

/* Writes dir/name.gltf or dir/name.glb with the document's buffer, views, accessors and images
 * plus `members` (more top-level JSON members, without braces; may be ""). Sets `path`. */
static int doc_write(const tlf_doc *d, const char *name, tlf_storage storage, const char *members, char *path,
                     size_t path_size)
{
    tlf_buf bin = {0}, views = {0}, json = {0};
    int rc = -1;
    buf_put(&bin, d->bin.p, d->bin.n);
    buf_put(&views, d->views.p, d->views.n);
    size_t view_count = d->view_count;
    int image_view[TLF_MAX_IMAGES];
    unsigned char *image_bytes[TLF_MAX_IMAGES] = {0};
    size_t image_size[TLF_MAX_IMAGES] = {0};
    for (size_t i = 0; i < d->image_count; i++) {
        if (storage == TLF_EXTERNAL) continue;
        char file[1024];
        tlf_join(file, sizeof file, d->dir, d->images[i].file);
        image_bytes[i] = tlf_read_file(file, &image_size[i]);
        if (!image_bytes[i]) {
            fprintf(stderr, "gltf fixtures: cannot read %s\n", file);
            goto done;
        }
        if (storage == TLF_GLB) {
            buf_pad(&bin, 4, 0);
            buf_printf(&views, "%s{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}", view_count ? "," : "", bin.n,
                       image_size[i]);
            buf_put(&bin, image_bytes[i], image_size[i]);
            image_view[i] = (int)view_count++;
        }
    }
    buf_pad(&bin, 4, 0);

    buf_printf(&json, "{\"asset\":{\"version\":\"2.0\",\"generator\":\"thinlight tests/gltf_fixtures.c\"}");
    if (bin.n) {
        buf_printf(&json, ",\"buffers\":[{\"byteLength\":%zu", bin.n);
        if (storage == TLF_EXTERNAL) {
            char bin_name[256], bin_path[1024];
            snprintf(bin_name, sizeof bin_name, "%s.bin", name);
            tlf_join(bin_path, sizeof bin_path, d->dir, bin_name);
            if (tlf_write_file(bin_path, bin.p, bin.n)) goto done;
            buf_printf(&json, ",\"uri\":\"%s\"", bin_name);
        } else if (storage == TLF_DATA_URI) {
            buf_printf(&json, ",\"uri\":\"data:application/octet-stream;base64,");
            buf_base64(&json, bin.p, bin.n);
            buf_printf(&json, "\"");
        }
        buf_printf(&json, "}]");
    }
    if (view_count) buf_printf(&json, ",\"bufferViews\":[%s]", buf_str(&views));
    if (d->accessor_count) buf_printf(&json, ",\"accessors\":[%s]", (const char *)d->accessors.p);
    if (d->image_count) {
        buf_printf(&json, ",\"images\":[");
        for (size_t i = 0; i < d->image_count; i++) {
            const char *sep = i ? "," : "";
            if (storage == TLF_EXTERNAL) {
                buf_printf(&json, "%s{\"uri\":\"%s\"}", sep, d->images[i].file);
            } else if (storage == TLF_DATA_URI) {
                buf_printf(&json, "%s{\"uri\":\"data:%s;base64,", sep, d->images[i].mime);
                buf_base64(&json, image_bytes[i], image_size[i]);
                buf_printf(&json, "\"}");
            } else {
                buf_printf(&json, "%s{\"bufferView\":%d,\"mimeType\":\"%s\"}", sep, image_view[i], d->images[i].mime);
            }
        }
        buf_printf(&json, "]");
    }
    if (members && *members) buf_printf(&json, ",%s", members);
    buf_printf(&json, "}");
    if (bin.oom || views.oom || json.oom || d->bin.oom || d->views.oom || d->accessors.oom) goto done;

    char file_name[256];
    snprintf(file_name, sizeof file_name, "%s.%s", name, storage == TLF_GLB ? "glb" : "gltf");
    tlf_join(path, path_size, d->dir, file_name);
    if (storage != TLF_GLB) {
        rc = tlf_write_file(path, json.p, json.n);
    } else {
        /* GLB: 12-byte header, JSON chunk padded with spaces, BIN chunk padded with zeros. */
        tlf_buf glb = {0};
        buf_pad(&json, 4, ' ');
        size_t total = 12 + 8 + json.n + (bin.n ? 8 + bin.n : 0);
        buf_put(&glb, "glTF", 4);
        put_u32(&glb, 2);
        put_u32(&glb, (uint32_t)total);
        put_u32(&glb, (uint32_t)json.n);
        put_u32(&glb, 0x4E4F534Au);
        buf_put(&glb, json.p, json.n);
        if (bin.n) {
            put_u32(&glb, (uint32_t)bin.n);
            put_u32(&glb, 0x004E4942u);
            buf_put(&glb, bin.p, bin.n);
        }
        rc = glb.oom ? -1 : tlf_write_file(path, glb.p, glb.n);
        buf_free(&glb);
    }
done:
    for (size_t i = 0; i < d->image_count; i++) free(image_bytes[i]);
    buf_free(&bin);
    buf_free(&views);
    buf_free(&json);
    return rc;
}

/* ---- geometry ------------------------------------------------------------------------------ */

typedef struct tlf_mesh {
    float pos[24][3];
    float nrm[24][3];
    float uv[24][2];
    uint16_t idx[36];
    size_t nv, ni;
} tlf_mesh;

/* An axis-aligned box of half size h around c: 4 vertices per face, counter-clockwise from
 * outside, UVs glTF-style (v grows against the face's second axis, so tangents have w = -1). */
static void make_box(tlf_mesh *m, const float c[3], float h)
{
    m->nv = m->ni = 0;
    for (int a = 0; a < 3; a++)
        for (int s = 1; s >= -1; s -= 2) {
            float n[3] = {0, 0, 0}, u[3] = {0, 0, 0}, v[3] = {0, 0, 0};
            n[a] = (float)s;
            /* u x v = n: (e[a+1], e[a+2]) for +, swapped for - */
            u[s > 0 ? (a + 1) % 3 : (a + 2) % 3] = 1.0f;
            v[s > 0 ? (a + 2) % 3 : (a + 1) % 3] = 1.0f;
            static const float cu[4] = {-1, 1, 1, -1}, cv[4] = {-1, -1, 1, 1};
            uint16_t base = (uint16_t)m->nv;
            for (int k = 0; k < 4; k++) {
                for (int j = 0; j < 3; j++) {
                    m->pos[m->nv][j] = c[j] + h * (n[j] + cu[k] * u[j] + cv[k] * v[j]);
                    m->nrm[m->nv][j] = n[j];
                }
                m->uv[m->nv][0] = 0.5f * (cu[k] + 1.0f);
                m->uv[m->nv][1] = 0.5f * (1.0f - cv[k]);
                m->nv++;
            }
            static const uint16_t tri[6] = {0, 1, 2, 0, 2, 3};
            for (int k = 0; k < 6; k++) m->idx[m->ni++] = (uint16_t)(base + tri[k]);
        }
}

/* A horizontal quad facing +Y: centre (cx, y, cz), half size h; UV (0,0) at (-x, -z). */
static void make_quad(tlf_mesh *m, float cx, float y, float cz, float h)
{
    static const float corner[4][2] = {{-1, 1}, {1, 1}, {1, -1}, {-1, -1}}; /* (x, z) */
    m->nv = 4;
    for (int k = 0; k < 4; k++) {
        m->pos[k][0] = cx + h * corner[k][0];
        m->pos[k][1] = y;
        m->pos[k][2] = cz + h * corner[k][1];
        m->nrm[k][0] = m->nrm[k][2] = 0.0f;
        m->nrm[k][1] = 1.0f;
        m->uv[k][0] = 0.5f * (corner[k][0] + 1.0f);
        m->uv[k][1] = 0.5f * (corner[k][1] + 1.0f);
    }
    static const uint16_t tri[6] = {0, 1, 2, 0, 2, 3};
    memcpy(m->idx, tri, sizeof tri);
    m->ni = 6;
}

/* A vertical quad facing +Z: centre (cx, cy, z), half size h; UV (0,0) at the top left. */
static void make_wall_quad(tlf_mesh *m, float cx, float cy, float z, float h)
{
    static const float corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}; /* (x, y) */
    m->nv = 4;
    for (int k = 0; k < 4; k++) {
        m->pos[k][0] = cx + h * corner[k][0];
        m->pos[k][1] = cy + h * corner[k][1];
        m->pos[k][2] = z;
        m->nrm[k][0] = m->nrm[k][1] = 0.0f;
        m->nrm[k][2] = 1.0f;
        m->uv[k][0] = 0.5f * (corner[k][0] + 1.0f);
        m->uv[k][1] = 0.5f * (1.0f - corner[k][1]);
    }
    static const uint16_t tri[6] = {0, 1, 2, 0, 2, 3};
    memcpy(m->idx, tri, sizeof tri);
    m->ni = 6;
}

/* POSITION, NORMAL, TEXCOORD_0 (float) and u16 indices; returns the first accessor index. */
static int add_mesh(tlf_doc *d, const tlf_mesh *m)
{
    int first = doc_accessor(d, m->pos, m->nv, F32, "VEC3", 0);
    doc_accessor(d, m->nrm, m->nv, F32, "VEC3", 0);
    doc_accessor(d, m->uv, m->nv, F32, "VEC2", 0);
    doc_accessor(d, m->idx, m->ni, U16, "SCALAR", 0);
    return first;
}

/* ---- images -------------------------------------------------------------------------------- */

/* 4x4: two-colour checker (albedo), flat normal map, metallic-roughness (G 128, B 255), and an
 * alpha ramp. */
static int write_images(const char *dir)
{
    uint8_t albedo[64], normal[64], mr[64], alpha[64];
    for (int i = 0; i < 16; i++) {
        int on = ((i % 4) + (i / 4)) % 2;
        uint8_t a[4] = {on ? 230 : 40, on ? 200 : 60, on ? 160 : 90, 255};
        uint8_t n[4] = {128, 128, 255, 255};
        uint8_t r[4] = {0, 128, 255, 255};
        uint8_t t[4] = {255, 255, 255, (uint8_t)(i * 17)};
        memcpy(albedo + 4 * i, a, 4);
        memcpy(normal + 4 * i, n, 4);
        memcpy(mr + 4 * i, r, 4);
        memcpy(alpha + 4 * i, t, 4);
    }
    return write_png(dir, "albedo.png", 4, 4, albedo) || write_png(dir, "normal.png", 4, 4, normal) ||
           write_png(dir, "mr.png", 4, 4, mr) || write_png(dir, "albedo_alpha.png", 4, 4, alpha);
}

/* ---- the three scenes ----------------------------------------------------------------------- */

int tlf_write_textured_boxes(const char *dir, const char *name, tlf_storage storage)
{
    if (write_images(dir)) return -1;
    tlf_doc d = {.dir = dir};
    tlf_mesh m;
    const float origin[3] = {0, 0, 0};
    make_box(&m, origin, 0.5f);
    add_mesh(&d, &m); /* accessors 0..3 */
    make_quad(&m, 0.0f, 0.55f, 0.0f, 0.5f); /* a lid just above the box: coplanar faces would z-fight */
    add_mesh(&d, &m); /* accessors 4..7 */
    doc_image(&d, "albedo.png", "image/png");
    doc_image(&d, "normal.png", "image/png");
    doc_image(&d, "mr.png", "image/png");
    const char *members =
        "\"samplers\":[{\"magFilter\":9729,\"minFilter\":9987}],"
        "\"textures\":[{\"source\":0,\"sampler\":0},{\"source\":1,\"sampler\":0},{\"source\":2,\"sampler\":0}],"
        "\"materials\":["
        "{\"name\":\"checker\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0.9,0.8,1],\"baseColorTexture\":{\"index\":0},"
        "\"metallicFactor\":0.5,\"roughnessFactor\":0.75,\"metallicRoughnessTexture\":{\"index\":2}},"
        "\"normalTexture\":{\"index\":1,\"scale\":0.8}},"
        "{\"name\":\"painted\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.2,0.4,0.6,1],\"baseColorTexture\":{\"index\":0},"
        "\"metallicFactor\":0,\"roughnessFactor\":0.5}}],"
        "\"meshes\":["
        "{\"name\":\"box\",\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2},\"indices\":3,\"material\":0}]},"
        "{\"name\":\"two_part\",\"primitives\":["
        "{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2},\"indices\":3,\"material\":1},"
        "{\"attributes\":{\"POSITION\":4,\"NORMAL\":5,\"TEXCOORD_0\":6},\"indices\":7,\"material\":0}]}],"
        "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.8,\"znear\":0.1}}],"
        "\"nodes\":["
        "{\"name\":\"root\",\"translation\":[10,0,0],\"scale\":[2,2,2],\"children\":[1,2]},"
        "{\"name\":\"spinner\",\"translation\":[0,1,0],\"rotation\":[0,0.70710678118654752,0,0.70710678118654752],"
        "\"mesh\":0,\"children\":[3]},"
        "{\"name\":\"matrixed\",\"matrix\":[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,3,1],\"mesh\":1},"
        "{\"name\":\"leaf\",\"translation\":[1,0,0],\"mesh\":0},"
        "{\"name\":\"camera\",\"translation\":[10,2,14],\"camera\":0}],"
        "\"scenes\":[{\"nodes\":[0,4]}],\"scene\":0";
    char path[1024];
    int rc = doc_write(&d, name, storage, members, path, sizeof path);
    doc_free(&d);
    return rc;
}

int tlf_write_materials(const char *dir, const char *name, tlf_storage storage)
{
    if (write_images(dir)) return -1;
    tlf_doc d = {.dir = dir};
    tlf_buf prims = {0};
    for (int i = 0; i < 8; i++) {
        tlf_mesh m;
        make_wall_quad(&m, 1.5f * (float)i, 0.5f, 0.0f, 0.5f);
        int pos = doc_accessor(&d, m.pos, 4, F32, "VEC3", 0);
        int nrm = i < 4 ? doc_accessor(&d, m.nrm, 4, F32, "VEC3", 0) : -1;
        /* UVs as normalised integers: 8-bit on even quads, 16-bit on odd ones. */
        int uv;
        if (i % 2 == 0) {
            uint8_t q[8];
            for (int k = 0; k < 8; k++) q[k] = (uint8_t)(m.uv[k / 2][k % 2] * 255.0f);
            uv = doc_accessor(&d, q, 4, U8, "VEC2", 1);
        } else {
            uint16_t q[8];
            for (int k = 0; k < 8; k++) q[k] = (uint16_t)(m.uv[k / 2][k % 2] * 65535.0f);
            uv = doc_accessor(&d, q, 4, U16, "VEC2", 1);
        }
        int idx = doc_accessor(&d, m.idx, 6, U16, "SCALAR", 0);
        buf_printf(&prims, "%s{\"attributes\":{\"POSITION\":%d,", i ? "," : "", pos);
        if (nrm >= 0) buf_printf(&prims, "\"NORMAL\":%d,", nrm);
        buf_printf(&prims, "\"TEXCOORD_0\":%d},\"indices\":%d", uv, idx);
        if (i < 7) buf_printf(&prims, ",\"material\":%d", i);
        buf_printf(&prims, "}");
    }
    doc_image(&d, "albedo_alpha.png", "image/png");
    doc_image(&d, "mr.png", "image/png");
    tlf_buf members = {0};
    buf_printf(&members,
               "\"extensionsUsed\":[\"KHR_materials_emissive_strength\"],"
               "\"textures\":[{\"source\":0},{\"source\":1}],"
               "\"materials\":["
               "{\"name\":\"metal\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.9,0.6,0.3,1],\"metallicFactor\":1,\"roughnessFactor\":0.2}},"
               "{\"name\":\"dielectric\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.5,0.5,0.5,1],\"metallicFactor\":0,\"roughnessFactor\":1}},"
               "{\"name\":\"half_metal\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.8,0.2,0.4,1],\"metallicFactor\":0.5,\"roughnessFactor\":0.4}},"
               "{\"name\":\"mask\",\"alphaMode\":\"MASK\",\"alphaCutoff\":0.3,\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,1,1,0.9],"
               "\"baseColorTexture\":{\"index\":0},\"metallicFactor\":0}},"
               "{\"name\":\"blend\",\"alphaMode\":\"BLEND\",\"doubleSided\":true,\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.1,0.8,0.1,0.5],"
               "\"metallicFactor\":0,\"roughnessFactor\":0.3}},"
               "{\"name\":\"emissive_double\",\"doubleSided\":true,\"emissiveFactor\":[1,0.5,0],"
               "\"extensions\":{\"KHR_materials_emissive_strength\":{\"emissiveStrength\":2}},\"pbrMetallicRoughness\":{\"metallicFactor\":0}},"
               "{\"name\":\"mr_textured\",\"pbrMetallicRoughness\":{\"metallicFactor\":0.7,\"roughnessFactor\":0.6,"
               "\"metallicRoughnessTexture\":{\"index\":1}},\"occlusionTexture\":{\"index\":1,\"strength\":0.5}}],"
               "\"meshes\":[{\"name\":\"swatches\",\"primitives\":[%s]}],"
               "\"nodes\":[{\"name\":\"swatches\",\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
               buf_str(&prims));
    char path[1024];
    int rc = prims.oom || members.oom ? -1 : doc_write(&d, name, storage, buf_str(&members), path, sizeof path);
    buf_free(&prims);
    buf_free(&members);
    doc_free(&d);
    return rc;
}

int tlf_write_lights(const char *dir, const char *name, tlf_storage storage)
{
    tlf_doc d = {.dir = dir};
    tlf_mesh m;
    make_quad(&m, 0.0f, 0.0f, 0.0f, 10.0f);
    int floor_pos = doc_accessor(&d, m.pos, 4, F32, "VEC3", 0);
    int floor_nrm = doc_accessor(&d, m.nrm, 4, F32, "VEC3", 0);
    uint32_t idx32[6];
    for (int k = 0; k < 6; k++) idx32[k] = m.idx[k];
    int floor_idx = doc_accessor(&d, idx32, 6, U32, "SCALAR", 0);
    const float origin[3] = {0, 0, 0};
    make_box(&m, origin, 0.5f);
    int box = add_mesh(&d, &m);
    tlf_buf members = {0};
    buf_printf(&members,
               "\"extensionsUsed\":[\"KHR_lights_punctual\"],"
               "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":["
               "{\"name\":\"warm_point\",\"type\":\"point\",\"color\":[1,0.5,0.25],\"intensity\":10,\"range\":5},"
               "{\"name\":\"white_point\",\"type\":\"point\",\"intensity\":3.14159265358979},"
               "{\"name\":\"spot\",\"type\":\"spot\",\"color\":[0.5,0.5,1],\"intensity\":20,\"range\":10,"
               "\"spot\":{\"innerConeAngle\":0.2,\"outerConeAngle\":0.5}},"
               "{\"name\":\"sun\",\"type\":\"directional\",\"color\":[1,1,0.9],\"intensity\":3}]}},"
               "\"materials\":[{\"name\":\"floor\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.6,0.6,0.6,1],\"metallicFactor\":0,"
               "\"roughnessFactor\":0.8}}],"
               "\"meshes\":[{\"name\":\"floor\",\"primitives\":[{\"attributes\":{\"POSITION\":%d,\"NORMAL\":%d},\"indices\":%d,\"material\":0}]},"
               "{\"name\":\"box\",\"primitives\":[{\"attributes\":{\"POSITION\":%d,\"NORMAL\":%d,\"TEXCOORD_0\":%d},\"indices\":%d,\"material\":0}]}],"
               "\"nodes\":["
               "{\"name\":\"floor\",\"mesh\":0},"
               "{\"name\":\"box\",\"mesh\":1,\"translation\":[0,0.5,0]},"
               "{\"name\":\"warm\",\"translation\":[1,2,3],\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}},"
               "{\"name\":\"white\",\"translation\":[-4,5,0],\"extensions\":{\"KHR_lights_punctual\":{\"light\":1}}},"
               "{\"name\":\"rig\",\"translation\":[2,0,0],\"children\":[5]},"
               "{\"name\":\"spot\",\"translation\":[0,6,0],\"rotation\":[-0.70710678118654752,0,0,0.70710678118654752],"
               "\"extensions\":{\"KHR_lights_punctual\":{\"light\":2}}},"
               "{\"name\":\"sun\",\"rotation\":[0,0.70710678118654752,0,0.70710678118654752],"
               "\"extensions\":{\"KHR_lights_punctual\":{\"light\":3}}}],"
               "\"scenes\":[{\"nodes\":[0,1,2,3,4,6]}]",
               floor_pos, floor_nrm, floor_idx, box, box + 1, box + 2, box + 3);
    char path[1024];
    int rc = members.oom ? -1 : doc_write(&d, name, storage, buf_str(&members), path, sizeof path);
    buf_free(&members);
    doc_free(&d);
    return rc;
}

int tl_test_write_gltf_scenes(const char *dir)
{
    if (tlf_mkdir_p(dir)) {
        fprintf(stderr, "gltf fixtures: cannot create %s\n", dir);
        return -1;
    }
    if (tlf_write_textured_boxes(dir, "textured_boxes", TLF_EXTERNAL) || tlf_write_materials(dir, "materials", TLF_GLB) ||
        tlf_write_lights(dir, "lights", TLF_DATA_URI))
        return -1;
    return 0;
}

/* ---- named cases --------------------------------------------------------------------------- */

/* One quad (4 float positions, u16 indices) as accessors 0 and 1, with `members` appended; the
 * default mesh/node/scene members unless `custom` is set. */
static int quad_case(const char *dir, const char *name, tlf_storage storage, const char *members, int custom, char *path,
                     size_t path_size)
{
    tlf_doc d = {.dir = dir};
    tlf_mesh m;
    make_quad(&m, 0.0f, 0.0f, 0.0f, 1.0f);
    doc_accessor(&d, m.pos, 4, F32, "VEC3", 0);
    doc_accessor(&d, m.idx, 6, U16, "SCALAR", 0);
    tlf_buf all = {0};
    if (!custom)
        buf_printf(&all, "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]%s",
                   members && *members ? "," : "");
    buf_printf(&all, "%s", members ? members : "");
    int rc = all.oom ? -1 : doc_write(&d, name, storage, buf_str(&all), path, path_size);
    buf_free(&all);
    doc_free(&d);
    return rc;
}

static int write_text(const char *dir, const char *file, const char *text, char *path, size_t path_size)
{
    tlf_join(path, path_size, dir, file);
    return tlf_write_file(path, text, strlen(text));
}

/* A quad whose positions, normals or indices are given. */
static int geometry_case(const char *dir, const char *name, const float (*pos)[3], const float (*nrm)[3], size_t nv,
                         const uint32_t *idx, size_t ni, char *path, size_t path_size)
{
    tlf_doc d = {.dir = dir};
    int p = doc_accessor(&d, pos, nv, F32, "VEC3", 0);
    int n = nrm ? doc_accessor(&d, nrm, nv, F32, "VEC3", 0) : -1;
    int i = idx ? doc_accessor(&d, idx, ni, U32, "SCALAR", 0) : -1;
    tlf_buf members = {0};
    buf_printf(&members, "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":%d", p);
    if (n >= 0) buf_printf(&members, ",\"NORMAL\":%d", n);
    buf_printf(&members, "}");
    if (i >= 0) buf_printf(&members, ",\"indices\":%d", i);
    buf_printf(&members, "}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]");
    int rc = members.oom ? -1 : doc_write(&d, name, TLF_EXTERNAL, buf_str(&members), path, path_size);
    buf_free(&members);
    doc_free(&d);
    return rc;
}

static uint32_t crc32_png(const unsigned char *p, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return c ^ 0xFFFFFFFFu;
}

/* A valid 4x4 PNG whose header then claims w x h (CRC fixed, so only the size is absurd). */
static int huge_png(const char *dir, const char *file, uint32_t w, uint32_t h)
{
    uint8_t px[64] = {0};
    if (write_png(dir, file, 4, 4, px)) return -1;
    char path[1024];
    tlf_join(path, sizeof path, dir, file);
    size_t n = 0;
    unsigned char *b = tlf_read_file(path, &n);
    if (!b || n < 33 || memcmp(b + 12, "IHDR", 4) != 0) {
        free(b);
        return -1;
    }
    for (int k = 0; k < 4; k++) {
        b[16 + k] = (unsigned char)(w >> (24 - 8 * k));
        b[20 + k] = (unsigned char)(h >> (24 - 8 * k));
    }
    uint32_t crc = crc32_png(b + 12, 17);
    for (int k = 0; k < 4; k++) b[29 + k] = (unsigned char)(crc >> (24 - 8 * k));
    int rc = tlf_write_file(path, b, n);
    free(b);
    return rc;
}

/* A quad with TEXCOORD_0 and a material whose base colour texture is image 0 given by `image`
 * JSON (or by the document's first image when `image` is NULL). */
static int textured_quad_case(const char *dir, const char *name, tlf_storage storage, const char *image_file,
                              const char *image_json, char *path, size_t path_size)
{
    tlf_doc d = {.dir = dir};
    tlf_mesh m;
    make_quad(&m, 0.0f, 0.0f, 0.0f, 1.0f);
    add_mesh(&d, &m);
    if (image_file) doc_image(&d, image_file, "image/png");
    tlf_buf members = {0};
    buf_printf(&members,
               "%s%s\"textures\":[{\"source\":0}],"
               "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.25,0.5,0.75,1],\"baseColorTexture\":{\"index\":0},"
               "\"metallicFactor\":0}}],"
               "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2},\"indices\":3,\"material\":0}]}],"
               "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
               image_json ? image_json : "", image_json ? "," : "");
    int rc = members.oom ? -1 : doc_write(&d, name, storage, buf_str(&members), path, path_size);
    buf_free(&members);
    doc_free(&d);
    return rc;
}

static int case_indices(const char *dir, const char *name, char *path, size_t path_size)
{
    /* Four quads at x = 0, 3, 6, 9: u8, u16, u32 indices and non-indexed; UVs as normalised u8,
     * normalised u16, float, float. */
    tlf_doc d = {.dir = dir};
    tlf_buf prims = {0};
    for (int q = 0; q < 4; q++) {
        tlf_mesh m;
        make_quad(&m, 3.0f * (float)q, 0.0f, 0.0f, 1.0f);
        int pos, uv, idx = -1;
        if (q < 3) {
            pos = doc_accessor(&d, m.pos, 4, F32, "VEC3", 0);
        } else {
            float flat[6][3];
            for (int k = 0; k < 6; k++) memcpy(flat[k], m.pos[m.idx[k]], sizeof flat[k]);
            pos = doc_accessor(&d, flat, 6, F32, "VEC3", 0);
        }
        if (q == 0) {
            uint8_t t[8] = {0, 255, 255, 255, 255, 0, 0, 0};
            uv = doc_accessor(&d, t, 4, U8, "VEC2", 1);
            uint8_t i8[6];
            for (int k = 0; k < 6; k++) i8[k] = (uint8_t)m.idx[k];
            idx = doc_accessor(&d, i8, 6, U8, "SCALAR", 0);
        } else if (q == 1) {
            uint16_t t[8] = {0, 65535, 65535, 65535, 65535, 0, 0, 0};
            uv = doc_accessor(&d, t, 4, U16, "VEC2", 1);
            idx = doc_accessor(&d, m.idx, 6, U16, "SCALAR", 0);
        } else if (q == 2) {
            float t[8] = {0, 1, 1, 1, 1, 0, 0, 0};
            uv = doc_accessor(&d, t, 4, F32, "VEC2", 0);
            uint32_t i32[6];
            for (int k = 0; k < 6; k++) i32[k] = m.idx[k];
            idx = doc_accessor(&d, i32, 6, U32, "SCALAR", 0);
        } else {
            float t[12] = {0, 1, 1, 1, 1, 0, 0, 1, 1, 0, 0, 0};
            uv = doc_accessor(&d, t, 6, F32, "VEC2", 0);
        }
        buf_printf(&prims, "%s{\"attributes\":{\"POSITION\":%d,\"TEXCOORD_0\":%d}", q ? "," : "", pos, uv);
        if (idx >= 0) buf_printf(&prims, ",\"indices\":%d", idx);
        buf_printf(&prims, "}");
    }
    tlf_buf members = {0};
    buf_printf(&members, "\"meshes\":[{\"primitives\":[%s]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
               buf_str(&prims));
    int rc = members.oom || prims.oom ? -1 : doc_write(&d, name, TLF_EXTERNAL, buf_str(&members), path, path_size);
    buf_free(&prims);
    buf_free(&members);
    doc_free(&d);
    return rc;
}

/* A box of 8 shared corners (indexed, no NORMAL), with a normal-mapped material: the loader
 * generates normals (flat: unshared; smooth: shared) and tangents. */
static int case_generated_frames(const char *dir, const char *name, char *path, size_t path_size)
{
    if (write_images(dir)) return -1;
    tlf_doc d = {.dir = dir};
    tlf_mesh m;
    const float origin[3] = {0, 0, 0};
    make_box(&m, origin, 0.5f);
    float pos[8][3], uv[8][2];
    uint16_t idx[36];
    size_t n = 0;
    for (size_t i = 0; i < m.ni; i++) {
        const float *p = m.pos[m.idx[i]];
        size_t k = 0;
        while (k < n && memcmp(pos[k], p, sizeof pos[k]) != 0) k++;
        if (k == n) {
            memcpy(pos[n], p, sizeof pos[n]);
            /* A planar projection: some faces get no UV area (their tangents need a fallback). */
            uv[n][0] = p[0] + 0.5f;
            uv[n][1] = 0.5f - p[2] + 0.25f * p[1];
            n++;
        }
        idx[i] = (uint16_t)k;
    }
    doc_accessor(&d, pos, n, F32, "VEC3", 0);
    doc_accessor(&d, uv, n, F32, "VEC2", 0);
    doc_accessor(&d, idx, 36, U16, "SCALAR", 0);
    doc_image(&d, "normal.png", "image/png");
    const char *members =
        "\"textures\":[{\"source\":0}],\"materials\":[{\"normalTexture\":{\"index\":0}}],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":1},\"indices\":2,\"material\":0}]}],"
        "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]";
    int rc = doc_write(&d, name, TLF_EXTERNAL, members, path, path_size);
    doc_free(&d);
    return rc;
}

int tlf_write_case(const char *dir, const char *name, char *path, size_t path_size)
{
    if (tlf_mkdir_p(dir)) return -1;
    const float nan = strtof("nan", NULL), inf = strtof("inf", NULL);
    if (strcmp(name, "textured_boxes") == 0 || strcmp(name, "textured_boxes_glb") == 0 ||
        strcmp(name, "textured_boxes_data_uri") == 0) {
        tlf_storage s = strcmp(name, "textured_boxes") == 0 ? TLF_EXTERNAL
                        : strcmp(name, "textured_boxes_glb") == 0 ? TLF_GLB : TLF_DATA_URI;
        if (tlf_write_textured_boxes(dir, name, s)) return -1;
        char file[256];
        snprintf(file, sizeof file, "%s.%s", name, s == TLF_GLB ? "glb" : "gltf");
        tlf_join(path, path_size, dir, file);
        return 0;
    }
    if (strcmp(name, "materials") == 0) {
        if (tlf_write_materials(dir, name, TLF_GLB)) return -1;
        tlf_join(path, path_size, dir, "materials.glb");
        return 0;
    }
    if (strcmp(name, "lights") == 0) {
        if (tlf_write_lights(dir, name, TLF_DATA_URI)) return -1;
        tlf_join(path, path_size, dir, "lights.gltf");
        return 0;
    }
    if (strcmp(name, "indices") == 0) return case_indices(dir, name, path, path_size);
    if (strcmp(name, "generated_frames") == 0) return case_generated_frames(dir, name, path, path_size);
    if (strcmp(name, "quad") == 0) return quad_case(dir, name, TLF_EXTERNAL, "", 0, path, path_size);
    if (strcmp(name, "malformed_json") == 0)
        return write_text(dir, "malformed_json.gltf", "{\"asset\":{\"version\":\"2.0\"},\"scenes\":[{\"nodes\":[0]}", path,
                          path_size);
    if (strcmp(name, "wrong_types") == 0) {
        /* accessors[0].count is a string */
        tlf_doc d = {.dir = dir};
        float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        doc_view(&d, p, sizeof p);
        doc_raw_accessor(&d, "{\"bufferView\":0,\"componentType\":5126,\"count\":\"three\",\"type\":\"VEC3\"}");
        int rc = doc_write(&d, name, TLF_EXTERNAL,
                           "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{\"mesh\":0}],"
                           "\"scenes\":[{\"nodes\":[0]}]",
                           path, path_size);
        doc_free(&d);
        return rc;
    }
    if (strcmp(name, "missing_bin") == 0) {
        if (quad_case(dir, name, TLF_EXTERNAL, "", 0, path, path_size)) return -1;
        char bin[1024];
        tlf_join(bin, sizeof bin, dir, "missing_bin.bin");
        return remove(bin) == 0 ? 0 : -1;
    }
    if (strcmp(name, "missing_image") == 0) {
        /* the image file is never written */
        return textured_quad_case(dir, name, TLF_EXTERNAL, NULL, "\"images\":[{\"uri\":\"no_such_image.png\"}]", path,
                                  path_size);
    }
    if (strcmp(name, "texture_unsupported") == 0) {
        char file[1024];
        tlf_join(file, sizeof file, dir, "not_an_image.png");
        const char junk[] = "this is not an image, whatever its name says";
        if (tlf_write_file(file, junk, sizeof junk)) return -1;
        return textured_quad_case(dir, name, TLF_GLB, "not_an_image.png", NULL, path, path_size);
    }
    if (strcmp(name, "texture_truncated_png") == 0) {
        /* a valid PNG cut in half */
        if (write_images(dir)) return -1;
        char file[1024];
        tlf_join(file, sizeof file, dir, "albedo.png");
        size_t n = 0;
        unsigned char *b = tlf_read_file(file, &n);
        tlf_join(file, sizeof file, dir, "half.png");
        int rc = b ? tlf_write_file(file, b, n / 2) : -1;
        free(b);
        return rc ? rc : textured_quad_case(dir, name, TLF_EXTERNAL, "half.png", NULL, path, path_size);
    }
    if (strcmp(name, "texture_jpeg") == 0) {
        /* an 8x8 mid-grey RGB JPEG, embedded in a GLB (decoded from memory) */
        uint8_t rgb[8 * 8 * 3];
        memset(rgb, 128, sizeof rgb);
        char file[1024];
        tlf_join(file, sizeof file, dir, "grey.jpg");
        tl_image_desc jd = {.width = 8, .height = 8, .channels = 3, .type = TL_PIXEL_U8, .logger = {log_stderr, NULL}};
        if (tl_image_write(file, &jd, rgb) != TL_OK) return -1;
        tlf_doc d = {.dir = dir};
        tlf_mesh m;
        make_quad(&m, 0.0f, 0.0f, 0.0f, 1.0f);
        add_mesh(&d, &m);
        doc_image(&d, "grey.jpg", "image/jpeg");
        int rc = doc_write(&d, name, TLF_GLB,
                           "\"textures\":[{\"source\":0}],\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}],"
                           "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2},\"indices\":3,\"material\":0}]}],"
                           "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
                           path, path_size);
        doc_free(&d);
        return rc;
    }
    if (strcmp(name, "texture_huge") == 0) {
        if (huge_png(dir, "huge.png", 60000, 60000)) return -1;
        return textured_quad_case(dir, name, TLF_EXTERNAL, "huge.png", NULL, path, path_size);
    }
    if (strcmp(name, "texture_4x4") == 0) {
        if (write_images(dir)) return -1;
        return textured_quad_case(dir, name, TLF_EXTERNAL, "albedo.png", NULL, path, path_size);
    }
    if (strcmp(name, "bufferview_out_of_range") == 0) {
        tlf_doc d = {.dir = dir};
        float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        doc_view(&d, p, sizeof p);
        doc_raw_accessor(&d, "{\"bufferView\":99,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}");
        int rc = doc_write(&d, name, TLF_EXTERNAL,
                           "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{\"mesh\":0}],"
                           "\"scenes\":[{\"nodes\":[0]}]",
                           path, path_size);
        doc_free(&d);
        return rc;
    }
    if (strcmp(name, "accessor_past_view") == 0) {
        tlf_doc d = {.dir = dir};
        float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        doc_view(&d, p, sizeof p);
        doc_raw_accessor(&d, "{\"bufferView\":0,\"componentType\":5126,\"count\":300,\"type\":\"VEC3\"}");
        int rc = doc_write(&d, name, TLF_EXTERNAL,
                           "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{\"mesh\":0}],"
                           "\"scenes\":[{\"nodes\":[0]}]",
                           path, path_size);
        doc_free(&d);
        return rc;
    }
    if (strcmp(name, "view_past_buffer") == 0) {
        tlf_doc d = {.dir = dir};
        float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        doc_view(&d, p, sizeof p);
        /* a second view that starts inside the buffer and runs past its end */
        buf_printf(&d.views, ",{\"buffer\":0,\"byteOffset\":24,\"byteLength\":4096}");
        d.view_count++;
        doc_raw_accessor(&d, "{\"bufferView\":1,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}");
        int rc = doc_write(&d, name, TLF_EXTERNAL,
                           "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{\"mesh\":0}],"
                           "\"scenes\":[{\"nodes\":[0]}]",
                           path, path_size);
        doc_free(&d);
        return rc;
    }
    if (strcmp(name, "accessor_ref_out_of_range") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":42},\"indices\":1}]}],"
                         "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
                         1, path, path_size);
    if (strcmp(name, "mesh_ref_out_of_range") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"mesh\":7}],\"scenes\":[{\"nodes\":[0]}]",
                         1, path, path_size);
    if (strcmp(name, "index_out_of_range") == 0) {
        const float pos[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        const uint32_t idx[6] = {0, 1, 2, 0, 2, 99};
        return geometry_case(dir, name, pos, NULL, 3, idx, 6, path, path_size);
    }
    if (strcmp(name, "node_cycle") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"children\":[1]},{\"children\":[2],\"mesh\":0},{\"children\":[0]}],"
                         "\"scenes\":[{\"nodes\":[0]}]",
                         1, path, path_size);
    if (strcmp(name, "node_self_child") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"children\":[0],\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
                         1, path, path_size);
    if (strcmp(name, "node_two_parents") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"children\":[2]},{\"children\":[2]},{\"mesh\":0}],\"scenes\":[{\"nodes\":[0,1]}]",
                         1, path, path_size);
    if (strcmp(name, "node_child_out_of_range") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"children\":[5],\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
                         1, path, path_size);
    if (strcmp(name, "nan_position") == 0 || strcmp(name, "inf_position") == 0) {
        float bad = name[0] == 'n' ? nan : inf;
        const float pos[3][3] = {{0, 0, 0}, {1, bad, 0}, {0, 1, 0}};
        return geometry_case(dir, name, pos, NULL, 3, NULL, 0, path, path_size);
    }
    if (strcmp(name, "zero_normals") == 0) {
        const float pos[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 0, -1}, {0, 0, -1}};
        const float nrm[4][3] = {{0, 0, 0}, {0, 2, 0}, {nan, 0, 0}, {0, 0, 0}};
        const uint32_t idx[6] = {0, 1, 2, 0, 2, 3};
        return geometry_case(dir, name, pos, nrm, 4, idx, 6, path, path_size);
    }
    if (strcmp(name, "empty_scene") == 0)
        return write_text(dir, "empty_scene.gltf",
                          "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"name\":\"nothing\"}],\"scenes\":[{\"nodes\":[0]}]}",
                          path, path_size);
    if (strcmp(name, "no_scenes") == 0)
        return write_text(dir, "no_scenes.gltf", "{\"asset\":{\"version\":\"2.0\"}}", path, path_size);
    if (strcmp(name, "required_extension") == 0)
        return quad_case(dir, name, TLF_EXTERNAL, "\"extensionsRequired\":[\"KHR_draco_mesh_compression\"],"
                                                  "\"extensionsUsed\":[\"KHR_draco_mesh_compression\"]",
                         0, path, path_size);
    if (strcmp(name, "sparse_accessor") == 0) {
        tlf_doc d = {.dir = dir};
        float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        uint16_t si[1] = {1};
        float sv[3] = {5, 5, 5};
        doc_view(&d, p, sizeof p);
        doc_view(&d, si, sizeof si);
        doc_view(&d, sv, sizeof sv);
        doc_raw_accessor(&d, "{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\",\"sparse\":{\"count\":1,"
                             "\"indices\":{\"bufferView\":1,\"componentType\":5123},\"values\":{\"bufferView\":2}}}");
        int rc = doc_write(&d, name, TLF_EXTERNAL,
                           "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{\"mesh\":0}],"
                           "\"scenes\":[{\"nodes\":[0]}]",
                           path, path_size);
        doc_free(&d);
        return rc;
    }
    if (strcmp(name, "lines_mode") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"mode\":1},"
                         "{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
                         1, path, path_size);
    if (strcmp(name, "multi_scene") == 0)
        /* scene 0 draws node 0 (x = 0), scene 1 (the default) node 1 (x = 5) */
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"mesh\":0},{\"mesh\":0,\"translation\":[5,0,0]}],"
                         "\"scenes\":[{\"nodes\":[0]},{\"nodes\":[1]}],\"scene\":1",
                         1, path, path_size);
    if (strcmp(name, "zero_accessors") == 0) {
        /* POSITION and NORMAL without buffer views (all zeros, glTF says) for 300000 vertices,
         * one triangle drawn */
        tlf_doc d = {.dir = dir};
        uint16_t idx[3] = {0, 1, 2};
        doc_raw_accessor(&d, "{\"componentType\":5126,\"count\":300000,\"type\":\"VEC3\"}");
        doc_raw_accessor(&d, "{\"componentType\":5126,\"count\":300000,\"type\":\"VEC3\"}");
        doc_accessor(&d, idx, 3, U16, "SCALAR", 0);
        int rc = doc_write(&d, name, TLF_EXTERNAL,
                           "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},\"indices\":2}]}],"
                           "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
                           path, path_size);
        doc_free(&d);
        return rc;
    }
    if (strcmp(name, "mirrored") == 0)
        /* the same quad as is (x = 0) and mirrored in x (at x = 5) */
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"mesh\":0},{\"mesh\":0,\"translation\":[5,0,0],\"scale\":[-1,1,1]}],"
                         "\"scenes\":[{\"nodes\":[0,1]}]",
                         1, path, path_size);
    if (strcmp(name, "orthographic_camera") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"cameras\":[{\"type\":\"orthographic\",\"orthographic\":{\"xmag\":1,\"ymag\":1,\"znear\":0.1,\"zfar\":10}}],"
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"mesh\":0},{\"camera\":0,\"translation\":[0,0,5]}],\"scenes\":[{\"nodes\":[0,1]}]",
                         1, path, path_size);
    if (strcmp(name, "camera_zfar") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":1.0,\"znear\":0.5,\"zfar\":50}}],"
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"mesh\":0},{\"camera\":0,\"translation\":[0,3,0],"
                         "\"rotation\":[-0.70710678118654752,0,0,0.70710678118654752]}],\"scenes\":[{\"nodes\":[0,1]}]",
                         1, path, path_size);
    fprintf(stderr, "gltf fixtures: unknown case '%s'\n", name);
    return -1;
}

const char *const tlf_case_names[] = {
    "textured_boxes", "textured_boxes_glb", "textured_boxes_data_uri", "materials", "lights", "indices",
    "generated_frames", "quad", "malformed_json", "wrong_types", "missing_bin", "missing_image",
    "texture_unsupported", "texture_truncated_png", "texture_jpeg", "texture_huge", "texture_4x4", "bufferview_out_of_range", "accessor_past_view",
    "view_past_buffer", "accessor_ref_out_of_range", "mesh_ref_out_of_range", "index_out_of_range", "node_cycle",
    "node_self_child", "node_two_parents", "node_child_out_of_range", "nan_position", "inf_position",
    "zero_normals", "empty_scene", "no_scenes", "required_extension", "sparse_accessor", "lines_mode",
    "multi_scene", "zero_accessors", "mirrored", "orthographic_camera", "camera_zfar", NULL};

#ifdef TLF_MAIN
/* make_gltf_scenes DIR: writes the three test scenes (tests/gltf.cmake builds this file alone
 * with TLF_MAIN for other tests and the docs). */
int main(int argc, char **argv)
{
    if (argc != 2 || argv[1][0] == '-') {
        fprintf(stderr, "usage: make_gltf_scenes DIR\n"
                        "writes textured_boxes.gltf, materials.glb and lights.gltf (and their files) into DIR\n");
        return 2;
    }
    return tl_test_write_gltf_scenes(argv[1]) == 0 ? 0 : 1;
}
#endif
