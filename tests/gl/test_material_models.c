/* Material models (scene.h tl_material.model; docs/lighting.md, "Material models"), on the
 * showcase scene: the plan builds one material-pass program per model present and nothing for a
 * standard-only scene; the standard model's pixels do not change when other models are on screen;
 * the models the light sums hold exactly match forward's per-light evaluation as closely as the
 * standard model does; the wrap model's thin-lpp scaling and forward's exact weight against a double
 * evaluation on facing quads; the specular/ior mapping is the F0 it says; bad parameters are refused. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "models_measure.h"
#include "render_fixture.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"
#include "tl_test.h"

#define W 320
#define H 180

/* The loader is spelled out: models_measure.c makes renderers from this descriptor itself. */
static tl_renderer_desc desc(tl_render_mode mode)
{
    return (tl_renderer_desc){.width = W, .height = H, .options = {.mode = mode},
                              .get_proc_address = tl_context_proc_loader, .get_proc_address_user = g_ctx,
                              .logger = tl_test_logger};
}

static tl_scene *showcase(uint32_t lights)
{
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_showcase(&(tl_showcase_scene_desc){.point_lights = lights}, &s) == TL_OK);
    return s;
}

/* The material pass's programs of a plan for `models`: count, and whether any program of any pass
 * names the models' switches. */
static size_t material_programs(uint32_t models, int *switches, char names[][32])
{
    tl_scene_feature_set f = {.point_lights = 4, .has_specular = 1, .has_microfacet = 1, .material_models = models};
    static tl_frame_plan p;
    TL_CHECK(tl_frame_plan_build(&(tl_renderer_desc){.width = 64, .height = 64}, &f, &p) == TL_OK);
    size_t n = 0;
    *switches = 0;
    for (size_t i = 0; i < p.program_count; i++) {
        if (strstr(p.programs[i].defines, "TL_MODEL") || strstr(p.programs[i].defines, "TL_MATERIAL_MODELS"))
            *switches = 1;
        if (p.programs[i].pass == TL_PASS_MATERIAL) snprintf(names[n++], 32, "%s", p.programs[i].name);
    }
    return n;
}

TL_TEST(material_models_plan_one_program_per_model)
{
    char names[8][32];
    int switches = 0;
    /* a hand-made feature set (0) and a scene of standard materials (bit 0): today's one program */
    for (uint32_t models = 0; models <= 1; models++) {
        TL_CHECK_EQ_U(material_programs(models, &switches, names), 1);
        TL_CHECK(strcmp(names[0], "material") == 0);
        TL_CHECK(!switches);
    }
    TL_CHECK_EQ_U(material_programs(1u << TL_MATERIAL_MODEL_TOON, &switches, names), 1);
    TL_CHECK(strcmp(names[0], "material.toon") == 0 && switches);
    TL_CHECK_EQ_U(material_programs((1u << TL_MATERIAL_MODEL_COUNT_) - 1u, &switches, names), TL_MATERIAL_MODEL_COUNT_);
    for (uint32_t m = 1; m < TL_MATERIAL_MODEL_COUNT_; m++) {
        char want[32];
        snprintf(want, sizeof want, "material.%s", tl_material_model_name(m));
        TL_CHECK(strcmp(names[m], want) == 0);
    }
    /* the showcase's features name all six; its standard-only copy none but the standard one */
    tl_scene *s = showcase(8), *std = s ? tl_mm_standard_only(s) : NULL;
    if (!std) return;
    tl_scene_feature_set fs, fstd;
    tl_scene_features(s, &fs);
    tl_scene_features(std, &fstd);
    TL_CHECK_EQ_U(fs.material_models, (1u << TL_MATERIAL_MODEL_COUNT_) - 1u);
    TL_CHECK_EQ_U(fstd.material_models, 1u);
    tl_mm_free(std);
    tl_scene_destroy(s);
}

/* The standard row's pixels, byte for byte, with and without the other models on screen. */
TL_TEST(material_models_standard_pixels_unchanged_by_other_models)
{
    if (!ensure_context()) return;
    tl_scene *s = showcase(8), *std = s ? tl_mm_standard_only(s) : NULL;
    size_t n = (size_t)W * H;
    float *a = malloc(n * 16), *b = malloc(n * 16);
    uint8_t *rows = malloc(n);
    TL_CHECK(std && a && b && rows && tl_mm_rows(s, desc(TL_MODE_FORWARD), rows) == 0);
    const tl_render_mode modes[5] = {TL_MODE_THIN_LPP, TL_MODE_FORWARD, TL_MODE_FAT, TL_MODE_THIN_DEFERRED,
                                     TL_MODE_VISIBILITY};
    for (int k = 0; k < 5 && std && a && b && rows; k++) {
        TL_CHECK(tl_mm_render(s, desc(modes[k]), 1, a, NULL) == 0);
        TL_CHECK(tl_mm_render(std, desc(modes[k]), 1, b, NULL) == 0);
        size_t standard = 0, differ = 0;
        for (size_t i = 0; i < n; i++) {
            if (rows[i] != TL_MATERIAL_MODEL_STANDARD) continue;
            standard++;
            differ += memcmp(a + 4 * i, b + 4 * i, 3 * sizeof(float)) != 0;
        }
        printf("  %s: %zu standard pixels, %zu differ\n", tl_render_mode_name(modes[k]), standard, differ);
        TL_CHECK_LE(W * H / 50, standard);
        TL_CHECK_EQ_U(differ, 0);
    }
    free(a);
    free(b);
    free(rows);
    tl_mm_free(std);
    tl_scene_destroy(s);
}

/* Errors of thin-lpp against forward of `s` per row of the showcase `layout` (s or a copy). */
static int row_errors(const tl_scene *layout, const tl_scene *s, tl_mm_error *e)
{
    size_t n = (size_t)W * H;
    float *a = malloc(n * 16), *f = malloc(n * 16);
    uint8_t *rows = malloc(n);
    int bad = !a || !f || !rows || tl_mm_rows(layout, desc(TL_MODE_FORWARD), rows) ||
              tl_mm_render(s, desc(TL_MODE_THIN_LPP), 1, a, NULL) || tl_mm_render(s, desc(TL_MODE_FORWARD), 1, f, NULL);
    if (!bad) tl_mm_compare(a, f, rows, n, e);
    free(a);
    free(f);
    free(rows);
    return bad;
}

/* Unlit is exact (no light at all); toon ramps the same sums forward forms, so it is off only
 * where FP16 rounding moves a sum across a band edge; the clearcoat whose coat has the base's
 * roughness is exact in its coat and as close as the standard model in its base. Sheen and wrap are
 * approximations here (printed): the wrap's is bounded in
 * material_models_wrap_thin_lpp_bounded_by_double_reference. */
