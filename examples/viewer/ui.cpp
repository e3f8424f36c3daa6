// The viewer's panel: Dear ImGui (Debian's libimgui-dev) with its GLFW and OpenGL 3 back ends.
// Edits vw_app's settings (every renderer option, made from the option registry; a change sets
// app->rebuild, or goes through vw_update_view) and shows
// the smoothed per-pass times, the bytes per pixel and the frame plan. The view image is drawn
// behind the panel with the background draw list.
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "viewer.h"
extern "C" {
#include "session.h"
}

static bool vw_ui_started;

int vw_ui_init(void *glfw_window)
{
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini left in the working directory
    ImGui::StyleColorsDark();
    ImGui::GetStyle().Alpha = 0.92f;
    if (!ImGui_ImplGlfw_InitForOpenGL(static_cast<GLFWwindow *>(glfw_window), true)) return 0;
    if (!ImGui_ImplOpenGL3_Init("#version 450 core")) return 0;
    vw_ui_started = true;
    return 1;
}

void vw_ui_shutdown(void)
{
    if (!vw_ui_started) return;
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    vw_ui_started = false;
}

int vw_ui_wants_mouse(void) { return vw_ui_started && ImGui::GetIO().WantCaptureMouse; }
int vw_ui_wants_keyboard(void) { return vw_ui_started && ImGui::GetIO().WantCaptureKeyboard; }

// A combo over an enum whose names a table gives; true when the choice changed.
template <typename E> static bool vw_combo(const char *label, E *value, const char *const *names, int first, int count)
{
    int v = static_cast<int>(*value) < first ? first : static_cast<int>(*value);
    bool changed = false;
    if (ImGui::BeginCombo(label, names[v - first])) {
        for (int i = 0; i < count; i++)
            if (ImGui::Selectable(names[i], v == first + i)) {
                *value = static_cast<E>(first + i);
                changed = v != first + i;
            }
        ImGui::EndCombo();
    }
    return changed;
}

// The light scale's dynamic switch (the scale itself is an option below) and the scale in use now.
static bool vw_ui_light_scale(vw_app *app)
{
    bool dyn = app->dyn.on != 0, c = false;
    if (ImGui::Checkbox("dynamic light scale: lower while the camera moves", &dyn)) {
        vw_light_scale_toggle_dynamic(app);
        c = true;
    }
    ImGui::TextDisabled("  light scale now: %s%s%s", vw_light_scale_name(app->applied_scale),
                        app->dyn.divisor ? " (camera moving)" : "",
                        app->desc.options.mode == TL_MODE_THIN_LPP ? "" : " (thin-lpp only)");
    return c;
}

// Antialiasing as one choice (key M): none, FXAA or MSAA n (aa.c), and what the plan made of it.
static bool vw_ui_aa(vw_app *app)
{
    vw_aa a = vw_aa_of(&app->desc.options);
    bool c = false;
    if (ImGui::BeginCombo("antialiasing", vw_aa_name(a))) {
        for (int i = 0; i < VW_AA_COUNT; i++)
            if (ImGui::Selectable(vw_aa_name(static_cast<vw_aa>(i)), i == a) && i != a) {
                vw_aa_set(app, static_cast<vw_aa>(i));
                c = true;
            }
        ImGui::EndCombo();
    }
    if (app->plan.msaa_reason[0]) ImGui::TextDisabled("  msaa: %u (%s)", app->plan.msaa, app->plan.msaa_reason);
    return c;
}

// ---- the renderer options, from the option registry (thinlight/options.h) -----------------------
// Every field of tl_renderer_options gets a widget made from its row: a checkbox (on/off), a combo
// (an enum, a switch, a power of two, the kept targets), a slider over its range or a drag for an
// unbounded one, a colour for a colour. A zero field shows its default until edited. An effect's
// fields show under its `enabled` while it is on; turning it off keeps them for when it comes back.

