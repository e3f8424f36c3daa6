/* Texture level of detail at a grazing angle: a large plane with a fine checkerboard (the scene's
 * own texture path: an sRGB RGBA8 tl_texture, mipmapped and sampled trilinearly by the renderer)
 * seen so that it is strongly minified towards the horizon, lit by ambient 1 alone, so that every
 * HDR value is the albedo texture as sampled. The reference is computed on the CPU in double: the
 * texture's level 0 as GL reconstructs it (each texel decoded from sRGB, bilinear, repeated)
 * integrated over each pixel's square by 32 x 32 stratified jittered rays intersected with the
 * plane, i.e. the box-filtered checkerboard. No renderer output is pasted anywhere.
 *
 * Three figures over the pixels wholly on the plane (lod_error): the mean absolute error, and the
 * two ways a level of detail goes wrong, as contrast about the texture's mean: contrast the
 * reference does not have (excess: too fine a level, aliasing) and contrast it has that the frame
 * lost (missing: too coarse a level, blur; isotropic trilinear filtering loses some at any grazing
 * angle, which is most of fat's error).
 *
 * What it holds (the modes of the list `lod_modes`, by registry name):
 *   - fat's error is at most half of the smaller error of two CPU renderings of a broken level of
 *     detail: level 0 at the pixel centre (LOD forced to 0) and the texture's mean everywhere (the
 *     last mip); both computed here and printed;
 *   - each mode's three figures are at most fat's x 1.10 + one 8-bit step (1/255: the thin modes
 *     store the albedo in 8 bits); no NaN or Inf in HDR.
 * Controls (fat, changing the renderer's own texture object through GL, found by its label): with
 * the mip chain cut to level 0 (GL_TEXTURE_MAX_LEVEL 0) fat's error exceeds its bound (and equals
 * the CPU's LOD-0 figure to 1e-4: the reference's rays are the renderer's); a LOD bias of +1
 * octave exceeds a mode's bound on missing contrast and -1 octave on excess contrast, so the case
 * fails when a mode's level of detail is off by one octave either way.
 * Measured (llvmpipe): fat 0.0450 (excess 0.0057, missing 0.0376), bound 0.0717; LOD 0 0.1435,
 * mean 0.2605; biases +1 / -1: missing 0.0975, excess 0.0310; every mode 0.0450. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl/gl.h"
#include "stability.h" /* camera_ray */

/* The modes held to fat's level of detail, by their registry names (tl_render_mode_from_name).
 * Adding a mode is one line here. */
static const char *const lod_modes[] = {
    "thin-lpp",
    "thin-deferred",
    "fat",
    "forward",
    "visibility",
};
#define LOD_MODE_COUNT (sizeof lod_modes / sizeof lod_modes[0])

#define W 320
#define H 180
#define TEX 256            /* texture side, texels */
#define CHECK 4            /* texels per check: 64 x 64 checks a texture */
#define PLANE_L 1000.0f    /* the plane: |x| <= L, -L <= z <= -PLANE_Z0, y = 0 */
#define PLANE_Z0 0.5f
#define UV_SCALE 0.125     /* uv per world unit: a check is 1 / (64 x 0.125) = 0.125 units */
#define UV_ANGLE_DEG 20.0  /* the checks are turned against the view, so neither axis is aligned */
#define EYE_Y 1.0f         /* the camera 1 unit above the plane, looking 8 degrees down */
#define PITCH_DEG 8.0
#define FOV_Y 1.0471976f   /* 60 degrees */
#define SUB 32             /* reference rays per pixel and axis */
#define LOD_LABEL "lod.checker"

/* One 8-bit step: the thin modes store the albedo in 8 bits (RT0 / RT1). */
#define STEP8 (1.0 / (double)TL_UNORM_MAX(8))
/* The modes' bound against fat's error. */
#define MODE_SLACK 1.10

static const double pi = 3.14159265358979323846;

typedef struct lod_scene {
    tl_vertex v[4];
    uint32_t idx[6];
    tl_object obj;
    tl_material mat;
    tl_texture tex;
    uint8_t rgba[TEX * TEX * 4];
    tl_scene s;
} lod_scene;

static void plane_uv(double x, double z, double uv[2])
{
    double a = UV_ANGLE_DEG * pi / 180.0, ca = cos(a), sa = sin(a);
    uv[0] = UV_SCALE * (ca * x - sa * z) + 0.37;
    uv[1] = UV_SCALE * (sa * x + ca * z) + 0.11;
}

