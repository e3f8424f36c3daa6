/* The option registry itself (thinlight/options.h), no GL: it holds every field of
 * tl_renderer_options once (the rows tile the struct byte for byte), each field's text round-trips
 * through tl_option_parse and tl_option_format and every value its row puts out of range is refused
 * naming the field, the enum names round-trip, and docs/renderer.md's table of options is the
 * registry's (the case prints the table it expects). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "option_values.h"
#include "tl_test.h"

/* Every byte of tl_renderer_options belongs to exactly one row (its fields are all 4 bytes wide:
 * no padding), names are unique and tl_option_find finds each row. A field added to the struct
 * without a row leaves bytes uncovered. */
TL_TEST(option_registry_covers_every_field_once)
{
    static unsigned char owner[sizeof(tl_renderer_options)];
    memset(owner, 0, sizeof owner);
    size_t n = tl_option_count(), overlaps = 0, covered = 0, unfound = 0;
    for (size_t i = 0; i < n; i++) {
        const tl_option_info *o = tl_option_at(i);
        TL_CHECK(o && o->name && o->help && o->unit && o->offset + o->size <= sizeof(tl_renderer_options));
        if (!o || o->offset + o->size > sizeof(tl_renderer_options)) continue;
        unfound += tl_option_find(o->name) != o;
        for (size_t b = o->offset; b < o->offset + o->size; b++) overlaps += owner[b]++ != 0;
    }
    for (size_t b = 0; b < sizeof owner; b++) covered += owner[b] != 0;
    printf("  %zu rows cover %zu of %zu bytes of tl_renderer_options; %zu overlapping, %zu not found by name\n", n,
           covered, sizeof owner, overlaps, unfound);
    TL_CHECK(tl_option_at(n) == NULL && tl_option_find("no.such") == NULL && tl_option_find(NULL) == NULL);
    TL_CHECK_EQ_U(covered, sizeof owner);
    TL_CHECK_EQ_U(overlaps, 0);
    TL_CHECK_EQ_U(unfound, 0);
}

/* Each field: its good text (option_values.h) parses, formats back to text that parses to the same
 * bytes, and each value out of range is refused with one line "options.NAME = ..." leaving the
 * options as they were. */
TL_TEST(option_parse_format_round_trip_and_refusals_every_field)
{
    size_t fields = 0, refused = 0, values = 0;
    for (size_t i = 0; i < tl_option_count(); i++) {
        const tl_option_info *o = tl_option_at(i);
        tl_renderer_options a = {0}, b = {0};
        char text[256], back[512];
        tl_test_option_good_text(o, text, sizeof text);
        tl_error_capture log = {0};
        tl_logger logger = {tl_error_capture_log, &log};
        int ok = tl_option_parse(o, text, &a, &logger) == TL_OK;
        tl_option_format(o, &a, back, sizeof back);
        ok = ok && tl_option_parse(o, back, &b, &logger) == TL_OK && memcmp(&a, &b, sizeof a) == 0 &&
             tl_option_value_valid(o, tl_test_option_good_value(o));
        if (!ok) fprintf(stderr, "  %s: '%s' -> '%s' does not round-trip (%s)\n", o->name, text, back, log.last);
        fields += (size_t)ok;
        double bad[8];
        size_t n = tl_test_option_bad_values(o, bad, 8);
        for (size_t k = 0; k < n; k++) {
            char want[96];
            snprintf(text, sizeof text, "%.9g", bad[k]);
            snprintf(want, sizeof want, "options.%s = ", o->name);
            tl_renderer_options c = a;
            tl_error_capture l = {0};
            tl_logger lg = {tl_error_capture_log, &l};
            int r = tl_option_parse(o, text, &c, &lg) == TL_ERROR_INVALID_ARGUMENT && l.errors == 1 &&
                    strncmp(l.last, want, strlen(want)) == 0 && memcmp(&c, &a, sizeof a) == 0 &&
                    !tl_option_value_valid(o, bad[k]);
            if (!r) fprintf(stderr, "  %s = %s: not refused by name: \"%s\"\n", o->name, text, l.last);
            refused += (size_t)r;
            values++;
        }
    }
    printf("  %zu of %zu fields round-trip; %zu of %zu values out of range refused naming the field\n", fields,
           tl_option_count(), refused, values);
    TL_CHECK_EQ_U(fields, tl_option_count());
    TL_CHECK_EQ_U(refused, values);
    TL_CHECK(tl_option_parse(NULL, "1", &(tl_renderer_options){0}, NULL) == TL_ERROR_INVALID_ARGUMENT);
}

/* Every value of every enumerated field has a name, the name gives back the value (or the value
 * DEFAULT stands for, which has the same name), and a name of none is refused. */
