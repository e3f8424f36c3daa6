/* The screen-space effects' per-frame parameters (docs/effects.md): the resolved options of SSAO,
 * fog, depth of field, reflections and bloom, with the camera's time and focus, into the frame's uniform block. */
#include <string.h>

#include "renderer_internal.h"

void tl__frame_ubo_effects(const tl_renderer_desc *d, const tl__view *v, tl__frame_ubo *u)
{
    const tl_ssao_desc *s = &d->options.ssao;
    const tl_fog_desc *f = &d->options.fog;
    u->ssao[0] = s->radius;
    u->ssao[1] = s->bias;
    u->ssao[2] = s->falloff;
    u->ssao[3] = s->exponent;
    memcpy(u->fog_color, f->color, sizeof f->color);
    u->fog_color[3] = f->density;
    u->fog[0] = f->height;
    u->fog[1] = f->height_falloff;
    u->fog[2] = f->noise;
    u->fog[3] = f->noise_scale;
    u->effects[0] = f->noise_speed;
    u->effects[1] = v->time;
    u->effects[2] = d->options.dof.focus_distance > 0.0f ? d->options.dof.focus_distance : v->target_distance;
    u->effects[3] = d->options.dof.aperture;
    u->dof[0] = d->options.dof.max_radius;
    u->bloom[0] = d->options.bloom.threshold;
    u->bloom[1] = d->options.bloom.knee * d->options.bloom.threshold;
    u->bloom[2] = d->options.bloom.intensity;
    u->bloom[3] = d->options.bloom.scatter;
    u->ssr[0] = d->options.ssr.max_distance;
    u->ssr[1] = d->options.ssr.thickness;
    u->ssr[2] = d->options.ssr.min_gloss;
    u->ssr[3] = d->options.ssr.edge_fade;
    u->ssr2[0] = d->options.ssr.intensity;
    u->ssr2[1] = v->near_z;
}
