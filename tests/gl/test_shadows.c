/* Shadows (docs/shadows.md) against ray-traced truth (Embree, examples/common/shadow_rt.c):
 * the fraction of pixels whose lit or shadowed state differs from the truth outside the penumbra
 * (acne and leaks apart), per mode, strategy and depth format, on the stiff scene and the crypt;
 * and what the planner and the cache promise; PCSS against the truth of lights with a size (area
 * sampling), in the penumbra and outside it. Figures go to stdout. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_fixture.h"
#include "shadow_rt.h"
#include "shadow_term.h"
#include "tl_test.h"

enum { TL__BAND = 2 }; /* pixels beside a change of the truth's state: the penumbra's reach on screen */

typedef struct tl__truth {
    uint8_t *state;
    uint32_t *object;
} tl__truth;

static int tl__truth_make(const tl_shadow_case *c, const tl_light *l, uint32_t w, uint32_t h, tl__truth *t)
{
    tl_shadow_rt *rt = tl_shadow_rt_create(c->scene);
    t->state = malloc((size_t)w * h);
    t->object = malloc((size_t)w * h * sizeof(uint32_t));
    if (!rt || !t->state || !t->object) {
        tl_shadow_rt_destroy(rt);
        return 0;
    }
    tl_shadow_rt_truth(rt, &c->scene->camera, w, h, l, t->state, t->object);
    tl_shadow_rt_destroy(rt);
    return 1;
}

static void tl__truth_free(tl__truth *t)
{
    free(t->state);
    free(t->object);
}

static const char *tl__depth_name(tl_depth_format f) { return f == TL_DEPTH_FORMAT_D32F_REVERSED ? "D32F-rev" : "D24"; }

/* With TL_SHADOW_DUMP=DIR: the term (grey, blue where the light adds nothing), the truth (white lit,
 * grey shadowed, dark blue facing away) and their disagreement (red acne, green leaks) as PPM. */
static void tl__dump(const char *name, const float *term, const tl__truth *t, uint32_t w, uint32_t h)
{
    const char *dir = getenv("TL_SHADOW_DUMP");
    if (!dir) return;
    char path[512];
    snprintf(path, sizeof path, "%s/%s.ppm", dir, name);
    FILE *f = fopen(path, "wb");
    if (!f) return;
    fprintf(f, "P6\n%u %u\n255\n", w * 2, h);
    for (uint32_t yy = 0; yy < h; yy++) {
        uint32_t y = h - 1 - yy;
        for (uint32_t x = 0; x < 2 * w; x++) {
            size_t i = (size_t)y * w + (x % w);
            uint8_t px[3] = {0, 0, 64};
            if (x < w && term[i] >= 0.0f) px[0] = px[1] = px[2] = (uint8_t)(term[i] * 255.0f);
            if (x >= w) {
                uint8_t s = t->state[i];
                uint8_t v = s == TL_RT_LIT ? 255 : s == TL_RT_SHADOWED ? 96 : 0;
                px[0] = px[1] = px[2] = v;
                if (s == TL_RT_AWAY) px[2] = 128;
                if (term[i] >= 0.0f && s == TL_RT_LIT && term[i] < 0.5f) px[0] = 255, px[1] = px[2] = 0;
                if (term[i] >= 0.0f && s == TL_RT_SHADOWED && term[i] >= 0.5f) px[1] = 255, px[0] = px[2] = 0;
            }
            fwrite(px, 1, 3, f);
        }
    }
    fclose(f);
}

/* One configuration against the truth: prints the figures, returns the error. */
static tl_shadow_error tl__measure(const char *scene, const tl_shadow_case *c, size_t light, const tl__truth *t,
                                   tl_renderer_options o, const char *what, uint32_t w, uint32_t h, float **keep)
{
    tl_shadow_error e = {0};
    float *term = tl_shadow_term(c, &c->lights[light], o, w, h, NULL);
    TL_CHECK(term != NULL);
    if (!term) return e;
    e = tl_shadow_rt_compare(t->state, t->object, term, w, h, TL__BAND);
    printf("shadow-error scene=%s light=\"%s\" %s depth=%s size=%ux%u counted=%zu acne=%zu (%.4f%%) leaks=%zu "
           "(%.4f%%) wrong=%.4f%%\n", scene, c->light_names[light], what, tl__depth_name(o.depth_format), w, h,
           e.counted, e.acne, 100.0 * (double)e.acne / (double)(e.counted ? e.counted : 1), e.leaks,
           100.0 * (double)e.leaks / (double)(e.counted ? e.counted : 1), 100.0 * e.wrong);
    TL_CHECK(e.counted > 0);
    char name[160];
    snprintf(name, sizeof name, "%s-%zu-%s-%.24s", scene, light, tl__depth_name(o.depth_format), what + 5);
    for (char *ch = name; *ch; ch++)
        if (*ch == ' ' || *ch == '=' || *ch == '(' || *ch == ')') *ch = '_';
    tl__dump(name, term, t, w, h);
    if (keep) *keep = term;
    else free(term);
    return e;
}

/* Every mode and strategy the lookup lives in (light volumes, tiled fragment and compute, forward
 * with per-object lists and Forward+, visibility's resolve over the tile lists). */
typedef struct tl__config {
    const char *name;
    tl_render_mode mode;
    tl_light_strategy strategy;
    tl_tiled_shading tiled;
} tl__config;
static const tl__config tl__configs[] = {
    {"mode=thin-lpp strategy=volumes", TL_MODE_THIN_LPP, TL_LIGHT_STRATEGY_VOLUMES, TL_TILED_SHADING_DEFAULT},
    {"mode=thin-lpp strategy=tiled", TL_MODE_THIN_LPP, TL_LIGHT_STRATEGY_TILED, TL_TILED_SHADING_FRAGMENT},
    {"mode=thin-lpp strategy=tiled-compute", TL_MODE_THIN_LPP, TL_LIGHT_STRATEGY_TILED, TL_TILED_SHADING_COMPUTE},
    {"mode=thin-deferred strategy=volumes", TL_MODE_THIN_DEFERRED, TL_LIGHT_STRATEGY_VOLUMES, TL_TILED_SHADING_DEFAULT},
    {"mode=fat strategy=volumes", TL_MODE_FAT, TL_LIGHT_STRATEGY_VOLUMES, TL_TILED_SHADING_DEFAULT},
    {"mode=forward strategy=volumes", TL_MODE_FORWARD, TL_LIGHT_STRATEGY_VOLUMES, TL_TILED_SHADING_DEFAULT},
    {"mode=forward strategy=tiled(Forward+)", TL_MODE_FORWARD, TL_LIGHT_STRATEGY_TILED, TL_TILED_SHADING_DEFAULT},
    {"mode=visibility strategy=tiled", TL_MODE_VISIBILITY, TL_LIGHT_STRATEGY_TILED, TL_TILED_SHADING_DEFAULT},
};
#define TL__CONFIG_VISIBILITY 7

static tl_renderer_options tl__options(const tl__config *k, tl_depth_format depth)
{
    return (tl_renderer_options){.mode = k->mode, .light_strategy = k->strategy, .tiled_shading = k->tiled,
                                 .depth_format = depth};
}

/* The stiff scene: the configurations [first, first + count) of tl__configs, both depth formats,
 * both lights. No acne anywhere (the grazing plane included) and at most 0.5 % of the pixels in
 * the wrong state. */
