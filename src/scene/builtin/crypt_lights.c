/* Lights of the built-in crypt: coloured point lights spread evenly through the hall's free
 * volume, spot lights hanging under the vaults and pointing down, and dim moonlight.
 *
 * Exposure: light colours have pi folded in (diffuse radiance = albedo * colour * attenuation *
 * N.L, as shaders/lighting.glsl does). Intensities are scaled with the light count so that the mean
 * irradiance on the surfaces stays about the same for any count (about 0.7, so the textured stone,
 * linear albedo about 0.3, reflects about 0.2): the image is meant for exposure 1.0 followed by
 * ACES (or Reinhard), with no auto-exposure. */
#include <math.h>

#include "scene_internal.h"

#define TL__PI 3.14159265358979323846
/* Source radii of the crypt's emitters (tl_light.source_radius, metres): they change nothing under
 * Blinn-Phong (the crypt's default model) and make sphere lights under GGX. */
#define TL__TORCH_RADIUS 0.06f
#define TL__BRAZIER_RADIUS 0.15f
#define TL__LANTERN_RADIUS 0.1f

static float tl__clampf(float v, float lo, float hi) { return v < lo ? lo : v > hi ? hi : v; }

float tl__crypt_ceiling(float x, float z)
{
    const float r = 0.5f * TL__BAY, ri = r - TL__RIB_DEPTH, m = TL__RIB_HALF_WIDTH + 0.2f;
    float fx = floorf((x + TL__HALL_HALF_X) / TL__BAY), fz = floorf((z - TL__HALL_Z0) / TL__BAY);
    int bx = (int)tl__clampf(fx, 0.0f, (float)(TL__BAYS_X - 1));
    int bz = (int)tl__clampf(fz, 0.0f, (float)(TL__BAYS_Z - 1));
    float cx = -TL__HALL_HALF_X + TL__BAY * ((float)bx + 0.5f);
    float cz = TL__HALL_Z0 + TL__BAY * ((float)bz + 0.5f);
    float dx = tl__clampf(x - cx, -r, r), dz = tl__clampf(z - cz, -r, r);
    float h = TL__SPRING + fmaxf(sqrtf(r * r - dx * dx), sqrtf(r * r - dz * dz));
    /* the ribs hang below the vault along every line of columns */
    for (int s = -1; s <= 1; s += 2) {
        if (fabsf(x - (float)s * r) < m) h = fminf(h, TL__SPRING + sqrtf(fmaxf(0.0f, ri * ri - dz * dz)));
    }
    for (int k = 1; k < TL__BAYS_Z; k++) {
        float zr = TL__HALL_Z0 + TL__BAY * (float)k;
        if (fabsf(z - zr) < m) h = fminf(h, TL__SPRING + sqrtf(fmaxf(0.0f, ri * ri - dx * dx)));
    }
    for (int s = -1; s <= 1; s += 2) {
        float zr = s < 0 ? TL__HALL_Z0 + TL__RIB_HALF_WIDTH : TL__HALL_Z1 - TL__RIB_HALF_WIDTH;
        if (fabsf(z - zr) < m && fabsf(x) < r) h = fminf(h, TL__SPRING + sqrtf(fmaxf(0.0f, ri * ri - x * x)));
    }
    return h;
}

static int tl__blocked(const tl__light_plan *plan, float x, float y, float z, float margin)
{
    /* columns, and above them the crowded springing of four ribs, at any height */
    for (int k = 1; k < TL__BAYS_Z; k++) {
        float zc = TL__HALL_Z0 + TL__BAY * (float)k;
        if (fabsf(z - zc) < TL__COLUMN_CLEAR && fabsf(fabsf(x) - 0.5f * TL__BAY) < TL__COLUMN_CLEAR) return 1;
    }
    for (size_t i = 0; i < plan->solid_count; i++) {
        const float *s = plan->solids[i];
        if (x > s[0] - margin && x < s[3] + margin && y > s[1] - margin && y < s[4] + margin &&
            z > s[2] - margin && z < s[5] + margin)
            return 1;
    }
    return 0;
}

