/* fuzz_seeds DIR: writes the seed corpora of the libFuzzer targets (tests/fuzz/README.md) into
 * DIR/gltf_json, DIR/gltf_glb, DIR/image and DIR/codec, all generated: the glTF test scenes and
 * every named case of tests/common/gltf_fixtures.h (buffers and images as data: URIs or inside the GLB),
 * small PNG and JPEG images of each channel count, PNG of every colour type and bit depth
 * (palette with transparency, 1 to 16 bits), and codec inputs for every function family.
 * Nothing binary is committed. Exit 0, or 1 with a line on stderr. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_fixtures.h"
#include "thinlight/io.h"

static void log_error(void *user, tl_log_level level, const char *message)
{
    (void)user;
    if (level == TL_LOG_ERROR) fprintf(stderr, "fuzz_seeds: %s\n", message);
}

static int sub(char *out, size_t n, const char *dir, const char *name)
{
    tlf_join(out, n, dir, name);
    return tlf_mkdir_p(out);
}

/* The three scenes, self-contained: data URIs for the JSON target, GLB for the binary one. */
static int scenes(const char *json_dir, const char *glb_dir)
{
    int (*const writers[3])(const char *, const char *, tlf_storage) = {tlf_write_textured_boxes, tlf_write_materials,
                                                                         tlf_write_lights};
    const char *names[3] = {"textured_boxes", "materials", "lights"};
    for (int i = 0; i < 3; i++)
        if (writers[i](json_dir, names[i], TLF_DATA_URI) || writers[i](glb_dir, names[i], TLF_GLB)) return -1;
    return 0;
}

/* Every named case, written into scratch/CASE; its main file is copied into the corpus its
 * content belongs to (external files it names are not there: those inputs test the failure). */
static int cases(const char *scratch, const char *json_dir, const char *glb_dir)
{
    for (const char *const *c = tlf_case_names; *c; c++) {
        char dir[1024], path[1024], dst[1024];
        if (sub(dir, sizeof dir, scratch, *c) || tlf_write_case(dir, *c, path, sizeof path)) return -1;
        size_t n = 0;
        unsigned char *b = tlf_read_file(path, &n);
        if (!b) return -1;
        int glb = n >= 4 && memcmp(b, "glTF", 4) == 0;
        char name[256];
        snprintf(name, sizeof name, "case_%s.%s", *c, glb ? "glb" : "gltf");
        tlf_join(dst, sizeof dst, glb ? glb_dir : json_dir, name);
        int rc = tlf_write_file(dst, b, n);
        free(b);
        if (rc) return -1;
    }
    return 0;
}

/* PNG with 1 to 4 channels and JPEG with 1 and 3, in sizes that stress row and block edges. */
static int images(const char *dir)
{
    static const uint32_t sizes[][2] = {{1, 1}, {7, 5}, {16, 16}, {33, 9}};
    uint8_t px[33 * 16 * 4];
    for (size_t i = 0; i < sizeof px; i++) px[i] = (uint8_t)(i * 37u + (i >> 5) * 11u);
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
        for (uint32_t ch = 1; ch <= 4; ch++) {
            const char *ext[2] = {"png", "jpg"};
            for (int e = 0; e < 2; e++) {
                if (e == 1 && ch != 1 && ch != 3) continue;
                char name[64], path[1024];
                snprintf(name, sizeof name, "%ux%u_%uch.%s", sizes[s][0], sizes[s][1], ch, ext[e]);
                tlf_join(path, sizeof path, dir, name);
                tl_image_desc d = {.width = sizes[s][0], .height = sizes[s][1], .channels = ch,
                                   .logger = {log_error, NULL}};
                if (tl_image_write(path, &d, px) != TL_OK) return -1;
            }
        }
    return 0;
}

/* ---- PNG variants tl_image_write does not make ----------------------------------------------- */

static void be32(uint8_t *p, uint32_t v)
{
    for (int k = 0; k < 4; k++) p[k] = (uint8_t)(v >> (24 - 8 * k));
}

static uint32_t crc32_of(const uint8_t *p, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xFFFFFFFFu;
}

static size_t chunk(uint8_t *out, const char *type, const uint8_t *d, size_t n)
{
    be32(out, (uint32_t)n);
    memcpy(out + 4, type, 4);
    if (n) memcpy(out + 8, d, n);
    be32(out + 8 + n, crc32_of(out + 4, n + 4));
    return 12 + n;
}

/* A w x h PNG of colour type `ct` and bit depth `bits`, rows of varied bytes (filter 0) in one
 * stored deflate block; palette images get a PLTE and a tRNS chunk. */
