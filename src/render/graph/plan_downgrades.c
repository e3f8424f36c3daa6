/* The plan's downgrades (docs/frame.md, "Downgrades"): every option the caller set to a value whose
 * pass, method or saving the plan leaves out or replaces, with what it asked, what the plan does
 * instead and why, in tl_frame_plan.downgrades (the renderer logs each once, the tools print it).
 * An option that only describes a part the mode or strategy does not have (the light buffer's
 * layout outside thin-lpp, RT0's packing in fat, tile sizes with volumes) replaces nothing and is
 * not one. Pure: reads the plan's input as plan.c resolved it. */
#include <stdio.h>
#include <string.h>

#include "plan_internal.h"

static void tl__downgrade(tl_frame_plan *p, const char *option, const char *asked, const char *planned, const char *why)
{
    if (p->downgrade_count >= TL_PLAN_MAX_DOWNGRADES) return; /* more rows than the table below has: never */
    tl_plan_downgrade *d = &p->downgrades[p->downgrade_count++];
    snprintf(d->option, sizeof d->option, "%s", option);
    snprintf(d->asked, sizeof d->asked, "%s", asked);
    snprintf(d->planned, sizeof d->planned, "%s", planned);
    snprintf(d->reason, sizeof d->reason, "%s", why);
}

/* MSAA, the light scale, transparency, the clearcoat's sums and the Fresnel layout. */
static void tl__downgrades_lighting(const tl__plan_input *in, tl_frame_plan *p)
{
    const tl_renderer_options *o = in->o;
    char asked[24];
    if (o->msaa > 1u && in->msaa <= 1u) {
        snprintf(asked, sizeof asked, "%u", (unsigned)o->msaa);
        tl__downgrade(p, "msaa", asked, "1", tl__msaa_refusal(o));
    }
    if (o->light_scale != 1.0f && !in->light_shift) {
        snprintf(asked, sizeof asked, "%g", (double)o->light_scale);
        tl__downgrade(p, "light_scale", asked, "1", "only thin-lpp has a light buffer to reduce");
    }
    if (o->transparency == TL_TRANSPARENCY_STIPPLE && in->transparency_why)
        tl__downgrade(p, "transparency", "stipple", "forward", in->transparency_why);
    if (o->clearcoat == TL_CLEARCOAT_SUMS && in->coat_why) tl__downgrade(p, "clearcoat", "sums", "approx", in->coat_why);
    /* asked, not defaulted: the compact layout's default is one sum */
    if (in->asked.fresnel == TL_FRESNEL_TWO_SUMS && in->fresnel == TL_FRESNEL_NV)
        tl__downgrade(p, "fresnel", "two-sums", "nv", "the compact light buffer keeps one specular sum");
    if (in->mode->visibility && o->light_strategy == TL_LIGHT_STRATEGY_VOLUMES)
        tl__downgrade(p, "light_strategy", "volumes", "tiled", "visibility: the resolve lights from the tile lists");
    if (in->mode->visibility && o->tiled_shading == TL_TILED_SHADING_FRAGMENT)
        tl__downgrade(p, "tiled_shading", "fragment", "compute", "visibility: the resolve is a compute pass");
    if (o->fullscreen_lights && in->lights && (in->mode->forward || in->strategy == TL_LIGHT_STRATEGY_TILED))
        tl__downgrade(p, "fullscreen_lights", "1", "0",
                      in->mode->forward ? "forward draws no light volumes" : "the tiled strategy draws no light volumes");
}

/* The effects and the passes the options ask for by a flag. */
static void tl__downgrades_passes(const tl__plan_input *in, tl_frame_plan *p)
{
    const tl_renderer_options *o = in->o;
    if (o->ssr.enabled && in->mode->forward)
        tl__downgrade(p, "ssr.enabled", "1", "0", "forward has no G-buffer gloss to read");
    if (o->ssao.enabled && !tl__ssao_pass(in))
        tl__downgrade(p, "ssao.enabled", "1", "0",
                      "forward without its depth pre-pass (forward_depth_prepass off) has no depth to read");
    if (o->forward_depth_prepass == TL_SWITCH_OFF && in->mode->forward && tl__forward_plus(in))
        tl__downgrade(p, "forward_depth_prepass", "off", "on", "Forward+ culls its tiles on the pre-pass's depth");
    /* without a casting light there is no shadow to show: nothing replaced */
    if (o->shadow_debug && in->shadows && !tl__shadow_debug_planned(in))
        tl__downgrade(p, "shadow_debug", "1", "0", "a multisampled G-buffer or depth (MSAA) would need a sample chosen");
}

void tl__plan_downgrades(const tl__plan_input *in, tl_frame_plan *p)
{
    p->downgrade_count = 0;
    tl__downgrades_lighting(in, p);
    tl__downgrades_passes(in, p);
}

size_t tl_plan_downgrade_format(const tl_plan_downgrade *d, char *buffer, size_t size)
{
    if (buffer && size) buffer[0] = '\0';
    if (!d) return 0;
    int n = snprintf(buffer, buffer ? size : 0, "options.%s = %s is planned as %s: %s", d->option, d->asked, d->planned,
                     d->reason);
    return n > 0 ? (size_t)n : 0;
}