static void tl__stiff_against_truth(tl_shadow_filter filter, size_t first, size_t count)
{
    tl_shadow_case c;
    TL_CHECK(tl_shadow_stiff_case(&c));
    const uint32_t w = 480, h = 270;
    for (size_t l = 0; l < c.light_count; l++) {
        tl__truth t;
        TL_CHECK(tl__truth_make(&c, &c.lights[l], w, h, &t));
        for (int d = 0; d < 2; d++)
            for (size_t k = first; k < first + count && k < sizeof tl__configs / sizeof tl__configs[0]; k++) {
                tl_depth_format depth = d ? TL_DEPTH_FORMAT_D32F_REVERSED : TL_DEPTH_FORMAT_D24;
                tl_renderer_options o = tl__options(&tl__configs[k], depth);
                o.shadows.filter = filter;
                tl_shadow_error e = tl__measure(filter == TL_SHADOW_FILTER_PCSS ? "stiff-pcss" : "stiff", &c, l, &t, o,
                                                tl__configs[k].name, w, h, NULL);
                TL_CHECK_LE(e.acne, 0);
                TL_CHECK_LE(e.wrong, 0.005);
            }
        tl__truth_free(&t);
    }
    tl_shadow_case_free(&c);
}

#define TL__CONFIGS (sizeof tl__configs / sizeof tl__configs[0])

/* The default tier: thin-lpp with tiles (the second configuration), PCF and PCSS, and visibility
 * (its resolve's shadow gate: the one lookup, in a compute pass); the full tier: every
 * configuration. */
TL_TEST(shadows_stiff_scene_against_truth_thin_lpp_tiled)
{
    tl__stiff_against_truth(TL_SHADOW_FILTER_DEFAULT, 1, 1);
    tl__stiff_against_truth(TL_SHADOW_FILTER_PCSS, 1, 1);
}

TL_TEST(shadows_stiff_scene_against_truth_visibility)
{
    tl__stiff_against_truth(TL_SHADOW_FILTER_DEFAULT, TL__CONFIG_VISIBILITY, 1);
}

TL_TEST_FULL(shadows_stiff_scene_against_truth) { tl__stiff_against_truth(TL_SHADOW_FILTER_DEFAULT, 0, TL__CONFIGS); }

/* The same with PCSS (the point light punctual, the sun 0.27 degrees in radius): its blocker search
 * and its receiver-plane comparisons add no acne at grazing angles, the horizon included. */
TL_TEST_FULL(shadows_pcss_stiff_scene_against_truth) { tl__stiff_against_truth(TL_SHADOW_FILTER_PCSS, 0, TL__CONFIGS); }

/* A spot light over a floor, its axis tilted from the floor's normal (shadow_scenes.c): without an
 * occluder every pixel the spot lights must be lit. The term is the HDR image with the light casting
 * over the image without; with a shadow of exactly 1 both are the same float operations, so the only
 * slack is the FP16 target's rounding of each (2^-11 relative): 1 - 2 x 2^-11. The filter's smallest
 * loss is far above that: one texel of PCF's (2r + 1)^2 tent wrongly shadowed takes its bilinear
 * weight, and PCSS's kernel at least PCF's. With a box standing in both pools, the term against the
 * ray-traced truth: no acne, at most 0.5 % of the pixels in the wrong state. Both depth formats,
 * in thin-lpp's light volumes and tiled compute, fat, Forward+ and visibility (the one lookup,
 * tl_shadow, in each kind of lighting pass). */
static void tl__spot_against_truth(tl_shadow_filter filter)
{
    const uint32_t w = 320, h = 180;
    /* light volumes, tiled compute, fat, Forward+, visibility's resolve: one lookup */
    const size_t configs[] = {0, 2, 4, 6, TL__CONFIG_VISIBILITY};
    const float slack = (float)TL_HALF_REL_STEP; /* two roundings, half an FP16 step (2^-11) each */
    tl_shadow_case open, boxed;
    TL_CHECK(tl_shadow_spot_case(&open, 0) && tl_shadow_spot_case(&boxed, 1));
    const char *scene = filter == TL_SHADOW_FILTER_PCSS ? "spot-pcss" : "spot";
    for (size_t l = 0; l < open.light_count; l++) {
        tl__truth t;
        TL_CHECK(tl__truth_make(&boxed, &boxed.lights[l], w, h, &t));
        for (int d = 0; d < 2; d++)
            for (size_t j = 0; j < sizeof configs / sizeof configs[0]; j++) {
                size_t k = configs[j];
                tl_renderer_options o = tl__options(&tl__configs[k], d ? TL_DEPTH_FORMAT_D32F_REVERSED : TL_DEPTH_FORMAT_D24);
                o.shadows.filter = filter;
                float *term = tl_shadow_term(&open, &open.lights[l], o, w, h, NULL);
                TL_CHECK(term != NULL);
                size_t lit = 0, dark = 0;
                float lowest = 1.0f;
                for (size_t i = 0; term && i < (size_t)w * h; i++) {
                    if (term[i] < 0.0f) continue;
                    lit++;
                    dark += term[i] < 1.0f - slack;
                    lowest = fminf(lowest, term[i]);
                }
                printf("shadow-spot-open scene=%s light=\"%s\" %s depth=%s lit=%zu below=%zu lowest=%.6f bound=%.6f\n",
                       scene, open.light_names[l], tl__configs[k].name, tl__depth_name(o.depth_format), lit, dark,
                       (double)lowest, 1.0 - (double)slack);
                TL_CHECK(lit > (size_t)w * h / 8);
                TL_CHECK_EQ_U(dark, 0);
                char name[96];
                snprintf(name, sizeof name, "%s-open-%zu-%s-%zu", scene, l, tl__depth_name(o.depth_format), k);
                if (term) tl__dump(name, term, &t, w, h); /* the box's truth beside it: its pool lit */
                free(term);
                tl_shadow_error e = tl__measure(scene, &boxed, l, &t, o, tl__configs[k].name, w, h, NULL);
                TL_CHECK_LE(e.acne, 0);
                TL_CHECK_LE(e.wrong, 0.005);
            }
        tl__truth_free(&t);
    }
    tl_shadow_case_free(&open);
    tl_shadow_case_free(&boxed);
}

TL_TEST(shadows_spot_floor_tilted_axis_no_acne_pcf) { tl__spot_against_truth(TL_SHADOW_FILTER_PCF); }
TL_TEST(shadows_spot_floor_tilted_axis_no_acne_pcss) { tl__spot_against_truth(TL_SHADOW_FILTER_PCSS); }

/* The crypt (its moonlight and two braziers, one at a time): thin-lpp and fat with D24 and reversed
 * D32F. Targets: at most 0.5 % of the pixels in the wrong state with reversed D32F; thin-lpp and fat
 * differ from each other by less than either differs from the truth (the rebuilt position is not
 * what limits the shadows). TL_SHADOW_SIZE=WxH measures at another size (the figures of
 * docs/shadows.md are at 1280x720). */
TL_TEST_FULL(shadows_crypt_against_truth)
{
    tl_shadow_case c;
    TL_CHECK(tl_shadow_crypt_case(&c, 0));
    uint32_t w = 320, h = 180;
    const char *size = getenv("TL_SHADOW_SIZE");
    if (size && sscanf(size, "%ux%u", &w, &h) != 2) w = 320, h = 180;
    for (size_t l = 0; l < c.light_count; l++) {
        tl__truth t;
        TL_CHECK(tl__truth_make(&c, &c.lights[l], w, h, &t));
        for (int d = 0; d < 2; d++) {
            tl_depth_format depth = d ? TL_DEPTH_FORMAT_D32F_REVERSED : TL_DEPTH_FORMAT_D24;
            float *thin = NULL, *fat = NULL;
            tl_shadow_error et = tl__measure("crypt", &c, l, &t, tl__options(&tl__configs[0], depth), tl__configs[0].name,
                                             w, h, &thin);
            tl_shadow_error ef = tl__measure("crypt", &c, l, &t, tl__options(&tl__configs[4], depth), tl__configs[4].name,
                                             w, h, &fat);
            if (thin && fat) {
                tl_shadow_error tf = tl_shadow_rt_compare_terms(t.state, t.object, thin, fat, w, h, TL__BAND);
                printf("shadow-thin-vs-fat scene=crypt light=\"%s\" depth=%s differ=%.4f%% thin-vs-truth=%.4f%% "
                       "fat-vs-truth=%.4f%%\n", c.light_names[l], tl__depth_name(depth), 100.0 * tf.wrong,
                       100.0 * et.wrong, 100.0 * ef.wrong);
                TL_CHECK_LE(tf.wrong, et.wrong > ef.wrong ? et.wrong : ef.wrong);
            }
            if (d) TL_CHECK_LE(et.wrong, 0.005);
            free(thin);
            free(fat);
        }
        tl__truth_free(&t);
    }
    tl_shadow_case_free(&c);
}