static int png_variant(const char *dir, uint32_t w, uint32_t h, uint8_t ct, uint8_t bits)
{
    static const unsigned channels[7] = {1, 0, 3, 1, 2, 0, 4};
    size_t row = 1 + ((size_t)w * channels[ct] * bits + 7) / 8, raw = row * h;
    uint8_t z[2 + 5 + 4096 + 4], out[8 + 25 + 12 + 768 + 12 + 256 + 12 + sizeof z + 12];
    if (raw > 4096) return -1;
    uint32_t a = 1, b = 0;
    z[0] = 0x78;
    z[1] = 0x01;
    z[2] = 1;
    z[3] = (uint8_t)raw;
    z[4] = (uint8_t)(raw >> 8);
    z[5] = (uint8_t)~raw;
    z[6] = (uint8_t)(~raw >> 8);
    for (size_t i = 0; i < raw; i++) {
        z[7 + i] = i % row == 0 ? 0 : (uint8_t)(i * 29u + i / 3u);
        a = (a + z[7 + i]) % 65521u;
        b = (b + a) % 65521u;
    }
    be32(z + 7 + raw, b << 16 | a);
    uint8_t ihdr[13] = {0};
    be32(ihdr, w);
    be32(ihdr + 4, h);
    ihdr[8] = bits;
    ihdr[9] = ct;
    memcpy(out, "\x89PNG\r\n\x1a\n", 8);
    size_t n = 8 + chunk(out + 8, "IHDR", ihdr, 13);
    if (ct == 3) {
        uint8_t plte[768], trns[256];
        for (int i = 0; i < 768; i++) plte[i] = (uint8_t)(i * 7);
        for (int i = 0; i < 256; i++) trns[i] = (uint8_t)(255 - i);
        n += chunk(out + n, "PLTE", plte, (size_t)3 << bits);
        n += chunk(out + n, "tRNS", trns, (size_t)1 << bits);
    }
    n += chunk(out + n, "IDAT", z, 7 + raw + 4);
    n += chunk(out + n, "IEND", NULL, 0);
    char name[64], path[1024];
    snprintf(name, sizeof name, "variant_ct%u_%ubit.png", ct, bits);
    tlf_join(path, sizeof path, dir, name);
    return tlf_write_file(path, out, n);
}

/* Every valid colour type and bit depth of PNG. */
static int png_variants(const char *dir)
{
    static const uint8_t combos[][2] = {{0, 1}, {0, 2}, {0, 4}, {0, 8}, {0, 16}, {2, 8}, {2, 16}, {3, 1}, {3, 2},
                                        {3, 4}, {3, 8}, {4, 8}, {4, 16}, {6, 8}, {6, 16}};
    for (size_t i = 0; i < sizeof combos / sizeof combos[0]; i++)
        if (png_variant(dir, 9, 5, combos[i][0], combos[i][1])) return -1;
    return 0;
}

/* Codec inputs: the family byte, then parameters and values from a fixed generator, with the
 * float patterns that matter (0, -0, 1, denormal, Inf, NaN) mixed in. */
static int codec(const char *dir)
{
    static const uint32_t special[] = {0x00000000u, 0x80000000u, 0x3F800000u, 0x00000001u, 0x7F800000u,
                                       0xFF800000u, 0x7FC00000u, 0x3F3504F3u};
    unsigned long long s = 1;
    for (int family = 0; family < 6; family++)
        for (int v = 0; v < 4; v++) {
            uint8_t b[1 + 4 * 64];
            b[0] = (uint8_t)family;
            for (size_t i = 1; i < sizeof b; i += 4) {
                s = s * 6364136223846793005ull + 1442695040888963407ull;
                uint32_t w = (uint32_t)(s >> 32);
                if ((w & 3u) == 0) w = special[(w >> 2) % 8];
                if (i < 17) w = (uint32_t)(v * 5 + (int)i) % 24; /* small parameters: bits, enums, sizes */
                memcpy(b + i, &w, 4);
            }
            char name[64], path[1024];
            snprintf(name, sizeof name, "family%d_%d", family, v);
            tlf_join(path, sizeof path, dir, name);
            if (tlf_write_file(path, b, sizeof b)) return -1;
        }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: fuzz_seeds DIR\n");
        return 2;
    }
    char json[1024], glb[1024], image[1024], codec_dir[1024], scratch[1024];
    if (sub(json, sizeof json, argv[1], "gltf_json") || sub(glb, sizeof glb, argv[1], "gltf_glb") ||
        sub(image, sizeof image, argv[1], "image") || sub(codec_dir, sizeof codec_dir, argv[1], "codec") ||
        sub(scratch, sizeof scratch, argv[1], "scratch")) {
        fprintf(stderr, "fuzz_seeds: cannot create the folders in %s\n", argv[1]);
        return 1;
    }
    if (scenes(json, glb) || cases(scratch, json, glb) || images(image) || png_variants(image) || codec(codec_dir)) {
        fprintf(stderr, "fuzz_seeds: cannot write the seeds into %s\n", argv[1]);
        return 1;
    }
    return 0;
}
