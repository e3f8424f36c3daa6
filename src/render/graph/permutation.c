/* Permutation keys into #define text (permutation.h). */
#include <stdio.h>
#include <string.h>

#include "permutation.h"

static const char *const tl__flag_names[TL__FLAG_COUNT] = {
#define TL__FLAG_NAME(name) "TL_" #name,
    TL__FLAG_LIST(TL__FLAG_NAME)
#undef TL__FLAG_NAME
};
static const char *const tl__value_names[TL__VALUE_COUNT] = {
#define TL__VALUE_NAME(name) "TL_" #name,
    TL__VALUE_LIST(TL__VALUE_NAME)
#undef TL__VALUE_NAME
};

/* The texts a value indexes, for the switches that have them (NULL: the value is the number). */
static const char *const tl__far_depths[] = {"1.0", "0.0", NULL};
static const char *const tl__image_formats[] = {"rgba16f", "r11f_g11f_b10f", NULL};
static const char *const *tl__value_texts(unsigned v)
{
    return v == TL__V_FULLSCREEN_DEPTH ? tl__far_depths : v == TL__V_LIGHT_IMAGE_FORMAT ? tl__image_formats : NULL;
}

void tl__perm_merge(tl__perm *k, const tl__perm *b)
{
    for (size_t i = 0; i < sizeof k->flags / sizeof k->flags[0]; i++) k->flags[i] |= b->flags[i];
    for (unsigned v = 0; v < TL__VALUE_COUNT; v++)
        if (b->set & (1u << v)) tl__perm_value(k, v, b->value[v]);
}

int tl__perm_check(const tl__perm *k, char *why, size_t size)
{
    for (unsigned v = 0; v < TL__VALUE_COUNT; v++) {
        if (!(k->set & (1u << v))) continue;
        const char *const *texts = tl__value_texts(v);
        size_t n = 0;
        while (texts && texts[n]) n++;
        if (texts ? k->value[v] < n : k->value[v] <= TL__PERM_VALUE_MAX) continue;
        snprintf(why, size, "%s=%u", tl__value_names[v], (unsigned)k->value[v]);
        return 0;
    }
    return 1;
}

/* One define's text into `out` (at most TL__PERM_TEXT_MAX), its length. */
static size_t tl__perm_one(const tl__perm *k, unsigned i, char *out, size_t size)
{
    if (i < TL__FLAG_COUNT) return tl__perm_has(k, i) ? (size_t)snprintf(out, size, "%s", tl__flag_names[i]) : 0u;
    unsigned v = i - TL__FLAG_COUNT;
    if (!(k->set & (1u << v))) return 0;
    const char *const *texts = tl__value_texts(v);
    if (texts) return (size_t)snprintf(out, size, "%s=%s", tl__value_names[v], texts[k->value[v]]);
    return (size_t)snprintf(out, size, "%s=%u", tl__value_names[v], (unsigned)k->value[v]);
}

size_t tl__perm_format(const tl__perm *k, char *out, size_t size)
{
    size_t len = 0;
    char one[96];
    for (unsigned i = 0; i < TL__FLAG_COUNT + TL__VALUE_COUNT; i++) {
        size_t n = tl__perm_one(k, i, one, sizeof one);
        if (!n) continue;
        if (len + (len ? 1u : 0u) + n < size) snprintf(out + len, size - len, "%s%s", len ? " " : "", one);
        len += (len ? 1u : 0u) + n;
    }
    if (size && len >= size) out[size - 1] = '\0';
    if (size && !len) out[0] = '\0';
    return len;
}

size_t tl__perm_split(const tl__perm *k, char *buf, const char **out)
{
    size_t count = 0, at = 0;
    for (unsigned i = 0; i < TL__FLAG_COUNT + TL__VALUE_COUNT; i++) {
        size_t n = tl__perm_one(k, i, buf + at, TL__PERM_TEXT_MAX - at);
        if (!n) continue;
        out[count++] = buf + at;
        at += n + 1;
    }
    return count;
}
