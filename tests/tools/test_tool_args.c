/* The tools' one command-line parser (examples/common/tool_args.c) and their logger's once-only
 * lines (tool_log.c), in-process: integers at and past 2^32 and 2^64, signs, spaces, hex and
 * exponents where an integer is wanted, reals that are not finite or not plain decimals, sizes, byte
 * counts with units, lists with empty and surplus items, every kind of option against the same
 * values through a table, and the messages (one line naming the option). */
#define _POSIX_C_SOURCE 200809L /* fmemopen, open_memstream, dup */

#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "tl_test.h"
#include "tool_args.h"
#include "tool_log.h"

TL_TEST(tool_args_u64_boundaries)
{
    uint64_t v = 7;
    TL_CHECK(tl_arg_u64("0", 0, UINT64_MAX, &v) == TL_ARG_OK && v == 0);
    TL_CHECK(tl_arg_u64("4294967295", 0, UINT64_MAX, &v) == TL_ARG_OK && v == UINT32_MAX);
    TL_CHECK(tl_arg_u64("4294967296", 0, UINT64_MAX, &v) == TL_ARG_OK && v == (uint64_t)UINT32_MAX + 1);
    TL_CHECK(tl_arg_u64("18446744073709551615", 0, UINT64_MAX, &v) == TL_ARG_OK && v == UINT64_MAX);
    TL_CHECK(tl_arg_u64("0018446744073709551615", 0, UINT64_MAX, &v) == TL_ARG_OK && v == UINT64_MAX);
    v = 7;
    TL_CHECK(tl_arg_u64("18446744073709551616", 0, UINT64_MAX, &v) == TL_ARG_RANGE); /* 2^64 */
    TL_CHECK(tl_arg_u64("99999999999999999999999", 0, UINT64_MAX, &v) == TL_ARG_RANGE);
    TL_CHECK(tl_arg_u64("36893488147419103232", 0, UINT64_MAX, &v) == TL_ARG_RANGE); /* 2^65 */
    TL_CHECK(v == 7); /* untouched on failure */
    TL_CHECK(tl_arg_u64("10", 0, 9, &v) == TL_ARG_RANGE);
    TL_CHECK(tl_arg_u64("0", 1, 9, &v) == TL_ARG_RANGE);
    /* wider past 2^64 with trailing garbage: the garbage is what is wrong */
    TL_CHECK(tl_arg_u64("99999999999999999999999x", 0, UINT64_MAX, &v) == TL_ARG_SYNTAX);
}

TL_TEST(tool_args_u32_boundaries_and_wrapping)
{
    uint32_t v = 7;
    TL_CHECK(tl_arg_u32("0", 0, UINT32_MAX, &v) == TL_ARG_OK && v == 0);
    TL_CHECK(tl_arg_u32("4294967295", 0, UINT32_MAX, &v) == TL_ARG_OK && v == UINT32_MAX);
    v = 7;
    TL_CHECK(tl_arg_u32("4294967296", 0, UINT32_MAX, &v) == TL_ARG_RANGE); /* 2^32: no wrap to 0 */
    TL_CHECK(tl_arg_u32("4294967297", 0, UINT32_MAX, &v) == TL_ARG_RANGE); /* 2^32 + 1: no wrap to 1 */
    TL_CHECK(tl_arg_u32("18446744073709551617", 0, UINT32_MAX, &v) == TL_ARG_RANGE);
    TL_CHECK(v == 7);
}

TL_TEST(tool_args_integers_are_plain_decimal_digits)
{
    static const char *const bad[] = {"-1", "-0", "+1", " 1", "1 ", "\t1", "0x10", "0X10", "010x", "1e3", "1E3",
                                      "1.0", "1.", ".5", "1,2", "12x", "x12", "nan", "inf", "one", "1_000"};
    uint32_t v = 7;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        tl_arg_status st = tl_arg_u32(bad[i], 0, UINT32_MAX, &v);
        if (st != TL_ARG_SYNTAX) printf("'%s': status %d\n", bad[i], (int)st);
        TL_CHECK(st == TL_ARG_SYNTAX);
    }
    TL_CHECK(tl_arg_u32("", 0, UINT32_MAX, &v) == TL_ARG_EMPTY);
    TL_CHECK(tl_arg_u32(NULL, 0, UINT32_MAX, &v) == TL_ARG_EMPTY);
    TL_CHECK(v == 7);
    TL_CHECK(tl_arg_u32("010", 0, UINT32_MAX, &v) == TL_ARG_OK && v == 10); /* decimal, not octal */
}

