/* The built-in scene: a Romanesque hall crypt, 15 m x 40 m, three aisles of eight square bays
 * under groin vaults (crown 7.5 m), fourteen columns with attic bases and cushion capitals, round
 * transverse and longitudinal arches, an apse with a half dome, walls of ashlar with painted
 * niches, and props (sarcophagi, benches, pedestals with spheres, urns, braziers, crates, an
 * altar on steps). Y is up, metres; the camera stands at the z = +20 end looking down the nave
 * towards the apse at z = -20.
 *
 * Geometry depends only on `detail`; the seed only moves and colours the lights. Every column,
 * arch, wall panel, vault bay and prop is its own object with tight world bounds. */
#include <math.h>
#include <string.h>

#include "core/log.h"
#include "scene_internal.h"

#define TL__PI 3.14159265358979323846
#define TL__MAX_LIGHTS 65536u
#define TL__MAX_DETAIL 8u
#define TL__MAX_SOLIDS 256

/* ---- materials ----------------------------------------------------------------------------- */

enum {
    TL__M_STONE = 0,
    TL__M_PLASTER,
    TL__M_FLAGSTONE,
    TL__M_ASHLAR,
    TL__M_MARBLE,
    TL__M_MARBLE_DARK,
    TL__M_TILES,
    TL__M_RED,
    TL__M_BLUE,
    TL__M_GOLD,
    TL__M_BRONZE,
    TL__M_EMBERS,
    TL__M_GLASS, /* only in a scene with glass panes */
    TL__M_COUNT
};

typedef struct tl__material_def {
    const char *name;
    float albedo[3];   /* linear */
    float specular[3]; /* linear F0 */
    float gloss;
    float emissive[3];
    int texture; /* TL__TEX_*, or -1 */
} tl__material_def;

static const tl__material_def tl__crypt_materials[TL__M_COUNT] = {
    [TL__M_STONE] = {"stone_matte", {0.34f, 0.31f, 0.27f}, {0.02f, 0.02f, 0.02f}, 0.2f, {0}, -1},
    [TL__M_PLASTER] = {"plaster_vault", {0.52f, 0.49f, 0.44f}, {0.015f, 0.015f, 0.015f}, 0.15f, {0}, -1},
    [TL__M_FLAGSTONE] = {"flagstone_floor", {1, 1, 1}, {0.03f, 0.03f, 0.03f}, 0.3f, {0}, TL__TEX_FLAGSTONE},
    [TL__M_ASHLAR] = {"ashlar_wall", {1, 1, 1}, {0.02f, 0.02f, 0.02f}, 0.2f, {0}, TL__TEX_ASHLAR},
    [TL__M_MARBLE] = {"marble_polished", {1, 1, 1}, {0.06f, 0.06f, 0.06f}, 0.85f, {0}, TL__TEX_MARBLE},
    [TL__M_MARBLE_DARK] = {"marble_verde", {0.03f, 0.06f, 0.05f}, {0.05f, 0.05f, 0.05f}, 0.8f, {0}, -1},
    [TL__M_TILES] = {"tile_pavement", {1, 1, 1}, {0.04f, 0.04f, 0.04f}, 0.6f, {0}, TL__TEX_TILES},
    [TL__M_RED] = {"painted_red", {0.42f, 0.05f, 0.035f}, {0.03f, 0.03f, 0.03f}, 0.35f, {0}, -1},
    [TL__M_BLUE] = {"painted_blue", {0.035f, 0.08f, 0.38f}, {0.03f, 0.03f, 0.03f}, 0.35f, {0}, -1},
    [TL__M_GOLD] = {"gold", {0.09f, 0.065f, 0.02f}, {1.0f, 0.77f, 0.34f}, 0.78f, {0}, -1},
    [TL__M_BRONZE] = {"bronze", {0.10f, 0.06f, 0.03f}, {0.45f, 0.30f, 0.16f}, 0.6f, {0}, -1},
    [TL__M_EMBERS] = {"embers", {0.04f, 0.02f, 0.01f}, {0, 0, 0}, 0.0f, {2.0f, 0.55f, 0.1f}, -1},
    [TL__M_GLASS] = {"glass_tinted", {0.05f, 0.30f, 0.26f}, {0.04f, 0.04f, 0.04f}, 0.9f, {0}, -1},
};

#define TL__GLASS_ALPHA 0.35f
#define TL__MAX_GLASS 8u

/* ---- layout --------------------------------------------------------------------------------- */

typedef struct tl__crypt {
    tl__builder *b;
    uint32_t detail;
    uint32_t glass_panes;
    size_t solids[TL__MAX_SOLIDS]; /* objects lights must not sit in */
    size_t solid_count;
    float warm[8][3]; /* above the braziers */
    size_t warm_count;
} tl__crypt;

static void tl__obj(tl__crypt *c, int material)
{
    int tex = tl__crypt_materials[material].texture;
    tl__begin_object(c->b, (uint32_t)material, tex >= 0 ? 1.0f / tl__texture_metres(tex) : 1.0f);
}

static void tl__obj_end(tl__crypt *c, int solid)
{
    size_t index = tl__end_object(c->b);
    if (solid && c->solid_count < TL__MAX_SOLIDS) c->solids[c->solid_count++] = index;
}

