/* One validation of cameras, textures and lights (issue 25; scene/validate.h, the tables of
 * docs/renderer-limits.md): what the renderer cannot draw is refused with the field named, and
 * what it falls back on is documented, warned about once and drawn. Each case renders the room
 * (render_room.h) at 64x64 and compares read-back images; the fallbacks are compared with the
 * camera they stand for, computed here from their documented rule. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_room.h"
#include "tl_test.h"

#define W 64
#define H 64

typedef struct seen {
    int errors, warnings;
    char error[512], warning[512];
} seen;

static void seen_log(void *user, tl_log_level level, const char *message)
{
    seen *s = (seen *)user;
    if (level == TL_LOG_ERROR) {
        s->errors++;
        snprintf(s->error, sizeof s->error, "%s", message);
    } else if (level == TL_LOG_WARNING) {
        s->warnings++;
        snprintf(s->warning, sizeof s->warning, "%s", message);
    }
}

static tl_renderer *renderer(seen *log, tl_depth_format depth)
{
    return tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = W, .height = H, .options = {.depth_format = depth, .fxaa = TL_FXAA_OFF}, .logger = {seen_log, log}}});
}

/* The room lit by an off-centre point light and a directional light, with some ambient. */
static void lit_room(test_scene *t)
{
    build_room(t);
    t->lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {4, 6, -3}, .color = {60, 50, 40}, .radius = 30};
    t->lights[1] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {-0.3f, -1, -0.2f},
                              .color = {0.6f, 0.6f, 0.7f}};
    t->s.light_count = 2;
    t->s.ambient[0] = t->s.ambient[1] = t->s.ambient[2] = 0.05f;
}

/* The output after one frame with `cam` (NULL: the scene's); malloc'd, NULL when the frame fails. */
static uint8_t *frame(tl_renderer *r, const tl_camera *cam)
{
    size_t size = (size_t)W * H * 4;
    uint8_t *px = malloc(size);
    if (!px) return NULL;
    if (tl_renderer_render(r, cam, NULL) != TL_OK || tl_renderer_read_output(r, px, &size) != TL_OK) {
        free(px);
        return NULL;
    }
    return px;
}

/* Pixels whose brightest channel is above 8 of 255. */
static double lit_fraction(const uint8_t *px)
{
    size_t lit = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        uint8_t m = px[4 * i] > px[4 * i + 1] ? px[4 * i] : px[4 * i + 1];
        lit += (m > px[4 * i + 2] ? m : px[4 * i + 2]) > 8;
    }
    return (double)lit / (double)(W * H);
}

/* Pixels with some channel more than `steps` apart. */
static size_t differ(const uint8_t *a, const uint8_t *b, int steps)
{
    size_t n = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        int d = 0;
        for (int k = 0; k < 3; k++) d |= abs((int)a[4 * i + k] - (int)b[4 * i + k]) > steps;
        n += (size_t)d;
    }
    return n;
}

static int same_image(const uint8_t *a, const uint8_t *b) { return a && b && memcmp(a, b, (size_t)W * H * 4) == 0; }

/* ---- cameras ------------------------------------------------------------------------------------ */

/* Every camera field the renderer cannot use is TL_ERROR_INVALID_ARGUMENT with the field named,
 * from render (a camera argument) and from set_scene (the scene's camera); the renderer keeps its
 * scene and draws the same frame afterwards. Before: fov_y = pi was "invalid camera (fov ...)",
 * near_z < 0 the default, far_z < 0 infinite, and position == target TL_OK with a black frame. */
