/* Fuzzed glTF files: the test scenes with random byte mutations must load or fail cleanly, never
 * crash, and free everything (gltf_checks.h). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_checks.h"

static void fuzz_file(const char *test, const char *fixture_name, const char *mutated_name, unsigned long long seed,
                      int rounds)
{
    char path[1024], dir[1024], mutated[1024];
    if (fixture(test, fixture_name, path, sizeof path)) return;
    case_dir(dir, sizeof dir, test);
    tlf_join(mutated, sizeof mutated, dir, mutated_name); /* beside the original: same .bin, PNGs */
    size_t n = 0;
    unsigned char *orig = tlf_read_file(path, &n);
    TL_CHECK(orig != NULL);
    if (!orig) return;
    unsigned char *b = malloc(n);
    tl_rng rng = {seed};
    int ok = 0;
    for (int r = 0; r < rounds && b; r++) {
        memcpy(b, orig, n);
        int edits = 1 + (int)(tl_rng_u64(&rng) % 8);
        for (int e = 0; e < edits; e++) {
            size_t at = (size_t)(tl_rng_u64(&rng) % n);
            switch (tl_rng_u64(&rng) % 4) {
            case 0: b[at] = (unsigned char)tl_rng_u64(&rng); break;            /* random byte */
            case 1: b[at] ^= (unsigned char)(1u << (tl_rng_u64(&rng) % 8)); break; /* bit flip */
            case 2: b[at] = (unsigned char)("0123456789-.e[]{},\":"[tl_rng_u64(&rng) % 20]); break; /* JSON-ish */
            default: b[at] = 0xFF; break;
            }
        }
        size_t len = tl_rng_u64(&rng) % 8 == 0 ? (size_t)(tl_rng_u64(&rng) % n) : n; /* sometimes truncated */
        if (tlf_write_file(mutated, b, len)) break;
        counter cnt = {0};
        tl_gltf_options o = {.allocator = {count_alloc, count_free, &cnt}};
        tl_scene *s = NULL;
        tl_result res = tl_scene_load_gltf(mutated, &o, &s);
        TL_CHECK(res < TL_RESULT_COUNT_);
        TL_CHECK((res == TL_OK) == (s != NULL));
        if (s) {
            ok++;
            check_geometry(s);
        }
        tl_scene_destroy(s);
        TL_CHECK(cnt.live == 0);
    }
    printf("%s: %d of %d mutated files loaded\n", fixture_name, ok, rounds);
    free(b);
    free(orig);
}

/* Mutates the external .bin of textured_boxes in place (positions, normals, UVs, indices). */
static void fuzz_bin(const char *test, unsigned long long seed, int rounds)
{
    char path[1024], dir[1024], bin[1024];
    if (fixture(test, "textured_boxes", path, sizeof path)) return;
    case_dir(dir, sizeof dir, test);
    tlf_join(bin, sizeof bin, dir, "textured_boxes.bin");
    size_t n = 0;
    unsigned char *orig = tlf_read_file(bin, &n);
    TL_CHECK(orig != NULL);
    if (!orig) return;
    unsigned char *b = malloc(n);
    tl_rng rng = {seed};
    int ok = 0;
    for (int r = 0; r < rounds && b; r++) {
        memcpy(b, orig, n);
        int edits = 1 + (int)(tl_rng_u64(&rng) % 4);
        for (int e = 0; e < edits; e++) {
            size_t at = (size_t)(tl_rng_u64(&rng) % n);
            b[at] = tl_rng_u64(&rng) % 2 ? (unsigned char)tl_rng_u64(&rng) : 0xFF; /* 0xFF makes NaNs and big indices */
        }
        if (tlf_write_file(bin, b, n)) break;
        counter cnt = {0};
        tl_gltf_options o = {.allocator = {count_alloc, count_free, &cnt}};
        tl_scene *s = NULL;
        tl_result res = tl_scene_load_gltf(path, &o, &s);
        TL_CHECK(res == TL_OK || res == TL_ERROR_PARSE);
        TL_CHECK((res == TL_OK) == (s != NULL));
        if (s) {
            ok++;
            check_geometry(s);
            check_tangents(s, 0, 24);
        }
        tl_scene_destroy(s);
        TL_CHECK(cnt.live == 0);
    }
    tlf_write_file(bin, orig, n);
    printf("textured_boxes.bin: %d of %d mutated buffers loaded\n", ok, rounds);
    free(b);
    free(orig);
}

TL_TEST(gltf_fuzz_mutations)
{
    fuzz_file("gltf_fuzz_mutations", "textured_boxes_glb", "mutated.glb", 1, 600);
    fuzz_file("gltf_fuzz_mutations", "textured_boxes", "mutated.gltf", 2, 600);
    fuzz_file("gltf_fuzz_mutations", "lights", "mutated_lights.gltf", 3, 300);
    fuzz_bin("gltf_fuzz_mutations", 4, 400);
}
