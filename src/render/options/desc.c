/* Renderer options with their defaults resolved (the one place a zeroed field becomes a value):
 * every field's range and single default from the option registry, what depends on several
 * fields here and in each pass's resolve (tl__pass_def.resolve). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "plan_internal.h"

/* Resolved options: the registry's check (every field in range, option_check.h), its defaults,
 * then what depends on several fields (each pass's resolve: effects that are off zeroed whole,
 * defaults computed from other fields). */
tl_result tl__options_resolve(const tl_renderer_options *in, tl_renderer_options *out, tl__why *why)
{
    *out = *in;
    if (!tl__options_check(in, why)) return TL_ERROR_INVALID_ARGUMENT;
    tl__options_defaults(out);
    if (out->shadows.filter == TL_SHADOW_FILTER_BILINEAR) { /* the PCF kernel of radius 0 */
        out->shadows.filter = TL_SHADOW_FILTER_PCF;
        out->shadows.pcf_radius = 0;
    }
    /* R11G11B10F has no alpha for the compact layout's specular luminance */
    if (out->light_format == TL_LIGHT_FORMAT_R11G11B10F && out->light_buffer != TL_LIGHT_BUFFER_EXACT) {
        tl__why_say(why, "options.light_format = %d (R11G11B10F) needs options.light_buffer = %d (EXACT), not %d",
                    (int)out->light_format, (int)TL_LIGHT_BUFFER_EXACT, (int)out->light_buffer);
        return TL_ERROR_INVALID_ARGUMENT;
    }
    for (int i = 0; i < TL_PASS_COUNT; i++) {
        const tl__pass_def *def = tl__pass_table[i];
        if (def->resolve) def->resolve((char *)out + def->options_offset);
    }
    return TL_OK;
}

tl_result tl__renderer_desc_resolve(const tl_renderer_desc *in, tl_renderer_desc *d, tl__why *why)
{
    tl_renderer_desc r = *in;
    if (!r.width) r.width = 1280;
    if (!r.height) r.height = 720;
    tl_result res = tl__options_resolve(&in->options, &r.options, why);
    *d = r;
    if (res != TL_OK) return res;
    if (r.width > TL__MAX_SIZE || r.height > TL__MAX_SIZE) {
        tl__why_say(why, "size %ux%u is over %u per side", r.width, r.height, TL__MAX_SIZE);
        return TL_ERROR_LIMIT;
    }
    return TL_OK;
}
