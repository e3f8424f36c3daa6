/* Angle between two directions. */
#include <math.h>

#include "thinlight/metrics.h"

double tl_angle_deg(const float a[3], const float b[3])
{
    if (!a || !b) return 180.0;
    /* Floats widen exactly and each product of two floats is exact in double, so the cross
     * product of nearly parallel vectors keeps its tiny magnitude instead of cancelling. */
    double ax = a[0], ay = a[1], az = a[2], bx = b[0], by = b[1], bz = b[2];
    if (!(isfinite(ax) && isfinite(ay) && isfinite(az) && isfinite(bx) && isfinite(by) &&
          isfinite(bz)))
        return 180.0;
    if ((ax == 0.0 && ay == 0.0 && az == 0.0) || (bx == 0.0 && by == 0.0 && bz == 0.0))
        return 180.0;
    double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    double dot = ax * bx + ay * by + az * bz;
    /* atan2 stays well conditioned at 0 and 180 degrees, where acos(dot) loses half its digits. */
    return atan2(sqrt(cx * cx + cy * cy + cz * cz), dot) * (180.0 / 3.14159265358979323846);
}
