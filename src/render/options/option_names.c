/* The names of every option enum, from their one list (option_check.h, TL__OPTION_ENUMS): for each,
 * the public tl_X_name and tl_X_from_name and the registry's value_name. */
#include <string.h>

#include "option_check.h"

/* A name's value: the first value from 1 that has it (DEFAULT shares the name of the value it stands
 * for), else 0 when DEFAULT has a name of its own ("auto"); -1 for none. */
static int tl__enum_find(const char *const *names, int count, const char *name)
{
    if (!name) return -1;
    for (int i = 1; i < count; i++)
        if (strcmp(names[i], name) == 0) return i;
    return strcmp(names[0], name) == 0 ? 0 : -1;
}

#define TL__ENUM_NAMES(type, short_, count, ...)                                                                 \
    static const char *const tl__names_##type[] = {__VA_ARGS__};                                                 \
    _Static_assert(sizeof tl__names_##type / sizeof tl__names_##type[0] == (count), #type ": a name per value"); \
    const char *tl_##short_##_name(type value)                                                                   \
    {                                                                                                             \
        return (unsigned)value < (unsigned)(count) ? tl__names_##type[value] : "unknown";                         \
    }                                                                                                             \
    tl_result tl_##short_##_from_name(const char *name, type *value)                                              \
    {                                                                                                             \
        int i = tl__enum_find(tl__names_##type, (int)(count), name);                                             \
        if (i < 0 || !value) return TL_ERROR_INVALID_ARGUMENT;                                                    \
        *value = (type)i;                                                                                         \
        return TL_OK;                                                                                             \
    }                                                                                                             \
    const char *tl__value_name_##type(uint32_t value) { return tl_##short_##_name((type)value); }

TL__OPTION_ENUMS(TL__ENUM_NAMES)

const char *tl__value_name_tl_depth_format(uint32_t value) { return tl_depth_format_name((tl_depth_format)value); }
const char *tl__value_name_tl_target_id(uint32_t value) { return tl_target_name((tl_target_id)value); }
