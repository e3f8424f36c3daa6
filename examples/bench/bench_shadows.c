/* The shadows' measurements (--shadows): at the first size and the first light count, every
 * configuration (each strategy's, fat first) is rendered by three renderers taking turns frame by
 * frame (the first to go rotates): the scene's lights without shadows, casting (the crypt's
 * moonlight and braziers; a glTF file's by the loader's shadow rule and its flags; the cache on:
 * nothing moves, so the maps are kept), and casting with every map rendered every frame (no
 * cache). Then each configuration's shadow term of each casting point light (one at a time), with
 * D24 and with reversed D32F, is compared with the ray-traced truth (bench_shadows_truth.c) and
 * with fat's of the same strategy; the counts add up over the lights. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_shadows.h"
#include "tool_log.h"

enum { BENCH__OFF, BENCH__ON, BENCH__NOCACHE, BENCH__SLOTS };

/* The configurations measured: every strategy's, without the light-buffer variants (fat first). */
static size_t bench__shadow_configs(const bench_options *opt, bench_config *out)
{
    bench_config modes[BENCH_CONFIGS];
    size_t n = bench_render_modes(opt, modes), k = 0;
    for (size_t m = 0; m < n; m++)
        if (!bench_config_variant_of(modes[m])) out[k++] = modes[m];
    return k;
}

uint64_t bench_shadows_frames(const bench_options *opt)
{
    bench_config configs[BENCH_CONFIGS];
    return opt->shadows ? (uint64_t)bench__shadow_configs(opt, configs) * BENCH__SLOTS * (opt->warmup + opt->frames) : 0;
}

/* The lights of the first light count, without shadows [0] and casting [1] (copies). */
typedef struct bench__shadow_lights {
    tl_light *list[2];
    size_t count[2];
    tl_light truth[BENCH_SHADOW_TRUTH_LIGHTS]; /* the casting point lights (the braziers), nearest first */
    size_t truth_count;
} bench__shadow_lights;

static int bench__nearer(const tl_light *x, const tl_light *y, const float eye[3])
{
    float dx = 0.0f, dy = 0.0f;
    for (int k = 0; k < 3; k++) {
        dx += (x->position[k] - eye[k]) * (x->position[k] - eye[k]);
        dy += (y->position[k] - eye[k]) * (y->position[k] - eye[k]);
    }
    return dx < dy;
}

static int bench__shadow_lights_make(bench_scene *scene, uint32_t n, bench__shadow_lights *l)
{
    for (int k = 0; k < 2; k++) {
        const tl_light *src;
        if (bench_scene_casting_lights(scene, n, k, &src, &l->count[k])) return 1;
        if (!(l->list[k] = malloc((l->count[k] + 1) * sizeof *src))) {
            tl_tool_fail(BENCH_TOOL, "out of memory");
            return 1;
        }
        memcpy(l->list[k], src, l->count[k] * sizeof *src);
        for (size_t i = 0; i < l->count[k] && !k; i++) l->list[k][i].shadow = 0; /* "off": a file's flags too */
    }
    const float *eye = bench_scene_get(scene)->camera.position;
    for (size_t i = 0; i < l->count[1]; i++) { /* insertion by distance, the nearest kept */
        const tl_light *c = &l->list[1][i];
        if (!c->shadow || c->type != TL_LIGHT_POINT) continue;
        size_t k = l->truth_count < BENCH_SHADOW_TRUTH_LIGHTS ? l->truth_count++ : BENCH_SHADOW_TRUTH_LIGHTS;
        for (; k > 0 && bench__nearer(c, &l->truth[k - 1], eye); k--)
            if (k < BENCH_SHADOW_TRUTH_LIGHTS) l->truth[k] = l->truth[k - 1];
        if (k < BENCH_SHADOW_TRUTH_LIGHTS) l->truth[k] = *c;
    }
    return 0;
}

static tl_renderer_desc bench__shadow_desc(const bench_options *opt, bench_config c, int slot)
{
    tl_renderer_desc d = bench_config_desc(opt, c, opt->sizes[0].width, opt->sizes[0].height);
    if (slot == BENCH__NOCACHE) d.options.shadows.cache = TL_SWITCH_OFF;
    tl_tool_budget_renderer(&opt->budgets, &d);
    return d;
}