// Writes `text` into the field through the registry (its range checked); true when it changed.
static bool vw_ui_set(vw_app *app, const tl_option_info *f, const char *text)
{
    tl_renderer_options o = app->desc.options;
    char why[256] = "";
    tl_logger log = {[](void *user, tl_log_level, const char *m) { snprintf(static_cast<char *>(user), 256, "%s", m); },
                     why};
    if (tl_option_parse(f, text, &o, &log) != TL_OK) {
        snprintf(app->status, sizeof app->status, "%s", why);
        return false;
    }
    bool changed = memcmp(&o, &app->desc.options, sizeof o) != 0;
    app->desc.options = o;
    return changed;
}

static double vw_ui_get(const vw_app *app, const tl_option_info *f, size_t k = 0)
{
    const char *at = reinterpret_cast<const char *>(&app->desc.options) + f->offset;
    if (f->type == TL_OPTION_FLOAT || f->type == TL_OPTION_FLOAT3) {
        float v;
        memcpy(&v, at + k * sizeof v, sizeof v);
        return v;
    }
    uint32_t u;
    memcpy(&u, at, sizeof u);
    return f->type == TL_OPTION_UINT || f->type == TL_OPTION_TARGETS ? u : static_cast<double>(static_cast<int32_t>(u));
}

// The label: the field's name below its struct ("refine" under ssr).
static const char *vw_ui_label(const tl_option_info *f)
{
    const char *dot = strrchr(f->name, '.');
    return dot ? dot + 1 : f->name;
}

// A choice among names: an enum's or a switch's values, or a power of two's.
static bool vw_ui_combo(vw_app *app, const tl_option_info *f)
{
    char now[64];
    tl_option_format(f, &app->desc.options, now, sizeof now);
    if (f->flags & TL_OPTION_POW2 && vw_ui_get(app, f) == 0.0) snprintf(now, sizeof now, "%g", f->zero);
    bool c = false;
    if (!ImGui::BeginCombo(vw_ui_label(f), now)) return false;
    if (f->flags & TL_OPTION_POW2) {
        for (double v = f->min; v <= f->max; v *= 2.0) {
            char t[32];
            snprintf(t, sizeof t, "%g", v);
            if (ImGui::Selectable(t, strcmp(t, now) == 0)) c |= vw_ui_set(app, f, t);
        }
    } else {
        for (uint32_t v = 1; v <= f->count; v++) { // DEFAULT last, where its name is its own ("auto")
            const char *name = f->value_name(v % f->count);
            bool alias = false;
            for (uint32_t w = 1; v == f->count && w < f->count; w++) alias |= strcmp(name, f->value_name(w)) == 0;
            if (!alias && ImGui::Selectable(name, strcmp(name, now) == 0)) c |= vw_ui_set(app, f, name);
        }
    }
    ImGui::EndCombo();
    return c;
}

// The kept targets: a checkbox per target.
static bool vw_ui_targets(vw_app *app, const tl_option_info *f)
{
    char now[512];
    tl_option_format(f, &app->desc.options, now, sizeof now);
    bool c = false;
    if (!ImGui::BeginCombo(vw_ui_label(f), now)) return false;
    uint32_t bits = static_cast<uint32_t>(vw_ui_get(app, f));
    for (uint32_t t = 0; t < f->count && t < 32u; t++) {
        bool on = (bits >> t) & 1u;
        if (ImGui::Checkbox(f->value_name(t), &on)) { /* every value is in range: no check to make */
            bits = on ? bits | (1u << t) : bits & ~(1u << t);
            memcpy(reinterpret_cast<char *>(&app->desc.options) + f->offset, &bits, sizeof bits);
            c = true;
        }
    }
    ImGui::EndCombo();
    return c;
}

