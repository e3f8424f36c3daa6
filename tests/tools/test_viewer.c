/* thinlight-viewer from a script, under Xvfb (xvfb-run when DISPLAY is unset): every mode and every
 * debug view written with --screenshot. Checks: an unmoved camera gives exactly thinlight-render's
 * image in each mode (the same library, camera and rasteriser: no tolerance is needed, and a
 * difference means the viewer changed the view); each view a mode has is non-blank and each it
 * lacks shows the placeholder; views that must differ do; a full-size view equals its thumbnail in
 * the grid; the split view's halves are the two modes' images; a resize keeps the bytes per pixel
 * and scales the bytes; --help and bad usage. */
#define _POSIX_C_SOURCE 200809L /* popen */
#include "viewer_harness.h"

enum { VW_W = 320, VW_H = 180, GRID_W = 640, GRID_H = 360 };

enum { NM = 5 };
static const char *const modes[NM] = {"thin-lpp", "thin-deferred", "fat", "forward", "visibility"};
/* The views in the viewer's order (--view names; the grid puts them row by row, 5 across). */
enum { NV = 26, NV_NO_EFFECTS = 14, V_VIS_ID = 24, V_VIS_NORMALS = 25 }; /* views; those that need no effect first */
static const char *const views[NV] = {"final", "normals", "gloss", "luma", "chroma", "albedo", "depth",
                                      "position", "light-diffuse", "light-specular", "tile-lights", "hdr",
                                      "before-fxaa", "diff-fat", "ao-raw", "ao", "dof-coc", "ssr", "bloom",
                                      "msaa-edges", "material-model", "shadow-atlas", "shadow-cascades",
                                      "shadow-only", "vis-id", "vis-normals"};
/* Which views each mode has (the G-buffer it writes) with every effect off: 1 = available
 * (the effects' views: test_viewer_effects.c; the shadow views need --shadows: test_viewer_shadows.c). */
static const int has_view[NM][NV] = {
    /* thin-lpp: RT0, light buffer; no RT1 */
    {1, 1, 1, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0},
    /* thin-deferred: RT0, RT1; no light buffer */
    {1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0},
    /* fat: its normal, albedo and position targets */
    {1, 1, 1, 0, 0, 1, 1, 1, 0, 0, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0},
    /* forward: depth only (Forward+ has the tile lists) */
    {1, 0, 0, 0, 0, 0, 1, 1, 0, 0, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0},
    /* visibility: depth and the id, the tile lists; RT0 (normals, gloss) kept by the viewer's pass */
    {1, 1, 1, 0, 0, 0, 1, 1, 0, 0, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1},
};
/* Views that draw a scale legend into their pixels (bottom left; not in the grid's thumbnails). */
static const int has_legend[NV] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1, 1, 1, 0, 0, 0, 0, 1, 1, 1, 0, 0};

/* An unmoved camera: the scene's, exactly as thinlight-render draws it, in every mode. */
static void final_view_equals_render(int m)
{
    char args[128], png[64], ref[64], cmd[2048];
    snprintf(args, sizeof args, "--size %ux%u --mode %s", VW_W, VW_H, modes[m]);
    snprintf(png, sizeof png, "final_%s.png", modes[m]);
    snprintf(ref, sizeof ref, "render_%s.png", modes[m]);
    TL_CHECK(viewer(args, png) == 0);
    snprintf(cmd, sizeof cmd, "'%s' default --size %ux%u --mode %s --light-strategy tiled -o '%s/%s' 2>/dev/null",
             TL_RENDER, VW_W, VW_H, modes[m], TL_WORK, ref);
    TL_CHECK(run(cmd) == 0);
    image a = load(png), b = load(ref);
    tl_image_error e = compare(&a, &b);
    printf("%s: viewer vs thinlight-render max %.0f mean %.5f levels\n", modes[m], e.max_abs, e.mean_abs);
    TL_CHECK(a.px && a.w == VW_W && a.h == VW_H && colours(&a) > 32);
    TL_CHECK(e.max_abs == 0.0);
    release(&a);
    release(&b);
}

/* The default mode (the default tier), then every other mode (the full tier). */
TL_TEST(viewer_final_view_equals_thinlight_render) { final_view_equals_render(0); }

TL_TEST_FULL(viewer_final_view_equals_thinlight_render_each_mode)
{
    for (int m = 1; m < NM; m++) final_view_equals_render(m);
}

/* The grid in each mode: views the mode has are non-blank, views it lacks are the placeholder,
 * views that must differ do, and fat against itself differs nowhere. */