TL_TEST(tool_args_reals_finite_decimal_in_range)
{
    tl_arg_range any = {-FLT_MAX, FLT_MAX, 0, 0}, positive = {0.0, 1e6, 1, 0}, unit_open = {0.0, 1.0, 0, 1};
    double v = 0.0;
    TL_CHECK(tl_arg_real("1", &any, &v) == TL_ARG_OK && v == 1.0);
    TL_CHECK(tl_arg_real("-2.5", &any, &v) == TL_ARG_OK && v == -2.5);
    TL_CHECK(tl_arg_real(".5", &any, &v) == TL_ARG_OK && v == 0.5);
    TL_CHECK(tl_arg_real("5.", &any, &v) == TL_ARG_OK && v == 5.0);
    TL_CHECK(tl_arg_real("1e3", &any, &v) == TL_ARG_OK && v == 1000.0);
    TL_CHECK(tl_arg_real("1E-3", &any, &v) == TL_ARG_OK && v == 1e-3);
    TL_CHECK(tl_arg_real("2.5e+1", &any, &v) == TL_ARG_OK && v == 25.0);
    TL_CHECK(tl_arg_real("1e-999", &any, &v) == TL_ARG_OK && v == 0.0); /* underflow is 0, not an error */
    static const char *const syntax[] = {"nan", "NaN", "-nan", "inf", "-inf", "infinity", "0x10", "0x1p3", "+1", " 1",
                                         "1 ", "1e", "1e+", "e3", ".", "-", "1..2", "1,5", "12x", "1f", "--1"};
    for (size_t i = 0; i < sizeof syntax / sizeof syntax[0]; i++) {
        tl_arg_status st = tl_arg_real(syntax[i], &any, &v);
        if (st != TL_ARG_SYNTAX) printf("'%s': status %d\n", syntax[i], (int)st);
        TL_CHECK(st == TL_ARG_SYNTAX);
    }
    TL_CHECK(tl_arg_real("", &any, &v) == TL_ARG_EMPTY);
    TL_CHECK(tl_arg_real("1e999", &any, &v) == TL_ARG_RANGE);
    TL_CHECK(tl_arg_real("-1e999", &any, &v) == TL_ARG_RANGE);
    TL_CHECK(tl_arg_real("1e39", &any, &v) == TL_ARG_RANGE); /* finite as a double, not as a float */
    TL_CHECK(tl_arg_real("0", &positive, &v) == TL_ARG_RANGE);   /* an open end */
    TL_CHECK(tl_arg_real("-0", &positive, &v) == TL_ARG_RANGE);
    TL_CHECK(tl_arg_real("1e6", &positive, &v) == TL_ARG_OK);     /* a closed end */
    TL_CHECK(tl_arg_real("1000000.1", &positive, &v) == TL_ARG_RANGE);
    TL_CHECK(tl_arg_real("1", &unit_open, &v) == TL_ARG_RANGE);
    TL_CHECK(tl_arg_real("0.999", &unit_open, &v) == TL_ARG_OK && v == 0.999);
}

TL_TEST(tool_args_sizes)
{
    uint32_t w = 0, h = 0;
    TL_CHECK(tl_arg_size("1x1", 1, 16384, &w, &h) == TL_ARG_OK && w == 1 && h == 1);
    TL_CHECK(tl_arg_size("16384x9", 1, 16384, &w, &h) == TL_ARG_OK && w == 16384 && h == 9);
    w = h = 7;
    TL_CHECK(tl_arg_size("4294967297x1", 1, 16384, &w, &h) == TL_ARG_RANGE); /* wrapped to 1x1 before */
    TL_CHECK(tl_arg_size("1x4294967297", 1, 16384, &w, &h) == TL_ARG_RANGE);
    TL_CHECK(tl_arg_size("18446744073709551617x1", 1, 16384, &w, &h) == TL_ARG_RANGE);
    TL_CHECK(tl_arg_size("16385x1", 1, 16384, &w, &h) == TL_ARG_RANGE);
    TL_CHECK(tl_arg_size("0x10", 1, 16384, &w, &h) == TL_ARG_RANGE);
    static const char *const syntax[] = {"12x", "x12", "12", "12X12", "12x12x12", " 12x12", "12x12 ", "+12x12",
                                         "-1x12", "12x-1", "1e3x12", "12.0x12", "12*12", "12,12"};
    for (size_t i = 0; i < sizeof syntax / sizeof syntax[0]; i++) {
        tl_arg_status st = tl_arg_size(syntax[i], 1, 16384, &w, &h);
        if (st != TL_ARG_SYNTAX) printf("'%s': status %d\n", syntax[i], (int)st);
        TL_CHECK(st == TL_ARG_SYNTAX);
    }
    TL_CHECK(tl_arg_size("", 1, 16384, &w, &h) == TL_ARG_EMPTY);
    TL_CHECK(w == 7 && h == 7);
}