TL_TEST(material_models_exact_ones_match_forward)
{
    if (!ensure_context()) return;
    tl_scene *s = showcase(64);
    if (!s) return;
    for (size_t i = 0; i + 1 < s->material_count; i++) /* the coats as rough as their bases */
        s->materials[i].clearcoat_roughness = 1.0f - s->materials[i].gloss;
    tl_mm_error e[TL_MATERIAL_MODEL_COUNT_], base[TL_MATERIAL_MODEL_COUNT_];
    tl_scene *std = tl_mm_standard_only(s); /* the same spheres, every one standard */
    TL_CHECK(std && row_errors(s, s, e) == 0 && row_errors(s, std, base) == 0);
    tl_mm_free(std);
    for (int m = 0; m < TL_MATERIAL_MODEL_COUNT_; m++) {
        printf("  %-9s %5zu px  PSNR %6.1f dB  max abs %.3g  max rel %.3g\n", tl_material_model_name((uint32_t)m),
               e[m].pixels, e[m].psnr_db, e[m].max_abs, e[m].max_rel);
        TL_CHECK_EQ_U(e[m].nan_pixels, 0);
        TL_CHECK_LE(W * H / 200, e[m].pixels);
    }
    /* FP16: unlit reads no light, so its colour is the same float computation in both modes */
    TL_CHECK_LE(e[TL_MATERIAL_MODEL_UNLIT].max_rel, 1.0 / 1024.0);
    /* the coat's sums are the standard model's sums (same roughness, same G-buffer): its error is
     * the thin G-buffer's, on pixels whose specular light the coat at most doubles (Fc <= 1 on
     * top of the base's (1 - Fc)): at most 20 log10(2) = 6.02 dB below the same spheres' error
     * when standard */
    printf("  the clearcoat row's spheres as standard: PSNR %.1f dB\n", base[TL_MATERIAL_MODEL_CLEARCOAT].psnr_db);
    TL_CHECK_LE(base[TL_MATERIAL_MODEL_CLEARCOAT].psnr_db - 6.03, e[TL_MATERIAL_MODEL_CLEARCOAT].psnr_db);
    TL_CHECK_LE(40.0, e[TL_MATERIAL_MODEL_TOON].psnr_db); /* the target */
    TL_CHECK_LE(40.0, e[TL_MATERIAL_MODEL_STANDARD].psnr_db);
    tl_scene_destroy(s);
}

/* A plan of `f` at 64x64 with the clearcoat choice `cc` (and a light scale). */
static void coat_plan(const tl_scene_feature_set *f, tl_clearcoat_lighting cc, float scale, tl_frame_plan *p)
{
    tl_renderer_desc d = {.width = 64, .height = 64, .options = {.clearcoat = cc, .light_scale = scale}};
    TL_CHECK(tl_frame_plan_build(&d, f, p) == TL_OK);
}

/* Two plans the same: passes, targets, bytes and every program's switches. */
static int plans_equal(const tl_frame_plan *a, const tl_frame_plan *b)
{
    int same = a->pass_count == b->pass_count && a->targets == b->targets && a->program_count == b->program_count &&
               a->allocated_bytes_per_pixel == b->allocated_bytes_per_pixel && a->bytes_per_pixel == b->bytes_per_pixel;
    for (size_t i = 0; same && i < a->pass_count; i++)
        same = a->passes[i].reads == b->passes[i].reads && a->passes[i].writes == b->passes[i].writes;
    for (size_t i = 0; same && i < a->program_count; i++)
        same = !strcmp(a->programs[i].name, b->programs[i].name) && !strcmp(a->programs[i].defines, b->programs[i].defines);
    return same;
}

/* TL_CLEARCOAT_SUMS: without a clearcoat drawn, the plan of every other model mix is the default's;
 * with one, volumes and tiles (fragment and compute) write the coat's sum, the G-buffer its gloss:
 * 1 + 8 B/px with RGBA16F; the default (auto) plans the same, with the stipple too; at a light
 * scale below 1 both fall back to the approximation, a downgrade only where the sums were asked. */
TL_TEST(material_models_clearcoat_sums_plan)
{
    static tl_frame_plan a, b;
    uint32_t all = (1u << TL_MATERIAL_MODEL_COUNT_) - 1u, cc = 1u << TL_MATERIAL_MODEL_CLEARCOAT;
    const uint32_t mixes[3] = {0u, 1u, all & ~cc};
    for (int k = 0; k < 3; k++) {
        tl_scene_feature_set f = {.point_lights = 4, .has_specular = 1, .has_microfacet = 1, .material_models = mixes[k]};
        coat_plan(&f, TL_CLEARCOAT_DEFAULT, 1.0f, &a);
        coat_plan(&f, TL_CLEARCOAT_SUMS, 1.0f, &b);
        TL_CHECK(plans_equal(&a, &b));
    }
    const size_t lights[2] = {4, 64}; /* volumes, tiles */
    for (int k = 0; k < 2; k++) {
        tl_scene_feature_set f = {.point_lights = lights[k], .has_specular = 1, .has_microfacet = 1, .material_models = all};
        coat_plan(&f, TL_CLEARCOAT_APPROXIMATE, 1.0f, &a);
        coat_plan(&f, TL_CLEARCOAT_SUMS, 1.0f, &b);
        tl_target_set coat = TL_TARGET_BIT(TL_TARGET_COAT_GLOSS) | TL_TARGET_BIT(TL_TARGET_LIGHT_COAT);
        TL_CHECK_EQ_U(a.targets & coat, 0);
        TL_CHECK_EQ_U(b.targets & coat, coat);
        TL_CHECK_EQ_U(b.target_bytes_per_pixel[TL_TARGET_COAT_GLOSS], 1);
        TL_CHECK_EQ_U(b.target_bytes_per_pixel[TL_TARGET_LIGHT_COAT], 8);
        TL_CHECK_EQ_U(b.bytes_per_pixel - a.bytes_per_pixel, 9);
        size_t coat_programs = 0;
        for (size_t i = 0; i < b.program_count; i++) coat_programs += strstr(b.programs[i].defines, "TL_COAT_SUMS") != NULL;
        TL_CHECK_LE(3, coat_programs); /* the G-buffer's, a light pass's, the material pass's */
        TL_CHECK(b.clearcoat == TL_CLEARCOAT_SUMS && a.clearcoat == TL_CLEARCOAT_APPROXIMATE);
        coat_plan(&f, TL_CLEARCOAT_DEFAULT, 1.0f, &a); /* auto: the sums */
        TL_CHECK(plans_equal(&a, &b) && a.clearcoat == TL_CLEARCOAT_SUMS && a.downgrade_count == 0);
        f.has_alpha_blend = 1; /* with the stipple too */
        f.alpha_blend_objects = 1;
        coat_plan(&f, TL_CLEARCOAT_DEFAULT, 1.0f, &a);
        TL_CHECK(a.transparency == TL_TRANSPARENCY_STIPPLE && (a.targets & coat) == coat);
        coat_plan(&f, TL_CLEARCOAT_SUMS, 0.5f, &b); /* asked where they cannot be: a downgrade */
        TL_CHECK_EQ_U(b.targets & coat, 0);
        TL_CHECK(b.clearcoat == TL_CLEARCOAT_APPROXIMATE && b.downgrade_count == 1 &&
                 !strcmp(b.downgrades[0].option, "clearcoat") && !strcmp(b.downgrades[0].planned, "approx"));
        coat_plan(&f, TL_CLEARCOAT_DEFAULT, 0.5f, &b); /* auto: the approximation, no downgrade */
        TL_CHECK(b.clearcoat == TL_CLEARCOAT_APPROXIMATE && b.downgrade_count == 0 && (b.targets & coat) == 0);
    }
}