/* The term's value itself, away from any shadow edge: 1 on what the truth calls lit, 0 on what it
 * calls shadowed. A lit pixel whose kernel self-shadows part of its taps (too small a normal
 * offset) or a kernel whose weights do not sum to 1 stays >= 0.5 and passes the state comparison
 * above; here it fails. "Away" is derived per pixel from the lookup's reach (docs/shadows.md): the
 * kernel and its bilinear footprint read (r + 1) texels w around the looked-up point, and the
 * normal offset ((r + 1) w sin(theta) + e_gbuffer along n) moves that point across the light by
 * (r + 1) w sin^2(theta) + e_gbuffer sin(theta): X in all. On the receiver's plane the texels' rays
 * meet it within an ellipse X / cos(theta) by X around the pixel's point (theta between n and l);
 * a pixel is measured when no pixel within that ellipse's projection plus 2 (Chebyshev distance,
 * so also the Euclidean one) has another truth state or object, or lies off the image. */

/* Bounds of a casting light's texel world size (shadow_views.c): cascades, the sphere around the
 * eye that holds the slice, 2 split sqrt(1 + k2) (the renderer's is no larger) over the tile side;
 * spot and cube faces, 2 tan(half angle) distance over the side; each widened as the renderer widens
 * it by the kernel's reach plus 2 texels a side. */
typedef struct tl__reach {
    int cascades;            /* 1: a directional light's four cascades */
    float split[4], texel[4]; /* cascades: the view depth where each ends, its texel bound */
    float texel_per_distance; /* spot and cube faces */
    float r;                  /* the PCF radius */
} tl__reach;

static int tl__reach_of(const tl_shadow_case *c, const tl_light *light, tl_renderer_options o, uint32_t w, uint32_t h,
                        const tl_shadow_view_info *v, size_t n, tl__reach *out)
{
    if (!n || (v[0].type == TL_LIGHT_DIRECTIONAL && n < 4)) return 0;
    memset(out, 0, sizeof *out);
    out->r = o.shadows.filter == TL_SHADOW_FILTER_BILINEAR ? 0.0f : o.shadows.pcf_radius ? (float)o.shadows.pcf_radius : 1.0f;
    const tl_camera *cam = &c->scene->camera;
    double ty = tan(0.5 * (cam->fov_y > 0.0f ? cam->fov_y : 1.04719755)), tx = ty * w / h;
    double widen = 1.0 / (1.0 - 2.0 * (out->r + 2.0) / v[0].size);
    out->cascades = v[0].type == TL_LIGHT_DIRECTIONAL;
    for (size_t i = 0; out->cascades && i < 4; i++) {
        out->split[i] = v[i].split;
        out->texel[i] = (float)(2.0 * v[i].split * sqrt(1.0 + tx * tx + ty * ty) * widen / v[i].size);
    }
    double co = fmax(light->cos_outer, 0.17), tan_half = v[0].type == TL_LIGHT_SPOT ? sqrt(1.0 - co * co) / co : 1.0;
    out->texel_per_distance = (float)(2.0 * tan_half * widen / v[0].size);
    return 1;
}

/* The texel bound at world point p of view depth z (0: beyond the last cascade, not looked up);
 * over the last 10 % of a cascade the lookup blends into the next one: the larger of the two. */
static double tl__texel_at(const tl__reach *re, const tl_light *l, const float p[3], double z)
{
    if (!re->cascades) {
        double d2 = 0.0;
        for (int k = 0; k < 3; k++) d2 += (double)(l->position[k] - p[k]) * (l->position[k] - p[k]);
        return re->texel_per_distance * sqrt(d2);
    }
    for (int i = 0; i < 4; i++) {
        if (z >= re->split[i]) continue;
        double start = i ? re->split[i - 1] : 0.0;
        int blend = i < 3 && z > re->split[i] - 0.1 * (re->split[i] - start);
        return blend ? fmax(re->texel[i], re->texel[i + 1]) : re->texel[i];
    }
    return 0.0;
}

/* Per pixel the Chebyshev distance in pixels to the nearest pixel whose truth state or object
 * differs from a neighbour's, or that has no lit or shadowed state; off the image counts as such. */
static int32_t *tl__edge_distance(const uint8_t *state, const uint32_t *object, uint32_t w, uint32_t h)
{
    int32_t *d = malloc((size_t)w * h * sizeof *d);
    if (!d) return NULL;
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            int edge = state[i] != TL_RT_LIT && state[i] != TL_RT_SHADOWED;
            for (int dy = -1; dy <= 1 && !edge; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    int xx = (int)x + dx, yy = (int)y + dy;
                    if (xx < 0 || yy < 0 || xx >= (int)w || yy >= (int)h) continue;
                    size_t j = (size_t)yy * w + (size_t)xx;
                    edge |= state[j] != state[i] || object[j] != object[i];
                }
            uint32_t border = x + 1 < w - x ? x + 1 : w - x, by = y + 1 < h - y ? y + 1 : h - y;
            d[i] = edge ? 0 : (int32_t)(border < by ? border : by);
        }
    for (int pass = 0; pass < 2; pass++) /* forward, then backward, over the 8 neighbours */
        for (size_t k = 0; k < (size_t)w * h; k++) {
            size_t i = pass ? (size_t)w * h - 1 - k : k;
            int x = (int)(i % w), y = (int)(i / w), s = pass ? 1 : -1;
            const int nb[4][2] = {{s, 0}, {-1, s}, {0, s}, {1, s}};
            for (int m = 0; m < 4; m++) {
                int xx = x + nb[m][0], yy = y + nb[m][1];
                if (xx < 0 || yy < 0 || xx >= (int)w || yy >= (int)h) continue;
                int32_t v = d[(size_t)yy * w + (size_t)xx] + 1;
                if (v < d[i]) d[i] = v;
            }
        }
    return d;
}

typedef struct tl__surface {
    float *position, *normal; /* the truth's primary hits (tl_shadow_rt_surface) */
} tl__surface;

/* The camera as the truth's rays see it (shadow_rt.c): its basis, the field of view's tangents. */
typedef struct tl__eye {
    double pos[3], right[3], up[3], fwd[3], tx, ty, near, far;
    uint32_t w, h;
} tl__eye;

static void tl__unit(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0.0) v[0] /= l, v[1] /= l, v[2] /= l;
}

static void tl__cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1], out[1] = a[2] * b[0] - a[0] * b[2], out[2] = a[0] * b[1] - a[1] * b[0];
}