static void check_grid(int m)
{
    char args[128], png[64];
    snprintf(args, sizeof args, "--size %ux%u --mode %s --grid", GRID_W, GRID_H, modes[m]);
    snprintf(png, sizeof png, "grid_%s.png", modes[m]);
    TL_CHECK(viewer(args, png) == 0);
    image g = load(png), c[NV];
    TL_CHECK(g.px && g.w == GRID_W && g.h == GRID_H && opaque(&g));
    if (!g.px) return;
    for (int v = 0; v < NV; v++) {
        c[v] = cell(&g, v);
        int blank = colours(&c[v]) < 2, placeholder = is_placeholder(&c[v]);
        int diff_in_fat = m == 2 && v == 13; /* fat against fat: all black, as it must be */
        printf("%s %-14s %s\n", modes[m], views[v], placeholder ? "placeholder" : blank ? "blank" : "image");
        if (!has_view[m][v]) TL_CHECK(placeholder);
        else if (diff_in_fat) TL_CHECK(blank && c[v].px[0] == 0 && c[v].px[1] == 0 && c[v].px[2] == 0);
        else TL_CHECK(!placeholder && !blank);
    }
    static const int differ[][2] = {{0, 1}, {0, 11}, {6, 7}, {1, 2}, {3, 5}, {8, 9}, {0, 10}};
    for (size_t k = 0; k < sizeof differ / sizeof differ[0]; k++) {
        int a = differ[k][0], b = differ[k][1];
        if (!has_view[m][a] || !has_view[m][b]) continue;
        tl_image_error e = compare(&c[a], &c[b]);
        printf("%s: %s vs %s mean %.2f levels\n", modes[m], views[a], views[b], e.mean_abs);
        TL_CHECK(e.mean_abs > 1.0);
    }
    for (int v = 0; v < NV; v++) free(c[v].px);
    release(&g);
}

TL_TEST(viewer_grid_views_thin_lpp) { check_grid(0); }
TL_TEST_FULL(viewer_grid_views_thin_deferred) { check_grid(1); }
TL_TEST_FULL(viewer_grid_views_fat) { check_grid(2); }
TL_TEST_FULL(viewer_grid_views_forward) { check_grid(3); }
TL_TEST_FULL(viewer_grid_views_visibility) { check_grid(4); }

/* The vis-id view's colour of an id (docs/viewer.md): Wellons' lowbias32 hash of (object slot + 1)
 * << 20 | triangle, each of its three low bytes b as 64 + 3 b / 4; black where nothing was drawn. */
static void vis_colour(const float *p, uint8_t rgb[3])
{
    uint32_t id = p[2] > 0.5f ? (((uint32_t)p[0] + 1u) << 20) | (uint32_t)p[1] : 0u, h = id;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    for (int k = 0; k < 3; k++) rgb[k] = id ? (uint8_t)(64u + ((h >> (8 * k)) & 255u) * 3u / 4u) : 0;
}

/* vis-id (mode visibility): every pixel the colour docs/viewer.md gives the id thinlight-render's
 * --dump-targets wrote for the same frame (vis_id.exr: object, triangle, drawn), exactly; many
 * colours (the crypt's triangles); the placeholder in another mode. */
TL_TEST(viewer_vis_id_view_colours_each_triangle)
{
    char cmd[2048], path[1024];
    snprintf(cmd, sizeof cmd, "'%s' default --size %ux%u --mode visibility --light-strategy tiled -o '%s/vis.png' "
             "--dump-targets '%s/vis_targets' 2>/dev/null", TL_RENDER, VW_W, VW_H, TL_WORK, TL_WORK);
    TL_CHECK(run(cmd) == 0);
    image v = shot(VW_W, VW_H, "--mode visibility --view vis-id", "vis_id.png"),
          none = shot(VW_W, VW_H, "--mode thin-lpp --view vis-id", "vis_id_thin.png");
    snprintf(path, sizeof path, "%s/vis_targets/vis_id.exr", TL_WORK);
    tl_float_image ids = {0};
    TL_CHECK(tl_image_read_rgb_float(path, &(tl_image_read_desc){.logger = {.fn = log_line}}, &ids) == TL_OK);
    TL_CHECK(v.px && ids.rgb && v.w == ids.width && v.h == ids.height);
    size_t wrong = 0, drawn = 0;
    for (uint32_t y = 0; v.px && ids.rgb && y < VW_H; y++) /* both rows top to bottom */
        for (uint32_t x = 0; x < VW_W; x++) {
            const float *f = ids.rgb + 3 * ((size_t)y * VW_W + x);
            uint8_t want[3];
            vis_colour(f, want);
            drawn += f[2] > 0.5f;
            wrong += memcmp(at(&v, x, y), want, 3) != 0;
        }
    printf("vis-id: %zu of %zu pixels drawn, %zu not the colour of their id, %zu colours (64: at least)\n", drawn,
           (size_t)VW_W * VW_H, wrong, v.px ? colours(&v) : 0);
    TL_CHECK(drawn > 0 && wrong == 0 && colours(&v) == 64);
    TL_CHECK(none.px && is_placeholder(&none));
    tl_float_image_free(&ids);
    release(&v);
    release(&none);
}