TL_TEST(tool_args_byte_counts_with_units)
{
    uint64_t v = 0;
    TL_CHECK(tl_arg_bytes("1", 1, UINT64_MAX, &v) == TL_ARG_OK && v == 1);
    TL_CHECK(tl_arg_bytes("3KiB", 1, UINT64_MAX, &v) == TL_ARG_OK && v == 3072);
    TL_CHECK(tl_arg_bytes("512MiB", 1, UINT64_MAX, &v) == TL_ARG_OK && v == (uint64_t)512 << 20);
    TL_CHECK(tl_arg_bytes("2GiB", 1, UINT64_MAX, &v) == TL_ARG_OK && v == (uint64_t)2 << 30);
    TL_CHECK(tl_arg_bytes("16777215TiB", 1, UINT64_MAX, &v) == TL_ARG_OK && v == (uint64_t)16777215 << 40);
    TL_CHECK(tl_arg_bytes("16777216TiB", 1, UINT64_MAX, &v) == TL_ARG_RANGE); /* 2^64 */
    TL_CHECK(tl_arg_bytes("18446744073709551616", 1, UINT64_MAX, &v) == TL_ARG_RANGE);
    TL_CHECK(tl_arg_bytes("0", 1, UINT64_MAX, &v) == TL_ARG_RANGE);
    TL_CHECK(tl_arg_bytes("2GiB", 1, (uint64_t)1 << 30, &v) == TL_ARG_RANGE);
    static const char *const syntax[] = {"MiB", "1 MiB", "1mib", "1MB", "1M", "1KB", "1GiBx", "-1", "+1", "1.5GiB",
                                         "1e3", "0x10", " 1"};
    for (size_t i = 0; i < sizeof syntax / sizeof syntax[0]; i++) {
        tl_arg_status st = tl_arg_bytes(syntax[i], 1, UINT64_MAX, &v);
        if (st != TL_ARG_SYNTAX) printf("'%s': status %d\n", syntax[i], (int)st);
        TL_CHECK(st == TL_ARG_SYNTAX);
    }
    TL_CHECK(tl_arg_bytes("", 1, UINT64_MAX, &v) == TL_ARG_EMPTY);
}

TL_TEST(tool_args_lists_refuse_empty_and_surplus_items)
{
    char buf[64], *items[4];
    size_t n = 0;
    TL_CHECK(tl_arg_split("a,b,c", buf, sizeof buf, items, 4, &n) == TL_ARG_OK && n == 3);
    TL_CHECK(n == 3 && !strcmp(items[0], "a") && !strcmp(items[2], "c"));
    TL_CHECK(tl_arg_split("a", buf, sizeof buf, items, 4, &n) == TL_ARG_OK && n == 1);
    static const char *const empty[] = {"", ",", "a,", ",a", "a,,b", ",,"};
    for (size_t i = 0; i < sizeof empty / sizeof empty[0]; i++)
        TL_CHECK(tl_arg_split(empty[i], buf, sizeof buf, items, 4, &n) == TL_ARG_EMPTY);
    TL_CHECK(tl_arg_split("a,b,c,d,e", buf, sizeof buf, items, 4, &n) == TL_ARG_TOO_MANY);
    char longer[100];
    memset(longer, 'a', sizeof longer - 1);
    longer[sizeof longer - 1] = '\0';
    TL_CHECK(tl_arg_split(longer, buf, sizeof buf, items, 4, &n) == TL_ARG_TOO_MANY); /* never truncated */
}

/* ---- options through a table ---------------------------------------------------------------- */

static const char *const test_names[] = {"one", "two", NULL};
static const int test_values[] = {10, 20};
static const tl_opt test_opts[] = {
    {"--flag", TL_OPT_FLAG, .id = 1},
    {"--text", TL_OPT_TEXT, .id = 2},
    {"--count", TL_OPT_UINT, .id = 3, .lo = 1, .hi = 100},
    {"--real", TL_OPT_REAL, .id = 4, .min = 0.0, .max = 1.0, .flags = TL_OPT_MIN_OPEN},
    {"--size", TL_OPT_SIZE, .id = 5, .lo = 1, .hi = 16384},
    {"--bytes", TL_OPT_BYTES, .id = 6, .lo = 1, .hi = UINT64_MAX, .flags = TL_OPT_NONE},
    {"--names", TL_OPT_TEXT_LIST, .id = 7, .items = 3, .choices = test_names, .values = test_values},
    {"--counts", TL_OPT_UINT_LIST, .id = 8, .lo = 0, .hi = 65536, .items = 4},
    {"--sizes", TL_OPT_SIZE_LIST, .id = 9, .lo = 1, .hi = 16384, .items = 2},
    {"--rgb", TL_OPT_REALS, .id = 10, .min = 0.0, .max = FLT_MAX, .items = 3},
    {"--choice", TL_OPT_TEXT, .id = 11, .choices = test_names, .values = test_values},
};

