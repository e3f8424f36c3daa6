/* What the renderer refuses says exactly what is wrong (issue 38): every option out of range names
 * the field, the value and the range (every field of the option registry, so a new option needs no
 * line here); a
 * scene's bad object names the one field that fails; an MSAA count over the context's names
 * options.msaa; and reading the output before a frame drew it is refused, not zero bytes. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "option_values.h"
#include "render_room.h"
#include "tl_test.h"

#define W 64
#define H 64

static tl_renderer *renderer(tl_error_capture *log)
{
    return tl_test_renderer(&(tl_test_renderer_desc){.renderer = {.width = W, .height = H, .logger = {tl_error_capture_log, log}}});
}

static void lit_room(test_scene *t)
{
    build_room(t);
    t->lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {3, 6, -2}, .color = {60, 55, 50}, .radius = 30};
    t->s.light_count = 1;
}

/* ---- reading the output before a frame ---------------------------------------------------------- */

/* read_output before render drew a frame at the renderer's size (none yet, only render_to, or a
 * resize since) is TL_ERROR_INVALID_ARGUMENT saying so, and the buffer is left alone; after a
 * render it reads. Before: TL_OK and whatever the fresh target held. */
TL_TEST(renderer_read_output_before_any_frame_refused)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_error_capture log = {0};
    tl_renderer *r = renderer(&log);
    if (!r) return;
    static test_scene t;
    lit_room(&t);
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
    static uint8_t px[W * H * 4], blank[W * H * 4];
    memset(px, 0xAB, sizeof px);
    memset(blank, 0xAB, sizeof blank);
    size_t size = 0;
    TL_CHECK(tl_renderer_read_output(r, NULL, &size) == TL_OK && size == sizeof px); /* asking is fine */
    const char *why = "tl_renderer_read_output: no frame was rendered into the output at 64x64";
    int refused = 0;
    tl_result res = tl_renderer_read_output(r, px, &size);
    refused += res == TL_ERROR_INVALID_ARGUMENT && strstr(log.last, why) && memcmp(px, blank, sizeof px) == 0;
    printf("  before any frame: %s \"%s\"\n", tl_result_string(res), log.last);
    /* render_to draws into the caller's framebuffer (0: OSMesa's), not the output */
    TL_CHECK(tl_renderer_render_to(r, NULL, &(tl_render_output){0}, NULL) == TL_OK);
    res = tl_renderer_read_output(r, px, &size);
    refused += res == TL_ERROR_INVALID_ARGUMENT && strstr(log.last, why) && memcmp(px, blank, sizeof px) == 0;
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_read_output(r, px, &size) == TL_OK && memcmp(px, blank, sizeof px) != 0);
    TL_CHECK(tl_renderer_resize(r, 32, 32) == TL_OK);
    memset(px, 0xAB, sizeof px);
    size = sizeof px;
    res = tl_renderer_read_output(r, px, &size);
    refused += res == TL_ERROR_INVALID_ARGUMENT && strstr(log.last, "no frame was rendered into the output at 32x32") &&
               memcmp(px, blank, sizeof px) == 0;
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_read_output(r, px, &size) == TL_OK && size == (size_t)32 * 32 * 4);
    printf("  %d of 3 reads refused (before a frame, after render_to only, after a resize)\n", refused);
    TL_CHECK_EQ_U(refused, 3);
    tl_renderer_destroy(r);
}

/* ---- options: every field of the registry ------------------------------------------------------ */

/* The line set_options must log for `o` refused at field `i` (component k) holding `v`: the field, the
 * value as it was given, the registry's range. */
static void refusal_line(const tl_option_info *i, size_t k, double v, char *out, size_t size)
{
    char range[200], value[48], index[8] = "";
    tl_option_range_format(i, range, sizeof range);
    if (i->type == TL_OPTION_FLOAT3) snprintf(index, sizeof index, "[%zu]", k);
    if (i->type == TL_OPTION_FLOAT || i->type == TL_OPTION_FLOAT3) snprintf(value, sizeof value, "%g", (double)(float)v);
    else snprintf(value, sizeof value, "%.0f", v);
    snprintf(out, size, "options.%s%s = %s is out of range (%s)", i->name, index, value, range);
}

/* `v` into component k of field i of `o` (as its C type). */
static void put(const tl_option_info *i, tl_renderer_options *o, size_t k, double v)
{
    char *at = (char *)o + i->offset;
    if (i->type == TL_OPTION_FLOAT || i->type == TL_OPTION_FLOAT3) {
        float f = (float)v;
        memcpy(at + k * sizeof f, &f, sizeof f);
    } else if (i->type == TL_OPTION_UINT || i->type == TL_OPTION_TARGETS) {
        uint32_t u = (uint32_t)(int64_t)v;
        memcpy(at, &u, sizeof u);
    } else {
        int e = (int)v;
        memcpy(at, &e, sizeof e);
    }
}