static void tl__v3(float o[3], float x, float y, float z)
{
    o[0] = x;
    o[1] = y;
    o[2] = z;
}

static void tl__box_at(tl__crypt *c, float x, float y, float z, float hx, float hy, float hz, float yaw)
{
    float centre[3], half[3];
    tl__v3(centre, x, y, z);
    tl__v3(half, hx, hy, hz);
    tl__box(c->b, centre, half, yaw);
}

/* Appends arc points (rc + rad cos a, yc + rad sin a) for a from a0 to a1, skipping a first point
 * that repeats the profile's last. */
#define TL__PROFILE_MAX 160

typedef struct tl__profile {
    tl__profile_point p[TL__PROFILE_MAX];
    size_t n;
} tl__profile;

static void tl__profile_add(tl__profile *pr, float r, float y, float square, int crease)
{
    if (pr->n > 0) {
        const tl__profile_point *last = &pr->p[pr->n - 1];
        if (fabsf(last->r - r) < 1e-6f && fabsf(last->y - y) < 1e-6f) {
            if (crease) pr->p[pr->n - 1].crease = 1;
            return;
        }
    }
    if (pr->n >= TL__PROFILE_MAX) return;
    pr->p[pr->n++] = (tl__profile_point){r, y, square, crease};
}

static void tl__profile_arc(tl__profile *pr, float rc, float yc, float rad, double a0, double a1,
                            uint32_t steps)
{
    for (uint32_t k = 0; k <= steps; k++) {
        double a = a0 + (a1 - a0) * k / steps;
        tl__profile_add(pr, (float)(rc + rad * cos(a)), (float)(yc + rad * sin(a)), 0.0f, 0);
    }
}

static void tl__profile_crease(tl__profile *pr)
{
    if (pr->n > 0) pr->p[pr->n - 1].crease = 1;
}

static void tl__lathe_at(tl__crypt *c, const tl__profile *pr, float x, float y, float z,
                         uint32_t segments, double phi0, double phi1, int inward)
{
    tl__lathe_desc d = {{x, y, z}, pr->p, pr->n, segments, (float)phi0, (float)phi1, inward};
    tl__lathe(c->b, &d);
}

static uint32_t tl__ring_segments(const tl__crypt *c) { return 16u * c->detail; }
static uint32_t tl__vault_n(const tl__crypt *c) { return 4u * c->detail; }

static void tl__crypt_floor(tl__crypt *c)
{
    const float n[3] = {0, 1, 0};
    for (int bx = 0; bx < TL__BAYS_X; bx++) {
        for (int bz = 0; bz < TL__BAYS_Z; bz++) {
            float x0 = -TL__HALL_HALF_X + TL__BAY * (float)bx, x1 = x0 + TL__BAY;
            float z0 = TL__HALL_Z0 + TL__BAY * (float)bz, z1 = z0 + TL__BAY;
            /* run under the walls so the skirting never cracks */
            if (bx == 0) x0 -= 0.1f;
            if (bx == TL__BAYS_X - 1) x1 += 0.1f;
            if (bz == 0) z0 -= 0.1f;
            if (bz == TL__BAYS_Z - 1) z1 += 0.1f;
            float p0[3], p1[3], p2[3], p3[3];
            tl__v3(p0, x0, 0, z1);
            tl__v3(p1, x1, 0, z1);
            tl__v3(p2, x1, 0, z0);
            tl__v3(p3, x0, 0, z0);
            tl__obj(c, bx == 1 ? TL__M_TILES : TL__M_FLAGSTONE);
            tl__flat_quad(c->b, p0, p1, p2, p3, n, c->detail, c->detail);
            tl__obj_end(c, 0);
        }
    }
}

static void tl__crypt_vaults(tl__crypt *c)
{
    for (int bx = 0; bx < TL__BAYS_X; bx++) {
        for (int bz = 0; bz < TL__BAYS_Z; bz++) {
            tl__obj(c, TL__M_PLASTER);
            tl__groin_vault(c->b, -TL__HALL_HALF_X + TL__BAY * ((float)bx + 0.5f),
                            TL__HALL_Z0 + TL__BAY * ((float)bz + 0.5f), 0.5f * TL__BAY, TL__SPRING,
                            tl__vault_n(c));
            tl__obj_end(c, 0);
        }
    }
}

/* The apse: a half-cylinder wall and a half dome behind the middle bay of the z0 wall. The dome's
 * rim repeats the vault's edge points bit for bit, so the two meet without a crack. */
