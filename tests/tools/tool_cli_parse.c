/* Every option of thinlight-render, thinlight-bench and thinlight-viewer against the values it
 * must refuse, in-process: each tool's own parse function (render_args.c, bench_args.c,
 * viewer/args.c) with the arguments of a small job and `OPTION VALUE` last must return 2 (bad
 * usage) after exactly one line on stderr naming the option. The options come from the tool's own
 * `--list-options` (its tables), so an option added to a tool is tested without a line here; the
 * values are those of tests/input/cli_options.cmake (which runs the same matrix with one process
 * per value in the full tier: the exit status and the empty output folder of the real program),
 * each option given the whole matrix. */
#define _POSIX_C_SOURCE 200809L /* open_memstream, dup, fileno */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "option_values.h"
#include "tl_test.h"
#include "tool_options.h"

#if TL_HAVE_RENDER_ARGS
#include "render.h"
#endif
#if TL_HAVE_BENCH_ARGS
#include "bench.h"
#endif
#if TL_HAVE_VIEWER_ARGS
#include "args.h"
#endif

typedef int (*parse_fn)(int argc, char **argv);

/* Each tool's parse, its arguments kept for the registry's cases (what the renderer options became). */
#if TL_HAVE_RENDER_ARGS
static render_args g_render;
static int parse_render(int argc, char **argv) { return render_parse_args(argc, argv, &g_render); }
#endif
#if TL_HAVE_BENCH_ARGS
static bench_options g_bench;
static int parse_bench(int argc, char **argv) { return bench_parse_args(argc, argv, &g_bench); }
#endif
#if TL_HAVE_VIEWER_ARGS
static vw_args g_viewer;
static int parse_viewer(int argc, char **argv) { return vw_parse_args(argc, argv, &g_viewer); }
#endif

/* ---- running a parse with stdout and stderr captured -------------------------------------------- */

typedef struct captured {
    int rc;
    char out[1 << 15], err[4096];
} captured;

static void read_back(FILE *f, char *buf, size_t size)
{
    fflush(f);
    rewind(f);
    size_t n = fread(buf, 1, size - 1, f);
    buf[n] = '\0';
}

static void run_parse(parse_fn parse, int argc, char **argv, captured *c)
{
    FILE *out = tmpfile(), *err = tmpfile();
    if (!out || !err) {
        TL_CHECK(!"tmpfile");
        c->rc = -99;
        if (out) fclose(out);
        if (err) fclose(err);
        return;
    }
    fflush(stdout);
    fflush(stderr);
    int saved_out = dup(1), saved_err = dup(2);
    dup2(fileno(out), 1);
    dup2(fileno(err), 2);
    c->rc = parse(argc, argv);
    fflush(stdout);
    fflush(stderr);
    dup2(saved_out, 1);
    dup2(saved_err, 2);
    close(saved_out);
    close(saved_err);
    read_back(out, c->out, sizeof c->out);
    read_back(err, c->err, sizeof c->err);
    fclose(out);
    fclose(err);
}

/* ---- the bad values of an option (cli_options.cmake's bad_values, every option with `more`) ----- */

typedef struct values {
    char v[64][256];
    size_t n;
} values;

static void add(values *s, const char *fmt, const char *a, const char *b)
{
    if (s->n < sizeof s->v / sizeof s->v[0]) snprintf(s->v[s->n++], sizeof s->v[0], fmt, a, b);
}

