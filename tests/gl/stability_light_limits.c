/* Absurd lights (docs/renderer-limits.md): any finite radius from 1e-30 to 3e38 and any finite
 * intensity leave every target of every mode finite; a negative intensity is taken as 0, so it
 * renders exactly as a black light does (it gave -inf in the FP16 targets before). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "stability.h"
#include "tl_test.h"

static void absurd_scene(mini_scene *m, float radius, float intensity)
{
    mini_init(m, 1.0471976f, 0.1f, 100.0f);
    m->mat[0] = plain_material(0.5f, 0.5f, 0.5f);
    add_wall(m, 5.0f, 0);
    m->light[0] = point_light(0.0f, 0.0f, -4.0f, radius, intensity, intensity, intensity);
    m->light[1] = point_light(0.5f, 0.2f, -4.0f, radius, intensity, intensity, intensity);
    m->light[2] = m->light[0];
    m->light[2].type = TL_LIGHT_SPOT;
    m->light[2].direction[2] = -1.0f;
    m->light[2].direction[1] = 0.0f;
    m->light[2].cos_inner = 0.9f;
    m->light[2].cos_outer = 0.8f;
    m->s.light_count = 3;
}

TL_TEST(stability_absurd_light_radius_and_intensity_finite)
{
    static const float radii[] = {1e-30f, 6.0f, 1e12f, 3e38f};
    static const float intensities[] = {0.0f, 1e6f, 3e38f, -3e38f};
    static const tl_render_mode modes[] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_FORWARD};
    for (size_t mi = 0; mi < 4; mi++)
        for (size_t ri = 0; ri < 4; ri++) {
            float *black = NULL; /* the HDR target with intensity 0 (intensities[0]) */
            for (size_t ii = 0; ii < 4; ii++) {
                mini_scene m;
                absurd_scene(&m, radii[ri], intensities[ii]);
                char label[96];
                snprintf(label, sizeof label, "%s radius %g intensity %g", tl_render_mode_name(modes[mi]), radii[ri],
                         intensities[ii]);
                run u;
                if (!run_scene(&u, (tl_renderer_desc){.width = 32, .height = 24, .options.mode = modes[mi]}, &m.s,
                               label))
                    continue;
                size_t bad = 0;
                count_nonfinite_all_targets(u.r, label, &bad);
                if (bad) fprintf(stderr, "  %s: %zu non-finite values\n", label, bad);
                TL_CHECK_EQ_U(bad, 0);
                float *hdr = read_target(u.r, TL_TARGET_HDR);
                size_t bytes = (size_t)32 * 24 * 4 * sizeof(float);
                if (ii == 0) black = hdr;
                else if (intensities[ii] < 0.0f) TL_CHECK(hdr && black && memcmp(hdr, black, bytes) == 0);
                if (hdr != black) free(hdr);
                run_free(&u);
            }
            free(black);
        }
}