/* vis-normals (mode visibility): the normals rebuilt on the CPU from each pixel's id and the
 * scene's triangle are the rasteriser's, RT0's as the normals view shows it in the same mode (its
 * octahedral 2 x 12 bits aside: measured at most 2 levels apart, 0.005 on average, at 320x180; the
 * crypt has no normal map), and not the final
 * image; the placeholder in another mode. */
TL_TEST(viewer_vis_normals_view_matches_rt0)
{
    image rebuilt = shot(VW_W, VW_H, "--mode visibility --view vis-normals", "vis_normals.png"),
          rt0 = shot(VW_W, VW_H, "--mode visibility --view normals", "vis_rt0_normals.png"),
          fin = shot(VW_W, VW_H, "--mode visibility", "vis_final.png"),
          none = shot(VW_W, VW_H, "--mode fat --view vis-normals", "vis_normals_fat.png");
    tl_image_error e = compare(&rebuilt, &rt0), f = compare(&rebuilt, &fin);
    printf("vis-normals against RT0's normals: max %.0f mean %.4f levels; against the final image mean %.1f\n",
           e.max_abs, e.mean_abs, f.mean_abs);
    TL_CHECK(rebuilt.px && colours(&rebuilt) > 32 && !is_placeholder(&rebuilt) && !is_placeholder(&rt0));
    TL_CHECK(e.max_abs <= 3.0 && e.mean_abs < 0.1 && f.mean_abs > 10.0);
    TL_CHECK(none.px && is_placeholder(&none));
    release(&rebuilt);
    release(&rt0);
    release(&fin);
    release(&none);
}

/* Thumbnail pixel (x, y) of a cell (GL rows: from the bottom) is the full view's pixel
 * (x W / cw, y H / ch); PNG rows run from the top. The full view's legend is left out: the
 * bottom-left 200 x 48 pixels (the legend's box at 640 x 360 is 8 + 134 or the title's width
 * across, 8 + 32 up). */
static double thumbnail_error(const image *full, const image *grid, int v)
{
    uint32_t cw = grid->w / GRID_COLS, ch = grid->h / GRID_ROWS, cx = (uint32_t)(v % GRID_COLS),
             cy = GRID_ROWS - 1 - (uint32_t)(v / GRID_COLS);
    double worst = 0;
    for (uint32_t y = 1; y + 1 < ch; y++)
        for (uint32_t x = 1; x + 1 < cw; x++) {
            uint32_t sx = x * full->w / cw, sy = y * full->h / ch;
            if (has_legend[v] && sx < 200 && sy < 48) continue;
            const uint8_t *a = at(grid, cx * cw + x, grid->h - 1 - (cy * ch + y)), *b = at(full, sx, full->h - 1 - sy);
            for (int k = 0; k < 3; k++) worst = abs(a[k] - b[k]) > worst ? abs(a[k] - b[k]) : worst;
        }
    return worst;
}

/* Every view on its own at full size (in thin-deferred, or thin-lpp for the light buffer): not
 * blank, and the same pixels as its thumbnail in that mode's grid. */