static void bad_uints(values *s, double low, double high, int list, int bytes, const char *ok)
{
    static const char *const items[] = {"1e999", "12x",     "-1",  "0x10", "+1",   " 1",  "1 ",
                                        "1.5",   "nan",     "1e3", "18446744073709551616", "99999999999999999999999"};
    const char *fmt = list ? "%s,%s" : "%.0s%s";
    for (size_t i = 0; i < sizeof items / sizeof items[0]; i++) add(s, fmt, ok, items[i]);
    char edge[40];
    if (high < 4294967297.0) {
        add(s, fmt, ok, "4294967297");
    } else if (high < 18446744073709551615.0) {
        snprintf(edge, sizeof edge, "%.0f", high + 1.0);
        add(s, fmt, ok, edge);
    }
    if (bytes) {
        static const char *const units[] = {"1KB", "1 MiB", "1mib", "MiB", "16777216TiB"};
        for (size_t i = 0; i < 5; i++) add(s, "%.0s%s", "", units[i]);
    } else if (low > 0) {
        snprintf(edge, sizeof edge, "%.0f", low - 1.0);
        add(s, fmt, ok, edge);
    }
    if (list) {
        add(s, "%s,,%s", ok, ok);
        add(s, "%s,%s", ok, "");
        add(s, "%.0s,%s", "", ok);
        add(s, "%.0s%s", "", ",");
    }
}

static void bad_reals(values *s, const char *low, const char *high, const char *open, int tuple)
{
    static const char *const items[] = {"1e999", "12x", "nan", "inf", "-inf", "-1e999", "0x10", "+1", " 1", "1 ",
                                        "1e", "."};
    const char *ok = strstr(open, "min-open") ? "1" : low;
    const char *fmt = tuple ? "%s,%s" : "%.0s%s";
    char pre[72];
    snprintf(pre, sizeof pre, "%s,%s", ok, ok);
    for (size_t i = 0; i < sizeof items / sizeof items[0]; i++) add(s, fmt, pre, items[i]);
    if (atof(high) < 4294967297.0) add(s, fmt, pre, "4294967297");
    if (atof(low) > -1.0 || (atof(low) == -1.0 && strstr(open, "min-open"))) add(s, fmt, pre, "-1");
    if (strstr(open, "min-open")) add(s, fmt, pre, low);
    if (strstr(open, "max-open")) add(s, fmt, pre, high);
    if (tuple) {
        add(s, "%.0s%s", "", ok);
        add(s, "%s,,%s", pre, ok);
    }
}

static void bad_sizes(values *s, double low, double high, int list)
{
    char l[24], a[24], b[24], item[120];
    snprintf(l, sizeof l, "%.0f", low);
    snprintf(a, sizeof a, "%.0f", high + 1.0);
    snprintf(b, sizeof b, "%.0f", low - 1.0);
    const char *fmt = list ? "%sx%s," : "%.0s%.0s";
    char pre[56];
    snprintf(pre, sizeof pre, fmt, l, l);
    const char *items[] = {"4294967297x%s", "%sx4294967297", "-1x%s", "1e999x%s", "x12", "12", "12X12", "12x12x12",
                           " 12x12", "+12x12", "1e3x12", "0x10x10", "18446744073709551616x1", "12x"};
    for (size_t i = 0; i < sizeof items / sizeof items[0]; i++) {
        snprintf(item, sizeof item, items[i], l);
        add(s, "%s%s", pre, item);
    }
    snprintf(item, sizeof item, "%sx%s", a, l);
    add(s, "%s%s", pre, item);
    if (low > 0) {
        snprintf(item, sizeof item, "%sx%s", l, b);
        add(s, "%s%s", pre, item);
    }
    if (list) {
        snprintf(item, sizeof item, "%sx%s,,%sx%s", l, l, l, l);
        add(s, "%.0s%s", "", item);
    }
}

