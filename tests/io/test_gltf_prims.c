/* glTF primitive modes and vertex attributes past the first (tl_scene_load_gltf, no GL): triangle
 * strips and fans become triangle lists that cover the strip's area with one winding, points and
 * lines keep their vertices as point and line lists, COLOR_0 in every component type becomes
 * tl_scene.colors, TEXCOORD_1 becomes tl_scene.uv1 for the maps whose texCoord is 1. The files are
 * written at run time (gltf_prims.h). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_checks.h"
#include "gltf_doc.h"
#include "gltf_prims.h"

/* Loads dir/<test>/<name>.gltf written from `prims`; checks the scene's invariants. */
static tl_scene *load_prims(const char *test, const tlf_prim *prims, size_t n, const char *materials, const char *more,
                            capture *log)
{
    char dir[1024], path[1024];
    case_dir(dir, sizeof dir, test);
    if (tlf_write_prims(dir, test, prims, n, materials, more, path, sizeof path)) {
        TL_CHECK(0 && "written");
        return NULL;
    }
    memset(log, 0, sizeof *log);
    tl_gltf_options o = {.logger = {capture_fn, log}};
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_load_gltf(path, &o, &s) == TL_OK);
    if (s) check_geometry(s);
    return s;
}

/* Twice the signed area of a triangle's projection on z = 0. */
static double area2(const tl_scene *s, const uint32_t *t)
{
    const float *a = s->vertices[t[0]].position, *b = s->vertices[t[1]].position, *c = s->vertices[t[2]].position;
    return ((double)b[0] - a[0]) * ((double)c[1] - a[1]) - ((double)b[1] - a[1]) * ((double)c[0] - a[0]);
}

/* Every triangle of object `o`: distinct corners, counter-clockwise seen from +Z (flat normals
 * +Z); returns their total area. */
static double ccw_area(const tl_scene *s, const tl_object *o)
{
    double total = 0.0;
    TL_CHECK_EQ_U(o->primitive, TL_PRIMITIVE_TRIANGLES);
    for (uint32_t k = 0; k + 2 < o->index_count; k += 3) {
        const uint32_t *t = s->indices + o->first_index + k;
        double a = area2(s, t);
        TL_CHECK(a > 0.0);
        for (int c = 0; c < 3; c++) TL_CHECK(s->vertices[t[c]].normal[2] > 0.999f);
        total += 0.5 * a;
    }
    return total;
}

/* A zig-zag of unit squares along x: bottom, top, bottom, ... (counter-clockwise from +Z as a
 * strip: the first triangle is (0,0), (1,0)... see below). */
static const float strip_pos[8][3] = {{0, 1, 0}, {0, 0, 0}, {1, 1, 0}, {1, 0, 0},
                                      {2, 1, 0}, {2, 0, 0}, {3, 1, 0}, {3, 0, 0}};

TL_TEST(gltf_triangle_strip_and_fan_become_ccw_lists)
{
    /* two strips joined by repeated indices (the degenerate triangles are dropped), the same
     * strip without indices, and a fan around a hexagon's centre */
    static const uint32_t joined[] = {0, 1, 2, 3, 3, 4, 4, 5, 6, 7};
    float fan[8][3] = {{0, 0, 0}};
    for (int k = 0; k < 7; k++) {
        double a = 2.0 * 3.14159265358979 * (k % 6) / 6.0;
        fan[k + 1][0] = (float)cos(a), fan[k + 1][1] = (float)sin(a);
    }
    tlf_prim p[3] = {{.mode = 5, .pos = strip_pos, .nv = 8, .idx = joined, .ni = 10, .material = -1},
                     {.mode = 5, .pos = strip_pos, .nv = 8, .material = -1},
                     {.mode = 6, .pos = (const float(*)[3])fan, .nv = 8, .material = -1}};
    capture log;
    tl_scene *s = load_prims("gltf_triangle_strip_and_fan_become_ccw_lists", p, 3, "", "", &log);
    if (!s) return;
    TL_CHECK_EQ_U(log.warnings, 0);
    TL_CHECK_EQ_U(s->object_count, 3);
    if (s->object_count == 3) {
        /* joined: the two triangles of strip 0, 1, 2, 3 and of 4, 5, 6, 7 (squares 1 and 3); the
         * four of the join (2 3 3, 3 4 3, 3 4 4, 4 5 4) repeat an index */
        double hexagon = 6.0 * 0.5 * sin(2.0 * 3.14159265358979 / 6.0);
        TL_CHECK_EQ_U(s->objects[0].index_count, 3 * 4);
        TL_CHECK(fabs(ccw_area(s, &s->objects[0]) - 2.0) < 1e-6);
        TL_CHECK_EQ_U(s->objects[1].index_count, 3 * 6);
        TL_CHECK(fabs(ccw_area(s, &s->objects[1]) - 3.0) < 1e-6);
        TL_CHECK_EQ_U(s->objects[2].index_count, 3 * 6);
        TL_CHECK(fabs(ccw_area(s, &s->objects[2]) - hexagon) < 1e-5);
    }
    tl_scene_destroy(s);
}