TL_TEST(renderer_camera_fields_refused_naming_the_field)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    seen log = {0};
    tl_renderer *r = renderer(&log, TL_DEPTH_FORMAT_D24);
    if (!r) return;
    static test_scene t;
    lit_room(&t);
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
    uint8_t *before = frame(r, NULL);
    const tl_camera good = t.s.camera;
    const struct { const char *field; float value; const char *message; } cases[] = {
        {"fov_y", 3.14159265f, "camera.fov_y = 3.14159: outside (0, pi)"},
        {"fov_y", 3.1415925f, "camera.fov_y = 3.14159: outside (0, pi)"},
        {"fov_y", -1.0f, "camera.fov_y = -1: outside (0, pi)"},
        {"fov_y", NAN, "camera.fov_y = nan: outside (0, pi)"},
        {"fov_y", 1e-39f, "camera.fov_y = 1e-39: outside (0, pi)"},
        {"near_z", -1.0f, "camera.near_z = -1: not a finite distance > 0"},
        {"near_z", NAN, "camera.near_z = nan: not a finite distance > 0"},
        {"near_z", INFINITY, "camera.near_z = inf: not a finite distance > 0"},
        {"far_z", 0.1f, "camera.far_z = 0.1: not beyond near_z = 0.1"},
        {"far_z", 0.05f, "camera.far_z = 0.05: not beyond near_z = 0.1"},
        {"far_z", -1.0f, "camera.far_z = -1: not a distance"},
        {"far_z", NAN, "camera.far_z = nan: not a distance"},
        {"position", NAN, "camera.position = (nan, 3, 8): not finite"},
        {"target", INFINITY, "camera.target = (inf, 1.5, 0): not finite"},
        {"up", NAN, "camera.up = (nan, 1, 0): not finite"},
        {"target", 0.0f, "camera.target = (0, 3, 8): the position, no view direction"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        tl_camera c = good;
        c.near_z = 0.1f;
        if (strcmp(cases[i].field, "fov_y") == 0) c.fov_y = cases[i].value;
        if (strcmp(cases[i].field, "near_z") == 0) c.near_z = cases[i].value;
        if (strcmp(cases[i].field, "far_z") == 0) c.far_z = cases[i].value;
        if (strcmp(cases[i].field, "position") == 0) c.position[0] = cases[i].value;
        if (strcmp(cases[i].field, "up") == 0) c.up[0] = cases[i].value;
        if (strcmp(cases[i].field, "target") == 0 && cases[i].value != 0.0f) c.target[0] = cases[i].value;
        if (strcmp(cases[i].field, "target") == 0 && cases[i].value == 0.0f) memcpy(c.target, c.position, sizeof c.target);
        log.error[0] = 0;
        tl_result res = tl_renderer_render(r, &c, NULL);
        if (res != TL_ERROR_INVALID_ARGUMENT || !strstr(log.error, cases[i].message))
            fprintf(stderr, "  %s %g: got %s \"%s\", want \"%s\"\n", cases[i].field, (double)cases[i].value,
                    tl_result_string(res), log.error, cases[i].message);
        TL_CHECK(res == TL_ERROR_INVALID_ARGUMENT);
        TL_CHECK(strstr(log.error, cases[i].message) != NULL);
        TL_CHECK(strcmp(log.error, tl_renderer_last_error(r)) == 0);
        /* the same camera as the scene's: set_scene refuses it and keeps the room */
        test_scene bad = t;
        bad.s.vertices = bad.v, bad.s.indices = bad.idx, bad.s.objects = bad.obj, bad.s.materials = bad.mat;
        bad.s.lights = bad.lights;
        bad.s.camera = c;
        log.error[0] = 0;
        TL_CHECK(tl_renderer_set_scene(r, &bad.s) == TL_ERROR_INVALID_ARGUMENT);
        TL_CHECK(strstr(log.error, "scene.camera.") && strstr(log.error, cases[i].message + strlen("camera.")));
    }
    uint8_t *after = frame(r, NULL);
    TL_CHECK(same_image(before, after));
    TL_CHECK_EQ_U(log.warnings, 0);
    printf("  %zu cameras refused from render and from set_scene; the room's frame unchanged\n",
           sizeof cases / sizeof cases[0]);
    free(before);
    free(after);
    tl_renderer_destroy(r);
}

/* The near plane's floor (docs/renderer-limits.md): below 2^-24 of the distance from the eye to
 * the farthest corner of the objects' bounds D24 holds nothing of the scene, and near_z is raised
 * to 2^-16 of that distance with one warning (not one per frame); the frame is lit and is exactly
 * what a camera with that near plane draws. Before, near_z = 1e-30 was TL_OK with no word and a
 * black frame (far-plane depth everywhere). Reversed D32F holds n / z, but a triangle clipped at
 * such a near plane loses precision: near 1e-30 dropped a floor triangle in some frames (an unlit
 * wedge, frames a and b differing), so the floor is the same for both formats. Ten frames each. */
