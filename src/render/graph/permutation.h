/* Shader permutations as keys (bits and small integers), not strings: a pass's permute step sets
 * the switches of each of its programs in a tl__perm; the #define text is generated from the key
 * once, where a program is built (programs.c) and for the public plan (tl_plan_program.defines),
 * into buffers sized by the longest text the lists below can make (TL__PERM_TEXT_MAX), so no switch
 * can be dropped. A value past its field is refused naming the switch (tl__perm_check). Adding a
 * switch is one line here and its use in the shaders. */
#ifndef TL_RENDER_PERMUTATION_H
#define TL_RENDER_PERMUTATION_H

#include <stddef.h>
#include <stdint.h>

/* Switches defined or not: TL_<NAME>. */
#define TL__FLAG_LIST(X)                                                                          \
    X(SPECULAR_NONE) X(SPECULAR_EXACT) X(SPECULAR_COMPACT) X(GGX) X(FRESNEL_SUMS) X(FRESNEL_NV)   \
    X(SHADOWS) X(PCSS) X(RT0_RGBA8) X(RT0_RGB10A2) X(HAS_UV) X(NORMAL_MAP) X(MR_TEXTURE)          \
    X(EMISSIVE_TEXTURE) X(OCCLUSION) X(ALPHA_MASK) X(VCOLOR) X(UV1) X(MATERIAL_MODELS)            \
    X(COAT_SUMS) X(IBL) X(DEPTH_ONLY) X(AO_STORE) X(NO_LIGHTS) X(STIPPLE) X(MSAA_LIGHT)           \
    X(RELIGHT_TILES) X(DEPTH_FLOAT) X(FORWARD) X(FORWARD_TILED) X(TRANSPARENT) X(SSAO_AMBIENT)    \
    X(SSAO_DIFFUSE) X(LIGHT_ACCUM) X(LIGHT_SHADE_THIN) X(LIGHT_SHADE_FAT) X(LIGHT_FULLSCREEN)     \
    X(MSAA_SAMPLE) X(CULL_DEPTH_MSAA) X(CULL_NO_PAIRS) X(CLASSIFY_RT1) X(CLASSIFY_FAT) X(FOG_DISTANCE)            \
    X(FOG_HEIGHT) X(FOG_NOISE) X(BLOOM) X(BLOOM_PREFILTER) X(BLOOM_DOWN) X(BLOOM_UP) X(FXAA_FINE) \
    X(SHADOW_DEBUG) X(SHADOW_DEBUG_FAT) X(SHADOW_DEBUG_DEPTH_NORMALS) X(SKY_ENV) X(SSAO_FAT)      \
    X(SSAO_DEPTH_NORMALS) X(SSAO_DISC) X(SSAO_HEMISPHERE) X(DEPTH_UNORM24) X(VIGNETTE_FACTOR)

/* Switches with a value: TL_<NAME>=<value>, the value a number, or with a list of texts the text
 * the value indexes (permutation.c). */
#define TL__VALUE_LIST(X)                                                                         \
    X(UPSAMPLE) X(LIGHT_SHIFT) X(LIGHT_SAMPLES) X(GBUFFER_SAMPLES) X(DEPTH_SAMPLES) X(MSAA_SAMPLES) \
    X(MODEL) X(LIGHT_TYPE) X(SSAO_SAMPLES) X(SSAO_BLUR_RADIUS) X(SSR_STEPS) X(SSR_REFINE)        \
    X(DOF_SAMPLES) X(FXAA_STEPS) X(FULLSCREEN_DEPTH) X(LIGHT_IMAGE_FORMAT)

enum {
#define TL__FLAG_ENUM(name) TL__F_##name,
    TL__FLAG_LIST(TL__FLAG_ENUM)
#undef TL__FLAG_ENUM
    TL__FLAG_COUNT
};
enum {
#define TL__VALUE_ENUM(name) TL__V_##name,
    TL__VALUE_LIST(TL__VALUE_ENUM)
#undef TL__VALUE_ENUM
    TL__VALUE_COUNT
};

/* The texts of TL__V_FULLSCREEN_DEPTH (the depth the sky is drawn at) and TL__V_LIGHT_IMAGE_FORMAT
 * (the compute light pass's image format), by value. */
enum { TL__DEPTH_FAR_ONE = 0, TL__DEPTH_FAR_ZERO = 1 };
enum { TL__IMAGE_FORMAT_RGBA16F = 0, TL__IMAGE_FORMAT_R11G11B10F = 1 };

/* The largest value a switch holds. */
#define TL__PERM_VALUE_MAX 65535u

typedef struct tl__perm {
    uint64_t flags[(TL__FLAG_COUNT + 63) / 64];
    uint32_t set;                     /* values set: bit TL__V_* */
    uint32_t value[TL__VALUE_COUNT];  /* each at most TL__PERM_VALUE_MAX (tl__perm_check) */
} tl__perm;

_Static_assert(TL__VALUE_COUNT <= 32, "the value switches fit tl__perm.set");

/* The longest text a key makes: every switch with its largest value, a space after each. */
#define TL__PERM_FLAG_TEXT(name) +sizeof("TL_" #name " ")
#define TL__PERM_VALUE_TEXT(name) +sizeof("TL_" #name "=65535 ")
#define TL__PERM_TEXT_MAX                                                                         \
    (1 TL__FLAG_LIST(TL__PERM_FLAG_TEXT) TL__VALUE_LIST(TL__PERM_VALUE_TEXT) + sizeof("r11f_g11f_b10f"))

/* TL__F_NONE: no switch (a table's empty entry). */
#define TL__F_NONE 0xFFu
static inline void tl__perm_flag(tl__perm *k, unsigned flag)
{
    if (flag < TL__FLAG_COUNT) k->flags[flag / 64] |= (uint64_t)1 << (flag % 64);
}
static inline int tl__perm_has(const tl__perm *k, unsigned flag) { return (k->flags[flag / 64] >> (flag % 64)) & 1u; }
static inline void tl__perm_value(tl__perm *k, unsigned v, uint32_t value)
{
    k->set |= 1u << v;
    k->value[v] = value;
}
/* Every switch of `b` into `k` (a value of b's replaces k's). */
void tl__perm_merge(tl__perm *k, const tl__perm *b);
/* The first switch whose value is past TL__PERM_VALUE_MAX or its texts, written "TL_NAME=value"
 * into why; 1 when there is none. */
int tl__perm_check(const tl__perm *k, char *why, size_t size);
/* The defines, space-separated, in list order; returns the length written (snprintf's). */
size_t tl__perm_format(const tl__perm *k, char *out, size_t size);
/* Each define as its own NUL-terminated string in `buf` (TL__PERM_TEXT_MAX bytes), pointers into
 * it appended to `out`; returns how many. */
size_t tl__perm_split(const tl__perm *k, char *buf, const char **out);

#endif
