/* What loads renders (issue 25): a glTF camera or texture that the renderer would refuse gets the
 * loader's documented fallback with one warning (docs/gltf.md), and the scene then goes through
 * tl_renderer_set_scene and a frame without an error or another warning; the fallback draws what
 * it stands for (the framing camera: the frame of the same file without a camera; the flat colour:
 * the frame without the texture). Files are made here, in memory: a quad with a data-URI buffer,
 * a camera node and a PNG made by gltf_hostile.h. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_hostile.h"
#include "render_room.h"
#include "thinlight/io.h"
#include "tl_test.h"

#define W 64
#define H 64
#define TL_GL45_TEST_MAX 16384u /* GL_MAX_TEXTURE_SIZE that GL 4.5 guarantees */

/* The quad [-1,1]^2 at z = 0 facing +Z: positions, normals, uvs (float), indices (uint16). */
static void quad_buffer(tlh_text *t)
{
    unsigned char b[140];
    const float p[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, n[12] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    const float uv[8] = {0, 1, 1, 1, 1, 0, 0, 0};
    const uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
    memcpy(b, p, 48);
    memcpy(b + 48, n, 48);
    memcpy(b + 96, uv, 32);
    memcpy(b + 128, idx, 12);
    tlh_put(t, "data:application/octet-stream;base64,");
    tlh_base64(t, b, sizeof b);
}

/* A glTF of the quad with a diffuse material; `camera` (JSON of one camera, NULL: none) on a node
 * at (0, 0, 4); `png` (NULL: none) as the base colour texture. */
static void quad_gltf(tlh_text *t, const char *camera, const unsigned char *png, size_t png_size)
{
    tlh_put(t, "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"buffers\":[{\"byteLength\":140,\"uri\":\"");
    quad_buffer(t);
    tlh_put(t, "\"}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":48},{\"buffer\":0,\"byteOffset\":48,\"byteLength\":48},"
               "{\"buffer\":0,\"byteOffset\":96,\"byteLength\":32},{\"buffer\":0,\"byteOffset\":128,\"byteLength\":12}],"
               "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\",\"min\":[-1,-1,0],"
               "\"max\":[1,1,0]},{\"bufferView\":1,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\"},"
               "{\"bufferView\":2,\"componentType\":5126,\"count\":4,\"type\":\"VEC2\"},"
               "{\"bufferView\":3,\"componentType\":5123,\"count\":6,\"type\":\"SCALAR\"}],"
               "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2},"
               "\"indices\":3,\"material\":0}]}],"
               "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.8,0.8,0.8,1],\"metallicFactor\":0,"
               "\"roughnessFactor\":0.6");
    if (png) tlh_put(t, ",\"baseColorTexture\":{\"index\":0}");
    tlh_put(t, "}}]");
    if (png) {
        tlh_put(t, ",\"textures\":[{\"source\":0}],\"images\":[{\"uri\":\"data:image/png;base64,");
        tlh_base64(t, png, png_size);
        tlh_put(t, "\"}]");
    }
    if (camera)
        tlh_printf(t, ",\"cameras\":[%s],\"nodes\":[{\"mesh\":0},{\"camera\":0,\"translation\":[0,0,4]}],"
                      "\"scenes\":[{\"nodes\":[0,1]}]}", camera);
    else
        tlh_put(t, ",\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}");
}

typedef struct loaded_scene {
    tl_scene *s;
    tlh_log log;
} loaded_scene;

static tl_result parse(const tlh_text *t, loaded_scene *l)
{
    memset(l, 0, sizeof *l);
    tl_gltf_options o = {.logger = TLH_LOGGER(&l->log)};
    if (!t->p) return TL_ERROR_OUT_OF_MEMORY;
    return tl_scene_parse_gltf(t->p, t->n, &o, &l->s);
}

typedef struct seen {
    int errors, warnings;
    char line[512];
} seen;

static void seen_log(void *user, tl_log_level level, const char *message)
{
    seen *s = (seen *)user;
    if (level == TL_LOG_INFO) return;
    s->errors += level == TL_LOG_ERROR;
    s->warnings += level == TL_LOG_WARNING;
    snprintf(s->line, sizeof s->line, "%s", message);
}

/* The scene through set_scene and one frame: its output (malloc'd) when neither says anything. */
static uint8_t *render_quietly(const tl_scene *s)
{
    seen log = {0};
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = W, .height = H, .logger = {seen_log, &log}}, .scene = s, .frames = 1});
    size_t size = (size_t)W * H * 4;
    uint8_t *px = malloc(size);
    int ok = px && r && tl_renderer_read_output(r, px, &size) == TL_OK;
    if (log.errors + log.warnings) fprintf(stderr, "  the renderer said: \"%s\"\n", log.line);
    TL_CHECK(ok);
    TL_CHECK_EQ_U(log.errors + log.warnings, 0);
    tl_renderer_destroy(r);
    if (!ok) {
        free(px);
        return NULL;
    }
    return px;
}