static tl__eye tl__eye_of(const tl_camera *c, uint32_t w, uint32_t h)
{
    tl__eye e = {.near = c->near_z, .far = c->far_z, .w = w, .h = h};
    double up[3] = {c->up[0], c->up[1], c->up[2]};
    if (up[0] == 0.0 && up[1] == 0.0 && up[2] == 0.0) up[1] = 1.0;
    for (int k = 0; k < 3; k++) e.pos[k] = c->position[k], e.fwd[k] = (double)c->target[k] - c->position[k];
    tl__unit(e.fwd);
    tl__cross(e.fwd, up, e.right);
    tl__unit(e.right);
    tl__cross(e.right, e.fwd, e.up);
    e.ty = tan(0.5 * (c->fov_y > 0.0f ? c->fov_y : 1.04719755));
    e.tx = e.ty * w / h;
    return e;
}

/* Pixel coordinates of world point q; 0 when it is not in front of the near plane. */
static int tl__project(const tl__eye *e, const double q[3], double px[2])
{
    double d[3] = {q[0] - e->pos[0], q[1] - e->pos[1], q[2] - e->pos[2]};
    double x = d[0] * e->right[0] + d[1] * e->right[1] + d[2] * e->right[2];
    double y = d[0] * e->up[0] + d[1] * e->up[1] + d[2] * e->up[2];
    double z = d[0] * e->fwd[0] + d[1] * e->fwd[1] + d[2] * e->fwd[2];
    if (z <= e->near) return 0;
    px[0] = (x / (z * e->tx) + 1.0) * 0.5 * e->w;
    px[1] = (y / (z * e->ty) + 1.0) * 0.5 * e->h;
    return 1;
}

/* How many pixels (Chebyshev) from pixel point p (normal n) the lookup's footprint reaches on its
 * plane: the rim of the ellipse X / cos(theta) by X, projected at 64 points, plus a pixel for the
 * rim between them; infinite where it is not looked up or reaches behind the near plane. */
static double tl__screen_reach(const tl__eye *e, const tl_light *l, const tl__reach *re, tl_depth_format depth,
                               const float pf[3], const float nf[3])
{
    double p[3] = {pf[0], pf[1], pf[2]}, n[3] = {nf[0], nf[1], nf[2]}, to[3], t1[3], t2[3], c0[2], c[2];
    double z = 0.0, cos_t = 0.0;
    for (int k = 0; k < 3; k++) {
        to[k] = l->type == TL_LIGHT_DIRECTIONAL ? -l->direction[k] : l->position[k] - p[k];
        z += (p[k] - e->pos[k]) * e->fwd[k];
    }
    tl__unit(to);
    for (int k = 0; k < 3; k++) cos_t += n[k] * to[k];
    double texel = tl__texel_at(re, l, pf, z), sin2 = fmax(1.0 - cos_t * cos_t, 0.0);
    if (texel <= 0.0 || cos_t <= 0.0 || !tl__project(e, p, c0)) return INFINITY;
    double e_gbuffer = depth == TL_DEPTH_FORMAT_D32F_REVERSED
                           ? ldexp(z, -22)
                           : ldexp(z * z * (e->far - e->near) / (e->far * e->near), -23);
    double x = (re->r + 1.0) * texel * (1.0 + sin2) + e_gbuffer * sqrt(sin2), reach = 0.0;
    for (int k = 0; k < 3; k++) t1[k] = to[k] - cos_t * n[k]; /* along the plane towards the light */
    if (sin2 < 1e-12) t1[0] = n[1], t1[1] = n[2], t1[2] = n[0];  /* any direction in the plane will do */
    tl__unit(t1);
    tl__cross(n, t1, t2);
    tl__unit(t2);
    for (int i = 0; i < 64; i++) {
        double a = cos(i * 0.09817477) * x / cos_t, b = sin(i * 0.09817477) * x, q[3];
        for (int k = 0; k < 3; k++) q[k] = p[k] + a * t1[k] + b * t2[k];
        if (!tl__project(e, q, c)) return INFINITY;
        reach = fmax(reach, fmax(fabs(c[0] - c0[0]), fabs(c[1] - c0[1])));
    }
    return reach + 1.0;
}

static int tl__surface_make(const tl_shadow_case *c, uint32_t w, uint32_t h, tl__surface *s)
{
    tl_shadow_rt *rt = tl_shadow_rt_create(c->scene);
    s->position = malloc((size_t)w * h * 3 * sizeof(float));
    s->normal = malloc((size_t)w * h * 3 * sizeof(float));
    int ok = rt && s->position && s->normal;
    if (ok) tl_shadow_rt_surface(rt, &c->scene->camera, w, h, s->position, s->normal);
    tl_shadow_rt_destroy(rt);
    return ok;
}

typedef struct tl__values {
    size_t lit, shadowed;          /* pixels measured */
    size_t lit_off, shadowed_off;  /* of those, off 1 (0) by more than the tolerance */
    size_t lit_all;                /* every pixel the truth calls lit (and the light reaches) */
    double worst_lit, worst_shadowed;
} tl__values;

static tl__values tl__values_count(const tl_shadow_case *c, const tl_light *l, const tl__truth *t,
                                   const tl__surface *s, const float *ratio, tl_renderer_options o, uint32_t w,
                                   uint32_t h, const tl_shadow_view_info *views, size_t view_count, double tol)
{
    tl__values v = {0};
    tl__reach re;
    int32_t *dist = tl__edge_distance(t->state, t->object, w, h);
    int ok = dist && tl__reach_of(c, l, o, w, h, views, view_count, &re);
    tl__eye e = tl__eye_of(&c->scene->camera, w, h);
    TL_CHECK(ok);
    for (size_t i = 0; ok && i < (size_t)w * h; i++) {
        int lit = t->state[i] == TL_RT_LIT;
        if ((!lit && t->state[i] != TL_RT_SHADOWED) || ratio[i] < 0.0f) continue;
        v.lit_all += (size_t)lit;
        double k = tl__screen_reach(&e, l, &re, o.depth_format, &s->position[3 * i], &s->normal[3 * i]);
        if (!(dist[i] >= k + 2.0)) continue;
        double off = fabs(ratio[i] - (lit ? 1.0 : 0.0));
        if (lit) v.lit++, v.lit_off += off > tol, v.worst_lit = fmax(v.worst_lit, off);
        else v.shadowed++, v.shadowed_off += off > tol, v.worst_shadowed = fmax(v.worst_shadowed, off);
    }
    free(dist);
    return v;
}

/* One case's lights with PCF in the configurations [first, first + count), both depth formats:
 * no measured pixel off its value by more than `tol`; the pixels measured added to lit[light] and
 * *shadowed. */
static void tl__term_values(const tl_shadow_case *c, const char *scene, uint32_t w, uint32_t h, size_t lights,
                            size_t first, size_t count, double tol, size_t *lit, size_t *shadowed)
{
    for (size_t l = 0; l < lights && l < c->light_count; l++) {
        tl__truth t;
        tl__surface s = {0};
        TL_CHECK(tl__truth_make(c, &c->lights[l], w, h, &t) && tl__surface_make(c, w, h, &s));
        for (int d = 0; d < 2; d++)
            for (size_t k = first; k < first + count && k < TL__CONFIGS; k++) {
                tl_depth_format depth = d ? TL_DEPTH_FORMAT_D32F_REVERSED : TL_DEPTH_FORMAT_D24;
                tl_renderer_options o = tl__options(&tl__configs[k], depth);
                tl_shadow_view_info views[8];
                size_t view_count = 8;
                float *ratio = tl_shadow_ratio(c, &c->lights[l], o, w, h, NULL, views, &view_count);
                TL_CHECK(ratio != NULL);
                if (!ratio) continue;
                tl__values v = tl__values_count(c, &c->lights[l], &t, &s, ratio, o, w, h, views, view_count, tol);
                printf("shadow-values scene=%s light=\"%s\" %s depth=%s size=%ux%u lit: %zu of %zu measured, %zu off 1 "
                       "by more than %.2g (worst %.3g); shadowed: %zu measured, %zu off 0 (worst %.3g)\n",
                       scene, c->light_names[l], tl__configs[k].name, tl__depth_name(o.depth_format), w, h, v.lit,
                       v.lit_all, v.lit_off, tol, v.worst_lit, v.shadowed, v.shadowed_off, v.worst_shadowed);
                TL_CHECK_EQ_U(v.lit_off, 0);
                TL_CHECK_EQ_U(v.shadowed_off, 0);
                lit[l] += v.lit;
                *shadowed += v.shadowed;
                free(ratio);
            }
        free(s.position);
        free(s.normal);
        tl__truth_free(&t);
    }
}