static void tl__crypt_apse(tl__crypt *c)
{
    const float r = 0.5f * TL__BAY;
    uint32_t n = tl__vault_n(c); /* even */
    uint32_t segs = tl__ring_segments(c) / 2;
    tl__profile pr = {.n = 0};

    tl__obj(c, TL__M_ASHLAR);
    tl__profile_add(&pr, r, -0.05f, 0, 0);
    tl__profile_add(&pr, r, TL__SPRING, 0, 0);
    tl__lathe_at(c, &pr, 0, 0, TL__HALL_Z0, segs, TL__PI, 2.0 * TL__PI, 1);
    tl__obj_end(c, 0);

    pr.n = 0;
    for (uint32_t j = 0; j <= n / 2; j++) {
        double phi = 0.5 * TL__PI * (2.0 * j / n - 1.0); /* as tl__groin_vault computes it */
        float pr_r = j == n / 2 ? 0.0f : (float)(-(double)r * sin(phi));
        tl__profile_add(&pr, pr_r, (float)(TL__SPRING + r * cos(phi)), 0, 0);
    }
    tl__obj(c, TL__M_BLUE);
    tl__lathe_at(c, &pr, 0, 0, TL__HALL_Z0, segs, TL__PI, 2.0 * TL__PI, 1);
    tl__obj_end(c, 0);

    /* a platform (radius a little over the wall's, hidden behind it), two steps, the altar */
    {
        float pts[2 * 64 + 1][2];
        uint32_t m = 2 * c->detail + 2;
        if (m > 2 * 64) m = 2 * 64;
        for (uint32_t k = 0; k <= m; k++) {
            double a = TL__PI + TL__PI * k / m;
            pts[k][0] = (float)(2.52 * cos(a));
            pts[k][1] = (float)(k == 0 || k == m ? 0.0 : 2.52 * sin(a));
        }
        float origin[3] = {0, 0, TL__HALL_Z0}, ax[3] = {1, 0, 0}, az[3] = {0, 0, 1}, up[3] = {0, 1, 0};
        tl__obj(c, TL__M_STONE);
        tl__prism(c->b, origin, ax, az, up, 0.54f, (const float (*)[2])pts, m + 1);
        tl__obj_end(c, 1);
    }
    tl__obj(c, TL__M_STONE);
    tl__box_at(c, 0, 0.09f, TL__HALL_Z0 + 0.6f, 2.1f, 0.09f, 0.6f, 0);
    tl__obj_end(c, 1);
    tl__obj(c, TL__M_STONE);
    tl__box_at(c, 0, 0.18f, TL__HALL_Z0 + 0.4f, 2.1f, 0.18f, 0.4f, 0);
    tl__obj_end(c, 1);

    tl__obj(c, TL__M_MARBLE);
    tl__box_at(c, 0, 0.54f + 0.45f, TL__HALL_Z0 - 1.1f, 0.75f, 0.45f, 0.4f, 0);
    tl__obj_end(c, 1);
    tl__obj(c, TL__M_MARBLE_DARK);
    tl__box_at(c, 0, 1.49f, TL__HALL_Z0 - 1.1f, 0.85f, 0.05f, 0.48f, 0);
    tl__obj_end(c, 1);

    /* candlesticks */
    pr.n = 0;
    tl__profile_add(&pr, 0.0f, 0.0f, 0, 0);
    tl__profile_add(&pr, 0.08f, 0.0f, 0, 1);
    tl__profile_add(&pr, 0.08f, 0.02f, 0, 1);
    tl__profile_add(&pr, 0.03f, 0.05f, 0, 0);
    tl__profile_add(&pr, 0.02f, 0.09f, 0, 0);
    tl__profile_add(&pr, 0.018f, 0.35f, 0, 1);
    tl__profile_add(&pr, 0.05f, 0.36f, 0, 1);
    tl__profile_add(&pr, 0.05f, 0.38f, 0, 1);
    tl__profile_add(&pr, 0.0f, 0.38f, 0, 0);
    for (int s = -1; s <= 1; s += 2) {
        tl__obj(c, TL__M_GOLD);
        tl__lathe_at(c, &pr, 0.6f * (float)s, 1.54f, TL__HALL_Z0 - 1.1f, tl__ring_segments(c) / 2, 0, 0, 0);
        tl__obj_end(c, 1);
    }
}

static void tl__urn_profile(tl__profile *pr, uint32_t detail)
{
    pr->n = 0;
    tl__profile_add(pr, 0.0f, 0.0f, 0, 0);
    tl__profile_add(pr, 0.11f, 0.0f, 0, 1);
    tl__profile_add(pr, 0.12f, 0.03f, 0, 1);
    uint32_t steps = 4 * detail;
    for (uint32_t k = 0; k <= steps; k++) {
        double t = (double)k / steps;
        double r = 0.065 + 0.15 * sin(TL__PI * t) * (1.0 - 0.35 * t);
        tl__profile_add(pr, (float)r, (float)(0.08 + 0.5 * t), 0, k == 0);
    }
    tl__profile_add(pr, 0.09f, 0.64f, 0, 1);
    tl__profile_add(pr, 0.10f, 0.66f, 0, 1);
    tl__profile_add(pr, 0.075f, 0.665f, 0, 1);
    tl__profile_add(pr, 0.06f, 0.62f, 0, 1);
    tl__profile_add(pr, 0.0f, 0.62f, 0, 0);
}

