/* Helpers of the hostile-input tests (gltf_hostile.h). */
#define _XOPEN_SOURCE 700

#include "gltf_hostile.h"

#include <errno.h>
#include <ftw.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- the allocator and the logger ---------------------------------------------------------- */

typedef union tlh_header {
    size_t size;
    max_align_t align;
} tlh_header;

void *tlh_alloc(size_t size, void *user)
{
    tlh_counter *c = user;
    c->calls++;
    if (size > c->largest) c->largest = size;
    if (c->fail_above && size > c->fail_above) return NULL;
    if (size > SIZE_MAX - sizeof(tlh_header)) return NULL;
    tlh_header *h = malloc(sizeof *h + size);
    if (!h) return NULL;
    h->size = size;
    c->live_blocks++;
    c->live += size;
    if (c->live > c->peak) c->peak = c->live;
    return h + 1;
}

void tlh_free(void *ptr, void *user)
{
    tlh_counter *c = user;
    if (!ptr) return;
    tlh_header *h = (tlh_header *)ptr - 1;
    c->live_blocks--;
    c->live -= h->size;
    free(h);
}

void tlh_log_fn(void *user, tl_log_level level, const char *message)
{
    tlh_log *l = user;
    if (strchr(message, '\n') || strchr(message, '\r')) l->multiline++;
    if (level == TL_LOG_ERROR) {
        l->errors++;
        snprintf(l->error, sizeof l->error, "%s", message);
    } else if (level == TL_LOG_WARNING) {
        l->warnings++;
        size_t n = strlen(l->warnings_text);
        snprintf(l->warnings_text + n, sizeof l->warnings_text - n, "%s\n", message);
    }
}

/* ---- text ---------------------------------------------------------------------------------- */

static void tlh_reserve(tlh_text *t, size_t extra)
{
    if (t->cap && !t->p) return; /* out of memory before */
    if (t->n + extra + 1 <= t->cap) return;
    size_t cap = t->cap ? t->cap : 256;
    while (cap < t->n + extra + 1) cap *= 2;
    char *p = realloc(t->p, cap);
    if (!p) free(t->p);
    t->p = p;
    t->cap = cap;
}

void tlh_put(tlh_text *t, const char *s)
{
    size_t n = strlen(s);
    tlh_reserve(t, n);
    if (!t->p) return;
    memcpy(t->p + t->n, s, n + 1);
    t->n += n;
}

void tlh_printf(tlh_text *t, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0) return;
    tlh_reserve(t, (size_t)n);
    if (!t->p) return;
    va_start(ap, fmt);
    vsnprintf(t->p + t->n, (size_t)n + 1, fmt, ap);
    va_end(ap);
    t->n += (size_t)n;
}

void tlh_repeat(tlh_text *t, const char *s, size_t times)
{
    size_t n = strlen(s);
    tlh_reserve(t, n * times);
    for (size_t i = 0; t->p && i < times; i++) {
        memcpy(t->p + t->n, s, n);
        t->n += n;
    }
    if (t->p) t->p[t->n] = '\0';
}

