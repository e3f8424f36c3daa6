/* The plan as text (--print-plan): the compiled pass table with each pass's reads, writes and
 * clears, every target's lifetime and memory, the shared blocks, attributes, the choices with
 * their reasons and the downgrades, and programs. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "gl/gl.h"
#include "thinlight/renderer.h"

typedef struct tl__out {
    char *buf;
    size_t size, len;
} tl__out;

static void tl__printf(tl__out *o, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *dst = o->len < o->size ? o->buf + o->len : NULL;
    int n = vsnprintf(dst, dst ? o->size - o->len : 0, fmt, ap);
    va_end(ap);
    if (n > 0) o->len += (size_t)n;
}

static void tl__print_targets(tl__out *o, tl_target_set bits)
{
    if (!bits) {
        tl__printf(o, "-");
        return;
    }
    const char *sep = "";
    for (int i = 0; i < TL_TARGET_COUNT; i++)
        if (bits & TL_TARGET_BIT(i)) {
            tl__printf(o, "%s%s", sep, tl_target_name((tl_target_id)i));
            sep = ", ";
        }
}

static void tl__print_passes(tl__out *o, const tl_frame_plan *p)
{
    tl__printf(o, "passes:\n");
    int width = p->pass_count >= 10 ? 2 : 1; /* numbers right-aligned: the names stay in a column */
    for (size_t i = 0; i < p->pass_count; i++) {
        const tl_plan_pass *pp = &p->passes[i];
        tl__printf(o, "  %*zu %-13s reads ", width, i + 1, pp->name);
        tl__print_targets(o, pp->reads);
        tl__printf(o, "; writes ");
        tl__print_targets(o, pp->writes);
        if (pp->clears) {
            tl__printf(o, "; clears ");
            tl__print_targets(o, pp->clears);
        }
        tl__printf(o, "%s\n", pp->pass == TL_PASS_COUNT ? " (application)" : "");
    }
}

static void tl__print_targets_table(tl__out *o, const tl_frame_plan *p)
{
    tl__printf(o, "targets (bytes per pixel, lifetime in passes, memory block):\n");
    for (int i = 0; i < TL_TARGET_COUNT; i++) {
        const tl_plan_target *t = &p->target_info[i];
        if (!t->bytes_per_pixel) continue;
        char last[16];
        if (t->last_pass >= p->pass_count) snprintf(last, sizeof last, "end");
        else snprintf(last, sizeof last, "%u", t->last_pass + 1);
        tl__printf(o, "  %-15s %2u  %u..%-3s  block %u%s", tl_target_name((tl_target_id)i), t->bytes_per_pixel,
                   t->first_pass + 1, last, t->block,
                   (p->blocks[t->block].targets & ~TL_TARGET_BIT(i)) ? " (shared)" : "");
        if (t->levels > 1 || t->width != p->width || t->height != p->height)
            tl__printf(o, " (%ux%u, %u level%s, %zu bytes)", t->width, t->height, t->levels, t->levels > 1 ? "s" : "",
                       t->bytes);
        if (t->samples > 1) tl__printf(o, " (%u samples)", t->samples);
        tl__printf(o, "\n");
    }
    tl__printf(o, "  %-15s %2u (G-buffer and light buffer: %u)\n", "sum", p->bytes_per_pixel, p->gbuffer_bytes_per_pixel);
    tl__printf(o, "  %-15s %2u in %zu blocks (most live at once: %u; %.2f MiB)\n", "allocated",
               p->allocated_bytes_per_pixel, p->block_count, p->peak_live_bytes_per_pixel,
               (double)p->allocated_bytes / 1048576.0);
}

size_t tl_frame_plan_format(const tl_frame_plan *p, char *buffer, size_t size)
{
    tl__out o = {buffer, buffer ? size : 0, 0};
    if (buffer && size) buffer[0] = '\0';
    if (!p) return 0;
    tl__printf(&o, "frame plan: mode %s, %ux%u\n", tl_render_mode_name(p->mode), p->width, p->height);
    tl__print_passes(&o, p);
    tl__print_targets_table(&o, p);
    tl__printf(&o, "vertex attributes: position, normal%s%s%s%s\n", p->vertex_attributes & TL_ATTRIBUTE_UV ? ", uv" : "",
               p->vertex_attributes & TL_ATTRIBUTE_TANGENT ? ", tangent" : "",
               p->vertex_attributes & TL_ATTRIBUTE_COLOR ? ", color" : "",
               p->vertex_attributes & TL_ATTRIBUTE_UV1 ? ", uv1" : "");
    tl__printf(&o, "light types:%s%s%s%s\n", p->light_types & (1u << TL_LIGHT_POINT) ? " point" : "",
               p->light_types & (1u << TL_LIGHT_SPOT) ? " spot" : "",
               p->light_types & (1u << TL_LIGHT_DIRECTIONAL) ? " directional" : "", p->light_types ? "" : " none");
    tl__printf(&o, "light strategy: %s (%s)", tl_light_strategy_name(p->light_strategy), p->strategy_reason);
    if (p->light_strategy == TL_LIGHT_STRATEGY_TILED)
        tl__printf(&o, "; %ux%u-pixel tiles, %u x %u%s%s", p->tile_size, p->tile_size, p->tiles_x, p->tiles_y,
                   p->tiled_shading ? ", shaded by a " : "", p->tiled_shading ? (p->tiled_shading == TL_TILED_SHADING_COMPUTE
                                                                                   ? "compute pass" : "fragment pass") : "");
    tl__printf(&o, "\n");
    if (p->light_scale_reason[0])
        tl__printf(&o, "light scale: %g (%s)\n", (double)p->light_scale, p->light_scale_reason);
    if (p->msaa_reason[0]) tl__printf(&o, "msaa: %u sample%s (%s)\n", p->msaa, p->msaa > 1 ? "s" : "", p->msaa_reason);
    if (p->transparency_reason[0])
        tl__printf(&o, "transparency: %s (%s)\n", tl_transparency_name(p->transparency), p->transparency_reason);
    if (p->clearcoat_reason[0])
        tl__printf(&o, "clearcoat: %s (%s)\n", p->clearcoat == TL_CLEARCOAT_SUMS ? "sums" : "approx", p->clearcoat_reason);
    for (size_t i = 0; i < p->downgrade_count && i < TL_PLAN_MAX_DOWNGRADES; i++) {
        char line[256];
        tl_plan_downgrade_format(&p->downgrades[i], line, sizeof line);
        tl__printf(&o, "downgrade: %s\n", line);
    }
    tl__printf(&o, "lighting: %s (%s)", tl_lighting_model_name(p->lighting), p->lighting_reason);
    if (p->fresnel != TL_FRESNEL_DEFAULT)
        tl__printf(&o, "; Fresnel in the light buffer: %s", p->fresnel == TL_FRESNEL_TWO_SUMS
                                                                 ? "two sums, F0 S1 + S2 (exact)"
                                                                 : "one sum, Schlick with n.v per pixel");
    tl__printf(&o, "\n");
    tl__printf(&o, "programs:\n");
    for (size_t i = 0; i < p->program_count; i++)
        tl__printf(&o, "  %-19s %s\n", p->programs[i].name, p->programs[i].defines[0] ? p->programs[i].defines : "-");
    return o.len;
}