/* The bad values of one --list-options line; 0 when the option takes none (flags, free text). */
static size_t bad_values_of(const char *kind, const char *rest, values *s)
{
    char low[32] = "", high[32] = "", open[32] = "";
    s->n = 0;
    int numbers = sscanf(rest, "%31s %31s %31s", low, high, open) >= 2 && strchr("-0123456789", low[0]);
    if (!numbers) low[0] = high[0] = open[0] = '\0';
    if (!strcmp(kind, "uint") || !strcmp(kind, "uint-list") || !strcmp(kind, "bytes"))
        bad_uints(s, atof(low), atof(high), !strcmp(kind, "uint-list"), !strcmp(kind, "bytes"), low);
    else if (!strcmp(kind, "real") || !strcmp(kind, "reals"))
        bad_reals(s, low, high, open, !strcmp(kind, "reals"));
    else if (!strcmp(kind, "size") || !strcmp(kind, "size-list"))
        bad_sizes(s, atof(low), atof(high), !strcmp(kind, "size-list"));
    else if (!strncmp(kind, "text", 4) && rest[0] && !numbers) {
        char first[40];
        snprintf(first, sizeof first, "%.*s", (int)strcspn(rest, ","), rest);
        add(s, "%.0s%s", "", "4294967297");
        add(s, " %s%.0s", first, "");
        if (!strcmp(kind, "text-list")) add(s, "%s,,%s", first, first);
    }
    if (s->n) add(s, "%.0s%s", "", "");
    return s->n;
}

/* ---- one tool ----------------------------------------------------------------------------------- */

/* Every option of the tool's --list-options against its bad values, after `job`. */
static void every_option_refuses(const char *tool, parse_fn parse, const char *const *job, int job_count)
{
    static captured c, r;
    static char listing[sizeof c.out];
    char *list_argv[] = {(char *)tool, "--list-options", NULL};
    run_parse(parse, 2, list_argv, &c);
    TL_CHECK(c.rc == -1 || c.rc == 0);
    TL_CHECK(strstr(c.out, "--help flag") != NULL);
    memcpy(listing, c.out, sizeof listing);
    size_t options = 0, runs = 0, failures = 0;
    char *save = NULL;
    for (char *line = strtok_r(listing, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
        char option[64], kind[32];
        int used = 0;
        if (sscanf(line, "%63s %31s %n", option, kind, &used) < 2 || option[0] != '-') continue;
        values s;
        if (!bad_values_of(kind, line + used, &s)) continue;
        options++;
        for (size_t i = 0; i < s.n; i++) {
            char *argv[32];
            int argc = 0;
            argv[argc++] = (char *)tool;
            for (int j = 0; j < job_count; j++) argv[argc++] = (char *)job[j];
            argv[argc++] = option;
            argv[argc++] = s.v[i];
            argv[argc] = NULL;
            run_parse(parse, argc, argv, &r);
            runs++;
            size_t len = strlen(r.err);
            int one_line = len > 0 && strchr(r.err, '\n') == r.err + len - 1;
            if (r.rc != 2 || !one_line || !strstr(r.err, option)) {
                if (failures++ < 10)
                    fprintf(stderr, "%s %s '%s': returned %d, expected 2 and one line naming the option:\n%s", tool,
                            option, s.v[i], r.rc, r.err);
            }
        }
    }
    printf("%s: %zu options, %zu refused values, %zu failures\n", tool, options, runs, failures);
    TL_CHECK(options >= 3);
    TL_CHECK_EQ_U(failures, 0);
}

#if TL_HAVE_RENDER_ARGS
TL_TEST(render_every_option_refuses_bad_values_in_process)
{
    static const char *const job[] = {"default", "-o", "x.png", "--size", "16x16", "--lights", "1"};
    every_option_refuses("thinlight-render", parse_render, job, 7);
}
#endif

#if TL_HAVE_BENCH_ARGS
TL_TEST(bench_every_option_refuses_bad_values_in_process)
{
    static const char *const job[] = {"--json", "x.json", "--size", "16x16", "--lights", "1", "--frames", "1",
                                      "--warmup", "0", "--modes", "fat", "--strategies", "volumes",
                                      "--light-formats", "rgba16f", "--no-plot"};
    every_option_refuses("thinlight-bench", parse_bench, job, 17);
}
#endif

#if TL_HAVE_VIEWER_ARGS
TL_TEST(viewer_every_option_refuses_bad_values_in_process)
{
    static const char *const job[] = {"--frames", "1", "--screenshot", "x.png"};
    every_option_refuses("thinlight-viewer", parse_viewer, job, 4);
}
#endif

#if TL_HAVE_BENCH_ARGS
/* The bench's bad usage that its parse function refuses (tests/input/bench_bad_input.cmake runs
 * these and the checks after parsing with one process each, in the full tier): 2, one line. */
TL_TEST(bench_bad_usage_in_process)
{
    static const char *const cases[][3] = {
        {"--no-such-flag", NULL, "unknown option"},
        {"stray", NULL, "unexpected argument"},
        {"--lights", NULL, "--lights without a value"},
        {"--lights", "70000", "more than 65536 lights"},
        {"--lights", "8,,64", "empty item in --lights"},
        {"--lights", "eight", "not a count"},
        {"--size", "20000x10", "size over 16384"},
        {"--size", "0x10", "zero size"},
        {"--size", "12by3", "malformed size"},
        {"--modes", "thin-lpp,bogus", "unknown mode"},
        {"--strategies", "tiled,clustered", "unknown light strategy"},
        {"--strategies", NULL, "--strategies without a value"},
        {"--light-formats", "rgba16f,rgb9e5", "unknown light buffer format"},
        {"--frames", "0", "zero frames"},
        {"--effects", "ssao,glow", "unknown effect"},
        {"--effects", "ssao,,fog", "empty item in --effects"},
        {"--effects", NULL, "--effects without a value"},
        {"--bloom-levels", "0", "zero bloom levels"},
        {"--bloom-threshold", "-1", "negative bloom threshold"},
        {"--bloom-scatter", "1.5", "bloom scatter over 1"},
        {"--ssao-samples", "65", "too many SSAO samples"},
        {"--aa", "none,msaa3", "unknown AA method"},
        {"--aa", "fxaa,,none", "empty item in --aa"},
        {"--aa", NULL, "--aa without a value"},
    };
    static captured r;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char *argv[6] = {"thinlight-bench", (char *)cases[i][0], NULL, NULL, NULL, NULL};
        int argc = 2;
        if (cases[i][1]) argv[argc++] = (char *)cases[i][1];
        if (cases[i][1] || strcmp(cases[i][0], "stray") == 0 || strcmp(cases[i][0], "--no-such-flag") == 0) {
            argv[argc++] = "--json";
            argv[argc++] = "x.json";
        }
        run_parse(parse_bench, argc, argv, &r);
        size_t len = strlen(r.err);
        int one_line = len > 0 && strchr(r.err, '\n') == r.err + len - 1;
        if (r.rc != 2 || !one_line) fprintf(stderr, "%s: returned %d, expected 2 and one line:\n%s", cases[i][2], r.rc, r.err);
        TL_CHECK(r.rc == 2 && one_line);
    }
}
#endif