TL_TEST(renderer_camera_tiny_near_raised_once_with_warning)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    static test_scene t;
    lit_room(&t);
    t.s.ambient[0] = t.s.ambient[1] = t.s.ambient[2] = 0.0f; /* only the lights: no light is black */
    const tl_camera *c = &t.s.camera;
    /* the room [-10,10] x [0,10] x [-10,10]: its farthest corner from (0, 3, 8) */
    double far_corner = sqrt(10.0 * 10.0 + 7.0 * 7.0 + 18.0 * 18.0);
    float floor_z = (float)ldexp(far_corner, -16);
    tl_camera tiny = *c, floored = *c;
    tiny.near_z = 1e-30f;
    floored.near_z = floor_z;
    for (int f = 0; f < 2; f++) {
        tl_depth_format depth = f ? TL_DEPTH_FORMAT_D32F_REVERSED : TL_DEPTH_FORMAT_D24;
        seen log = {0};
        tl_renderer *r = renderer(&log, depth);
        if (!r) continue;
        TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
        uint8_t *a = frame(r, &tiny), *b = frame(r, &tiny), *ref = frame(r, &floored);
        TL_CHECK(a && b && ref);
        if (!a || !b || !ref) {
            free(a), free(b), free(ref);
            tl_renderer_destroy(r);
            continue;
        }
        printf("  %s: near 1e-30 lit %.3f of the pixels, %d warning(s): \"%s\"\n", f ? "reversed D32F" : "D24",
               lit_fraction(a), log.warnings, log.warning);
        TL_CHECK(lit_fraction(a) > 0.5);
        TL_CHECK_EQ_U(log.warnings, 1);
        TL_CHECK(strstr(log.warning, f ? "camera.near_z = 1e-30: below 2^-24 of the distance to the scene's farthest "
                                         "point (21.7486), where clipping at the near plane loses triangles"
                                       : "camera.near_z = 1e-30: below 2^-24 of the distance to the scene's farthest "
                                         "point (21.7486), where D24 depth holds nothing of the scene") != NULL);
        TL_CHECK(same_image(a, ref)); /* the documented fallback, exactly */
        TL_CHECK(same_image(a, b));
        for (int k = 0; k < 8; k++) { /* every frame the same: no triangle lost now and then */
            uint8_t *again = frame(r, &tiny);
            TL_CHECK(same_image(a, again));
            free(again);
        }
        /* the scene's own camera: the warning comes with set_scene, once */
        if (depth == TL_DEPTH_FORMAT_D24) {
            test_scene u = t;
            u.s.vertices = u.v, u.s.indices = u.idx, u.s.objects = u.obj, u.s.materials = u.mat, u.s.lights = u.lights;
            u.s.camera = tiny;
            log.warnings = 0;
            TL_CHECK(tl_renderer_set_scene(r, &u.s) == TL_OK);
            TL_CHECK_EQ_U(log.warnings, 1);
            uint8_t *d = frame(r, NULL), *e = frame(r, NULL);
            TL_CHECK_EQ_U(log.warnings, 1);
            TL_CHECK(same_image(d, ref) && same_image(e, ref));
            free(d), free(e);
        }
        TL_CHECK_EQ_U(log.errors, 0);
        free(a), free(b), free(ref);
        tl_renderer_destroy(r);
    }
}

/* Up parallel to the view: looking straight down (and up) along the up vector is defined as the
 * limit of views tilted towards -Z, so the frame is lit (before: black) and equals a view whose
 * target is 1 mm towards -Z, 9 m away (1.1e-4 rad, 0.007 pixels here), up to a pixel on an edge;
 * tilted the other way the image turns round. */
