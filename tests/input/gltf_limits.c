/* glTF limits (docs/gltf.md, "Limits"): the load's memory budget, JSON hostile in shape (nesting
 * thousands deep, enormous arrays and strings), and counts that overflow 32 bits or size_t. Every
 * file is generated here and parsed from memory (tl_scene_parse_gltf), with an allocator that
 * records the largest request: a limit must fail before the big allocation, not after it. */
#include <stdint.h>

#include "gltf_hostile.h"
#include "thinlight/io.h"
#include "thinlight/scene.h"
#include "tl_test.h"

#define MiB ((size_t)1 << 20)

typedef struct parsed {
    tl_result result;
    tl_scene *scene;
    tlh_counter count;
    tlh_log log;
} parsed;

/* Parses `size` bytes with the recording allocator and logger on top of `base`; checks what
 * every load must keep (one line per message, a scene exactly on success, nothing leaked). */
static void parse(parsed *p, const void *data, size_t size, const tl_gltf_options *base)
{
    memset(p, 0, sizeof *p);
    tl_gltf_options o = base ? *base : (tl_gltf_options){0};
    o.allocator = TLH_ALLOCATOR(&p->count);
    o.logger = TLH_LOGGER(&p->log);
    p->result = tl_scene_parse_gltf(data, size, &o, &p->scene);
    TL_CHECK(p->log.multiline == 0);
    TL_CHECK((p->result == TL_OK) == (p->scene != NULL));
    TL_CHECK((p->result == TL_OK) == (p->log.errors == 0));
    if (p->result != TL_OK) TL_CHECK(p->count.live_blocks == 0);
}

static void done(parsed *p)
{
    tl_scene_destroy(p->scene);
    p->scene = NULL;
    TL_CHECK(p->count.live_blocks == 0);
}

static void expect(const parsed *p, tl_result want, const char *needle)
{
    if (p->result != want || (needle && !strstr(p->log.error, needle)))
        fprintf(stderr, "got %s (%s), want %s with '%s'\n", tl_result_string(p->result), p->log.error,
                tl_result_string(want), needle ? needle : "");
    TL_CHECK(p->result == want);
    if (needle) TL_CHECK(strstr(p->log.error, needle) != NULL);
}

static const char *const ASSET = "\"asset\":{\"version\":\"2.0\"}";

/* ---- the memory budget --------------------------------------------------------------------- */

/* 200 bytes: a POSITION accessor without a buffer view is 201326592 zero vertices (2^26
 * triangles, inside max_triangles). Before the budget the loader asked for 9216 MiB in one
 * request (9984 MiB in all) and built them; now it fails before allocating. */
static const char SMALL_GLTF[] =
    "{\"asset\":{\"version\":\"2.0\"},\"accessors\":[{\"componentType\":5126,\"count\":201326592,"
    "\"type\":\"VEC3\"}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{\"mesh\":0}],"
    "\"scenes\":[{\"nodes\":[0]}]}";

TL_TEST(gltf_budget_200_byte_file_asks_for_no_gigabytes)
{
    TL_CHECK(strlen(SMALL_GLTF) == 200);
    parsed p;
    parse(&p, SMALL_GLTF, strlen(SMALL_GLTF), NULL);
    expect(&p, TL_ERROR_LIMIT, "201326592 vertices");
    TL_CHECK(strstr(p.log.error, "memory budget of 512.0 MiB") != NULL);
    printf("200-byte glTF: %s; largest request %zu bytes, peak %zu bytes\n", p.log.error, p.count.largest,
           p.count.peak);
    TL_CHECK_LE(p.count.largest, MiB);
    done(&p);
    /* the application may allow it: the request is then made (and refused by this allocator) */
    tl_gltf_options big = {.max_memory = SIZE_MAX};
    memset(&p, 0, sizeof p);
    tlh_counter c = {.fail_above = 64 * MiB};
    big.allocator = TLH_ALLOCATOR(&c);
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_parse_gltf(SMALL_GLTF, strlen(SMALL_GLTF), &big, &s) == TL_ERROR_OUT_OF_MEMORY);
    TL_CHECK(c.largest == (size_t)201326592 * sizeof(tl_vertex) && c.live_blocks == 0);
}