/* The stiff scene (the grazing plane: the normal offset at work) and the penumbra case's spot light
 * (large shadows) in the configurations [first, first + count): every light measures lit pixels,
 * the spot and point lights of the penumbra case shadowed ones. (The point light's cube faces
 * measured 0.966 to 0.998 on 32 to 35 lit pixels while the normal offset took its angle from the
 * ray to the light instead of the face's axis; with the axis every pixel is 1.) */
static void tl__term_values_scenes(size_t first, size_t count)
{
    /* the casting and the non-casting frame differ by one FP16 step (2^-10) of the light sum and
     * one of HDR at most (the programs differ by TL_SHADOWS; a term of exactly 1 or 0 multiplies) */
    const double tol = ldexp(1.0, -9);
    tl_shadow_case c;
    size_t lit[4] = {0}, shadowed = 0;
    TL_CHECK(tl_shadow_stiff_case(&c));
    tl__term_values(&c, "stiff", 480, 270, c.light_count, first, count, tol, lit, &shadowed);
    for (size_t l = 0; l < c.light_count; l++) TL_CHECK_LE(100, lit[l]);
    tl_shadow_case_free(&c);
    memset(lit, 0, sizeof lit);
    shadowed = 0;
    TL_CHECK(tl_shadow_penumbra_case(&c));
    tl__term_values(&c, "penumbra", 320, 180, c.light_count, first, count, tol, lit, &shadowed);
    TL_CHECK_LE(100, lit[0]);
    TL_CHECK_LE(100, shadowed);
    tl_shadow_case_free(&c);
}

TL_TEST(shadows_term_one_lit_zero_shadowed_away_from_edges) { tl__term_values_scenes(1, 1); }

TL_TEST(shadows_term_one_lit_zero_shadowed_away_from_edges_visibility)
{
    tl__term_values_scenes(TL__CONFIG_VISIBILITY, 1);
}

TL_TEST_FULL(shadows_term_one_lit_zero_shadowed_away_from_edges_every_config)
{
    tl__term_values_scenes(0, TL__CONFIGS);
}

/* The shadow term against the area light's visibility (tl_shadow_rt_area): the mean absolute error
 * over the penumbra (the pixels that see part of the emitter) and over every measured pixel. */
typedef struct tl__soft_error {
    double penumbra, all;
    size_t penumbra_pixels, pixels;
} tl__soft_error;

static tl__soft_error tl__soft_compare(const float *visibility, const float *term, size_t n)
{
    tl__soft_error e = {0};
    for (size_t i = 0; i < n; i++) {
        if (visibility[i] < 0.0f || term[i] < 0.0f) continue;
        double d = fabs((double)term[i] - (double)visibility[i]);
        e.all += d, e.pixels++;
        if (visibility[i] > 0.0f && visibility[i] < 1.0f) e.penumbra += d, e.penumbra_pixels++;
    }
    e.all /= (double)(e.pixels ? e.pixels : 1);
    e.penumbra /= (double)(e.penumbra_pixels ? e.penumbra_pixels : 1);
    return e;
}

typedef struct tl__area_truth {
    float *visibility;
    uint8_t *state;    /* lit, shadowed, or none in the penumbra (tl_shadow_rt_area_state) */
    uint32_t *object;
} tl__area_truth;

enum { TL__AREA_STRATA = 8 }; /* 64 shadow rays per pixel: visibility in steps of 1/64 */

static int tl__area_make(const tl_shadow_case *c, const tl_light *l, float angle, uint32_t w, uint32_t h,
                         tl__area_truth *t)
{
    tl_shadow_rt *rt = tl_shadow_rt_create(c->scene);
    size_t n = (size_t)w * h;
    t->visibility = malloc(n * sizeof(float));
    t->state = malloc(n);
    t->object = malloc(n * sizeof(uint32_t));
    if (!rt || !t->visibility || !t->state || !t->object) {
        tl_shadow_rt_destroy(rt);
        return 0;
    }
    tl_shadow_rt_area(rt, &c->scene->camera, w, h, l, angle, TL__AREA_STRATA, t->visibility, t->object);
    tl_shadow_rt_area_state(t->visibility, t->state, n);
    tl_shadow_rt_destroy(rt);
    return 1;
}

static void tl__area_free(tl__area_truth *t)
{
    free(t->visibility);
    free(t->state);
    free(t->object);
}

/* With TL_SHADOW_DUMP=DIR: the term, the area truth's visibility (blue where not measured) and
 * their difference four times over (red: the term too dark, green: too bright) as PPM. */
static void tl__soft_dump(const char *name, const float *term, const float *visibility, uint32_t w, uint32_t h)
{
    const char *dir = getenv("TL_SHADOW_DUMP");
    char path[512];
    FILE *f = dir && snprintf(path, sizeof path, "%s/%s.ppm", dir, name) > 0 ? fopen(path, "wb") : NULL;
    if (!f) return;
    fprintf(f, "P6\n%u %u\n255\n", w * 3, h);
    for (uint32_t yy = 0; yy < h; yy++)
        for (uint32_t x = 0; x < 3 * w; x++) {
            size_t i = (size_t)(h - 1 - yy) * w + (x % w);
            float v = x < w ? term[i] : visibility[i], d = term[i] - visibility[i];
            uint8_t px[3] = {0, 0, 64};
            if (x < 2 * w && v >= 0.0f) px[0] = px[1] = px[2] = (uint8_t)(v * 255.0f);
            if (x >= 2 * w && term[i] >= 0.0f && visibility[i] >= 0.0f) {
                px[2] = 0;
                px[d < 0.0f ? 0 : 1] = (uint8_t)fminf(255.0f, fabsf(d) * 4.0f * 255.0f);
            }
            fwrite(px, 1, 3, f);
        }
    fclose(f);
}

/* One filter against the area truth: prints the penumbra's and the whole image's errors and the
 * wrong-state count outside the penumbra (TL__BAND pixels around it left out). */
static tl__soft_error tl__soft_measure(const tl_shadow_case *c, size_t light, const tl__area_truth *t,
                                       tl_renderer_options o, const char *what, uint32_t w, uint32_t h,
                                       tl_shadow_error *outside)
{
    tl__soft_error e = {0};
    float *term = tl_shadow_term(c, &c->lights[light], o, w, h, NULL);
    TL_CHECK(term != NULL);
    if (!term) return e;
    e = tl__soft_compare(t->visibility, term, (size_t)w * h);
    *outside = tl_shadow_rt_compare(t->state, t->object, term, w, h, TL__BAND);
    const char *filter = o.shadows.filter == TL_SHADOW_FILTER_PCSS ? "pcss" : "pcf";
    printf("shadow-penumbra light=\"%s\" %s depth=%s filter=%s size=%ux%u penumbra_pixels=%zu mae_penumbra=%.4f "
           "pixels=%zu mae_all=%.4f outside: counted=%zu acne=%zu leaks=%zu wrong=%.4f%%\n", c->light_names[light],
           what, tl__depth_name(o.depth_format), filter, w, h, e.penumbra_pixels, e.penumbra, e.pixels, e.all,
           outside->counted, outside->acne, outside->leaks, 100.0 * outside->wrong);
    char name[160];
    snprintf(name, sizeof name, "penumbra-%zu-%s-%s-%.20s", light, tl__depth_name(o.depth_format), filter, what + 5);
    for (char *ch = name; *ch; ch++)
        if (*ch == ' ' || *ch == '=' || *ch == '(' || *ch == ')') *ch = '_';
    tl__soft_dump(name, term, t->visibility, w, h);
    free(term);
    return e;
}

