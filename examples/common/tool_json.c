/* JSON output for the tools: escaped strings, numbers that stay valid JSON (null for NaN and Inf),
 * and a streaming writer that handles commas and indentation. */
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "tool_util.h"

void tl_tool_json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; s && *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') fprintf(f, "\\%c", c);
        else if (c < 0x20) fprintf(f, "\\u%04x", c);
        else fputc(c, f);
    }
    fputc('"', f);
}

void tl_tool_json_number(FILE *f, double v)
{
    if (isfinite(v)) fprintf(f, "%.9g", v);
    else fputs("null", f);
}

void tl_tool_json_begin(tl_tool_json *j, FILE *f)
{
    memset(j, 0, sizeof *j);
    j->f = f;
}

/* Separator, line break and indentation before a member, then its key. */
static void tl__json_member(tl_tool_json *j, const char *key)
{
    int d = j->depth;
    if (j->count[d]++) fputc(',', j->f);
    if (d > 0 && j->inline_[d]) {
        if (j->count[d] > 1) fputc(' ', j->f);
    } else if (d > 0) {
        fprintf(j->f, "\n%*s", 2 * d, "");
    }
    if (key) {
        tl_tool_json_string(j->f, key);
        fputs(": ", j->f);
    }
}

static void tl__json_open(tl_tool_json *j, const char *key, int inline_members, char bracket)
{
    tl__json_member(j, key);
    fputc(bracket, j->f);
    if (j->depth + 1 < TL_TOOL_JSON_MAX_DEPTH) j->depth++;
    j->count[j->depth] = 0;
    j->inline_[j->depth] = inline_members || j->inline_[j->depth - 1];
}

void tl_tool_json_object(tl_tool_json *j, const char *key, int inline_members)
{
    tl__json_open(j, key, inline_members, '{');
}

void tl_tool_json_array(tl_tool_json *j, const char *key, int inline_members)
{
    tl__json_open(j, key, inline_members, '[');
}

void tl_tool_json_close(tl_tool_json *j, char bracket)
{
    int d = j->depth;
    if (j->count[d] && !j->inline_[d]) fprintf(j->f, "\n%*s", 2 * (d - 1), "");
    fputc(bracket, j->f);
    if (j->depth > 0) j->depth--;
}

void tl_tool_json_str(tl_tool_json *j, const char *key, const char *value)
{
    tl__json_member(j, key);
    tl_tool_json_string(j->f, value);
}

void tl_tool_json_num(tl_tool_json *j, const char *key, double value)
{
    tl__json_member(j, key);
    tl_tool_json_number(j->f, value);
}

void tl_tool_json_uint(tl_tool_json *j, const char *key, uint64_t value)
{
    tl__json_member(j, key);
    fprintf(j->f, "%" PRIu64, value);
}

void tl_tool_json_bool(tl_tool_json *j, const char *key, int value)
{
    tl__json_member(j, key);
    fputs(value ? "true" : "false", j->f);
}

void tl_tool_json_end(tl_tool_json *j) { fputc('\n', j->f); }