static void lod_scene_build(lod_scene *m)
{
    memset(m, 0, sizeof *m);
    for (int j = 0; j < TEX; j++)
        for (int i = 0; i < TEX; i++) {
            uint8_t c = (((i / CHECK) + (j / CHECK)) & 1) ? 255 : 0;
            uint8_t *p = &m->rgba[4 * (j * TEX + i)];
            p[0] = p[1] = p[2] = c;
            p[3] = 255;
        }
    m->tex = (tl_texture){.width = TEX, .height = TEX, .rgba = m->rgba};
    snprintf(m->tex.name, sizeof m->tex.name, "%s", LOD_LABEL);
    /* albedo 1 x the texture, no specular, ambient 1, no light: HDR = the sampled texture */
    m->mat = (tl_material){.albedo = {1, 1, 1}, .alpha = 1, .albedo_map = TL_TEXTURE_MAP(0)};
    static const float corner[4][2] = {
        {-PLANE_L, -PLANE_Z0}, {PLANE_L, -PLANE_Z0}, {PLANE_L, -PLANE_L}, {-PLANE_L, -PLANE_L}};
    for (int i = 0; i < 4; i++) {
        double uv[2];
        plane_uv(corner[i][0], corner[i][1], uv);
        m->v[i] = (tl_vertex){.position = {corner[i][0], 0, corner[i][1]}, .normal = {0, 1, 0},
                              .uv = {(float)uv[0], (float)uv[1]}};
    }
    static const uint32_t q[6] = {0, 1, 2, 0, 2, 3}; /* counter-clockwise seen from +Y */
    memcpy(m->idx, q, sizeof q);
    m->obj = (tl_object){.index_count = 6}; /* identity transform, bounds computed */
    double t = tan(PITCH_DEG * pi / 180.0);
    m->s = (tl_scene){.vertices = m->v, .vertex_count = 4, .indices = m->idx, .index_count = 6, .objects = &m->obj,
                      .object_count = 1, .materials = &m->mat, .material_count = 1, .textures = &m->tex,
                      .texture_count = 1, .ambient = {1, 1, 1},
                      .camera = {{0, EYE_Y, 0}, {0, (float)(EYE_Y - t), -1}, {0, 1, 0}, FOV_Y, 0.1f, 5000.0f}};
}

/* ---- the CPU reference, in double ------------------------------------------------------------ */

static double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4); }

/* Level 0 at (u, v) as GL samples it with GL_LINEAR and GL_REPEAT: texels decoded from sRGB before
 * the bilinear weights (rows top to bottom, v downward, as the renderer uploads them). Grey: one
 * channel. */
static double texel_linear(const lod_scene *m, long i, long j)
{
    static double lut[256];
    static int ready;
    if (!ready) {
        for (int k = 0; k < 256; k++) lut[k] = srgb_to_linear(k / 255.0);
        ready = 1;
    }
    i = ((i % TEX) + TEX) % TEX;
    j = ((j % TEX) + TEX) % TEX;
    return lut[m->rgba[4 * (j * TEX + i)]];
}

static double sample_level0(const lod_scene *m, const double uv[2])
{
    double s = uv[0] * TEX - 0.5, t = uv[1] * TEX - 0.5, fs = floor(s), ft = floor(t), a = s - fs, b = t - ft;
    long i = (long)fs, j = (long)ft;
    return (1 - b) * ((1 - a) * texel_linear(m, i, j) + a * texel_linear(m, i + 1, j)) +
           b * ((1 - a) * texel_linear(m, i, j + 1) + a * texel_linear(m, i + 1, j + 1));
}

/* The plane point the ray through window position (x, y) (pixels, rows bottom-up) hits; 0 when it
 * misses the plane. */
static int ray_hit(const tl_camera *c, double x, double y, double p[3])
{
    double d[3];
    camera_ray(c, W, H, x, y, d);
    if (d[1] >= 0.0) return 0;
    double t = -(double)c->position[1] / d[1];
    for (int k = 0; k < 3; k++) p[k] = (double)c->position[k] + t * d[k];
    return fabs(p[0]) <= PLANE_L && p[2] <= -PLANE_Z0 && p[2] >= -PLANE_L;
}

typedef struct lod_reference {
    double *ref;     /* W x H box-filtered texture; < 0 where the pixel is not wholly on the plane */
    double *lod0;    /* level 0 at the pixel centre: what LOD forced to 0 samples */
    size_t covered;  /* pixels wholly on the plane */
    double noise;    /* mean over covered pixels of the reference's standard error (iid bound) */
    double mean;     /* the texture's mean, linear: what the last mip level holds */
} lod_reference;

