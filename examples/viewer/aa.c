/* The antialiasing control (key M and the panel): none, FXAA or MSAA with 2, 4 or 8 samples, as
 * the two options that make it: tl_renderer_options.fxaa and .msaa. */
#include "viewer.h"

static const char *const vw_aa_names[VW_AA_COUNT] = {"none", "FXAA", "MSAA 2x", "MSAA 4x", "MSAA 8x"};

vw_aa vw_aa_of(const tl_renderer_options *o)
{
    if (o->msaa > 1) return o->msaa >= 8 ? VW_AA_MSAA8 : o->msaa >= 4 ? VW_AA_MSAA4 : VW_AA_MSAA2;
    return o->fxaa == TL_FXAA_OFF ? VW_AA_NONE : VW_AA_FXAA;
}

const char *vw_aa_name(vw_aa a) { return (unsigned)a < VW_AA_COUNT ? vw_aa_names[a] : "?"; }

void vw_aa_set(vw_app *app, vw_aa a)
{
    tl_renderer_options *o = &app->desc.options;
    o->msaa = a >= VW_AA_MSAA2 ? 2u << (a - VW_AA_MSAA2) : 1u;
    o->fxaa = a == VW_AA_FXAA ? TL_FXAA_29 : TL_FXAA_OFF;
    app->rebuild = 1;
}

void vw_aa_cycle(vw_app *app) { vw_aa_set(app, (vw_aa)((vw_aa_of(&app->desc.options) + 1) % VW_AA_COUNT)); }
