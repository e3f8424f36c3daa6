/* The scene of a sweep and its lights for each light count.
 *
 * "N lights" means N local lights (point + spot, the ones drawn as volumes), the same for every
 * mode, plus the scene's directional light(s):
 *   - built-in crypt: N/8 spot lights and N - N/8 point lights, laid out by the scene generator
 *     itself (tl_scene_create_default with those counts: it scales intensities with the count so
 *     that the image keeps its brightness), plus its one directional moonlight;
 *   - glTF file: the file's point and spot lights are replaced by the first N of the loader's
 *     seeded extra point lights (tl_gltf_options.extra_lights, loaded once for the largest N, so
 *     that every count shares a layout), with the crypt's scaling: radius times (8/N)^(1/6) and
 *     intensity chosen so that N x intensity x radius stays constant; the file's directional
 *     lights (or the loader's default key light) are kept. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "tool_gl.h"
#include "tool_util.h"

struct bench_scene {
    tl_scene *scene;     /* geometry and camera (lights replaced per light count) */
    int builtin;
    uint64_t seed;
    tl_light *lights;    /* the current light count's lights */
    size_t light_count;
    tl_light *fixed;     /* glTF: the file's directional lights */
    size_t fixed_count;
    const tl_light *extra; /* glTF: the loader's seeded point lights, for the largest N */
    size_t extra_count;
};

static int bench__load_file(const bench_options *opt, bench_scene *s, tl_tool_log *log)
{
    char error[512] = "";
    uint32_t largest = opt->lights[opt->light_count - 1];
    /* with --shadows on, the shadow rule (docs/gltf.md, "Shadows"); the lights' flags always */
    tl_gltf_options o = {.extra_lights = largest, .seed = opt->seed,
                         .shadow_lights = opt->shadows ? TL_SHADOW_DEFAULT_MAX_LIGHTS : 0};
    tl_tool_budget_gltf(&opt->budgets, &o);
    tl_result res = tl_tool_load_gltf(opt->scene, &o, log, &s->scene, error, sizeof error);
    if (res != TL_OK) {
        if (error[0]) tl_tool_fail(BENCH_TOOL, "cannot load scene %s", error);
        else tl_tool_fail(BENCH_TOOL, "cannot load scene '%s': %s", opt->scene, tl_result_string(res));
        return BENCH_EXIT_BAD_INPUT;
    }
    /* the loader appends the extra lights after the file's own (or its default rig) */
    if (s->scene->light_count < largest) {
        tl_tool_fail(BENCH_TOOL, "scene '%s': the loader gave %zu lights, fewer than the %u extra ones asked for",
                     opt->scene, s->scene->light_count, largest);
        return BENCH_EXIT_BAD_INPUT;
    }
    size_t own = s->scene->light_count - largest;
    s->extra = s->scene->lights + own;
    s->extra_count = largest;
    s->fixed = calloc(own + 1, sizeof *s->fixed);
    if (!s->fixed) {
        tl_tool_fail(BENCH_TOOL, "out of memory");
        return BENCH_EXIT_BAD_INPUT;
    }
    for (size_t i = 0; i < own; i++)
        if (s->scene->lights[i].type == TL_LIGHT_DIRECTIONAL) s->fixed[s->fixed_count++] = s->scene->lights[i];
    return 0;
}

int bench_scene_open(const bench_options *opt, bench_scene **out, bench_run *run)
{
    *out = NULL;
    bench_scene *s = calloc(1, sizeof *s);
    if (!s) {
        tl_tool_fail(BENCH_TOOL, "out of memory");
        return BENCH_EXIT_BAD_INPUT;
    }
    s->seed = opt->seed;
    s->builtin = strcmp(opt->scene, "default") == 0;
    if (s->builtin) {
        /* geometry only: the lights come per light count */
        tl_result res = tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 1, .spot_lights = 0,
                                                                         .seed = opt->seed}, &s->scene);
        if (res != TL_OK) {
            tl_tool_fail(BENCH_TOOL, "building the default scene: %s", tl_result_string(res));
            free(s);
            return BENCH_EXIT_BAD_INPUT;
        }
        snprintf(run->scene_name, sizeof run->scene_name, "built-in crypt");
        snprintf(run->light_definition, sizeof run->light_definition,
                 "lights = local lights per frame (point + spot, 1 in 8 a spot light), plus the crypt's directional "
                 "moonlight");
        snprintf(run->shadow_casters, sizeof run->shadow_casters, "the moonlight and the braziers");
    } else {
        int rc = bench__load_file(opt, s, &run->log);
        if (rc) {
            bench_scene_close(s);
            return rc;
        }
        const char *base = strrchr(opt->scene, '/');
        snprintf(run->scene_name, sizeof run->scene_name, "%s", base ? base + 1 : opt->scene);
        run->scene_file_lights = s->scene->light_count - s->extra_count;
        snprintf(run->light_definition, sizeof run->light_definition,
                 "lights = seeded point lights per frame (the file's point and spot lights left out), plus its %zu "
                 "directional light(s)", s->fixed_count);
        snprintf(run->shadow_casters, sizeof run->shadow_casters,
                 "those the loader's shadow rule and the file's thinlight_shadow flags make cast: docs/gltf.md");
    }
    run->scene_triangles = s->scene->index_count / 3;
    run->scene_objects = s->scene->object_count;
    *out = s;
    return 0;
}