TL_TEST_FULL(viewer_each_view_full_size_matches_its_thumbnail)
{
    image grids[2];
    for (int m = 0; m < 2; m++) {
        char args[128], png[64];
        snprintf(args, sizeof args, "--size %ux%u --mode %s --grid", GRID_W, GRID_H, modes[m]);
        snprintf(png, sizeof png, "thumbs_%s.png", modes[m]);
        TL_CHECK(viewer(args, png) == 0);
        grids[m] = load(png);
    }
    image final_view = {0, 0, NULL};
    for (int v = 0; v < NV_NO_EFFECTS; v++) {
        int m = has_view[1][v] ? 1 : 0;
        char args[128], png[64];
        snprintf(args, sizeof args, "--size %ux%u --mode %s --view %s", GRID_W, GRID_H, modes[m], views[v]);
        snprintf(png, sizeof png, "view_%s.png", views[v]);
        TL_CHECK(viewer(args, png) == 0);
        image full = load(png);
        TL_CHECK(full.px && colours(&full) > 1 && !is_placeholder(&full) && opaque(&full));
        double e = full.px && grids[m].px ? thumbnail_error(&full, &grids[m], v) : 1e9;
        printf("%-14s (%s): thumbnail max difference %.0f\n", views[v], modes[m], e);
        TL_CHECK(e == 0.0);
        if (v == 0) { final_view = full; continue; }
        if (v == 12) { /* FXAA moves edge pixels only */
            tl_image_error d = compare(&full, &final_view);
            printf("before-fxaa vs final: max %.0f mean %.3f levels\n", d.max_abs, d.mean_abs);
            TL_CHECK(d.max_abs > 0 && d.mean_abs < 2.0);
        }
        release(&full);
    }
    release(&final_view);
    for (int m = 0; m < 2; m++) release(&grids[m]);
}

/* Left half thin-deferred, right half fat, a white column between. */
TL_TEST(viewer_split_view_halves_are_the_two_modes)
{
    image s = shot(VW_W, VW_H, "--mode thin-deferred --split fat", "split.png"),
          l = shot(VW_W, VW_H, "--mode thin-deferred", "split_left.png"), r = shot(VW_W, VW_H, "--mode fat", "split_right.png");
    TL_CHECK(s.px && l.px && r.px && s.w == VW_W && l.w == VW_W && r.w == VW_W);
    size_t wrong_left = 0, wrong_right = 0, wrong_line = 0;
    for (uint32_t y = 0; s.px && l.px && r.px && y < VW_H; y++)
        for (uint32_t x = 0; x < VW_W; x++) {
            const uint8_t *p = at(&s, x, y);
            if (x < VW_W / 2) wrong_left += memcmp(p, at(&l, x, y), 3) != 0;
            else if (x == VW_W / 2) wrong_line += p[0] != 255 || p[1] != 255 || p[2] != 255;
            else wrong_right += memcmp(p, at(&r, x, y), 3) != 0;
        }
    printf("split: %zu left, %zu right, %zu line pixels wrong\n", wrong_left, wrong_right, wrong_line);
    TL_CHECK(wrong_left == 0 && wrong_right == 0 && wrong_line == 0);
    tl_image_error e = compare(&l, &r); /* the halves come from different images */
    TL_CHECK(e.max_abs > 0);
    release(&s);
    release(&l);
    release(&r);
}

/* --print-targets lines before and after the window grows 2 x 2: the same bytes per pixel, four
 * times the bytes (light volumes: no per-tile buffer whose size rounds to tiles). */
TL_TEST(viewer_resize_reallocates_targets)
{
    char cmd[2048], line[256];
    snprintf(cmd, sizeof cmd, "%s'%s' --no-panel --light-strategy volumes --size 320x180 --resize 640x360 --frames 6 "
             "--print-targets", xvfb(), TL_VIEWER);
    FILE *f = popen(cmd, "r");
    TL_CHECK(f != NULL);
    unsigned w[2] = {0, 0}, h[2] = {0, 0}, sum[2] = {0, 0}, peak[2] = {0, 0}, alloc[2] = {0, 0};
    size_t total[2] = {0, 0}, allocated[2] = {0, 0}, n = 0;
    while (f && fgets(line, sizeof line, f))
        if (n < 2 && sscanf(line, "targets %ux%u: %u B/px sum, %u B/px peak, %u B/px allocated, %zu bytes total, %zu bytes allocated",
                            &w[n], &h[n], &sum[n], &peak[n], &alloc[n], &total[n], &allocated[n]) == 7) {
            printf("%s", line);
            n++;
        }
    TL_CHECK(f && pclose(f) == 0);
    TL_CHECK(n == 2);
    TL_CHECK(w[0] == 320 && h[0] == 180 && w[1] == 640 && h[1] == 360);
    TL_CHECK(sum[0] > 0 && sum[0] == sum[1] && peak[0] == peak[1] && alloc[0] == alloc[1]);
    TL_CHECK(total[0] == (size_t)sum[0] * 320 * 180 && total[1] == 4 * total[0] && allocated[1] == 4 * allocated[0]);
}