/* The sum of the output's RGB values: how much light the frame shows. */
static double brightness(const uint8_t *px)
{
    double sum = 0.0;
    for (size_t i = 0; px && i < (size_t)W * H; i++) sum += (double)px[4 * i] + px[4 * i + 1] + px[4 * i + 2];
    return sum;
}

static size_t lit_pixels(const uint8_t *px)
{
    size_t n = 0;
    for (size_t i = 0; px && i < (size_t)W * H; i++) n += px[4 * i] > 8 || px[4 * i + 1] > 8 || px[4 * i + 2] > 8;
    return n;
}

/* ---- cameras ------------------------------------------------------------------------------------ */

/* A camera the renderer would refuse is a warning naming the camera and the field, and the
 * framing camera: the same camera and the same frame as the file without a camera. Before, yfov =
 * 3.14159265 (below pi in double, pi in float) loaded without a word and set_scene refused it, and
 * zfar <= znear or < 0 gave an infinite far plane instead of the documented framing camera. */
TL_TEST(gltf_camera_the_renderer_refuses_is_the_framing_camera_with_a_warning)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tlh_text plain = {0};
    quad_gltf(&plain, NULL, NULL, 0);
    loaded_scene ref;
    TL_CHECK(parse(&plain, &ref) == TL_OK && ref.log.warnings == 0);
    uint8_t *framing = ref.s ? render_quietly(ref.s) : NULL;
    printf("  framing camera: %zu lit pixels\n", lit_pixels(framing));
    TL_CHECK(lit_pixels(framing) > W * H / 20);
    static const struct { const char *camera, *warning; } cases[] = {
        {"\"yfov\":3.141592653589793,\"znear\":0.1", "cameras[0]: camera.fov_y = 3.14159: outside (0, pi)"},
        {"\"yfov\":3.14159265,\"znear\":0.1", "cameras[0]: camera.fov_y = 3.14159: outside (0, pi)"},
        {"\"yfov\":1,\"znear\":0.5,\"zfar\":0.5", "cameras[0]: camera.far_z = 0.5: not beyond near_z = 0.5"},
        {"\"yfov\":1,\"znear\":0.5,\"zfar\":0.25", "cameras[0]: camera.far_z = 0.25: not beyond near_z = 0.5"},
        {"\"yfov\":1,\"znear\":0.5,\"zfar\":-5", "cameras[0]: camera.far_z = -5: not a distance"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0] && ref.s; i++) {
        char camera[128];
        snprintf(camera, sizeof camera, "{\"type\":\"perspective\",\"perspective\":{%s}}", cases[i].camera);
        tlh_text t = {0};
        quad_gltf(&t, camera, NULL, 0);
        loaded_scene l;
        TL_CHECK(parse(&t, &l) == TL_OK);
        if (l.log.warnings != 1 || !strstr(l.log.warnings_text, cases[i].warning))
            fprintf(stderr, "  %s: %d warning(s): \"%s\"\n", cases[i].camera, l.log.warnings, l.log.warnings_text);
        TL_CHECK(l.log.warnings == 1);
        TL_CHECK(strstr(l.log.warnings_text, cases[i].warning) != NULL);
        TL_CHECK(strstr(l.log.warnings_text, "; using a camera that frames the scene") != NULL);
        if (l.s) {
            TL_CHECK(memcmp(&l.s->camera, &ref.s->camera, sizeof l.s->camera) == 0);
            uint8_t *px = render_quietly(l.s);
            TL_CHECK(px && framing && memcmp(px, framing, (size_t)W * H * 4) == 0);
            free(px);
        }
        tl_scene_destroy(l.s);
        free(t.p);
    }
    printf("  %zu refused cameras: one warning each, the framing camera's frame\n", sizeof cases / sizeof cases[0]);
    free(framing);
    tl_scene_destroy(ref.s);
    free(plain.p);
}

