/* The tools' one command-line parser (tool_args.h). */
#include "tool_args.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

/* ---- values ------------------------------------------------------------------------------- */

static int tl__digit(char c) { return c >= '0' && c <= '9'; }

/* Digits only: the value, or TL_ARG_RANGE past 2^64 - 1 (the whole string is still checked). */
static tl_arg_status tl__digits(const char *s, const char *end, uint64_t *out)
{
    uint64_t v = 0;
    int over = 0;
    if (s == end) return *s ? TL_ARG_SYNTAX : TL_ARG_EMPTY;
    for (const char *p = s; p < end; p++) {
        if (!tl__digit(*p)) return TL_ARG_SYNTAX;
        unsigned d = (unsigned)(*p - '0');
        if (v > (UINT64_MAX - d) / 10) over = 1;
        else v = v * 10 + d;
    }
    *out = v;
    return over ? TL_ARG_RANGE : TL_ARG_OK;
}

tl_arg_status tl_arg_u64(const char *s, uint64_t lo, uint64_t hi, uint64_t *out)
{
    uint64_t v = 0;
    tl_arg_status st = s ? tl__digits(s, s + strlen(s), &v) : TL_ARG_EMPTY;
    if (st) return st;
    if (v < lo || v > hi) return TL_ARG_RANGE;
    *out = v;
    return TL_ARG_OK;
}

tl_arg_status tl_arg_u32(const char *s, uint32_t lo, uint32_t hi, uint32_t *out)
{
    uint64_t v = 0;
    tl_arg_status st = tl_arg_u64(s, lo, hi, &v);
    if (!st) *out = (uint32_t)v;
    return st;
}

/* [-]digits[.digits][e[+|-]digits], with digits on at least one side of the point. */
static int tl__real_syntax(const char *p)
{
    int digits = 0;
    if (*p == '-') p++;
    for (; tl__digit(*p); p++) digits++;
    if (*p == '.')
        for (p++; tl__digit(*p); p++) digits++;
    if (!digits) return 0;
    if (*p == 'e' || *p == 'E') {
        p++;
        if (*p == '+' || *p == '-') p++;
        if (!tl__digit(*p)) return 0;
        while (tl__digit(*p)) p++;
    }
    return *p == '\0';
}

tl_arg_status tl_arg_real(const char *s, const tl_arg_range *r, double *out)
{
    if (!s || !*s) return TL_ARG_EMPTY;
    if (!tl__real_syntax(s)) return TL_ARG_SYNTAX;
    errno = 0;
    double v = strtod(s, NULL);
    if (!isfinite(v) || (errno == ERANGE && fabs(v) > 1.0)) return TL_ARG_RANGE; /* underflow is 0 */
    if (v < r->min || v > r->max || (r->min_open && v == r->min) || (r->max_open && v == r->max)) return TL_ARG_RANGE;
    *out = v;
    return TL_ARG_OK;
}

tl_arg_status tl_arg_size(const char *s, uint32_t lo, uint32_t hi, uint32_t *w, uint32_t *h)
{
    if (!s || !*s) return TL_ARG_EMPTY;
    const char *x = strchr(s, 'x');
    uint64_t a = 0, b = 0;
    if (!x || x == s || !x[1]) return TL_ARG_SYNTAX;
    tl_arg_status sa = tl__digits(s, x, &a), sb = tl__digits(x + 1, x + strlen(x), &b);
    if (sa == TL_ARG_SYNTAX || sb == TL_ARG_SYNTAX) return TL_ARG_SYNTAX;
    if (sa || sb || a < lo || a > hi || b < lo || b > hi) return TL_ARG_RANGE;
    *w = (uint32_t)a;
    *h = (uint32_t)b;
    return TL_ARG_OK;
}

tl_arg_status tl_arg_bytes(const char *s, uint64_t lo, uint64_t hi, uint64_t *out)
{
    static const char *const units[] = {"", "KiB", "MiB", "GiB", "TiB"};
    if (!s || !*s) return TL_ARG_EMPTY;
    const char *end = s;
    while (tl__digit(*end)) end++;
    size_t unit = 0;
    while (unit < sizeof units / sizeof units[0] && strcmp(end, units[unit])) unit++;
    if (unit == sizeof units / sizeof units[0]) return TL_ARG_SYNTAX;
    uint64_t v = 0;
    tl_arg_status st = tl__digits(s, end, &v);
    if (st) return st == TL_ARG_EMPTY ? TL_ARG_SYNTAX : st; /* "MiB" alone */
    for (size_t k = 0; k < unit; k++) {
        if (v > UINT64_MAX / 1024) return TL_ARG_RANGE;
        v *= 1024;
    }
    if (v < lo || v > hi) return TL_ARG_RANGE;
    *out = v;
    return TL_ARG_OK;
}

