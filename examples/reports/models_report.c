#define _POSIX_C_SOURCE 200809L /* clock_gettime */
/* thinlight-models-report: the material models measured on the showcase scene (docs/lighting.md,
 * "Material models"): per model and light count, thin-lpp against forward (the exact per-light
 * evaluation) and against fat, fat and thin-deferred against forward, the bytes per pixel the plan
 * allocates and the material pass's time with every sphere in that model; then a frame with every
 * model on screen against the same frame with the standard model only (thin-lpp, interleaved
 * runs). Writes a markdown table on stdout. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "models_measure.h"
#include "tool_gl.h"
#include "tool_log.h"

#define TOOL "thinlight-models-report"

typedef struct args {
    uint32_t width, height, frames, runs;
    uint32_t lights[8];
    size_t light_count;
    int clearcoat; /* tl_clearcoat_lighting, or -1: both, compared (clearcoat_table) */
} args;

static int usage(FILE *f, int rc)
{
    fprintf(f, "usage: " TOOL " [--size WxH] [--lights 8,64,256] [--frames N] [--runs N]\n"
               "  --size WxH    image size (default 640x360)\n"
               "  --lights L    point-light counts of the showcase (default 8,64,256)\n"
               "  --frames N    frames per measured image; the material pass timed by the fastest after\n"
               "                the first (default 4)\n"
               "  --runs N      interleaved pairs for the all-models / one-model ratio (default 15)\n"
               "  --clearcoat C thin-lpp's clearcoat: auto (default: the library's, the coat's own sums),\n"
               "                approx or sums; both: only the table comparing approx and sums on the\n"
               "                clearcoat row\n");
    return rc;
}

static int parse(int argc, char **argv, args *a)
{
    *a = (args){.width = 640, .height = 360, .frames = 4, .runs = 15, .lights = {8, 64, 256}, .light_count = 3};
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(o, "--help")) return usage(stdout, -1);
        if (!v) return usage(stderr, 2);
        i++;
        if (!strcmp(o, "--size") && sscanf(v, "%ux%u", &a->width, &a->height) == 2 && a->width && a->height &&
            a->width <= 8192 && a->height <= 8192)
            continue;
        if (!strcmp(o, "--frames") && sscanf(v, "%u", &a->frames) == 1 && a->frames && a->frames <= 1000) continue;
        if (!strcmp(o, "--runs") && sscanf(v, "%u", &a->runs) == 1 && a->runs && a->runs <= 1000) continue;
        if (!strcmp(o, "--clearcoat") &&
            (!strcmp(v, "auto") || !strcmp(v, "approx") || !strcmp(v, "sums") || !strcmp(v, "both"))) {
            a->clearcoat = !strcmp(v, "auto")     ? TL_CLEARCOAT_DEFAULT
                           : !strcmp(v, "approx") ? TL_CLEARCOAT_APPROXIMATE
                           : !strcmp(v, "sums")   ? TL_CLEARCOAT_SUMS
                                                  : -1;
            continue;
        }
        if (!strcmp(o, "--lights")) {
            a->light_count = 0;
            for (const char *p = v; *p && a->light_count < 8;) {
                char *end;
                unsigned long n = strtoul(p, &end, 10);
                if (end == p || n == 0 || n > 65536) return usage(stderr, 2);
                a->lights[a->light_count++] = (uint32_t)n;
                p = *end == ',' ? end + 1 : end;
                if (*end && *end != ',') return usage(stderr, 2);
            }
            continue;
        }
        fprintf(stderr, TOOL ": bad option or value: %s %s\n", o, v);
        return 2;
    }
    return 0;
}

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* A copy of the showcase with every sphere in `model` (the floor stays standard). */
static tl_scene *one_model(const tl_scene *s, uint32_t model)
{
    tl_scene *c = tl_mm_standard_only(s);
    for (size_t i = 0; c && i + 1 < c->material_count; i++) c->materials[i].model = model;
    return c;
}