/* ---- the option registry through each tool ------------------------------------------------------ */

/* A tool, a small job it accepts, what its parse returns on success, and where its renderer options
 * land. */
typedef struct tool {
    const char *name;
    parse_fn parse;
    const char *const *job;
    int job_count, ok;
    const tl_renderer_options *options;
} tool;

/* The tool's flag of field f: its own (tool_options.h), or for the bench's swept fields its list. */
static void flag_of(const tool *t, const tl_option_info *f, tl_tool_flag_spec *spec)
{
    tl_tool_flag_spec_of(f, spec);
#if TL_HAVE_BENCH_ARGS
    if (t->parse == parse_bench)
        for (size_t k = 0; bench_swept_fields[k]; k++)
            if (strcmp(bench_swept_fields[k], f->name) == 0) snprintf(spec->name, sizeof spec->name, "%s", bench_swept_flags[k]);
#else
    (void)t;
#endif
}

/* The field's value in the tool's terms (its scale, one number for a broadcast colour). */
static void value_text(const tl_option_info *f, const tl_tool_flag_spec *spec, double v, char *out, size_t size)
{
    if (f->type == TL_OPTION_ENUM || f->type == TL_OPTION_SWITCH) snprintf(out, size, "%s", f->value_name((uint32_t)v));
    else if (f->type == TL_OPTION_TARGETS) tl_test_option_good_text(f, out, size);
    else if (f->type == TL_OPTION_FLOAT3 && !spec->broadcast) snprintf(out, size, "%.9g,%.9g,%.9g", v, v, v);
    else snprintf(out, size, "%.9g", v * spec->scale);
}