/* Parses argv[1..] (a NULL-terminated list) with test_opts; the last status, stderr's text in
 * `err`, the last option parsed and its value. */
typedef struct parsed {
    int status, options;
    const tl_opt *last;
    tl_opt_value value;
    char err[1024];
} parsed;

static void parse(parsed *p, const char *const *args)
{
    char *argv[16] = {"tool"};
    int argc = 1;
    for (; args[argc - 1] && argc < 16; argc++) argv[argc] = (char *)args[argc - 1];
    memset(p, 0, sizeof *p);
    const tl_opt_table tables[] = {TL_OPT_TABLE(test_opts)};
    tl_opt_parser parser;
    tl_opt_begin(&parser, "tool", argc, argv, tables, 1);
    fflush(stderr);
    int saved = dup(fileno(stderr));
    FILE *capture = tmpfile();
    if (!capture || saved < 0) return;
    dup2(fileno(capture), fileno(stderr));
    const tl_opt *o;
    tl_opt_value v;
    while ((p->status = tl_opt_next(&parser, &o, &v)) == 1) {
        p->options++;
        p->last = o;
        p->value = v; /* the numbers; item[] still points into v */
    }
    fflush(stderr);
    dup2(saved, fileno(stderr));
    close(saved);
    rewind(capture);
    size_t n = fread(p->err, 1, sizeof p->err - 1, capture);
    p->err[n] = '\0';
    fclose(capture);
}

/* Exactly one line, naming `option`. */
static int one_line_naming(const char *err, const char *option)
{
    const char *nl = strchr(err, '\n');
    return nl && nl[1] == '\0' && strstr(err, option) != NULL && strncmp(err, "tool: ", 6) == 0;
}

TL_TEST(tool_args_table_parses_every_kind)
{
    parsed p;
    parse(&p, (const char *const[]){"--flag", "pos", "--text", "x y", "--count", "100", NULL});
    TL_CHECK(p.status == 0 && p.options == 4 && p.err[0] == '\0');
    parse(&p, (const char *const[]){"--real", "1", NULL});
    TL_CHECK(p.status == 0 && p.last && p.last->id == 4 && p.value.f[0] == 1.0);
    parse(&p, (const char *const[]){"--size", "640x360", NULL});
    TL_CHECK(p.status == 0 && p.value.w[0] == 640 && p.value.h[0] == 360);
    parse(&p, (const char *const[]){"--bytes", "none", NULL});
    TL_CHECK(p.status == 0 && p.value.none == 1);
    parse(&p, (const char *const[]){"--bytes", "4GiB", NULL});
    TL_CHECK(p.status == 0 && !p.value.none && p.value.u[0] == (uint64_t)4 << 30);
    parse(&p, (const char *const[]){"--names", "two,one", NULL});
    TL_CHECK(p.status == 0 && p.value.count == 2 && p.value.u[0] == 20 && p.value.u[1] == 10);
    parse(&p, (const char *const[]){"--counts", "0,65536,8", NULL});
    TL_CHECK(p.status == 0 && p.value.count == 3 && p.value.u[1] == 65536);
    parse(&p, (const char *const[]){"--sizes", "1x2,3x4", NULL});
    TL_CHECK(p.status == 0 && p.value.count == 2 && p.value.w[1] == 3 && p.value.h[1] == 4);
    parse(&p, (const char *const[]){"--rgb", "0,0.5,2", NULL});
    TL_CHECK(p.status == 0 && p.value.count == 3 && p.value.f[2] == 2.0);
    parse(&p, (const char *const[]){"--choice", "two", NULL});
    TL_CHECK(p.status == 0 && p.value.u[0] == 20);
    parse(&p, (const char *const[]){"-", NULL}); /* "-" alone is an argument */
    TL_CHECK(p.status == 0 && p.options == 1 && p.last == NULL);
}