/* The showcase's spheres as standard ones (`coat`: each clearcoat sphere made a pure specular
 * reflector of F0 1 at its coat's gloss, so its colour is the coat's sum S1 + S2 alone). */
static tl_scene *standard_spheres(const tl_scene *s, int coat)
{
    tl_scene *c = tl_mm_standard_only(s);
    for (size_t i = 0; c && coat && i + 1 < c->material_count; i++) {
        if (s->materials[i].model != TL_MATERIAL_MODEL_CLEARCOAT) continue;
        tl_material *m = &c->materials[i];
        m->flags &= ~(uint32_t)TL_MATERIAL_METALLIC_ROUGHNESS;
        m->albedo[0] = m->albedo[1] = m->albedo[2] = -1.0f;
        m->specular[0] = m->specular[1] = m->specular[2] = 1.0f;
        m->emissive[0] = m->emissive[1] = m->emissive[2] = 0.0f;
        m->gloss = 1.0f - s->materials[i].clearcoat_roughness;
    }
    return c;
}

/* Errors of thin-lpp (clearcoat choice cc) against forward of `s`, per row of `layout`. */
static int row_errors_cc(const tl_scene *layout, const tl_scene *s, tl_clearcoat_lighting cc, tl_mm_error *e)
{
    size_t n = (size_t)W * H;
    float *a = malloc(n * 16), *f = malloc(n * 16);
    uint8_t *rows = malloc(n);
    tl_renderer_desc d = desc(TL_MODE_THIN_LPP);
    d.options.clearcoat = cc;
    int bad = !a || !f || !rows || tl_mm_rows(layout, desc(TL_MODE_FORWARD), rows) || tl_mm_render(s, d, 1, a, NULL) ||
              tl_mm_render(s, desc(TL_MODE_FORWARD), 1, f, NULL);
    if (!bad) tl_mm_compare(a, f, rows, n, e);
    free(a);
    free(f);
    free(rows);
    return bad;
}

/* The coat's own sums: the clearcoat is (1 - Fc) c_base + Fc coat, both terms formed from sums as
 * exact as the standard model's, so per pixel its error is (1 - Fc) e_base + Fc e_coat, 0 <= Fc
 * <= 1; over the row (Minkowski) its RMS is at most RMS(e_base) + RMS(e_coat), each measured here
 * on standard spheres (the base; a pure specular of F0 1 at the coat's gloss). The bound in dB is
 * -20 log10 of that sum (PSNR's peak is 1); the margin is the coat byte's gloss step (1/254 against
 * RT0's 1/255) on a roughness-0.1 lobe, taken as the standard row's own spread between its two
 * light strategies (volumes at 8 lights, tiles at 64). The approximation must be worse. */
TL_TEST(material_models_clearcoat_sums_match_forward)
{
    if (!ensure_context()) return;
    const uint32_t counts[2] = {8, 64};
    double std_db[2] = {0.0, 0.0}, sums_db[2] = {0.0, 0.0}, bound_db[2] = {0.0, 0.0};
    for (int k = 0; k < 2; k++) {
        tl_scene *s = showcase(counts[k]), *base = s ? standard_spheres(s, 0) : NULL, *coat = s ? standard_spheres(s, 1) : NULL;
        TL_CHECK(base && coat);
        if (!base || !coat) return;
        tl_mm_error sums[TL_MATERIAL_MODEL_COUNT_], approx[TL_MATERIAL_MODEL_COUNT_], eb[TL_MATERIAL_MODEL_COUNT_],
            ec[TL_MATERIAL_MODEL_COUNT_];
        TL_CHECK(row_errors_cc(s, s, TL_CLEARCOAT_SUMS, sums) == 0 && row_errors_cc(s, s, TL_CLEARCOAT_APPROXIMATE, approx) == 0 &&
                 row_errors_cc(s, base, TL_CLEARCOAT_SUMS, eb) == 0 && row_errors_cc(s, coat, TL_CLEARCOAT_SUMS, ec) == 0);
        const int cc = TL_MATERIAL_MODEL_CLEARCOAT;
        double rms = pow(10.0, -eb[cc].psnr_db / 20.0) + pow(10.0, -ec[cc].psnr_db / 20.0);
        double bound = -20.0 * log10(rms);
        std_db[k] = sums[TL_MATERIAL_MODEL_STANDARD].psnr_db;
        printf("  %u lights: clearcoat sums %.1f dB (max abs %.3g), approx %.1f dB (max abs %.3g); base %.1f dB, coat "
               "%.1f dB: bound %.1f dB; standard row %.1f dB\n",
               counts[k], sums[cc].psnr_db, sums[cc].max_abs, approx[cc].psnr_db, approx[cc].max_abs, eb[cc].psnr_db,
               ec[cc].psnr_db, bound, std_db[k]);
        TL_CHECK_EQ_U(sums[cc].nan_pixels, 0);
        TL_CHECK_LE(W * H / 200, sums[cc].pixels);
        sums_db[k] = sums[cc].psnr_db;
        bound_db[k] = bound;
        TL_CHECK_LE(approx[cc].psnr_db + 10.0, sums[cc].psnr_db);
        tl_mm_free(base);
        tl_mm_free(coat);
        tl_scene_destroy(s);
    }
    double margin = fabs(std_db[1] - std_db[0]);
    printf("  margin %.2f dB\n", margin);
    for (int k = 0; k < 2; k++) TL_CHECK_LE(bound_db[k] - margin, sums_db[k]);
}

/* A copy of the showcase `s` with a glass pane (alpha-blended, alpha 0.4) standing between the
 * unlit and the clearcoat rows, in front of the clearcoat row's left three spheres; free with
 * free_with_pane. */
