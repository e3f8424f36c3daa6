/* Primitive generators for the built-in scene: flat quads, prisms and boxes, surfaces of
 * revolution, groin vaults, arches and walls with niches. Everything is written in world space
 * (object transforms are identity), normals are unit and point out of the solid (into the room
 * for walls and vaults), and every triangle is counter-clockwise seen from that side. */
#include <math.h>
#include <string.h>

#include "scene_internal.h"

#define TL__PI 3.14159265358979323846

/* ---- small vector helpers ------------------------------------------------------------------ */

static void tl__set3(float o[3], double x, double y, double z)
{
    o[0] = (float)x;
    o[1] = (float)y;
    o[2] = (float)z;
}

static void tl__sub3(float o[3], const float a[3], const float b[3])
{
    o[0] = a[0] - b[0];
    o[1] = a[1] - b[1];
    o[2] = a[2] - b[2];
}

static void tl__cross3(float o[3], const float a[3], const float b[3])
{
    float x = a[1] * b[2] - a[2] * b[1];
    float y = a[2] * b[0] - a[0] * b[2];
    float z = a[0] * b[1] - a[1] * b[0];
    o[0] = x;
    o[1] = y;
    o[2] = z;
}

static float tl__dot3(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Normalises in double; returns 0 (and leaves o unchanged) for a zero or non-finite vector. */
static int tl__normalize3(float o[3], const float v[3])
{
    double x = v[0], y = v[1], z = v[2];
    double len = sqrt(x * x + y * y + z * z);
    if (!(len > 1e-20) || !isfinite(len)) return 0;
    tl__set3(o, x / len, y / len, z / len);
    return 1;
}

/* ---- builder ---------------------------------------------------------------------------------- */

void tl__begin_object(tl__builder *b, uint32_t material, float uv_scale)
{
    b->object_first_vertex = b->vertex_count;
    b->object_first_index = b->index_count;
    b->material = material;
    b->uv_scale = uv_scale;
}

size_t tl__end_object(tl__builder *b)
{
    size_t index = b->object_count++;
    if (b->counting) return index;
    if (index >= b->object_capacity) {
        b->overflow = 1;
        return index;
    }
    tl_object *o = &b->objects[index];
    memset(o, 0, sizeof(*o));
    o->first_index = (uint32_t)b->object_first_index;
    o->index_count = (uint32_t)(b->index_count - b->object_first_index);
    o->material = b->material;
    o->transform[0] = o->transform[5] = o->transform[10] = o->transform[15] = 1.0f;
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    size_t end = b->vertex_count < b->vertex_capacity ? b->vertex_count : b->vertex_capacity;
    for (size_t v = b->object_first_vertex; v < end; v++) {
        for (int k = 0; k < 3; k++) {
            float p = b->vertices[v].position[k];
            if (p < lo[k]) lo[k] = p;
            if (p > hi[k]) hi[k] = p;
        }
    }
    if (end <= b->object_first_vertex) {
        for (int k = 0; k < 3; k++) lo[k] = hi[k] = 0.0f;
    }
    memcpy(o->bounds_min, lo, sizeof(lo));
    memcpy(o->bounds_max, hi, sizeof(hi));
    return index;
}

uint32_t tl__vertex(tl__builder *b, const float p[3], const float n[3], const float uv[2],
                    const float dpdu[3], const float dpdv[3])
{
    uint32_t index = (uint32_t)b->vertex_count;
    b->vertex_count++;
    if (b->counting) return index;
    if (index >= b->vertex_capacity) {
        b->overflow = 1;
        return 0;
    }
    tl_vertex *v = &b->vertices[index];
    float nn[3], t[3];
    if (!tl__normalize3(nn, n)) tl__set3(nn, 0, 1, 0);
    float d = tl__dot3(nn, dpdu);
    tl__set3(t, dpdu[0] - nn[0] * d, dpdu[1] - nn[1] * d, dpdu[2] - nn[2] * d);
    if (!tl__normalize3(t, t)) {
        /* no usable u direction: any unit vector perpendicular to the normal */
        float axis[3];
        if (fabsf(nn[1]) < 0.9f)
            tl__set3(axis, 0, 1, 0);
        else
            tl__set3(axis, 1, 0, 0);
        tl__cross3(t, axis, nn);
        tl__normalize3(t, t);
    }
    float bt[3];
    tl__cross3(bt, nn, t);
    memcpy(v->position, p, sizeof(v->position));
    memcpy(v->normal, nn, sizeof(v->normal));
    v->uv[0] = uv[0];
    v->uv[1] = uv[1];
    memcpy(v->tangent, t, sizeof(t));
    v->tangent[3] = tl__dot3(bt, dpdv) < 0.0f ? -1.0f : 1.0f;
    return index;
}

void tl__triangle(tl__builder *b, uint32_t i0, uint32_t i1, uint32_t i2)
{
    size_t at = b->index_count;
    b->index_count += 3;
    if (b->counting) return;
    if (at + 3 > b->index_capacity || i0 >= b->vertex_capacity || i1 >= b->vertex_capacity ||
        i2 >= b->vertex_capacity) {
        b->overflow = 1;
        return;
    }
    const tl_vertex *v0 = &b->vertices[i0], *v1 = &b->vertices[i1], *v2 = &b->vertices[i2];
    float e1[3], e2[3], fn[3], vn[3];
    tl__sub3(e1, v1->position, v0->position);
    tl__sub3(e2, v2->position, v0->position);
    tl__cross3(fn, e1, e2);
    for (int k = 0; k < 3; k++) vn[k] = v0->normal[k] + v1->normal[k] + v2->normal[k];
    if (tl__dot3(fn, vn) < 0.0f) {
        uint32_t t = i1;
        i1 = i2;
        i2 = t;
    }
    b->indices[at] = i0;
    b->indices[at + 1] = i1;
    b->indices[at + 2] = i2;
}

void tl__quad_indices(tl__builder *b, uint32_t a, uint32_t c1, uint32_t c2, uint32_t d)
{
    tl__triangle(b, a, c1, c2);
    tl__triangle(b, a, c2, d);
}

/* ---- flat quads ------------------------------------------------------------------------------- */

static void tl__planar_uv(const tl__builder *b, float uv[2], const float p[3], const float ua[3],
                          const float va[3])
{
    uv[0] = tl__dot3(p, ua) * b->uv_scale;
    uv[1] = tl__dot3(p, va) * b->uv_scale;
}

/* A flat quad with planar UVs along the unit axes ua, va. */
static void tl__flat_quad_axes(tl__builder *b, const float p0[3], const float p1[3],
                               const float p2[3], const float p3[3], const float n[3],
                               const float ua[3], const float va[3], uint32_t nu, uint32_t nv)
{
    if (nu < 1) nu = 1;
    if (nv < 1) nv = 1;
    uint32_t base = (uint32_t)b->vertex_count;
    for (uint32_t j = 0; j <= nv; j++) {
        double t = (double)j / nv;
        for (uint32_t i = 0; i <= nu; i++) {
            double s = (double)i / nu;
            float p[3], uv[2];
            for (int k = 0; k < 3; k++) {
                double bottom = p0[k] + s * (p1[k] - p0[k]);
                double top = p3[k] + s * (p2[k] - p3[k]);
                p[k] = (float)(bottom + t * (top - bottom));
            }
            /* exact corners, so that neighbouring quads meet bit for bit */
            if (i == 0 && j == 0) memcpy(p, p0, sizeof(p));
            if (i == nu && j == 0) memcpy(p, p1, sizeof(p));
            if (i == nu && j == nv) memcpy(p, p2, sizeof(p));
            if (i == 0 && j == nv) memcpy(p, p3, sizeof(p));
            tl__planar_uv(b, uv, p, ua, va);
            tl__vertex(b, p, n, uv, ua, va);
        }
    }
    for (uint32_t j = 0; j < nv; j++) {
        for (uint32_t i = 0; i < nu; i++) {
            uint32_t a = base + j * (nu + 1) + i;
            tl__quad_indices(b, a, a + 1, a + nu + 2, a + nu + 1);
        }
    }
}

void tl__flat_quad(tl__builder *b, const float p0[3], const float p1[3], const float p2[3],
                   const float p3[3], const float n[3], uint32_t nu, uint32_t nv)
{
    float ua[3], va[3], e[3];
    tl__sub3(e, p1, p0);
    if (!tl__normalize3(ua, e)) tl__set3(ua, 1, 0, 0);
    tl__cross3(va, n, ua); /* completes the frame in the quad's plane */
    if (!tl__normalize3(va, va)) tl__set3(va, 0, 0, 1);
    tl__flat_quad_axes(b, p0, p1, p2, p3, n, ua, va, nu, nv);
}

/* ---- prisms and boxes ------------------------------------------------------------------------- */

void tl__prism(tl__builder *b, const float origin[3], const float a[3], const float bax[3],
               const float e[3], float length, const float (*pts)[2], size_t count)
{
    if (count < 3) return;
    float c2[2] = {0, 0};
    for (size_t k = 0; k < count; k++) {
        c2[0] += pts[k][0] / (float)count;
        c2[1] += pts[k][1] / (float)count;
    }
    float centroid[3];
    for (int i = 0; i < 3; i++) centroid[i] = origin[i] + a[i] * c2[0] + bax[i] * c2[1];

    /* sides */
    float perimeter = 0.0f;
    float down[3] = {-e[0], -e[1], -e[2]};
    for (size_t k = 0; k < count; k++) {
        size_t k1 = (k + 1) % count;
        float p[4][3];
        for (int i = 0; i < 3; i++) {
            p[0][i] = origin[i] + a[i] * pts[k][0] + bax[i] * pts[k][1];
            p[1][i] = origin[i] + a[i] * pts[k1][0] + bax[i] * pts[k1][1];
            p[2][i] = p[1][i] + e[i] * length;
            p[3][i] = p[0][i] + e[i] * length;
        }
        float edge[3], dir[3], n[3], mid[3], out[3];
        tl__sub3(edge, p[1], p[0]);
        if (!tl__normalize3(dir, edge)) continue;
        tl__cross3(n, dir, e);
        tl__normalize3(n, n);
        for (int i = 0; i < 3; i++) mid[i] = 0.5f * (p[0][i] + p[1][i]);
        tl__sub3(out, mid, centroid);
        if (tl__dot3(out, n) < 0.0f) tl__set3(n, -n[0], -n[1], -n[2]);
        float elen = sqrtf(tl__dot3(edge, edge));
        uint32_t base = (uint32_t)b->vertex_count;
        for (int c = 0; c < 4; c++) {
            float uv[2];
            uv[0] = (perimeter + ((c == 1 || c == 2) ? elen : 0.0f)) * b->uv_scale;
            uv[1] = -((c >= 2) ? length : 0.0f) * b->uv_scale;
            tl__vertex(b, p[c], n, uv, dir, down);
        }
        perimeter += elen;
        tl__quad_indices(b, base, base + 1, base + 2, base + 3);
    }

    /* caps: fans over the convex polygon */
    for (int cap = 0; cap < 2; cap++) {
        float n[3];
        double s = cap ? 1.0 : -1.0;
        tl__set3(n, s * e[0], s * e[1], s * e[2]);
        uint32_t base = (uint32_t)b->vertex_count;
        for (size_t k = 0; k < count; k++) {
            float p[3], uv[2];
            for (int i = 0; i < 3; i++)
                p[i] = origin[i] + a[i] * pts[k][0] + bax[i] * pts[k][1] + (cap ? e[i] * length : 0.0f);
            tl__planar_uv(b, uv, p, a, bax);
            tl__vertex(b, p, n, uv, a, bax);
        }
        for (size_t k = 1; k + 1 < count; k++)
            tl__triangle(b, base, base + (uint32_t)k, base + (uint32_t)k + 1);
    }
}

void tl__box(tl__builder *b, const float centre[3], const float half[3], float yaw)
{
    double c = cos(yaw), s = sin(yaw);
    float a[3], bax[3], e[3] = {0, 1, 0}, origin[3];
    tl__set3(a, c, 0, -s);
    tl__set3(bax, s, 0, c);
    tl__set3(origin, centre[0], centre[1] - half[1], centre[2]);
    const float pts[4][2] = {
        {-half[0], -half[2]}, {half[0], -half[2]}, {half[0], half[2]}, {-half[0], half[2]}};
    tl__prism(b, origin, a, bax, e, 2.0f * half[1], pts, 4);
}

/* ---- surfaces of revolution ------------------------------------------------------------------ */

static void tl__lathe_pos(const tl__lathe_desc *d, size_t i, double phi, float out[3])
{
    const tl__profile_point *pp = &d->points[i];
    double c = cos(phi), s = sin(phi);
    double sq = pp->square > 2.0f ? pp->square : 2.0;
    if (sq != 2.0) {
        double k = pow(pow(fabs(c), sq) + pow(fabs(s), sq), -1.0 / sq);
        c *= k;
        s *= k;
    }
    tl__set3(out, d->centre[0] + pp->r * c, d->centre[1] + pp->y, d->centre[2] + pp->r * s);
}

void tl__lathe(tl__builder *b, const tl__lathe_desc *d)
{
    if (d->count < 2 || d->segments < 3) return;
    int full = d->phi0 == d->phi1;
    double phi0 = full ? 0.0 : d->phi0;
    double phi1 = full ? 2.0 * TL__PI : d->phi1;
    uint32_t segs = d->segments;

    /* u repeats a whole number of times around a full turn so the seam does not show */
    double rmax = 0.0;
    for (size_t i = 0; i < d->count; i++)
        if (d->points[i].r > rmax) rmax = d->points[i].r;
    double reps = floor(2.0 * TL__PI * rmax * b->uv_scale + 0.5);
    if (reps < 1.0) reps = 1.0;
    double u_per_radian = reps / (2.0 * TL__PI);

    double arc = 0.0; /* profile arc length at the start of the current run */
    size_t s = 0;
    while (s + 1 < d->count) {
        size_t e = s + 1;
        while (e + 1 < d->count && !d->points[e].crease) e++;
        uint32_t run_base = (uint32_t)b->vertex_count;
        double run_arc = arc;
        for (size_t i = s; i <= e; i++) {
            if (i > s) {
                double dr = d->points[i].r - d->points[i - 1].r;
                double dy = d->points[i].y - d->points[i - 1].y;
                run_arc += sqrt(dr * dr + dy * dy);
            }
            size_t ia = i > s ? i - 1 : i, ib = i < e ? i + 1 : i;
            int pole = d->points[i].r == 0.0f;
            /* the pole's normal is vertical, on the side the neighbouring segment faces */
            double seg_dr = i == s ? d->points[s + 1].r - d->points[s].r
                                   : d->points[i].r - d->points[i - 1].r;
            for (uint32_t j = 0; j <= segs; j++) {
                double phi = phi0 + (phi1 - phi0) * j / segs;
                double phi_pos = (full && j == segs) ? phi0 : phi; /* closed seam, bit for bit */
                float p[3], pa[3], pb[3], pl[3], pr[3], dt[3], dphi[3], n[3], uv[2], dpdv[3];
                tl__lathe_pos(d, i, phi_pos, p);
                tl__lathe_pos(d, ia, phi_pos, pa);
                tl__lathe_pos(d, ib, phi_pos, pb);
                tl__sub3(dt, pb, pa);
                const double h = 1e-3;
                tl__lathe_pos(d, i, phi_pos - h, pl);
                tl__lathe_pos(d, i, phi_pos + h, pr);
                tl__sub3(dphi, pr, pl);
                tl__cross3(n, dt, dphi);
                if (pole || !tl__normalize3(n, n)) tl__set3(n, 0, seg_dr > 0.0 ? -1.0 : 1.0, 0);
                if (d->inward) tl__set3(n, -n[0], -n[1], -n[2]);
                if (pole || !tl__normalize3(dphi, dphi)) tl__set3(dphi, -sin(phi), 0, cos(phi));
                tl__set3(dpdv, -dt[0], -dt[1], -dt[2]);
                uv[0] = (float)((phi - phi0) * u_per_radian);
                uv[1] = (float)(-run_arc * b->uv_scale);
                tl__vertex(b, p, n, uv, dphi, dpdv);
            }
        }
        for (size_t i = s; i < e; i++) {
            uint32_t r0 = run_base + (uint32_t)(i - s) * (segs + 1);
            uint32_t r1 = r0 + segs + 1;
            int pole0 = d->points[i].r == 0.0f, pole1 = d->points[i + 1].r == 0.0f;
            for (uint32_t j = 0; j < segs; j++) {
                if (!pole0) tl__triangle(b, r0 + j, r1 + j, r0 + j + 1);
                if (!pole1) tl__triangle(b, r0 + j + 1, r1 + j, r1 + j + 1);
            }
        }
        arc = run_arc;
        s = e;
    }
}

/* ---- groin vault ------------------------------------------------------------------------------- */

void tl__groin_vault(tl__builder *b, float cx, float cz, float r, float y0, uint32_t n)
{
    if (n < 1) n = 1;
    static const float axes[4][3] = {{0, 0, 1}, {1, 0, 0}, {0, 0, -1}, {-1, 0, 0}};
    for (int sector = 0; sector < 4; sector++) {
        /* barrel along A (out of the bay centre through one edge), profile along Q = Y x A */
        const float *A = axes[sector];
        float Q[3], Y[3] = {0, 1, 0};
        tl__cross3(Q, Y, A);
        uint32_t base = (uint32_t)b->vertex_count;
        for (uint32_t i = 0; i <= n; i++) {
            double psi = 0.5 * TL__PI * i / n;
            double along = r * sin(psi);
            for (uint32_t j = 0; j <= i; j++) {
                double phi = i == 0 ? 0.0 : psi * (2.0 * j / i - 1.0);
                double sp = sin(phi), cp = cos(phi);
                float p[3], nrm[3], uv[2], dpdu[3];
                tl__set3(p, cx + Q[0] * r * sp + A[0] * along, y0 + r * cp,
                         cz + Q[2] * r * sp + A[2] * along);
                tl__set3(nrm, -Q[0] * sp, -cp, -Q[2] * sp);
                tl__set3(dpdu, Q[0] * cp, -sp, Q[2] * cp);
                uv[0] = (float)(r * phi * b->uv_scale);
                uv[1] = (float)(along * b->uv_scale);
                tl__vertex(b, p, nrm, uv, dpdu, A);
            }
        }
        for (uint32_t i = 0; i < n; i++) {
            uint32_t r0 = base + i * (i + 1) / 2, r1 = base + (i + 1) * (i + 2) / 2;
            for (uint32_t j = 0; j <= i; j++) tl__triangle(b, r0 + j, r1 + j, r1 + j + 1);
            for (uint32_t j = 0; j < i; j++) tl__triangle(b, r0 + j, r1 + j + 1, r0 + j + 1);
        }
    }
}

/* ---- arches ------------------------------------------------------------------------------------ */

void tl__arch(tl__builder *b, const float centre[3], const float span[3], float ri, float ro,
              float hw, uint32_t segments)
{
    if (segments < 2) segments = 2;
    float H[3], W[3], Y[3] = {0, 1, 0}, down[3] = {0, -1, 0};
    tl__normalize3(H, span);
    tl__cross3(W, H, Y);
    tl__normalize3(W, W);

    /* intrados (faces the arch centre) and extrados */
    for (int outer = 0; outer < 2; outer++) {
        float rho = outer ? ro : ri;
        uint32_t base = (uint32_t)b->vertex_count;
        for (uint32_t k = 0; k <= segments; k++) {
            double th = TL__PI * k / segments;
            double c = k == segments ? -1.0 : cos(th), s = k == segments ? 0.0 : sin(th);
            float R[3], n[3], dr[3];
            tl__set3(R, c * H[0], s, c * H[2]);
            tl__set3(dr, -s * H[0], c, -s * H[2]);
            tl__set3(n, outer ? R[0] : -R[0], outer ? R[1] : -R[1], outer ? R[2] : -R[2]);
            for (int side = 0; side < 2; side++) {
                double w = side ? hw : -hw;
                float p[3], uv[2];
                tl__set3(p, centre[0] + rho * R[0] + w * W[0], centre[1] + rho * R[1],
                         centre[2] + rho * R[2] + w * W[2]);
                uv[0] = (float)(rho * th * b->uv_scale);
                uv[1] = (float)(w * b->uv_scale);
                tl__vertex(b, p, n, uv, dr, W);
            }
        }
        for (uint32_t k = 0; k < segments; k++) {
            uint32_t a = base + 2 * k;
            tl__quad_indices(b, a, a + 2, a + 3, a + 1);
        }
    }

    /* the two flat faces */
    for (int side = 0; side < 2; side++) {
        double w = side ? hw : -hw;
        float n[3];
        tl__set3(n, side ? W[0] : -W[0], 0, side ? W[2] : -W[2]);
        uint32_t base = (uint32_t)b->vertex_count;
        for (uint32_t k = 0; k <= segments; k++) {
            double th = TL__PI * k / segments;
            double c = k == segments ? -1.0 : cos(th), s = k == segments ? 0.0 : sin(th);
            for (int outer = 0; outer < 2; outer++) {
                double rho = outer ? ro : ri;
                float p[3], uv[2];
                tl__set3(p, centre[0] + rho * c * H[0] + w * W[0], centre[1] + rho * s,
                         centre[2] + rho * c * H[2] + w * W[2]);
                uv[0] = (float)(rho * c * b->uv_scale);
                uv[1] = (float)(-rho * s * b->uv_scale);
                tl__vertex(b, p, n, uv, H, down);
            }
        }
        for (uint32_t k = 0; k < segments; k++) {
            uint32_t a = base + 2 * k;
            tl__quad_indices(b, a, a + 2, a + 3, a + 1);
        }
    }

    /* the feet, facing down onto their supports */
    for (int foot = 0; foot < 2; foot++) {
        double c = foot ? -1.0 : 1.0;
        float p[4][3];
        for (int q = 0; q < 4; q++) {
            double rho = (q == 1 || q == 2) ? ro : ri;
            double w = q >= 2 ? hw : -hw;
            tl__set3(p[q], centre[0] + rho * c * H[0] + w * W[0], centre[1],
                     centre[2] + rho * c * H[2] + w * W[2]);
        }
        tl__flat_quad(b, p[0], p[1], p[2], p[3], down, 1, 1);
    }
}

/* ---- walls with niches ------------------------------------------------------------------------- */

#define TL__WALL_MAX_SAMPLES 400

typedef struct tl__wall_sample {
    float u;
    float top;  /* the niche head's height at u, when inside the opening */
    int inside; /* within [uc - na, uc + na] */
} tl__wall_sample;

static void tl__wall_frame(const tl__wall_desc *d, float U[3])
{
    float Y[3] = {0, 1, 0};
    tl__cross3(U, Y, d->normal);
    tl__normalize3(U, U);
}

static void tl__wall_point(const tl__wall_desc *d, const float U[3], double u, double y, double depth,
                           float p[3])
{
    tl__set3(p, d->origin[0] + U[0] * u - d->normal[0] * depth, d->origin[1] + y,
             d->origin[2] + U[2] * u - d->normal[2] * depth);
}

static double tl__wall_top(const tl__wall_desc *d, double u)
{
    double r = 0.5 * d->w, x = u - r;
    double h = d->y_spring;
    if (u > 0.0 && u < d->w) h += sqrt(fmax(0.0, r * r - x * x));
    return h + d->top_margin;
}

static size_t tl__wall_samples(const tl__wall_desc *d, tl__wall_sample *out)
{
    size_t n = 0;
    uint32_t L = d->lunette_segments < 2 ? 2 : d->lunette_segments;
    uint32_t M = d->niche_segments < 2 ? 2 : d->niche_segments;
    if (L > 180) L = 180;
    if (M > 180) M = 180;
    double uc = 0.5 * d->w, r = 0.5 * d->w;
    double lo = uc - d->na, hi = uc + d->na;
    int inserted = 0;
    if (d->u0 < 0.0f) out[n++] = (tl__wall_sample){d->u0, 0.0f, 0};
    for (uint32_t j = 0; j <= L; j++) {
        double u = j == 0 ? 0.0 : j == L ? d->w : uc - r * cos(TL__PI * j / L);
        if (d->niche && !inserted && u > lo - 0.02) {
            /* the opening's head samples replace the lunette samples it covers */
            for (uint32_t k = 0; k <= M; k++) {
                double a = TL__PI * k / M;
                double uu = k == 0 ? lo : k == M ? hi : uc - d->na * cos(a);
                double top = d->level_spring + (k == 0 || k == M ? 0.0 : d->na * sin(a));
                out[n++] = (tl__wall_sample){(float)uu, (float)top, 1};
            }
            inserted = 1;
        }
        if (d->niche && u > lo - 0.02 && u < hi + 0.02) continue;
        out[n++] = (tl__wall_sample){(float)u, 0.0f, 0};
    }
    if (d->u1 > d->w) out[n++] = (tl__wall_sample){d->u1, 0.0f, 0};
    return n;
}

static void tl__wall_quad(tl__builder *b, const tl__wall_desc *d, const float U[3], double ua,
                          double ya0, double ya1, double ub, double yb0, double yb1)
{
    float p[4][3], va[3] = {0, -1, 0};
    tl__wall_point(d, U, ua, ya0, 0.0, p[0]);
    tl__wall_point(d, U, ub, yb0, 0.0, p[1]);
    tl__wall_point(d, U, ub, yb1, 0.0, p[2]);
    tl__wall_point(d, U, ua, ya1, 0.0, p[3]);
    tl__flat_quad_axes(b, p[0], p[1], p[2], p[3], d->normal, U, va, 1, 1);
}

void tl__wall(tl__builder *b, const tl__wall_desc *d)
{
    tl__wall_sample s[TL__WALL_MAX_SAMPLES];
    size_t n = tl__wall_samples(d, s);
    float U[3];
    tl__wall_frame(d, U);
    const double bottom = -0.05; /* sunk below the floor: no crack along the skirting */
    for (size_t k = 0; k + 1 < n; k++) {
        double ua = s[k].u, ub = s[k + 1].u;
        if (!(ub > ua)) continue;
        double ha = tl__wall_top(d, ua), hb = tl__wall_top(d, ub);
        if (s[k].inside && s[k + 1].inside) {
            tl__wall_quad(b, d, U, ua, bottom, d->level_sill, ub, bottom, d->level_sill);
            tl__wall_quad(b, d, U, ua, s[k].top, ha, ub, s[k + 1].top, hb);
        } else {
            tl__wall_quad(b, d, U, ua, bottom, d->level_sill, ub, bottom, d->level_sill);
            tl__wall_quad(b, d, U, ua, d->level_sill, d->level_spring, ub, d->level_sill,
                          d->level_spring);
            tl__wall_quad(b, d, U, ua, d->level_spring, ha, ub, d->level_spring, hb);
        }
    }
}

void tl__niche_recess(tl__builder *b, const tl__wall_desc *d)
{
    if (!d->niche) return;
    uint32_t M = d->niche_segments < 2 ? 2 : d->niche_segments;
    if (M > 180) M = 180;
    float U[3], Y[3] = {0, 1, 0}, va[3] = {0, -1, 0}, in[3];
    tl__wall_frame(d, U);
    tl__set3(in, -d->normal[0], -d->normal[1], -d->normal[2]);
    double uc = 0.5 * d->w;

    /* outline counter-clockwise seen from the room: sill, right jamb, head, left jamb */
    size_t count = M + 3;
    double ou[TL__WALL_MAX_SAMPLES], oy[TL__WALL_MAX_SAMPLES];
    float on[TL__WALL_MAX_SAMPLES][3]; /* normal of the recess surface at that outline point */
    ou[0] = uc - d->na;
    oy[0] = d->level_sill;
    ou[1] = uc + d->na;
    oy[1] = d->level_sill;
    for (uint32_t k = 0; k <= M; k++) {
        uint32_t kk = M - k; /* from the right jamb's top over to the left's */
        double a = TL__PI * kk / M;
        ou[2 + k] = kk == 0 ? uc - d->na : kk == M ? uc + d->na : uc - d->na * cos(a);
        oy[2 + k] = d->level_spring + (kk == 0 || kk == M ? 0.0 : d->na * sin(a));
        double c = kk == M ? -1.0 : kk == 0 ? 1.0 : cos(a), s = kk == 0 || kk == M ? 0.0 : sin(a);
        tl__set3(on[2 + k], c * U[0] - s * Y[0], -s, c * U[2] - s * Y[2]);
    }

    /* sides: one quad per outline edge, from the wall face back to the recess's depth */
    double along = 0.0;
    for (size_t k = 0; k < count; k++) {
        size_t k1 = (k + 1) % count;
        float p[4][3], n0[3], n1[3], edge[3], dir[3];
        tl__wall_point(d, U, ou[k], oy[k], 0.0, p[0]);
        tl__wall_point(d, U, ou[k1], oy[k1], 0.0, p[1]);
        tl__wall_point(d, U, ou[k1], oy[k1], d->nd, p[2]);
        tl__wall_point(d, U, ou[k], oy[k], d->nd, p[3]);
        tl__sub3(edge, p[1], p[0]);
        if (!tl__normalize3(dir, edge)) continue;
        int head = k >= 2 && k1 >= 2; /* both ends on the curved head */
        if (head) {
            memcpy(n0, on[k], sizeof(n0));
            memcpy(n1, on[k1], sizeof(n1));
        } else {
            /* flat: rotate the edge a quarter turn towards the opening's inside */
            float fn[3];
            tl__cross3(fn, d->normal, dir);
            tl__normalize3(fn, fn);
            memcpy(n0, fn, sizeof(n0));
            memcpy(n1, fn, sizeof(n1));
        }
        double elen = sqrt(tl__dot3(edge, edge));
        uint32_t base = (uint32_t)b->vertex_count;
        for (int c = 0; c < 4; c++) {
            float uv[2];
            uv[0] = (float)((along + ((c == 1 || c == 2) ? elen : 0.0)) * b->uv_scale);
            uv[1] = (float)((c >= 2 ? d->nd : 0.0) * b->uv_scale);
            tl__vertex(b, p[c], (c == 1 || c == 2) ? n1 : n0, uv, dir, in);
        }
        along += elen;
        tl__quad_indices(b, base, base + 1, base + 2, base + 3);
    }

    /* back: a fan from a point inside the (convex) outline */
    uint32_t centre;
    {
        float p[3], uv[2];
        tl__wall_point(d, U, uc, 0.5 * (d->level_sill + d->level_spring), d->nd, p);
        tl__planar_uv(b, uv, p, U, va);
        centre = tl__vertex(b, p, d->normal, uv, U, va);
    }
    uint32_t base = (uint32_t)b->vertex_count;
    for (size_t k = 0; k < count; k++) {
        float p[3], uv[2];
        tl__wall_point(d, U, ou[k], oy[k], d->nd, p);
        tl__planar_uv(b, uv, p, U, va);
        tl__vertex(b, p, d->normal, uv, U, va);
    }
    for (size_t k = 0; k < count; k++)
        tl__triangle(b, centre, base + (uint32_t)k, base + (uint32_t)((k + 1) % count));
}