TL_TEST(tool_args_table_refuses_with_one_line_naming_the_option)
{
    static const char *const cases[][2] = {
        {"--count", "4294967297"}, {"--count", "-1"}, {"--count", "1e999"}, {"--count", "12x"}, {"--count", ""},
        {"--count", "101"},       {"--count", "0"},  {"--count", "0x10"},  {"--count", "+5"},  {"--count", " 5"},
        {"--real", "0"},          {"--real", "nan"}, {"--real", "1e999"}, {"--real", "-1"},  {"--real", "12x"},
        {"--real", "inf"},        {"--real", ""},    {"--size", "4294967297x1"}, {"--size", "12x"}, {"--size", ""},
        {"--size", "-1x1"},       {"--bytes", "1e999"}, {"--bytes", "-1"}, {"--bytes", "12x"}, {"--bytes", "0"},
        {"--bytes", ""},          {"--names", "one,,two"}, {"--names", "one,three"}, {"--names", "one,one,one,one"},
        {"--names", ""},          {"--counts", "8,4294967297"}, {"--counts", "8,-1"}, {"--counts", "8,"},
        {"--counts", "1,2,3,4,5"}, {"--sizes", "1x1,12x"}, {"--sizes", "1x1,,1x1"}, {"--rgb", "1,2"},
        {"--rgb", "1,2,3,4"},     {"--rgb", "1,2,nan"}, {"--rgb", "1,2,-1"}, {"--choice", "three"},
        {"--choice", "4294967297"}, {"--text", ""},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        parsed p;
        parse(&p, (const char *const[]){"--flag", cases[i][0], cases[i][1], NULL});
        int ok = p.status == 2 && one_line_naming(p.err, cases[i][0]);
        if (!ok) printf("%s '%s': status %d, stderr: %s\n", cases[i][0], cases[i][1], p.status, p.err);
        TL_CHECK(ok);
    }
    parsed p;
    parse(&p, (const char *const[]){"--unknown-flag", NULL});
    TL_CHECK(p.status == 2 && one_line_naming(p.err, "unknown option '--unknown-flag'"));
    parse(&p, (const char *const[]){"--count", NULL});
    TL_CHECK(p.status == 2 && one_line_naming(p.err, "--count needs a value"));
    printf("e.g. %s", p.err);
}

TL_TEST(tool_args_list_options_names_kinds_and_ranges)
{
    char *text = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&text, &size);
    TL_CHECK(f != NULL);
    if (!f) return;
    const tl_opt_table tables[] = {TL_OPT_TABLE(test_opts)};
    tl_opt_list(f, tables, 1);
    fclose(f);
    printf("%s", text);
    TL_CHECK(strstr(text, "--flag flag\n") && strstr(text, "--count uint 1 100\n") &&
             strstr(text, "--real real 0 1 min-open\n") && strstr(text, "--size size 1 16384\n") &&
             strstr(text, "--bytes bytes 1 18446744073709551615 none\n") && strstr(text, "--names text-list one,two\n") &&
             strstr(text, "--rgb reals 0 3.40282347e+38\n") && strstr(text, "--choice text one,two\n"));
    free(text);
}

/* ---- the logger ----------------------------------------------------------------------------- */

TL_TEST(tool_log_prints_each_line_once)
{
    tl_tool_log log = {.tool = "tool"};
    fflush(stderr);
    int saved = dup(fileno(stderr));
    FILE *capture = tmpfile();
    TL_CHECK(capture && saved >= 0);
    if (!capture || saved < 0) return;
    dup2(fileno(capture), fileno(stderr));
    tl_logger l = tl_tool_log_logger(&log);
    for (int i = 0; i < 10; i++) { /* ten renderers of one scene, each warning alike */
        l.fn(l.user, TL_LOG_WARNING, "textures[0]: dropped");
        l.fn(l.user, TL_LOG_INFO, "planned");
    }
    l.fn(l.user, TL_LOG_WARNING, "textures[1]: dropped");
    l.fn(l.user, TL_LOG_ERROR, "renderer: invalid camera");
    tl_tool_log_error(&log, "%s", "renderer: invalid camera"); /* the tool repeating the logger's line */
    l.fn(l.user, TL_LOG_ERROR, "textures[0]: dropped"); /* the same text at another level is another line */
    fflush(stderr);
    dup2(saved, fileno(stderr));
    close(saved);
    char text[1024];
    rewind(capture);
    size_t n = fread(text, 1, sizeof text - 1, capture);
    text[n] = '\0';
    fclose(capture);
    printf("%s", text);
    TL_CHECK(!strcmp(text, "tool: warning: textures[0]: dropped\n"
                           "tool: warning: textures[1]: dropped\n"
                           "tool: renderer: invalid camera\n"
                           "tool: textures[0]: dropped\n"));
    TL_CHECK_EQ_U(log.repeats, 10);
}