static tl_scene *with_pane(const tl_scene *s)
{
    tl_scene *c = calloc(1, sizeof *c);
    if (!c) return NULL;
    *c = *s;
    c->vertices = malloc((s->vertex_count + 4) * sizeof *c->vertices);
    c->indices = malloc((s->index_count + 6) * sizeof *c->indices);
    c->objects = malloc((s->object_count + 1) * sizeof *c->objects);
    c->materials = malloc((s->material_count + 1) * sizeof *c->materials);
    if (!c->vertices || !c->indices || !c->objects || !c->materials) return c; /* the caller sees the NULL */
    memcpy(c->vertices, s->vertices, s->vertex_count * sizeof *c->vertices);
    memcpy(c->indices, s->indices, s->index_count * sizeof *c->indices);
    memcpy(c->objects, s->objects, s->object_count * sizeof *c->objects);
    memcpy(c->materials, s->materials, s->material_count * sizeof *c->materials);
    const float x[4] = {-2.6f, 0.4f, 0.4f, -2.6f}, y[4] = {0.0f, 0.0f, 1.0f, 1.0f};
    for (int i = 0; i < 4; i++)
        c->vertices[s->vertex_count + (size_t)i] = (tl_vertex){.position = {x[i], y[i], 1.0f}, .normal = {0, 0, 1}};
    static const uint32_t quad[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 6; i++) c->indices[s->index_count + (size_t)i] = (uint32_t)s->vertex_count + quad[i];
    c->materials[s->material_count] = (tl_material){.albedo = {0.3f, 0.5f, 0.6f}, .alpha = 0.4f,
                                                    .flags = TL_MATERIAL_ALPHA_BLEND};
    c->objects[s->object_count] = (tl_object){.first_index = (uint32_t)s->index_count, .index_count = 6,
                                              .material = (uint32_t)s->material_count};
    c->vertex_count += 4;
    c->index_count += 6;
    c->object_count++;
    c->material_count++;
    return c;
}

static void free_with_pane(tl_scene *c)
{
    if (!c) return;
    free(c->vertices);
    free(c->indices);
    free(c->objects);
    free(c->materials);
    free(c);
}

/* HDR of `s` in thin-lpp with the default options and of its reference `ref` (W x H x 4 each). */
static int default_against(const tl_scene *s, tl_render_mode ref, float *lpp, float *out)
{
    return tl_mm_render(s, desc(TL_MODE_THIN_LPP), 1, lpp, NULL) || tl_mm_render(s, desc(ref), 1, out, NULL);
}

/* The default options keep a clearcoat's two lobes exact with a blended object on screen too (the
 * stipple): the coat's own sums are the default, gathered with the coat's lobe where a layer took
 * a pixel (stipple_opaque.glsl). On the showcase with a glass pane in front of the clearcoat row:
 * against forward, material_models_clearcoat_sums_match_forward's bound in the same frame (the
 * row's RMS error at most RMS(e_base) + RMS(e_coat), its spheres as standard bases and as pure
 * F0-1 speculars at the coat's gloss, each through the same stipple); and the target, at
 * least 50 dB against fat over the row. Before, the stipple planned the approximation: 31 dB from
 * forward and from fat. */
TL_TEST(material_models_clearcoat_default_with_blended_object_matches_fat)
{
    if (!ensure_context()) return;
    tl_scene *s = showcase(8), *base = s ? standard_spheres(s, 0) : NULL, *coat = s ? standard_spheres(s, 1) : NULL;
    tl_scene *ps = s ? with_pane(s) : NULL, *pb = base ? with_pane(base) : NULL, *pc = coat ? with_pane(coat) : NULL;
    size_t n = (size_t)W * H;
    float *lpp = malloc(n * 16), *ref = malloc(n * 16);
    uint8_t *rows = malloc(n);
    int ok = ps && pb && pc && ps->materials && pb->materials && pc->materials && lpp && ref && rows;
    ok = ok && tl_mm_rows(s, desc(TL_MODE_FORWARD), rows) == 0; /* each pixel's row, behind the pane too */
    tl_mm_error e[TL_MATERIAL_MODEL_COUNT_], ef[TL_MATERIAL_MODEL_COUNT_], eb[TL_MATERIAL_MODEL_COUNT_],
        ec[TL_MATERIAL_MODEL_COUNT_];
    if ((ok = ok && default_against(ps, TL_MODE_FAT, lpp, ref) == 0)) tl_mm_compare(lpp, ref, rows, n, ef);
    if ((ok = ok && tl_mm_render(ps, desc(TL_MODE_FORWARD), 1, ref, NULL) == 0)) tl_mm_compare(lpp, ref, rows, n, e);
    if ((ok = ok && default_against(pb, TL_MODE_FORWARD, lpp, ref) == 0)) tl_mm_compare(lpp, ref, rows, n, eb);
    if ((ok = ok && default_against(pc, TL_MODE_FORWARD, lpp, ref) == 0)) tl_mm_compare(lpp, ref, rows, n, ec);
    TL_CHECK(ok);
    tl_renderer *r = ok ? tl_test_renderer(&(tl_test_renderer_desc){.renderer = desc(TL_MODE_THIN_LPP), .scene = ps,
                                                                    .may_fail = true})
                        : NULL;
    tl_frame_plan plan;
    if (r && tl_renderer_get_plan(r, &plan) == TL_OK) {
        printf("  plan: clearcoat %s (%s), transparency %s\n", plan.clearcoat == TL_CLEARCOAT_SUMS ? "sums" : "approx",
               plan.clearcoat_reason, tl_transparency_name(plan.transparency));
        TL_CHECK(plan.transparency == TL_TRANSPARENCY_STIPPLE);
    }
    tl_renderer_destroy(r);
    if (ok) {
        const int cc = TL_MATERIAL_MODEL_CLEARCOAT;
        double bound = -20.0 * log10(pow(10.0, -eb[cc].psnr_db / 20.0) + pow(10.0, -ec[cc].psnr_db / 20.0));
        printf("  clearcoat row: %.1f dB from forward (max abs %.3g), %.1f dB from fat (max abs %.3g), %zu pixels; "
               "bound %.1f dB (base %.1f, coat %.1f)\n",
               e[cc].psnr_db, e[cc].max_abs, ef[cc].psnr_db, ef[cc].max_abs, e[cc].pixels, bound, eb[cc].psnr_db,
               ec[cc].psnr_db);
        TL_CHECK_LE(W * H / 200, e[cc].pixels);
        TL_CHECK_EQ_U(e[cc].nan_pixels, 0);
        TL_CHECK_LE(bound, e[cc].psnr_db);
        TL_CHECK_LE(50.0, ef[cc].psnr_db); /* the target */
    }
    free(lpp);
    free(ref);
    free(rows);
    free_with_pane(ps);
    free_with_pane(pb);
    free_with_pane(pc);
    tl_mm_free(base);
    tl_mm_free(coat);
    tl_scene_destroy(s);
}