static void lod_reference_make(const lod_scene *m, lod_reference *out)
{
    memset(out, 0, sizeof *out);
    out->ref = malloc((size_t)W * H * sizeof *out->ref);
    out->lod0 = malloc((size_t)W * H * sizeof *out->lod0);
    if (!out->ref || !out->lod0) return;
    const tl_camera *cam = &m->s.camera;
    double sum = 0.0;
    for (long j = 0; j < TEX; j++)
        for (long i = 0; i < TEX; i++) sum += texel_linear(m, i, j);
    out->mean = sum / (TEX * TEX);
    tl_rng rng = {0x10D0C4EC5ull};
    double noise = 0.0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t px = (size_t)y * W + x;
            double s1 = 0.0, s2 = 0.0, p[3], uv[2];
            int inside = 1;
            for (int b = 0; b < SUB && inside; b++)
                for (int a = 0; a < SUB && inside; a++) {
                    double fx = (a + tl_rng_unit(&rng)) / SUB, fy = (b + tl_rng_unit(&rng)) / SUB;
                    inside = ray_hit(cam, x + fx, y + fy, p);
                    if (!inside) break;
                    plane_uv(p[0], p[2], uv);
                    double v = sample_level0(m, uv);
                    s1 += v;
                    s2 += v * v;
                }
            out->ref[px] = out->lod0[px] = -1.0;
            if (!inside) continue;
            double n = (double)SUB * SUB, mu = s1 / n;
            out->ref[px] = mu;
            noise += sqrt(fmax(0.0, s2 / n - mu * mu) / n);
            ray_hit(cam, x + 0.5, y + 0.5, p);
            plane_uv(p[0], p[2], uv);
            out->lod0[px] = sample_level0(m, uv);
            out->covered++;
        }
    out->noise = out->covered ? noise / (double)out->covered : 0.0;
}

static void lod_reference_free(lod_reference *r)
{
    free(r->ref);
    free(r->lod0);
}

/* How far an image is from the reference over the covered pixels (RGB averaged), and the two
 * ways a level of detail goes wrong, measured as contrast about the texture's mean m: contrast the
 * reference does not have (too fine a level: aliasing) and contrast it has that the image lost (too
 * coarse a level: blur). Per pixel |g - r| >= excess + missing, so each is at most the error. */
typedef struct lod_error {
    double mae;     /* mean |g - r| */
    double excess;  /* mean max(0, |g - m| - |r - m|) */
    double missing; /* mean max(0, |r - m| - |g - m|) */
    double band[3]; /* mae over three bands of the covered rows, nearest first */
} lod_error;

/* `img`: HDR RGBA; or NULL with `grey` one value a pixel (W x H). */
static lod_error lod_error_of(const lod_reference *r, const float *img, const double *grey)
{
    lod_error e = {0};
    int top = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            if (r->ref[(size_t)y * W + x] >= 0.0) top = y + 1;
    double band_n[3] = {0};
    for (int y = 0; y < top; y++)
        for (int x = 0; x < W; x++) {
            size_t px = (size_t)y * W + x;
            double ref = r->ref[px];
            if (ref < 0.0) continue;
            for (int ch = 0; ch < 3; ch++) {
                double g = img ? (double)img[4 * px + ch] : grey[px], d = fabs(g - ref) / 3.0;
                double cg = fabs(g - r->mean), cr = fabs(ref - r->mean);
                e.mae += d;
                e.band[3 * y / top] += d;
                e.excess += fmax(0.0, cg - cr) / 3.0;
                e.missing += fmax(0.0, cr - cg) / 3.0;
            }
            band_n[3 * y / top]++;
        }
    double n = r->covered ? (double)r->covered : 1.0;
    e.mae /= n;
    e.excess /= n;
    e.missing /= n;
    for (int b = 0; b < 3; b++) e.band[b] = band_n[b] > 0 ? e.band[b] / band_n[b] : 0.0;
    return e;
}

static void lod_error_print(const char *what, const lod_error *e)
{
    printf("  %-40s error %.5f (near / middle / far rows %.5f / %.5f / %.5f), excess contrast %.5f, "
           "missing contrast %.5f\n", what, e->mae, e->band[0], e->band[1], e->band[2], e->excess, e->missing);
}

/* ---- rendering ----------------------------------------------------------------------------- */

