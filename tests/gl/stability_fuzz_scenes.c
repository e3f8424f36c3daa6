/* Fuzzed scenes: seeded random soups of triangles (any size, any orientation, some through the near
 * plane, some double-sided, some textured or alpha-masked), random point, spot and directional
 * lights, rendered in visibility and in forward with tiles (Forward+), whose light loop and colour
 * visibility's resolve shares. Asserted per scene: both render, no target holds NaN or Inf, and
 * where both frames stored the same depth (the same surface: silhouettes and coplanar ties left
 * out) visibility's HDR is forward's within 4 FP16 steps per value on all but 0.5 % of the values
 * (the rebuilt barycentrics against the rasteriser's plane equations, through the lights), with no
 * value off by more than a quarter of its own size. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "stability.h"

#define FUZZ_W 160
#define FUZZ_H 96
#define FUZZ_TRIANGLES 48 /* 3 vertices each: 144 of MAX_V, 144 of MAX_I */

static float frand(tl_rng *r, float lo, float hi) { return lo + (hi - lo) * (float)tl_rng_unit(r); }

static void fuzz_scene(mini_scene *m, unsigned long long seed)
{
    tl_rng r = {seed};
    mini_init(m, 1.0f, 0.1f, 100.0f);
    static uint8_t texels[2][16 * 16 * 4];
    for (int t = 0; t < 2; t++) {
        for (int i = 0; i < 16 * 16 * 4; i++) texels[t][i] = (uint8_t)(tl_rng_u64(&r) & 0xFF);
        m->tex[t] = (tl_texture){.width = 16, .height = 16, .rgba = texels[t]};
        snprintf(m->tex[t].name, sizeof m->tex[t].name, "fuzz.%d", t);
    }
    m->s.textures = m->tex;
    m->s.texture_count = 2;
    m->mat[0] = plain_material(0.6f, 0.3f, 0.6f);
    m->mat[1] = plain_material(0.8f, 0.1f, 0.3f);
    m->mat[1].albedo_map = TL_TEXTURE_MAP(0);
    m->mat[1].flags = TL_MATERIAL_DOUBLE_SIDED;
    m->mat[2] = plain_material(0.4f, 0.5f, 0.9f);
    m->mat[2].albedo_map = TL_TEXTURE_MAP(1);
    m->mat[2].flags = TL_MATERIAL_ALPHA_MASK;
    m->mat[2].alpha = 1.0f;
    m->mat[2].alpha_cutoff = 0.5f;
    m->mat[3] = plain_material(0.7f, 0.0f, 0.2f);
    m->mat[3].flags = TL_MATERIAL_DOUBLE_SIDED;
    m->s.material_count = 4;
    /* three objects, a third of the triangles each */
    for (int o = 0; o < 3; o++) {
        tl_object *ob = &m->obj[m->s.object_count++];
        memcpy(ob->transform, identity, sizeof identity);
        ob->first_index = (uint32_t)m->ni;
        ob->material = (uint32_t)(tl_rng_u64(&r) % 4);
        for (int t = 0; t < FUZZ_TRIANGLES / 3; t++) {
            /* a centre in front of the camera (some near it, so that corners cross the near
             * plane), an extent from a sliver to larger than the view */
            float c[3] = {frand(&r, -3, 3), frand(&r, -2, 2), frand(&r, -12, -0.3f)};
            float size = powf(10.0f, frand(&r, -2.0f, 1.0f));
            float nrm[3];
            tl_rng_direction(&r, nrm);
            for (int k = 0; k < 3; k++) {
                tl_vertex *v = &m->v[m->nv];
                for (int a = 0; a < 3; a++) v->position[a] = c[a] + size * frand(&r, -1, 1);
                float d[3];
                tl_rng_direction(&r, d); /* per-vertex normals near a random one: curved */
                float len = 0.0f;
                for (int a = 0; a < 3; a++) v->normal[a] = nrm[a] + 0.3f * d[a], len += v->normal[a] * v->normal[a];
                for (int a = 0; a < 3; a++) v->normal[a] /= sqrtf(len);
                v->uv[0] = frand(&r, -2, 3);
                v->uv[1] = frand(&r, -2, 3);
                m->idx[m->ni++] = (uint32_t)m->nv++;
            }
        }
        ob->index_count = (uint32_t)m->ni - ob->first_index;
    }
    m->s.vertex_count = m->nv;
    m->s.index_count = m->ni;
    int lights = 2 + (int)(tl_rng_u64(&r) % 6);
    for (int i = 0; i < lights; i++) {
        float p[3] = {frand(&r, -4, 4), frand(&r, -3, 3), frand(&r, -10, 0)};
        tl_light *l = &m->light[i];
        *l = point_light(p[0], p[1], p[2], frand(&r, 2, 12), frand(&r, 0.5f, 3), frand(&r, 0.5f, 3), frand(&r, 0.5f, 3));
        int kind = (int)(tl_rng_u64(&r) % 4);
        if (kind == 1) {
            l->type = TL_LIGHT_SPOT;
            tl_rng_direction(&r, l->direction);
            l->cos_inner = 0.9f;
            l->cos_outer = 0.7f;
        } else if (kind == 2) {
            l->type = TL_LIGHT_DIRECTIONAL;
            tl_rng_direction(&r, l->direction);
        }
    }
    m->s.light_count = (size_t)lights;
    m->s.ambient[0] = m->s.ambient[1] = m->s.ambient[2] = 0.05f;
}