/* One wall panel per bay side; niches hold a gold urn. */
static void tl__crypt_wall(tl__crypt *c, float ox, float oz, float nx, float nz, int niche)
{
    tl__wall_desc d = {
        .origin = {ox, 0.0f, oz},
        .normal = {nx, 0.0f, nz},
        .w = TL__BAY,
        .u0 = -0.05f,
        .u1 = TL__BAY + 0.05f,
        .y_spring = TL__SPRING,
        .top_margin = 0.03f,
        .level_sill = 0.9f,
        .level_spring = 2.6f,
        .lunette_segments = tl__vault_n(c),
        .niche = niche,
        .na = 0.7f,
        .nd = 0.6f,
        .niche_segments = tl__vault_n(c),
    };
    tl__obj(c, TL__M_ASHLAR);
    tl__wall(c->b, &d);
    tl__obj_end(c, 0);
    if (!niche) return;
    tl__obj(c, TL__M_RED);
    tl__niche_recess(c->b, &d);
    tl__obj_end(c, 0);

    /* U = Y x n, the niche's middle is half a bay along U and half its depth behind the wall */
    float ux = nz, uz = -nx;
    float cx = ox + ux * 0.5f * TL__BAY - nx * 0.5f * d.nd;
    float cz = oz + uz * 0.5f * TL__BAY - nz * 0.5f * d.nd;
    tl__profile pr;
    tl__urn_profile(&pr, c->detail);
    tl__obj(c, TL__M_GOLD);
    tl__lathe_at(c, &pr, cx, d.level_sill, cz, tl__ring_segments(c) / 2, 0, 0, 0);
    tl__obj_end(c, 1);
}

static void tl__crypt_walls(tl__crypt *c)
{
    for (int side = -1; side <= 1; side += 2) {
        float x = (float)side * TL__HALL_HALF_X;
        for (int bz = 0; bz < TL__BAYS_Z; bz++) {
            float z0 = TL__HALL_Z0 + TL__BAY * (float)bz, z1 = z0 + TL__BAY;
            /* normal (-side, 0, 0): U = (0, 0, -side), so u = 0 is at z1 on the left wall */
            tl__crypt_wall(c, x, side < 0 ? z1 : z0, (float)-side, 0.0f, bz % 2 == 0);
        }
    }
    for (int bx = 0; bx < TL__BAYS_X; bx++) {
        float x0 = -TL__HALL_HALF_X + TL__BAY * (float)bx, x1 = x0 + TL__BAY;
        if (bx != 1) tl__crypt_wall(c, x0, TL__HALL_Z0, 0.0f, 1.0f, 0); /* the apse opens here */
        tl__crypt_wall(c, x1, TL__HALL_Z1, 0.0f, -1.0f, bx == 1);
    }
}

static void tl__crypt_pilasters(tl__crypt *c)
{
    const float wall_x = TL__HALL_HALF_X;
    for (int side = -1; side <= 1; side += 2) {
        float s = (float)side;
        for (int k = 1; k < TL__BAYS_Z; k++) {
            float z = TL__HALL_Z0 + TL__BAY * (float)k;
            tl__obj(c, TL__M_STONE);
            tl__box_at(c, s * (wall_x - 0.125f), 2.35f, z, 0.175f, 2.35f, 0.4f, 0);
            tl__box_at(c, s * (wall_x - 0.175f), 4.85f, z, 0.225f, 0.15f, 0.5f, 0);
            tl__obj_end(c, 1);
        }
    }
    for (int end = 0; end < 2; end++) {
        float zw = end ? TL__HALL_Z1 : TL__HALL_Z0, in = end ? -1.0f : 1.0f;
        for (int side = -1; side <= 1; side += 2) {
            float x = (float)side * 0.5f * TL__BAY;
            tl__obj(c, TL__M_STONE);
            tl__box_at(c, x, 2.35f, zw + in * 0.125f, 0.4f, 2.35f, 0.175f, 0);
            tl__box_at(c, x, 4.85f, zw + in * 0.175f, 0.5f, 0.15f, 0.225f, 0);
            tl__obj_end(c, 1);
        }
    }
}

static void tl__crypt_columns(tl__crypt *c)
{
    const uint32_t d = c->detail, segs = tl__ring_segments(c);
    tl__profile base = {.n = 0}, shaft = {.n = 0}, capital = {.n = 0};
    /* attic base: torus, scotia, torus, fillet */
    tl__profile_arc(&base, 0.34f, 0.33f, 0.08f, -0.5 * TL__PI, 0.5 * TL__PI, 2 * d + 2);
    tl__profile_arc(&base, 0.34f, 0.45f, 0.04f, 1.5 * TL__PI, 0.5 * TL__PI, d + 2);
    tl__profile_arc(&base, 0.34f, 0.52f, 0.03f, -0.5 * TL__PI, 0.5 * TL__PI, 2 * d + 2);
    tl__profile_crease(&base);
    tl__profile_add(&base, 0.30f, 0.55f, 0, 0);
    /* shaft with a slight entasis */
    for (uint32_t k = 0, rows = 2 * d + 1; k <= rows; k++) {
        double t = (double)k / rows;
        tl__profile_add(&shaft, (float)(0.30 - 0.03 * t + 0.01 * sin(TL__PI * t)), (float)(0.55 + 3.7 * t), 0, 0);
    }
    /* astragal, then the cushion: a circle swelling into a square under the abacus */
    tl__profile_arc(&capital, 0.27f, 4.29f, 0.04f, -0.5 * TL__PI, 0.5 * TL__PI, d + 2);
    tl__profile_crease(&capital);
    for (uint32_t k = 1, rows = 4 * d; k <= rows; k++) {
        double t = (double)k / rows;
        tl__profile_add(&capital, (float)(0.27 + 0.17 * sin(0.5 * TL__PI * t)), (float)(4.33 + 0.37 * t),
                        (float)(2.0 + 10.0 * t * t), 0);
    }

    for (int side = -1; side <= 1; side += 2) {
        for (int k = 1; k < TL__BAYS_Z; k++) {
            float x = (float)side * 0.5f * TL__BAY, z = TL__HALL_Z0 + TL__BAY * (float)k;
            tl__obj(c, TL__M_STONE);
            tl__box_at(c, x, 0.125f, z, 0.45f, 0.125f, 0.45f, 0);
            tl__lathe_at(c, &base, x, 0, z, segs, 0, 0, 0);
            tl__lathe_at(c, &capital, x, 0, z, segs, 0, 0, 0);
            tl__box_at(c, x, 4.85f, z, 0.475f, 0.15f, 0.475f, 0);
            tl__obj_end(c, 1);
            tl__obj(c, ((k + (side > 0)) % 2) ? TL__M_MARBLE : TL__M_MARBLE_DARK);
            tl__lathe_at(c, &shaft, x, 0, z, segs, 0, 0, 0);
            tl__obj_end(c, 1);
        }
    }
}

