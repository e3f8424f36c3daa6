/* The glTF fixture writer's document builder (gltf_doc.h): one buffer, buffer views, accessors and
 * images, written as .gltf with an external .bin, .gltf with data: URIs, or .glb; and the file
 * helpers of gltf_fixtures.h. */
#include "gltf_doc.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "thinlight/io.h"

/* ---- growable bytes ------------------------------------------------------------------------ */
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

void buf_printf(tlf_buf *b, const char *fmt, ...)
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

const char *buf_str(tlf_buf *b)
{
    buf_put(b, "", 0);
    return b->oom || !b->p ? "" : (const char *)b->p;
}

void buf_free(tlf_buf *b)
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

void tlf_log_stderr(void *user, tl_log_level level, const char *message)
{
    (void)user;
    if (level == TL_LOG_ERROR) fprintf(stderr, "gltf fixtures: %s\n", message);
}

int write_png(const char *dir, const char *name, uint32_t w, uint32_t h, const uint8_t *rgba)
{
    char path[1024];
    tlf_join(path, sizeof path, dir, name);
    tl_image_desc d = {.width = w, .height = h, .channels = 4, .type = TL_PIXEL_U8, .logger = {tlf_log_stderr, NULL}};
    return tl_image_write(path, &d, rgba) == TL_OK ? 0 : -1;
}

/* ---- the document ---------------------------------------------------------------------------- */
static size_t component_bytes(int ct) { return ct == U8 ? 1 : ct == U16 ? 2 : 4; }
static size_t type_components(const char *t)
{
    return strcmp(t, "SCALAR") == 0 ? 1 : strcmp(t, "VEC2") == 0 ? 2 : strcmp(t, "VEC3") == 0 ? 3 : 4;
}

int doc_view(tlf_doc *d, const void *data, size_t n)
{
    buf_pad(&d->bin, 4, 0);
    size_t off = d->bin.n;
    buf_put(&d->bin, data, n);
    buf_printf(&d->views, "%s{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}", d->view_count ? "," : "", off, n);
    return (int)d->view_count++;
}

void doc_raw_accessor(tlf_doc *d, const char *json)
{
    buf_printf(&d->accessors, "%s%s", d->accessor_count ? "," : "", json);
    d->accessor_count++;
}

/* A tightly packed accessor over its own view; float VEC3 gets the min/max glTF requires for
 * POSITION. Returns the accessor index. */
int doc_accessor(tlf_doc *d, const void *data, size_t count, int ct, const char *type, int normalized)
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
int doc_image(tlf_doc *d, const char *file, const char *mime)
{
    if (d->image_count == TLF_MAX_IMAGES) return -1;
    snprintf(d->images[d->image_count].file, sizeof d->images[0].file, "%s", file);
    snprintf(d->images[d->image_count].mime, sizeof d->images[0].mime, "%s", mime);
    return (int)d->image_count++;
}

void doc_free(tlf_doc *d)
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
int doc_write(const tlf_doc *d, const char *name, tlf_storage storage, const char *members, char *path,
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
