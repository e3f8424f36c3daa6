/* Image-based light on the CPU (ibl_bake.h): SH projection, the pyramid, the prefiltered chain and
 * the split-sum table. Done once per tl_renderer_set_environment, in double where it sums. */
#include "ibl_bake.h"

#include <math.h>
#include <string.h>

#include "thinlight/codec.h"

#define TL__PI 3.14159265358979323846

void tl__ibl_direction(double u, double v, double d[3])
{
    double phi = 2.0 * TL__PI * (u - 0.5), theta = TL__PI * v;
    d[0] = sin(theta) * cos(phi);
    d[1] = cos(theta);
    d[2] = sin(theta) * sin(phi);
}

static void tl__ibl_uv(const double d[3], double *u, double *v)
{
    double r = sqrt(d[0] * d[0] + d[2] * d[2]);
    *u = r > 0.0 ? atan2(d[2], d[0]) / (2.0 * TL__PI) + 0.5 : 0.5;
    *v = atan2(r, d[1]) / TL__PI;
}

void tl__ibl_sh_basis(const double d[3], double y[9])
{
    double x = d[0], yy = d[1], z = d[2];
    y[0] = 0.282094791773878;
    y[1] = 0.488602511902920 * yy;
    y[2] = 0.488602511902920 * z;
    y[3] = 0.488602511902920 * x;
    y[4] = 1.092548430592079 * x * yy;
    y[5] = 1.092548430592079 * yy * z;
    y[6] = 0.315391565252520 * (3.0 * z * z - 1.0);
    y[7] = 1.092548430592079 * x * z;
    y[8] = 0.546274215296040 * (x * x - yy * yy);
}

void tl__ibl_sh9(const float *rgb, uint32_t w, uint32_t h, double sh[9][3])
{
    memset(sh, 0, 9 * sizeof sh[0]);
    for (uint32_t j = 0; j < h; j++) {
        double v = (j + 0.5) / h, dw = (2.0 * TL__PI / w) * (TL__PI / h) * sin(TL__PI * v);
        for (uint32_t i = 0; i < w; i++) {
            double d[3], y[9];
            tl__ibl_direction((i + 0.5) / w, v, d);
            tl__ibl_sh_basis(d, y);
            const float *c = rgb + ((size_t)j * w + i) * 3;
            for (int k = 0; k < 9; k++)
                for (int ch = 0; ch < 3; ch++) sh[k][ch] += c[ch] * y[k] * dw;
        }
    }
}

void tl__ibl_sh_diffuse(double sh[9][3], float out[9][4])
{
    static const double band[9] = {1.0, 2.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0, 0.25, 0.25, 0.25, 0.25, 0.25};
    for (int k = 0; k < 9; k++) {
        for (int ch = 0; ch < 3; ch++) out[k][ch] = (float)(sh[k][ch] * band[k]); /* A_l / pi */
        out[k][3] = 0.0f;
    }
}

/* ---- the pyramid ------------------------------------------------------------------------------ */

size_t tl__ibl_pyramid_floats(uint32_t w, uint32_t h)
{
    size_t n = 0;
    while (w > 1 || h > 1) {
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
        n += (size_t)w * h * 3;
    }
    return n;
}

static void tl__ibl_downsample(const float *src, uint32_t sw, uint32_t sh, float *dst, uint32_t dw, uint32_t dh)
{
    for (uint32_t y = 0; y < dh; y++)
        for (uint32_t x = 0; x < dw; x++)
            for (int c = 0; c < 3; c++) {
                uint32_t x0 = x * 2 < sw ? x * 2 : sw - 1, x1 = x * 2 + 1 < sw ? x * 2 + 1 : x0;
                uint32_t y0 = y * 2 < sh ? y * 2 : sh - 1, y1 = y * 2 + 1 < sh ? y * 2 + 1 : y0;
                dst[((size_t)y * dw + x) * 3 + c] =
                    0.25f * (src[((size_t)y0 * sw + x0) * 3 + c] + src[((size_t)y0 * sw + x1) * 3 + c] +
                             src[((size_t)y1 * sw + x0) * 3 + c] + src[((size_t)y1 * sw + x1) * 3 + c]);
            }
}

void tl__ibl_pyramid_build(const float *rgb, uint32_t w, uint32_t h, float *store, tl__ibl_pyramid *p)
{
    memset(p, 0, sizeof *p);
    p->store = store;
    p->w[0] = w;
    p->h[0] = h;
    p->px[0] = rgb;
    p->levels = 1;
    float *next = store;
    while ((w > 1 || h > 1) && p->levels < 16) {
        uint32_t nw = w > 1 ? w / 2 : 1, nh = h > 1 ? h / 2 : 1;
        tl__ibl_downsample(p->px[p->levels - 1], w, h, next, nw, nh);
        p->w[p->levels] = w = nw;
        p->h[p->levels] = h = nh;
        p->px[p->levels++] = next;
        next += (size_t)nw * nh * 3;
    }
}