/* A GLB of one PNG header (8192 x 8192 RGBA, 256 MiB decoded, in 11 bytes of IDAT) used by
 * `refs` images, each with its own material: before, every image asked for 256 MiB before the
 * decoder found the data short (1024 MiB from 988 bytes). Now the header is checked against the
 * data first and nothing large is requested; each image is a warning. */
static unsigned char *png_header_glb(int refs, size_t *size)
{
    size_t png_size = 0;
    unsigned char *png = tlh_png_header(8192, 8192, 11, &png_size);
    tlh_text j = {0};
    tlh_printf(&j, "{%s,\"buffers\":[{\"byteLength\":%zu}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":%zu}],", ASSET,
               png_size, png_size);
    tlh_put(&j, "\"images\":[");
    for (int i = 0; i < refs; i++) tlh_printf(&j, "%s{\"bufferView\":0,\"mimeType\":\"image/png\"}", i ? "," : "");
    tlh_put(&j, "],\"textures\":[");
    for (int i = 0; i < refs; i++) tlh_printf(&j, "%s{\"source\":%d}", i ? "," : "", i);
    tlh_put(&j, "],\"materials\":[");
    for (int i = 0; i < refs; i++)
        tlh_printf(&j, "%s{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":%d}}}", i ? "," : "", i);
    tlh_put(&j, "],\"accessors\":[{\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}],\"meshes\":[{\"primitives\":[");
    for (int i = 0; i < refs; i++) tlh_printf(&j, "%s{\"attributes\":{\"POSITION\":0},\"material\":%d}", i ? "," : "", i);
    tlh_put(&j, "]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}");
    unsigned char *glb = png && j.p ? tlh_glb(j.p, png, png_size, size) : NULL;
    free(png);
    free(j.p);
    return glb;
}

TL_TEST(gltf_budget_small_glb_png_headers_ask_for_nothing)
{
    size_t n = 0;
    unsigned char *glb = png_header_glb(4, &n);
    TL_CHECK(glb != NULL && n < 1024);
    if (!glb) return;
    parsed p;
    parse(&p, glb, n, NULL);
    TL_CHECK(p.result == TL_OK);
    TL_CHECK(p.log.warnings == 4 && strstr(p.log.warnings_text, "cannot hold 8192x8192 pixels") != NULL);
    printf("%zu-byte GLB: largest request %zu bytes, peak %zu bytes\n", n, p.count.largest, p.count.peak);
    TL_CHECK_LE(p.count.largest, MiB);
    if (p.scene) TL_CHECK(p.scene->texture_count == 0);
    done(&p);
    free(glb);
}

/* One real 256x256 PNG (256 KiB decoded) used by 8 images: each decode counts, even of the same
 * bytes. A budget that holds 4 of them fails at the fifth, naming the image. */
TL_TEST(gltf_budget_counts_each_image_reference)
{
    uint8_t *rgba = malloc(256 * 256 * 4);
    if (!rgba) return;
    for (size_t i = 0; i < 256 * 256 * 4; i++) rgba[i] = (uint8_t)i;
    size_t png_size = 0;
    unsigned char *png = tlh_png(256, 256, rgba, &png_size);
    free(rgba);
    tlh_text j = {0};
    tlh_printf(&j, "{%s,\"buffers\":[{\"byteLength\":%zu}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":%zu}],\"images\":[",
               ASSET, png_size, png_size);
    for (int i = 0; i < 8; i++) tlh_printf(&j, "%s{\"bufferView\":0}", i ? "," : "");
    tlh_put(&j, "],\"textures\":[");
    for (int i = 0; i < 8; i++) tlh_printf(&j, "%s{\"source\":%d}", i ? "," : "", i);
    tlh_put(&j, "],\"materials\":[");
    for (int i = 0; i < 8; i++) tlh_printf(&j, "%s{\"emissiveTexture\":{\"index\":%d}}", i ? "," : "", i);
    tlh_put(&j, "],\"accessors\":[{\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}],\"meshes\":[{\"primitives\":[");
    for (int i = 0; i < 8; i++) tlh_printf(&j, "%s{\"attributes\":{\"POSITION\":0},\"material\":%d}", i ? "," : "", i);
    tlh_put(&j, "]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}");
    size_t n = 0;
    unsigned char *glb = png && j.p ? tlh_glb(j.p, png, png_size, &n) : NULL;
    free(png);
    free(j.p);
    TL_CHECK(glb != NULL);
    if (!glb) return;
    parsed p;
    parse(&p, glb, n, NULL);
    TL_CHECK(p.result == TL_OK);
    if (p.scene) TL_CHECK_EQ_U(p.scene->texture_count, 8);
    size_t peak = p.count.peak;
    TL_CHECK(peak >= 8 * 256 * 256 * 4);
    done(&p);
    /* 4.5 images' worth above what the rest needs */
    tl_gltf_options o = {.max_memory = peak - 3 * 256 * 256 * 4 - 256 * 256 * 2};
    parse(&p, glb, n, &o);
    expect(&p, TL_ERROR_LIMIT, "images[");
    TL_CHECK(strstr(p.log.error, "(256x256 pixels)") != NULL && strstr(p.log.error, "memory budget") != NULL);
    done(&p);
    free(glb);
}