static GLADapiproc lod_gl_load(void *user, const char *name)
{
    return (GLADapiproc)tl_context_get_proc_address((tl_context *)user, name);
}

/* The controls: sets `pname` on the renderer's own texture object(s) labelled LOD_LABEL (the sRGB
 * upload of the scene's texture), found by label; returns how many it changed. */
static int lod_texture_parameter(GLenum pname, float value)
{
    static GladGLContext gl;
    static int loaded;
    char msg[256];
    if (!loaded && tl__gl_load(&gl, lod_gl_load, g_ctx, msg, sizeof msg) != TL_OK) {
        fprintf(stderr, "glad: %s\n", msg);
        return 0;
    }
    loaded = 1;
    int changed = 0;
    for (GLuint id = 1; id < 4096; id++) {
        if (!gl.IsTexture(id)) continue;
        char label[64] = {0};
        GLsizei len = 0;
        gl.GetObjectLabel(GL_TEXTURE, id, (GLsizei)sizeof label, &len, label);
        if ((size_t)len != strlen(LOD_LABEL) || memcmp(label, LOD_LABEL, (size_t)len) != 0) continue;
        if (pname == GL_TEXTURE_MAX_LEVEL)
            gl.TextureParameteri(id, pname, (GLint)value);
        else
            gl.TextureParameterf(id, pname, value);
        changed++;
    }
    return changed;
}

/* The HDR target (W x H RGBA floats, rows bottom-up) of one frame of `s` in the mode named `name`;
 * with pname set, after that control on the texture. NULL (a failed check) when a step fails. */
static float *render_hdr(const tl_scene *s, const char *name, GLenum pname, float value)
{
    tl_render_mode mode;
    if (tl_render_mode_from_name(name, &mode) != TL_OK) {
        fprintf(stderr, "  mode \"%s\" is not in the registry\n", name);
        tl_test_failures++;
        return NULL;
    }
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = W, .height = H, .options = {.mode = mode, .fxaa = TL_FXAA_OFF}}, .scene = s,
        .readable = true});
    if (!r) return NULL;
    if (pname) TL_CHECK(lod_texture_parameter(pname, value) >= 1);
    tl_result res = tl_renderer_render(r, NULL, NULL);
    if (res != TL_OK) fprintf(stderr, "  %s: render: %s\n", name, tl_renderer_last_error(r));
    TL_CHECK(res == TL_OK);
    float *hdr = res == TL_OK ? tl_test_read_target(r, TL_TARGET_HDR, (size_t)W * H) : NULL;
    TL_CHECK(hdr != NULL);
    tl_renderer_destroy(r);
    if (hdr) {
        size_t bad = 0;
        for (size_t i = 0; i < (size_t)W * H * 4; i++) bad += !isfinite(hdr[i]);
        if (bad) fprintf(stderr, "  %s: %zu non-finite HDR values\n", name, bad);
        TL_CHECK_EQ_U(bad, 0);
    }
    return hdr;
}

/* fat's figures, its absolute bound and the modes' bounds. */
typedef struct lod_fat {
    lod_error fat, lod0, flat;
    double bound;                      /* on fat's error: half the smaller of lod0's and flat's */
    double mae_max, excess_max, missing_max; /* a mode's: fat's x MODE_SLACK + STEP8 */
} lod_fat;

static int lod_fat_measure(const lod_scene *m, const lod_reference *ref, lod_fat *out)
{
    float *fat = render_hdr(&m->s, "fat", 0, 0.0f);
    double *flat = malloc((size_t)W * H * sizeof *flat);
    TL_CHECK(flat != NULL);
    if (!fat || !flat) {
        free(fat);
        free(flat);
        return 0;
    }
    for (size_t px = 0; px < (size_t)W * H; px++) flat[px] = ref->mean;
    out->fat = lod_error_of(ref, fat, NULL);
    out->lod0 = lod_error_of(ref, NULL, ref->lod0);
    out->flat = lod_error_of(ref, NULL, flat);
    out->bound = 0.5 * fmin(out->lod0.mae, out->flat.mae);
    out->mae_max = out->fat.mae * MODE_SLACK + STEP8;
    out->excess_max = out->fat.excess * MODE_SLACK + STEP8;
    out->missing_max = out->fat.missing * MODE_SLACK + STEP8;
    printf("  reference: %zu of %d pixels wholly on the plane, %d x %d rays each, standard error %.5f (an iid "
           "bound); texture mean %.4f\n", ref->covered, W * H, SUB, SUB, ref->noise, ref->mean);
    lod_error_print("CPU, LOD forced to 0 (level 0, centre)", &out->lod0);
    lod_error_print("CPU, the texture's mean (the last mip)", &out->flat);
    lod_error_print("fat", &out->fat);
    printf("  fat's bound %.5f (half the smaller CPU error); a mode's: error %.5f, excess %.5f, missing %.5f "
           "(fat's x %.2f + 1/255)\n", out->bound, out->mae_max, out->excess_max, out->missing_max, MODE_SLACK);
    free(fat);
    free(flat);
    return 1;
}