/* A glTF file opens; every view its mode has shows something. */
TL_TEST(viewer_gltf_scene_grid)
{
#ifdef TL_MAKE_SCENES
    char cmd[2048], args[1200];
    snprintf(cmd, sizeof cmd, "'%s' '%s/scenes' >/dev/null", TL_MAKE_SCENES, TL_WORK);
    TL_CHECK(run(cmd) == 0);
    snprintf(args, sizeof args, "'%s/scenes/textured_boxes.gltf' --size %ux%u --mode thin-deferred --grid", TL_WORK,
             GRID_W, GRID_H);
    TL_CHECK(viewer(args, "gltf_grid.png") == 0);
    image g = load("gltf_grid.png");
    TL_CHECK(g.px != NULL);
    for (int v = 0; g.px && v < 13; v++) { /* diff-fat may be black: few edges; effects are off */
        image c = cell(&g, v);
        if (has_view[1][v]) TL_CHECK(colours(&c) > 1 && !is_placeholder(&c));
        free(c.px);
    }
    release(&g);
#else
    printf("no make_gltf_scenes in this build\n");
#endif
}

TL_TEST(viewer_help_lists_keys_bad_usage_fails)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "'%s' --help | grep -q 'Keys'", TL_VIEWER);
    TL_CHECK(run(cmd) == 0);
    snprintf(cmd, sizeof cmd, "'%s' --view nonsense 2>/dev/null", TL_VIEWER);
    TL_CHECK(run(cmd) == 2);
    /* the scene is read before a window is opened: no display needed */
    snprintf(cmd, sizeof cmd, VW_ENV "'%s' '%s/no-such-file.gltf' --frames 1 2>/dev/null", TL_VIEWER, TL_WORK);
    TL_CHECK(run(cmd) == 1);
}

/* The dynamic light scale (examples/viewer/light_scale.c) under scripted motion: --move-camera
 * orbits the camera on frames MOVE_FIRST .. MOVE_FIRST + MOVE_COUNT - 1, --frames runs fixed 1/30 s
 * steps, --print-frames prints each frame's scale (the one given to the renderer and the one its
 * plan reports). Expected, from the rule: the chosen scale before the motion; `lowered` (never
 * above the chosen one) on every moving frame and on the still frames after it until 0.25 s (8
 * steps of 1/30 s, at least 3 frames) have passed; the chosen scale again from then on. */
enum { MOVE_FIRST = 4, MOVE_COUNT = 8, MOVE_FRAMES = 26 };

static int still_frames_to_restore(void)
{
    int n = 0;
    double t = 0.0;
    while (t < 0.25 - 1e-6 || n < 3) t += (double)(1.0f / 30.0f), n++;
    return n;
}

static void check_dynamic(const char *more, float chosen, float lowered)
{
    char cmd[2048], line[256];
    snprintf(cmd, sizeof cmd, "%s'%s' --no-panel --size 192x108 --frames %d --move-camera %d,%d --print-frames %s",
             xvfb(), TL_VIEWER, MOVE_FRAMES, MOVE_FIRST, MOVE_COUNT, more);
    FILE *f = popen(cmd, "r");
    TL_CHECK(f != NULL);
    int seen = 0, wrong = 0, restore = MOVE_FIRST + MOVE_COUNT - 1 + still_frames_to_restore();
    while (f && fgets(line, sizeof line, f)) {
        unsigned frame;
        float scale, plan;
        int moving, dynamic;
        double ms;
        if (sscanf(line, "frame %u: light-scale %g plan-scale %g moving %d dynamic %d gpu-ms %lf", &frame, &scale, &plan,
                   &moving, &dynamic, &ms) != 6)
            continue;
        int moves = (int)frame >= MOVE_FIRST && (int)frame < MOVE_FIRST + MOVE_COUNT;
        float want = (int)frame < MOVE_FIRST || (int)frame >= restore ? chosen : lowered;
        int bad = scale != want || plan != want || moving != moves;
        printf("%s%s", bad ? "WRONG (want " : "", line);
        if (bad) printf("  ... want light-scale %g moving %d)\n", want, moves);
        wrong += bad;
        seen++;
    }
    TL_CHECK(f && pclose(f) == 0);
    TL_CHECK(seen == MOVE_FRAMES);
    TL_CHECK(wrong == 0);
}

/* No frame reaches a 1e6 ms budget: 1/2 while moving. */
TL_TEST(viewer_dynamic_light_scale_half_while_moving)
{
    check_dynamic("--dynamic-light-scale --light-budget-ms 1e6", 1.0f, 0.5f);
}

