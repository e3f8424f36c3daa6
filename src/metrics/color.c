/* sRGB to CIE L*a*b* and the CIEDE2000 colour difference. */
#include <math.h>

#include "thinlight/metrics.h"

#define TL__PI 3.14159265358979323846
#define TL__DEG (TL__PI / 180.0)

/* IEC 61966-2-1 decoding curve (exact piecewise form, not a 2.2 power). */
static double tl__srgb_to_linear(double c)
{
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

/* CIE f(t) with the exact rational constants (epsilon = 216/24389, kappa = 24389/27), so the
 * two branches meet without a step. */
static double tl__lab_f(double t)
{
    return t > 216.0 / 24389.0 ? cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0;
}

void tl_srgb_to_lab(const double srgb[3], double lab[3])
{
    if (!lab) return;
    if (!srgb) {
        lab[0] = lab[1] = lab[2] = NAN;
        return;
    }
    double r = tl__srgb_to_linear(srgb[0]), g = tl__srgb_to_linear(srgb[1]),
           b = tl__srgb_to_linear(srgb[2]);
    /* sRGB primaries to XYZ at 7 decimals: rows sum to the D65 white below, so that sRGB white
     * lands on a* = b* = 0 (the rounded 4-decimal matrix misses by 0.01). */
    double x = 0.4124564 * r + 0.3575761 * g + 0.1804375 * b;
    double y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
    double z = 0.0193339 * r + 0.1191920 * g + 0.9503041 * b;
    double fx = tl__lab_f(x / 0.95047), fy = tl__lab_f(y), fz = tl__lab_f(z / 1.08883);
    /* L* from its own branch so that black is exactly 0 rather than 116 * (16/116) - 16. */
    lab[0] = y > 216.0 / 24389.0 ? 116.0 * fy - 16.0 : 24389.0 / 27.0 * y;
    lab[1] = 500.0 * (fx - fy);
    lab[2] = 200.0 * (fy - fz);
}

/* sqrt(c^7 / (c^7 + 25^7)), written so that c = 0 and huge c give 0 and 1 rather than NaN. */
static double tl__chroma_weight(double c)
{
    double c2 = c * c, c7 = c2 * c2 * c2 * c;
    return 1.0 / sqrt(1.0 + 6103515625.0 / c7);
}

/* Hue angle in [0, 360) degrees; 0 for the neutral axis (Sharma et al. eq. 7). */
static double tl__hue_deg(double b, double ap)
{
    if (ap == 0.0 && b == 0.0) return 0.0;
    double h = atan2(b, ap) / TL__DEG;
    if (h < 0.0) h += 360.0;
    if (h >= 360.0) h -= 360.0; /* -tiny + 360 rounds to 360 */
    return h;
}

/* Sharma, Wu and Dalal, "The CIEDE2000 color-difference formula: implementation notes,
 * supplementary test data, and mathematical observations", Color Res. Appl. 30(1), 2005.
 * Equation numbers below are theirs. */
double tl_ciede2000(const double lab1[3], const double lab2[3])
{
    if (!lab1 || !lab2) return NAN;
    double L1 = lab1[0], a1 = lab1[1], b1 = lab1[2];
    double L2 = lab2[0], a2 = lab2[1], b2 = lab2[2];

    /* (2)-(7) */
    double cab = 0.5 * (sqrt(a1 * a1 + b1 * b1) + sqrt(a2 * a2 + b2 * b2));
    double g = 0.5 * (1.0 - tl__chroma_weight(cab));
    double a1p = (1.0 + g) * a1, a2p = (1.0 + g) * a2;
    double c1p = sqrt(a1p * a1p + b1 * b1), c2p = sqrt(a2p * a2p + b2 * b2);
    double h1p = tl__hue_deg(b1, a1p), h2p = tl__hue_deg(b2, a2p);

    /* (8)-(10), (14). Whether |h1' - h2'| exceeds 180 decides both the hue difference and the
     * mean hue; pairs 9-14 of the paper's data sit exactly on 180. Rounded angles cannot settle
     * that tie, so near 180 the sign of the exact-ish cross product decides: going from the
     * smaller hue to the larger one turns counter-clockwise by at most 180 iff it is >= 0. */
    double dLp = L2 - L1, dCp = c2p - c1p, dhp = 0.0, hbar;
    double cprod = c1p * c2p;
    if (cprod == 0.0) {
        hbar = h1p + h2p;
    } else {
        double diff = h2p - h1p;
        int wraps;
        if (fabs(fabs(diff) - 180.0) < 1e-6) {
            double cross = a1p * b2 - b1 * a2p;
            wraps = diff >= 0.0 ? cross < 0.0 : cross > 0.0;
        } else {
            wraps = fabs(diff) > 180.0;
        }
        dhp = !wraps ? diff : diff > 0.0 ? diff - 360.0 : diff + 360.0;
        double sum = h1p + h2p;
        hbar = !wraps ? 0.5 * sum : sum < 360.0 ? 0.5 * (sum + 360.0) : 0.5 * (sum - 360.0);
    }
    double dHp = 2.0 * sqrt(cprod) * sin(0.5 * dhp * TL__DEG);

    /* (12)-(22) with kL = kC = kH = 1 */
    double lbar = 0.5 * (L1 + L2), cbar = 0.5 * (c1p + c2p);
    double t = 1.0 - 0.17 * cos((hbar - 30.0) * TL__DEG) + 0.24 * cos(2.0 * hbar * TL__DEG) +
               0.32 * cos((3.0 * hbar + 6.0) * TL__DEG) - 0.20 * cos((4.0 * hbar - 63.0) * TL__DEG);
    double hr = (hbar - 275.0) / 25.0;
    double dtheta = 30.0 * exp(-hr * hr);
    double rc = 2.0 * tl__chroma_weight(cbar);
    double l50 = (lbar - 50.0) * (lbar - 50.0);
    double sl = 1.0 + 0.015 * l50 / sqrt(20.0 + l50);
    double sc = 1.0 + 0.045 * cbar;
    double sh = 1.0 + 0.015 * cbar * t;
    double rt = -sin(2.0 * dtheta * TL__DEG) * rc;
    double tl = dLp / sl, tc = dCp / sc, th = dHp / sh;
    double e2 = tl * tl + tc * tc + th * th + rt * tc * th;
    return e2 < 0.0 ? 0.0 : sqrt(e2); /* rounding may leave a tiny negative; NaN stays NaN */
}