/* Per model at `lights`: errors against forward and fat, bytes per pixel, material-pass time. */
static int error_table(const args *a, tl_renderer_desc d, uint32_t lights)
{
    tl_scene *s = NULL;
    if (tl_scene_create_showcase(&(tl_showcase_scene_desc){.point_lights = lights}, &s) != TL_OK) return 1;
    size_t n = (size_t)a->width * a->height;
    float *img[4] = {malloc(n * 16), malloc(n * 16), malloc(n * 16), malloc(n * 16)};
    uint8_t *rows = malloc(n);
    const tl_render_mode modes[4] = {TL_MODE_THIN_LPP, TL_MODE_FORWARD, TL_MODE_FAT, TL_MODE_THIN_DEFERRED};
    int bad = !img[0] || !img[1] || !img[2] || !img[3] || !rows || tl_mm_rows(s, d, rows);
    tl_frame_stats st[4];
    for (int k = 0; k < 4 && !bad; k++) {
        d.options.mode = modes[k];
        bad = tl_mm_render(s, d, a->frames, img[k], &st[k]);
    }
    tl_mm_error fwd[TL_MATERIAL_MODEL_COUNT_], fat[TL_MATERIAL_MODEL_COUNT_], fat_fwd[TL_MATERIAL_MODEL_COUNT_],
        td_fwd[TL_MATERIAL_MODEL_COUNT_];
    if (!bad) {
        tl_mm_compare(img[0], img[1], rows, n, fwd);
        tl_mm_compare(img[0], img[2], rows, n, fat);
        tl_mm_compare(img[2], img[1], rows, n, fat_fwd); /* fat and thin-deferred against forward */
        tl_mm_compare(img[3], img[1], rows, n, td_fwd);
    }
    for (uint32_t m = 0; m < TL_MATERIAL_MODEL_COUNT_ && !bad; m++) {
        tl_scene *c = one_model(s, m);
        tl_frame_stats one, base;
        d.options.mode = TL_MODE_THIN_LPP;
        bad = !c || tl_mm_render(c, d, a->frames, NULL, &one);
        tl_mm_free(c);
        c = tl_mm_standard_only(s);
        bad = bad || !c || tl_mm_render(c, d, a->frames, NULL, &base);
        tl_mm_free(c);
        if (bad) break;
        double extra = ((double)one.total_target_bytes - (double)base.total_target_bytes) / (double)n;
        printf("| %u | %s | %zu | %.1f | %.3g | %.3g | %.1f | %.3g | %.1f | %.3g | %.1f | %.3g | %+.2f | %.2f | %.2f |\n",
               lights, tl_material_model_name(m), fwd[m].pixels, fwd[m].psnr_db, fwd[m].max_abs, fwd[m].max_rel,
               fat[m].psnr_db, fat[m].max_abs, fat_fwd[m].psnr_db, fat_fwd[m].max_abs, td_fwd[m].psnr_db,
               td_fwd[m].max_abs, extra, one.pass_ms[TL_PASS_MATERIAL], base.pass_ms[TL_PASS_MATERIAL]);
    }
    for (int k = 0; k < 4; k++) free(img[k]);
    free(rows);
    tl_scene_destroy(s);
    return bad;
}

/* The light pass's time, whichever strategy the plan took. */
static double light_ms(const tl_frame_stats *st)
{
    return st->pass_ms[TL_PASS_LIGHTS] + st->pass_ms[TL_PASS_LIGHTS_TILED];
}

/* thin-lpp's two clearcoat choices at `lights`, on the clearcoat row against forward: errors, the
 * bytes per pixel the sums add (against the approximation's frame), and with every sphere a
 * clearcoat the material pass's and the light pass's times. */