TL_TEST(renderer_camera_straight_down_and_up_is_the_limit_of_tilted_views)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    seen log = {0};
    tl_renderer *r = renderer(&log, TL_DEPTH_FORMAT_D24);
    if (!r) return;
    static test_scene t;
    lit_room(&t);
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
    const struct { const char *what; float eye[3], target[3], up[3]; } views[] = {
        {"straight down", {0.5f, 9.5f, 0.5f}, {0.5f, 0.0f, 0.5f}, {0, 1, 0}},
        {"straight up", {0.5f, 0.5f, 0.5f}, {0.5f, 9.5f, 0.5f}, {0, 1, 0}},
        {"straight down, up -Y", {0.5f, 9.5f, 0.5f}, {0.5f, 0.0f, 0.5f}, {0, -3, 0}},
    };
    for (size_t i = 0; i < sizeof views / sizeof views[0]; i++) {
        tl_camera c = {.fov_y = 1.2f, .near_z = 0.1f, .far_z = 100.0f};
        memcpy(c.position, views[i].eye, sizeof c.position);
        memcpy(c.target, views[i].target, sizeof c.target);
        memcpy(c.up, views[i].up, sizeof c.up);
        tl_camera near_view = c, other = c;
        near_view.target[2] -= 1e-3f; /* whichever way the view runs along up */
        other.target[2] += 1e-3f;
        uint8_t *a = frame(r, &c), *b = frame(r, &near_view), *o = frame(r, &other);
        TL_CHECK(a && b && o);
        if (a && b && o) {
            size_t close = differ(a, b, 8), turned = differ(a, o, 8);
            printf("  %s: lit %.3f; %zu pixels differ by > 8 steps from the view tilted 1.1e-4 rad towards -Z, "
                   "%zu from the opposite tilt\n", views[i].what, lit_fraction(a), close, turned);
            TL_CHECK(lit_fraction(a) > 0.5);
            TL_CHECK(close <= (size_t)(W * H / 100));
            TL_CHECK(turned > (size_t)(W * H / 10));
        }
        free(a), free(b), free(o);
    }
    TL_CHECK_EQ_U(log.errors + log.warnings, 0);
    tl_renderer_destroy(r);
}

/* ---- textures ------------------------------------------------------------------------------------ */

static int gl_max_texture_size(void)
{
    typedef void (*get_integerv_fn)(unsigned, int *);
    get_integerv_fn get = (get_integerv_fn)tl_context_proc_loader(g_ctx, "glGetIntegerv");
    int v = 0;
    if (get) get(0x0D33 /* GL_MAX_TEXTURE_SIZE */, &v);
    return v;
}

/* Textures the renderer cannot upload and texture indices past the scene's textures are refused by
 * set_scene, naming the field, and the renderer keeps its scene; before, each drew the material
 * untextured with TL_OK. A texture exactly GL_MAX_TEXTURE_SIZE wide is taken and drawn. */
TL_TEST(renderer_set_scene_bad_textures_refused_naming_them)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    seen log = {0};
    tl_renderer *r = renderer(&log, TL_DEPTH_FORMAT_D24);
    if (!r) return;
    uint32_t max = (uint32_t)gl_max_texture_size();
    uint8_t *px = calloc((size_t)(max + 1) * 4, 1);
    static test_scene t;
    lit_room(&t);
    TL_CHECK(px && max >= 16384);
    if (!px) return;
    for (uint32_t i = 0; i <= max; i++) px[4 * i] = px[4 * i + 3] = 255; /* red */
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
    uint8_t *before = frame(r, NULL);
    tl_texture tex[2] = {{4, 1, px, "four"}, {max, 1, px, "widest"}};
    char widest[96];
    snprintf(widest, sizeof widest, "textures[1].width = %u: over the largest texture side, %u", max + 1, max);
    const struct { int what; tl_result want; const char *message; } cases[] = {
        {0, TL_ERROR_INVALID_ARGUMENT, "textures[1].width = 0: outside 1.."},
        {1, TL_ERROR_INVALID_ARGUMENT, "textures[1].height = 0: outside 1.."},
        {2, TL_ERROR_INVALID_ARGUMENT, "textures[1].rgba = NULL: a "},
        {3, TL_ERROR_LIMIT, widest},
        {4, TL_ERROR_INVALID_ARGUMENT, "materials[1].occlusion_map = 3: texture 2, past the scene's 2 textures"},
        /* UINT32_MAX: what TL_NO_TEXTURE was before maps, in a program built against that header */
        {5, TL_ERROR_INVALID_ARGUMENT, "materials[0].albedo_map = 4294967295: texture 4294967294, past the scene's 2 "
                                       "textures (a map is a texture's index + 1, TL_TEXTURE_MAP; 0 for none)"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        test_scene u = t;
        u.s.vertices = u.v, u.s.indices = u.idx, u.s.objects = u.obj, u.s.materials = u.mat, u.s.lights = u.lights;
        tl_texture x[2] = {tex[0], tex[1]};
        u.s.textures = x;
        u.s.texture_count = 2;
        u.mat[1].albedo_map = TL_TEXTURE_MAP(1);
        if (cases[i].what == 0) x[1].width = 0;
        if (cases[i].what == 1) x[1].height = 0;
        if (cases[i].what == 2) x[1].rgba = NULL;
        if (cases[i].what == 3) x[1].width = max + 1;
        if (cases[i].what == 4) u.mat[1].occlusion_map = TL_TEXTURE_MAP(2);
        if (cases[i].what == 5) u.mat[0].albedo_map = UINT32_MAX;
        log.error[0] = 0;
        tl_result res = tl_renderer_set_scene(r, &u.s);
        if (res != cases[i].want || !strstr(log.error, cases[i].message))
            fprintf(stderr, "  case %d: got %s \"%s\", want \"%s\"\n", cases[i].what, tl_result_string(res), log.error,
                    cases[i].message);
        TL_CHECK(res == cases[i].want);
        TL_CHECK(strstr(log.error, cases[i].message) != NULL);
    }
    uint8_t *after = frame(r, NULL);
    TL_CHECK(same_image(before, after)); /* the room stayed */
    /* the widest texture GL takes, red on the box: drawn */
    test_scene u = t;
    u.s.vertices = u.v, u.s.indices = u.idx, u.s.objects = u.obj, u.s.materials = u.mat, u.s.lights = u.lights;
    u.s.textures = tex;
    u.s.texture_count = 2;
    u.mat[1].albedo_map = TL_TEXTURE_MAP(1);
    u.mat[1].albedo[0] = u.mat[1].albedo[1] = u.mat[1].albedo[2] = 1.0f;
    TL_CHECK(tl_renderer_set_scene(r, &u.s) == TL_OK);
    uint8_t *textured = frame(r, NULL);
    TL_CHECK(textured && !same_image(before, textured));
    printf("  6 bad textures and indices refused; a %ux1 texture drawn (%zu pixels changed)\n", max,
           textured ? differ(before, textured, 2) : 0);
    TL_CHECK_EQ_U(log.warnings, 0);
    free(before), free(after), free(textured), free(px);
    tl_renderer_destroy(r);
}