/* fat within half of what a broken level of detail costs, and the controls on the renderer's own
 * texture: level 0 alone exceeds that bound; one octave of bias either way exceeds a mode's bound
 * on the contrast it adds or loses. */
TL_TEST(lod_minified_checkerboard_grazing_fat_against_box_filtered_reference)
{
    if (!ensure_context()) {
        tl_test_failures++;
        return;
    }
    static lod_scene m;
    lod_scene_build(&m);
    lod_reference ref;
    lod_reference_make(&m, &ref);
    TL_CHECK(ref.ref && ref.lod0);
    lod_fat f;
    if (ref.ref && ref.lod0 && lod_fat_measure(&m, &ref, &f)) {
        /* the plane fills most of the frame below the horizon, and the reference is precise enough
         * to judge fat: its standard error (an upper bound: the rays are stratified) a quarter of
         * fat's error at most */
        TL_CHECK(ref.covered > (size_t)W * H / 2);
        TL_CHECK_LE(ref.noise, 0.25 * f.fat.mae);
        TL_CHECK_LE(f.fat.mae, f.bound);
        enum { MAE_ABS, EXCESS, MISSING };
        static const struct {
            const char *what;
            GLenum pname;
            float value;
            int figure;
        } controls[] = {
            {"fat, GL_TEXTURE_MAX_LEVEL 0 (no mip chain)", GL_TEXTURE_MAX_LEVEL, 0.0f, MAE_ABS},
            {"fat, GL_TEXTURE_LOD_BIAS +1", GL_TEXTURE_LOD_BIAS, 1.0f, MISSING},
            {"fat, GL_TEXTURE_LOD_BIAS -1", GL_TEXTURE_LOD_BIAS, -1.0f, EXCESS},
        };
        for (size_t c = 0; c < sizeof controls / sizeof controls[0]; c++) {
            float *img = render_hdr(&m.s, "fat", controls[c].pname, controls[c].value);
            if (!img) continue;
            lod_error e = lod_error_of(&ref, img, NULL);
            lod_error_print(controls[c].what, &e);
            switch (controls[c].figure) {
            case MAE_ABS: /* fails fat's own bound, and is the CPU's LOD-0 frame: the same rays, up to
                           * the bilinear weights' 8-bit fraction (llvmpipe, and most GPUs) */
                TL_CHECK(e.mae > f.bound);
                TL_CHECK_LE(fabs(e.mae - f.lod0.mae), 0x1.0p-8);
                break;
            case EXCESS: TL_CHECK(e.excess > f.excess_max); break; /* fails a mode's bounds */
            default: TL_CHECK(e.missing > f.missing_max); break;
            }
            free(img);
        }
    }
    lod_reference_free(&ref);
}

/* Every mode of the list within fat's figures x 1.10 + one 8-bit step. */
TL_TEST(lod_minified_checkerboard_grazing_every_mode_within_fat)
{
    if (!ensure_context()) {
        tl_test_failures++;
        return;
    }
    static lod_scene m;
    lod_scene_build(&m);
    lod_reference ref;
    lod_reference_make(&m, &ref);
    TL_CHECK(ref.ref && ref.lod0);
    lod_fat f;
    if (ref.ref && ref.lod0 && lod_fat_measure(&m, &ref, &f)) {
        TL_CHECK_LE(f.fat.mae, f.bound);
        for (size_t i = 0; i < LOD_MODE_COUNT; i++) {
            float *img = render_hdr(&m.s, lod_modes[i], 0, 0.0f);
            if (!img) continue;
            lod_error e = lod_error_of(&ref, img, NULL);
            lod_error_print(lod_modes[i], &e);
            TL_CHECK_LE(e.mae, f.mae_max);
            TL_CHECK_LE(e.excess, f.excess_max);
            TL_CHECK_LE(e.missing, f.missing_max);
            free(img);
        }
    }
    lod_reference_free(&ref);
}