/* The deferred modes shade each light under the model the G-buffer stores (fat_models.glsl): unlit
 * is exact (no light at all), wrap, clearcoat (and fat's sheen) are forward's per-light terms with
 * their parameters quantized (fat: 8 bits, the sheen's colour 4; thin-deferred: 5 bits, the coat's
 * factor 1 as the showcase's). Before the model was stored they were shaded as standard: 23, 30
 * and 12 dB against forward. */
TL_TEST(material_models_deferred_modes_match_forward)
{
    if (!ensure_context()) return;
    tl_scene *s = showcase(8);
    size_t n = (size_t)W * H;
    float *a = malloc(n * 16), *f = malloc(n * 16);
    uint8_t *rows = malloc(n);
    int bad = !s || !a || !f || !rows || tl_mm_rows(s, desc(TL_MODE_FORWARD), rows) ||
              tl_mm_render(s, desc(TL_MODE_FORWARD), 1, f, NULL);
    TL_CHECK(!bad);
    const tl_render_mode modes[2] = {TL_MODE_FAT, TL_MODE_THIN_DEFERRED};
    const double floor_db[2] = {50.0, 40.0}; /* measured 60.5 / 56.8 (fat), 43.5 / 53.6 (thin-deferred) */
    for (int k = 0; k < 2 && !bad; k++) {
        tl_mm_error e[TL_MATERIAL_MODEL_COUNT_];
        TL_CHECK(tl_mm_render(s, desc(modes[k]), 1, a, NULL) == 0);
        tl_mm_compare(a, f, rows, n, e);
        for (int m = 0; m < TL_MATERIAL_MODEL_COUNT_; m++)
            printf("  %-13s %-9s PSNR %6.1f dB  max abs %.3g\n", tl_render_mode_name(modes[k]),
                   tl_material_model_name((uint32_t)m), e[m].psnr_db, e[m].max_abs);
        TL_CHECK_LE(W * H / 200, e[TL_MATERIAL_MODEL_UNLIT].pixels);
        TL_CHECK_LE(e[TL_MATERIAL_MODEL_UNLIT].max_rel, 1.0 / 1024.0);
        TL_CHECK_LE(floor_db[k], e[TL_MATERIAL_MODEL_WRAP].psnr_db);
        TL_CHECK_LE(floor_db[k], e[TL_MATERIAL_MODEL_CLEARCOAT].psnr_db);
        TL_CHECK_LE(floor_db[k], e[TL_MATERIAL_MODEL_STANDARD].psnr_db);
        if (modes[k] == TL_MODE_FAT) TL_CHECK_LE(50.0, e[TL_MATERIAL_MODEL_SHEEN].psnr_db); /* measured 64.4 */
    }
    free(a);
    free(f);
    free(rows);
    tl_scene_destroy(s);
}

/* Visibility's resolve evaluates each material with forward's light loop and colour (the exact
 * per-light model terms, forward_color.glsl) on attributes rebuilt from the triangle: on the
 * showcase every model's pixel is forward's within 2 FP16 steps (each frame's HDR store rounds once,
 * GL allowing truncation: a whole step each; the sums are float in both). Against fat, which stores
 * the models' parameters quantized and shades toon as standard, its error is printed beside
 * forward's (material_models_deferred_modes_match_forward bounds fat's). */
TL_TEST(material_models_visibility_matches_forward_every_model)
{
    if (!ensure_context()) return;
    tl_scene *s = showcase(8);
    size_t n = (size_t)W * H;
    float *v = malloc(n * 16), *f = malloc(n * 16), *fat = malloc(n * 16);
    uint8_t *rows = malloc(n);
    int bad = !s || !v || !f || !fat || !rows || tl_mm_rows(s, desc(TL_MODE_FORWARD), rows) ||
              tl_mm_render(s, desc(TL_MODE_FORWARD), 1, f, NULL) || tl_mm_render(s, desc(TL_MODE_FAT), 1, fat, NULL) ||
              tl_mm_render(s, desc(TL_MODE_VISIBILITY), 1, v, NULL);
    TL_CHECK(!bad);
    if (!bad) {
        tl_mm_error ef[TL_MATERIAL_MODEL_COUNT_], vfat[TL_MATERIAL_MODEL_COUNT_], ffat[TL_MATERIAL_MODEL_COUNT_];
        tl_mm_compare(v, f, rows, n, ef);
        tl_mm_compare(v, fat, rows, n, vfat);
        tl_mm_compare(f, fat, rows, n, ffat);
        const double tol = 2.0 * ldexp(1.0, -10);
        size_t over[TL_MATERIAL_MODEL_COUNT_] = {0};
        for (size_t i = 0; i < n; i++)
            for (int c = 0; c < 3 && rows[i] < TL_MATERIAL_MODEL_COUNT_; c++)
                over[rows[i]] += fabs(v[4 * i + c] - f[4 * i + c]) > tol * fabs(f[4 * i + c]) + 0x1.0p-24;
        for (int m = 0; m < TL_MATERIAL_MODEL_COUNT_; m++) {
            printf("  %-9s %4zu pixels: against forward largest relative %.3g (bound %.3g), %zu values over; PSNR "
                   "against fat %.1f dB (forward's %.1f dB)\n",
                   tl_material_model_name((uint32_t)m), ef[m].pixels, ef[m].max_rel, tol, over[m], vfat[m].psnr_db,
                   ffat[m].psnr_db);
            TL_CHECK_LE(W * H / 400, ef[m].pixels);
            TL_CHECK_EQ_U(over[m], 0);
            TL_CHECK_EQ_U(ef[m].nan_pixels, 0);
        }
    }
    free(v);
    free(f);
    free(fat);
    free(rows);
    tl_scene_destroy(s);
}

/* KHR_materials_specular/_ior map onto F0: a metallic-roughness material converted per pixel from
 * dielectric_f0 renders as the constant material whose specular is mix(F0, base, metal) computed
 * here, in thin-lpp and forward. */