/* Many objects from a few bytes: 200 nodes each drawing a mesh of 200 primitives. */
TL_TEST(gltf_budget_objects_from_instancing)
{
    tlh_text j = {0};
    tlh_printf(&j, "{%s,\"accessors\":[{\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}],\"meshes\":[{\"primitives\":[",
               ASSET);
    for (int i = 0; i < 200; i++) tlh_printf(&j, "%s{\"attributes\":{\"POSITION\":0}}", i ? "," : "");
    tlh_put(&j, "]}],\"nodes\":[");
    for (int i = 0; i < 200; i++) tlh_printf(&j, "%s{\"mesh\":0}", i ? "," : "");
    tlh_put(&j, "]}");
    if (!j.p) return;
    tl_gltf_options o = {.max_memory = 2 * MiB};
    parsed p;
    parse(&p, j.p, j.n, &o);
    expect(&p, TL_ERROR_LIMIT, "40000 objects");
    done(&p);
    parse(&p, j.p, j.n, NULL); /* the default budget holds them */
    TL_CHECK(p.result == TL_OK);
    if (p.scene) TL_CHECK_EQ_U(p.scene->object_count, 40000);
    done(&p);
    free(j.p);
}

/* max_memory is the one budget: a tiny one fails the same file early, naming what. */
TL_TEST(gltf_budget_option_settable)
{
    const char *quad = "{\"asset\":{\"version\":\"2.0\"},\"accessors\":[{\"componentType\":5126,\"count\":6,\"type\":\"VEC3\"}],"
                       "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{\"mesh\":0}]}";
    parsed p;
    parse(&p, quad, strlen(quad), NULL);
    TL_CHECK(p.result == TL_OK);
    size_t peak = p.count.peak;
    done(&p);
    tl_gltf_options o = {.max_memory = 1024};
    parse(&p, quad, strlen(quad), &o);
    expect(&p, TL_ERROR_LIMIT, "parsing the JSON");
    TL_CHECK(strstr(p.log.error, "budget of 1024 bytes") != NULL);
    done(&p);
    o.max_memory = SIZE_MAX;
    parse(&p, quad, strlen(quad), &o);
    TL_CHECK(p.result == TL_OK && p.count.peak == peak);
    done(&p);
}

/* ---- JSON hostile in shape ----------------------------------------------------------------- */

/* A document with `open` and `close` repeated `depth` times at `where` (a %s in `frame`). */
static char *nested(const char *frame, const char *open, const char *close, size_t depth)
{
    tlh_text inner = {0}, t = {0};
    tlh_repeat(&inner, open, depth);
    tlh_put(&inner, "0");
    tlh_repeat(&inner, close, depth);
    if (inner.p) tlh_printf(&t, frame, inner.p);
    free(inner.p);
    return t.p;
}

