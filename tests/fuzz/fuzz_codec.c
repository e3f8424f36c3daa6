/* libFuzzer target: the codec's batch and chroma functions (include/thinlight/codec.h) with
 * arbitrary sizes, bit budgets, enum values and float bit patterns (NaN, Inf, denormals, -0).
 * The first byte picks a function family; the next bytes give its parameters; the rest are the
 * values. Properties from the header's contract: no NaN or Inf out of any function (except
 * tl_half_to_float, which returns what is stored), unit vectors out of every decoder, values in
 * their documented ranges, and batch results bit-identical to the scalar ones. */
#include <math.h>
#include <string.h>

#include "fuzz_common.h"
#include "thinlight/codec.h"

#define FUZZ_MAX_COUNT 4096u
#define FUZZ_MAX_SIDE 64u

/* The input as a stream; past its end it reads zeros. */
typedef struct reader {
    const uint8_t *p;
    size_t n;
} reader;

static uint32_t read_u32(reader *r)
{
    uint32_t v = 0;
    for (int i = 0; i < 4; i++) {
        v |= (uint32_t)(r->n ? *r->p : 0) << (8 * i);
        if (r->n) {
            r->p++;
            r->n--;
        }
    }
    return v;
}

static float read_f32(reader *r)
{
    uint32_t u = read_u32(r);
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/* Static buffers: the targets run one input at a time, and nothing here may allocate. */
static float fin[FUZZ_MAX_COUNT * 3], fout[FUZZ_MAX_COUNT * 3], fout2[FUZZ_MAX_COUNT * 3], gl[FUZZ_MAX_COUNT];
static uint32_t codes[FUZZ_MAX_COUNT], codes2[FUZZ_MAX_COUNT];
static uint8_t texels[FUZZ_MAX_COUNT * 4];
static uint16_t halves[FUZZ_MAX_COUNT];

static size_t count_of(reader *r) { return read_u32(r) % (FUZZ_MAX_COUNT + 1); }

static void require_unit(const float *n)
{
    FUZZ_REQUIRE(isfinite(n[0]) && isfinite(n[1]) && isfinite(n[2]));
    float l = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    FUZZ_REQUIRE(fabsf(l - 1.0f) < 1e-3f);
}

static void fill_floats(reader *r, size_t count)
{
    for (size_t i = 0; i < count; i++) fin[i] = read_f32(r);
}

static void oct_family(reader *r)
{
    uint32_t bits = read_u32(r);
    size_t count = count_of(r);
    fill_floats(r, 3 * count);
    tl_oct_encode_n(fin, codes, count, bits);
    tl_oct_encode_precise_n(fin, codes2, count, bits);
    for (size_t i = 0; i < count; i++) {
        FUZZ_REQUIRE(codes[i] == tl_oct_encode(fin + 3 * i, bits));
        FUZZ_REQUIRE(codes2[i] == tl_oct_encode_precise(fin + 3 * i, bits));
        codes2[i] ^= read_u32(r); /* arbitrary codes too */
    }
    tl_oct_decode_n(codes2, fout, count, bits);
    for (size_t i = 0; i < count; i++) {
        float n[3];
        tl_oct_decode(codes2[i], bits, n);
        FUZZ_REQUIRE(memcmp(n, fout + 3 * i, sizeof n) == 0);
        require_unit(n);
    }
}

static void normal_family(reader *r)
{
    tl_normal_encoding enc = (tl_normal_encoding)read_u32(r);
    uint32_t bits = read_u32(r);
    size_t count = count_of(r);
    fill_floats(r, 3 * count);
    tl_normal_encode_n(enc, fin, codes, count, bits);
    for (size_t i = 0; i < count; i++) {
        FUZZ_REQUIRE(codes[i] == tl_normal_encode(enc, fin + 3 * i, bits));
        codes[i] ^= read_u32(r);
    }
    tl_normal_decode_n(enc, codes, fout, count, bits);
    for (size_t i = 0; i < count; i++) {
        float n[3];
        tl_normal_decode(enc, codes[i], bits, n);
        FUZZ_REQUIRE(memcmp(n, fout + 3 * i, sizeof n) == 0);
        require_unit(n);
    }
    FUZZ_REQUIRE(tl_normal_encoding_name(enc) != NULL);
}

static void rt0_family(reader *r)
{
    size_t count = count_of(r);
    fill_floats(r, 3 * count);
    for (size_t i = 0; i < count; i++) gl[i] = read_f32(r);
    tl_rt0_encode_rgba8_n(fin, gl, texels, count);
    for (size_t i = 0; i < count; i++) {
        uint8_t t[4];
        tl_rt0_encode_rgba8(fin + 3 * i, gl[i], t);
        FUZZ_REQUIRE(memcmp(t, texels + 4 * i, 4) == 0);
        texels[4 * i] ^= (uint8_t)read_u32(r);
    }
    tl_rt0_decode_rgba8_n(texels, fout, gl, count);
    for (size_t i = 0; i < count; i++) {
        float n[3], g;
        tl_rt0_decode_rgba8(texels + 4 * i, n, &g);
        FUZZ_REQUIRE(memcmp(n, fout + 3 * i, sizeof n) == 0 && memcmp(&g, gl + i, sizeof g) == 0);
        require_unit(n);
        FUZZ_REQUIRE(g >= 0.0f && g <= 1.0f);
        uint32_t flags = 0, texel = read_u32(r);
        tl_rt0_decode_rgb10a2(texel, n, &g, &flags);
        require_unit(n);
        FUZZ_REQUIRE(g >= 0.0f && g <= 1.0f && flags <= 3);
        uint32_t want = read_u32(r);
        tl_rt0_decode_rgb10a2(tl_rt0_encode_rgb10a2(fin + 3 * i, gl[i], want), n, &g, &flags);
        require_unit(n);
        FUZZ_REQUIRE(flags == (want & 3u));
    }
}

/* Luma/chroma: the whole image path with arbitrary sizes, spaces, filters and values. */
static void chroma_family(reader *r)
{
    tl_color_space space = (tl_color_space)read_u32(r);
    tl_chroma_filter filter = (tl_chroma_filter)read_u32(r);
    uint32_t w = read_u32(r) % (FUZZ_MAX_SIDE + 1), h = read_u32(r) % (FUZZ_MAX_SIDE + 1);
    size_t n = (size_t)w * h;
    fill_floats(r, 3 * n);
    tl_result er = tl_albedo_encode_image(space, fin, w, h, texels);
    FUZZ_REQUIRE(er == TL_OK || er == TL_ERROR_INVALID_ARGUMENT);
    if (er != TL_OK) {
        FUZZ_REQUIRE(n == 0);
        return;
    }
    for (size_t i = 0; i < 2 * n; i++) texels[i] ^= (uint8_t)(read_u32(r) & 0xFF);
    tl_result rr = tl_albedo_reconstruct(space, filter, texels, w, h, fout);
    if (rr == TL_OK) {
        for (size_t i = 0; i < 3 * n; i++) FUZZ_REQUIRE(fout[i] >= 0.0f && fout[i] <= 1.0f);
    } else {
        FUZZ_REQUIRE(rr == TL_ERROR_INVALID_ARGUMENT);
    }
    /* any pixel, any coordinate (outside the image too), any filter */
    for (int k = 0; k < 8; k++) {
        uint32_t x = read_u32(r), y = read_u32(r);
        float c = tl_albedo_missing_chroma(filter, texels, w, h, x % (w + 2), y % (h + 2));
        FUZZ_REQUIRE(c >= 0.0f && c <= 1.0f);
        float rgb[3] = {read_f32(r), read_f32(r), read_f32(r)}, ycc[3], back[3];
        tl_rgb_to_luma_chroma(space, rgb, ycc);
        tl_luma_chroma_to_rgb(space, ycc, back);
        for (int i = 0; i < 3; i++) FUZZ_REQUIRE(ycc[i] >= 0.0f && ycc[i] <= 1.0f && back[i] >= 0.0f && back[i] <= 1.0f);
        uint8_t px[2];
        tl_albedo_encode_pixel(space, rgb, x, y, px);
    }
    FUZZ_REQUIRE(tl_color_space_name(space) != NULL && tl_chroma_filter_name(filter) != NULL);
}

static void depth_family(reader *r)
{
    tl_depth_format format = (tl_depth_format)read_u32(r);
    float fov = read_f32(r), aspect = read_f32(r), near_z = read_f32(r), far_z = read_f32(r);
    size_t count = count_of(r);
    fill_floats(r, 3 * count);
    tl_depth_encode_d24_n(fin, codes, count);
    for (size_t i = 0; i < count; i++) {
        FUZZ_REQUIRE(codes[i] == tl_depth_encode_d24(fin[i]) && codes[i] <= 0xFFFFFFu);
        codes[i] ^= read_u32(r);
    }
    tl_depth_decode_d24_n(codes, fout, count);
    for (size_t i = 0; i < count; i++) FUZZ_REQUIRE(fout[i] >= 0.0f && fout[i] <= 1.0f);
    tl_projection proj;
    tl_result pr = tl_projection_perspective(format, fov, aspect, near_z, far_z, &proj);
    FUZZ_REQUIRE(pr == TL_OK || pr == TL_ERROR_INVALID_ARGUMENT);
    if (pr != TL_OK) return;
    /* depths from the stream, in [0, 1] as the depth buffer holds them */
    for (size_t i = 0; i < count; i++) gl[i] = tl_depth_quantize(format, fout[i]);
    tl_view_position_from_depth_n(&proj, fin, gl, fout2, count / 2);
    for (size_t i = 0; i < count / 2; i++) {
        float p[3];
        tl_view_position_from_depth(&proj, fin[2 * i], fin[2 * i + 1], gl[i], p);
        FUZZ_REQUIRE(memcmp(p, fout2 + 3 * i, sizeof p) == 0);
        float d = tl_depth_window_from_distance(&proj, fin[i]);
        FUZZ_REQUIRE(d >= 0.0f && d <= 1.0f);
        FUZZ_REQUIRE(isfinite(tl_depth_linearize(&proj, gl[i])));
    }
}

static void half_family(reader *r)
{
    size_t count = count_of(r);
    fill_floats(r, count);
    tl_half_from_float_n(fin, halves, count);
    for (size_t i = 0; i < count; i++) {
        FUZZ_REQUIRE(halves[i] == tl_half_from_float(fin[i]));
        FUZZ_REQUIRE(isfinite(tl_half_to_float(halves[i]))); /* saturating: never Inf or NaN */
        halves[i] ^= (uint16_t)read_u32(r);
    }
    tl_half_to_float_n(halves, fout, count);
    for (size_t i = 0; i < count; i++) {
        float f = tl_half_to_float(halves[i]);
        FUZZ_REQUIRE(memcmp(&f, fout + i, sizeof f) == 0);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    reader r = {data + 1, size - 1};
    switch (data[0] % 6) {
    case 0: oct_family(&r); break;
    case 1: normal_family(&r); break;
    case 2: rt0_family(&r); break;
    case 3: chroma_family(&r); break;
    case 4: depth_family(&r); break;
    default: half_family(&r); break;
    }
    return 0;
}