/* Whether the parsed tool holds value v in field f: its renderer options, or the bench's sweep. */
static int holds(const tool *t, const tl_option_info *f, double v)
{
#if TL_HAVE_BENCH_ARGS
    if (t->parse == parse_bench) {
        const bench_options *o = &g_bench;
        if (!strcmp(f->name, "mode")) return o->mode_count == 1 && o->modes[0] == (tl_render_mode)v;
        if (!strcmp(f->name, "light_strategy")) return o->strategy_count == 1 && o->strategies[0] == (tl_light_strategy)v;
        if (!strcmp(f->name, "light_format")) return (v == TL_LIGHT_FORMAT_R11G11B10F) == o->small_light_buffer;
        if (!strcmp(f->name, "light_scale")) return v == 0.25 && o->light_scales == 2u; /* bit 1: 2^-2 */
    }
#endif
    const char *at = (const char *)t->options + f->offset;
    for (size_t k = 0; k < (f->type == TL_OPTION_FLOAT3 ? 3u : 1u); k++) {
        float x;
        int32_t n;
        memcpy(&x, at + k * sizeof x, sizeof x);
        memcpy(&n, at, sizeof n);
        double got = f->type == TL_OPTION_FLOAT || f->type == TL_OPTION_FLOAT3 ? (double)x
                     : f->type == TL_OPTION_UINT || f->type == TL_OPTION_TARGETS ? (double)(uint32_t)n
                                                                                   : (double)n;
        if (!(fabs(got - v) <= 1e-6 * fabs(v))) return 0;
    }
    return 1;
}

static int run_job(const tool *t, const char *flag, const char *value, captured *c)
{
    char *argv[40];
    int argc = 0;
    argv[argc++] = (char *)t->name;
    for (int j = 0; j < t->job_count; j++) argv[argc++] = (char *)t->job[j];
    argv[argc++] = (char *)flag;
    if (value) argv[argc++] = (char *)value;
    argv[argc] = NULL;
    run_parse(t->parse, argc, argv, c);
    return c->rc;
}

/* Every field of the registry through one tool: its flag is listed once by --list-options, a value
 * in range (not zero, not the default where the range allows) lands in the field, and each value
 * the registry puts out of range is refused with exit status 2 and one line naming the flag.
 * Returns the fields that failed. */
