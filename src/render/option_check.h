/* The renderer options' range checks (desc.c for the frame's options, each pass's resolve for its
 * own slice, the shadow atlas's): a table of fields per struct, and the first field outside its
 * range made one message naming the field, its value and the range, e.g.
 * "options.ssr.refine = 9 is out of range (1..8; 0: 4)". */
#ifndef TL_RENDER_OPTION_CHECK_H
#define TL_RENDER_OPTION_CHECK_H

#include <stddef.h>
#include <stdint.h>

#include "core/log.h"

/* Why options were refused: one line naming the field, its value and what it may be. */
typedef struct tl__why {
    char text[256];
} tl__why;

typedef struct tl__option_range {
    int bad;           /* the value is outside its range */
    const char *field; /* below the struct: "refine", "color[1]"; NULL: the option itself */
    double value;
    int integer;       /* 1: printed as an integer, 0: as %g */
    const char *range; /* what it may be: "1..8; 0: 4", "finite"; with `count`, the enum's name */
    uint32_t count;    /* an enum of `count` values: the range is 0..count - 1 */
} tl__option_range;

/* A row for an unsigned or enum field, a float field, and an enum field of `count` values. */
#define TL__RANGE_INT(bad, field, value, range) {(bad), (field), (double)(value), 1, (range), 0u}
#define TL__RANGE_FLOAT(bad, field, value, range) {(bad), (field), (double)(value), 0, (range), 0u}
#define TL__RANGE_ENUM(field, value, count, type)                                                    \
    {(unsigned)(value) >= (unsigned)(count), (field), (double)(int)(value), 1, (type), (uint32_t)(count)}

/* 1 when no row is bad; otherwise 0 with the first bad row in `why` (may be NULL) as
 * "PREFIX.FIELD = VALUE is out of range (RANGE)". */
int tl__option_ranges(const tl__option_range *rows, size_t count, const char *prefix, tl__why *why);
/* Writes a message of its own into `why` (may be NULL); returns 0, a refusal. */
int tl__why_say(tl__why *why, const char *fmt, ...) TL__PRINTF_LIKE(2, 3);

#endif
