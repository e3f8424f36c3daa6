/* Values of the option registry's fields (thinlight/options.h) for the tests that walk it: values
 * each field must refuse and one it must take, derived from its row (type, min, max, flags), so a
 * field added to the registry is tested with no line written for it. */
#ifndef TL_TEST_OPTION_VALUES_H
#define TL_TEST_OPTION_VALUES_H

#include <stddef.h>

#include "thinlight/options.h"

/* Up to `max` values the field must refuse (outside its range; NaN and infinities for floats; a
 * value between the powers of two of a POW2 field); returns how many. TL_OPTION_TARGETS takes
 * every value: none. */
size_t tl_test_option_bad_values(const tl_option_info *o, double *out, size_t max);
/* A value in range, not zero and not the default where the range allows (the largest, or one
 * above the least for unbounded fields, or an enum's last value). */
double tl_test_option_good_value(const tl_option_info *o);
/* The same as text tl_option_parse and the tools read: a name, a number, "V,V,V", target names. */
void tl_test_option_good_text(const tl_option_info *o, char *out, size_t size);
/* `o` with the effect the field sits in switched on (its `enabled`; not the field itself), so that
 * the field is looked at. */
void tl_test_option_enable_group(const tl_option_info *field, tl_renderer_options *o);

/* The renderer's error lines as a logger sees them (tl_logger {tl_error_capture_log, &capture}):
 * how many, and the last one, for a test that checks a refusal's words. */
typedef struct tl_error_capture {
    int errors;
    char last[512];
} tl_error_capture;
void tl_error_capture_log(void *user, tl_log_level level, const char *message);

#endif
