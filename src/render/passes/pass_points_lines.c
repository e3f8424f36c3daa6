/* Points and lines (tl_object.primitive): they have no surface for a G-buffer, so every mode draws
 * them here, after the opaque frame, with the forward shader and their objects' light lists: lit
 * with their normal, or facing the viewer where it is zero (material.glsl), 1 pixel wide. In the
 * plan only when the scene draws some (docs/gltf.md, "Points and lines"). */
#include <stdio.h>

#include "gl/gl.h"
#include "lights.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

/* Depth-tested against the opaque frame without writing depth, as the transparent pass after it:
 * the passes after the frame read depth as the opaque surfaces left it. */
static void tl__points_lines_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->f.has_points_lines) return;
    d->writes = TL__B(HDR);
    d->depth_target = (uint8_t)tl__shading_depth(in); /* HDR's own samples with MSAA */
    d->reads = TL_TARGET_BIT(d->depth_target) | TL__B(HDR); /* drawn onto */
    d->attach_depth = 1;
    d->light_data = TL__LIGHTS_VIEW | TL__LIGHTS_INDEX_BUFFER | TL__LIGHTS_OBJECT_LISTS;
    d->state = (tl__pipeline){.depth_test = TL__DEPTH_LEQUAL, .color_write = 1,
                              .clip_zero_one = in->o->depth_format == TL_DEPTH_FORMAT_D32F_REVERSED};
}

static void tl__points_lines_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    out->used[0] = 1;
    tl__perm_flag(&out->slot[0], TL__F_FORWARD);
    tl__perm_merge(&out->slot[0], &in->spec_perm);
    tl__perm_merge(&out->slot[0], &in->material);
}

const tl__pass_def tl__pass_points_lines = {
    .id = TL_PASS_POINTS_LINES,
    .name = "points-lines",
    .programs = {{"points-lines", "gbuffer.vert.glsl", "forward.frag.glsl"}},
    .declare = tl__points_lines_declare,
    .permute = tl__points_lines_permute,
    .execute = tl__draw_points_lines,
    .services = TL__PASS_SCENE,
};