static int clearcoat_table(const args *a, tl_renderer_desc d, uint32_t lights)
{
    tl_scene *s = NULL;
    if (tl_scene_create_showcase(&(tl_showcase_scene_desc){.point_lights = lights}, &s) != TL_OK) return 1;
    size_t n = (size_t)a->width * a->height;
    float *img[3] = {malloc(n * 16), malloc(n * 16), malloc(n * 16)};
    uint8_t *rows = malloc(n);
    tl_scene *coats = one_model(s, TL_MATERIAL_MODEL_CLEARCOAT);
    int bad = !img[0] || !img[1] || !img[2] || !rows || !coats || tl_mm_rows(s, d, rows);
    tl_frame_stats st[3], one[2];
    const tl_clearcoat_lighting choice[2] = {TL_CLEARCOAT_APPROXIMATE, TL_CLEARCOAT_SUMS};
    d.options.mode = TL_MODE_FORWARD;
    bad = bad || tl_mm_render(s, d, a->frames, img[2], &st[2]);
    d.options.mode = TL_MODE_THIN_LPP;
    for (int k = 0; k < 2 && !bad; k++) {
        d.options.clearcoat = choice[k];
        bad = tl_mm_render(s, d, a->frames, img[k], &st[k]) || tl_mm_render(coats, d, a->frames, NULL, &one[k]);
    }
    tl_mm_error e[2][TL_MATERIAL_MODEL_COUNT_];
    for (int k = 0; k < 2 && !bad; k++) tl_mm_compare(img[k], img[2], rows, n, e[k]);
    const uint32_t cc = TL_MATERIAL_MODEL_CLEARCOAT, sd = TL_MATERIAL_MODEL_STANDARD;
    if (!bad)
        printf("| %u | %.1f | %.3g | %.1f | %.3g | %.1f | %+.2f | %.2f | %.2f | %.2f | %.2f |\n", lights, e[0][cc].psnr_db,
               e[0][cc].max_abs, e[1][cc].psnr_db, e[1][cc].max_abs, e[1][sd].psnr_db,
               ((double)st[1].total_target_bytes - (double)st[0].total_target_bytes) / (double)n,
               one[0].pass_ms[TL_PASS_MATERIAL], one[1].pass_ms[TL_PASS_MATERIAL], light_ms(&one[0]), light_ms(&one[1]));
    for (int k = 0; k < 3; k++) free(img[k]);
    free(rows);
    tl_mm_free(coats);
    tl_scene_destroy(s);
    return bad;
}

/* The frame with every model against the standard-only one: thin-lpp, interleaved pairs, the
 * median of each and of the pairs' ratios. */
static int cost_ratio(const args *a, tl_renderer_desc d, uint32_t lights)
{
    tl_scene *s = NULL;
    if (tl_scene_create_showcase(&(tl_showcase_scene_desc){.point_lights = lights}, &s) != TL_OK) return 1;
    tl_scene *std = tl_mm_standard_only(s);
    d.options.mode = TL_MODE_THIN_LPP;
    d.options.synchronous_stats = 1;
    tl_renderer *r[2] = {NULL, NULL};
    const tl_scene *sc[2] = {s, std};
    int bad = !std;
    for (int k = 0; k < 2 && !bad; k++)
        bad = tl_renderer_create(&d, &r[k]) != TL_OK || tl_renderer_set_scene(r[k], sc[k]) != TL_OK;
    double *t[2] = {calloc(a->runs, sizeof(double)), calloc(a->runs, sizeof(double))};
    double *ratio = calloc(a->runs, sizeof(double)), *mat[2] = {calloc(a->runs, 8), calloc(a->runs, 8)};
    bad = bad || !t[0] || !t[1] || !ratio || !mat[0] || !mat[1];
    for (int k = 0; k < 2 && !bad; k++) /* warm-up: programs compiled, lists grown */
        for (int f = 0; f < 3 && !bad; f++) bad = tl_renderer_render(r[k], NULL, NULL) != TL_OK;
    for (uint32_t i = 0; i < a->runs && !bad; i++) {
        for (int k = 0; k < 2 && !bad; k++) {
            int which = (int)((i + (uint32_t)k) & 1u); /* alternate which goes first */
            tl_frame_stats st;
            double t0 = now_ms();
            bad = tl_renderer_render(r[which], NULL, &st) != TL_OK;
            t[which][i] = now_ms() - t0;
            mat[which][i] = st.pass_ms[TL_PASS_MATERIAL];
        }
        ratio[i] = t[0][i] / t[1][i];
    }
    if (!bad) {
        for (int k = 0; k < 2; k++) {
            qsort(t[k], a->runs, sizeof(double), cmp_double);
            qsort(mat[k], a->runs, sizeof(double), cmp_double);
        }
        qsort(ratio, a->runs, sizeof(double), cmp_double);
        size_t h = a->runs / 2;
        printf("| %u | %ux%u | %u | %.2f | %.2f | %.3f | %.2f | %.2f | %.3f |\n", lights, a->width, a->height, a->runs,
               t[0][h], t[1][h], ratio[h], mat[0][h], mat[1][h], mat[0][h] / mat[1][h]);
    }
    for (int k = 0; k < 2; k++) {
        tl_renderer_destroy(r[k]);
        free(t[k]);
        free(mat[k]);
    }
    free(ratio);
    tl_mm_free(std);
    tl_scene_destroy(s);
    return bad;
}

