/* The renderer options as command-line flags, from the option registry (tool_options.h). */
#include "tool_options.h"

#include <float.h>
#include <stdarg.h>
#include <string.h>

/* Spellings the tools had before the registry, kept (a field name, or a struct prefix ending in
 * '.', and its flag). Every other flag is the field's name with '.' and '_' as '-'. */
static const struct {
    const char *field, *flag;
} tl__spellings[] = {
    {"depth_format", "--depth"},
    {"environment.background", "--background"},
    {"ssao.blur_radius", "--ssao-blur"},
    {"fog.height_falloff", "--fog-falloff"},
    {"dof.focus_distance", "--dof-focus"},
    {"dof.max_radius", "--dof-max"},
    {"ssr.max_distance", "--ssr-distance"},
    {"shadows.max_lights", "--shadow-max"},
    {"shadows.pcf_radius", "--shadow-pcf"},
    {"shadows.directional_angle", "--shadow-sun-angle"},
    {"shadows.", "--shadow-"},
};

/* Flags beside a field's own: a fixed value under an established name. */
static const struct {
    const char *field, *flag, *value;
} tl__extra_flags[] = {
    {"forward_depth_prepass", "--no-depth-prepass", "off"},
    {"shadows.cache", "--shadow-no-cache", "off"},
};

#define TL__DEGREES (180.0 / 3.14159265358979323846)

void tl_tool_flag_spec_of(const tl_option_info *field, tl_tool_flag_spec *out)
{
    *out = (tl_tool_flag_spec){.scale = 1.0};
    const char *name = field->name, *prefix = "--";
    for (size_t i = 0; i < sizeof tl__spellings / sizeof tl__spellings[0]; i++) {
        size_t n = strlen(tl__spellings[i].field);
        int whole = strcmp(name, tl__spellings[i].field) == 0;
        if (whole || (tl__spellings[i].field[n - 1] == '.' && strncmp(name, tl__spellings[i].field, n) == 0)) {
            prefix = tl__spellings[i].flag;
            name = whole ? "" : name + n;
            break;
        }
    }
    size_t len = strlen(name);
    if (field->type == TL_OPTION_BOOL && len > 8 && strcmp(name + len - 8, ".enabled") == 0) len -= 8; /* --ssr */
    snprintf(out->name, sizeof out->name, "%s%.*s", prefix, (int)len, name);
    for (char *c = out->name + 2; *c; c++)
        if (*c == '.' || *c == '_') *c = '-';
    if (strcmp(field->name, "shadows.directional_angle") == 0) out->scale = TL__DEGREES;
    out->broadcast = strcmp(field->name, "ambient") == 0;
}

/* ---- building the table ------------------------------------------------------------------------ */

/* The names a TEXT flag takes: each value's once (DEFAULT's name is its value's unless its own). */
static void tl__enum_choices(tl_tool_options *t, size_t k, const tl_option_info *f)
{
    size_t n = 0;
    for (uint32_t v = 0; v < f->count && n < TL_TOOL_OPTION_CHOICES; v++) {
        const char *name = f->value_name(v);
        int seen = 0;
        for (uint32_t w = v + 1; v == 0 && w < f->count; w++) seen |= strcmp(f->value_name(w), name) == 0;
        if (seen) continue;
        t->values[k][n] = (int)v;
        t->choices[k][n++] = name;
    }
    t->choices[k][n] = NULL;
}

/* A power-of-two field's values as choices ("0.25", "0.5", "1"). */
static void tl__pow2_choices(tl_tool_options *t, size_t k, const tl_option_info *f)
{
    size_t n = 0;
    for (double v = f->min; v <= f->max && n < 8; v *= 2.0, n++) {
        snprintf(t->text[k][n], sizeof t->text[k][n], "%g", v);
        t->choices[k][n] = t->text[k][n];
        t->values[k][n] = (int)n;
    }
    t->choices[k][n] = NULL;
}

/* Target names, "all" and "none". */
static void tl__target_choices(tl_tool_options *t, size_t k, const tl_option_info *f)
{
    size_t n = 0;
    for (uint32_t v = 0; v < f->count && n + 2 < TL_TOOL_OPTION_CHOICES; v++) t->choices[k][n++] = f->value_name(v);
    t->choices[k][n++] = "all";
    t->choices[k][n++] = "none";
    t->choices[k][n] = NULL;
}