/* Every frame is over a 1 microsecond budget: straight to 1/4 (the frames before the motion were
 * measured over it). */
TL_TEST(viewer_dynamic_light_scale_quarter_over_budget)
{
    check_dynamic("--dynamic-light-scale --light-budget-ms 0.001", 1.0f, 0.25f);
}

/* Without the flag the scale stays; with a chosen 1/4 the dynamic rule never raises it. */
TL_TEST_FULL(viewer_light_scale_fixed_without_dynamic_never_above_chosen)
{
    check_dynamic("--light-scale 0.5", 0.5f, 0.5f);
    check_dynamic("--light-scale 0.25 --dynamic-light-scale --light-budget-ms 1e6", 0.25f, 0.25f);
}

/* MSAA with per-sample lighting on edges (fat, --msaa 4): the final view is thinlight-render's
 * image, and the msaa-edges view marks in red the pixels msaa-classify lit per sample (msaa.edges:
 * some, never most of the frame). */
TL_TEST_FULL(viewer_msaa_sample_edges_view)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd,
             "'%s' default --size %ux%u --mode fat --msaa 4 --fxaa off --light-strategy tiled -o '%s/%s' 2>/dev/null",
             TL_RENDER, VW_W, VW_H, TL_WORK, "render_msaa_fat.png");
    TL_CHECK(run(cmd) == 0);
    TL_CHECK(viewer("--size 320x180 --mode fat --msaa 4 --fxaa off", "final_msaa_fat.png") == 0);
    TL_CHECK(viewer("--size 320x180 --mode fat --msaa 4 --fxaa off --view msaa-edges", "edges_msaa_fat.png") == 0);
    image ref = load("render_msaa_fat.png"), fin = load("final_msaa_fat.png"), e = load("edges_msaa_fat.png");
    TL_CHECK(fin.px && ref.px && compare(&fin, &ref).max_abs == 0.0);
    size_t red = 0, n = (size_t)VW_W * VW_H;
    for (uint32_t y = 0; e.px && y < VW_H; y++)
        for (uint32_t x = 0; x < VW_W; x++) {
            const uint8_t *p = at(&e, x, y);
            red += p[0] == 255 && p[1] == 0 && p[2] == 0;
        }
    printf("msaa-edges, fat per-sample edges: %zu of %zu pixels red\n", red, n);
    TL_CHECK(red > 50 && red < n / 5);
    release(&ref);
    release(&fin);
    release(&e);
}

/* MSAA (key M, --msaa): thin-lpp's final view is thinlight-render's image with the same samples,
 * and the msaa-edges view marks in red the pixels whose material pass re-lit a sample (edge pixels:
 * 11 % of the crypt at 320x180, never most of the frame); without MSAA the view is the placeholder. */
TL_TEST(viewer_msaa_final_and_edges_view)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "'%s' default --size %ux%u --msaa 4 --fxaa off --light-strategy tiled -o '%s/%s' 2>/dev/null",
             TL_RENDER, VW_W, VW_H, TL_WORK, "render_msaa.png");
    TL_CHECK(run(cmd) == 0);
    TL_CHECK(viewer("--size 320x180 --msaa 4 --fxaa off", "final_msaa.png") == 0);
    TL_CHECK(viewer("--size 320x180 --msaa 4 --fxaa off --view msaa-edges", "edges_msaa.png") == 0);
    TL_CHECK(viewer("--size 320x180 --view msaa-edges", "edges_none.png") == 0);
    image ref = load("render_msaa.png"), fin = load("final_msaa.png"), e = load("edges_msaa.png"),
          none = load("edges_none.png");
    tl_image_error d = compare(&fin, &ref);
    TL_CHECK(fin.px && ref.px && d.max_abs == 0.0);
    size_t red = 0, n = (size_t)VW_W * VW_H;
    for (uint32_t y = 0; e.px && y < VW_H; y++)
        for (uint32_t x = 0; x < VW_W; x++) {
            const uint8_t *p = at(&e, x, y);
            red += p[0] == 255 && p[1] == 0 && p[2] == 0;
        }
    printf("msaa-edges: %zu of %zu pixels red\n", red, n);
    TL_CHECK(red > 50 && red < n / 5);
    TL_CHECK(none.px && is_placeholder(&none));
    release(&ref);
    release(&fin);
    release(&e);
    release(&none);
}