// A number: a slider over a bounded range, a drag over an unbounded one; zero shown as the default.
static bool vw_ui_number(vw_app *app, const tl_option_info *f)
{
    double raw = vw_ui_get(app, f);
    bool neg_zero = (f->flags & TL_OPTION_NEGATIVE_ZERO) != 0, bounded = f->min > -FLT_MAX && f->max < FLT_MAX;
    float lo = f->min > -FLT_MAX ? static_cast<float>(f->min) : -1e6f, hi = bounded ? static_cast<float>(f->max) : 1e6f;
    float v = static_cast<float>(raw == 0.0 ? (f->zero_text ? 0.0 : f->zero) : raw < 0.0 && neg_zero ? 0.0 : raw);
    const char *fmt = raw == 0.0 && f->zero_text ? "default" : f->type == TL_OPTION_UINT ? "%.0f" : "%.3f";
    if (f->type == TL_OPTION_UINT) {
        int n = static_cast<int>(v);
        if (ImGui::SliderInt(vw_ui_label(f), &n, static_cast<int>(lo), static_cast<int>(hi))) v = static_cast<float>(n);
    } else if (bounded) {
        ImGui::SliderFloat(vw_ui_label(f), &v, lo, hi, fmt);
    } else {
        float speed = static_cast<float>(fmax(fabs(f->zero), 0.1) * 0.01);
        ImGui::DragFloat(vw_ui_label(f), &v, speed, lo, hi, fmt);
    }
    if (!ImGui::IsItemDeactivatedAfterEdit() && !(f->type == TL_OPTION_UINT && ImGui::IsItemEdited())) return false;
    char text[48];
    snprintf(text, sizeof text, "%.9g", v == 0.0f && neg_zero ? -1.0 : static_cast<double>(v));
    return vw_ui_set(app, f, text);
}