int main(int argc, char **argv)
{
    args a;
    int rc = parse(argc, argv, &a);
    if (rc) return rc < 0 ? 0 : rc;
    tl_tool_context_options co = {0};
    tl_context *ctx = NULL;
    if (tl_tool_context_open(TOOL, &co, a.width, a.height, &ctx)) return 1;
    static tl_tool_log log = {.tool = TOOL}; /* the renderers' warnings (downgrades), each line once */
    tl_renderer_desc d = {.width = a.width, .height = a.height, .get_proc_address = tl_context_proc_loader,
                          .get_proc_address_user = ctx, .logger = tl_tool_log_logger(&log)};
    if (a.clearcoat < 0) { /* --clearcoat both */
        printf("| lights | approx PSNR vs forward (dB) | approx max abs | sums PSNR vs forward (dB) | sums max abs | "
               "standard row, sums frame (dB) | sums extra B/px | material pass, all clearcoat, approx (ms) | "
               "material pass, sums (ms) | light pass, approx (ms) | light pass, sums (ms) |\n"
               "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        for (size_t i = 0; i < a.light_count && !rc; i++) {
            fprintf(stderr, TOOL ": clearcoat at %u lights\n", a.lights[i]);
            rc = clearcoat_table(&a, d, a.lights[i]);
        }
        tl_context_destroy(ctx);
        if (rc) fprintf(stderr, TOOL ": failed\n");
        return rc ? 1 : 0;
    }
    d.options.clearcoat = (tl_clearcoat_lighting)a.clearcoat;
    printf("| lights | model | pixels | PSNR vs forward (dB) | max abs vs forward | max rel vs forward | PSNR vs fat "
           "(dB) | max abs vs fat | fat vs forward (dB) | fat max abs vs forward | thin-deferred vs forward (dB) | "
           "thin-deferred max abs vs forward | extra B/px | material pass, all spheres this model (ms) | material "
           "pass, all standard (ms) |\n|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (size_t i = 0; i < a.light_count && !rc; i++) {
        fprintf(stderr, TOOL ": errors at %u lights\n", a.lights[i]);
        rc = error_table(&a, d, a.lights[i]);
    }
    if (!rc) {
        printf("\n| lights | size | pairs | all models, frame (ms) | standard only, frame (ms) | ratio (median of "
               "pairs) | all models, material pass (ms) | standard only, material pass (ms) | ratio |\n"
               "|---:|---|---:|---:|---:|---:|---:|---:|---:|\n");
        fprintf(stderr, TOOL ": interleaved frames at 256 lights\n");
        rc = cost_ratio(&a, d, 256);
    }
    tl_context_destroy(ctx);
    if (rc) fprintf(stderr, TOOL ": failed\n");
    return rc ? 1 : 0;
}
