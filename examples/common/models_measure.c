/* See models_measure.h. */
#include "models_measure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static tl_scene *tl__mm_copy(const tl_scene *s)
{
    tl_scene *c = calloc(1, sizeof *c);
    tl_material *m = calloc(s->material_count, sizeof *m);
    if (!c || !m) {
        free(c);
        free(m);
        return NULL;
    }
    *c = *s;
    memcpy(m, s->materials, s->material_count * sizeof *m);
    c->materials = m;
    return c;
}

/* The copies share everything but their materials: free those and the struct only. */
void tl_mm_free(tl_scene *c)
{
    if (!c) return;
    free(c->materials);
    free(c);
}

tl_scene *tl_mm_standard_only(const tl_scene *s)
{
    tl_scene *c = tl__mm_copy(s);
    for (size_t i = 0; c && i < c->material_count; i++) c->materials[i].model = TL_MATERIAL_MODEL_STANDARD;
    return c;
}

int tl_mm_render(const tl_scene *s, tl_renderer_desc d, uint32_t frames, float *hdr, tl_frame_stats *stats)
{
    d.options.keep_targets |= TL_TARGET_BIT(TL_TARGET_HDR);
    d.options.synchronous_stats = 1;
    tl_renderer *r = NULL;
    tl_frame_stats st;
    double least = INFINITY; /* the material pass's fastest frame after the first: robust to a busy machine */
    if (tl_renderer_create(&d, &r) != TL_OK) return 1;
    int bad = tl_renderer_set_scene(r, s) != TL_OK;
    for (uint32_t f = 0; !bad && f < (frames ? frames : 1); f++) {
        bad = tl_renderer_render(r, NULL, &st) != TL_OK;
        if (!bad && (f > 0 || frames <= 1)) least = fmin(least, st.pass_ms[TL_PASS_MATERIAL]);
    }
    if (!bad) st.pass_ms[TL_PASS_MATERIAL] = least;
    size_t size = (size_t)d.width * d.height * 4 * sizeof(float);
    if (!bad && hdr) bad = tl_renderer_read_target(r, TL_TARGET_HDR, hdr, &size) != TL_OK;
    if (bad) fprintf(stderr, "models: rendering the showcase: %s\n", tl_renderer_last_error(r));
    if (!bad && stats) *stats = st;
    tl_renderer_destroy(r);
    return bad;
}

int tl_mm_rows(const tl_scene *s, tl_renderer_desc d, uint8_t *rows)
{
    tl_scene *c = tl__mm_copy(s);
    size_t n = (size_t)d.width * d.height;
    float *hdr = malloc(n * 4 * sizeof(float));
    int bad = !c || !hdr;
    for (size_t i = 0; !bad && i < c->material_count; i++) { /* unlit, red = (row + 1) / 8; the floor black */
        tl_material *m = &c->materials[i];
        uint32_t row = m->model;
        int floor = i + 1 == c->material_count;
        float code = floor ? -1.0f : (float)(row + 1) / 8.0f;
        *m = (tl_material){.model = TL_MATERIAL_MODEL_UNLIT, .albedo = {code, -1, -1}};
    }
    if (!bad) {
        c->light_count = 0;
        d.options.mode = TL_MODE_FORWARD;
        bad = tl_mm_render(c, d, 1, hdr, NULL);
    }
    for (size_t i = 0; !bad && i < n; i++) {
        long code = lround(hdr[4 * i] * 8.0f);
        rows[i] = code >= 1 && code <= TL_MATERIAL_MODEL_COUNT_ ? (uint8_t)(code - 1) : TL_MM_NO_ROW;
    }
    free(hdr);
    tl_mm_free(c);
    return bad;
}

void tl_mm_compare(const float *a, const float *ref, const uint8_t *rows, size_t n, tl_mm_error *out)
{
    double se[TL_MATERIAL_MODEL_COUNT_] = {0};
    memset(out, 0, TL_MATERIAL_MODEL_COUNT_ * sizeof *out);
    for (size_t i = 0; i < n; i++) {
        if (rows[i] >= TL_MATERIAL_MODEL_COUNT_) continue;
        tl_mm_error *e = &out[rows[i]];
        e->pixels++;
        int nan = 0;
        for (int k = 0; k < 3; k++) {
            double x = a[4 * i + k], y = ref[4 * i + k];
            if (!isfinite(x)) {
                nan = 1;
                continue;
            }
            double cx = x < 0 ? 0 : x > 1 ? 1 : x, cy = y < 0 ? 0 : y > 1 ? 1 : y, d = fabs(x - y);
            se[rows[i]] += (cx - cy) * (cx - cy);
            if (d > e->max_abs) e->max_abs = d;
            double rel = d / fmax(fabs(y), 1e-3);
            if (rel > e->max_rel) e->max_rel = rel;
        }
        e->nan_pixels += (size_t)nan;
    }
    for (int m = 0; m < TL_MATERIAL_MODEL_COUNT_; m++) {
        double mse = out[m].pixels ? se[m] / (3.0 * (double)out[m].pixels) : 0.0;
        out[m].psnr_db = mse > 0.0 ? 10.0 * log10(1.0 / mse) : INFINITY;
    }
}