/* PCF and PCSS in one configuration: PCSS is nearer the area truth in the penumbra (at most half
 * PCF's error) and over the whole image, and outside the penumbra it has no more acne than PCF and stays within 0.5 %. */
static void tl__pcss_against_pcf(const tl_shadow_case *c, size_t light, const tl__area_truth *t, tl_renderer_options o,
                                 const char *what, uint32_t w, uint32_t h)
{
    tl_shadow_error out_pcf, out_pcss;
    o.shadows.filter = TL_SHADOW_FILTER_PCF;
    tl__soft_error pcf = tl__soft_measure(c, light, t, o, what, w, h, &out_pcf);
    o.shadows.filter = TL_SHADOW_FILTER_PCSS;
    tl__soft_error pcss = tl__soft_measure(c, light, t, o, what, w, h, &out_pcss);
    TL_CHECK(pcf.penumbra_pixels >= 200);
    TL_CHECK_LE(pcss.penumbra, 0.5 * pcf.penumbra);
    TL_CHECK(pcss.all < pcf.all);
    TL_CHECK_LE(out_pcss.acne, out_pcf.acne);
    TL_CHECK_LE(out_pcss.wrong, 0.005);
}

/* PCSS against the truth of a light with a size (64 stratified shadow rays per pixel over the
 * emitter): the spot light in every mode and strategy with reversed D32F, and both lights in
 * thin-lpp with both depth formats. TL_SHADOW_SIZE=WxH measures at another size (docs/shadows.md
 * quotes 480x270, the default). */
TL_TEST_FULL(shadows_pcss_penumbra_against_area_truth)
{
    tl_shadow_case c;
    TL_CHECK(tl_shadow_penumbra_case(&c));
    uint32_t w = 480, h = 270;
    const char *size = getenv("TL_SHADOW_SIZE");
    if (size && sscanf(size, "%ux%u", &w, &h) != 2) w = 480, h = 270;
    for (size_t l = 0; l < c.light_count; l++) {
        tl__area_truth t;
        TL_CHECK(tl__area_make(&c, &c.lights[l], 0.0f, w, h, &t));
        for (int d = 0; d < 2; d++) {
            tl_depth_format depth = d ? TL_DEPTH_FORMAT_D32F_REVERSED : TL_DEPTH_FORMAT_D24;
            size_t configs = l == 0 && d ? sizeof tl__configs / sizeof tl__configs[0] : 1;
            for (size_t k = 0; k < configs; k++)
                tl__pcss_against_pcf(&c, l, &t, tl__options(&tl__configs[k], depth), tl__configs[k].name, w, h);
        }
        tl__area_free(&t);
    }
    tl_shadow_case_free(&c);
}

/* The crypt's casting lights (the braziers' spheres 0.15 m, the lantern's 0.1 m, the moonlight's
 * disc 0.27 degrees in radius) at 320x180, thin-lpp light volumes and reversed D32F: PCSS against
 * the area truth, figures printed. Asserted: where the penumbra covers at least 200 pixels (the
 * braziers) PCSS is nearer the truth than PCF there and over the image; for every light, outside
 * the penumbra, no more acne than PCF and at most 0.5 % wrong. TL_SHADOW_SIZE=WxH measures at
 * another size. */
TL_TEST_FULL(shadows_pcss_crypt_against_area_truth)
{
    tl_shadow_case c;
    TL_CHECK(tl_shadow_crypt_case(&c, 0));
    uint32_t w = 320, h = 180;
    const char *size = getenv("TL_SHADOW_SIZE");
    if (size && sscanf(size, "%ux%u", &w, &h) != 2) w = 320, h = 180;
    tl_renderer_options o = tl__options(&tl__configs[0], TL_DEPTH_FORMAT_D32F_REVERSED);
    for (size_t l = 0; l < c.light_count; l++) {
        tl__area_truth t;
        TL_CHECK(tl__area_make(&c, &c.lights[l], 0.00465f, w, h, &t));
        tl_shadow_error out_pcf, out_pcss;
        o.shadows.filter = TL_SHADOW_FILTER_PCF;
        tl__soft_error pcf = tl__soft_measure(&c, l, &t, o, "crypt mode=thin-lpp", w, h, &out_pcf);
        o.shadows.filter = TL_SHADOW_FILTER_PCSS;
        tl__soft_error pcss = tl__soft_measure(&c, l, &t, o, "crypt mode=thin-lpp", w, h, &out_pcss);
        if (pcf.penumbra_pixels >= 200) { /* the braziers; the lantern's penumbra is 88 pixels, the moon's none */
            TL_CHECK(pcss.penumbra < pcf.penumbra);
            TL_CHECK(pcss.all < pcf.all);
        }
        TL_CHECK_LE(out_pcss.acne, out_pcf.acne);
        TL_CHECK_LE(out_pcss.wrong, 0.005);
        tl__area_free(&t);
    }
    tl_shadow_case_free(&c);
}

/* A renderer on the stiff scene with `lights` (every target kept, statistics synchronous). */
static tl_renderer *tl__stiff_renderer(tl_shadow_case *c, tl_light *lights, size_t n, tl_renderer_options o)
{
    tl_scene s = *c->scene;
    s.lights = lights;
    s.light_count = n;
    o.synchronous_stats = 1;
    return tl_test_render_once(&s, (tl_renderer_desc){.width = 160, .height = 90, .options = o});
}

/* No casting light: no shadow pass, no TL_SHADOWS in any program, the same plan and the same image
 * whatever the shadow options say, and no atlas; in the default mode and in visibility. */
TL_TEST(shadows_left_out_without_casters)
{
    tl_shadow_case c;
    TL_CHECK(tl_shadow_stiff_case(&c));
    tl_light lights[2] = {c.lights[0], c.lights[1]};
    lights[0].shadow = lights[1].shadow = 0;
    for (int vis = 0; vis < 2; vis++) {
        const tl_render_mode mode = vis ? TL_MODE_VISIBILITY : TL_MODE_DEFAULT;
        tl_renderer_options other = {.mode = mode, .shadows = {.atlas_size = 1024, .max_lights = 2, .pcf_radius = 3}};
        tl_renderer *a = tl__stiff_renderer(&c, lights, 2, (tl_renderer_options){.mode = mode});
        tl_renderer *b = tl__stiff_renderer(&c, lights, 2, other);
        TL_CHECK(a && b);
        if (a && b) {
            tl_frame_plan pa, pb;
            TL_CHECK(tl_renderer_get_plan(a, &pa) == TL_OK && tl_renderer_get_plan(b, &pb) == TL_OK);
            TL_CHECK_EQ_U(pa.shadow_lights, 0);
            for (size_t i = 0; i < pa.program_count; i++)
                TL_CHECK(strstr(pa.programs[i].defines, "TL_SHADOWS") == NULL);
            char ta[16384], tb[16384];
            tl_frame_plan_format(&pa, ta, sizeof ta);
            tl_frame_plan_format(&pb, tb, sizeof tb);
            TL_CHECK(strcmp(ta, tb) == 0);
            tl_frame_stats st;
            TL_CHECK(tl_renderer_render(a, NULL, &st) == TL_OK);
            TL_CHECK_EQ_U(st.shadow_atlas_bytes, 0);
            TL_CHECK_EQ_U(st.shadow_maps_rendered, 0);
            float *ia = tl_test_read_target(a, TL_TARGET_HDR, 160 * 90);
            float *ib = tl_test_read_target(b, TL_TARGET_HDR, 160 * 90);
            TL_CHECK(ia && ib && memcmp(ia, ib, 160 * 90 * 4 * sizeof(float)) == 0);
            free(ia);
            free(ib);
        }
        tl_renderer_destroy(a);
        tl_renderer_destroy(b);
    }
    tl_shadow_case_free(&c);
}

