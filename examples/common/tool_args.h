/* The tools' one command-line parser: strict numbers, sizes, byte counts and lists, and a walk
 * over argv driven by each tool's table of options, so that every option of every tool is parsed
 * the same way and listed by --list-options. Not part of the library.
 *
 * Numbers are strict: an integer is decimal digits only (no sign, space, "0x", exponent or
 * trailing character) and must fit its range, overflow included; a real is
 * [-]digits[.digits][e[+|-]digits] (no "+", space, hex, "nan" or "inf") and must be finite and in
 * its range; a size is WxH with two such integers; a byte count is an integer with an optional
 * unit KiB, MiB, GiB or TiB (or "none" where the option allows it); a list is comma-separated
 * with no empty item. */
#ifndef TL_TOOL_ARGS_H
#define TL_TOOL_ARGS_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* ---- values ------------------------------------------------------------------------------- */

typedef enum tl_arg_status {
    TL_ARG_OK = 0,
    TL_ARG_EMPTY,    /* an empty string, or an empty list item */
    TL_ARG_SYNTAX,   /* not written as the kind of value asked for */
    TL_ARG_RANGE,    /* a number outside its range, or past what its type holds */
    TL_ARG_TOO_MANY  /* more list items than allowed, or a list too long to hold */
} tl_arg_status;

/* An unsigned integer in lo..hi. */
tl_arg_status tl_arg_u64(const char *s, uint64_t lo, uint64_t hi, uint64_t *out);
tl_arg_status tl_arg_u32(const char *s, uint32_t lo, uint32_t hi, uint32_t *out);

/* A real in min..max; an end marked open is excluded (min_open: value > min). */
typedef struct tl_arg_range {
    double min, max;
    int min_open, max_open;
} tl_arg_range;
tl_arg_status tl_arg_real(const char *s, const tl_arg_range *r, double *out);

/* WxH, each side in lo..hi. */
tl_arg_status tl_arg_size(const char *s, uint32_t lo, uint32_t hi, uint32_t *w, uint32_t *h);

/* A byte count in lo..hi: digits with an optional unit (KiB, MiB, GiB, TiB). */
tl_arg_status tl_arg_bytes(const char *s, uint64_t lo, uint64_t hi, uint64_t *out);

/* Copies s into buf (size bytes) and splits it at commas into at most max items. */
tl_arg_status tl_arg_split(const char *s, char *buf, size_t size, char **items, size_t max, size_t *count);

/* ---- options ------------------------------------------------------------------------------ */

typedef enum tl_opt_kind {
    TL_OPT_FLAG,      /* no value */
    TL_OPT_TEXT,      /* a non-empty string; with choices, one of them (its index or value in u[0]) */
    TL_OPT_UINT,      /* an integer in lo..hi (u[0]) */
    TL_OPT_REAL,      /* a real in min..max (f[0]) */
    TL_OPT_SIZE,      /* WxH, each side in lo..hi (w[0], h[0]) */
    TL_OPT_BYTES,     /* a byte count in lo..hi (u[0]); "none" too with TL_OPT_NONE (none = 1) */
    TL_OPT_TEXT_LIST, /* up to `items` non-empty names (item[]); with choices, indices or values in u[] */
    TL_OPT_UINT_LIST, /* up to `items` integers in lo..hi (u[]) */
    TL_OPT_SIZE_LIST, /* up to `items` sizes (w[], h[]) */
    TL_OPT_REALS,     /* exactly `items` reals in min..max (f[]) */
    TL_OPT_KIND_COUNT
} tl_opt_kind;

#define TL_OPT_MIN_OPEN 1u /* REAL, REALS: the value must be above min */
#define TL_OPT_MAX_OPEN 2u /* REAL, REALS: the value must be below max */
#define TL_OPT_NONE 4u     /* BYTES: "none" is accepted (no budget) */
#define TL_OPT_USER 0x100u /* this bit and those above: the table owner's own */

#define TL_OPT_MAX_ITEMS 32

/* One option of a tool's table. `id` is the tool's own. */
typedef struct tl_opt {
    const char *name;              /* "--size", "-o" */
    tl_opt_kind kind;
    int id;
    uint64_t lo, hi;               /* UINT, SIZE, BYTES and their lists */
    double min, max;               /* REAL, REALS */
    unsigned flags;                /* TL_OPT_MIN_OPEN, TL_OPT_MAX_OPEN, TL_OPT_NONE */
    uint32_t items;                /* lists: most items (REALS: exactly); 0 = 1 */
    const char *const *choices;    /* TEXT, TEXT_LIST: the names accepted, NULL-terminated */
    const int *values;             /* with choices: each one's value, given in u[] instead of its index */
} tl_opt;

typedef struct tl_opt_table {
    const tl_opt *opts;
    size_t count;
} tl_opt_table;

/* An initializer of a tl_opt_table from an array of options. */
#define TL_OPT_TABLE(a) {(a), sizeof(a) / sizeof((a)[0])}

/* A parsed value. */
typedef struct tl_opt_value {
    const char *text;                   /* the argument as given */
    size_t count;                       /* list items (1 for a single value) */
    int none;                           /* BYTES: "none" */
    uint64_t u[TL_OPT_MAX_ITEMS];
    uint32_t w[TL_OPT_MAX_ITEMS], h[TL_OPT_MAX_ITEMS];
    double f[TL_OPT_MAX_ITEMS];
    char *item[TL_OPT_MAX_ITEMS];       /* TEXT_LIST: into buf */
    char buf[1024];
} tl_opt_value;

/* Walks argv (from argv[1]) against the tables. */
typedef struct tl_opt_parser {
    const char *tool;
    int argc;
    char *const *argv;
    int next;
    const tl_opt_table *tables;
    size_t table_count;
} tl_opt_parser;

void tl_opt_begin(tl_opt_parser *p, const char *tool, int argc, char *const *argv, const tl_opt_table *tables,
                  size_t table_count);

/* The next argument: 1 with *opt and its parsed value, or *opt NULL for a positional argument
 * (v->text; "-" alone is one); 0 when none is left; 2 after one line on stderr naming the
 * option (unknown, missing or bad value): the tool's bad-usage exit status. */
int tl_opt_next(tl_opt_parser *p, const tl_opt **opt, tl_opt_value *v);

/* Whether `o` is one of the table's options. */
int tl_opt_in(const tl_opt *o, tl_opt_table table);

/* "TOOL: message (see --help)" on stderr; returns 2 (bad usage), for checks across options. */
int tl_opt_usage(const char *tool, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* --list-options: one line per option, "NAME KIND" and for numbers "LOW HIGH" (reals: and
 * "min-open", "max-open" where an end is excluded), for scripts and tests. */
void tl_opt_list(FILE *f, const tl_opt_table *tables, size_t table_count);

#endif