TL_TEST(material_models_dielectric_f0_is_the_specular_colour)
{
    if (!ensure_context()) return;
    tl_scene *s = showcase(8), *c = s ? tl_mm_standard_only(s) : NULL, *k = s ? tl_mm_standard_only(s) : NULL;
    uint8_t mr_px[4] = {0, 255, 255, 255}; /* roughness and metal factors taken as they are */
    tl_texture tex = {.width = 1, .height = 1, .rgba = mr_px, .name = "mr"};
    size_t n = (size_t)W * H;
    float *a = malloc(n * 16), *b = malloc(n * 16);
    if (!c || !k || !a || !b) goto done;
    c->textures = &tex;
    c->texture_count = 1;
    const float f0[3] = {0.12f, 0.08f, 0.05f}, metal = 0.3f;
    for (size_t i = 0; i + 1 < c->material_count; i++) {
        tl_material *m = &c->materials[i], *q = &k->materials[i];
        m->flags |= TL_MATERIAL_METALLIC_ROUGHNESS;
        m->metallic_roughness_map = TL_TEXTURE_MAP(0);
        m->metallic = metal;
        m->roughness = 1.0f - m->gloss;
        memcpy(m->dielectric_f0, f0, sizeof f0);
        for (int j = 0; j < 3; j++) {
            q->specular[j] = (float)((1.0 - metal) * f0[j] + (double)metal * m->albedo[j]);
            q->albedo[j] = (float)(m->albedo[j] * (1.0 - metal));
        }
    }
    const tl_render_mode modes[2] = {TL_MODE_THIN_LPP, TL_MODE_FORWARD};
    for (int mo = 0; mo < 2; mo++) {
        TL_CHECK(tl_mm_render(c, desc(modes[mo]), 1, a, NULL) == 0);
        TL_CHECK(tl_mm_render(k, desc(modes[mo]), 1, b, NULL) == 0);
        double worst = 0.0;
        for (size_t i = 0; i < 4 * n; i++)
            if (i % 4 != 3) worst = fmax(worst, fabs(a[i] - b[i]) / fmax(fabs(b[i]), 1e-3));
        printf("  %s: largest relative difference %.3g\n", tl_render_mode_name(modes[mo]), worst);
        /* float rounding of the two conversions, through FP16 sums: well inside one FP16 step */
        TL_CHECK_LE(worst, 1.0 / 1024.0);
    }
done:
    free(a);
    free(b);
    tl_mm_free(c);
    tl_mm_free(k);
    tl_scene_destroy(s);
}

/* Every mode draws every model finite and lit (fat and thin-deferred as the standard model). */
TL_TEST(material_models_every_mode_finite_and_lit)
{
    if (!ensure_context()) return;
    tl_scene *s = showcase(8);
    size_t n = (size_t)W * H;
    float *a = malloc(n * 16);
    uint8_t *rows = malloc(n);
    if (!s || !a || !rows) goto done;
    TL_CHECK(tl_mm_rows(s, desc(TL_MODE_FORWARD), rows) == 0);
    const tl_render_mode modes[5] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_FORWARD,
                                     TL_MODE_VISIBILITY};
    for (int k = 0; k < 5; k++) {
        TL_CHECK(tl_mm_render(s, desc(modes[k]), 1, a, NULL) == 0);
        double mean[TL_MATERIAL_MODEL_COUNT_] = {0};
        size_t count[TL_MATERIAL_MODEL_COUNT_] = {0}, bad = 0;
        for (size_t i = 0; i < n; i++) {
            for (int c = 0; c < 3; c++) bad += !isfinite(a[4 * i + c]);
            if (rows[i] < TL_MATERIAL_MODEL_COUNT_) {
                mean[rows[i]] += a[4 * i] + a[4 * i + 1] + a[4 * i + 2];
                count[rows[i]]++;
            }
        }
        TL_CHECK_EQ_U(bad, 0);
        for (int m = 0; m < TL_MATERIAL_MODEL_COUNT_; m++) TL_CHECK(count[m] > 0 && mean[m] / (double)count[m] > 0.05);
    }
done:
    free(a);
    free(rows);
    tl_scene_destroy(s);
}

TL_TEST(material_models_bad_parameters_refused)
{
    if (!ensure_context()) return;
    tl_scene *s = showcase(8);
    if (!s) return;
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = desc(TL_MODE_THIN_LPP)});
    const char *want[3] = {"model", "toon_steps", "sheen_roughness"};
    for (int k = 0; k < 3 && r; k++) {
        tl_material keep = s->materials[3];
        if (k == 0) s->materials[3].model = TL_MATERIAL_MODEL_COUNT_;
        if (k == 1) s->materials[3].toon_steps = 65;
        if (k == 2) s->materials[3].sheen_roughness = NAN;
        TL_CHECK(tl_renderer_set_scene(r, s) == TL_ERROR_INVALID_ARGUMENT);
        TL_CHECK(strstr(tl_renderer_last_error(r), want[k]) != NULL);
        s->materials[3] = keep;
        TL_CHECK(tl_renderer_set_scene(r, s) == TL_OK);
        tl_material bad = s->materials[3];
        bad.model = 77;
        TL_CHECK(tl_renderer_set_material(r, 3, &bad) == TL_ERROR_INVALID_ARGUMENT);
    }
    tl_renderer_destroy(r);
    tl_scene_destroy(s);
}

static void half_free(void *p, void *user)
{
    (void)user;
    free(p);
}

/* tl_showcase_scene_desc: zeroed is the NULL descriptor's scene (8 lights, seed 1); bad input is
 * refused with nothing returned. */
TL_TEST(material_models_showcase_desc_zero_is_default)
{
    tl_scene *a = NULL, *b = NULL, *c = NULL;
    TL_CHECK(tl_scene_create_showcase(NULL, &a) == TL_OK);
    TL_CHECK(tl_scene_create_showcase(&(tl_showcase_scene_desc){0}, &b) == TL_OK);
    TL_CHECK(tl_scene_create_showcase(&(tl_showcase_scene_desc){.point_lights = 8, .seed = 1}, &c) == TL_OK);
    if (a && b && c) {
        TL_CHECK_EQ_U(a->light_count, 8);
        TL_CHECK(a->light_count == b->light_count);
        TL_CHECK(memcmp(a->lights, b->lights, a->light_count * sizeof *a->lights) == 0);
        TL_CHECK(memcmp(a->lights, c->lights, a->light_count * sizeof *a->lights) == 0);
        TL_CHECK_EQ_U(a->object_count, (size_t)TL_MATERIAL_MODEL_COUNT_ * 5 + 1);
    }
    tl_scene *d = (tl_scene *)&d;
    TL_CHECK(tl_scene_create_showcase(&(tl_showcase_scene_desc){.point_lights = 65537}, &d) == TL_ERROR_LIMIT && !d);
    tl_allocator half = {.alloc = NULL, .free = half_free};
    TL_CHECK(tl_scene_create_showcase(&(tl_showcase_scene_desc){.allocator = half}, &d) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_scene_create_showcase(NULL, NULL) == TL_ERROR_INVALID_ARGUMENT);
    tl_scene_destroy(a);
    tl_scene_destroy(b);
    tl_scene_destroy(c);
}

