/* The effect options of the tools (tool_effects.h). */
#include "tool_effects.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char tl_tool_effects_help[] =
    "  --ssao                screen-space ambient occlusion (disc estimator); --ssao-method disc|hemisphere,\n"
    "                        --ssao-samples N (16), --ssao-radius R (1), --ssao-bias K_B (0),\n"
    "                        --ssao-falloff K_D (2 R), --ssao-exponent X (3), --ssao-blur PX (2),\n"
    "                        --ssao-diffuse (AO scales the diffuse light too: thin-lpp, forward)\n"
    "  --fog                 distance fog; --fog-mode distance|height, --fog-density D (0.05),\n"
    "                        --fog-color R,G,B (0,0,0), --fog-height Y (0), --fog-falloff K (0.5),\n"
    "                        --fog-noise 0..1 (0)\n"
    "  --dof                 depth of field; --dof-focus DIST (camera target), --dof-aperture A (0.01 of\n"
    "                        the height), --dof-max M (2 A), --dof-samples N (48)\n"
    "  --bloom               bloom; --bloom-threshold T (1; 0: everything), --bloom-knee K (0.5 of T),\n"
    "                        --bloom-intensity I (0.5), --bloom-scatter S (0.7), --bloom-levels N (6, 1..8)\n"
    "  --ssr                 screen-space reflections (thin-lpp, thin-deferred, fat); --ssr-steps N (48),\n"
    "                        --ssr-distance D (16), --ssr-thickness T (0.4), --ssr-min-gloss G (0.4),\n"
    "                        --ssr-intensity I (1)\n";

static int tl__bad(const char *tool, const char *opt, const char *value, const char *want)
{
    fprintf(stderr, "%s: %s %s: %s\n", tool, opt, value ? value : "(missing)", want);
    return -1;
}

static int tl__float(const char *s, float *out)
{
    char *end;
    errno = 0;
    float v = s ? strtof(s, &end) : 0.0f;
    if (!s || errno || end == s || *end || !isfinite(v)) return 0;
    *out = v;
    return 1;
}

static int tl__u32(const char *s, uint32_t *out)
{
    char *end;
    errno = 0;
    unsigned long v = s ? strtoul(s, &end, 10) : 0;
    if (!s || errno || end == s || *end || s[0] == '-' || v > 0xFFFFFFFFul) return 0;
    *out = (uint32_t)v;
    return 1;
}

static int tl__flag(tl_renderer_desc *d, const char *opt)
{
    if (!strcmp(opt, "--ssao")) {
        if (d->ssao.method == TL_SSAO_OFF) d->ssao.method = TL_SSAO_DISC;
    } else if (!strcmp(opt, "--ssao-diffuse")) d->ssao.diffuse = 1;
    else if (!strcmp(opt, "--fog")) {
        if (d->fog.mode == TL_FOG_OFF) d->fog.mode = TL_FOG_DISTANCE;
    } else if (!strcmp(opt, "--dof")) d->dof.enabled = 1;
    else if (!strcmp(opt, "--bloom")) d->bloom.enabled = 1;
    else if (!strcmp(opt, "--ssr")) d->ssr.enabled = 1;
    else return 0;
    return 1;
}

static int tl__ssao_value(const char *tool, tl_ssao_desc *s, const char *opt, const char *v)
{
    int ok = 1;
    if (!strcmp(opt, "--ssao-method")) {
        if (v && !strcmp(v, "disc")) s->method = TL_SSAO_DISC;
        else if (v && !strcmp(v, "hemisphere")) s->method = TL_SSAO_HEMISPHERE;
        else return tl__bad(tool, opt, v, "wants disc or hemisphere");
    } else if (!strcmp(opt, "--ssao-samples")) ok = tl__u32(v, &s->samples) && s->samples >= 1 && s->samples <= 64;
    else if (!strcmp(opt, "--ssao-radius")) ok = tl__float(v, &s->radius) && s->radius > 0.0f;
    else if (!strcmp(opt, "--ssao-bias")) ok = tl__float(v, &s->bias) && s->bias >= 0.0f;
    else if (!strcmp(opt, "--ssao-falloff")) ok = tl__float(v, &s->falloff) && s->falloff > 0.0f;
    else if (!strcmp(opt, "--ssao-exponent")) ok = tl__float(v, &s->exponent) && s->exponent > 0.0f;
    else if (!strcmp(opt, "--ssao-blur")) ok = tl__u32(v, &s->blur_radius) && s->blur_radius >= 1 && s->blur_radius <= 8;
    else return 0;
    return ok ? 2 : tl__bad(tool, opt, v, "out of range (see --help)");
}

