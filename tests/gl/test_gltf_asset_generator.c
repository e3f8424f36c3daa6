/* glTF-Asset-Generator's Mesh_PrimitiveMode models (Debian's assimp-testmodels; CMake adds this
 * test only where they are installed): every model, in every mode, draws what its name says, as
 * many pixels as computed from its own geometry through the scene's camera: triangles their
 * projected area, lines the pixels a 1-pixel line steps through (the larger of |dx| and |dy| per
 * segment), points the distinct pixels their projections fall in. Before issue 30, points, lines,
 * strips and fans were skipped and rendered black. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_fixture.h"
#include "thinlight/io.h"
#include "tl_test.h"

#define W 128
#define H 96

static const tl_render_mode modes[] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_FORWARD,
                                        TL_MODE_VISIBILITY};
#define MODES ((int)(sizeof modes / sizeof modes[0]))

/* The pixel position of world point p through the scene's camera (GL conventions). */
static void project(const tl_camera *c, const float p[3], double out[2])
{
    double f[3], up[3] = {c->up[0], c->up[1], c->up[2]}, r[3], u[3], d[3], fl = 0.0;
    if (up[0] == 0.0 && up[1] == 0.0 && up[2] == 0.0) up[1] = 1.0;
    for (int k = 0; k < 3; k++) f[k] = (double)c->target[k] - c->position[k], fl += f[k] * f[k];
    for (int k = 0; k < 3; k++) f[k] /= sqrt(fl), d[k] = (double)p[k] - c->position[k];
    r[0] = f[1] * up[2] - f[2] * up[1], r[1] = f[2] * up[0] - f[0] * up[2], r[2] = f[0] * up[1] - f[1] * up[0];
    double rl = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int k = 0; k < 3; k++) r[k] /= rl;
    u[0] = r[1] * f[2] - r[2] * f[1], u[1] = r[2] * f[0] - r[0] * f[2], u[2] = r[0] * f[1] - r[1] * f[0];
    double x = r[0] * d[0] + r[1] * d[1] + r[2] * d[2], y = u[0] * d[0] + u[1] * d[1] + u[2] * d[2];
    double z = f[0] * d[0] + f[1] * d[1] + f[2] * d[2];
    double t = 1.0 / tan(0.5 * (c->fov_y > 0.0f ? c->fov_y : 1.0471975511965976));
    out[0] = (x * t / ((double)W / H) / z * 0.5 + 0.5) * W;
    out[1] = (y * t / z * 0.5 + 0.5) * H;
}

/* What a model should draw, from its objects: the pixels expected and how far off they may be. */
static void expected_pixels(const tl_scene *s, double *want, double *tol)
{
    *want = *tol = 0.0;
    uint8_t *seen = calloc((size_t)W * H, 1);
    for (size_t i = 0; i < s->object_count && seen; i++) {
        const tl_object *o = &s->objects[i];
        const uint32_t *ix = s->indices + o->first_index;
        uint32_t per = o->primitive == TL_PRIMITIVE_TRIANGLES ? 3u : o->primitive == TL_PRIMITIVE_LINES ? 2u : 1u;
        for (uint32_t k = 0; k + per <= o->index_count; k += per) {
            double q[3][2];
            for (uint32_t c = 0; c < per; c++) project(&s->camera, s->vertices[ix[k + c]].position, q[c]);
            if (per == 3) { /* area, and half the perimeter of edge pixels either way */
                *want += 0.5 * fabs((q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0]));
                for (int e = 0; e < 3; e++) *tol += 0.5 * hypot(q[(e + 1) % 3][0] - q[e][0], q[(e + 1) % 3][1] - q[e][1]);
            } else if (per == 2) {
                *want += fmax(fabs(q[1][0] - q[0][0]), fabs(q[1][1] - q[0][1]));
                *tol += 2.0; /* its ends */
            } else {
                long x = (long)floor(q[0][0]), y = (long)floor(q[0][1]);
                if (x >= 0 && y >= 0 && x < W && y < H && !seen[y * W + x]++) *want += 1.0;
                *tol += 0.02; /* projections within rounding of a pixel border */
            }
        }
    }
    free(seen);
}

static void check_model(int n)
{
    char path[512];
    snprintf(path, sizeof path, "%s/Mesh_PrimitiveMode_%02d.gltf", TL_PRIMITIVE_MODE_DIR, n);
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_load_gltf(path, NULL, &s) == TL_OK);
    if (!s) return;
    TL_CHECK(s->object_count == 1);
    double want, tol;
    expected_pixels(s, &want, &tol);
    TL_CHECK(want > 40.0); /* every model draws something on screen */
    for (int m = 0; m < MODES; m++) {
        tl_renderer_desc d = {.width = W, .height = H, .options = {.mode = modes[m]}};
        tl_renderer *r = tl_test_render_once(s, d);
        TL_CHECK(r != NULL);
        float *hdr = r ? tl_test_read_target(r, TL_TARGET_HDR, (size_t)W * H) : NULL;
        size_t drawn = 0;
        for (size_t i = 0; hdr && i < (size_t)W * H; i++) drawn += hdr[4 * i] + hdr[4 * i + 1] + hdr[4 * i + 2] > 0.0f;
        TL_CHECK(fabs((double)drawn - want) <= tol);
        if (fabs((double)drawn - want) > tol || getenv("TL_DEBUG_PRIMS"))
            fprintf(stderr, "Mesh_PrimitiveMode_%02d in %s: %zu pixels drawn, %.1f +- %.1f expected\n", n,
                    tl_render_mode_name(modes[m]), drawn, want, tol);
        free(hdr);
        tl_renderer_destroy(r);
    }
    tl_scene_destroy(s);
}

#define MODEL_TEST(n, what)                                                                        \
    TL_TEST(gltf_asset_generator_primitive_mode_##n##_##what) { check_model(n); }

MODEL_TEST(0, points)
MODEL_TEST(1, lines)
MODEL_TEST(2, line_loop)
MODEL_TEST(3, line_strip)
MODEL_TEST(4, triangle_strip)
MODEL_TEST(5, triangle_fan)
MODEL_TEST(6, triangles)
MODEL_TEST(7, points_indexed)
MODEL_TEST(8, lines_indexed)
MODEL_TEST(9, line_loop_indexed)
MODEL_TEST(10, line_strip_indexed)
MODEL_TEST(11, triangle_strip_indexed)
MODEL_TEST(12, triangle_fan_indexed)
MODEL_TEST(13, triangles_u32)
MODEL_TEST(14, triangles_u8)
MODEL_TEST(15, triangles_u16)