/* ---- lights --------------------------------------------------------------------------------------- */

/* A light the renderer cannot draw is refused by set_lights and set_scene, naming the field, and
 * the renderer keeps its lights; before, radius 0, equal cones and zero directions were TL_OK
 * (a black contribution, or a direction made up) and NaN fields "light 0 has a non-finite or
 * invalid field". */
TL_TEST(renderer_lights_refused_naming_the_field)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    seen log = {0};
    tl_renderer *r = renderer(&log, TL_DEPTH_FORMAT_D24);
    if (!r) return;
    static test_scene t;
    lit_room(&t);
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
    uint8_t *before = frame(r, NULL);
    const tl_light point = {.type = TL_LIGHT_POINT, .position = {0, 5, 0}, .color = {5, 5, 5}, .radius = 10};
    const tl_light spot = {.type = TL_LIGHT_SPOT, .position = {0, 5, 0}, .direction = {0, -1, 0},
                           .color = {5, 5, 5}, .radius = 10, .cos_inner = 0.9f, .cos_outer = 0.8f};
    const tl_light dir = {.type = TL_LIGHT_DIRECTIONAL, .direction = {0, -1, 0}, .color = {1, 1, 1}};
    const tl_light degrees = {.type = TL_LIGHT_SPOT, .position = {0, 5, 0}, .direction = {0, -1, 0},
                              .color = {5, 5, 5}, .radius = 10, .cos_inner = 30, .cos_outer = 20}; /* angles, not cosines */
    struct { tl_light l; const char *message; } cases[24];
    size_t n = 0;