static void tl__crypt_arches(tl__crypt *c)
{
    const float r = 0.5f * TL__BAY, ri = r - TL__RIB_DEPTH, hw = TL__RIB_HALF_WIDTH;
    const uint32_t segs = 8u * c->detail;
    float centre[3], along_z[3] = {0, 0, 1}, along_x[3] = {1, 0, 0};
    for (int side = -1; side <= 1; side += 2) {
        for (int k = 0; k < TL__BAYS_Z; k++) {
            tl__v3(centre, (float)side * r, TL__SPRING, TL__HALL_Z0 + TL__BAY * ((float)k + 0.5f));
            tl__obj(c, TL__M_STONE);
            tl__arch(c->b, centre, along_z, ri, r, hw, segs);
            tl__obj_end(c, 0);
        }
    }
    for (int k = 1; k < TL__BAYS_Z; k++) {
        for (int bx = 0; bx < TL__BAYS_X; bx++) {
            tl__v3(centre, -TL__HALL_HALF_X + TL__BAY * ((float)bx + 0.5f), TL__SPRING,
                   TL__HALL_Z0 + TL__BAY * (float)k);
            tl__obj(c, TL__M_STONE);
            tl__arch(c->b, centre, along_x, ri, r, hw, segs);
            tl__obj_end(c, 0);
        }
    }
    /* framing the apse and the entrance bay, against the end walls */
    for (int end = 0; end < 2; end++) {
        tl__v3(centre, 0, TL__SPRING, end ? TL__HALL_Z1 - hw : TL__HALL_Z0 + hw);
        tl__obj(c, TL__M_STONE);
        tl__arch(c->b, centre, along_x, ri, r, hw, segs);
        tl__obj_end(c, 0);
    }
}

static void tl__sphere_profile(tl__profile *pr, float radius, uint32_t steps)
{
    pr->n = 0;
    for (uint32_t k = 0; k <= steps; k++) {
        double a = -0.5 * TL__PI + TL__PI * k / steps;
        float rr = (k == 0 || k == steps) ? 0.0f : (float)(radius * cos(a));
        tl__profile_add(pr, rr, (float)(radius * sin(a)), 0, 0);
    }
}

/* sarcophagi along the aisles, with gabled lids, and benches against the walls */
static void tl__crypt_sarcophagi(tl__crypt *c)
{
    static const float sarcophagus_z[3] = {-12.5f, -2.5f, 7.5f};
    static const int lid_material[3] = {TL__M_RED, TL__M_BLUE, TL__M_MARBLE_DARK};
    for (int side = -1; side <= 1; side += 2) {
        float s = (float)side;
        for (int i = 0; i < 3; i++) {
            float x = s * 5.0f, z = sarcophagus_z[i];
            float yaw = s * (i % 2 ? 0.06f : -0.04f);
            tl__obj(c, TL__M_MARBLE);
            tl__box_at(c, x, 0.06f, z, 0.58f, 0.06f, 1.18f, yaw);
            tl__box_at(c, x, 0.52f, z, 0.5f, 0.4f, 1.1f, yaw);
            tl__obj_end(c, 1);
            /* gabled lid, extruded along the chest's length */
            const float pts[5][2] = {{-0.56f, 0}, {0.56f, 0}, {0.56f, 0.1f}, {0, 0.32f}, {-0.56f, 0.1f}};
            float a[3], up[3] = {0, 1, 0}, e[3], origin[3];
            tl__v3(a, cosf(yaw), 0, -sinf(yaw));
            tl__v3(e, sinf(yaw), 0, cosf(yaw));
            tl__v3(origin, x - e[0] * 1.15f, 0.92f, z - e[2] * 1.15f);
            tl__obj(c, lid_material[(i + (side > 0)) % 3]);
            tl__prism(c->b, origin, a, up, e, 2.3f, pts, 5);
            tl__obj_end(c, 1);
            /* a bench against the wall opposite */
            float bx = s * (TL__HALL_HALF_X - 0.3f);
            tl__obj(c, TL__M_STONE);
            tl__box_at(c, bx, 0.45f, z, 0.25f, 0.05f, 1.5f, 0);
            tl__box_at(c, bx, 0.2f, z - 1.1f, 0.2f, 0.2f, 0.12f, 0);
            tl__box_at(c, bx, 0.2f, z + 1.1f, 0.2f, 0.2f, 0.12f, 0);
            tl__obj_end(c, 1);
        }
    }
}

