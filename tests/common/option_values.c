/* Values of the option registry's fields (option_values.h). */
#include "option_values.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static void add(double *out, size_t max, size_t *n, double v)
{
    if (*n < max) out[(*n)++] = v;
}

size_t tl_test_option_bad_values(const tl_option_info *o, double *out, size_t max)
{
    size_t n = 0;
    int pow2 = (o->flags & TL_OPTION_POW2) != 0, neg_zero = (o->flags & TL_OPTION_NEGATIVE_ZERO) != 0;
    switch (o->type) {
    case TL_OPTION_TARGETS: return 0;
    case TL_OPTION_BOOL:
    case TL_OPTION_ENUM:
    case TL_OPTION_SWITCH:
        add(out, max, &n, o->max + 1.0);
        add(out, max, &n, -1.0);
        return n;
    case TL_OPTION_UINT:
        add(out, max, &n, o->max + 1.0);
        if (o->min > 1.0) add(out, max, &n, o->min - 1.0);
        if (pow2 && o->min * 3.0 <= o->max) add(out, max, &n, o->min * 3.0);
        return n;
    default: /* FLOAT, FLOAT3 */
        add(out, max, &n, NAN);
        add(out, max, &n, INFINITY);
        if (o->max < FLT_MAX) add(out, max, &n, (o->flags & TL_OPTION_MAX_OPEN) ? o->max : o->max * 2.0 + 1.0);
        if (o->min > -FLT_MAX && !neg_zero && o->min != 1.0) add(out, max, &n, o->min - 1.0);
        if (pow2) add(out, max, &n, o->min * 1.5);
        return n;
    }
}

double tl_test_option_good_value(const tl_option_info *o)
{
    switch (o->type) {
    case TL_OPTION_BOOL: return 1.0;
    case TL_OPTION_ENUM:
    case TL_OPTION_SWITCH: return o->max;
    case TL_OPTION_TARGETS: return (double)(TL_TARGET_BIT(TL_TARGET_DEPTH) | TL_TARGET_BIT(TL_TARGET_HDR));
    default: break;
    }
    if (o->max < FLT_MAX) {
        double v = (o->flags & TL_OPTION_MAX_OPEN) ? (o->min + o->max) / 2.0 : o->max;
        return v == o->zero && !o->zero_text && tl_option_value_valid(o, o->min) && o->min != 0.0 ? o->min : v;
    }
    return (o->min > -FLT_MAX ? o->min : 0.0) + (o->type == TL_OPTION_UINT ? 2.0 : 2.5);
}

void tl_test_option_good_text(const tl_option_info *o, char *out, size_t size)
{
    double v = tl_test_option_good_value(o);
    switch (o->type) {
    case TL_OPTION_ENUM:
    case TL_OPTION_SWITCH: snprintf(out, size, "%s", o->value_name((uint32_t)v)); break;
    case TL_OPTION_TARGETS:
        snprintf(out, size, "%s,%s", o->value_name(TL_TARGET_DEPTH), o->value_name(TL_TARGET_HDR));
        break;
    case TL_OPTION_FLOAT: snprintf(out, size, "%.9g", v); break;
    case TL_OPTION_FLOAT3: snprintf(out, size, "%.9g,%.9g,%.9g", v, v, v); break;
    default: snprintf(out, size, "%.0f", v); break;
    }
}

void tl_test_option_enable_group(const tl_option_info *field, tl_renderer_options *o)
{
    const char *dot = strchr(field->name, '.');
    if (!dot) return;
    char name[64];
    snprintf(name, sizeof name, "%.*s.enabled", (int)(dot - field->name), field->name);
    const tl_option_info *g = tl_option_find(name);
    int on = 1;
    if (g && g != field && g->type == TL_OPTION_BOOL) memcpy((char *)o + g->offset, &on, sizeof on);
}

void tl_error_capture_log(void *user, tl_log_level level, const char *message)
{
    tl_error_capture *s = (tl_error_capture *)user;
    if (level != TL_LOG_ERROR) return;
    s->errors++;
    snprintf(s->last, sizeof s->last, "%s", message);
}