/* The undirected edges of a line object as a bit set over the square's 4 vertices (bit i*4+j). */
static unsigned edge_set(const tl_scene *s, const tl_object *o, const float (*pos)[3])
{
    unsigned set = 0;
    for (uint32_t k = 0; k + 1 < o->index_count; k += 2) {
        int e[2] = {-1, -1};
        for (int c = 0; c < 2; c++)
            for (int v = 0; v < 4; v++)
                if (!memcmp(s->vertices[s->indices[o->first_index + k + (uint32_t)c]].position, pos[v], sizeof pos[v]))
                    e[c] = v;
        if (e[0] < 0 || e[1] < 0) return 0;
        int a = e[0] < e[1] ? e[0] : e[1], b = e[0] < e[1] ? e[1] : e[0];
        set |= 1u << (a * 4 + b);
    }
    return set;
}

TL_TEST(gltf_points_and_lines_become_point_and_line_lists)
{
    static const float sq[4][3] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    static const uint32_t lines[] = {0, 1, 1, 2, 2, 3, 3, 0}, strip[] = {0, 1, 2, 3, 0}, loop[] = {0, 1, 2, 3};
    tlf_prim p[5] = {{.mode = 0, .pos = sq, .nv = 4, .material = -1},
                     {.mode = 1, .pos = sq, .nv = 4, .idx = lines, .ni = 8, .material = -1},
                     {.mode = 2, .pos = sq, .nv = 4, .idx = loop, .ni = 4, .material = -1},
                     {.mode = 3, .pos = sq, .nv = 4, .idx = strip, .ni = 5, .material = -1},
                     {.mode = 2, .pos = sq, .nv = 4, .material = -1}};
    capture log;
    tl_scene *s = load_prims("gltf_points_and_lines_become_point_and_line_lists", p, 5, "", "", &log);
    if (!s) return;
    TL_CHECK_EQ_U(log.warnings, 0);
    TL_CHECK_EQ_U(s->object_count, 5);
    const unsigned square = (1u << 1) | (1u << 6) | (1u << 11) | (1u << 3); /* 0-1, 1-2, 2-3, 0-3 */
    if (s->object_count == 5) {
        TL_CHECK_EQ_U(s->objects[0].primitive, TL_PRIMITIVE_POINTS);
        TL_CHECK_EQ_U(s->objects[0].index_count, 4);
        for (int k = 1; k < 5; k++) {
            TL_CHECK_EQ_U(s->objects[k].primitive, TL_PRIMITIVE_LINES);
            TL_CHECK_EQ_U(s->objects[k].index_count, 8);
            TL_CHECK_EQ_U(edge_set(s, &s->objects[k], sq), square);
        }
    }
    /* no NORMAL: zero normals, which the renderer turns to the viewer */
    for (size_t i = 0; i < s->vertex_count; i++) TL_CHECK(len3(s->vertices[i].normal) == 0.0f);
    tl_scene_destroy(s);
}

