/* The effects' measurements (--effects): at the first size and the first light count, every
 * configuration of the first strategy (fat, the reference, first) is rendered without effects and
 * with each effect, by one renderer each, the renderers taking turns frame by frame (the first to
 * go rotates), so that each effect's frames sit beside frames without it (forward has no
 * reflections: it gets no ssr record). Its cost is the GPU time
 * of its own passes; its error compares the final image with fat's under the same effect, and for
 * SSAO the AO target with fat's. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "tool_log.h"

const char *const bench_effect_names[BENCH_EFFECTS + 2] = {"ssao", "fog", "dof", "bloom", "ssr", "vignette", "none", NULL};

const char *bench_effect_name(bench_effect e) { return (unsigned)e < BENCH_EFFECTS ? bench_effect_names[e] : "?"; }

/* The passes each effect adds (their GPU time is its cost). */
static double bench__effect_ms(bench_effect e, const tl_frame_stats *st)
{
    static const tl_pass passes[BENCH_EFFECTS][3] = {{TL_PASS_SSAO, TL_PASS_SSAO_BLUR, TL_PASS_SSAO_APPLY},
                                                     {TL_PASS_FOG, TL_PASS_COUNT, TL_PASS_COUNT},
                                                     {TL_PASS_DOF, TL_PASS_DOF_APPLY, TL_PASS_COUNT},
                                                     {TL_PASS_BLOOM, TL_PASS_COUNT, TL_PASS_COUNT},
                                                     {TL_PASS_SSR, TL_PASS_SSR_APPLY, TL_PASS_COUNT},
                                                     {TL_PASS_VIGNETTE, TL_PASS_COUNT, TL_PASS_COUNT}};
    double ms = 0.0;
    for (int k = 0; k < 3; k++)
        if (passes[e][k] != TL_PASS_COUNT && st->pass_ms[passes[e][k]] > 0.0) ms += st->pass_ms[passes[e][k]];
    return ms;
}

void bench_effect_enable(const bench_options *opt, bench_effect e, tl_renderer_desc *d)
{
    size_t n = strlen(bench_effect_names[e]);
    const tl_option_info *f;
    for (size_t i = 0; (f = tl_option_at(i)) != NULL; i++) /* the fields of its struct, "ssao.*" */
        if (strncmp(f->name, bench_effect_names[e], n) == 0 && f->name[n] == '.')
            memcpy((char *)&d->options + f->offset, (const char *)&opt->base + f->offset, f->size);
    char name[48];
    snprintf(name, sizeof name, "%s.enabled", bench_effect_names[e]);
    int on = 1;
    if ((f = tl_option_find(name)) != NULL) memcpy((char *)&d->options + f->offset, &on, sizeof on);
}

/* Whether configuration c has effect e at all: forward plans no reflections (no gloss to read). */
static int bench__effect_applies(bench_effect e, bench_config c)
{
    return !(e == BENCH_EFFECT_SSR && bench_config_mode(c) == TL_MODE_FORWARD);
}

/* The configurations measured: those of the first strategy, without the light-buffer variants. */
static size_t bench__effect_configs(const bench_options *opt, bench_config *out)
{
    bench_config modes[BENCH_CONFIGS];
    size_t n = bench_render_modes(opt, modes), k = 0;
    for (size_t m = 0; m < n; m++)
        if (bench_config_strategy(modes[m]) == opt->strategies[0] && !bench_config_variant_of(modes[m])) out[k++] = modes[m];
    return k;
}

/* The effects measured in configuration *c (every one asked for when c is NULL), in enum order. */
static size_t bench__effect_list(const bench_options *opt, const bench_config *c, bench_effect *out)
{
    size_t n = 0;
    for (int e = 0; e < BENCH_EFFECTS; e++)
        if ((opt->effects & (1u << e)) && (!c || bench__effect_applies((bench_effect)e, *c))) out[n++] = (bench_effect)e;
    return n;
}

uint64_t bench_effects_frames(const bench_options *opt)
{
    bench_config configs[BENCH_CONFIGS];
    bench_effect list[BENCH_EFFECTS];
    if (!bench__effect_list(opt, NULL, list)) return 0;
    uint64_t frames = 0;
    for (size_t m = 0, n = bench__effect_configs(opt, configs); m < n; m++)
        frames += (uint64_t)(bench__effect_list(opt, &configs[m], list) + 1) * (opt->warmup + opt->frames);
    return frames;
}