tl_arg_status tl_arg_split(const char *s, char *buf, size_t size, char **items, size_t max, size_t *count)
{
    *count = 0;
    if (!s || !*s) return TL_ARG_EMPTY;
    if (strlen(s) >= size) return TL_ARG_TOO_MANY;
    strcpy(buf, s);
    for (char *p = buf;;) {
        char *comma = strchr(p, ',');
        if (comma) *comma = '\0';
        if (!*p) return TL_ARG_EMPTY;
        if (*count == max) return TL_ARG_TOO_MANY;
        items[(*count)++] = p;
        if (!comma) return TL_ARG_OK;
        p = comma + 1;
    }
}

/* ---- options ------------------------------------------------------------------------------ */

/* Each kind: its name in --list-options, and the kind of one value (lists: of each item). */
static const struct {
    const char *name;
    tl_opt_kind item;
    int numeric;
} tl__kinds[TL_OPT_KIND_COUNT] = {
    [TL_OPT_FLAG] = {"flag", TL_OPT_FLAG, 0},           [TL_OPT_TEXT] = {"text", TL_OPT_TEXT, 0},
    [TL_OPT_UINT] = {"uint", TL_OPT_UINT, 1},           [TL_OPT_REAL] = {"real", TL_OPT_REAL, 1},
    [TL_OPT_SIZE] = {"size", TL_OPT_SIZE, 1},           [TL_OPT_BYTES] = {"bytes", TL_OPT_BYTES, 1},
    [TL_OPT_TEXT_LIST] = {"text-list", TL_OPT_TEXT, 0}, [TL_OPT_UINT_LIST] = {"uint-list", TL_OPT_UINT, 1},
    [TL_OPT_SIZE_LIST] = {"size-list", TL_OPT_SIZE, 1}, [TL_OPT_REALS] = {"reals", TL_OPT_REAL, 1},
};

static int tl__is_list(tl_opt_kind k) { return tl__kinds[k].item != k; }

/* One value of kind `item` into slot i of v. */
static tl_arg_status tl__one(const tl_opt *o, tl_opt_kind item, const char *s, tl_opt_value *v, size_t i)
{
    tl_arg_range r = {o->min, o->max, (o->flags & TL_OPT_MIN_OPEN) != 0, (o->flags & TL_OPT_MAX_OPEN) != 0};
    uint32_t lo = o->lo > UINT32_MAX ? UINT32_MAX : (uint32_t)o->lo, hi = o->hi > UINT32_MAX ? UINT32_MAX : (uint32_t)o->hi;
    switch (item) {
    case TL_OPT_TEXT:
        if (!*s) return TL_ARG_EMPTY;
        for (size_t c = 0; o->choices && o->choices[c]; c++)
            if (!strcmp(s, o->choices[c])) {
                v->u[i] = o->values ? (uint64_t)o->values[c] : c;
                return TL_ARG_OK;
            }
        return o->choices ? TL_ARG_SYNTAX : TL_ARG_OK;
    case TL_OPT_UINT: return tl_arg_u64(s, o->lo, o->hi, &v->u[i]);
    case TL_OPT_REAL: return tl_arg_real(s, &r, &v->f[i]);
    case TL_OPT_SIZE: return tl_arg_size(s, lo, hi, &v->w[i], &v->h[i]);
    case TL_OPT_BYTES:
        if ((o->flags & TL_OPT_NONE) && !strcmp(s, "none")) {
            v->none = 1;
            return TL_ARG_OK;
        }
        return tl_arg_bytes(s, o->lo, o->hi, &v->u[i]);
    default: return TL_ARG_SYNTAX;
    }
}

static tl_arg_status tl__parse(const tl_opt *o, tl_opt_value *v)
{
    tl_opt_kind item = tl__kinds[o->kind].item;
    if (!tl__is_list(o->kind)) return tl__one(o, item, v->text, v, 0);
    size_t max = o->items ? o->items : 1;
    if (max > TL_OPT_MAX_ITEMS) max = TL_OPT_MAX_ITEMS;
    tl_arg_status st = tl_arg_split(v->text, v->buf, sizeof v->buf, v->item, max, &v->count);
    for (size_t i = 0; !st && i < v->count; i++) st = tl__one(o, item, v->item[i], v, i);
    if (!st && o->kind == TL_OPT_REALS && v->count != max) st = TL_ARG_SYNTAX;
    return st;
}