/* znear = 1e-30, below the renderer's floor (2^-24 of the distance to the farthest corner of the
 * bounds, sqrt(18) from (0, 0, 4), with D24), is raised by the loader to 2^-16 of that distance
 * with one warning, so the renderer has nothing to add, and the quad is drawn lit (before: no word,
 * and an unlit silhouette: 15 % of the light of znear = 0.1). */
TL_TEST(gltf_camera_tiny_znear_raised_with_one_warning)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tlh_text t = {0}, u = {0};
    quad_gltf(&t, "{\"type\":\"perspective\",\"perspective\":{\"yfov\":1,\"znear\":1e-30}}", NULL, 0);
    quad_gltf(&u, "{\"type\":\"perspective\",\"perspective\":{\"yfov\":1,\"znear\":0.1}}", NULL, 0);
    loaded_scene l, ok;
    TL_CHECK(parse(&t, &l) == TL_OK && parse(&u, &ok) == TL_OK);
    if (!l.s || !ok.s) return;
    printf("  \"%s\"\n", l.log.warnings_text);
    TL_CHECK(l.log.warnings == 1);
    TL_CHECK(strstr(l.log.warnings_text, "cameras[0]: camera.near_z = 1e-30: below 2^-24 of the distance to the "
                                         "scene's farthest point (4.24264)") != NULL);
    TL_CHECK(l.s->camera.near_z == (float)ldexp(sqrt(18.0), -16));
    uint8_t *a = render_quietly(l.s), *b = render_quietly(ok.s);
    printf("  lit pixels: %zu with znear 1e-30 raised, %zu with znear 0.1; brightness %.0f and %.0f\n", lit_pixels(a),
           lit_pixels(b), brightness(a), brightness(b));
    TL_CHECK(lit_pixels(b) > W * H / 10);
    TL_CHECK(lit_pixels(a) * 4 >= lit_pixels(b) * 3);
    TL_CHECK(brightness(a) >= 0.95 * brightness(b));
    free(a), free(b);
    tl_scene_destroy(l.s), tl_scene_destroy(ok.s);
    free(t.p), free(u.p);
}

/* ---- textures ---------------------------------------------------------------------------------- */

/* An image wider than 16384 (GL_MAX_TEXTURE_SIZE that every GL 4.5 context has, the renderer's own
 * check) is a warning naming the image, and the flat colour: the frame of the file without the
 * texture. Before, it loaded (the loader allowed 65536) and the renderer dropped it without a
 * word. An image 16384 wide loads and is drawn. */
TL_TEST(gltf_texture_over_16384_is_the_flat_colour_with_a_warning)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    const uint32_t wide = TL_GL45_TEST_MAX + 1;
    uint8_t *rgba = malloc((size_t)wide * 4);
    if (!rgba) return;
    for (size_t i = 0; i < wide; i++) rgba[4 * i] = 255, rgba[4 * i + 1] = 40, rgba[4 * i + 2] = 40, rgba[4 * i + 3] = 255;
    tlh_text flat = {0};
    quad_gltf(&flat, NULL, NULL, 0);
    loaded_scene ref;
    TL_CHECK(parse(&flat, &ref) == TL_OK);
    uint8_t *untextured = ref.s ? render_quietly(ref.s) : NULL;
    for (uint32_t w = wide - 1; w <= wide; w++) {
        size_t png_size = 0;
        unsigned char *png = tlh_png(w, 1, rgba, &png_size);
        tlh_text t = {0};
        quad_gltf(&t, NULL, png, png_size);
        loaded_scene l;
        TL_CHECK(png && parse(&t, &l) == TL_OK);
        if (l.s) {
            uint8_t *px = render_quietly(l.s);
            int same = px && untextured && memcmp(px, untextured, (size_t)W * H * 4) == 0;
            printf("  %ux1: %zu texture(s), %d warning(s) \"%s\"; %s the untextured frame\n", w, l.s->texture_count,
                   l.log.warnings, l.log.warnings_text, same ? "same as" : "differs from");
            if (w == wide) {
                TL_CHECK(l.log.warnings == 1);
                TL_CHECK(strstr(l.log.warnings_text, "images[0].width = 16385: over the largest texture side, 16384 "
                                                     "(GL_MAX_TEXTURE_SIZE); using the flat colour") != NULL);
                TL_CHECK(l.s->texture_count == 0 && l.s->materials[0].albedo_map == 0);
                TL_CHECK(same);
            } else {
                TL_CHECK(l.log.warnings == 0 && l.s->texture_count == 1);
                TL_CHECK(px && !same);
            }
            free(px);
        }
        tl_scene_destroy(l.s);
        free(png);
        free(t.p);
    }
    free(untextured);
    tl_scene_destroy(ref.s);
    free(flat.p);
    free(rgba);
}