/* Linear RGB of hue h, saturation s (value 1), scaled to luminance 1. */
static void tl__hue_rgb(float h, float s, float out[3])
{
    float rgb[3];
    float hh = (h - floorf(h)) * 6.0f;
    int sector = (int)hh;
    float f = hh - (float)sector;
    float p = 1.0f - s, q = 1.0f - s * f, t = 1.0f - s * (1.0f - f);
    switch (sector % 6) {
    case 0: rgb[0] = 1; rgb[1] = t; rgb[2] = p; break;
    case 1: rgb[0] = q; rgb[1] = 1; rgb[2] = p; break;
    case 2: rgb[0] = p; rgb[1] = 1; rgb[2] = t; break;
    case 3: rgb[0] = p; rgb[1] = q; rgb[2] = 1; break;
    case 4: rgb[0] = t; rgb[1] = p; rgb[2] = 1; break;
    default: rgb[0] = 1; rgb[1] = p; rgb[2] = q; break;
    }
    float lum = 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2];
    for (int k = 0; k < 3; k++) out[k] = rgb[k] / lum;
}

/* An evenly spread sequence over the plan (the R2 sequence, Roberts 2018) from a seeded start. */
typedef struct tl__r2 {
    double x, y;
} tl__r2;

static void tl__r2_next(tl__r2 *r)
{
    const double a1 = 0.7548776662466927, a2 = 0.5698402909980532; /* 1/g, 1/g^2, g^3 = g + 1 */
    r->x += a1;
    r->y += a2;
    r->x -= floor(r->x);
    r->y -= floor(r->y);
}

/* A free spot in the hall: x, z from the sequence, y between y_lo and the ceiling less a gap. */
static int tl__place(const tl__light_plan *plan, tl__r2 *seq, tl__rng *rng, float y_lo,
                     float below_ceiling, float span_frac, float p[3])
{
    const float wall = 0.5f;
    for (int attempt = 0; attempt < 256; attempt++) {
        tl__r2_next(seq);
        float x = -TL__HALL_HALF_X + wall + (float)seq->x * 2.0f * (TL__HALL_HALF_X - wall);
        float z = TL__HALL_Z0 + wall + (float)seq->y * (TL__HALL_Z1 - TL__HALL_Z0 - 2.0f * wall);
        float top = tl__crypt_ceiling(x, z) - below_ceiling;
        float lo = fmaxf(y_lo, top - span_frac * (top - 0.3f));
        float t = (float)tl__rng_unit(rng);
        if (top - lo < 0.2f) continue;
        float y = lo + t * (top - lo);
        if (tl__blocked(plan, x, y, z, 0.2f)) continue;
        p[0] = x;
        p[1] = y;
        p[2] = z;
        return 1;
    }
    return 0;
}

/* Point lights: radius shrinks slowly with the count (64 -> 5 m, 4096 -> 2.5 m), intensity
 * falls so that count * intensity * radius (the mean irradiance) stays constant. */
static void tl__point_lights(const tl__light_plan *plan, tl__r2 *seq, tl__rng *rng, tl_light *out)
{
    uint32_t n = plan->point_lights;
    if (n == 0) return;
    float scale = 64.0f / (float)n;
    float radius = tl__clampf(5.0f * powf(scale, 1.0f / 6.0f), 1.5f, 6.0f);
    float intensity = 3.2f * scale * (5.0f / radius);
    /* a handful of lights leaves most of the view outside every range: lift them a little */
    if (n < 32) intensity *= sqrtf(32.0f / (float)n);
    for (uint32_t i = 0; i < n; i++) {
        tl_light *l = &out[i];
        *l = (tl_light){0};
        l->type = TL_LIGHT_POINT;
        int warm_spot = i < plan->warm_spot_count && i < n / 8;
        float p[3], rgb[3];
        if (warm_spot) {
            p[0] = plan->warm_spots[i][0];
            p[1] = plan->warm_spots[i][1];
            p[2] = plan->warm_spots[i][2];
            tl__hue_rgb(tl__rng_range(rng, 0.05f, 0.09f), tl__rng_range(rng, 0.7f, 0.8f), rgb);
        } else {
            if (!tl__place(plan, seq, rng, 0.3f, 0.5f, 1.0f, p)) {
                p[0] = 0.0f; /* the nave's centre line is always free */
                p[1] = 2.5f;
                p[2] = TL__HALL_Z0 + 1.0f + (float)seq->y * (TL__HALL_Z1 - TL__HALL_Z0 - 2.0f);
            }
            if (tl__rng_unit(rng) < 0.55)
                tl__hue_rgb(tl__rng_range(rng, 0.02f, 0.11f), tl__rng_range(rng, 0.4f, 0.7f), rgb);
            else
                tl__hue_rgb((float)tl__rng_unit(rng), tl__rng_range(rng, 0.25f, 0.6f), rgb);
        }
        float k = intensity * tl__rng_range(rng, 0.7f, 1.3f) * (warm_spot ? 1.5f : 1.0f);
        for (int c = 0; c < 3; c++) {
            l->position[c] = p[c];
            l->color[c] = rgb[c] * k;
        }
        l->radius = radius * tl__rng_range(rng, 0.8f, 1.2f);
        /* emitters as spheres (GGX lighting): braziers at the warm spots, torch flames elsewhere */
        l->source_radius = warm_spot ? TL__BRAZIER_RADIUS : TL__TORCH_RADIUS;
        l->shadow = warm_spot && plan->shadows;
    }
}