TL_TEST(gltf_json_nested_100000_deep_anywhere)
{
    /* Before: tinygltf converted extras recursively and crashed on 100000 levels. */
    static const char *const frames[] = {
        "{\"asset\":{\"version\":\"2.0\",\"extras\":%s}}",
        "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"extensions\":{\"X\":%s}}]}",
        "{\"asset\":{\"version\":\"2.0\"},\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"extras\":%s}]}]}",
        "{\"asset\":{\"version\":\"2.0\"},\"scenes\":%s}",
        "%s",
    };
    for (size_t f = 0; f < sizeof frames / sizeof frames[0]; f++)
        for (int kind = 0; kind < 2; kind++) {
            char *doc = nested(frames[f], kind ? "{\"a\":" : "[", kind ? "}" : "]", 100000);
            TL_CHECK(doc != NULL);
            if (!doc) continue;
            parsed p;
            parse(&p, doc, strlen(doc), NULL);
            expect(&p, TL_ERROR_LIMIT, "JSON nested more than 64 levels deep");
            done(&p);
            free(doc);
        }
    /* inside a GLB too, the offset counted from the file's start: 20 bytes of header, 35 of
     * {"asset":{"version":"2.0","extras": and the 63rd '[' (level 65) */
    char *doc = nested("{\"asset\":{\"version\":\"2.0\",\"extras\":%s}}", "[", "]", 5000);
    size_t n = 0;
    unsigned char *glb = doc ? tlh_glb(doc, NULL, 0, &n) : NULL;
    if (glb) {
        parsed p;
        parse(&p, glb, n, NULL);
        expect(&p, TL_ERROR_LIMIT, "levels deep (at byte 117)");
        done(&p);
    }
    free(glb);
    free(doc);
}

TL_TEST(gltf_json_nesting_at_the_limit_loads)
{
    /* the root object, "asset" and 62 arrays: 64 levels */
    char *doc = nested("{\"asset\":{\"version\":\"2.0\",\"extras\":%s}}", "[", "]", 62);
    parsed p;
    if (doc) parse(&p, doc, strlen(doc), NULL);
    TL_CHECK(doc && p.result == TL_OK);
    if (doc) done(&p);
    free(doc);
    doc = nested("{\"asset\":{\"version\":\"2.0\",\"extras\":%s}}", "[", "]", 63);
    if (doc) parse(&p, doc, strlen(doc), NULL);
    TL_CHECK(doc && p.result == TL_ERROR_LIMIT);
    if (doc) done(&p);
    free(doc);
    /* brackets inside strings are text, not nesting */
    tlh_text t = {0};
    tlh_put(&t, "{\"asset\":{\"version\":\"2.0\",\"extras\":\"");
    tlh_repeat(&t, "[{", 50000);
    tlh_put(&t, "\\\"\"}}");
    if (t.p) parse(&p, t.p, t.n, NULL);
    TL_CHECK(t.p && p.result == TL_OK);
    if (t.p) done(&p);
    free(t.p);
}

TL_TEST(gltf_json_enormous_array_refused_before_parsing)
{
    /* 10 million numbers in 20 MB of text: about 2 GB once parsed */
    tlh_text t = {0};
    tlh_put(&t, "{\"asset\":{\"version\":\"2.0\",\"extras\":[0");
    tlh_repeat(&t, ",0", 10000000);
    tlh_put(&t, "]}}");
    TL_CHECK(t.p != NULL);
    if (!t.p) return;
    parsed p;
    parse(&p, t.p, t.n, NULL);
    expect(&p, TL_ERROR_LIMIT, "parsing the JSON (");
    TL_CHECK(strstr(p.log.error, "10000004 values") != NULL); /* 3 members, 10000001 commas */
    TL_CHECK_LE(p.count.largest, MiB);
    done(&p);
    free(t.p);
    /* 300000 empty materials: 3 bytes each in the file, 2 KiB each in tinygltf */
    tlh_text m = {0};
    tlh_put(&m, "{\"asset\":{\"version\":\"2.0\"},\"materials\":[{}");
    tlh_repeat(&m, ",{}", 299999);
    tlh_put(&m, "]}");
    if (m.p) parse(&p, m.p, m.n, NULL);
    TL_CHECK(m.p && p.result == TL_ERROR_LIMIT);
    if (m.p) done(&p);
    free(m.p);
}

TL_TEST(gltf_json_enormous_string_counted)
{
    /* a 16 MB name: fine within the default budget, refused within a 32 MiB one */
    tlh_text t = {0};
    tlh_put(&t, "{\"asset\":{\"version\":\"2.0\"},\"scenes\":[{\"name\":\"");
    tlh_repeat(&t, "abcdefghijklmnop", 1000000);
    tlh_put(&t, "\"}]}");
    if (!t.p) return;
    parsed p;
    parse(&p, t.p, t.n, NULL);
    TL_CHECK(p.result == TL_OK);
    done(&p);
    tl_gltf_options o = {.max_memory = 32 * MiB};
    parse(&p, t.p, t.n, &o);
    expect(&p, TL_ERROR_LIMIT, "of strings)");
    done(&p);
    free(t.p);
}