/* Four quads facing the camera (view-space normal exactly +Z: the octahedral code is exact; gloss
 * k/255 exact in RT0; reversed D32F depth): thin-lpp differs from forward only by FP16. Standard
 * (a dielectric F0 other than 0.04), unlit and an emissive of strength 4 over 8 point lights: every
 * pixel within (lights + 2) FP16 ULPs of forward's value: each light's blend into a sum converts to
 * FP16 once and each mode's HDR write once, the terms are non-negative, and GL leaves the rounding
 * of a float-to-half conversion to the implementation (truncation allowed: a whole ULP each).
 * Visibility sums its lights in float as forward does: within 2 ULPs (the two HDR writes). */
TL_TEST(material_models_exact_ones_within_fp16_on_a_facing_plane)
{
    enum { Q = 4, L = 8 };
    static tl_vertex v[Q * 4];
    static uint32_t idx[Q * 6];
    static tl_object obj[Q];
    static tl_material mat[Q];
    static tl_light lights[L];
    for (int q = 0; q < Q; q++) {
        const float c[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int k = 0; k < 4; k++)
            v[q * 4 + k] = (tl_vertex){.position = {c[k][0] - 2.0f + (float)q, c[k][1] - 0.5f, 0.0f}, .normal = {0, 0, 1}};
        const uint32_t t[6] = {0, 1, 2, 0, 2, 3};
        for (int k = 0; k < 6; k++) idx[q * 6 + k] = (uint32_t)(q * 4) + t[k];
        obj[q] = (tl_object){.first_index = (uint32_t)(q * 6), .index_count = 6, .material = (uint32_t)q};
        mat[q] = (tl_material){.albedo = {0.6f, 0.4f, 0.3f}, .gloss = 153.0f / 255.0f, .flags = TL_MATERIAL_MICROFACET};
    }
    const float f0 = (float)((0.6 / 2.6) * (0.6 / 2.6)); /* ior 1.6 */
    for (int k = 0; k < 3; k++) mat[0].specular[k] = mat[2].specular[k] = f0;
    mat[1].model = TL_MATERIAL_MODEL_UNLIT;
    for (int k = 0; k < 3; k++) mat[3].emissive[k] = 4.0f * 0.25f;
    for (int i = 0; i < L; i++)
        lights[i] = (tl_light){.type = TL_LIGHT_POINT, .position = {-2.0f + 0.55f * (float)i, 0.3f * (float)(i % 3) - 0.3f,
                                                                    0.4f + 0.2f * (float)(i % 4)},
                               .color = {1.0f, 0.8f, 0.6f}, .radius = 6.0f};
    tl_scene s = {.vertices = v, .vertex_count = Q * 4, .indices = idx, .index_count = Q * 6, .objects = obj,
                  .object_count = Q, .materials = mat, .material_count = Q, .lights = lights, .light_count = L,
                  .camera = {.position = {0, 0, 4}, .target = {0, 0, 0}, .up = {0, 1, 0}, .near_z = 1, .far_z = 10}};
    if (!ensure_context()) return;
    size_t n = (size_t)W * H;
    float *a = malloc(n * 16), *f = malloc(n * 16);
    tl_renderer_desc d = desc(TL_MODE_FORWARD);
    d.options.depth_format = TL_DEPTH_FORMAT_D32F_REVERSED;
    TL_CHECK(a && f && tl_mm_render(&s, d, 1, f, NULL) == 0);
    /* thin-lpp's sums blend each light into FP16; visibility sums in float as forward does: its HDR
     * store and forward's round once each */
    const tl_render_mode modes[2] = {TL_MODE_THIN_LPP, TL_MODE_VISIBILITY};
    const double steps[2] = {L + 2, 2};
    for (int mo = 0; mo < 2; mo++) {
        d.options.mode = modes[mo];
        TL_CHECK(a && f && tl_mm_render(&s, d, 1, a, NULL) == 0);
        size_t lit = 0, over = 0;
        double worst = 0.0;
        for (size_t i = 0; a && f && i < n; i++) {
            if (f[4 * i] == 0.0f && f[4 * i + 1] == 0.0f && f[4 * i + 2] == 0.0f) continue; /* background */
            lit++;
            for (int k = 0; k < 3; k++) {
                double ref = f[4 * i + k], tol = steps[mo] * ldexp(1.0, -10) * ref + 1e-6, e = fabs(a[4 * i + k] - ref);
                worst = fmax(worst, e / fmax(ref, 1e-6));
                over += e > tol;
            }
        }
        printf("  %s: %zu pixels; largest relative difference %.3g (tolerance %.3g)\n", tl_render_mode_name(modes[mo]),
               lit, worst, steps[mo] * ldexp(1.0, -10));
        TL_CHECK_LE(n / 16, lit);
        TL_CHECK_EQ_U(over, 0);
    }
    free(a);
    free(f);
}

/* ---- the wrap model in thin-lpp -------------------------------------------------------------------- */

enum { WQ = 4, WL = 4, WW = 160, WH = 90 };
static const float wrap_w[WQ] = {0.25f, 0.5f, 1.0f, 0.0f}; /* the last quad standard */

/* Directional lights at angles acos(nl[i]) from the quads' normal +Z (view space: the camera looks
 * down -Z from +Z), azimuths a quarter turn apart, colours of different sums. */
static void wrap_lights(const double nl[WL], tl_light out[WL])
{
    for (int i = 0; i < WL; i++) {
        double s = sqrt(1.0 - nl[i] * nl[i]), phi = 1.5707963267948966 * i;
        out[i] = (tl_light){.type = TL_LIGHT_DIRECTIONAL,
                            .direction = {(float)(-s * cos(phi)), (float)(-s * sin(phi)), (float)-nl[i]},
                            .color = {0.5f + 0.25f * (float)i, 0.8f, 1.1f - 0.2f * (float)i}};
    }
}

/* HDR of `s` lit by each of `sets` light sets in turn (one renderer, set_lights between frames). */
static int wrap_render(const tl_scene *s, tl_render_mode mode, const tl_light sets[][WL], int count, float *hdr[])
{
    tl_renderer_desc d = {.width = WW, .height = WH, .options = {.mode = mode, .ambient = {-1, -1, -1}}};
    d.options.keep_targets = TL_TARGET_BIT(TL_TARGET_HDR);
    d.get_proc_address = tl_context_proc_loader, d.get_proc_address_user = g_ctx, d.logger = tl_test_logger;
    tl_renderer *r = NULL;
    int bad = tl_renderer_create(&d, &r) != TL_OK || tl_renderer_set_scene(r, s) != TL_OK;
    for (int k = 0; k < count && !bad; k++) {
        size_t size = (size_t)WW * WH * 16;
        bad = tl_renderer_set_lights(r, sets[k], WL) != TL_OK || tl_renderer_render(r, NULL, NULL) != TL_OK ||
              tl_renderer_read_target(r, TL_TARGET_HDR, hdr[k], &size) != TL_OK;
    }
    tl_renderer_destroy(r);
    return bad;
}