static void tl__ibl_bilinear(const tl__ibl_pyramid *p, uint32_t l, double u, double v, double out[3])
{
    uint32_t w = p->w[l], h = p->h[l];
    double x = u * w - 0.5, y = v * h - 0.5, fx = floor(x), fy = floor(y);
    double ax = x - fx, ay = y - fy;
    long x0 = ((long)fx % (long)w + (long)w) % (long)w, x1 = (x0 + 1) % (long)w;
    long y0 = fy < 0 ? 0 : (long)fy, y1 = y0 + 1;
    if (y0 > (long)h - 1) y0 = (long)h - 1;
    if (y1 > (long)h - 1) y1 = (long)h - 1;
    if (fy < 0) ay = 0.0;
    const float *a = p->px[l] + ((size_t)y0 * w + (size_t)x0) * 3, *b = p->px[l] + ((size_t)y0 * w + (size_t)x1) * 3;
    const float *c = p->px[l] + ((size_t)y1 * w + (size_t)x0) * 3, *e = p->px[l] + ((size_t)y1 * w + (size_t)x1) * 3;
    for (int k = 0; k < 3; k++)
        out[k] = (1.0 - ay) * ((1.0 - ax) * a[k] + ax * b[k]) + ay * ((1.0 - ax) * c[k] + ax * e[k]);
}

void tl__ibl_pyramid_sample(const tl__ibl_pyramid *p, const double d[3], double lod, double out[3])
{
    double u, v, a[3], b[3];
    tl__ibl_uv(d, &u, &v);
    double top = (double)(p->levels - 1);
    lod = lod < 0.0 ? 0.0 : lod > top ? top : lod;
    uint32_t l0 = (uint32_t)lod, l1 = l0 + 1 < p->levels ? l0 + 1 : l0;
    double t = lod - l0;
    tl__ibl_bilinear(p, l0, u, v, a);
    tl__ibl_bilinear(p, l1, u, v, b);
    for (int k = 0; k < 3; k++) out[k] = a[k] + t * (b[k] - a[k]);
}

/* ---- GGX sampling ---------------------------------------------------------------------------- */

static double tl__radical_inverse(uint32_t i)
{
    i = (i << 16) | (i >> 16);
    i = ((i & 0x55555555u) << 1) | ((i & 0xAAAAAAAAu) >> 1);
    i = ((i & 0x33333333u) << 2) | ((i & 0xCCCCCCCCu) >> 2);
    i = ((i & 0x0F0F0F0Fu) << 4) | ((i & 0xF0F0F0F0u) >> 4);
    i = ((i & 0x00FF00FFu) << 8) | ((i & 0xFF00FF00u) >> 8);
    return i * 2.3283064365386963e-10;
}

/* An orthonormal basis t, b around unit n (Duff et al. 2017). */
static void tl__basis(const double n[3], double t[3], double b[3])
{
    double s = n[2] >= 0.0 ? 1.0 : -1.0, a = -1.0 / (s + n[2]), c = n[0] * n[1] * a;
    t[0] = 1.0 + s * n[0] * n[0] * a;
    t[1] = s * c;
    t[2] = -s * n[0];
    b[0] = c;
    b[1] = s + n[1] * n[1] * a;
    b[2] = -n[1];
}

/* The i-th of n GGX half vectors around n (Hammersley), and its cosine to n. */
static double tl__ggx_half(uint32_t i, uint32_t n, double alpha, const double nrm[3], const double t[3],
                           const double b[3], double h[3])
{
    double e1 = (i + 0.5) / n, e2 = tl__radical_inverse(i);
    double phi = 2.0 * TL__PI * e1, a2 = alpha * alpha;
    double ct = sqrt((1.0 - e2) / (1.0 + (a2 - 1.0) * e2)), st = sqrt(1.0 - ct * ct);
    for (int k = 0; k < 3; k++) h[k] = st * cos(phi) * t[k] + st * sin(phi) * b[k] + ct * nrm[k];
    return ct;
}

static double tl__ggx_d(double nh, double alpha)
{
    double a2 = alpha * alpha, x = nh * nh * (a2 - 1.0) + 1.0;
    return a2 / (TL__PI * x * x);
}

static double tl__level_alpha(uint32_t level)
{
    return tl_gloss_to_ggx_alpha(1.0f - (float)level / (float)(TL__IBL_LEVELS - 1));
}

/* 512 whatever the image: the last level (roughness 1) is then 8 x 4 texels; at 4 x 2 (level 0 at
 * 256) rough gold's mean error against the Monte Carlo reference was 4.4 % instead of 2.8 %. */
uint32_t tl__ibl_base_width(uint32_t w)
{
    (void)w;
    return 512;
}

#define TL__LOBE_MAX 512

/* A level's samples around +Z, the same for every texel (n = v = r): each the direction l in the
 * lobe's frame, its n.l in l[2], and the pyramid level matching its solid angle 1 / (N pdf). */