/* One refusal by set_options and by create: TL_ERROR_INVALID_ARGUMENT, exactly one line, `want`. */
static int refused_by_both(tl_renderer *r, tl_error_capture *log, const tl_renderer_options *o, const char *want)
{
    char line[400];
    int before = log->errors;
    tl_result res = tl_renderer_set_options(r, o);
    snprintf(line, sizeof line, "renderer: set_options: %s", want);
    int ok = res == TL_ERROR_INVALID_ARGUMENT && log->errors == before + 1 && strcmp(log->last, line) == 0 &&
             strcmp(tl_renderer_last_error(r), line) == 0;
    if (!ok) fprintf(stderr, "  %s \"%s\"\n      want \"%s\"\n", tl_result_string(res), log->last, line);
    tl_error_capture at_create = {0};
    tl_renderer_desc d = {.width = W, .height = H, .options = *o, .get_proc_address = tl_context_proc_loader,
                          .get_proc_address_user = g_ctx, .logger = {tl_error_capture_log, &at_create}};
    tl_renderer *bad = NULL;
    snprintf(line, sizeof line, "renderer: %s", want);
    res = tl_renderer_create(&d, &bad);
    int ok_create = res == TL_ERROR_INVALID_ARGUMENT && !bad && at_create.errors == 1 && strcmp(at_create.last, line) == 0;
    if (!ok_create) fprintf(stderr, "  at create: %s \"%s\"\n      want \"%s\"\n", tl_result_string(res), at_create.last, line);
    tl_renderer_destroy(bad);
    return ok && ok_create;
}

/* Every field of the option registry (thinlight/options.h), each value its row puts out of range
 * (option_values.h: past either end, NaN and infinities, between the powers of two, every
 * component of a colour), is refused by set_options and by create with TL_ERROR_INVALID_ARGUMENT and
 * exactly one line naming the field, the value and the registry's range; the renderer keeps its
 * options. A field is walked with its effect on; the same value with the effect off is taken (the
 * field is not looked at). Lines written out by hand pin the text of a few. Before (one hand-written
 * row per field): 67 rows, and an effect's `enabled` or `diffuse` of 2 was taken, not refused. */
TL_TEST(renderer_options_out_of_range_name_field_value_and_range)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_error_capture log = {0};
    tl_renderer *r = renderer(&log);
    if (!r) return;
    size_t fields = 0, values = 0, named = 0, ignored_off = 0, below_effect = 0;
    for (size_t n = 0; n < tl_option_count(); n++) {
        const tl_option_info *i = tl_option_at(n);
        double bad[8];
        size_t count = tl_test_option_bad_values(i, bad, 8);
        fields += count > 0;
        for (size_t b = 0; b < count; b++)
            for (size_t k = 0; k < (i->type == TL_OPTION_FLOAT3 ? 3u : 1u); k++) {
                tl_renderer_options o = {0};
                put(i, &o, k, bad[b]);
                tl_renderer_options on = o;
                tl_test_option_enable_group(i, &on);
                if (memcmp(&on, &o, sizeof o) != 0 && !strstr(i->name, ".enabled")) { /* below an effect */
                    below_effect++;
                    ignored_off += tl_renderer_set_options(r, &o) == TL_OK; /* off: not looked at */
                }
                o = on;
                char want[320];
                refusal_line(i, k, bad[b], want, sizeof want);
                values++;
                named += (size_t)refused_by_both(r, &log, &o, want);
                TL_CHECK(tl_renderer_set_options(r, &(tl_renderer_options){0}) == TL_OK);
            }
    }
    static const struct {
        tl_renderer_options o;
        const char *said;
    } by_hand[] = {
        {{.ssr = {.enabled = 1, .refine = 9}}, "options.ssr.refine = 9 is out of range (1..8; 0: 4)"},
        {{.mode = (tl_render_mode)9}, "options.mode = 9 is out of range (0..5, a tl_render_mode)"},
        {{.light_scale = 0.3f}, "options.light_scale = 0.3 is out of range (0.25, 0.5 or 1; 0: 1)"},
        {{.ambient = {0.1f, NAN, 0.1f}}, "options.ambient[1] = nan is out of range (>= 0; 0: the scene's ambient (all three 0), < 0: 0)"},
        {{.ssr = {.enabled = 1, .min_gloss = 1}}, "options.ssr.min_gloss = 1 is out of range ((0, 1); 0: 0.4, < 0: 0)"},
        {{.shadows.atlas_size = 1000}, "options.shadows.atlas_size = 1000 is out of range (1024, 2048, 4096, 8192 or 16384; 0: 4096)"},
        {{.dof = {.enabled = 2}}, "options.dof.enabled = 2 is out of range (0 or 1)"},
        {{.light_format = TL_LIGHT_FORMAT_R11G11B10F, .light_buffer = TL_LIGHT_BUFFER_COMPACT},
         "options.light_format = 2 (R11G11B10F) needs options.light_buffer = 1 (EXACT), not 2"},
    };
    size_t hand = 0;
    for (size_t h = 0; h < sizeof by_hand / sizeof by_hand[0]; h++) hand += (size_t)refused_by_both(r, &log, &by_hand[h].o, by_hand[h].said);
    tl_renderer_options kept;
    tl_renderer_get_options(r, &kept);
    static const tl_renderer_options zero;
    TL_CHECK(memcmp(&kept, &zero, sizeof kept) == 0);
    printf("  %zu fields of %zu, %zu values out of range: %zu named with value and range by set_options and create; "
           "%zu of %zu below an effect taken while it is off; %zu of %zu lines by hand; e.g. \"%s\"\n",
           fields, tl_option_count(), values, named, ignored_off, below_effect, hand, sizeof by_hand / sizeof by_hand[0], log.last);
    TL_CHECK(fields + 1 == tl_option_count()); /* every field but keep_targets, which takes every value */
    TL_CHECK(below_effect > 0);
    TL_CHECK_EQ_U(ignored_off, below_effect);
    TL_CHECK_EQ_U(named, values);
    TL_CHECK_EQ_U(hand, sizeof by_hand / sizeof by_hand[0]);
    tl_renderer_destroy(r);
}