TL_TEST(fuzz_scenes_visibility_matches_forward)
{
    const int scenes = 24;
    size_t worst_share_at = 0, total = 0, total_beyond = 0;
    double worst_share = 0.0, worst_rel = 0.0;
    static mini_scene m;
    for (int k = 0; k < scenes; k++) {
        fuzz_scene(&m, 1000u + (unsigned long long)k);
        char label[64];
        run vis, fwd;
        tl_renderer_desc d = {.width = FUZZ_W, .height = FUZZ_H, .options.light_strategy = TL_LIGHT_STRATEGY_TILED};
        d.options.mode = TL_MODE_VISIBILITY;
        snprintf(label, sizeof label, "fuzz scene %d, visibility", k);
        int ok = run_scene(&vis, d, &m.s, label);
        if (ok) check_all_targets_finite(&vis, label);
        d.options.mode = TL_MODE_FORWARD;
        snprintf(label, sizeof label, "fuzz scene %d, forward", k);
        ok = run_scene(&fwd, d, &m.s, label) && ok;
        if (ok) check_all_targets_finite(&fwd, label);
        if (!ok || !vis.f.hdr || !fwd.f.hdr || !vis.f.depth || !fwd.f.depth) {
            TL_CHECK(!"both frames rendered and read");
            run_free(&vis);
            run_free(&fwd);
            continue;
        }
        size_t compared = 0, beyond = 0;
        for (size_t i = 0; i < (size_t)FUZZ_W * FUZZ_H; i++) {
            if (vis.f.depth[4 * i] != fwd.f.depth[4 * i] || vis.f.depth[4 * i] == vis.clear) continue;
            for (int c = 0; c < 3; c++) {
                double a = vis.f.hdr[4 * i + (size_t)c], b = fwd.f.hdr[4 * i + (size_t)c];
                double diff = fabs(a - b), scale = fmax(fabs(b), 1e-3);
                beyond += diff > 4.0 * TL_HALF_REL_STEP * scale + 0x1.0p-14;
                worst_rel = fmax(worst_rel, diff / scale);
                compared++;
            }
        }
        double share = compared ? (double)beyond / (double)compared : 1.0;
        if (share >= worst_share) worst_share = share, worst_share_at = (size_t)k;
        total += compared;
        total_beyond += beyond;
        TL_CHECK(compared > 300);
        TL_CHECK_LE(share, 0.005);
        run_free(&vis);
        run_free(&fwd);
    }
    printf("%d fuzzed scenes at %dx%d: %zu values on the same surface in visibility and forward, %zu beyond 4 FP16 "
           "steps (worst scene %zu: %.3f %%), worst relative difference %.3g\n",
           scenes, FUZZ_W, FUZZ_H, total, total_beyond, worst_share_at, 100.0 * worst_share, worst_rel);
    TL_CHECK_LE(worst_rel, 0.25);
}