typedef struct tl__lobe {
    uint32_t count;
    double l[TL__LOBE_MAX][4];
} tl__lobe;

static void tl__lobe_make(double alpha, uint32_t samples, double texel, tl__lobe *lobe)
{
    const double z[3] = {0, 0, 1}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0};
    lobe->count = 0;
    for (uint32_t i = 0; i < samples && i < TL__LOBE_MAX; i++) {
        double h[3], nh = tl__ggx_half(i, samples, alpha, z, x, y, h);
        double *l = lobe->l[lobe->count];
        for (int k = 0; k < 3; k++) l[k] = 2.0 * nh * h[k] - z[k];
        if (l[2] <= 0.0) continue;
        double pdf = tl__ggx_d(nh, alpha) * 0.25; /* D n.h / (4 v.h), v = n */
        l[3] = 0.5 * log2(1.0 / (samples * pdf * texel)) + 1.0;
        lobe->count++;
    }
}

/* One texel of a level: the lobe around r, n.l-weighted (Karis 2013). */
static void tl__prefilter_texel(const tl__ibl_pyramid *p, const tl__lobe *lobe, const double r[3], double out[3])
{
    double t[3], b[3], sum[3] = {0, 0, 0}, wsum = 0.0;
    tl__basis(r, t, b);
    for (uint32_t i = 0; i < lobe->count; i++) {
        const double *l = lobe->l[i];
        double d[3], c[3];
        for (int k = 0; k < 3; k++) d[k] = l[0] * t[k] + l[1] * b[k] + l[2] * r[k];
        tl__ibl_pyramid_sample(p, d, l[3], c);
        for (int k = 0; k < 3; k++) sum[k] += c[k] * l[2];
        wsum += l[2];
    }
    for (int k = 0; k < 3; k++) out[k] = wsum > 0.0 ? sum[k] / wsum : 0.0;
}

void tl__ibl_prefilter_level(const tl__ibl_pyramid *p, uint32_t level, uint32_t ow, uint32_t oh, float *out)
{
    static const uint32_t samples[TL__IBL_LEVELS] = {0, 64, 128, 256, 512, 512, 512};
    tl__lobe lobe;
    tl__lobe_make(tl__level_alpha(level), samples[level < TL__IBL_LEVELS ? level : 0],
                  4.0 * TL__PI / ((double)p->w[0] * p->h[0]), &lobe);
    double lod0 = log2((double)p->w[0] / ow); /* the mirror: the source at the texel's footprint */
    for (uint32_t j = 0; j < oh; j++)
        for (uint32_t i = 0; i < ow; i++) {
            double r[3], c[3];
            tl__ibl_direction((i + 0.5) / ow, (j + 0.5) / oh, r);
            if (lobe.count) tl__prefilter_texel(p, &lobe, r, c);
            else tl__ibl_pyramid_sample(p, r, lod0, c);
            float *o = out + ((size_t)j * ow + i) * 4;
            for (int k = 0; k < 3; k++) o[k] = (float)(c[k] < 65504.0 ? c[k] : 65504.0);
            o[3] = 1.0f;
        }
}

/* ---- the split-sum table ---------------------------------------------------------------------- */

/* A and B at (n.v, alpha): the GGX lobe's directional albedo split by Schlick's F0 (Karis 2013),
 * with the model's Schlick-GGX k = alpha / 2 (docs/lighting.md). */
static void tl__brdf_cell(double nv, double alpha, uint32_t samples, float out[2])
{
    const double n[3] = {0, 0, 1}, t[3] = {1, 0, 0}, b[3] = {0, 1, 0};
    double v[3] = {sqrt(1.0 - nv * nv), 0.0, nv}, a = 0.0, bb = 0.0, k = alpha * 0.5, h[3];
    for (uint32_t i = 0; i < samples; i++) {
        double nh = tl__ggx_half(i, samples, alpha, n, t, b, h);
        double vh = v[0] * h[0] + v[1] * h[1] + v[2] * h[2];
        double nl = 2.0 * vh * nh - nv;
        if (nl <= 0.0 || vh <= 0.0) continue;
        double g = (nl / (nl * (1.0 - k) + k)) * (nv / (nv * (1.0 - k) + k));
        double gv = g * vh / (nh * nv), fc = pow(1.0 - vh, 5.0);
        a += (1.0 - fc) * gv;
        bb += fc * gv;
    }
    out[0] = (float)(a / samples);
    out[1] = (float)(bb / samples);
}

void tl__ibl_brdf_table(float *out)
{
    const uint32_t n = TL__IBL_BRDF_SIZE;
    for (uint32_t j = 0; j < n; j++) {
        double alpha = tl_gloss_to_ggx_alpha(1.0f - (float)((j + 0.5) / n));
        for (uint32_t i = 0; i < n; i++) tl__brdf_cell((i + 0.5) / n, alpha, 1024u, out + ((size_t)j * n + i) * 2);
    }
}