/* Images of one configuration ([0]: no effect, [e + 1]: with effect e), and fat's. */
typedef struct bench__effect_images {
    size_t pixels;
    uint8_t *ldr[BENCH_EFFECTS + 1], *ref_ldr[BENCH_EFFECTS + 1];
    float *ao, *ref_ao; /* R of the AO target */
} bench__effect_images;

/* The run's renderer `slot` (bench_renderer) with the configuration's options and effect. */
static tl_renderer *bench__effect_renderer(bench_run *run, tl_context *ctx, const tl_scene *scene, const tl_light *lights,
                                           size_t count, bench_config c, int slot, const bench_effect *list)
{
    const bench_options *opt = &run->opt;
    tl_renderer_desc d = bench_config_desc(opt, c, opt->sizes[0].width, opt->sizes[0].height);
    if (slot) bench_effect_enable(opt, list[slot - 1], &d);
    if (d.options.ssao.enabled) d.options.keep_targets |= TL_TARGET_BIT(TL_TARGET_AO);
    tl_renderer *r = bench_renderer(run, ctx, (size_t)slot, d, scene);
    if (r && tl_renderer_set_lights(r, lights, count) != TL_OK) {
        tl_tool_log_error(&run->log, "%s", tl_renderer_last_error(r)); /* once: the logger said it */
        return NULL;
    }
    return r;
}

/* Reads image k's final image (and AO) after the last frame; fat's go to the reference buffers. */
static int bench__effect_read(tl_renderer *r, int ref, int k, int ssao, bench__effect_images *im)
{
    size_t n = im->pixels;
    uint8_t *ldr = ref ? im->ref_ldr[k] : im->ldr[k];
    if (tl_renderer_read_output(r, ldr, &(size_t){n * 4}) != TL_OK) return 1;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) ldr[3 * i + c] = ldr[4 * i + c];
    if (!ssao) return 0;
    float *ao = ref ? im->ref_ao : im->ao;
    if (tl_renderer_read_target(r, TL_TARGET_AO, ao, &(size_t){n * 4 * sizeof(float)}) != TL_OK) return 1;
    for (size_t i = 0; i < n; i++) ao[i] = ao[4 * i];
    return 0;
}

/* The timed frames of one configuration: ms[slot * frames + f] frame time, effect[...] its passes. */
static int bench__effect_frames(bench_run *run, tl_renderer **r, size_t slots, const bench_effect *list, double *ms,
                                double *effect, tl_tool_progress *progress, uint64_t *done, const char *name)
{
    const bench_options *opt = &run->opt;
    uint32_t total = opt->warmup + opt->frames;
    char label[96];
    for (uint32_t f = 0; f < total; f++) {
        snprintf(label, sizeof label, "effects: %s, frame %u/%u", name, f + 1, total);
        tl_tool_progress_update(progress, *done, label, f == 0);
        for (size_t j = 0; j < slots; j++, ++*done) {
            size_t s = (f + j) % slots;
            tl_frame_stats st;
            if (tl_renderer_render(r[s], NULL, &st) != TL_OK) {
                tl_tool_fail(BENCH_TOOL, "effects, %s: %s", name, tl_renderer_last_error(r[s]));
                return 1;
            }
            if (f < opt->warmup) continue;
            if (!(st.gpu_ms > 0.0)) run->timers_ok = 0;
            size_t k = s * opt->frames + (f - opt->warmup);
            ms[k] = st.gpu_ms > 0.0 ? st.gpu_ms : st.wall_ms;
            effect[k] = s ? bench__effect_ms(list[s - 1], &st) : 0.0;
        }
    }
    return 0;
}

static uint32_t bench__bpp(tl_renderer *r, size_t pixels)
{
    tl_frame_stats st;
    if (tl_renderer_wait(r, &st) != TL_OK) return 0;
    return (uint32_t)((st.allocated_target_bytes + pixels / 2) / pixels);
}

