/* The renderer tools' memory budgets (tool_budget.h). */
#include "tool_budget.h"

#include "tool_util.h"

const char tl_tool_budget_help[] =
    "  --max-target-memory B  the most memory the renderer's targets may take (default 2GiB; none: no\n"
    "                        budget); a larger frame is refused before anything is allocated\n"
    "  --max-load-memory B    the glTF load's memory budget (default 512MiB; none: no budget)\n"
    "  --max-texture-pixels N the largest texture a glTF file may hold, in pixels (default 67108864,\n"
    "                        8192x8192)\n"
    "                        (B: bytes, or with a unit: 512MiB, 4GiB; KiB, MiB, GiB, TiB)\n";

enum { TL_TOOL__TARGET, TL_TOOL__LOAD, TL_TOOL__TEXTURE };

static const tl_opt tl_tool__budget_opts[] = {
    {"--max-target-memory", TL_OPT_BYTES, .id = TL_TOOL__TARGET, .lo = 1, .hi = SIZE_MAX, .flags = TL_OPT_NONE},
    {"--max-load-memory", TL_OPT_BYTES, .id = TL_TOOL__LOAD, .lo = 1, .hi = SIZE_MAX, .flags = TL_OPT_NONE},
    {"--max-texture-pixels", TL_OPT_UINT, .id = TL_TOOL__TEXTURE, .lo = 1, .hi = (uint64_t)1 << 32},
};

const tl_opt_table tl_tool_budget_option_table = TL_OPT_TABLE(tl_tool__budget_opts);

int tl_tool_budget_option(tl_tool_budgets *b, const tl_opt *o, const tl_opt_value *v)
{
    if (!tl_opt_in(o, tl_tool_budget_option_table)) return 0;
    uint64_t value = v->none ? UINT64_MAX : v->u[0];
    if (o->id == TL_TOOL__TARGET) b->target_bytes = value;
    else if (o->id == TL_TOOL__LOAD) b->load_bytes = value;
    else b->texture_pixels = value;
    return 1;
}

void tl_tool_budget_renderer(const tl_tool_budgets *b, tl_renderer_desc *d)
{
    uint64_t t = b->target_bytes ? b->target_bytes : TL_TOOL_DEFAULT_TARGET_BYTES;
    d->max_target_bytes = t == UINT64_MAX ? 0 : (size_t)t; /* the renderer's 0: no budget */
}

void tl_tool_budget_gltf(const tl_tool_budgets *b, tl_gltf_options *o)
{
    o->max_memory = b->load_bytes == UINT64_MAX ? SIZE_MAX : (size_t)b->load_bytes; /* 0: the default */
    o->max_texture_pixels = (size_t)b->texture_pixels;
}

static void tl_tool__bytes(char *out, size_t size, double bytes)
{
    if (bytes >= 1073741824.0) snprintf(out, size, "%.1f GiB", bytes / 1073741824.0);
    else if (bytes >= 1048576.0) snprintf(out, size, "%.1f MiB", bytes / 1048576.0);
    else if (bytes >= 1024.0) snprintf(out, size, "%.1f KiB", bytes / 1024.0);
    else snprintf(out, size, "%.0f bytes", bytes);
}

int tl_tool_budget_check(const char *tool, const char *what, const tl_renderer_desc *d, const tl_scene *scene)
{
    tl_scene_feature_set features;
    tl_frame_plan plan;
    tl_scene_features(scene, &features);
    if (!d->max_target_bytes || tl_frame_plan_build(d, &features, &plan) != TL_OK) return 0; /* the renderer says */
    uint32_t w = d->width ? d->width : 1280, h = d->height ? d->height : 720;
    double need = (double)plan.allocated_bytes_per_pixel * w * h;
    if (need <= (double)d->max_target_bytes) return 0;
    char need_text[32], budget_text[32];
    tl_tool__bytes(need_text, sizeof need_text, need);
    tl_tool__bytes(budget_text, sizeof budget_text, (double)d->max_target_bytes);
    tl_tool_fail(tool, "%s%sthe targets of a %ux%u frame need %s (%u B/px), over the target-memory budget of %s "
                       "(--max-target-memory)",
                 what ? what : "", what ? ": " : "", w, h, need_text, plan.allocated_bytes_per_pixel, budget_text);
    return 1;
}
