/* The shadows' truth for the bench (--shadows): the ray-traced visibility of
 * examples/common/shadow_rt.c (Embree 3, a test and bench dependency, never the library's),
 * linked in only where CMake found Embree (BENCH_WITH_EMBREE); without it every figure is "no
 * truth" with the reason. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_shadows.h"

#if BENCH_WITH_EMBREE
#include "shadow_rt.h"

struct bench_shadow_truth {
    uint32_t width, height;
    uint8_t *state;
    uint32_t *object;
};

bench_shadow_truth *bench_shadow_truth_make(const tl_scene *scene, const tl_light *light, uint32_t w, uint32_t h,
                                            char *why, size_t why_size)
{
    bench_shadow_truth *t = calloc(1, sizeof *t);
    tl_shadow_rt *rt = t ? tl_shadow_rt_create(scene) : NULL;
    if (t) {
        t->width = w, t->height = h;
        t->state = malloc((size_t)w * h);
        t->object = malloc((size_t)w * h * sizeof *t->object);
    }
    if (!rt || !t->state || !t->object) {
        snprintf(why, why_size, "%s", rt ? "out of memory for the truth" : "Embree could not build the scene");
        tl_shadow_rt_destroy(rt);
        bench_shadow_truth_free(t);
        return NULL;
    }
    tl_shadow_rt_truth(rt, &scene->camera, w, h, light, t->state, t->object);
    tl_shadow_rt_destroy(rt);
    why[0] = '\0';
    return t;
}

void bench_shadow_truth_free(bench_shadow_truth *t)
{
    if (!t) return;
    free(t->state);
    free(t->object);
    free(t);
}

void bench_shadow_truth_compare(const bench_shadow_truth *t, const float *term, const float *fat,
                                bench_shadow_error *out)
{
    tl_shadow_error e = tl_shadow_rt_compare(t->state, t->object, term, t->width, t->height, BENCH_SHADOW_BAND);
    out->measured = 1;
    out->counted += e.counted, out->acne += e.acne, out->leaks += e.leaks;
    out->wrong = out->counted ? (double)(out->acne + out->leaks) / (double)out->counted : NAN;
    if (!fat) return;
    tl_shadow_error f = tl_shadow_rt_compare_terms(t->state, t->object, term, fat, t->width, t->height,
                                                   BENCH_SHADOW_BAND);
    out->fat_counted += f.counted, out->fat_differ += f.acne + f.leaks;
    out->vs_fat = out->fat_counted ? (double)out->fat_differ / (double)out->fat_counted : NAN;
}

#else

struct bench_shadow_truth {
    int unused;
};

bench_shadow_truth *bench_shadow_truth_make(const tl_scene *scene, const tl_light *light, uint32_t w, uint32_t h,
                                            char *why, size_t why_size)
{
    (void)scene, (void)light, (void)w, (void)h;
    snprintf(why, why_size, "this thinlight-bench was built without Embree 3 (libembree-dev)");
    return NULL;
}

void bench_shadow_truth_free(bench_shadow_truth *t) { free(t); }

void bench_shadow_truth_compare(const bench_shadow_truth *t, const float *term, const float *fat,
                                bench_shadow_error *out)
{
    (void)t, (void)term, (void)fat;
    out->wrong = out->vs_fat = NAN;
}

#endif
