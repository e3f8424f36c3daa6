/**
 * @file thinlight/options.h
 * @brief The option registry: every field of tl_renderer_options (and of its effect, shadow and
 * environment structs) with its name, type, range, default, unit and one line of help, in one table
 * that the renderer checks options against and that tools, panels and `--help` are generated from
 * (docs/renderer.md, "Options at run time"). renderer.h includes it.
 *
 * @code
 *   tl_renderer_options o = {0};
 *   const tl_option_info *refine = tl_option_find("ssr.refine");
 *   tl_option_parse(refine, "9", &o, &my_logger); // logs "options.ssr.refine = 9 is out of range (1..8; 0: 4)"
 *   for (size_t i = 0; i < tl_option_count(); i++) puts(tl_option_at(i)->name);
 * @endcode
 */
#ifndef THINLIGHT_OPTIONS_H
#define THINLIGHT_OPTIONS_H

#include "thinlight/base.h"
#include "thinlight/renderer.h"

#ifdef __cplusplus
extern "C" {
#endif

/** How a field is stored and what it takes. */
typedef enum tl_option_type {
    TL_OPTION_BOOL,    /**< int, 0 (off: the default) or 1 (on); effects' `enabled` */
    TL_OPTION_SWITCH,  /**< tl_switch: zero is on (the default), TL_SWITCH_OFF turns it off */
    TL_OPTION_ENUM,    /**< an enum (int-sized), 0 .. count - 1, each value named (value_name) */
    TL_OPTION_UINT,    /**< uint32_t */
    TL_OPTION_FLOAT,   /**< float */
    TL_OPTION_FLOAT3,  /**< float[3]: each component in the range */
    TL_OPTION_TARGETS, /**< uint32_t of TL_TARGET_BIT bits (or TL_TARGETS_ALL); every value is valid */
    TL_OPTION_TYPE_COUNT_ /**< number of values */
} tl_option_type;

/** tl_option_info.flags: min itself is outside the range (the value must be above it). */
#define TL_OPTION_MIN_OPEN 1u
/** tl_option_info.flags: max itself is outside the range. */
#define TL_OPTION_MAX_OPEN 2u
/** tl_option_info.flags: only the powers of two in min..max (1, 0.5 and 0.25; 8, 16 and 32). */
#define TL_OPTION_POW2 4u
/** tl_option_info.flags: a negative value means exactly 0 (zero itself is taken by the default). */
#define TL_OPTION_NEGATIVE_ZERO 8u

/**
 * One field. A field holds zero (its default: `zero`, or what `zero_text` says) or a value in
 * min..max (open ends and powers of two per `flags`; an integer type's whole numbers only); with
 * TL_OPTION_NEGATIVE_ZERO a negative value too (meaning exactly 0). Anything else is refused by
 * tl_renderer_create, tl_renderer_set_options and tl_option_parse, naming the field, the value and
 * the range. A field below an effect's `enabled` (`ssr.refine` below `ssr.enabled`) is ignored, not
 * checked, while the effect is off.
 */
typedef struct tl_option_info {
    const char *name;        /**< the field below tl_renderer_options as C spells it: "ssr.refine", "ambient" */
    tl_option_type type;     /**< its storage and kind of value */
    size_t offset;           /**< offsetof(tl_renderer_options, <name>) */
    size_t size;             /**< sizeof the field (FLOAT3: three floats) */
    double min;              /**< the least value (ENUM, SWITCH: 0; BOOL: 0) */
    double max;              /**< the largest (ENUM, SWITCH: count - 1; FLT_MAX: no bound but finite) */
    unsigned flags;          /**< TL_OPTION_MIN_OPEN, TL_OPTION_MAX_OPEN, TL_OPTION_POW2, TL_OPTION_NEGATIVE_ZERO */
    double zero;             /**< the value a zero resolves to when zero_text is NULL (the default) */
    const char *zero_text;   /**< what a zero means where it is not one value ("auto: the planner picks",
                                  "2 x radius"); NULL: `zero` */
    const char *unit;        /**< "px", "radians", "view units", ...; "" when it has none */
    const char *help;        /**< one line */
    const char *c_type;      /**< ENUM, SWITCH: the enum's C name ("tl_render_mode"); else NULL */
    uint32_t count;          /**< ENUM, SWITCH: values; TARGETS: TL_TARGET_COUNT; else 0 */
    const char *(*value_name)(uint32_t value); /**< ENUM, SWITCH, TARGETS: a value's name (the enum's
                                                    tl_X_name, tl_target_name); else NULL */
} tl_option_info;

/** Fields in the registry. */
TL_API size_t tl_option_count(void);
/** The field at `index` (0 .. tl_option_count() - 1; NULL past the end): the frame's own options
 *  first in declaration order, then each effect's, shadows' and environment's, each struct's
 *  `enabled` (where it has one) before its other fields. */
TL_API const tl_option_info *tl_option_at(size_t index);
/** The field named `name` ("ssr.refine"); NULL for any other name. */
TL_API const tl_option_info *tl_option_find(const char *name);

/**
 * Parses `text` into the field `info` of `options` and checks it as tl_renderer_set_options would:
 * BOOL "0" or "1"; SWITCH and ENUM a value's name (tl_X_name: "thin-lpp", "off"); UINT a whole
 * number; FLOAT a number; FLOAT3 "R,G,B"; TARGETS target names (tl_target_name) separated by commas,
 * or "all", or "none". TL_ERROR_INVALID_ARGUMENT, with one line to `logger` (may be NULL) naming the
 * field, the text and what it takes ("options.ssr.refine = 9 is out of range (1..8; 0: 4)"), for a
 * NULL argument, text that is not such a value, or a value out of range; `options` is then
 * unchanged.
 */
TL_API tl_result tl_option_parse(const tl_option_info *info, const char *text, tl_renderer_options *options,
                                 const tl_logger *logger);
/** Writes the field's value in `options` as text tl_option_parse reads back (names for ENUM, SWITCH
 *  and TARGETS, "%.9g" for floats). Returns the length it needs without the NUL, like snprintf; a
 *  NULL buffer asks for it. */
TL_API size_t tl_option_format(const tl_option_info *info, const tl_renderer_options *options, char *buffer,
                               size_t size);
/** Writes the field's range and default as refusals print them: "1..8; 0: 4", "(0, 1]; 0: 0.5, < 0:
 *  0", "8, 16 or 32; 0: 16", "0..4, a tl_render_mode". Returns the length it needs, like snprintf. */
TL_API size_t tl_option_range_format(const tl_option_info *info, char *buffer, size_t size);
/** 1 when `value` is a value the field takes as itself (in range, or zero); 0 otherwise (a negative
 *  value of a TL_OPTION_NEGATIVE_ZERO field counts as in range). For ENUM, SWITCH, BOOL, UINT and
 *  TARGETS the value is the integer, for FLOAT and FLOAT3 (each component) the float. */
TL_API int tl_option_value_valid(const tl_option_info *info, double value);

#ifdef __cplusplus
}
#endif
#endif