/* The kind and range of field f's flag, from its row. */
static void tl__kind(tl_tool_options *t, size_t k, const tl_option_info *f)
{
    tl_opt *o = &t->opts[k];
    const tl_tool_flag_spec *s = &t->spec[k];
    if (s->fixed || f->type == TL_OPTION_BOOL) {
        o->kind = TL_OPT_FLAG;
    } else if (f->type == TL_OPTION_ENUM || f->type == TL_OPTION_SWITCH) {
        o->kind = TL_OPT_TEXT, tl__enum_choices(t, k, f);
    } else if (f->type == TL_OPTION_TARGETS) {
        o->kind = TL_OPT_TEXT_LIST, o->items = f->count + 2u, tl__target_choices(t, k, f);
    } else if (f->flags & TL_OPTION_POW2) {
        o->kind = TL_OPT_TEXT, tl__pow2_choices(t, k, f);
    } else if (f->type == TL_OPTION_UINT) {
        o->kind = TL_OPT_UINT, o->lo = (uint64_t)f->min, o->hi = (uint64_t)f->max;
    } else {
        int neg_zero = (f->flags & TL_OPTION_NEGATIVE_ZERO) != 0; /* an explicit 0 is exactly 0 */
        o->kind = f->type == TL_OPTION_FLOAT3 && !s->broadcast ? TL_OPT_REALS : TL_OPT_REAL;
        o->items = o->kind == TL_OPT_REALS ? 3u : 0u;
        o->min = f->min > -FLT_MAX ? f->min * s->scale : -FLT_MAX;
        o->max = f->max < FLT_MAX ? f->max * s->scale : FLT_MAX;
        o->flags = ((f->flags & TL_OPTION_MIN_OPEN) && !neg_zero ? TL_OPT_MIN_OPEN : 0u) |
                   (f->flags & TL_OPTION_MAX_OPEN ? TL_OPT_MAX_OPEN : 0u);
    }
    if (t->choices[k][0]) o->choices = t->choices[k], o->values = t->values[k];
}

static int tl__excluded(const char *name, const char *const *exclude)
{
    for (size_t i = 0; exclude && exclude[i]; i++)
        if (strcmp(exclude[i], name) == 0) return 1;
    return 0;
}

static void tl__add(tl_tool_options *t, const tl_option_info *f, const tl_tool_flag_spec *spec)
{
    if (t->count == TL_TOOL_OPTIONS_MAX) return;
    size_t k = t->count++;
    t->field[k] = f;
    t->spec[k] = *spec;
    t->choices[k][0] = NULL;
    t->opts[k] = (tl_opt){.name = t->spec[k].name, .id = (int)k};
    tl__kind(t, k, f);
}

void tl_tool_options_build(tl_tool_options *t, const char *const *exclude)
{
    memset(t, 0, sizeof *t);
    for (size_t i = 0; i < tl_option_count(); i++) {
        const tl_option_info *f = tl_option_at(i);
        if (tl__excluded(f->name, exclude)) continue;
        tl_tool_flag_spec spec;
        tl_tool_flag_spec_of(f, &spec);
        tl__add(t, f, &spec);
        for (size_t e = 0; e < sizeof tl__extra_flags / sizeof tl__extra_flags[0]; e++)
            if (strcmp(tl__extra_flags[e].field, f->name) == 0) {
                tl_tool_flag_spec extra = {.scale = 1.0, .fixed = tl__extra_flags[e].value};
                snprintf(extra.name, sizeof extra.name, "%s", tl__extra_flags[e].flag);
                tl__add(t, f, &extra);
            }
    }
}

tl_opt_table tl_tool_options_table(const tl_tool_options *t) { return (tl_opt_table){t->opts, t->count}; }

/* ---- applying a value ------------------------------------------------------------------------- */

/* The value as the text tl_option_parse reads: numbers unscaled, an explicit 0 of a field whose
 * zero is its default written as -1 (exactly 0), a broadcast number as R,G,B. */
static void tl__value_text(const tl_tool_options *t, size_t k, const tl_opt_value *v, char *out, size_t size)
{
    const tl_tool_flag_spec *s = &t->spec[k];
    const tl_opt *o = &t->opts[k];
    if (s->fixed) snprintf(out, size, "%s", s->fixed);
    else if (o->kind == TL_OPT_FLAG) snprintf(out, size, "1");
    else if (o->kind != TL_OPT_REAL && o->kind != TL_OPT_REALS) snprintf(out, size, "%s", v->text);
    else {
        size_t n = o->kind == TL_OPT_REALS ? v->count : s->broadcast ? 3u : 1u, at = 0;
        int neg_zero = (t->field[k]->flags & TL_OPTION_NEGATIVE_ZERO) != 0;
        out[0] = '\0';
        for (size_t i = 0; i < n && at < size; i++) {
            double f = v->f[o->kind == TL_OPT_REALS ? i : 0] / s->scale;
            if (f == 0.0 && neg_zero) f = -1.0;
            at += (size_t)snprintf(out + at, size - at, "%s%.9g", i ? "," : "", f);
        }
    }
}

static void tl__keep_line(void *user, tl_log_level level, const char *message)
{
    (void)level;
    snprintf((char *)user, 256, "%s", message);
}

int tl_tool_options_apply(const char *tool, const tl_tool_options *t, tl_renderer_options *o, const tl_opt *opt,
                          const tl_opt_value *v)
{
    if (!tl_opt_in(opt, tl_tool_options_table(t))) return 0;
    size_t k = (size_t)opt->id;
    char text[256], why[256] = "";
    tl__value_text(t, k, v, text, sizeof text);
    tl_logger logger = {tl__keep_line, why};
    if (tl_option_parse(t->field[k], text, o, &logger) == TL_OK) return 1;
    return tl_opt_usage(tool, "%s '%s': %s", opt->name, opt->kind == TL_OPT_FLAG ? text : v->text, why);
}