/* ---- spot cones ----------------------------------------------------------------------------------- */

/* The quad lit by one KHR_lights_punctual spot at (0, 0, 2) looking down -Z onto it; `spot` is the
 * JSON inside its "spot" object. */
static void spot_gltf(tlh_text *t, const char *spot)
{
    quad_gltf(t, NULL, NULL, 0);
    const char *tail = ",\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}";
    size_t n = strlen(tail);
    if (!t->p || t->n < n || strcmp(t->p + t->n - n, tail) != 0) {
        free(t->p);
        t->p = NULL;
        return;
    }
    t->n -= n;
    t->p[t->n] = '\0';
    tlh_printf(t, ",\"extensionsUsed\":[\"KHR_lights_punctual\"],\"extensions\":{\"KHR_lights_punctual\":{\"lights\":"
                  "[{\"type\":\"spot\",\"intensity\":40,\"range\":10,\"spot\":{%s}}]}},\"nodes\":[{\"mesh\":0},"
                  "{\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}},\"translation\":[0,0,2]}],"
                  "\"scenes\":[{\"nodes\":[0,1]}]}", spot);
}

/* Cone angles outside glTF's 0 <= inner < outer <= pi/2 are clamped as docs/gltf.md says, each with
 * one warning naming the field, its value and the clamp, and the scene then renders without a word
 * from the renderer; pi/2 itself (90 degrees, the widest cone) loads as it is. Before: "cone angles
 * outside 0 <= inner < outer <= pi/2; clamped", naming neither the angle nor the value. */
TL_TEST(gltf_spot_cone_angles_clamped_naming_the_field)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    const double half_pi = 1.5707963267948966;
    static const struct {
        const char *spot, *warning;
        double inner, outer; /* the angles the light gets */
    } cases[] = {
        {"\"innerConeAngle\":0.3,\"outerConeAngle\":2",
         "KHR_lights_punctual.lights[0].spot.outerConeAngle = 2: outside (0, pi/2]; clamped to 1.5708", 0.3, 1.5707963267948966},
        {"\"innerConeAngle\":0.7,\"outerConeAngle\":0.5",
         "KHR_lights_punctual.lights[0].spot.innerConeAngle = 0.7: outside [0, outerConeAngle = 0.5); clamped to 0.4995",
         0.4995, 0.5},
        {"\"outerConeAngle\":-1", "KHR_lights_punctual.lights[0].spot.outerConeAngle = -1: outside (0, pi/2]; clamped to 0.001",
         0.0, 0.001},
        {"\"innerConeAngle\":0,\"outerConeAngle\":1.5707963267948966", NULL, 0.0, 1.5707963267948966},
    };
    size_t named = 0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        tlh_text t = {0};
        spot_gltf(&t, cases[i].spot);
        loaded_scene l;
        TL_CHECK(t.p && parse(&t, &l) == TL_OK);
        const tl_light *s = l.s && l.s->light_count == 1 ? &l.s->lights[0] : NULL;
        TL_CHECK(s && s->type == TL_LIGHT_SPOT);
        int warned = cases[i].warning ? l.log.warnings == 1 && strstr(l.log.warnings_text, cases[i].warning) != NULL
                                      : l.log.warnings == 0;
        if (!warned) fprintf(stderr, "  %s: %d warning(s) \"%s\"\n", cases[i].spot, l.log.warnings, l.log.warnings_text);
        named += (size_t)warned;
        if (s) {
            printf("  %s: cos_inner %.7g, cos_outer %.7g; \"%s\"\n", cases[i].spot, (double)s->cos_inner,
                   (double)s->cos_outer, l.log.warnings_text);
            TL_CHECK(s->cos_inner == (float)cos(cases[i].inner) && s->cos_outer == (float)cos(cases[i].outer));
            TL_CHECK(s->cos_outer >= 0.0f && s->cos_outer < s->cos_inner);
            uint8_t *px = render_quietly(l.s);
            TL_CHECK(lit_pixels(px) > 0 || cases[i].outer < 0.01);
            if (cases[i].outer == half_pi) TL_CHECK(lit_pixels(px) > W * H / 20); /* the quad lit whole */
            free(px);
        }
        tl_scene_destroy(l.s);
        free(t.p);
    }
    TL_CHECK_EQ_U(named, sizeof cases / sizeof cases[0]);
}
