/* option_check.h: the first field out of range, as one line. */
#include "option_check.h"

#include <stdarg.h>
#include <stdio.h>

int tl__why_say(tl__why *why, const char *fmt, ...)
{
    if (!why) return 0;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why->text, sizeof why->text, fmt, ap);
    va_end(ap);
    return 0;
}

int tl__option_ranges(const tl__option_range *rows, size_t count, const char *prefix, tl__why *why)
{
    for (size_t i = 0; i < count; i++) {
        const tl__option_range *r = &rows[i];
        if (!r->bad) continue;
        char value[48];
        if (r->integer) snprintf(value, sizeof value, "%.0f", r->value);
        else snprintf(value, sizeof value, "%g", r->value);
        const char *dot = r->field ? "." : "", *field = r->field ? r->field : "";
        if (r->count)
            return tl__why_say(why, "%s%s%s = %s is out of range (0..%u, a %s)", prefix, dot, field, value,
                               (unsigned)r->count - 1u, r->range);
        return tl__why_say(why, "%s%s%s = %s is out of range (%s)", prefix, dot, field, value, r->range);
    }
    return 1;
}