/* MSAA past the context's sample counts names options.msaa, its value and the counts the context
 * has, from set_options and from create (TL_ERROR_UNSUPPORTED: the context, not the value's range,
 * is the limit); the renderer keeps its options. Before: "target "target.depth.msaa": 8 samples,
 * the context allows 4 (GL_MAX_SAMPLES)", naming a target. */
TL_TEST(renderer_msaa_past_the_context_names_options_msaa)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    typedef void (*get_integer_fn)(unsigned, int *);
    get_integer_fn get_integer = (get_integer_fn)tl_context_get_proc_address(g_ctx, "glGetIntegerv");
    int max_samples = 0;
    if (get_integer) get_integer(0x8D57 /* GL_MAX_SAMPLES */, &max_samples);
    if (max_samples >= 8) {
        printf("  this context has 8 samples (GL_MAX_SAMPLES %d): nothing to refuse\n", max_samples);
        return;
    }
    tl_error_capture log = {0};
    tl_renderer *r = renderer(&log);
    if (!r) return;
    static test_scene t;
    lit_room(&t);
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
    const char *want = "renderer: set_options: options.msaa = 8 is out of range for this context (0, 1";
    tl_result res = tl_renderer_set_options(r, &(tl_renderer_options){.msaa = 8});
    printf("  set_options: %s \"%s\"\n", tl_result_string(res), log.last);
    TL_CHECK(res == TL_ERROR_UNSUPPORTED && strncmp(log.last, want, strlen(want)) == 0);
    TL_CHECK(strstr(log.last, "the sample counts its multisampled target formats have)") != NULL);
    tl_renderer_options kept;
    tl_renderer_get_options(r, &kept);
    TL_CHECK_EQ_U(kept.msaa, 0);
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    tl_error_capture at_create = {0};
    tl_renderer_desc d = {.width = W, .height = H, .options.msaa = 8, .get_proc_address = tl_context_proc_loader,
                          .get_proc_address_user = g_ctx, .logger = {tl_error_capture_log, &at_create}};
    tl_renderer *bad = NULL;
    res = tl_renderer_create(&d, &bad);
    printf("  create: %s \"%s\"\n", tl_result_string(res), at_create.last);
    const char *want_create = "renderer: options.msaa = 8 is out of range for this context (0, 1";
    TL_CHECK(res == TL_ERROR_UNSUPPORTED && !bad);
    TL_CHECK_EQ_U(at_create.errors, 1);
    TL_CHECK(strncmp(at_create.last, want_create, strlen(want_create)) == 0);
    tl_renderer_destroy(bad);
    tl_renderer_destroy(r);
}
