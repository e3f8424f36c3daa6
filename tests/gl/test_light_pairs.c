/* The light pass's roofline (docs/bandwidth.md, "Reading the results"): the exact pixel-light
 * pairs tl_renderer_count_light_pairs counts, against pairs computed analytically in double from
 * the camera and a plane facing it (each pixel centre's view ray meets the plane; is that point
 * inside the light's sphere, and a spot's cone?), independently of the depth buffer: only pixels
 * within a thin band of a boundary may go either way. What the strategies evaluate
 * (tl_frame_stats.light_pairs) against them, the tile lists' overflow, and the ALU probe. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "render_fixture.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"
#include "tl_test.h"

#define W 64u
#define H 48u
#define FOV 1.0471976f /* 60 degrees */
#define PLANE 5.0      /* the plane z = -PLANE faces the camera at the origin, looking down -Z */
#define BAND 1e-3      /* relative: a pixel this close to a boundary may go either way */

typedef struct plane_scene {
    tl_vertex v[4];
    uint32_t idx[6];
    tl_object obj;
    tl_material mat;
    tl_light lights[80];
    tl_scene s;
} plane_scene;

static void plane_init(plane_scene *p)
{
    memset(p, 0, sizeof *p);
    float s = 40.0f;
    for (int i = 0; i < 4; i++) {
        p->v[i].position[0] = (i == 1 || i == 2) ? s : -s;
        p->v[i].position[1] = i >= 2 ? s : -s;
        p->v[i].position[2] = -(float)PLANE;
        p->v[i].normal[2] = 1.0f;
    }
    static const uint32_t q[6] = {0, 1, 2, 0, 2, 3};
    memcpy(p->idx, q, sizeof q);
    p->obj = (tl_object){.first_index = 0, .index_count = 6};
    p->mat = (tl_material){.albedo = {0.5f, 0.5f, 0.5f}, .specular = {0.2f, 0.2f, 0.2f}, .gloss = 0.5f, .alpha = 1.0f};
    p->s = (tl_scene){.vertices = p->v, .vertex_count = 4, .indices = p->idx, .index_count = 6, .objects = &p->obj,
                      .object_count = 1, .materials = &p->mat, .material_count = 1, .lights = p->lights,
                      .camera = {.position = {0, 0, 0}, .target = {0, 0, -1}, .up = {0, 1, 0}, .fov_y = FOV,
                                 .near_z = 0.1f, .far_z = 100.0f}};
}

static tl_light point(double x, double y, double z, double r)
{
    return (tl_light){.type = TL_LIGHT_POINT, .position = {(float)x, (float)y, (float)z}, .radius = (float)r,
                      .color = {1, 1, 1}};
}

/* Where the centre of pixel (x, y) of a w x h grid (of the W x H frame: k pixels a cell) sees the
 * plane, in double. */
static void plane_point(double x, double y, double p[3])
{
    double t = tan(0.5 * (double)FOV), aspect = (double)W / (double)H;
    double nx = 2.0 * x / W - 1.0, ny = 2.0 * y / H - 1.0;
    p[0] = PLANE * nx * t * aspect;
    p[1] = PLANE * ny * t;
    p[2] = -PLANE;
}

/* 1 inside, 0 outside, -1 within the band of a boundary (the range sphere or the cone). */
static int analytic_inside(const tl_light *l, const double p[3])
{
    double d[3] = {p[0] - l->position[0], p[1] - l->position[1], p[2] - l->position[2]};
    double dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), r = l->radius;
    if (fabs(dist - r) < BAND * r) return -1;
    if (dist >= r) return 0;
    if (l->type != TL_LIGHT_SPOT) return 1;
    double a[3] = {l->direction[0], l->direction[1], l->direction[2]};
    double al = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    double c = (d[0] * a[0] + d[1] * a[1] + d[2] * a[2]) / (al * dist);
    if (fabs(c - l->cos_outer) < BAND) return -1;
    return c > l->cos_outer;
}

