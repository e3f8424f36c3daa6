/* Helpers of the hostile-input tests (tests/input: gltf_limits.c, gltf_files.c, image_files.c;
 * tests/tools/outputs.c): an allocator that records every request, a logger that keeps the
 * lines, text and GLB builders, and PNG bytes made here (stored deflate blocks), so every input
 * is generated at run time. */
#ifndef TL_GLTF_HOSTILE_H
#define TL_GLTF_HOSTILE_H

#include <stddef.h>
#include <stdint.h>

#include "thinlight/base.h"

/* Counts calls, live blocks and bytes, the peak and the largest single request; fails every
 * request above `fail_above` bytes when it is set. */
typedef struct tlh_counter {
    size_t calls, live_blocks, live, peak, largest, fail_above;
} tlh_counter;
void *tlh_alloc(size_t size, void *user);
void tlh_free(void *ptr, void *user);
#define TLH_ALLOCATOR(counter) ((tl_allocator){tlh_alloc, tlh_free, (counter)})

/* Keeps the last error and every warning (joined with newlines); counts lines with a newline. */
typedef struct tlh_log {
    int errors, warnings, multiline;
    char error[2048];
    char warnings_text[16384];
} tlh_log;
void tlh_log_fn(void *user, tl_log_level level, const char *message);
#define TLH_LOGGER(log) ((tl_logger){tlh_log_fn, (log)})

/* A growable NUL-terminated text; on out of memory `p` is NULL and stays so. */
typedef struct tlh_text {
    char *p;
    size_t n, cap;
} tlh_text;
void tlh_put(tlh_text *t, const char *s);
void tlh_printf(tlh_text *t, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void tlh_repeat(tlh_text *t, const char *s, size_t times);

/* A GLB of a JSON text and a BIN chunk (NULL/0: none), malloc'ed; *size gets its length. */
unsigned char *tlh_glb(const char *json, const void *bin, size_t bin_size, size_t *size);
/* An 8-bit RGBA PNG of w*h pixels (stored, uncompressed), malloc'ed. */
unsigned char *tlh_png(uint32_t w, uint32_t h, const uint8_t *rgba, size_t *size);
/* An 8-bit RGBA PNG of w*h pixels of one colour, compressed (an 8192x8192 texture in 4 MiB),
 * malloc'ed. */
unsigned char *tlh_png_flat(uint32_t w, uint32_t h, const uint8_t rgba[4], size_t *size);
/* A PNG whose IHDR says w*h RGBA but whose IDAT holds `idat_bytes` bytes only, malloc'ed. */
unsigned char *tlh_png_header(uint32_t w, uint32_t h, size_t idat_bytes, size_t *size);
/* Base64 of the bytes appended to `t`. */
void tlh_base64(tlh_text *t, const unsigned char *d, size_t n);

/* Files: 0 on success. */
int tlh_write(const char *path, const void *data, size_t size);
/* The whole file, malloc'ed, *size its length; NULL when it cannot be read. */
unsigned char *tlh_read(const char *path, size_t *size);
int tlh_mkdirs(const char *dir);
/* Removes a test's folder and everything in it (no symbolic link is followed). */
void tlh_rmtree(const char *dir);

#endif