/* The quad whose interior (a pixel's world size inside its edges) holds pixel i's centre, -1 for none. */
static int wrap_quad_at(size_t i)
{
    double t = tan(3.14159265358979 / 6.0), px = 2.0 * 4.0 * t / WH; /* the default 60 degrees, 4 m away */
    double x = (2.0 * ((double)(i % WW) + 0.5) / WW - 1.0) * 4.0 * t * WW / WH;
    double y = (2.0 * ((double)(i / WW) + 0.5) / WH - 1.0) * 4.0 * t;
    int q = (int)floor(x + 2.0);
    double fx = x + 2.0 - q;
    return q >= 0 && q < WQ && fx > px && fx < 1.0 - px && fabs(y) < 0.5 - px ? q : -1;
}

/* Pixel channel c of quad q under light set `l`, as `mode` forms it (double): forward the wrapped
 * weight per light, thin-lpp the diffuse sum D times the weights' ratio at n.l = 1/2. */
static double wrap_expected(tl_render_mode mode, const tl_material *m, const tl_light *l, int c)
{
    double w = m->model == TL_MATERIAL_MODEL_WRAP ? m->wrap : 0.0, d = 0.0, wrapped = 0.0;
    for (int i = 0; i < WL; i++) {
        const float *v = l[i].direction;
        double nl = -v[2] / sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]);
        d += l[i].color[c] * fmax(nl, 0.0);
        wrapped += l[i].color[c] * fmax(nl + w, 0.0) / ((1.0 + w) * (1.0 + w));
    }
    if (m->model != TL_MATERIAL_MODEL_WRAP) return m->albedo[c] * d;
    if (mode == TL_MODE_FORWARD || mode == TL_MODE_VISIBILITY) return m->albedo[c] * wrapped; /* forward's loop */
    return m->albedo[c] * d * (0.5 + w) / (0.5 * (1.0 + w) * (1.0 + w));
}

/* The wrap model on quads facing the camera (view normal exactly +Z) under directional lights,
 * against its double evaluation: forward's exact per-light weight, thin-lpp's documented scaling of
 * the diffuse sum (docs/lighting.md, "Wrap"), for wraps 0.25, 0.5 and 1 and a standard quad. All
 * four lights at 60 degrees from the normal, where the scaling is exact, thin-lpp's value is
 * forward's; at 0, 37, 73 and 102 degrees (the last past the terminator: only forward wraps it)
 * each mode has its own. Tolerance: each light's blend into thin-lpp's FP16 sum and each HDR write
 * round once (a whole FP16 step each, GL allows truncation): (lights + 2) steps for thin-lpp, 2 for
 * forward and visibility (forward's light loop in its resolve: the exact weight). Dropping the
 * scaling moves thin-lpp's wraps by 4 %, 12.5 % and 33 %. */
TL_TEST(material_models_wrap_thin_lpp_bounded_by_double_reference)
{
    static tl_vertex v[WQ * 4];
    static uint32_t idx[WQ * 6];
    static tl_object obj[WQ];
    static tl_material mat[WQ];
    static tl_light sets[2][WL];
    for (int q = 0; q < WQ; q++) {
        const float c[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int k = 0; k < 4; k++)
            v[q * 4 + k] =
                (tl_vertex){.position = {c[k][0] - 2.0f + (float)q, c[k][1] - 0.5f, 0.0f}, .normal = {0, 0, 1}};
        const uint32_t t[6] = {0, 1, 2, 0, 2, 3};
        for (int k = 0; k < 6; k++) idx[q * 6 + k] = (uint32_t)(q * 4) + t[k];
        obj[q] = (tl_object){.first_index = (uint32_t)(q * 6), .index_count = 6, .material = (uint32_t)q};
        mat[q] = (tl_material){.albedo = {0.6f, 0.4f, 0.3f}, .wrap = wrap_w[q],
                               .model = wrap_w[q] > 0.0f ? TL_MATERIAL_MODEL_WRAP : TL_MATERIAL_MODEL_STANDARD};
    }
    wrap_lights((const double[WL]){0.5, 0.5, 0.5, 0.5}, sets[0]);
    wrap_lights((const double[WL]){1.0, 0.8, 0.3, -0.2}, sets[1]);
    tl_scene s = {.vertices = v, .vertex_count = WQ * 4, .indices = idx, .index_count = WQ * 6, .objects = obj,
                  .object_count = WQ, .materials = mat, .material_count = WQ, .lights = sets[0], .light_count = WL,
                  .camera = {.position = {0, 0, 4}, .target = {0, 0, 0}, .up = {0, 1, 0}, .near_z = 1, .far_z = 10}};
    if (!ensure_context()) return;
    const tl_render_mode modes[3] = {TL_MODE_THIN_LPP, TL_MODE_FORWARD, TL_MODE_VISIBILITY};
    const size_t n = (size_t)WW * WH;
    for (int mo = 0; mo < 3; mo++) {
        float *hdr[2] = {malloc(n * 16), malloc(n * 16)};
        TL_CHECK(hdr[0] && hdr[1] && wrap_render(&s, modes[mo], (const tl_light(*)[WL])sets, 2, hdr) == 0);
        double steps = mo == 0 ? WL + 2.0 : 2.0;
        for (int k = 0; k < 2 && hdr[0] && hdr[1]; k++)
            for (int q = 0; q < WQ; q++) {
                size_t pixels = 0, over = 0;
                double worst = 0.0;
                for (size_t i = 0; i < n; i++) {
                    if (wrap_quad_at(i) != q) continue;
                    pixels++;
                    for (int c = 0; c < 3; c++) {
                        double ref = wrap_expected(modes[mo], &mat[q], sets[k], c), e = fabs(hdr[k][4 * i + c] - ref);
                        worst = fmax(worst, e / ref);
                        over += e > steps * ldexp(1.0, -10) * ref;
                    }
                }
                printf("  %-8s lights at %s, %s %.2f: %zu pixels, worst relative error %.3g (tolerance %.3g)\n",
                       tl_render_mode_name(modes[mo]), k ? "0/37/73/102 deg" : "60 deg",
                       q < WQ - 1 ? "wrap" : "standard", wrap_w[q], pixels, worst, steps * ldexp(1.0, -10));
                TL_CHECK_LE(100, pixels);
                TL_CHECK_EQ_U(over, 0);
            }
        free(hdr[0]);
        free(hdr[1]);
    }
}
