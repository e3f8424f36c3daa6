/* tl_option_parse (thinlight/options.h): text into one field of tl_renderer_options, checked
 * against the field's row as tl_renderer_set_options checks it. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "option_check.h"

static int tl__digit(char c) { return c >= '0' && c <= '9'; }

/* [-]digits[.digits][e[+|-]digits] up to `end`, with digits on one side of the point at least. */
static int tl__number_syntax(const char *p, const char *end)
{
    int digits = 0;
    if (p < end && *p == '-') p++;
    for (; p < end && tl__digit(*p); p++) digits++;
    if (p < end && *p == '.')
        for (p++; p < end && tl__digit(*p); p++) digits++;
    if (!digits) return 0;
    if (p < end && (*p == 'e' || *p == 'E')) {
        p++;
        if (p < end && (*p == '+' || *p == '-')) p++;
        if (p == end || !tl__digit(*p)) return 0;
        while (p < end && tl__digit(*p)) p++;
    }
    return p == end;
}

/* The number in s .. end (overflow gives +-inf, which no range holds); 0 when it is not one. */
static int tl__number(const char *s, const char *end, double *out)
{
    char buf[64];
    size_t n = (size_t)(end - s);
    if (!tl__number_syntax(s, end) || n >= sizeof buf) return 0;
    memcpy(buf, s, n);
    buf[n] = '\0';
    errno = 0;
    *out = strtod(buf, NULL);
    return 1;
}

/* An enum's or switch's value named `text` (as tl_X_from_name), or a number; -1: neither. */
static int tl__named(const tl_option_info *i, const char *text, double *v)
{
    for (uint32_t k = 1; k <= i->count; k++)
        if (strcmp(i->value_name(k % i->count), text) == 0) {
            *v = k % i->count;
            return 1;
        }
    return tl__number(text, text + strlen(text), v) ? 1 : -1;
}

/* Target names (tl_target_name) separated by commas, "all" or "none". */
static int tl__targets(const tl_option_info *i, const char *text, double *v)
{
    if (strcmp(text, "all") == 0) return *v = -1.0, 1; /* TL_TARGETS_ALL (tl__set) */
    if (strcmp(text, "none") == 0) return *v = 0.0, 1;
    tl_target_set bits = 0;
    for (const char *p = text;;) {
        size_t n = strcspn(p, ",");
        uint32_t t = 0;
        while (t < i->count && (strlen(i->value_name(t)) != n || strncmp(i->value_name(t), p, n) != 0)) t++;
        if (t == i->count || t >= 64u) return 0;
        bits |= TL_TARGET_BIT(t);
        if (!p[n]) break;
        p += n + 1;
    }
    *v = (double)bits; /* exact: fewer than 53 targets */
    return 1;
}

/* What the text must be, for the refusal of text that is not a value. */
static const char *tl__wants(const tl_option_info *i)
{
    switch (i->type) {
    case TL_OPTION_ENUM:
    case TL_OPTION_SWITCH: return "a value's name";
    case TL_OPTION_TARGETS: return "target names separated by commas, all or none";
    case TL_OPTION_FLOAT: return "a number";
    case TL_OPTION_FLOAT3: return "three numbers R,G,B";
    default: return "a whole number";
    }
}

/* Each component's value from the text: the count read, or 0 when the text is not such a value. */
static size_t tl__values(const tl_option_info *i, const char *text, double v[3])
{
    if (i->type == TL_OPTION_ENUM || i->type == TL_OPTION_SWITCH) return tl__named(i, text, v) == 1;
    if (i->type == TL_OPTION_TARGETS) return (size_t)tl__targets(i, text, v);
    size_t want = i->type == TL_OPTION_FLOAT3 ? 3u : 1u, n = 0;
    for (const char *p = text; n < want; n++) {
        const char *end = p + strcspn(p, ",");
        if (!tl__number(p, end, &v[n])) return 0;
        if (!*end) return n + 1 == want ? want : 0;
        p = end + 1;
    }
    return 0;
}

tl_result tl_option_parse(const tl_option_info *i, const char *text, tl_renderer_options *options,
                          const tl_logger *logger)
{
    if (!i || !text || !options)
        return tl__logger_fail(logger, TL_ERROR_INVALID_ARGUMENT, "tl_option_parse: NULL %s",
                               !i ? "option" : !text ? "text" : "options");
    double v[3] = {0.0, 0.0, 0.0};
    size_t n = tl__values(i, text, v);
    if (!n) return tl__logger_fail(logger, TL_ERROR_INVALID_ARGUMENT, "options.%s = '%s': not %s", i->name, text, tl__wants(i));
    tl_renderer_options o = *options;
    char *at = (char *)&o + i->offset;
    for (size_t k = 0; k < n; k++) {
        if (!tl_option_value_valid(i, v[k])) {
            char range[160];
            tl_option_range_format(i, range, sizeof range);
            return tl__logger_fail(logger, TL_ERROR_INVALID_ARGUMENT, "options.%s = %s is out of range (%s)", i->name,
                                   text, range);
        }
        if (i->type == TL_OPTION_FLOAT || i->type == TL_OPTION_FLOAT3) {
            float f = (float)v[k];
            memcpy(at + k * sizeof f, &f, sizeof f);
        } else if (i->type == TL_OPTION_TARGETS) {
            tl_target_set t = v[k] < 0.0 ? TL_TARGETS_ALL : (tl_target_set)v[k];
            memcpy(at, &t, sizeof t);
        } else if (i->type == TL_OPTION_UINT) {
            uint32_t u = (uint32_t)v[k];
            memcpy(at, &u, sizeof u);
        } else {
            int e = (int)v[k];
            memcpy(at, &e, sizeof e);
        }
    }
    *options = o;
    return TL_OK;
}