static size_t registry_through(const tool *t, size_t *refused)
{
    static captured c;
    static char listing[sizeof c.out];
    char *list_argv[] = {(char *)t->name, "--list-options", NULL};
    run_parse(t->parse, 2, list_argv, &c);
    memcpy(listing, c.out, sizeof listing);
    size_t failed = 0;
    for (size_t i = 0; i < tl_option_count(); i++) {
        const tl_option_info *f = tl_option_at(i);
        tl_tool_flag_spec spec;
        flag_of(t, f, &spec);
        char line_start[64];
        snprintf(line_start, sizeof line_start, "\n%s ", spec.name);
        const char *at = strstr(listing, line_start);
        int listed = at && !strstr(at + 1, line_start); /* once */
        double good = tl_test_option_good_value(f);
        char text[256];
        value_text(f, &spec, good, text, sizeof text);
        int taken = run_job(t, spec.name, f->type == TL_OPTION_BOOL ? NULL : text, &c) == t->ok && holds(t, f, good);
        double bad[8];
        size_t n = f->type == TL_OPTION_BOOL ? 0 : tl_test_option_bad_values(f, bad, 8), ok_bad = 0;
        for (size_t b = 0; b < n; b++) {
            value_text(f, &spec, bad[b], text, sizeof text);
            if (f->type == TL_OPTION_ENUM || f->type == TL_OPTION_SWITCH) snprintf(text, sizeof text, "%.0f", bad[b]);
            size_t len;
            int rc = run_job(t, spec.name, text, &c);
            len = strlen(c.err);
            int one_line = len > 0 && strchr(c.err, '\n') == c.err + len - 1;
            ok_bad += rc == 2 && one_line && strstr(c.err, spec.name);
            if (!(rc == 2 && one_line && strstr(c.err, spec.name)))
                fprintf(stderr, "%s %s '%s': returned %d, expected 2 and one line naming it:\n%s", t->name, spec.name,
                        text, rc, c.err);
        }
        *refused += ok_bad;
        if (!listed || !taken || ok_bad != n) {
            failed++;
            fprintf(stderr, "%s: options.%s as %s: %s%s%s\n", t->name, f->name, spec.name, listed ? "" : "not listed once; ",
                    taken ? "" : "a value in range not taken; ", ok_bad == n ? "" : "a value out of range taken");
        }
    }
    return failed;
}

/* The option registry (thinlight/options.h) walked through each tool's own parse function: every field
 * is reachable from thinlight-render, thinlight-bench and thinlight-viewer (a flag listed once, a value
 * in range landing in the field: the bench's swept fields in its sweep) and refused out of range naming
 * the flag. The vignette and PCSS among them. Before the registry (the tools' own tables): thinlight-render
 * reached 59 of the 77 fields, thinlight-bench 42 (its sweeps included), thinlight-viewer 54; the
 * vignette none of them, PCSS (shadows.filter) thinlight-render only. */
TL_TEST(registry_every_option_reachable_from_every_tool)
{
    size_t fields = tl_option_count(), failed = 0, refused = 0, tools = 0;
    TL_CHECK(fields >= 70);
    TL_CHECK(tl_option_find("vignette.enabled") && tl_option_find("shadows.filter"));
#if TL_HAVE_RENDER_ARGS
    static const char *const render_job[] = {"default", "-o", "x.png", "--size", "16x16", "--lights", "1"};
    const tool render = {"thinlight-render", parse_render, render_job, 7, 0, &g_render.rd.options};
    size_t f = registry_through(&render, &refused);
    printf("thinlight-render: %zu of %zu fields reachable and refused out of range\n", fields - f, fields);
    failed += f, tools++;
#endif
#if TL_HAVE_BENCH_ARGS
    static const char *const bench_job[] = {"--json", "x.json", "--size", "16x16", "--lights", "1", "--frames", "1",
                                            "--warmup", "0", "--modes", "fat", "--strategies", "volumes",
                                            "--light-formats", "rgba16f", "--no-plot"};
    const tool bench = {"thinlight-bench", parse_bench, bench_job, 17, 0, &g_bench.base};
    f = registry_through(&bench, &refused);
    printf("thinlight-bench: %zu of %zu fields reachable and refused out of range\n", fields - f, fields);
    failed += f, tools++;
#endif
#if TL_HAVE_VIEWER_ARGS
    static const char *const viewer_job[] = {"--frames", "1", "--screenshot", "x.png"};
    const tool viewer = {"thinlight-viewer", parse_viewer, viewer_job, 4, -1, &g_viewer.desc.options};
    f = registry_through(&viewer, &refused);
    printf("thinlight-viewer: %zu of %zu fields reachable and refused out of range\n", fields - f, fields);
    failed += f, tools++;
#endif
    printf("%zu tools, %zu values out of range refused by name\n", tools, refused);
    TL_CHECK(tools >= 2);
    TL_CHECK(refused > 0);
    TL_CHECK_EQ_U(failed, 0);
}