/* Bounds of the exact pairs of `lights` (local ones) over a grid of cells k x k pixels each: a cell
 * is lit at one of its pixels (below light scale 1, the pixel its depth came from), so it is
 * certainly in when all are, possibly when any is. Covered pixels likewise. */
typedef struct bounds {
    uint64_t lo, hi, covered_lo, covered_hi;
} bounds;

static bounds analytic_pairs(const tl_light *lights, size_t n, uint32_t k)
{
    bounds b = {0};
    for (uint32_t y = 0; y < H / k; y++)
        for (uint32_t x = 0; x < W / k; x++) {
            int any_sure = 0, any_maybe = 0;
            for (size_t i = 0; i < n; i++) {
                if (lights[i].type == TL_LIGHT_DIRECTIONAL) continue;
                int all = 1, some = 0;
                for (uint32_t j = 0; j < k * k; j++) {
                    double p[3];
                    plane_point(x * k + j % k + 0.5, y * k + j / k + 0.5, p);
                    int in = analytic_inside(&lights[i], p);
                    all &= in == 1;
                    some |= in != 0;
                }
                b.lo += (uint64_t)all;
                b.hi += (uint64_t)some;
                any_sure |= all;
                any_maybe |= some;
            }
            b.covered_lo += (uint64_t)any_sure;
            b.covered_hi += (uint64_t)any_maybe;
        }
    return b;
}

static tl_renderer *render_plane(const plane_scene *p, tl_render_mode mode, tl_light_strategy strategy, float scale,
                                 tl_frame_stats *st)
{
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = W, .height = H, .options = {.mode = mode, .light_strategy = strategy, .light_scale = scale}},
        .scene = &p->s, .readable = true});
    if (r) TL_CHECK(tl_renderer_render(r, NULL, st) == TL_OK);
    return r;
}

/* The lights of the analytic cases: a point light over the plane, a spot aimed at it off axis, a
 * directional light, and three that reach no pixel (behind the camera, beyond the plane, aside). */
static size_t analytic_lights(tl_light *l)
{
    l[0] = point(0.4, -0.3, -PLANE + 0.8, 1.7);
    l[1] = (tl_light){.type = TL_LIGHT_SPOT, .position = {-0.5f, 0.4f, -1.0f}, .direction = {-0.15f, 0.1f, -1.0f},
                      .radius = 7.0f, .cos_outer = 0.97f, .cos_inner = 0.99f, .color = {1, 1, 1}};
    l[2] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {0.2f, -0.3f, -1.0f}, .color = {0.1f, 0.1f, 0.1f}};
    l[3] = point(0.0, 0.0, 3.0, 2.0);             /* behind the camera */
    l[4] = point(0.5, 0.0, -PLANE - 3.0, 2.0);    /* beyond the plane: 3 from it, radius 2 */
    l[5] = point(60.0, 0.0, -PLANE + 0.5, 2.0);   /* far aside, outside the view */
    return 6;
}

/* `slack`: how wide the bounds may be, over the sure count (the band of a pixel, or a block's
 * pixels that disagree). */
static void check_bounds(const char *label, const tl_light_pair_count *c, bounds b, uint64_t slack)
{
    printf("%s: exact pairs %llu in [%llu, %llu], covered %llu in [%llu, %llu]\n", label,
           (unsigned long long)c->exact_pairs, (unsigned long long)b.lo, (unsigned long long)b.hi,
           (unsigned long long)c->covered_pixels, (unsigned long long)b.covered_lo, (unsigned long long)b.covered_hi);
    TL_CHECK(c->exact_pairs >= b.lo && c->exact_pairs <= b.hi);
    TL_CHECK(c->covered_pixels >= b.covered_lo && c->covered_pixels <= b.covered_hi);
    /* the band is thin: the case is not decided by it */
    TL_CHECK(b.hi - b.lo <= b.lo / slack + 4);
}

/* One point light and one spot over the plane, a directional light, and lights that miss: exact
 * pairs within the analytic bounds, in both strategies, and what each strategy evaluated. */
