/* Uses the codec alone (thinlight::codec / pkg-config thinlight-codec): a normal and gloss through
 * RT0 and back, and the version of the library actually loaded. Exit 0 when all is well. */
#include <stdio.h>
#include <string.h>

#include "thinlight/codec.h"
#include "thinlight/metrics.h"
#include "thinlight/version.h"

int main(void)
{
    const float n[3] = {0.0f, 0.6f, -0.8f};
    uint8_t texel[4];
    float back[3], gloss = 0.0f;
    tl_rt0_encode_rgba8(n, 0.75f, texel);
    tl_rt0_decode_rgba8(texel, back, &gloss);
    double angle = tl_angle_deg(n, back);
    float gloss_error = gloss > 0.75f ? gloss - 0.75f : 0.75f - gloss; /* (no libm needed here) */
    int ok = angle < 0.05 && gloss_error < 0.5f / 255.0f;
    printf("rt0 round trip: %.4f degrees, gloss %.4f\n", angle, gloss);

    /* The header and the library agree. */
    if (tl_version() != TL_VERSION) {
        printf("tl_version() = %u, TL_VERSION = %u\n", (unsigned)tl_version(), (unsigned)TL_VERSION);
        ok = 0;
    }
    char expected[32];
    snprintf(expected, sizeof expected, "%d.%d.%d", TL_VERSION_MAJOR, TL_VERSION_MINOR, TL_VERSION_PATCH);
    if (strcmp(tl_version_string(), expected) != 0) {
        printf("tl_version_string() = %s, headers say %s\n", tl_version_string(), expected);
        ok = 0;
    }
#ifdef EXPECTED_VERSION
    if (strcmp(tl_version_string(), EXPECTED_VERSION) != 0) {
        printf("tl_version_string() = %s, the build system says %s\n", tl_version_string(), EXPECTED_VERSION);
        ok = 0;
    }
#endif
    printf("thinlight %s: %s\n", tl_version_string(), ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