static bool vw_ui_colour(vw_app *app, const tl_option_info *f)
{
    float rgb[3];
    for (size_t k = 0; k < 3; k++) rgb[k] = static_cast<float>(fmax(vw_ui_get(app, f, k), 0.0));
    ImGui::ColorEdit3(vw_ui_label(f), rgb, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    if (!ImGui::IsItemDeactivatedAfterEdit()) return false;
    char text[96];
    snprintf(text, sizeof text, "%.9g,%.9g,%.9g", rgb[0], rgb[1], rgb[2]);
    return vw_ui_set(app, f, text);
}

// One field's widget; true when an edit is finished (the renderer is then made again).
static bool vw_ui_option(vw_app *app, const tl_option_info *f)
{
    ImGui::PushID(f->name);
    bool c = false;
    if (f->type == TL_OPTION_BOOL) {
        bool on = vw_ui_get(app, f) != 0.0;
        const char *label = strstr(f->name, ".enabled") ? f->name : vw_ui_label(f);
        if (ImGui::Checkbox(label, &on)) c = vw_ui_set(app, f, on ? "1" : "0");
    } else if (f->type == TL_OPTION_ENUM || f->type == TL_OPTION_SWITCH || (f->flags & TL_OPTION_POW2)) {
        c = vw_ui_combo(app, f);
    } else if (f->type == TL_OPTION_TARGETS) {
        c = vw_ui_targets(app, f);
    } else if (f->type == TL_OPTION_FLOAT3) {
        c = vw_ui_colour(app, f);
    } else {
        c = vw_ui_number(app, f);
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (options.%s)", f->help, f->name);
    ImGui::PopID();
    return c;
}

// The struct a field belongs to ("ssr" of "ssr.refine"; "" for the frame's own), and whether it is
// an effect's (has an `enabled` switching it on) and on.
static void vw_ui_group(const tl_option_info *f, char *group, size_t size)
{
    const char *dot = strchr(f->name, '.');
    snprintf(group, size, "%.*s", dot ? static_cast<int>(dot - f->name) : 0, f->name);
}

static int vw_ui_effect_state(const vw_app *app, const char *group)
{
    char name[80];
    snprintf(name, sizeof name, "%s.enabled", group);
    const tl_option_info *e = group[0] ? tl_option_find(name) : nullptr;
    if (!e || e->type != TL_OPTION_BOOL) return -1; // not an effect
    return vw_ui_get(app, e) != 0.0;
}

// The fields of one kind: the frame's own (effects 0, groups 0), the effects' (effects 1) or the
// other structs' (groups 1: shadows, environment), in the registry's order.
static bool vw_ui_options(vw_app *app, int effects, int groups)
{
    bool c = false;
    char last[64] = "";
    for (size_t i = 0; i < tl_option_count(); i++) {
        const tl_option_info *f = tl_option_at(i);
        char group[64];
        vw_ui_group(f, group, sizeof group);
        int effect = vw_ui_effect_state(app, group);
        if ((effect >= 0) != (effects != 0) || (!effects && (group[0] != 0) != (groups != 0))) continue;
        if (effect == 0 && !strstr(f->name, ".enabled")) continue; // an effect that is off: its switch only
        if (!effect && group[0] && strcmp(group, last) != 0) {
            ImGui::Separator();
            ImGui::TextDisabled("%s", group);
        }
        snprintf(last, sizeof last, "%s", group);
        bool below = effect == 1 && !strstr(f->name, ".enabled");
        if (below) ImGui::Indent();
        c |= vw_ui_option(app, f);
        if (below) ImGui::Unindent();
    }
    return c;
}

static void vw_ui_settings(vw_app *app)
{
    bool c = vw_ui_aa(app);
    c |= vw_ui_light_scale(app);
    ImGui::TextDisabled("  planned: %s (%s)", tl_light_strategy_name(app->plan.light_strategy), app->plan.strategy_reason);
    ImGui::Text("lights: %zu", app->light_count);
    ImGui::SameLine();
    if (ImGui::SmallButton("x2")) vw_scale_lights(app, 1);
    ImGui::SameLine();
    if (ImGui::SmallButton("/2")) vw_scale_lights(app, 0);
    ImGui::SameLine();
    bool anim = app->animate != 0;
    if (ImGui::Checkbox("animate", &anim)) app->animate = anim;
    c |= vw_ui_options(app, 0, 0);
    if (c) app->rebuild = 1;
}

static void vw_ui_views(vw_app *app)
{
    static const char *modes[] = {"thin-lpp", "thin-deferred", "fat", "forward", "visibility"};
    static_assert(sizeof modes / sizeof modes[0] == TL_MODE_COUNT_ - TL_MODE_THIN_LPP, "a mode's name for the split combo");
    const char *names[VW_VIEW_COUNT];
    for (int i = 0; i < VW_VIEW_COUNT; i++) names[i] = vw_view_name(static_cast<vw_view>(i));
    bool c = vw_combo("view", &app->view, names, 0, VW_VIEW_COUNT);
    ImGui::TextDisabled("  %s", vw_view_help(app->view));
    if (app->view_note[0]) ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "  %s", app->view_note);
    bool grid = app->grid != 0, split = app->split_on != 0;
    if (ImGui::Checkbox("grid of every view", &grid)) { app->grid = grid; app->split_on = 0; c = true; }
    if (ImGui::Checkbox("split: right half in", &split)) { app->split_on = split; app->grid = 0; c = true; }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(120);
    if (vw_combo("##split", &app->split_mode, modes, TL_MODE_THIN_LPP, TL_MODE_COUNT_ - TL_MODE_THIN_LPP) && app->split_on)
        app->rebuild = 1; // the right-hand renderer's mode
    ImGui::SliderFloat("difference scale", &app->diff_scale, 1.0f, 64.0f, "x%.0f", ImGuiSliderFlags_Logarithmic);
    if (c) vw_update_view(app);
}

static void vw_ui_timings(const vw_app *app)
{
    const vw_timings *t = &app->timings;
    ImGui::Text("GPU %.2f ms, CPU %.2f ms (smoothed), light scale %s", t->gpu_ms, t->cpu_ms,
                vw_light_scale_name(app->applied_scale));
    double most = 0.001;
    for (int p = 0; p < TL_PASS_COUNT; p++) most = t->pass_ms[p] > most ? t->pass_ms[p] : most;
    for (size_t i = 0; i < app->plan.pass_count; i++) {
        const tl_plan_pass *pp = &app->plan.passes[i];
        if (pp->pass >= TL_PASS_COUNT) continue; // application passes
        char label[48];
        snprintf(label, sizeof label, "%.3f ms", t->pass_ms[pp->pass]);
        ImGui::ProgressBar(static_cast<float>(t->pass_ms[pp->pass] / most), ImVec2(160, 0), label);
        ImGui::SameLine();
        ImGui::TextUnformatted(pp->name);
    }
    const tl_frame_plan *p = &app->plan;
    ImGui::Text("bytes/pixel: %u sum, %u peak live, %u allocated", p->bytes_per_pixel, p->peak_live_bytes_per_pixel,
                p->allocated_bytes_per_pixel);
    ImGui::Text("G-buffer + light buffer: %u B/px", p->gbuffer_bytes_per_pixel);
    double px = static_cast<double>(app->width) * app->height;
    ImGui::Text("geometry pass: %llu fragments (%.2f / pixel)", static_cast<unsigned long long>(t->covered),
                px > 0 ? static_cast<double>(t->covered) / px : 0.0);
    if (app->kept) ImGui::TextDisabled("(debug views keep every target: no memory sharing)");
}

static void vw_ui_panel(vw_app *app)
{
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(430, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("thinlight");
    ImGui::Text("%s, %ux%u, %.1f fps", app->scene_path ? app->scene_path : "crypt", app->width, app->height,
                ImGui::GetIO().Framerate);
    ImGui::TextDisabled("camera: %s (F toggles, C resets)", app->cam.mode == VW_CAMERA_FLY ? "fly" : "orbit");
    if (ImGui::CollapsingHeader("Renderer", ImGuiTreeNodeFlags_DefaultOpen)) vw_ui_settings(app);
    if (ImGui::CollapsingHeader("Effects", ImGuiTreeNodeFlags_DefaultOpen) && vw_ui_options(app, 1, 0)) app->rebuild = 1;
    if (ImGui::CollapsingHeader("Shadows and environment") && vw_ui_options(app, 0, 1)) app->rebuild = 1;
    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) vw_ui_views(app);
    if (ImGui::CollapsingHeader("Passes and bytes", ImGuiTreeNodeFlags_DefaultOpen)) vw_ui_timings(app);
    if (ImGui::CollapsingHeader("Frame plan") && app->plan_text) {
        ImGui::BeginChild("plan", ImVec2(0, 300), true, ImGuiWindowFlags_HorizontalScrollbar);
        ImGui::TextUnformatted(app->plan_text);
        ImGui::EndChild();
    }
    if (app->status[0]) ImGui::TextWrapped("%s", app->status);
    ImGui::End();
}

// Labels over the grid and the split view. Scales (legends) are drawn into the view's pixels by
// views.c, so that screenshots carry them.
static void vw_ui_labels(vw_app *app, ImDrawList *dl, ImVec2 size)
{
    if (app->grid) {
        for (int v = 0; v < VW_VIEW_COUNT; v++)
            dl->AddText(ImVec2((v % VW_GRID_COLS) * size.x / VW_GRID_COLS + 4, (v / VW_GRID_COLS) * size.y / VW_GRID_ROWS + 2),
                        IM_COL32_WHITE, vw_view_name(static_cast<vw_view>(v)));
    } else if (app->split_on) {
        const char *left = tl_render_mode_name(app->desc.options.mode); // beside the dividing line
        dl->AddText(ImVec2(size.x / 2 - 8 - ImGui::CalcTextSize(left).x, size.y - 24), IM_COL32_WHITE, left);
        dl->AddText(ImVec2(size.x / 2 + 8, size.y - 24), IM_COL32_WHITE, tl_render_mode_name(app->split_mode));
    }
}

void vw_ui_frame(vw_app *app, uint32_t view_texture)
{
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImVec2 size = ImGui::GetIO().DisplaySize;
    ImDrawList *dl = ImGui::GetBackgroundDrawList();
    if (view_texture) // rows bottom to top: flip
        dl->AddImage(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(view_texture)), ImVec2(0, 0), size,
                     ImVec2(0, 1), ImVec2(1, 0));
    vw_ui_labels(app, dl, size);
    if (app->show_panel) vw_ui_panel(app);
    ImGui::Render();
}

void vw_ui_render(void) { ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData()); }