TL_TEST(light_pairs_plane_point_and_spot_analytic)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    plane_scene p;
    plane_init(&p);
    p.s.light_count = analytic_lights(p.lights);
    bounds b = analytic_pairs(p.lights, p.s.light_count, 1);
    bounds bp = analytic_pairs(p.lights, 1, 1), bs = analytic_pairs(p.lights + 1, 1, 1);
    TL_CHECK(bp.lo > 100 && bs.lo > 100); /* both lights reach a fair part of the frame */
    for (int tiled = 0; tiled < 2; tiled++) {
        tl_frame_stats st;
        tl_renderer *r = render_plane(&p, TL_MODE_THIN_LPP, tiled ? TL_LIGHT_STRATEGY_TILED : TL_LIGHT_STRATEGY_VOLUMES,
                                      0.0f, &st);
        if (!r) return;
        tl_light_pair_count c;
        TL_CHECK(tl_renderer_count_light_pairs(r, &c) == TL_OK);
        check_bounds(tiled ? "tiled" : "volumes", &c, b, 20);
        TL_CHECK_EQ_U(c.width, W);
        TL_CHECK_EQ_U(c.height, H);
        TL_CHECK_EQ_U(c.surface_pixels, (uint64_t)W * H);
        TL_CHECK_EQ_U(c.local_lights, 5);
        TL_CHECK_EQ_U(c.directional_lights, 1);
        TL_CHECK_EQ_U(c.directional_pairs, (uint64_t)W * H);
        if (tiled) {
            TL_CHECK(st.light_pairs >= c.exact_pairs);
        } else { /* the volumes' fragments past the range test: the same tests on the GPU */
            uint64_t f = st.light_fragments[TL_LIGHT_POINT] + st.light_fragments[TL_LIGHT_SPOT];
            TL_CHECK(f >= b.lo && f <= b.hi);
        }
        tl_renderer_destroy(r);
    }
}

/* Lights that reach no pixel: exactly 0 pairs and 0 covered pixels. */
TL_TEST(light_pairs_lights_missing_every_pixel)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    plane_scene p;
    plane_init(&p);
    tl_light l[6];
    analytic_lights(l);
    memcpy(p.lights, l + 3, 3 * sizeof *l);
    p.s.light_count = 3;
    tl_frame_stats st;
    tl_renderer *r = render_plane(&p, TL_MODE_FAT, TL_LIGHT_STRATEGY_TILED, 0.0f, &st);
    if (!r) return;
    tl_light_pair_count c;
    TL_CHECK(tl_renderer_count_light_pairs(r, &c) == TL_OK);
    TL_CHECK_EQ_U(c.exact_pairs, 0);
    TL_CHECK_EQ_U(c.covered_pixels, 0);
    TL_CHECK_EQ_U(c.local_lights, 3);
    TL_CHECK(st.light_pairs >= c.exact_pairs);
    tl_renderer_destroy(r);
}

/* At light scale 1/2 the count is over the light buffer's texels, each at the pixel its depth came
 * from: within the bounds of 2 x 2 blocks. */
TL_TEST(light_pairs_half_light_scale_counts_texels)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    plane_scene p;
    plane_init(&p);
    p.s.light_count = analytic_lights(p.lights);
    tl_frame_stats st;
    tl_renderer *r = render_plane(&p, TL_MODE_THIN_LPP, TL_LIGHT_STRATEGY_TILED, 0.5f, &st);
    if (!r) return;
    tl_light_pair_count c;
    TL_CHECK(tl_renderer_count_light_pairs(r, &c) == TL_OK);
    TL_CHECK_EQ_U(c.width, W / 2);
    TL_CHECK_EQ_U(c.height, H / 2);
    check_bounds("light scale 1/2", &c, analytic_pairs(p.lights, p.s.light_count, 2), 3);
    TL_CHECK(st.light_pairs >= c.exact_pairs);
    tl_renderer_destroy(r);
}

/* Tile lists that overflow in the first frame loop over every light of their chunk, and the pairs
 * count says so: 48 lights reach every tile (16 x 16 pixels, 12 tiles; 32 entries a tile to start,
 * so some lists do not fit) and 16 more are visible but beyond the plane, in no list. An
 * overflowing tile evaluates all 64; later frames, with grown lists, 48 at every pixel, which are
 * also the exact pairs. */