/* ---- counts past 32 bits and size_t -------------------------------------------------------- */

/* `prims` primitives each with a POSITION accessor of `count` vertices without a buffer view. */
static char *zero_vertices(const char *count, int prims)
{
    tlh_text j = {0};
    tlh_printf(&j, "{%s,\"accessors\":[{\"componentType\":5126,\"count\":%s,\"type\":\"VEC3\"}],\"meshes\":[{\"primitives\":[",
               ASSET, count);
    for (int i = 0; i < prims; i++) tlh_printf(&j, "%s{\"attributes\":{\"POSITION\":0}}", i ? "," : "");
    tlh_put(&j, "]}],\"nodes\":[{\"mesh\":0}]}");
    return j.p;
}

TL_TEST(gltf_vertex_count_over_2_32)
{
    /* the limits lifted by the application: 2 x (2^31 + 2) vertices still cannot be indexed */
    tl_gltf_options o = {.max_triangles = SIZE_MAX, .max_memory = SIZE_MAX};
    char *doc = zero_vertices("2147483650", 2);
    parsed p;
    if (doc) parse(&p, doc, strlen(doc), &o);
    TL_CHECK(doc && p.result == TL_ERROR_LIMIT && strstr(p.log.error, "more than 2^32 - 1 vertices or indices"));
    if (doc) {
        TL_CHECK_LE(p.count.largest, MiB);
        done(&p);
    }
    free(doc);
    /* one primitive of 2^32 + 2 (non-indexed: as many indices) */
    doc = zero_vertices("4294967298", 1);
    if (doc) parse(&p, doc, strlen(doc), &o);
    TL_CHECK(doc && p.result == TL_ERROR_LIMIT && strstr(p.log.error, "2^32 - 1"));
    if (doc) done(&p);
    free(doc);
}

TL_TEST(gltf_counts_near_2_64_do_not_wrap)
{
    /* 3 + (2^64 - 1) vertices wrapped to 2 in size_t, and the loader wrote 2^64 - 1 vertices into
     * a 2-vertex array (a heap overflow with default options; tests/fuzz/regressions). */
    tlh_text j = {0};
    tlh_printf(&j,
               "{%s,\"buffers\":[{\"byteLength\":12,\"uri\":\"data:application/octet-stream;base64,AAAAAAEAAAACAAAA\"}],"
               "\"bufferViews\":[{\"buffer\":0,\"byteLength\":12}],\"accessors\":["
               "{\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
               "{\"componentType\":5126,\"count\":18446744073709551615,\"type\":\"VEC3\"},"
               "{\"componentType\":5125,\"count\":3,\"type\":\"SCALAR\",\"bufferView\":0}],"
               "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}},"
               "{\"attributes\":{\"POSITION\":1,\"NORMAL\":1},\"indices\":2}]}],\"nodes\":[{\"mesh\":0}]}",
               ASSET);
    tl_gltf_options lifted = {.max_triangles = SIZE_MAX, .max_memory = SIZE_MAX};
    for (int k = 0; k < 2 && j.p; k++) {
        parsed p;
        parse(&p, j.p, j.n, k ? &lifted : NULL);
        expect(&p, TL_ERROR_LIMIT, "2^32 - 1");
        done(&p);
    }
    free(j.p);
    /* four instances of (2^64 - 1) / 3 triangles: the drawn sum passes 2^64 */
    tlh_text t = {0};
    tlh_printf(&t, "{%s,\"accessors\":[{\"componentType\":5126,\"count\":18446744073709551615,\"type\":\"VEC3\"}],"
                   "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
                   "\"nodes\":[{\"mesh\":0},{\"mesh\":0},{\"mesh\":0},{\"mesh\":0}]}",
               ASSET);
    if (t.p) {
        parsed p;
        parse(&p, t.p, t.n, &lifted);
        expect(&p, TL_ERROR_LIMIT, "triangles");
        done(&p);
    }
    free(t.p);
}