/* pedestals with spheres in the aisles, by the columns */
static void tl__crypt_pedestals(tl__crypt *c)
{
    const uint32_t d = c->detail, segs = tl__ring_segments(c);
    static const float pedestal_z[4] = {-17.5f, -7.5f, 2.5f, 12.5f};
    static const int sphere_material[4] = {TL__M_GOLD, TL__M_MARBLE, TL__M_BLUE, TL__M_MARBLE_DARK};
    tl__profile sphere;
    tl__sphere_profile(&sphere, 0.3f, 8 * d);
    for (int side = -1; side <= 1; side += 2) {
        for (int i = 0; i < 4; i++) {
            float x = (float)side * 3.7f, z = pedestal_z[i];
            tl__obj(c, TL__M_STONE);
            tl__box_at(c, x, 0.5f, z, 0.22f, 0.5f, 0.22f, 0);
            tl__box_at(c, x, 1.03f, z, 0.28f, 0.03f, 0.28f, 0);
            tl__obj_end(c, 1);
            tl__obj(c, sphere_material[(i + (side > 0) * 2) % 4]);
            tl__lathe_at(c, &sphere, x, 1.36f, z, segs, 0, 0, 0);
            tl__obj_end(c, 1);
        }
    }
}

/* braziers flanking the nave: bronze stand and bowl, glowing embers */
static void tl__crypt_braziers(tl__crypt *c)
{
    const uint32_t d = c->detail, segs = tl__ring_segments(c);
    static const float brazier_z[3] = {-12.5f, -2.5f, 7.5f};
    tl__profile stand = {.n = 0}, embers = {.n = 0};
    tl__profile_add(&stand, 0.0f, 0.0f, 0, 0);
    tl__profile_add(&stand, 0.26f, 0.0f, 0, 1);
    tl__profile_add(&stand, 0.26f, 0.05f, 0, 1);
    tl__profile_add(&stand, 0.06f, 0.10f, 0, 0);
    tl__profile_add(&stand, 0.045f, 0.5f, 0, 0);
    tl__profile_add(&stand, 0.045f, 0.75f, 0, 0);
    tl__profile_add(&stand, 0.08f, 0.82f, 0, 1);
    tl__profile_add(&stand, 0.30f, 0.92f, 0, 0);
    tl__profile_add(&stand, 0.36f, 1.02f, 0, 1);
    tl__profile_add(&stand, 0.33f, 1.03f, 0, 1);
    tl__profile_add(&stand, 0.28f, 0.98f, 0, 0);
    tl__profile_add(&stand, 0.0f, 0.95f, 0, 0);
    for (uint32_t k = 0, steps = 2 * d + 2; k <= steps; k++) {
        double a = 0.5 * TL__PI * k / steps;
        tl__profile_add(&embers, k == steps ? 0.0f : (float)(0.30 * cos(a)), (float)(0.985 + 0.115 * sin(a)), 0, 0);
    }
    for (int side = -1; side <= 1; side += 2) {
        for (int i = 0; i < 3; i++) {
            float x = (float)side * 1.6f, z = brazier_z[i];
            tl__obj(c, TL__M_BRONZE);
            tl__lathe_at(c, &stand, x, 0, z, segs, 0, 0, 0);
            tl__obj_end(c, 1);
            tl__obj(c, TL__M_EMBERS);
            tl__lathe_at(c, &embers, x, 0, z, segs, 0, 0, 0);
            tl__obj_end(c, 1);
            if (c->warm_count < 8) tl__v3(c->warm[c->warm_count++], x, 1.45f, z);
        }
    }
}

/* crates stacked in the entrance bays */
static void tl__crypt_crates(tl__crypt *c)
{
    for (int side = -1; side <= 1; side += 2) {
        float s = (float)side;
        tl__obj(c, TL__M_RED);
        tl__box_at(c, s * 5.6f, 0.4f, 17.0f, 0.4f, 0.4f, 0.4f, 0.2f * s);
        tl__obj_end(c, 1);
        tl__obj(c, TL__M_BLUE);
        tl__box_at(c, s * 5.55f, 1.1f, 17.05f, 0.3f, 0.3f, 0.3f, -0.35f * s);
        tl__obj_end(c, 1);
        tl__obj(c, TL__M_STONE);
        tl__box_at(c, s * 4.5f, 0.3f, 18.3f, 0.3f, 0.3f, 0.45f, 0.5f);
        tl__obj_end(c, 1);
    }
}

/* glass panes across the nave, 4 m apart, each shifted sideways so that the panes overlap on
 * screen in part: thin boxes (single-sided: only the faces towards a viewer are drawn) */