/* ---- --help ------------------------------------------------------------------------------------ */

/* Appends to out (size bytes, NUL-terminated). */
static void tl__cat(char *out, size_t size, const char *fmt, ...)
{
    size_t at = strlen(out);
    if (at + 1 >= size) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(out + at, size - at, fmt, ap);
    va_end(ap);
}

/* What the flag takes: its choices, or its range in the flag's unit. */
static void tl__takes(const tl_tool_options *t, size_t k, char *out, size_t size)
{
    const tl_opt *o = &t->opts[k];
    const tl_option_info *f = t->field[k];
    if (o->choices) {
        for (size_t c = 0; o->choices[c]; c++)
            tl__cat(out, size, "%s%s", c == 0 ? "" : o->choices[c + 1] ? ", " : " or ", o->choices[c]);
    } else if (o->kind == TL_OPT_UINT) {
        tl__cat(out, size, "%llu..%llu", (unsigned long long)o->lo, (unsigned long long)o->hi);
    } else if (o->kind == TL_OPT_REAL || o->kind == TL_OPT_REALS) {
        int lo = o->min > -FLT_MAX, hi = o->max < FLT_MAX, lo_open = (o->flags & TL_OPT_MIN_OPEN) != 0,
            hi_open = (o->flags & TL_OPT_MAX_OPEN) != 0;
        if (o->kind == TL_OPT_REALS) tl__cat(out, size, "R,G,B each ");
        if (!lo && !hi) tl__cat(out, size, "any number");
        else if (!hi) tl__cat(out, size, "%s %g", lo_open ? ">" : ">=", o->min);
        else if (!lo_open && !hi_open) tl__cat(out, size, "%g..%g", o->min, o->max);
        else tl__cat(out, size, "%c%g, %g%c", lo_open ? '(' : '[', o->min, o->max, hi_open ? ')' : ']');
    }
    if (f->unit[0] && o->kind != TL_OPT_FLAG) tl__cat(out, size, " %s", t->spec[k].scale != 1.0 ? "degrees" : f->unit);
    if (t->spec[k].broadcast) tl__cat(out, size, ", one number for R, G and B");
}

/* The default: the zero's meaning, in the flag's terms. */
static void tl__default(const tl_tool_options *t, size_t k, char *out, size_t size)
{
    const tl_option_info *f = t->field[k];
    if (f->zero_text) tl__cat(out, size, "default %s", f->zero_text);
    else if (f->type == TL_OPTION_ENUM || f->type == TL_OPTION_SWITCH)
        tl__cat(out, size, "default %s", f->value_name((uint32_t)f->zero));
    else if (f->type != TL_OPTION_BOOL && f->type != TL_OPTION_TARGETS)
        tl__cat(out, size, "default %g", f->zero * t->spec[k].scale);
}

/* One line, wrapped at 100 columns with the description column (24) kept. */
static void tl__print_wrapped(FILE *f, const char *left, const char *text)
{
    size_t col = (size_t)fprintf(f, "  %-21s", left);
    if (col > 23) fputs("\n                       ", f);
    col = 23;
    for (const char *p = text; *p;) {
        size_t word = strcspn(p, " ");
        if (col + 1 + word > 100) {
            fputs("\n                       ", f);
            col = 23;
        }
        col += (size_t)fprintf(f, " %.*s", (int)word, p);
        p += word;
        while (*p == ' ') p++;
    }
    fputc('\n', f);
}

void tl_tool_options_help(FILE *f, const tl_tool_options *t)
{
    static const char *const metavar[TL_OPT_KIND_COUNT] = {
        [TL_OPT_FLAG] = "", [TL_OPT_TEXT] = " V", [TL_OPT_UINT] = " N", [TL_OPT_REAL] = " X",
        [TL_OPT_TEXT_LIST] = " LIST", [TL_OPT_REALS] = " R,G,B"};
    for (size_t k = 0; k < t->count; k++) {
        const tl_opt *o = &t->opts[k];
        char left[64], text[1536] = "", takes[1024] = "", def[160] = "";
        snprintf(left, sizeof left, "%s%s", o->name, metavar[o->kind] ? metavar[o->kind] : "");
        if (t->spec[k].fixed) {
            tl_tool_flag_spec own;
            tl_tool_flag_spec_of(t->field[k], &own);
            snprintf(text, sizeof text, "%s %s", own.name, t->spec[k].fixed);
        } else {
            tl__takes(t, k, takes, sizeof takes);
            tl__default(t, k, def, sizeof def);
            snprintf(text, sizeof text, "%s%s%s%s%s%s", t->field[k]->help, takes[0] ? ": " : "", takes,
                     def[0] ? " (" : "", def, def[0] ? ")" : "");
        }
        tl__print_wrapped(f, left, text);
    }
}