const tl_scene *bench_scene_get(const bench_scene *s) { return s->scene; }

/* The crypt generator's own lights for n: n/8 spots, the rest points, one directional; with
 * `shadows` the moonlight and the braziers cast (the layout is the same). */
static int bench__crypt_lights(bench_scene *s, uint32_t n, int shadows)
{
    uint32_t spots = n / 8, points = n - spots;
    tl_scene *lit = NULL;
    /* Lights do not depend on the tessellation level (default_scene.c), so the cheapest one does. */
    tl_result res = tl_scene_create_default(&(tl_default_scene_desc){.point_lights = points ? points : 1,
                                                                     .spot_lights = spots, .seed = s->seed,
                                                                     .detail = 1, .shadows = shadows}, &lit);
    if (res != TL_OK) {
        tl_tool_fail(BENCH_TOOL, "building %u lights: %s", n, tl_result_string(res));
        return 1;
    }
    free(s->lights);
    s->lights = calloc(lit->light_count + 1, sizeof *s->lights);
    s->light_count = 0;
    if (!s->lights) {
        tl_scene_destroy(lit);
        tl_tool_fail(BENCH_TOOL, "out of memory");
        return 1;
    }
    for (size_t i = 0; i < lit->light_count; i++) {
        const tl_light *l = &lit->lights[i];
        if (n == 0 && l->type != TL_LIGHT_DIRECTIONAL) continue;
        s->lights[s->light_count++] = *l;
    }
    tl_scene_destroy(lit);
    return 0;
}

/* The first n of the loader's extra point lights, scaled like the crypt's, and the file's
 * directional lights. */
static int bench__file_lights(bench_scene *s, uint32_t n)
{
    free(s->lights);
    s->lights = calloc((size_t)n + s->fixed_count + 1, sizeof *s->lights);
    s->light_count = 0;
    if (!s->lights || n > s->extra_count) {
        tl_tool_fail(BENCH_TOOL, "out of memory");
        return 1;
    }
    double scale = 8.0 / (n > 8 ? n : 8), shrink = pow(scale, 1.0 / 6.0), dim = scale / shrink;
    for (uint32_t i = 0; i < n; i++) {
        tl_light *l = &s->lights[s->light_count++];
        *l = s->extra[i];
        l->radius = (float)(l->radius * shrink);
        for (int k = 0; k < 3; k++) l->color[k] = (float)(l->color[k] * dim);
    }
    for (size_t i = 0; i < s->fixed_count; i++) s->lights[s->light_count++] = s->fixed[i];
    return 0;
}

int bench_scene_lights(bench_scene *s, uint32_t n, const tl_light **lights, size_t *count)
{
    return bench_scene_casting_lights(s, n, 0, lights, count);
}

int bench_scene_casting_lights(bench_scene *s, uint32_t n, int shadows, const tl_light **lights, size_t *count)
{
    int err = s->builtin ? bench__crypt_lights(s, n, shadows) : bench__file_lights(s, n);
    *lights = s->lights;
    *count = s->light_count;
    return err;
}

void bench_scene_close(bench_scene *s)
{
    if (!s) return;
    tl_scene_destroy(s->scene);
    free(s->lights);
    free(s->fixed);
    free(s);
}

size_t bench_scene_bytes(const bench_scene *s)
{
    const tl_scene *sc = s->scene;
    double bytes = (double)sc->vertex_count * sizeof(tl_vertex) + (double)sc->index_count * sizeof(uint32_t);
    for (size_t i = 0; i < sc->texture_count; i++)
        bytes += (double)sc->textures[i].width * sc->textures[i].height * 4.0 * 4.0 / 3.0;
    return bytes < (double)SIZE_MAX ? (size_t)bytes : SIZE_MAX;
}