static void tl__crypt_glass(tl__crypt *c)
{
    for (uint32_t i = 0; i < c->glass_panes; i++) {
        float x = (i & 1u) ? 0.6f : -0.6f, z = 14.0f - 4.0f * (float)i;
        tl__obj(c, TL__M_GLASS);
        tl__box_at(c, x, 1.8f, z, 1.6f, 1.6f, 0.01f, 0.15f * (float)((int)(i % 3u) - 1));
        tl__obj_end(c, 0); /* lights may stand behind and before it, never in it: they do not move */
    }
}

static void tl__crypt_props(tl__crypt *c)
{
    tl__crypt_sarcophagi(c);
    tl__crypt_pedestals(c);
    tl__crypt_braziers(c);
    tl__crypt_crates(c);
}

static void tl__crypt_build(tl__crypt *c)
{
    tl__crypt_floor(c);
    tl__crypt_vaults(c);
    tl__crypt_apse(c);
    tl__crypt_walls(c);
    tl__crypt_pilasters(c);
    tl__crypt_columns(c);
    tl__crypt_arches(c);
    tl__crypt_props(c);
    tl__crypt_glass(c);
}

/* ---- creation ------------------------------------------------------------------------------- */

/* The scene's arrays for the counts pass 1 found, with its generated textures; NULL when out
 * of memory (nothing left allocated). */
static tl_scene *tl__crypt_alloc(const tl_allocator *a, const tl__builder *counts, size_t light_count)
{
    tl_scene *scene = tl__alloc_array(a, 1, sizeof(tl_scene));
    if (!scene) return NULL;
    memset(scene, 0, sizeof(*scene));
    scene->allocator = *a;
    scene->vertices = tl__alloc_array(a, counts->vertex_count, sizeof(tl_vertex));
    scene->indices = scene->vertices ? tl__alloc_array(a, counts->index_count, sizeof(uint32_t)) : NULL;
    scene->objects = scene->indices ? tl__alloc_array(a, counts->object_count, sizeof(tl_object)) : NULL;
    scene->materials = scene->objects ? tl__alloc_array(a, TL__M_COUNT, sizeof(tl_material)) : NULL;
    scene->textures = scene->materials ? tl__alloc_array(a, TL__TEX_COUNT, sizeof(tl_texture)) : NULL;
    scene->lights = scene->textures ? tl__alloc_array(a, light_count, sizeof(tl_light)) : NULL;
    if (!scene->lights) goto out_of_memory;
    memset(scene->textures, 0, TL__TEX_COUNT * sizeof(tl_texture));
    scene->texture_count = TL__TEX_COUNT;
    for (int t = 0; t < TL__TEX_COUNT; t++) {
        tl_texture *tex = &scene->textures[t];
        uint32_t size = tl__texture_size(t);
        tex->rgba = tl__alloc_array(a, (size_t)size * size, 4);
        if (!tex->rgba) goto out_of_memory;
        tex->width = tex->height = size;
        strncpy(tex->name, tl__texture_name(t), sizeof(tex->name) - 1);
        tl__texture_generate(t, tex->rgba);
    }
    return scene;

out_of_memory:
    tl_scene_destroy(scene);
    return NULL;
}

static void tl__crypt_material_table(tl_scene *scene, int glass)
{
    scene->material_count = glass ? TL__M_COUNT : TL__M_GLASS;
    for (int m = 0; m < (int)scene->material_count; m++) {
        const tl__material_def *def = &tl__crypt_materials[m];
        tl_material *mat = &scene->materials[m];
        memset(mat, 0, sizeof(*mat));
        memcpy(mat->albedo, def->albedo, sizeof(mat->albedo));
        memcpy(mat->specular, def->specular, sizeof(mat->specular));
        memcpy(mat->emissive, def->emissive, sizeof(mat->emissive));
        mat->gloss = def->gloss;
        mat->alpha_cutoff = 0.5f;
        mat->albedo_map = def->texture >= 0 ? TL_TEXTURE_MAP(def->texture) : 0;
        mat->alpha = m == TL__M_GLASS ? TL__GLASS_ALPHA : 1.0f;
        if (m == TL__M_GLASS) mat->flags = TL_MATERIAL_ALPHA_BLEND;
        strncpy(mat->name, def->name, sizeof(mat->name) - 1);
    }
}

/* Lights placed around the solids and warm spots the layout recorded (crypt_lights.c). */
static void tl__crypt_light_set(tl_scene *scene, const tl__crypt *layout, const tl_default_scene_desc *d,
                                size_t light_count)
{
    float solids[TL__MAX_SOLIDS][6];
    for (size_t i = 0; i < layout->solid_count; i++) {
        const tl_object *o = &scene->objects[layout->solids[i]];
        memcpy(solids[i], o->bounds_min, 3 * sizeof(float));
        memcpy(solids[i] + 3, o->bounds_max, 3 * sizeof(float));
    }
    tl__light_plan plan = {
        .point_lights = d->point_lights,
        .spot_lights = d->spot_lights,
        .directional = !d->no_directional,
        .seed = d->seed,
        .solids = (const float (*)[6])solids,
        .solid_count = layout->solid_count,
        .warm_spots = (const float (*)[3])layout->warm,
        .warm_spot_count = layout->warm_count,
        .shadows = d->shadows,
    };
    tl__crypt_lights(&plan, scene->lights);
    scene->light_count = light_count;
}