void tlh_base64(tlh_text *t, const unsigned char *d, size_t n)
{
    static const char a[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    char q[5] = {0};
    for (size_t i = 0; i < n; i += 3) {
        uint32_t v = (uint32_t)d[i] << 16 | (i + 1 < n ? (uint32_t)d[i + 1] << 8 : 0) | (i + 2 < n ? d[i + 2] : 0);
        q[0] = a[v >> 18];
        q[1] = a[(v >> 12) & 63];
        q[2] = i + 1 < n ? a[(v >> 6) & 63] : '=';
        q[3] = i + 2 < n ? a[v & 63] : '=';
        tlh_put(t, q);
    }
}

/* ---- GLB and PNG --------------------------------------------------------------------------- */

static void le32(unsigned char *p, uint32_t v)
{
    for (int k = 0; k < 4; k++) p[k] = (unsigned char)(v >> (8 * k));
}

static void be32(unsigned char *p, uint32_t v)
{
    for (int k = 0; k < 4; k++) p[k] = (unsigned char)(v >> (24 - 8 * k));
}

unsigned char *tlh_glb(const char *json, const void *bin, size_t bin_size, size_t *size)
{
    size_t jn = strlen(json), jpad = (4 - jn % 4) % 4, bpad = (4 - bin_size % 4) % 4;
    size_t total = 20 + jn + jpad + (bin ? 8 + bin_size + bpad : 0);
    unsigned char *g = calloc(1, total);
    if (!g) return NULL;
    memcpy(g, "glTF", 4);
    le32(g + 4, 2);
    le32(g + 8, (uint32_t)total);
    le32(g + 12, (uint32_t)(jn + jpad));
    memcpy(g + 16, "JSON", 4);
    memcpy(g + 20, json, jn);
    memset(g + 20 + jn, ' ', jpad);
    if (bin) {
        unsigned char *b = g + 20 + jn + jpad;
        le32(b, (uint32_t)(bin_size + bpad));
        memcpy(b + 4, "BIN", 4);
        memcpy(b + 8, bin, bin_size);
    }
    *size = total;
    return g;
}

static uint32_t crc32_of(const unsigned char *p, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xFFFFFFFFu;
}

/* Appends a chunk (length, type, data, CRC) at *at. */
static void png_chunk(unsigned char *out, size_t *at, const char *type, const unsigned char *d, size_t n)
{
    be32(out + *at, (uint32_t)n);
    memcpy(out + *at + 4, type, 4);
    if (n) memcpy(out + *at + 8, d, n);
    be32(out + *at + 8 + n, crc32_of(out + *at + 4, n + 4));
    *at += 12 + n;
}

static unsigned char *png_with_idat(uint32_t w, uint32_t h, const unsigned char *idat, size_t idat_n, size_t *size)
{
    unsigned char *out = malloc(8 + 25 + 12 + idat_n + 12);
    if (!out) return NULL;
    memcpy(out, "\x89PNG\r\n\x1a\n", 8);
    unsigned char ihdr[13] = {0};
    be32(ihdr, w);
    be32(ihdr + 4, h);
    ihdr[8] = 8; /* bits */
    ihdr[9] = 6; /* RGBA */
    size_t at = 8;
    png_chunk(out, &at, "IHDR", ihdr, 13);
    png_chunk(out, &at, "IDAT", idat, idat_n);
    png_chunk(out, &at, "IEND", NULL, 0);
    *size = at;
    return out;
}

unsigned char *tlh_png(uint32_t w, uint32_t h, const uint8_t *rgba, size_t *size)
{
    /* zlib stream of stored blocks over the filtered rows (filter 0 before each row) */
    size_t row = 1 + (size_t)w * 4, raw = row * h, blocks = (raw + 65534) / 65535;
    size_t n = 2 + raw + 5 * (blocks ? blocks : 1) + 4;
    unsigned char *z = malloc(n), *rows = malloc(raw ? raw : 1);
    if (!z || !rows) {
        free(z);
        free(rows);
        return NULL;
    }
    for (uint32_t y = 0; y < h; y++) {
        rows[y * row] = 0;
        memcpy(rows + y * row + 1, rgba + (size_t)y * w * 4, (size_t)w * 4);
    }
    size_t at = 0;
    z[at++] = 0x78;
    z[at++] = 0x01;
    uint32_t a = 1, b = 0;
    for (size_t off = 0; off < raw || off == 0; off += 65535) {
        size_t len = raw - off < 65535 ? raw - off : 65535;
        z[at++] = off + len >= raw ? 1 : 0;
        z[at++] = (unsigned char)len;
        z[at++] = (unsigned char)(len >> 8);
        z[at++] = (unsigned char)~len;
        z[at++] = (unsigned char)(~len >> 8);
        memcpy(z + at, rows + off, len);
        at += len;
        if (raw == 0) break;
    }
    for (size_t i = 0; i < raw; i++) {
        a = (a + rows[i]) % 65521u;
        b = (b + a) % 65521u;
    }
    be32(z + at, b << 16 | a);
    at += 4;
    unsigned char *png = png_with_idat(w, h, z, at, size);
    free(z);
    free(rows);
    return png;
}

unsigned char *tlh_png_header(uint32_t w, uint32_t h, size_t idat_bytes, size_t *size)
{
    unsigned char *idat = calloc(1, idat_bytes ? idat_bytes : 1);
    if (!idat) return NULL;
    unsigned char *png = png_with_idat(w, h, idat, idat_bytes, size);
    free(idat);
    return png;
}

/* Bits into a byte array, least significant first (deflate's order). */
typedef struct bit_writer {
    unsigned char *p;
    size_t at;
    uint32_t acc;
    int n;
} bit_writer;

static void bits(bit_writer *b, uint32_t v, int n)
{
    b->acc |= v << b->n;
    b->n += n;
    while (b->n >= 8) {
        b->p[b->at++] = (unsigned char)b->acc;
        b->acc >>= 8;
        b->n -= 8;
    }
}

/* A Huffman code goes most significant bit first. */
static void code(bit_writer *b, uint32_t c, int n)
{
    uint32_t r = 0;
    for (int i = 0; i < n; i++) r |= ((c >> i) & 1u) << (n - 1 - i);
    bits(b, r, n);
}

static void literal(bit_writer *b, unsigned v)
{
    if (v < 144) code(b, 0x30 + v, 8);
    else code(b, 0x190 + (v - 144), 9);
}

unsigned char *tlh_png_flat(uint32_t w, uint32_t h, const uint8_t rgba[4], size_t *size)
{
    /* one fixed-Huffman block: per row the filter byte and the first pixel as literals, then
     * copies of 258 bytes from 4 back, the rest as literals */
    size_t row = 1 + (size_t)w * 4, copies = (row - 5) / 258, rest = row - 5 - copies * 258;
    size_t n = 2 + 1 + h * ((5 + rest) * 9 + copies * 13) / 8 + 8 + 4;
    unsigned char *z = malloc(n);
    if (!z || !w || !h) {
        free(z);
        return NULL;
    }
    z[0] = 0x78;
    z[1] = 0x01;
    bit_writer b = {z, 2, 0, 0};
    bits(&b, 1, 1); /* BFINAL */
    bits(&b, 1, 2); /* fixed Huffman codes */
    /* Adler-32 of identical rows: a row adds sum1 to a and row * a + sum2 to s (mod 65521) */
    uint64_t sum1 = 0, sum2 = 0;
    for (size_t i = 1; i < row; i++) {
        sum1 += rgba[(i - 1) % 4];
        sum2 += (uint64_t)(row - i) * rgba[(i - 1) % 4];
    }
    uint64_t a = 1, s = 0;
    for (uint32_t y = 0; y < h; y++) {
        literal(&b, 0);
        for (int c = 0; c < 4; c++) literal(&b, rgba[c]);
        for (size_t k = 0; k < copies; k++) {
            code(&b, 0xC0 + 5, 8); /* length 258: symbol 285 */
            code(&b, 3, 5);        /* distance 4 */
        }
        for (size_t k = 0; k < rest; k++) literal(&b, rgba[(copies * 258 + k) % 4]);
        s = (s + (uint64_t)row % 65521u * a + sum2) % 65521u;
        a = (a + sum1) % 65521u;
    }
    code(&b, 0, 7); /* end of block */
    if (b.n) bits(&b, 0, 8 - b.n);
    be32(z + b.at, (uint32_t)(s << 16 | a));
    unsigned char *png = png_with_idat(w, h, z, b.at + 4, size);
    free(z);
    return png;
}

/* ---- files --------------------------------------------------------------------------------- */

int tlh_write(const char *path, const void *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    size_t put = fwrite(data, 1, size, f);
    return fclose(f) == 0 && put == size ? 0 : -1;
}

unsigned char *tlh_read(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    unsigned char *b = NULL;
    size_t cap = 0, len = 0, got;
    do {
        if (len == cap) {
            unsigned char *bigger = realloc(b, cap = cap ? 2 * cap : 65536);
            if (!bigger) {
                free(b);
                fclose(f);
                return NULL;
            }
            b = bigger;
        }
        got = fread(b + len, 1, cap - len, f);
        len += got;
    } while (got > 0);
    int bad = ferror(f);
    fclose(f);
    if (bad) {
        free(b);
        return NULL;
    }
    *size = len;
    return b;
}

int tlh_mkdirs(const char *dir)
{
    char tmp[1024];
    snprintf(tmp, sizeof tmp, "%s", dir);
    for (char *p = tmp + 1; *p; p++) {
        if (*p != '/') continue;
        *p = 0;
        mkdir(tmp, 0755);
        *p = '/';
    }
    return mkdir(tmp, 0755) == 0 || errno == EEXIST ? 0 : -1;
}

static int tlh_remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
    (void)st;
    (void)flag;
    (void)ftw;
    remove(path);
    return 0;
}

void tlh_rmtree(const char *dir) { nftw(dir, tlh_remove_entry, 16, FTW_DEPTH | FTW_PHYS); }
