/* Shader permutations: compiled on first use and cached for the renderer's life, keyed by the
 * shader files, the plan's #defines and the targets its pass binds, so re-planning for another scene
 * compiles only what is new. Every program gets the binding points of bindings.h and its pass's
 * texture and image units as #defines (TL_UNIT_<TARGET>, TL_IMAGE_<TARGET>: bindings.h), so the
 * shaders declare `layout(binding = TL_UNIT_RT0)` and no frame sets a sampler or looks up a
 * uniform. */
#include <stdio.h>
#include <string.h>

#include "device.h"
#include "targets.h"

#define TL__BINDING_STRING(name, value) "TL_" #name "=" #value,
static const char *const tl__binding_defines[] = {TL__BINDING_LIST(TL__BINDING_STRING)};
#define TL__BINDING_DEFINE_COUNT (sizeof tl__binding_defines / sizeof tl__binding_defines[0])
/* The bindings, three per target (texture and image unit, colour location) and every switch a key
 * has: no define is ever dropped (a fixed 64 once pushed a light program's last define out). */
#define TL__MAX_DEFINES (TL__BINDING_DEFINE_COUNT + 3 * TL_TARGET_COUNT + TL__FLAG_COUNT + TL__VALUE_COUNT)

/* Every target's texture and image unit for a pass binding `u` (see tl__program_units), and the
 * colour location of each of its colour writes (TL_OUT_<TARGET>, tl_target_id order). */
static size_t tl__unit_defines(const tl__program_units *u, char (*units)[48], const char **out)
{
    size_t n = 0;
    uint32_t unit = 0, image = 0, location = 0;
    const tl__target_def *defs[TL_TARGET_COUNT];
    tl__target_defs(defs);
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        if (!defs[t]) continue;
        int sampled = u && (u->samples & TL_TARGET_BIT(t)), imaged = u && (u->images & TL_TARGET_BIT(t));
        snprintf(units[3 * t], 48, "TL_UNIT_%s=%u", defs[t]->macro, sampled ? unit++ : (unsigned)TL__UNIT_NONE);
        snprintf(units[3 * t + 1], 48, "TL_IMAGE_%s=%u", defs[t]->macro, imaged ? image++ : (unsigned)TL__IMAGE_NONE);
        out[n++] = units[3 * t];
        out[n++] = units[3 * t + 1];
        if (u && (u->writes & TL_TARGET_BIT(t)) && !defs[t]->depth && !defs[t]->buffer_bytes) {
            snprintf(units[3 * t + 2], 48, "TL_OUT_%s=%u", defs[t]->macro, location++);
            out[n++] = units[3 * t + 2];
        }
    }
    return n;
}

/* The fixed binding defines, the units and the key's switches. */
static size_t tl__define_list(const tl__perm *key, const tl__program_units *u, char *buf, char (*units)[48],
                              const char **out)
{
    size_t n = 0;
    for (size_t i = 0; i < TL__BINDING_DEFINE_COUNT; i++) out[n++] = tl__binding_defines[i];
    n += tl__unit_defines(u, units, out + n);
    if (key) n += tl__perm_split(key, buf, out + n);
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

tl_result tl__program_get(tl__device *r, const char *label, const tl__program_src *src, const tl__perm *key,
                          const tl__program_units *units, GLuint *out)
{
    tl__program_entry want;
    memset(&want, 0, sizeof want); /* compared whole: padding too */
    want.src = src;
    if (key) want.key = *key;
    if (units) want.units = *units;
    for (size_t i = 0; i < r->cache_count; i++)
        if (memcmp(&r->cache[i].src, &want.src, sizeof want - offsetof(tl__program_entry, src)) == 0) {
            *out = r->cache[i].program;
            return TL_OK;
        }
    tl_result res = tl__cache_grow(r);
    if (res != TL_OK) return res;
    char buf[TL__PERM_TEXT_MAX], unit_text[3 * TL_TARGET_COUNT][48];
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
    pd.define_count = tl__define_list(key, units, buf, unit_text, defs);
    char log[2048], text[256];
    GLuint p = 0;
    res = tl__program_build(&r->gl, &pd, &p, log, sizeof log);
    if (res != TL_OK) {
        if (key) tl__perm_format(key, text, sizeof text);
        else text[0] = '\0';
        return tl__fail(r, res, "program %.64s (%.128s): %.700s", label, text, log);
    }
    want.program = p;
    r->cache[r->cache_count++] = want;
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