/* What a value of the option looks like, for messages: "a whole number in 1..16384". */
static void tl__describe(const tl_opt *o, char *out, size_t size)
{
    char range[160] = "";
    if (o->kind == TL_OPT_REAL || o->kind == TL_OPT_REALS) {
        int has_max = o->max < FLT_MAX;
        if (o->min > -FLT_MAX)
            snprintf(range, sizeof range, " %s %g%s", o->flags & TL_OPT_MIN_OPEN ? ">" : ">=", o->min, has_max ? " and" : "");
        if (has_max)
            snprintf(range + strlen(range), sizeof range - strlen(range), " %s %g", o->flags & TL_OPT_MAX_OPEN ? "<" : "<=",
                     o->max);
    } else if (o->kind != TL_OPT_BYTES || o->lo > 1 || o->hi < SIZE_MAX) {
        snprintf(range, sizeof range, " in %llu..%llu", (unsigned long long)o->lo, (unsigned long long)o->hi);
    }
    char choices[512] = "";
    for (size_t c = 0; o->choices && o->choices[c]; c++)
        snprintf(choices + strlen(choices), sizeof choices - strlen(choices), "%s%s",
                 c == 0 ? "" : o->choices[c + 1] ? ", " : " or ", o->choices[c]);
    uint32_t n = o->items ? o->items : 1;
    switch (o->kind) {
    case TL_OPT_TEXT: snprintf(out, size, "wants %s", o->choices ? choices : "a value"); break;
    case TL_OPT_UINT: snprintf(out, size, "wants a whole number%s", range); break;
    case TL_OPT_REAL: snprintf(out, size, "wants a number%s", range); break;
    case TL_OPT_SIZE: snprintf(out, size, "wants WxH, each side%s", range); break;
    case TL_OPT_BYTES:
        snprintf(out, size, "wants a byte count%s (N, NKiB, NMiB, NGiB or NTiB%s)", range,
                 o->flags & TL_OPT_NONE ? "; or none" : "");
        break;
    case TL_OPT_TEXT_LIST:
        snprintf(out, size, "wants up to %u comma-separated names%s%s", n, o->choices ? " of " : "", choices);
        break;
    case TL_OPT_UINT_LIST: snprintf(out, size, "wants up to %u comma-separated whole numbers%s", n, range); break;
    case TL_OPT_SIZE_LIST: snprintf(out, size, "wants up to %u comma-separated WxH, each side%s", n, range); break;
    case TL_OPT_REALS: snprintf(out, size, "wants %u comma-separated numbers%s", n, range); break;
    default: snprintf(out, size, "takes no value"); break;
    }
}

void tl_opt_begin(tl_opt_parser *p, const char *tool, int argc, char *const *argv, const tl_opt_table *tables,
                  size_t table_count)
{
    *p = (tl_opt_parser){tool, argc, argv, 1, tables, table_count};
}

int tl_opt_usage(const char *tool, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "%s: ", tool);
    vfprintf(stderr, fmt, ap);
    fputs(" (see --help)\n", stderr);
    va_end(ap);
    return 2;
}

int tl_opt_in(const tl_opt *o, tl_opt_table table) { return o && o >= table.opts && o < table.opts + table.count; }

static const tl_opt *tl__find(const tl_opt_parser *p, const char *name)
{
    for (size_t t = 0; t < p->table_count; t++)
        for (size_t i = 0; i < p->tables[t].count; i++)
            if (!strcmp(p->tables[t].opts[i].name, name)) return &p->tables[t].opts[i];
    return NULL;
}

int tl_opt_next(tl_opt_parser *p, const tl_opt **opt, tl_opt_value *v)
{
    *opt = NULL;
    v->count = 1;
    v->none = 0;
    if (p->next >= p->argc) return 0;
    const char *a = p->argv[p->next++];
    v->text = a;
    if (a[0] != '-' || a[1] == '\0') return 1; /* a positional argument */
    const tl_opt *o = tl__find(p, a);
    if (!o) return tl_opt_usage(p->tool, "unknown option '%s'", a);
    *opt = o;
    if (o->kind == TL_OPT_FLAG) return 1;
    if (p->next >= p->argc || !p->argv[p->next][0]) return tl_opt_usage(p->tool, "%s needs a value", a);
    v->text = p->argv[p->next++];
    tl_arg_status st = tl__parse(o, v);
    if (!st) return 1;
    char want[768];
    tl__describe(o, want, sizeof want);
    const char *why = st == TL_ARG_EMPTY      ? "an empty item; "
                      : st == TL_ARG_TOO_MANY ? "too many items; "
                      : st == TL_ARG_RANGE    ? "out of range; "
                                              : "";
    return tl_opt_usage(p->tool, "%s '%s': %s%s", a, v->text, why, want);
}

void tl_opt_list(FILE *f, const tl_opt_table *tables, size_t table_count)
{
    for (size_t t = 0; t < table_count; t++)
        for (size_t i = 0; i < tables[t].count; i++) {
            const tl_opt *o = &tables[t].opts[i];
            fprintf(f, "%s %s", o->name, tl__kinds[o->kind].name);
            if (o->kind == TL_OPT_REAL || o->kind == TL_OPT_REALS)
                fprintf(f, " %.9g %.9g%s%s", o->min, o->max, o->flags & TL_OPT_MIN_OPEN ? " min-open" : "",
                        o->flags & TL_OPT_MAX_OPEN ? " max-open" : "");
            else if (tl__kinds[o->kind].numeric)
                fprintf(f, " %llu %llu", (unsigned long long)o->lo, (unsigned long long)o->hi);
            if (o->kind == TL_OPT_BYTES && (o->flags & TL_OPT_NONE)) fputs(" none", f);
            for (size_t c = 0; o->choices && o->choices[c]; c++) fprintf(f, "%s%s", c ? "," : " ", o->choices[c]);
            fputc('\n', f);
        }
}