/* The light pass: light-cull + lights or lights-tiled (deferred), light-cull + forward, light-cull +
 * vis-resolve (visibility; bench_light_pass_ms). */
static double bench__light_ms(tl_render_mode m, const tl_frame_stats *st)
{
    double ms[TL_PASS_COUNT];
    for (int p = 0; p < TL_PASS_COUNT; p++) ms[p] = fmax(st->pass_ms[p], 0.0);
    return ms[TL_PASS_LIGHT_CULL] + bench_light_pass_ms(m, ms);
}

/* Per slot and timed frame: frame, shadow maps and light pass times; the last frame's statistics. */
typedef struct bench__shadow_frames {
    double *ms, *shadow, *light; /* [slot * frames + f] */
    tl_frame_stats last[BENCH__SLOTS];
} bench__shadow_frames;

static int bench__shadow_frames_run(bench_run *run, tl_renderer **r, bench_config c, bench__shadow_frames *fr,
                                    tl_tool_progress *progress, uint64_t *done)
{
    const bench_options *opt = &run->opt;
    uint32_t total = opt->warmup + opt->frames;
    char label[96];
    for (uint32_t f = 0; f < total; f++) {
        snprintf(label, sizeof label, "shadows: %s, frame %u/%u", bench_config_name(c), f + 1, total);
        tl_tool_progress_update(progress, *done, label, f == 0);
        for (size_t j = 0; j < BENCH__SLOTS; j++, ++*done) {
            size_t s = (f + j) % BENCH__SLOTS;
            tl_frame_stats *st = &fr->last[s];
            if (tl_renderer_render(r[s], NULL, st) != TL_OK) {
                tl_tool_fail(BENCH_TOOL, "shadows, %s: %s", bench_config_name(c), tl_renderer_last_error(r[s]));
                return 1;
            }
            if (f < opt->warmup) continue;
            if (!(st->gpu_ms > 0.0)) run->timers_ok = 0;
            size_t k = s * opt->frames + (f - opt->warmup);
            fr->ms[k] = st->gpu_ms > 0.0 ? st->gpu_ms : st->wall_ms;
            fr->shadow[k] = fmax(st->shadow_ms, 0.0);
            fr->light[k] = bench__light_ms(bench_config_mode(c), st);
        }
    }
    return 0;
}

/* A slot's median of one figure (v is reordered). */
static double bench__slot_median(double *v, size_t slot, uint32_t frames) { return bench_median(v + slot * frames, frames); }

static void bench__shadow_summarise(const bench_run *run, bench_config c, bench__shadow_frames *fr, uint32_t casting,
                                    bench_shadow_record *rec)
{
    uint32_t n = run->opt.frames;
    double ratios[BENCH_MAX_FRAMES];
    for (uint32_t f = 0; f < n; f++) ratios[f] = fr->ms[BENCH__ON * n + f] / fr->ms[BENCH__OFF * n + f];
    const tl_frame_stats *on = &fr->last[BENCH__ON];
    *rec = (bench_shadow_record){.config = c, .lights = run->opt.lights[0], .width = run->opt.sizes[0].width,
                                 .height = run->opt.sizes[0].height, .frames = n, .casting_lights = casting,
                                 .ratio = bench_median(ratios, n), .atlas_bytes = on->shadow_atlas_bytes,
                                 .shadow_lights = on->shadow_lights, .maps_rendered = on->shadow_maps_rendered,
                                 .maps_cached = on->shadow_maps_cached,
                                 .maps_nocache = fr->last[BENCH__NOCACHE].shadow_maps_rendered};
    rec->frame_ms = bench__slot_median(fr->ms, BENCH__ON, n);
    rec->frame_ms_off = bench__slot_median(fr->ms, BENCH__OFF, n);
    rec->frame_ms_nocache = bench__slot_median(fr->ms, BENCH__NOCACHE, n);
    rec->shadow_ms = bench__slot_median(fr->shadow, BENCH__ON, n);
    rec->shadow_ms_nocache = bench__slot_median(fr->shadow, BENCH__NOCACHE, n);
    rec->light_ms = bench__slot_median(fr->light, BENCH__ON, n);
    rec->light_ms_off = bench__slot_median(fr->light, BENCH__OFF, n);
    rec->lookup_ms = rec->light_ms - rec->light_ms_off;
    for (int d = 0; d < BENCH_SHADOW_DEPTHS; d++) rec->truth[d].wrong = rec->truth[d].vs_fat = NAN;
}