/* With a casting light the plan says so and every lighting program has the switch (visibility's
 * resolve too). */
TL_TEST(shadows_planned_with_a_caster)
{
    tl_shadow_case c;
    TL_CHECK(tl_shadow_stiff_case(&c));
    tl_renderer *r = tl__stiff_renderer(&c, c.lights, 2, (tl_renderer_options){0});
    TL_CHECK(r != NULL);
    tl_frame_plan p;
    if (r && tl_renderer_get_plan(r, &p) == TL_OK) {
        TL_CHECK_EQ_U(p.shadow_lights, 2);
        int lights = 0;
        for (size_t i = 0; i < p.program_count; i++)
            if (strncmp(p.programs[i].name, "lights.", 7) == 0) {
                lights++;
                TL_CHECK(strstr(p.programs[i].defines, "TL_SHADOWS") != NULL);
            }
        TL_CHECK(lights > 0);
        for (size_t i = 0; i < p.program_count; i++) TL_CHECK(strstr(p.programs[i].defines, "TL_PCSS") == NULL);
        /* PCSS: its code only in the programs that have the lookup */
        TL_CHECK(tl_renderer_set_options(r, &(tl_renderer_options){.shadows.filter = TL_SHADOW_FILTER_PCSS}) == TL_OK);
        TL_CHECK(tl_renderer_get_plan(r, &p) == TL_OK);
        int pcss = 0;
        for (size_t i = 0; i < p.program_count; i++) {
            const char *d = p.programs[i].defines;
            if (strncmp(p.programs[i].name, "lights.", 7) == 0) pcss += strstr(d, "TL_PCSS") != NULL;
            TL_CHECK(strstr(d, "TL_PCSS") == NULL || strstr(d, "TL_SHADOWS") != NULL);
        }
        TL_CHECK_EQ_U(pcss, lights);
        tl_light off[2] = {c.lights[0], c.lights[1]};
        off[0].shadow = off[1].shadow = 0; /* set_lights re-plans without shadows */
        TL_CHECK(tl_renderer_set_lights(r, off, 2) == TL_OK && tl_renderer_get_plan(r, &p) == TL_OK);
        TL_CHECK_EQ_U(p.shadow_lights, 0);
    }
    tl_renderer_destroy(r);
    /* visibility lights in its resolve: that program has the switch, and no light pass is planned */
    r = tl__stiff_renderer(&c, c.lights, 2, (tl_renderer_options){.mode = TL_MODE_VISIBILITY});
    TL_CHECK(r != NULL);
    if (r && tl_renderer_get_plan(r, &p) == TL_OK) {
        TL_CHECK_EQ_U(p.shadow_lights, 2);
        int resolve = 0;
        for (size_t i = 0; i < p.program_count; i++) {
            TL_CHECK(strncmp(p.programs[i].name, "lights.", 7) != 0);
            if (p.programs[i].pass != TL_PASS_VIS_RESOLVE) continue;
            resolve++;
            TL_CHECK(strstr(p.programs[i].defines, "TL_SHADOWS") != NULL);
        }
        TL_CHECK_EQ_U(resolve, 1);
    }
    tl_renderer_destroy(r);
    tl_shadow_case_free(&c);
}

/* Caching: a second frame with nothing changed renders no map and draws the same image as a frame
 * that renders every map; moving the box renders again only the views it is in. */
TL_TEST(shadows_cache_keeps_unchanged_maps)
{
    tl_shadow_case c;
    TL_CHECK(tl_shadow_stiff_case(&c));
    tl_renderer *r = tl__stiff_renderer(&c, c.lights, 2, (tl_renderer_options){0});
    tl_renderer *u = tl__stiff_renderer(&c, c.lights, 2, (tl_renderer_options){.shadows = {.cache = TL_SWITCH_OFF}});
    TL_CHECK(r && u);
    if (r && u) {
        tl_frame_stats st, su;
        TL_CHECK(tl_renderer_render(r, NULL, &st) == TL_OK && tl_renderer_render(u, NULL, &su) == TL_OK);
        TL_CHECK_EQ_U(st.shadow_maps_rendered, 0);
        TL_CHECK_EQ_U(st.shadow_maps_cached, 4 + 6);
        TL_CHECK_EQ_U(su.shadow_maps_rendered, 4 + 6);
        TL_CHECK_EQ_U(st.shadow_lights, 2);
        TL_CHECK_EQ_U(st.shadow_atlas_bytes, 4096u * 4096u * 4u);
        float *a = tl_test_read_target(r, TL_TARGET_HDR, 160 * 90), *b = tl_test_read_target(u, TL_TARGET_HDR, 160 * 90);
        TL_CHECK(a && b && memcmp(a, b, 160 * 90 * 4 * sizeof(float)) == 0);
        free(a);
        free(b);
        const float moved[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5f, 0, 0, 1};
        TL_CHECK(tl_renderer_set_object_transform(r, 2, moved) == TL_OK && tl_renderer_render(r, NULL, &st) == TL_OK);
        TL_CHECK(st.shadow_maps_rendered > 0);
        TL_CHECK(st.shadow_maps_rendered + st.shadow_maps_cached == 4 + 6);
        printf("shadow-cache moved-box rendered=%u cached=%u\n", st.shadow_maps_rendered, st.shadow_maps_cached);
    }
    tl_renderer_destroy(r);
    tl_renderer_destroy(u);
    tl_shadow_case_free(&c);
}

/* The shadow maps' GPU time is the frame's: gpu_ms is the passes' sum plus shadow_ms when maps were
 * rendered (every frame without the cache), and the passes' sum alone when every map was kept. */
TL_TEST(shadows_gpu_ms_includes_shadow_maps)
{
    tl_shadow_case c;
    TL_CHECK(tl_shadow_stiff_case(&c));
    tl_renderer *u = tl__stiff_renderer(&c, c.lights, 2, (tl_renderer_options){.shadows = {.cache = TL_SWITCH_OFF}});
    tl_renderer *k = tl__stiff_renderer(&c, c.lights, 2, (tl_renderer_options){0});
    TL_CHECK(u && k);
    for (int cached = 0; u && k && cached < 2; cached++) {
        tl_frame_stats st;
        TL_CHECK(tl_renderer_render(cached ? k : u, NULL, &st) == TL_OK);
        double passes = 0.0;
        for (int p = 0; p < TL_PASS_COUNT; p++)
            if (st.pass_ms[p] > 0.0) passes += st.pass_ms[p];
        TL_CHECK_EQ_U(st.shadow_maps_rendered, cached ? 0u : 4u + 6u);
        if (cached) TL_CHECK(st.shadow_ms == 0.0);
        else TL_CHECK(st.shadow_ms > 0.0);
        TL_CHECK(st.gpu_valid && passes > 0.0);
        /* the maps are the shadows pass's: part of the passes' sum, shadow_ms its time when it drew */
        TL_CHECK_LE(fabs(st.gpu_ms - passes), 1e-9 * st.gpu_ms);
        if (!cached) TL_CHECK(st.shadow_ms == st.pass_ms[TL_PASS_SHADOWS]);
        printf("shadow-gpu-ms %s gpu=%.3f passes=%.3f shadow=%.3f\n", cached ? "cached" : "no-cache", st.gpu_ms, passes,
               st.shadow_ms);
    }
    tl_renderer_destroy(u);
    tl_renderer_destroy(k);
    tl_shadow_case_free(&c);
}