/* Ambient, the camera down the nave, and the bounds of every vertex. */
static void tl__crypt_view(tl_scene *scene)
{
    scene->ambient[0] = 0.015f;
    scene->ambient[1] = 0.015f;
    scene->ambient[2] = 0.02f;
    scene->camera = (tl_camera){
        .position = {0.0f, 2.0f, 18.5f},
        .target = {0.0f, 1.0f, 0.0f},
        .up = {0.0f, 1.0f, 0.0f},
        .fov_y = (float)(TL__PI / 3.0),
        .near_z = 0.1f,
        .far_z = 100.0f,
    };
    for (int k = 0; k < 3; k++) {
        scene->bounds_min[k] = INFINITY;
        scene->bounds_max[k] = -INFINITY;
    }
    for (size_t v = 0; v < scene->vertex_count; v++) {
        for (int k = 0; k < 3; k++) {
            float p = scene->vertices[v].position[k];
            if (p < scene->bounds_min[k]) scene->bounds_min[k] = p;
            if (p > scene->bounds_max[k]) scene->bounds_max[k] = p;
        }
    }
}

tl_result tl_scene_create_default(const tl_default_scene_desc *desc, tl_scene **out)
{
    tl_default_scene_desc d = desc ? *desc : (tl_default_scene_desc){0};
    const tl_logger *log = &d.logger;
    if (!out) return tl__logger_fail(log, TL_ERROR_INVALID_ARGUMENT, "default scene: no place for the scene (out is NULL)");
    *out = NULL;
    if ((d.allocator.alloc == NULL) != (d.allocator.free == NULL))
        return tl__logger_fail(log, TL_ERROR_INVALID_ARGUMENT, "default scene: the allocator needs both alloc and free");
    if (d.detail > TL__MAX_DETAIL)
        return tl__logger_fail(log, TL_ERROR_INVALID_ARGUMENT, "default scene: detail = %u: outside 1..%u (0: 4)",
                               d.detail, TL__MAX_DETAIL);
    if (d.glass_panes > TL__MAX_GLASS)
        return tl__logger_fail(log, TL_ERROR_INVALID_ARGUMENT, "default scene: glass_panes = %u: outside 0..%u",
                               d.glass_panes, TL__MAX_GLASS);
    if (d.point_lights > TL__MAX_LIGHTS || d.spot_lights > TL__MAX_LIGHTS)
        return tl__logger_fail(log, TL_ERROR_LIMIT, "default scene: %s = %u: over the limit of %u",
                               d.point_lights > TL__MAX_LIGHTS ? "point_lights" : "spot_lights",
                               d.point_lights > TL__MAX_LIGHTS ? d.point_lights : d.spot_lights, TL__MAX_LIGHTS);
    if (d.point_lights == 0) d.point_lights = 64;
    if (d.spot_lights == 0) d.spot_lights = d.point_lights / 8;
    if (d.seed == 0) d.seed = 1;
    if (d.detail == 0) d.detail = 4;

    /* pass 1: count */
    tl__builder counter = {.counting = 1};
    tl__crypt layout = {.b = &counter, .detail = d.detail, .glass_panes = d.glass_panes};
    tl__crypt_build(&layout);
    if (counter.vertex_count > UINT32_MAX || counter.index_count > UINT32_MAX)
        return tl__logger_fail(log, TL_ERROR_LIMIT, "default scene: %zu vertices, %zu indices: past 32-bit indices",
                               counter.vertex_count, counter.index_count);
    size_t light_count = (size_t)d.point_lights + d.spot_lights + (d.no_directional ? 0 : 1);
    tl_scene *scene = tl__crypt_alloc(&d.allocator, &counter, light_count);
    if (!scene) return tl__logger_fail(log, TL_ERROR_OUT_OF_MEMORY, "default scene: out of memory");

    /* pass 2: write */
    tl__builder writer = {
        .vertices = scene->vertices,
        .vertex_capacity = counter.vertex_count,
        .indices = scene->indices,
        .index_capacity = counter.index_count,
        .objects = scene->objects,
        .object_capacity = counter.object_count,
    };
    layout = (tl__crypt){.b = &writer, .detail = d.detail, .glass_panes = d.glass_panes};
    tl__crypt_build(&layout);
    if (writer.overflow || writer.vertex_count != counter.vertex_count ||
        writer.index_count != counter.index_count || writer.object_count != counter.object_count) {
        tl_scene_destroy(scene); /* the two passes disagreed: a bug, never a partial scene */
        return tl__logger_fail(log, TL_ERROR_LIMIT, "default scene: the counting and the writing pass disagree");
    }
    scene->vertex_count = writer.vertex_count;
    scene->index_count = writer.index_count;
    scene->object_count = writer.object_count;
    tl__crypt_material_table(scene, d.glass_panes > 0);
    tl__crypt_light_set(scene, &layout, &d, light_count);
    tl__crypt_view(scene);
    *out = scene;
    return TL_OK;
}
