// Private: the little linear algebra the glTF adapter needs. Transforms compose in double (deep
// hierarchies keep their precision) and are stored as float in the scene. Column-major, as glTF.
#ifndef TL_GLTF_MATH_H
#define TL_GLTF_MATH_H

#include <cfloat>
#include <cmath>

namespace tl_gltf {

// double to float without undefined behaviour: out-of-range values saturate at +-FLT_MAX (a
// plain conversion of a value float cannot hold is undefined in C++).
inline float to_float(double v)
{
    if (v > FLT_MAX) return FLT_MAX;
    if (v < -FLT_MAX) return -FLT_MAX;
    return (float)v;
}

// Whether a double fits a float without saturating (NaN does not).
inline bool fits_float(double v) { return v >= -FLT_MAX && v <= FLT_MAX; }

inline void mat_identity(double m[16])
{
    for (int i = 0; i < 16; i++) m[i] = (i % 5 == 0) ? 1.0 : 0.0;
}

// out = a * b (out may alias neither).
inline void mat_mul(const double a[16], const double b[16], double out[16])
{
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++) {
            double s = 0.0;
            for (int k = 0; k < 4; k++) s += a[k * 4 + r] * b[c * 4 + k];
            out[c * 4 + r] = s;
        }
}

// T * R * S with the unit quaternion q = (x, y, z, w).
inline void mat_trs(const double t[3], const double q[4], const double s[3], double m[16])
{
    double x = q[0], y = q[1], z = q[2], w = q[3];
    double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),
                   2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                   2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y)};
    for (int c = 0; c < 3; c++) {
        for (int k = 0; k < 3; k++) m[c * 4 + k] = r[c * 3 + k] * s[c];
        m[c * 4 + 3] = 0.0;
    }
    m[12] = t[0];
    m[13] = t[1];
    m[14] = t[2];
    m[15] = 1.0;
}

inline void mat_point(const double m[16], const double p[3], double out[3])
{
    for (int r = 0; r < 3; r++) out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
}

inline void mat_dir(const double m[16], const double d[3], double out[3])
{
    for (int r = 0; r < 3; r++) out[r] = m[r] * d[0] + m[4 + r] * d[1] + m[8 + r] * d[2];
}

// Normalises v in place; returns false (v unchanged) when its length is zero or not finite.
template <class T> inline bool normalize3(T v[3])
{
    double l = std::sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]);
    if (!(l > 1e-30) || !std::isfinite(l)) return false;
    for (int i = 0; i < 3; i++) v[i] = (T)(v[i] / l);
    return true;
}

template <class T> inline void cross3(const T a[3], const T b[3], T out[3])
{
    T x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2], z = a[0] * b[1] - a[1] * b[0];
    out[0] = x;
    out[1] = y;
    out[2] = z;
}

template <class T> inline T dot3(const T a[3], const T b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Centre and half diagonal of scene bounds, for placing the default lights and camera. An empty
// or point-like box counts as a unit one; the radius is capped at 1e18 so that everything derived
// from it (light colours grow with radius^2) stays finite in single precision.
inline void scene_frame(const float bmin[3], const float bmax[3], double centre[3], double *radius)
{
    double d2 = 0.0;
    for (int k = 0; k < 3; k++) {
        centre[k] = 0.5 * ((double)bmin[k] + bmax[k]);
        double e = (double)bmax[k] - bmin[k];
        d2 += e * e;
    }
    double r = 0.5 * std::sqrt(d2);
    *radius = r > 1e-6 ? (r < 1e18 ? r : 1e18) : 0.5;
}

} // namespace tl_gltf

#endif