/* More casting lights than the budget: the budget's worth get a map; a bad atlas size is refused. */
TL_TEST(shadows_budget_and_bad_options)
{
    tl_shadow_case c;
    TL_CHECK(tl_shadow_stiff_case(&c));
    tl_light many[12];
    for (int i = 0; i < 12; i++)
        many[i] = (tl_light){.type = TL_LIGHT_POINT, .position = {-3.0f + 0.5f * (float)i, 1.0f, -6.0f},
                             .color = {1.0f + (float)i, 1, 1}, .radius = 8.0f, .shadow = 1};
    tl_renderer *r = tl__stiff_renderer(&c, many, 12, (tl_renderer_options){.shadows = {.max_lights = 4}});
    TL_CHECK(r != NULL);
    tl_frame_stats st;
    if (r && tl_renderer_render(r, NULL, &st) == TL_OK) {
        TL_CHECK_EQ_U(st.shadow_lights, 4);
        TL_CHECK_EQ_U(st.shadow_maps_rendered + st.shadow_maps_cached, 4 * 6);
    }
    tl_renderer_destroy(r);
    tl_renderer *bad = NULL;
    if (ensure_context())
        TL_CHECK(tl_renderer_create(&(tl_renderer_desc){.get_proc_address = tl_context_proc_loader,
                                                        .get_proc_address_user = g_ctx,
                                                        .options = {.shadows = {.atlas_size = 1000}}},
                                    &bad) == TL_ERROR_INVALID_ARGUMENT);
    tl_renderer_destroy(bad);
    const tl_shadow_desc refused[] = {{.filter = TL_SHADOW_FILTER_COUNT_}, {.directional_angle = -0.01f},
                                      {.directional_angle = 0.3f}, {.directional_angle = NAN}};
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        bad = NULL;
        if (ensure_context())
            TL_CHECK(tl_renderer_create(&(tl_renderer_desc){.get_proc_address = tl_context_proc_loader,
                                                            .get_proc_address_user = g_ctx,
                                                            .options = {.shadows = refused[i]}},
                                        &bad) == TL_ERROR_INVALID_ARGUMENT);
        tl_renderer_destroy(bad);
    }
    tl_shadow_case_free(&c);
}

/* The renderer's warnings, for the budget's line. */
typedef struct tl__warnings {
    unsigned count;
    char last[512];
} tl__warnings;

static void tl__warning(void *user, tl_log_level level, const char *message)
{
    tl__warnings *w = (tl__warnings *)user;
    if (level != TL_LOG_WARNING) return;
    w->count++;
    snprintf(w->last, sizeof w->last, "%s", message);
}

/* 101 casting point lights in view, a budget of 64 (the most the lookup holds): the 64 in the
 * budget each get their six cube faces, their tiles halve down to 1/32 of the atlas to fit (no
 * tile smaller, none overlapping, all inside the atlas), tl_frame_stats says 64 lights with a map
 * and 37 in view without one, and the renderer says why once, through its logger. */
TL_TEST(shadows_budget_every_light_in_it_gets_a_map)
{
    enum { LIGHTS = 101, BUDGET = 64, ATLAS = 4096 };
    tl_shadow_case c;
    TL_CHECK(tl_shadow_stiff_case(&c));
    tl_light many[LIGHTS];
    for (int i = 0; i < LIGHTS; i++) /* a grid over the plane in front of the camera */
        many[i] = (tl_light){.type = TL_LIGHT_POINT, .color = {1.0f + 0.01f * (float)i, 1, 1}, .radius = 6.0f,
                             .position = {-5.0f + (float)(i % 11), 0.5f, -2.0f - 1.5f * (float)(i / 11)}, .shadow = 1};
    tl_scene s = *c.scene;
    s.lights = many;
    s.light_count = LIGHTS;
    tl__warnings warned = {0};
    tl_renderer *r = NULL;
    TL_CHECK(ensure_context());
    tl_renderer_desc d = {.get_proc_address = tl_context_proc_loader, .get_proc_address_user = g_ctx,
                          .logger = {tl__warning, &warned}, .width = 160, .height = 90,
                          .options = {.synchronous_stats = 1, .shadows = {.max_lights = BUDGET, .atlas_size = ATLAS}}};
    TL_CHECK(g_ctx && tl_renderer_create(&d, &r) == TL_OK && tl_renderer_set_scene(r, &s) == TL_OK);
    tl_frame_stats st;
    for (int frame = 0; r && frame < 2; frame++) TL_CHECK(tl_renderer_render(r, NULL, &st) == TL_OK);
    size_t n = 0;
    uint32_t side = 0;
    TL_CHECK(r && tl_renderer_get_shadow_views(r, NULL, &n, &side) == TL_OK && side == ATLAS);
    tl_shadow_view_info *v = malloc((n ? n : 1) * sizeof *v);
    static uint8_t cells[32][32];
    memset(cells, 0, sizeof cells);
    uint8_t faces[LIGHTS] = {0};
    uint32_t smallest = ATLAS, lights = 0, overlaps = 0, outside = 0;
    if (r && v && tl_renderer_get_shadow_views(r, v, &n, NULL) == TL_OK) {
        for (size_t k = 0; k < n; k++) {
            const uint32_t cell = ATLAS / 32;
            smallest = v[k].size < smallest ? v[k].size : smallest;
            outside += v[k].x + v[k].size > ATLAS || v[k].y + v[k].size > ATLAS || v[k].size % cell || v[k].x % cell ||
                       v[k].y % cell;
            for (uint32_t y = v[k].y / cell; y < (v[k].y + v[k].size) / cell && y < 32; y++)
                for (uint32_t x = v[k].x / cell; x < (v[k].x + v[k].size) / cell && x < 32; x++) overlaps += cells[y][x]++ > 0;
            if (v[k].light < LIGHTS && v[k].type == TL_LIGHT_POINT) lights += faces[v[k].light]++ == 0;
        }
    }
    uint32_t full = 0;
    for (int i = 0; i < LIGHTS; i++) full += faces[i] == 6;
    printf("shadow-budget lights=%d budget=%d stats: with a map %u, without %u; views %zu of %u lights (%u with all six "
           "faces), smallest tile %u (atlas/%u), overlapping cells %u, outside %u; warnings %u: %s\n", LIGHTS, BUDGET,
           st.shadow_lights, st.shadow_lights_unmapped, n, lights, full, smallest, ATLAS / (smallest ? smallest : 1),
           overlaps, outside, warned.count, warned.last);
    TL_CHECK_EQ_U(lights, BUDGET);
    TL_CHECK_EQ_U(full, BUDGET);
    TL_CHECK_EQ_U(n, BUDGET * 6);
    TL_CHECK(smallest >= ATLAS / 32);
    TL_CHECK_EQ_U(overlaps, 0);
    TL_CHECK_EQ_U(outside, 0);
    TL_CHECK_EQ_U(st.shadow_lights, BUDGET);
    TL_CHECK_EQ_U(st.shadow_lights_unmapped, LIGHTS - BUDGET);
    TL_CHECK_EQ_U(warned.count, 1);
    TL_CHECK(strstr(warned.last, "37 of 101") != NULL && strstr(warned.last, "max_lights") != NULL);
    free(v);
    tl_renderer_destroy(r);
    tl_shadow_case_free(&c);
}