static int bench__shadow_config(bench_run *run, tl_context *ctx, const tl_scene *scene, bench_config c,
                                const bench__shadow_lights *l, tl_tool_progress *progress, uint64_t *done)
{
    tl_renderer *r[BENCH__SLOTS] = {NULL};
    uint32_t n = run->opt.frames, casting = 0;
    for (size_t i = 0; i < l->count[1]; i++) casting += l->list[1][i].shadow != 0;
    bench__shadow_frames fr = {.ms = malloc(3 * BENCH__SLOTS * n * sizeof(double))};
    int err = !fr.ms;
    if (err) tl_tool_fail(BENCH_TOOL, "out of memory");
    fr.shadow = fr.ms + BENCH__SLOTS * n, fr.light = fr.shadow + BENCH__SLOTS * n;
    for (size_t s = 0; !err && s < BENCH__SLOTS; s++) {
        int k = s != BENCH__OFF;
        err = !(r[s] = bench_renderer(run, ctx, s, bench__shadow_desc(&run->opt, c, (int)s), scene));
        if (!err && (err = tl_renderer_set_lights(r[s], l->list[k], l->count[k]) != TL_OK))
            tl_tool_log_error(&run->log, "%s", tl_renderer_last_error(r[s]));
    }
    if (!err) err = bench__shadow_frames_run(run, r, c, &fr, progress, done);
    if (!err) bench__shadow_summarise(run, c, &fr, casting, &run->shadows[run->shadow_count++]);
    free(fr.ms); /* the renderers stay the run's */
    return err;
}

/* ---- the shadow term against the truth ------------------------------------------------------- */

/* What the truth's measurement holds: the scene without emission, its renderer, the truth of the
 * light measured, and fat's terms of that light per strategy and depth (fat comes first in each
 * strategy's records). */
typedef struct bench__shadow_truth_state {
    tl_scene scene;
    tl_material *materials;
    tl_renderer *r;
    bench_shadow_truth *truth;
    float *fat[BENCH_STRATEGIES][BENCH_SHADOW_DEPTHS];
} bench__shadow_truth_state;

static int bench__truth_open(bench_run *run, tl_context *ctx, const tl_scene *scene, bench__shadow_truth_state *t)
{
    const bench_options *opt = &run->opt;
    t->scene = *scene;
    if (!(t->materials = malloc((scene->material_count + 1) * sizeof *t->materials))) {
        tl_tool_fail(BENCH_TOOL, "out of memory");
        return 1;
    }
    memcpy(t->materials, scene->materials, scene->material_count * sizeof *t->materials);
    for (size_t i = 0; i < scene->material_count; i++) memset(t->materials[i].emissive, 0, sizeof t->materials[i].emissive);
    t->scene.materials = t->materials;
    tl_renderer_desc d = {.width = opt->sizes[0].width, .height = opt->sizes[0].height};
    bench_renderer_desc(run, ctx, &d);
    if (tl_renderer_create(&d, &t->r) != TL_OK || tl_renderer_set_scene(t->r, &t->scene) != TL_OK) {
        tl_tool_fail(BENCH_TOOL, "shadows: the truth's renderer: %s", t->r ? tl_renderer_last_error(t->r) : "not created");
        return 1;
    }
    return 0;
}

static void bench__truth_fat_free(bench__shadow_truth_state *t)
{
    for (int s = 0; s < BENCH_STRATEGIES; s++)
        for (int d = 0; d < BENCH_SHADOW_DEPTHS; d++) {
            free(t->fat[s][d]);
            t->fat[s][d] = NULL;
        }
}

static void bench__truth_close(bench__shadow_truth_state *t)
{
    tl_renderer_destroy(t->r);
    bench_shadow_truth_free(t->truth);
    free(t->materials);
    bench__truth_fat_free(t);
}