TL_TEST(light_pairs_overflowing_tiles_count_their_whole_chunk)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    plane_scene p;
    plane_init(&p);
    for (int i = 0; i < 48; i++) p.lights[i] = point(0.01 * i, 0.0, -1.0, 40.0);
    for (int i = 48; i < 64; i++) p.lights[i] = point(0.05 * (i - 56), 0.0, -PLANE - 3.0, 2.0);
    p.s.light_count = 64;
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = W, .height = H,
                     .options = {.mode = TL_MODE_THIN_LPP, .light_strategy = TL_LIGHT_STRATEGY_TILED, .tile_size = 16}},
        .scene = &p.s, .readable = true});
    if (!r) return;
    tl_frame_stats first, later;
    TL_CHECK(tl_renderer_render(r, NULL, &first) == TL_OK);
    for (int f = 0; f < 6; f++) TL_CHECK(tl_renderer_render(r, NULL, &later) == TL_OK);
    tl_light_pair_count c;
    TL_CHECK(tl_renderer_count_light_pairs(r, &c) == TL_OK);
    printf("first frame: %u tiles overflowed, %llu pairs; later: %u, %llu pairs; exact %llu\n", first.tile_overflows,
           (unsigned long long)first.light_pairs, later.tile_overflows, (unsigned long long)later.light_pairs,
           (unsigned long long)c.exact_pairs);
    TL_CHECK(first.tile_overflows > 0 && later.tile_overflows == 0);
    TL_CHECK_EQ_U(later.light_pairs, (uint64_t)W * H * 48);
    TL_CHECK_EQ_U(c.exact_pairs, (uint64_t)W * H * 48);
    TL_CHECK_EQ_U(first.light_pairs - later.light_pairs, (uint64_t)first.tile_overflows * 16 * 16 * 16);
    tl_renderer_destroy(r);
}

/* The ALU probe gives a finite positive cost per pair, for the scene's lights (GGX and Blinn-Phong)
 * and for a scene without local lights (its unit point light). */
TL_TEST(light_probe_finite_positive_cost)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    plane_scene p;
    plane_init(&p);
    p.s.light_count = analytic_lights(p.lights);
    for (int ggx = 0; ggx < 2; ggx++)
        for (int none = 0; none < 2; none++) {
            p.s.light_count = none ? 0 : 6;
            tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
                .renderer = {.width = W, .height = H,
                             .options.lighting = ggx ? TL_LIGHTING_GGX : TL_LIGHTING_BLINN_PHONG},
                .scene = &p.s});
            if (!r) return;
            tl_light_probe_result pr;
            TL_CHECK(tl_renderer_light_probe(r, &pr) == TL_OK);
            printf("%s, %s: %.3f ns per pair (%llu pairs in %.2f ms, %u lights, %s)\n", ggx ? "GGX" : "Blinn-Phong",
                   none ? "no lights" : "scene lights", pr.ns_per_pair, (unsigned long long)pr.pairs, pr.ms, pr.lights,
                   pr.gpu_timed ? "timer query" : "wall clock");
            TL_CHECK(isfinite(pr.ns_per_pair) && pr.ns_per_pair > 0.0 && pr.pairs > 0 && pr.lights >= 1);
            tl_renderer_destroy(r);
        }
}

/* Before a frame there are no pairs to count: refused, naming why. */
TL_TEST(light_pairs_refused_before_a_frame)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    plane_scene p;
    plane_init(&p);
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = {.width = W, .height = H}, .scene = &p.s});
    if (!r) return;
    tl_light_pair_count c;
    TL_CHECK(tl_renderer_count_light_pairs(r, &c) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(strstr(tl_renderer_last_error(r), "no frame") != NULL);
    TL_CHECK(tl_renderer_count_light_pairs(NULL, &c) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_renderer_light_probe(r, NULL) == TL_ERROR_INVALID_ARGUMENT);
    tl_renderer_destroy(r);
}