/* One configuration's records (the frames are done): medians, sizes, errors against fat's images. */
static int bench__effect_summarise(bench_run *run, bench_config c, tl_renderer **r, size_t slots,
                                   const bench_effect *list, double *ms, double *effect, bench__effect_images *im)
{
    const bench_options *opt = &run->opt;
    uint32_t frames = opt->frames;
    int ref = bench_config_mode(c) == BENCH_REFERENCE;
    double ratios[BENCH_MAX_FRAMES];
    for (size_t s = 0; s < slots; s++)
        if (bench__effect_read(r[s], ref, s ? (int)list[s - 1] + 1 : 0, s && list[s - 1] == BENCH_EFFECT_SSAO, im)) {
            tl_tool_fail(BENCH_TOOL, "effects, %s: reading the images: %s", bench_config_name(c), tl_renderer_last_error(r[s]));
            return 1;
        }
    for (size_t s = 1; s < slots; s++) {
        bench_effect_record *e = &run->effects[run->effect_count++];
        memset(e, 0, sizeof *e);
        *e = (bench_effect_record){.effect = list[s - 1], .config = c, .lights = opt->lights[0],
                                   .width = opt->sizes[0].width, .height = opt->sizes[0].height, .frames = frames};
        for (uint32_t f = 0; f < frames; f++) ratios[f] = ms[s * frames + f] / ms[f];
        e->ratio = bench_median(ratios, frames);
        e->effect_ms = bench_median(effect + s * frames, frames);
        e->frame_ms = bench_median(ms + s * frames, frames);
        memcpy(ratios, ms, frames * sizeof *ratios);
        e->base_ms = bench_median(ratios, frames);
        e->bytes_per_pixel = bench__bpp(r[s], im->pixels);
        e->base_bytes_per_pixel = bench__bpp(r[0], im->pixels);
        size_t n3 = im->pixels * 3, k = (size_t)list[s - 1] + 1;
        tl_image_compare_u8(ref ? im->ref_ldr[k] : im->ldr[k], im->ref_ldr[k], n3, &e->ldr);
        tl_image_compare_u8(ref ? im->ref_ldr[0] : im->ldr[0], im->ref_ldr[0], n3, &e->base_ldr);
        if (e->effect == BENCH_EFFECT_SSAO) tl_image_compare(ref ? im->ref_ao : im->ao, im->ref_ao, im->pixels, 1.0, &e->ao);
    }
    return 0;
}

static int bench__effect_config(bench_run *run, tl_context *ctx, bench_scene *scene, bench_config c, const tl_light *lights,
                                size_t count, bench__effect_images *im, tl_tool_progress *progress, uint64_t *done)
{
    tl_renderer *r[BENCH_EFFECTS + 1] = {NULL};
    bench_effect list[BENCH_EFFECTS];
    size_t slots = bench__effect_list(&run->opt, &c, list) + 1;
    size_t frames = run->opt.frames;
    double *ms = malloc(2 * slots * frames * sizeof *ms), *effect = ms ? ms + slots * frames : NULL;
    int err = !ms;
    if (err) tl_tool_fail(BENCH_TOOL, "out of memory");
    for (size_t s = 0; !err && s < slots; s++)
        err = !(r[s] = bench__effect_renderer(run, ctx, bench_scene_get(scene), lights, count, c, (int)s, list));
    if (!err) err = bench__effect_frames(run, r, slots, list, ms, effect, progress, done, bench_config_name(c));
    if (!err) err = bench__effect_summarise(run, c, r, slots, list, ms, effect, im);
    free(ms); /* the renderers stay the run's for the next configuration */
    return err;
}

static void bench__effect_images_free(bench__effect_images *im)
{
    for (int s = 0; s <= BENCH_EFFECTS; s++) {
        free(im->ldr[s]);
        free(im->ref_ldr[s]);
    }
    free(im->ao);
    free(im->ref_ao);
}

int bench_effects_measure(bench_run *run, tl_context *ctx, bench_scene *scene, tl_tool_progress *progress, uint64_t *done)
{
    const bench_options *opt = &run->opt;
    bench_effect list[BENCH_EFFECTS];
    bench_config configs[BENCH_CONFIGS];
    size_t ne = bench__effect_list(opt, NULL, list), nc = bench__effect_configs(opt, configs);
    if (!ne || !nc) return 0;
    const tl_light *lights;
    size_t count;
    if (bench_scene_lights(scene, opt->lights[0], &lights, &count)) return 1;
    bench__effect_images im = {.pixels = (size_t)opt->sizes[0].width * opt->sizes[0].height};
    int err = !(run->effects = calloc(nc * ne, sizeof *run->effects));
    for (size_t s = 0; !err && s <= ne; s++) {
        size_t k = s ? (size_t)list[s - 1] + 1 : 0;
        err = !(im.ldr[k] = malloc(im.pixels * 4)) || !(im.ref_ldr[k] = malloc(im.pixels * 4));
    }
    if (!err) err = !(im.ao = malloc(im.pixels * 4 * sizeof(float))) || !(im.ref_ao = malloc(im.pixels * 4 * sizeof(float)));
    if (err) tl_tool_fail(BENCH_TOOL, "out of memory for the effects' images");
    for (size_t m = 0; !err && m < nc; m++) /* fat first: the reference images */
        err = bench__effect_config(run, ctx, scene, configs[m], lights, count, &im, progress, done);
    bench__effect_images_free(&im);
    return err;
}
