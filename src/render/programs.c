/* Shader permutations: compiled on first use and cached for the renderer's life, keyed by the
 * shader files and the plan's #defines, so re-planning for another scene compiles only what is new.
 * Every program gets the binding points of bindings.h and the targets' texture units as #defines,
 * so the shaders declare `layout(binding = TL_UNIT_RT0)` and no frame sets a sampler or looks up
 * a uniform. */
#include <stdio.h>
#include <string.h>

#include "device.h"
#include "targets.h"

#define TL__BINDING_STRING(name, value) "TL_" #name "=" #value,
static const char *const tl__binding_defines[] = {TL__BINDING_LIST(TL__BINDING_STRING)};
#define TL__BINDING_DEFINE_COUNT (sizeof tl__binding_defines / sizeof tl__binding_defines[0])
/* The fixed binding defines, a unit per target, then room for a program's own switches (with 64
 * in all, two more targets left a material program 6 of its 9 switches, silently) */
#define TL__MAX_DEFINES (TL__BINDING_DEFINE_COUNT + TL_TARGET_COUNT + 64)

/* Splits the space-separated `defines` (copied into buf) after the fixed binding defines. */
static size_t tl__define_list(const char *defines, char *buf, size_t buf_size, char units[][32], const char **out)
{
    size_t n = 0;
    const tl__target_def *defs[TL_TARGET_COUNT];
    tl__target_defs(defs);
    for (size_t i = 0; i < TL__BINDING_DEFINE_COUNT; i++) out[n++] = tl__binding_defines[i];
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        if (!defs[t]) continue;
        snprintf(units[t], 32, "TL_UNIT_%s=%d", defs[t]->macro, t);
        out[n++] = units[t];
    }
    snprintf(buf, buf_size, "%s", defines);
    for (char *c = buf; *c && n < TL__MAX_DEFINES;) { /* strtok keeps hidden state: split by hand */
        while (*c == ' ') *c++ = '\0';
        if (!*c) break;
        out[n++] = c;
        while (*c && *c != ' ') c++;
    }
    return n;
}

static tl_result tl__cache_grow(tl__device *r)
{
    if (r->cache_count < r->cache_capacity) return TL_OK;
    size_t cap = r->cache_capacity ? r->cache_capacity * 2 : 16;
    tl__program_entry *n = (tl__program_entry *)tl__alloc_array(&r->alloc, cap, sizeof *n);
    if (!n) return tl__fail(r, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for the program cache");
    if (r->cache_count) memcpy(n, r->cache, r->cache_count * sizeof *n);
    tl__free(&r->alloc, r->cache);
    r->cache = n;
    r->cache_capacity = cap;
    return TL_OK;
}

tl_result tl__program_get(tl__device *r, const char *label, const tl__program_src *src, const char *defines,
                          GLuint *out)
{
    char key[512];
    snprintf(key, sizeof key, "%s|%s|%s|%s", src->vs ? src->vs : "", src->fs ? src->fs : "", src->cs ? src->cs : "",
             defines);
    for (size_t i = 0; i < r->cache_count; i++)
        if (strcmp(r->cache[i].key, key) == 0) {
            *out = r->cache[i].program;
            return TL_OK;
        }
    tl_result res = tl__cache_grow(r);
    if (res != TL_OK) return res;
    char buf[512], units[TL_TARGET_COUNT][32];
    const char *defs[TL__MAX_DEFINES];
    tl__program_desc pd = {0};
    pd.label = label;
    if (src->cs) {
        pd.stages[0] = (tl__shader_stage){GL_COMPUTE_SHADER, src->cs, NULL};
    } else {
        pd.stages[0] = (tl__shader_stage){GL_VERTEX_SHADER, src->vs, NULL};
        pd.stages[1] = (tl__shader_stage){GL_FRAGMENT_SHADER, src->fs, NULL};
    }
    pd.defines = defs;
    pd.define_count = tl__define_list(defines, buf, sizeof buf, units, defs);
    char log[2048];
    GLuint p = 0;
    res = tl__program_build(&r->gl, &pd, &p, log, sizeof log);
    if (res != TL_OK) return tl__fail(r, res, "program %.64s (%.128s): %.700s", label, defines, log);
    tl__program_entry *e = &r->cache[r->cache_count++];
    snprintf(e->key, sizeof e->key, "%s", key);
    e->program = p;
    r->programs_compiled++;
    *out = p;
    return TL_OK;
}

void tl__program_cache_destroy(tl__device *r)
{
    for (size_t i = 0; i < r->cache_count; i++) r->gl.DeleteProgram(r->cache[i].program);
    tl__free(&r->alloc, r->cache);
    r->cache = NULL;
    r->cache_count = r->cache_capacity = 0;
}