/* One record's terms of one light (D24, reversed D32F) against the truth and against fat's. */
static int bench__truth_record(bench_run *run, bench__shadow_truth_state *t, const tl_light *light,
                               bench_shadow_record *rec)
{
    const bench_options *opt = &run->opt;
    size_t n = (size_t)rec->width * rec->height;
    for (int d = 0; d < BENCH_SHADOW_DEPTHS; d++) {
        tl_renderer_options o = bench__shadow_desc(opt, rec->config, BENCH__ON).options;
        o.depth_format = d ? TL_DEPTH_FORMAT_D32F_REVERSED : TL_DEPTH_FORMAT_D24;
        o.ambient[0] = o.ambient[1] = o.ambient[2] = -1.0f;
        o.keep_targets = TL_TARGET_BIT(TL_TARGET_HDR);
        float *term = NULL;
        if (tl_renderer_set_options(t->r, &o) == TL_OK) term = bench_shadow_term(t->r, light, n);
        if (!term) {
            tl_tool_fail(BENCH_TOOL, "shadows, %s: the shadow term: %s", bench_config_name(rec->config),
                         tl_renderer_last_error(t->r));
            return 1;
        }
        float **fat = &t->fat[bench_config_strategy(rec->config)][d];
        int ref = bench_config_mode(rec->config) == BENCH_REFERENCE;
        bench_shadow_truth_compare(t->truth, term, ref ? NULL : *fat, &rec->truth[d]);
        if (ref && !*fat) *fat = term;
        else free(term);
    }
    return 0;
}

/* Every record against the truth, one casting point light at a time (their counts added up). */
static int bench__truth_measure(bench_run *run, tl_context *ctx, const tl_scene *scene, const bench__shadow_lights *l)
{
    const bench_options *opt = &run->opt;
    if (!l->truth_count) {
        snprintf(run->shadow_truth_why, sizeof run->shadow_truth_why, "no casting point light in the frame");
        return 0;
    }
    snprintf(run->shadow_truth_light, sizeof run->shadow_truth_light, "the %zu casting %s (one at a time)",
             l->truth_count, strcmp(run->opt.scene, "default") == 0 ? "braziers" : "point lights");
    bench__shadow_truth_state t = {0};
    int err = 0;
    for (size_t k = 0; !err && k < l->truth_count; k++) {
        t.truth = bench_shadow_truth_make(scene, &l->truth[k], opt->sizes[0].width, opt->sizes[0].height,
                                          run->shadow_truth_why, sizeof run->shadow_truth_why);
        if (!t.truth) break; /* no Embree: the reason is the run's */
        if (!t.r) err = bench__truth_open(run, ctx, scene, &t);
        for (size_t i = 0; !err && i < run->shadow_count; i++) err = bench__truth_record(run, &t, &l->truth[k], &run->shadows[i]);
        bench_shadow_truth_free(t.truth);
        t.truth = NULL;
        bench__truth_fat_free(&t);
    }
    bench__truth_close(&t);
    return err;
}

int bench_shadows_measure(bench_run *run, tl_context *ctx, bench_scene *scene, tl_tool_progress *progress,
                          uint64_t *done)
{
    const bench_options *opt = &run->opt;
    bench_config configs[BENCH_CONFIGS];
    size_t nc = opt->shadows ? bench__shadow_configs(opt, configs) : 0;
    if (!nc) return 0;
    bench__shadow_lights *l = calloc(1, sizeof *l);
    int err = !l || bench__shadow_lights_make(scene, opt->lights[0], l);
    if (!err) err = !(run->shadows = calloc(nc, sizeof *run->shadows));
    if (!l || (!err && !run->shadows)) tl_tool_fail(BENCH_TOOL, "out of memory");
    for (size_t m = 0; !err && m < nc; m++)
        err = bench__shadow_config(run, ctx, bench_scene_get(scene), configs[m], l, progress, done);
    if (!err) err = bench__truth_measure(run, ctx, bench_scene_get(scene), l);
    if (l) {
        free(l->list[0]);
        free(l->list[1]);
    }
    free(l);
    return err;
}
