/* The registry's ranges at work (option_check.h): the check every set of options passes, the
 * defaults of every field whose default is one value, and tl_option_parse / format / range_format. */
#include "option_check.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

_Static_assert(sizeof(tl_render_mode) == sizeof(int) && sizeof(tl_switch) == sizeof(int), "enum fields are ints");

int tl__why_say(tl__why *why, const char *fmt, ...)
{
    if (!why) return 0;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why->text, sizeof why->text, fmt, ap);
    va_end(ap);
    return 0;
}

/* ---- values ----------------------------------------------------------------------------------- */

static int tl__integer_type(tl_option_type t) { return t != TL_OPTION_FLOAT && t != TL_OPTION_FLOAT3; }
static size_t tl__components(const tl_option_info *i) { return i->type == TL_OPTION_FLOAT3 ? 3u : 1u; }

/* Component k of the field as a double (a target set: its bits, exact below 2^53, and -1 for
 * TL_TARGETS_ALL). */
static double tl__get(const tl_option_info *i, const tl_renderer_options *o, size_t k)
{
    const char *at = (const char *)o + i->offset;
    int n;
    uint32_t u;
    tl_target_set t;
    float f;
    switch (i->type) {
    case TL_OPTION_BOOL:
    case TL_OPTION_SWITCH:
    case TL_OPTION_ENUM: memcpy(&n, at, sizeof n); return n;
    case TL_OPTION_UINT: memcpy(&u, at, sizeof u); return u;
    case TL_OPTION_TARGETS: memcpy(&t, at, sizeof t); return t == TL_TARGETS_ALL ? -1.0 : (double)t;
    default: memcpy(&f, at + k * sizeof f, sizeof f); return f;
    }
}

static void tl__set(const tl_option_info *i, tl_renderer_options *o, size_t k, double v)
{
    char *at = (char *)o + i->offset;
    int n = (int)v;
    uint32_t u = (uint32_t)v;
    tl_target_set t = v < 0.0 ? TL_TARGETS_ALL : (tl_target_set)v;
    float f = (float)v;
    if (i->type == TL_OPTION_BOOL || i->type == TL_OPTION_SWITCH || i->type == TL_OPTION_ENUM) memcpy(at, &n, sizeof n);
    else if (i->type == TL_OPTION_UINT) memcpy(at, &u, sizeof u);
    else if (i->type == TL_OPTION_TARGETS) memcpy(at, &t, sizeof t);
    else memcpy(at + k * sizeof f, &f, sizeof f);
}

static int tl__pow2(double v)
{
    int e;
    return v > 0.0 && frexp(v, &e) == 0.5;
}

int tl_option_value_valid(const tl_option_info *i, double v)
{
    if (!i || isnan(v)) return 0;
    if (tl__integer_type(i->type) && v != floor(v)) return 0;
    if (i->type == TL_OPTION_TARGETS) return v == -1.0 || (v >= 0.0 && v < ldexp(1.0, TL_TARGET_COUNT));
    double lo = i->min, hi = i->max;
    if (!tl__integer_type(i->type)) /* as the float field holds them: 0.2f is in (0, 0.2] */
        v = (double)(float)v, lo = (double)(float)lo, hi = (double)(float)hi;
    if (v == 0.0) return 1; /* the default */
    if (v < 0.0 && (i->flags & TL_OPTION_NEGATIVE_ZERO) && isfinite(v)) return 1;
    if (!isfinite(v) || v < lo || v > hi) return 0;
    if ((i->flags & TL_OPTION_MIN_OPEN) && v == lo) return 0;
    if ((i->flags & TL_OPTION_MAX_OPEN) && v == hi) return 0;
    return !(i->flags & TL_OPTION_POW2) || tl__pow2(v);
}

/* ---- the check and the defaults ------------------------------------------------------------ */

/* "options.NAME[K] = VALUE is out of range (RANGE)" for the row's first component out of range. */
static int tl__row_check(const tl_option_info *i, const tl_renderer_options *o, tl__why *why)
{
    for (size_t k = 0; k < tl__components(i); k++) {
        double v = tl__get(i, o, k);
        if (tl_option_value_valid(i, v)) continue;
        char range[160], index[8] = "";
        tl_option_range_format(i, range, sizeof range);
        if (i->type == TL_OPTION_FLOAT3) snprintf(index, sizeof index, "[%zu]", k);
        if (tl__integer_type(i->type)) return tl__why_say(why, "options.%s%s = %.0f is out of range (%s)", i->name, index, v, range);
        return tl__why_say(why, "options.%s%s = %g is out of range (%s)", i->name, index, v, range);
    }
    return 1;
}

/* Whether row i is an effect's `enabled` ("ssr.enabled"); its struct's prefix length in *n. */
static int tl__enabled_row(const tl_option_info *i, size_t *n)
{
    const char *dot = strchr(i->name, '.');
    if (i->type != TL_OPTION_BOOL || !dot || strcmp(dot, ".enabled") != 0) return 0;
    *n = (size_t)(dot - i->name) + 1u;
    return 1;
}

int tl__options_check(const tl_renderer_options *o, tl__why *why)
{
    const tl_option_info *i, *off = NULL; /* the `enabled` row of an effect that is off */
    size_t prefix = 0;
    for (size_t n = 0; (i = tl_option_at(n)) != NULL; n++) {
        /* a struct's rows follow its `enabled`: skipped while it is 0 */
        if (off && strncmp(i->name, off->name, prefix) == 0) continue;
        off = NULL;
        if (!tl__row_check(i, o, why)) return 0;
        if (tl__enabled_row(i, &prefix) && tl__get(i, o, 0) == 0.0) off = i;
    }
    return 1;
}