#define CASE(base, field, value, text)                                                                  \
    do {                                                                                                \
        cases[n].l = base;                                                                              \
        cases[n].l.field = value;                                                                       \
        cases[n++].message = text;                                                                      \
    } while (0)
    CASE(point, radius, 0.0f, "lights[1].radius = 0: a point light needs a finite radius > 0");
    CASE(point, radius, -1.0f, "lights[1].radius = -1: a point light needs a finite radius > 0");
    CASE(point, radius, NAN, "lights[1].radius = nan: a point light needs a finite radius > 0");
    CASE(point, radius, INFINITY, "lights[1].radius = inf: a point light needs a finite radius > 0");
    CASE(spot, radius, 0.0f, "lights[1].radius = 0: a spot light needs a finite radius > 0");
    CASE(point, source_radius, -1.0f, "lights[1].source_radius = -1: not a finite radius >= 0");
    CASE(spot, cos_outer, 0.9f, "lights[1].cos_outer = 0.9: not below cos_inner = 0.9");
    CASE(spot, cos_outer, 0.95f, "lights[1].cos_outer = 0.95: not below cos_inner = 0.9");
    CASE(spot, direction[1], 0.0f, "lights[1].direction = (0, 0, 0): a spot light needs a direction");
    /* cones: cosines of half angles up to 90 degrees (degrees given as cosines, cones over 90
     * degrees and NaN were taken: 30 and 20 lit the whole floor) */
    CASE(degrees, cos_inner, 30.0f, "lights[1].cos_inner = 30: not a cosine (-1..1; the cone's half angles enter as their "
                                 "cosines, cos_inner = cos(inner angle))");
    CASE(spot, cos_outer, -0.5f, "lights[1].cos_outer = -0.5: a cone wider than 90 degrees (cos_outer >= 0, as glTF's "
                                 "outerConeAngle <= pi/2)");
    CASE(spot, cos_outer, -1.5f, "lights[1].cos_outer = -1.5: not a cosine (-1..1;");
    CASE(spot, cos_outer, NAN, "lights[1].cos_outer = nan: not a cosine (-1..1;");
    CASE(spot, cos_inner, NAN, "lights[1].cos_inner = nan: not a cosine (-1..1;");
    CASE(dir, direction[1], 0.0f, "lights[1].direction = (0, 0, 0): a directional light needs a direction");
    CASE(point, color[1], NAN, "lights[1].color = (5, nan, 5): not finite");
    CASE(point, position[2], INFINITY, "lights[1].position = (0, 5, inf): not finite");
    CASE(point, type, (tl_light_type)9, "lights[1].type = 9: not a tl_light_type");
    /* the specular scale: >= 0 or TL_LIGHT_SPECULAR_NONE (-1) */
    CASE(point, specular, -0.5f, "lights[1].specular = -0.5: not a finite scale >= 0 (0: 1) or TL_LIGHT_SPECULAR_NONE");
    CASE(spot, specular, NAN, "lights[1].specular = nan: not a finite scale >= 0 (0: 1) or TL_LIGHT_SPECULAR_NONE");
    CASE(dir, specular, INFINITY, "lights[1].specular = inf: not a finite scale >= 0 (0: 1) or TL_LIGHT_SPECULAR_NONE");
#undef CASE
    for (size_t i = 0; i < n; i++) {
        tl_light two[2] = {t.lights[0], cases[i].l};
        log.error[0] = 0;
        tl_result res = tl_renderer_set_lights(r, two, 2);
        if (res != TL_ERROR_INVALID_ARGUMENT || !strstr(log.error, cases[i].message))
            fprintf(stderr, "  got %s \"%s\", want \"%s\"\n", tl_result_string(res), log.error, cases[i].message);
        TL_CHECK(res == TL_ERROR_INVALID_ARGUMENT);
        TL_CHECK(strstr(log.error, cases[i].message) != NULL);
        test_scene u = t;
        u.s.vertices = u.v, u.s.indices = u.idx, u.s.objects = u.obj, u.s.materials = u.mat, u.s.lights = two;
        u.s.light_count = 2;
        log.error[0] = 0;
        TL_CHECK(tl_renderer_set_scene(r, &u.s) == TL_ERROR_INVALID_ARGUMENT && strstr(log.error, cases[i].message));
    }
    uint8_t *after = frame(r, NULL);
    TL_CHECK(same_image(before, after));
    printf("  %zu lights refused by set_lights and set_scene; the room's frame unchanged\n", n);
    /* a direction of any length is a direction: made unit */
    tl_light unit[2] = {t.lights[0], t.lights[1]}, scaled[2] = {t.lights[0], t.lights[1]};
    for (int k = 0; k < 3; k++) scaled[1].direction[k] *= 1e-20f;
    TL_CHECK(tl_renderer_set_lights(r, scaled, 2) == TL_OK);
    uint8_t *s1 = frame(r, NULL);
    TL_CHECK(tl_renderer_set_lights(r, unit, 2) == TL_OK);
    uint8_t *s2 = frame(r, NULL);
    TL_CHECK(s1 && s2 && differ(s1, s2, 1) == 0);
    TL_CHECK_EQ_U(log.warnings, 0);
    free(before), free(after), free(s1), free(s2);
    tl_renderer_destroy(r);
}