TL_TEST(option_enum_names_round_trip)
{
    size_t names = 0, bad = 0;
    for (size_t i = 0; i < tl_option_count(); i++) {
        const tl_option_info *o = tl_option_at(i);
        if (o->type != TL_OPTION_ENUM && o->type != TL_OPTION_SWITCH) continue;
        for (uint32_t v = 0; v < o->count; v++) {
            const char *name = o->value_name(v);
            tl_renderer_options r = {0};
            int got = -1;
            if (tl_option_parse(o, name, &r, NULL) == TL_OK) memcpy(&got, (char *)&r + o->offset, sizeof got);
            int ok = got >= 0 && strcmp(o->value_name((uint32_t)got), name) == 0 && strcmp(name, "unknown") != 0;
            if (!ok) fprintf(stderr, "  %s value %u: name '%s' gives %d\n", o->name, v, name, got);
            bad += !ok;
            names++;
        }
        TL_CHECK(strcmp(o->value_name(o->count), "unknown") == 0);
        TL_CHECK(tl_option_parse(o, "no-such-name", &(tl_renderer_options){0}, NULL) == TL_ERROR_INVALID_ARGUMENT);
    }
    tl_render_mode m;
    tl_shadow_filter f;
    tl_switch s;
    TL_CHECK(tl_render_mode_from_name("fat", &m) == TL_OK && m == TL_MODE_FAT);
    TL_CHECK(tl_shadow_filter_from_name("bilinear", &f) == TL_OK && f == TL_SHADOW_FILTER_BILINEAR);
    TL_CHECK(tl_switch_from_name("off", &s) == TL_OK && s == TL_SWITCH_OFF);
    TL_CHECK(strcmp(tl_fxaa_preset_name(TL_FXAA_DEFAULT), "29") == 0);
    printf("  %zu names of enumerated fields, %zu not round-tripping\n", names, bad);
    TL_CHECK_EQ_U(bad, 0);
}

/* ---- docs/renderer.md's table ------------------------------------------------------------------- */

static const char *const k_types[TL_OPTION_TYPE_COUNT_] = {"bool", "switch", "enum", "uint", "float", "float[3]",
                                                          "targets"};

/* One row of the table: field, type, values (enums: their names) and default, unit, help. */
static void doc_row(const tl_option_info *o, char *out, size_t size)
{
    char range[512] = "";
    if (o->type == TL_OPTION_ENUM || o->type == TL_OPTION_SWITCH) {
        for (uint32_t v = 1; v <= o->count; v++) { /* DEFAULT last, where it has a name of its own */
            const char *name = o->value_name(v % o->count);
            int alias = 0;
            for (uint32_t w = 1; v == o->count && w < o->count; w++) alias |= strcmp(name, o->value_name(w)) == 0;
            if (!alias) snprintf(range + strlen(range), sizeof range - strlen(range), "%s`%s`", range[0] ? ", " : "", name);
        }
        snprintf(range + strlen(range), sizeof range - strlen(range), "; 0: %s",
                 o->zero_text ? o->zero_text : o->value_name((uint32_t)o->zero));
    } else {
        tl_option_range_format(o, range, sizeof range);
    }
    snprintf(out, size, "| `%s` | %s%s%s | %s | %s | %s |", o->name, k_types[o->type], o->c_type ? " " : "",
             o->c_type ? o->c_type : "", range, o->unit, o->help);
}

/* The rows between <!-- options:begin --> and <!-- options:end --> of docs/renderer.md are the
 * registry's, one per field in its order, after the header. */
TL_TEST(docs_renderer_md_lists_every_option)
{
    FILE *f = fopen(TL_SOURCE_DIR "/docs/renderer.md", "rb");
    TL_CHECK(f != NULL);
    if (!f) return;
    static char doc[1 << 20];
    size_t len = fread(doc, 1, sizeof doc - 1, f);
    fclose(f);
    doc[len] = '\0';
    const char *begin = strstr(doc, "<!-- options:begin -->\n"), *end = strstr(doc, "<!-- options:end -->");
    TL_CHECK(begin && end && begin < end);
    static char want[1 << 16];
    size_t at = (size_t)snprintf(want, sizeof want, "| option | type | range; 0 (the default) | unit | what |\n"
                                                    "|---|---|---|---|---|\n");
    for (size_t i = 0; i < tl_option_count() && at < sizeof want; i++) {
        char row[1024];
        doc_row(tl_option_at(i), row, sizeof row);
        at += (size_t)snprintf(want + at, sizeof want - at, "%s\n", row);
    }
    int same = begin && end && (size_t)(end - begin) == strlen("<!-- options:begin -->\n") + strlen(want) &&
               memcmp(begin + strlen("<!-- options:begin -->\n"), want, strlen(want)) == 0;
    if (!same) fprintf(stderr, "docs/renderer.md's table of options differs from the registry; it should read:\n%s", want);
    printf("  %zu options in the registry, the table in docs/renderer.md %s\n", tl_option_count(),
           same ? "lists each" : "differs");
    TL_CHECK(same);
}