TL_TEST(gltf_color0_every_component_type_into_scene_colors)
{
    static const float tri[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    static const float rgba[3][4] = {{0.2f, 0.4f, 0.6f, 0.8f}, {1.0f, 0.0f, 0.5f, 0.25f}, {0.1f, 0.9f, 0.3f, 1.0f}};
    static const float rgb[3][4] = {{0.5f, 0.25f, 0.125f, 0}, {0.75f, 1.0f, 0.0f, 0}, {0.3f, 0.6f, 0.9f, 0}};
    tlf_prim p[4] = {{.pos = tri, .nv = 3, .color = rgb, .color_components = 3, .color_type = F32, .mode = -1, .material = -1},
                     {.pos = tri, .nv = 3, .color = rgba, .color_components = 4, .color_type = U8, .mode = -1, .material = -1},
                     {.pos = tri, .nv = 3, .color = rgba, .color_components = 4, .color_type = U16, .mode = -1, .material = -1},
                     {.pos = tri, .nv = 3, .mode = -1, .material = -1}};
    capture log;
    tl_scene *s = load_prims("gltf_color0_every_component_type_into_scene_colors", p, 4, "", "", &log);
    if (!s) return;
    TL_CHECK(s->colors != NULL && s->uv1 == NULL);
    TL_CHECK_EQ_U(s->object_count, 4);
    if (s->colors && s->object_count == 4) {
        const float tol[4] = {0.0f, 0.5f / 255.0f, 0.5f / 65535.0f, 0.0f};
        for (int k = 0; k < 4; k++)
            for (uint32_t j = 0; j < 3; j++) {
                uint32_t v = s->indices[s->objects[k].first_index + j];
                const float *c = s->colors + 4 * v;
                const float *want = k == 0 ? rgb[v - s->indices[s->objects[k].first_index]] : rgba[v - s->indices[s->objects[k].first_index]];
                for (int ch = 0; ch < 4; ch++) {
                    float w = k == 3 ? 1.0f : (k == 0 && ch == 3) ? 1.0f : want[ch]; /* no COLOR_0: white; RGB: alpha 1 */
                    TL_CHECK(fabsf(c[ch] - w) <= tol[k] + 1e-7f);
                }
            }
    }
    tl_scene_destroy(s);
}

static const char *const two_textures =
    "\"images\":[{\"uri\":\"t.png\"}],\"samplers\":[{}],\"textures\":[{\"source\":0,\"sampler\":0}]";

TL_TEST(gltf_texcoord1_into_scene_uv1_for_maps_that_read_it)
{
    static const uint8_t px[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    char dir[1024];
    case_dir(dir, sizeof dir, "gltf_texcoord1_into_scene_uv1_for_maps_that_read_it");
    TL_CHECK(write_png(dir, "t.png", 2, 2, px) == 0);
    static const float tri[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    static const float uv0[3][2] = {{0, 0}, {1, 0}, {0, 1}}, uv1[3][2] = {{0.25f, 0.75f}, {0.5f, 0.5f}, {0.75f, 0.25f}};
    tlf_prim p[2] = {{.pos = tri, .nv = 3, .uv0 = uv0, .uv1 = uv1, .mode = -1, .material = 0},
                     {.pos = tri, .nv = 3, .uv0 = uv0, .mode = -1, .material = 1}};
    const char *materials =
        "{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0,\"texCoord\":1}},"
        "\"normalTexture\":{\"index\":0,\"texCoord\":1},\"emissiveTexture\":{\"index\":0},\"emissiveFactor\":[1,1,1]},"
        "{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0,\"texCoord\":2}}}";
    capture log;
    tl_scene *s = load_prims("gltf_texcoord1_into_scene_uv1_for_maps_that_read_it", p, 2, materials, two_textures, &log);
    if (!s) return;
    TL_CHECK(strstr(log.warnings_text, "materials[1].baseColorTexture: texCoord 2 is read as TEXCOORD_0") != NULL);
    TL_CHECK(s->uv1 != NULL && s->colors == NULL);
    TL_CHECK_EQ_U(s->material_count, 2);
    TL_CHECK_EQ_U(s->object_count, 2);
    if (s->material_count == 2) {
        TL_CHECK_EQ_U(s->materials[0].uv1_maps, TL_MAP_ALBEDO | TL_MAP_NORMAL);
        TL_CHECK_EQ_U(s->materials[1].uv1_maps, 0);
    }
    if (s->uv1 && s->object_count == 2)
        for (int k = 0; k < 2; k++)
            for (uint32_t j = 0; j < 3; j++) {
                uint32_t v = s->indices[s->objects[k].first_index + j];
                const float *want = k == 0 ? uv1[j] : uv0[j]; /* without TEXCOORD_1: the first set */
                TL_CHECK(s->uv1[2 * v] == want[0] && s->uv1[2 * v + 1] == want[1]);
            }
    tl_scene_destroy(s);
    /* TEXCOORD_1 that no map reads is not kept */
    p[0].material = 1;
    s = load_prims("gltf_texcoord1_into_scene_uv1_for_maps_that_read_it", p, 1, materials, two_textures, &log);
    if (s) TL_CHECK(s->uv1 == NULL);
    tl_scene_destroy(s);
}
