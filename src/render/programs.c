/* Shader permutations: compiled on first use and cached for the renderer's life, keyed by the
 * shader files and the plan's #defines, so re-planning for another scene compiles only what is new. */
#include <stdio.h>
#include <string.h>

#include "renderer_internal.h"

#define TL__MAX_DEFINES 24

tl_result tl__program_get(tl_renderer *r, const char *label, const char *vs, const char *fs, const char *defines,
                          GLuint *out)
{
    char key[256];
    snprintf(key, sizeof key, "%s|%s|%s", vs, fs, defines);
    for (size_t i = 0; i < r->cache_count; i++)
        if (strcmp(r->cache[i].key, key) == 0) {
            *out = r->cache[i].program;
            return TL_OK;
        }
    if (r->cache_count == r->cache_capacity) {
        size_t cap = r->cache_capacity ? r->cache_capacity * 2 : 16;
        tl__program_entry *n = (tl__program_entry *)tl__alloc(&r->alloc, cap * sizeof *n);
        if (!n) return tl__fail(r, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for the program cache");
        if (r->cache_count) memcpy(n, r->cache, r->cache_count * sizeof *n);
        tl__free(&r->alloc, r->cache);
        r->cache = n;
        r->cache_capacity = cap;
    }
    /* split the space-separated defines */
    char buf[256];
    snprintf(buf, sizeof buf, "%s", defines);
    const char *defs[TL__MAX_DEFINES];
    size_t nd = 0;
    for (char *c = buf; *c && nd < TL__MAX_DEFINES;) { /* strtok keeps hidden state: split by hand */
        while (*c == ' ') *c++ = '\0';
        if (!*c) break;
        defs[nd++] = c;
        while (*c && *c != ' ') c++;
    }
    tl__program_desc pd = {0};
    pd.label = label;
    pd.stages[0] = (tl__shader_stage){GL_VERTEX_SHADER, vs, NULL};
    pd.stages[1] = (tl__shader_stage){GL_FRAGMENT_SHADER, fs, NULL};
    pd.defines = defs;
    pd.define_count = nd;
    char log[2048];
    GLuint p = 0;
    tl_result res = tl__program_build(&r->gl, &pd, &p, log, sizeof log);
    if (res != TL_OK) return tl__fail(r, res, "program %.64s (%.128s): %.2047s", label, defines, log);
    tl__program_entry *e = &r->cache[r->cache_count++];
    snprintf(e->key, sizeof e->key, "%s", key);
    e->program = p;
    r->programs_compiled++;
    *out = p;
    return TL_OK;
}

void tl__program_cache_destroy(tl_renderer *r)
{
    for (size_t i = 0; i < r->cache_count; i++) r->gl.DeleteProgram(r->cache[i].program);
    tl__free(&r->alloc, r->cache);
    r->cache = NULL;
    r->cache_count = r->cache_capacity = 0;
}

tl_result tl__plan_programs(tl_renderer *r)
{
    memset(r->prog, 0, sizeof r->prog);
    memset(r->prog_light, 0, sizeof r->prog_light);
    for (size_t i = 0; i < r->plan.program_count; i++) {
        const tl_plan_program *pp = &r->plan.programs[i];
        const char *vs = "gbuffer.vert.glsl", *fs = NULL;
        GLuint *slot = &r->prog[pp->pass];
        switch (pp->pass) {
        case TL_PASS_DEPTH_PREPASS:
        case TL_PASS_FORWARD:
        case TL_PASS_TRANSPARENT: fs = "forward.frag.glsl"; break;
        case TL_PASS_GBUFFER: fs = "gbuffer.frag.glsl"; break;
        case TL_PASS_MATERIAL: fs = "material.frag.glsl"; break;
        case TL_PASS_LIGHTS:
            vs = "light.vert.glsl";
            fs = "light.frag.glsl";
            if (strstr(pp->defines, "TL_LIGHT_TYPE=1")) slot = &r->prog_light[0];
            else if (strstr(pp->defines, "TL_LIGHT_TYPE=2")) slot = &r->prog_light[1];
            else slot = &r->prog_light[2];
            break;
        case TL_PASS_TONEMAP:
            vs = "fullscreen.vert.glsl";
            fs = "tonemap.frag.glsl";
            break;
        case TL_PASS_FXAA:
            vs = "fullscreen.vert.glsl";
            fs = "fxaa.frag.glsl";
            break;
        case TL_PASS_COUNT: break;
        }
        if (!fs) continue;
        tl_result res = tl__program_get(r, pp->name, vs, fs, pp->defines, slot);
        if (res != TL_OK) return res;
    }
    return tl__program_get(r, "luma", "fullscreen.vert.glsl", "luma.frag.glsl", "", &r->prog_luma);
}