/* Spot lights: lanterns under the vault (upper third of the free height), tilted up to 25
 * degrees from straight down, cones of 26 to 43 degrees. */
static void tl__spot_lights(const tl__light_plan *plan, tl__r2 *seq, tl__rng *rng, tl_light *out)
{
    uint32_t ns = plan->spot_lights;
    if (ns == 0) return;
    float scale = 8.0f / (float)ns;
    float radius = tl__clampf(8.0f * powf(scale, 1.0f / 6.0f), 3.0f, 9.0f);
    float intensity = 10.0f * scale * (8.0f / radius);
    for (uint32_t i = 0; i < ns; i++) {
        tl_light *l = &out[i];
        *l = (tl_light){0};
        l->type = TL_LIGHT_SPOT;
        float p[3], rgb[3];
        if (!tl__place(plan, seq, rng, 2.5f, 0.5f, 0.33f, p)) {
            p[0] = 0.0f;
            p[1] = 4.0f;
            p[2] = TL__HALL_Z0 + 1.0f + (float)seq->y * (TL__HALL_Z1 - TL__HALL_Z0 - 2.0f);
        }
        float tilt = tl__rng_range(rng, 0.0f, 0.44f);
        float az = tl__rng_range(rng, 0.0f, 2.0f * (float)TL__PI);
        float outer = tl__rng_range(rng, 0.45f, 0.75f);
        float inner = outer * tl__rng_range(rng, 0.55f, 0.8f);
        tl__hue_rgb((float)tl__rng_unit(rng), tl__rng_range(rng, 0.1f, 0.35f), rgb);
        float k = intensity * tl__rng_range(rng, 0.8f, 1.2f);
        float d[3] = {sinf(tilt) * cosf(az), -cosf(tilt), sinf(tilt) * sinf(az)};
        float len = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int c = 0; c < 3; c++) {
            l->position[c] = p[c];
            l->direction[c] = d[c] / len;
            l->color[c] = rgb[c] * k;
        }
        l->radius = radius * tl__rng_range(rng, 0.9f, 1.1f);
        l->cos_inner = cosf(inner);
        l->cos_outer = cosf(outer);
        l->source_radius = TL__LANTERN_RADIUS;
    }
}

/* Moonlight through the roof: dim and cool. */
static void tl__moonlight(tl_light *l)
{
    *l = (tl_light){0};
    l->type = TL_LIGHT_DIRECTIONAL;
    const float d[3] = {-0.3f, -1.0f, -0.2f};
    float len = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int c = 0; c < 3; c++) l->direction[c] = d[c] / len;
    l->color[0] = 0.10f;
    l->color[1] = 0.13f;
    l->color[2] = 0.22f;
}

void tl__crypt_lights(const tl__light_plan *plan, tl_light *out)
{
    tl__rng rng = {plan->seed ^ 0x6c696768746c6967ull};
    tl__r2 seq = {tl__rng_unit(&rng), tl__rng_unit(&rng)};
    tl__point_lights(plan, &seq, &rng, out);
    tl__spot_lights(plan, &seq, &rng, out + plan->point_lights);
    if (plan->directional) {
        tl__moonlight(out + plan->point_lights + plan->spot_lights);
        out[plan->point_lights + plan->spot_lights].shadow = plan->shadows;
    }
}