void tl__options_defaults(tl_renderer_options *o)
{
    const tl_option_info *i;
    for (size_t n = 0; (i = tl_option_at(n)) != NULL; n++) {
        if (i->zero_text || i->type == TL_OPTION_TARGETS) continue;
        for (size_t k = 0; k < tl__components(i); k++) {
            double v = tl__get(i, o, k);
            if (v == 0.0 && i->zero != 0.0) tl__set(i, o, k, i->zero);
            else if (v < 0.0 && (i->flags & TL_OPTION_NEGATIVE_ZERO)) tl__set(i, o, k, 0.0);
        }
    }
}

/* ---- text ------------------------------------------------------------------------------------- */

/* Appends to buf[*at ..]; *at grows by what it would have written (snprintf's count). */
static void tl__add(char *buf, size_t size, size_t *at, const char *fmt, ...) TL__PRINTF_LIKE(4, 5);
static void tl__add(char *buf, size_t size, size_t *at, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(buf && *at < size ? buf + *at : NULL, buf && *at < size ? size - *at : 0, fmt, ap);
    va_end(ap);
    if (n > 0) *at += (size_t)n;
}

/* Whether 0 is a value of the range itself (then a zero default needs no mention). */
static int tl__zero_in_range(const tl_option_info *i)
{
    if (i->flags & TL_OPTION_POW2) return 0;
    return (i->min < 0.0 || (i->min == 0.0 && !(i->flags & TL_OPTION_MIN_OPEN))) &&
           (i->max > 0.0 || (i->max == 0.0 && !(i->flags & TL_OPTION_MAX_OPEN)));
}

/* The numbers themselves: a list of the powers of two, or an interval. */
static void tl__range_values(const tl_option_info *i, char *buf, size_t size, size_t *at)
{
    if (i->flags & TL_OPTION_POW2) {
        for (double v = i->min; v <= i->max; v *= 2.0)
            tl__add(buf, size, at, "%s%g", v == i->min ? "" : v * 2.0 > i->max ? " or " : ", ", v);
        return;
    }
    int lo = i->min > -FLT_MAX, hi = i->max < FLT_MAX;
    int lo_open = (i->flags & TL_OPTION_MIN_OPEN) != 0, hi_open = (i->flags & TL_OPTION_MAX_OPEN) != 0;
    if (!lo && !hi) tl__add(buf, size, at, "finite");
    else if (!hi) tl__add(buf, size, at, "%s %g", lo_open ? ">" : ">=", i->min);
    else if (!lo_open && !hi_open) tl__add(buf, size, at, "%g..%g", i->min, i->max);
    else tl__add(buf, size, at, "%c%g, %g%c", lo_open ? '(' : '[', i->min, i->max, hi_open ? ')' : ']');
}

size_t tl_option_range_format(const tl_option_info *i, char *buf, size_t size)
{
    size_t at = 0;
    if (buf && size) buf[0] = '\0';
    if (!i) return 0;
    if (i->type == TL_OPTION_BOOL) tl__add(buf, size, &at, "0 or 1");
    else if (i->type == TL_OPTION_ENUM || i->type == TL_OPTION_SWITCH)
        tl__add(buf, size, &at, "0..%u, a %s", (unsigned)i->count - 1u, i->c_type);
    else if (i->type == TL_OPTION_TARGETS) tl__add(buf, size, &at, "TL_TARGET_BIT bits");
    else {
        tl__range_values(i, buf, size, &at);
        if (i->zero_text) tl__add(buf, size, &at, "; 0: %s", i->zero_text);
        else if (i->zero != 0.0 || !tl__zero_in_range(i)) tl__add(buf, size, &at, "; 0: %g", i->zero);
        if (i->flags & TL_OPTION_NEGATIVE_ZERO) tl__add(buf, size, &at, ", < 0: 0");
    }
    return at;
}

static tl_target_set tl__target_mask(const tl_option_info *i)
{
    return i->count >= 64u ? TL_TARGETS_ALL : (TL_TARGET_BIT(i->count) - 1u);
}

size_t tl_option_format(const tl_option_info *i, const tl_renderer_options *o, char *buf, size_t size)
{
    size_t at = 0;
    if (buf && size) buf[0] = '\0';
    if (!i || !o) return 0;
    double v = tl__get(i, o, 0);
    switch (i->type) {
    case TL_OPTION_ENUM:
    case TL_OPTION_SWITCH: tl__add(buf, size, &at, "%s", i->value_name((uint32_t)v)); break;
    case TL_OPTION_FLOAT: tl__add(buf, size, &at, "%.9g", v); break;
    case TL_OPTION_FLOAT3:
        tl__add(buf, size, &at, "%.9g,%.9g,%.9g", v, tl__get(i, o, 1), tl__get(i, o, 2));
        break;
    case TL_OPTION_TARGETS:
        if (v < 0.0) tl__add(buf, size, &at, "all");
        else if (!((tl_target_set)v & tl__target_mask(i))) tl__add(buf, size, &at, "none");
        for (uint32_t t = 0; v >= 0.0 && t < i->count && t < 64u; t++)
            if ((tl_target_set)v & TL_TARGET_BIT(t)) tl__add(buf, size, &at, "%s%s", at ? "," : "", i->value_name(t));
        break;
    default: tl__add(buf, size, &at, "%.0f", v); break;
    }
    return at;
}