static int tl__fog_value(const char *tool, tl_fog_desc *f, const char *opt, const char *v)
{
    int ok = 1;
    if (!strcmp(opt, "--fog-mode")) {
        if (v && !strcmp(v, "distance")) f->mode = TL_FOG_DISTANCE;
        else if (v && !strcmp(v, "height")) f->mode = TL_FOG_HEIGHT;
        else return tl__bad(tool, opt, v, "wants distance or height");
    } else if (!strcmp(opt, "--fog-density")) ok = tl__float(v, &f->density) && f->density > 0.0f;
    else if (!strcmp(opt, "--fog-height")) ok = tl__float(v, &f->height);
    else if (!strcmp(opt, "--fog-falloff")) ok = tl__float(v, &f->height_falloff) && f->height_falloff > 0.0f;
    else if (!strcmp(opt, "--fog-noise")) ok = tl__float(v, &f->noise) && f->noise >= 0.0f && f->noise <= 1.0f;
    else if (!strcmp(opt, "--fog-color")) {
        char extra;
        ok = v && sscanf(v, "%f,%f,%f%c", &f->color[0], &f->color[1], &f->color[2], &extra) == 3;
        for (int k = 0; ok && k < 3; k++) ok = isfinite(f->color[k]) && f->color[k] >= 0.0f;
    } else return 0;
    return ok ? 2 : tl__bad(tool, opt, v, "out of range (see --help)");
}

static int tl__dof_value(const char *tool, tl_dof_desc *f, const char *opt, const char *v)
{
    int ok = 1;
    if (!strcmp(opt, "--dof-focus")) ok = tl__float(v, &f->focus_distance) && f->focus_distance > 0.0f;
    else if (!strcmp(opt, "--dof-aperture")) ok = tl__float(v, &f->aperture) && f->aperture > 0.0f && f->aperture <= 1.0f;
    else if (!strcmp(opt, "--dof-max")) ok = tl__float(v, &f->max_radius) && f->max_radius > 0.0f && f->max_radius <= 1.0f;
    else if (!strcmp(opt, "--dof-samples")) ok = tl__u32(v, &f->samples) && f->samples >= 8 && f->samples <= 128;
    else return 0;
    return ok ? 2 : tl__bad(tool, opt, v, "out of range (see --help)");
}

/* Zero means "the default" in tl_bloom_desc: an explicit 0 threshold or knee is passed as -1 (exactly 0). */
static int tl__bloom_value(const char *tool, tl_bloom_desc *b, const char *opt, const char *v)
{
    int ok = 1;
    if (!strcmp(opt, "--bloom-threshold")) {
        ok = tl__float(v, &b->threshold) && b->threshold >= 0.0f;
        if (ok && b->threshold == 0.0f) b->threshold = -1.0f;
    } else if (!strcmp(opt, "--bloom-knee")) {
        ok = tl__float(v, &b->knee) && b->knee >= 0.0f && b->knee <= 1.0f;
        if (ok && b->knee == 0.0f) b->knee = -1.0f;
    } else if (!strcmp(opt, "--bloom-intensity")) ok = tl__float(v, &b->intensity) && b->intensity > 0.0f;
    else if (!strcmp(opt, "--bloom-scatter")) ok = tl__float(v, &b->scatter) && b->scatter > 0.0f && b->scatter <= 1.0f;
    else if (!strcmp(opt, "--bloom-levels")) ok = tl__u32(v, &b->levels) && b->levels >= 1 && b->levels <= 8;
    else return 0;
    return ok ? 2 : tl__bad(tool, opt, v, "out of range (see --help)");
}

static int tl__ssr_value(const char *tool, tl_ssr_desc *f, const char *opt, const char *v)
{
    int ok = 1;
    if (!strcmp(opt, "--ssr-steps")) ok = tl__u32(v, &f->steps) && f->steps >= 4 && f->steps <= 256;
    else if (!strcmp(opt, "--ssr-distance")) ok = tl__float(v, &f->max_distance) && f->max_distance > 0.0f;
    else if (!strcmp(opt, "--ssr-thickness")) ok = tl__float(v, &f->thickness) && f->thickness > 0.0f;
    else if (!strcmp(opt, "--ssr-min-gloss")) {
        ok = tl__float(v, &f->min_gloss) && f->min_gloss >= 0.0f && f->min_gloss < 1.0f;
        if (ok && f->min_gloss == 0.0f) f->min_gloss = -1.0f; /* exactly 0 (zero is the default, 0.4) */
    } else if (!strcmp(opt, "--ssr-intensity")) ok = tl__float(v, &f->intensity) && f->intensity > 0.0f;
    else return 0;
    return ok ? 2 : tl__bad(tool, opt, v, "out of range (see --help)");
}

int tl_tool_effect_option(const char *tool, tl_renderer_desc *d, const char *opt, const char *value)
{
    if (tl__flag(d, opt)) return 1;
    int rc = tl__ssao_value(tool, &d->ssao, opt, value);
    if (!rc) rc = tl__fog_value(tool, &d->fog, opt, value);
    if (!rc) rc = tl__dof_value(tool, &d->dof, opt, value);
    if (!rc) rc = tl__bloom_value(tool, &d->bloom, opt, value);
    if (!rc) rc = tl__ssr_value(tool, &d->ssr, opt, value);
    return rc;
}
