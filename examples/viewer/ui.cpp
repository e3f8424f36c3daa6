// The viewer's panel: Dear ImGui (Debian's libimgui-dev) with its GLFW and OpenGL 3 back ends.
// Edits vw_app's settings (a change sets app->rebuild, or goes through vw_update_view) and shows
// the smoothed per-pass times, the bytes per pixel and the frame plan. The view image is drawn
// behind the panel with the background draw list.
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
#include "tool_effects.h"
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

// The light scale (thin-lpp): the one chosen, the dynamic switch and the scale in use now.
static bool vw_ui_light_scale(vw_app *app)
{
    static const char *scales[] = {"1", "1/2", "1/4"};
    static const float values[] = {1.0f, 0.5f, 0.25f};
    float *s = &app->desc.options.light_scale;
    int k = *s <= 0.25f ? 2 : *s <= 0.5f ? 1 : 0;
    bool c = false;
    if (ImGui::BeginCombo("light scale", scales[k])) {
        for (int i = 0; i < 3; i++)
            if (ImGui::Selectable(scales[i], i == k) && i != k) {
                *s = values[i];
                c = true;
            }
        ImGui::EndCombo();
    }
    bool dyn = app->dyn.on != 0;
    if (ImGui::Checkbox("dynamic: lower while the camera moves", &dyn)) {
        vw_light_scale_toggle_dynamic(app);
        c = true;
    }
    ImGui::TextDisabled("  light scale now: %s%s%s", vw_light_scale_name(app->applied_scale),
                        app->dyn.divisor ? " (camera moving)" : "",
                        app->desc.options.mode == TL_MODE_THIN_LPP ? "" : " (thin-lpp only)");
    return c;
}

// Antialiasing: none, FXAA or MSAA n (aa.c), and what the plan made of it.
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

static void vw_ui_settings(vw_app *app)
{
    static const char *modes[] = {"thin-lpp", "thin-deferred", "fat", "forward"};
    static const char *strategies[] = {"auto", "volumes", "tiled"};
    static const char *depths[] = {"d24", "d32f", "d32f-reversed"};
    static const char *rt0s[] = {"rgba8 (oct 2x12 + gloss 8)", "rgb10a2 (oct 2x10 + gloss 10)"};
    static const char *buffers[] = {"exact (diffuse + specular)", "compact (one RGBA16F)"};
    static const char *fxaas[] = {"off", "12", "29", "39"};
    tl_renderer_desc *d = &app->desc;
    bool c = vw_combo("mode", &d->options.mode, modes, TL_MODE_THIN_LPP, 4);
    c |= vw_combo("light strategy", &d->options.light_strategy, strategies, TL_LIGHT_STRATEGY_DEFAULT, 3);
    ImGui::TextDisabled("  planned: %s (%s)", tl_light_strategy_name(app->plan.light_strategy), app->plan.strategy_reason);
    c |= vw_ui_light_scale(app);
    c |= vw_combo("depth", &d->options.depth_format, depths, TL_DEPTH_FORMAT_D24, 3);
    c |= vw_combo("RT0 packing", &d->options.rt0, rt0s, TL_RT0_RGBA8, 2);
    c |= vw_combo("light buffer", &d->options.light_buffer, buffers, TL_LIGHT_BUFFER_EXACT, 2);
    c |= vw_ui_aa(app);
    if (d->options.msaa <= 1 && d->options.fxaa != TL_FXAA_OFF) c |= vw_combo("FXAA preset", &d->options.fxaa, fxaas, TL_FXAA_OFF, 4);
    if (d->options.exposure <= 0) d->options.exposure = 1.0f;
    ImGui::SliderFloat("exposure", &d->options.exposure, 0.05f, 20.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
    c |= ImGui::IsItemDeactivatedAfterEdit();
    ImGui::Text("lights: %zu", app->light_count);
    ImGui::SameLine();
    if (ImGui::SmallButton("x2")) vw_scale_lights(app, 1);
    ImGui::SameLine();
    if (ImGui::SmallButton("/2")) vw_scale_lights(app, 0);
    ImGui::SameLine();
    bool anim = app->animate != 0;
    if (ImGui::Checkbox("animate", &anim)) app->animate = anim;
    if (c) app->rebuild = 1;
}

// ---- screen-space effects ------------------------------------------------------------------------
// One row per effect: its name, the tool flag that turns it on with its defaults (tool_effects.h,
// the flags thinlight-render takes) and its options in tl_renderer_desc, whose first field (method,
// mode or enabled) is zero when the effect is off. A new effect is one more row (and a slot in
// vw_app.fx_saved); its parameters are rows of vw_params.
struct vw_effect {
    const char *name, *flag;
    size_t offset, size;
};
#define VW_FX(field) offsetof(tl_renderer_desc, field), sizeof(tl_renderer_desc::field)
static const vw_effect vw_effects[] = {
    {"SSAO", "--ssao", VW_FX(options.ssao)},
    {"fog", "--fog", VW_FX(options.fog)},
    {"depth of field", "--dof", VW_FX(options.dof)},
    {"reflections", "--ssr", VW_FX(options.ssr)},
    {"bloom", "--bloom", VW_FX(options.bloom)},
};
static const int vw_effect_count = static_cast<int>(sizeof vw_effects / sizeof vw_effects[0]);

// The main parameters, shown under their effect while it is on. A zero field means the
// library's default, shown as `def` until it is edited, or as "default" where that depends on
// other settings (def -1: k_d = 2 radius, focus on the camera's target, largest CoC 2 apertures).
enum vw_param_kind { VW_F32, VW_F32_LOG, VW_U32, VW_ENUM, VW_RGB, VW_BOOL };
struct vw_param {
    const char *effect, *label;
    vw_param_kind kind;
    size_t offset;
    float lo, hi, def;
    const char *const *names; // VW_ENUM: values 1, 2, ... (0 is off)
};
#define VW_AT(field) offsetof(tl_renderer_desc, field)
static const char *const vw_ssao_methods[] = {"disc (slides)", "hemisphere", nullptr};
static const char *const vw_fog_modes[] = {"distance", "height", nullptr};
static const vw_param vw_params[] = {
    {"SSAO", "estimator", VW_ENUM, VW_AT(options.ssao.method), 0, 0, 1, vw_ssao_methods},
    {"SSAO", "samples", VW_U32, VW_AT(options.ssao.samples), 1, 64, 16, nullptr},
    {"SSAO", "radius", VW_F32_LOG, VW_AT(options.ssao.radius), 0.05f, 10, 1, nullptr},
    {"SSAO", "bias k_b", VW_F32, VW_AT(options.ssao.bias), 0, 2, 0, nullptr},
    {"SSAO", "falloff k_d", VW_F32, VW_AT(options.ssao.falloff), 0, 20, -1, nullptr},
    {"SSAO", "exponent x", VW_F32, VW_AT(options.ssao.exponent), 0.25f, 8, 3, nullptr},
    {"SSAO", "blur half-width", VW_U32, VW_AT(options.ssao.blur_radius), 1, 8, 2, nullptr},
    {"SSAO", "on diffuse light too", VW_BOOL, VW_AT(options.ssao.diffuse), 0, 1, 0, nullptr},
    {"fog", "kind", VW_ENUM, VW_AT(options.fog.mode), 0, 0, 1, vw_fog_modes},
    {"fog", "density", VW_F32_LOG, VW_AT(options.fog.density), 0.001f, 1, 0.05f, nullptr},
    {"fog", "colour", VW_RGB, VW_AT(options.fog.color), 0, 0, 0, nullptr},
    {"fog", "height", VW_F32, VW_AT(options.fog.height), -20, 20, 0, nullptr},
    {"fog", "height falloff", VW_F32_LOG, VW_AT(options.fog.height_falloff), 0.01f, 5, 0.5f, nullptr},
    {"fog", "noise", VW_F32, VW_AT(options.fog.noise), 0, 1, 0, nullptr},
    {"depth of field", "focus distance", VW_F32, VW_AT(options.dof.focus_distance), 0, 100, -1, nullptr},
    {"depth of field", "aperture", VW_F32_LOG, VW_AT(options.dof.aperture), 0.001f, 0.1f, 0.01f, nullptr},
    {"depth of field", "largest CoC", VW_F32, VW_AT(options.dof.max_radius), 0, 0.2f, -1, nullptr},
    {"depth of field", "taps", VW_U32, VW_AT(options.dof.samples), 8, 128, 48, nullptr},
    {"reflections", "steps", VW_U32, VW_AT(options.ssr.steps), 4, 256, 48, nullptr},
    {"reflections", "distance", VW_F32_LOG, VW_AT(options.ssr.max_distance), 0.5f, 100, 16, nullptr},
    {"reflections", "thickness", VW_F32_LOG, VW_AT(options.ssr.thickness), 0.01f, 5, 0.4f, nullptr},
    {"reflections", "least gloss", VW_F32, VW_AT(options.ssr.min_gloss), 0, 0.99f, 0.4f, nullptr},
    {"reflections", "intensity", VW_F32_LOG, VW_AT(options.ssr.intensity), 0.1f, 10, 1, nullptr},
    {"bloom", "threshold", VW_F32_LOG, VW_AT(options.bloom.threshold), 0.05f, 20, 1, nullptr},
    {"bloom", "intensity", VW_F32_LOG, VW_AT(options.bloom.intensity), 0.02f, 4, 0.5f, nullptr},
    {"bloom", "scatter", VW_F32, VW_AT(options.bloom.scatter), 0.05f, 1, 0.7f, nullptr},
    {"bloom", "levels", VW_U32, VW_AT(options.bloom.levels), 1, 8, 6, nullptr},
};

// One parameter's widget; true when an edit is finished (the renderer is then made again).
static bool vw_ui_param(tl_renderer_desc *d, const vw_param &p)
{
    unsigned char *at = reinterpret_cast<unsigned char *>(d) + p.offset;
    float f;
    int i;
    memcpy(&f, at, sizeof f);
    memcpy(&i, at, sizeof i);
    bool edited = false;
    if (p.kind == VW_F32 || p.kind == VW_F32_LOG) {
        float v = f != 0 ? f : p.def > 0 ? p.def : 0.0f;
        ImGuiSliderFlags flags = p.kind == VW_F32_LOG ? ImGuiSliderFlags_Logarithmic : 0;
        if (ImGui::SliderFloat(p.label, &v, p.lo, p.hi, f == 0 && p.def < 0 ? "default" : "%.3f", flags))
            memcpy(at, &v, sizeof v);
        edited = ImGui::IsItemDeactivatedAfterEdit();
    } else if (p.kind == VW_U32) {
        int v = i != 0 ? i : static_cast<int>(p.def);
        if (ImGui::SliderInt(p.label, &v, static_cast<int>(p.lo), static_cast<int>(p.hi))) memcpy(at, &v, sizeof v);
        edited = ImGui::IsItemDeactivatedAfterEdit();
    } else if (p.kind == VW_ENUM) {
        int count = 0;
        while (p.names[count]) count++;
        edited = vw_combo(p.label, &i, p.names, 1, count);
        if (edited) memcpy(at, &i, sizeof i);
    } else if (p.kind == VW_RGB) {
        float rgb[3];
        memcpy(rgb, at, sizeof rgb);
        if (ImGui::ColorEdit3(p.label, rgb, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR)) memcpy(at, rgb, sizeof rgb);
        edited = ImGui::IsItemDeactivatedAfterEdit();
    } else {
        bool b = i != 0;
        edited = ImGui::Checkbox(p.label, &b);
        i = b ? 1 : 0;
        memcpy(at, &i, sizeof i);
    }
    return edited;
}

// A checkbox per effect (its first field says whether it is on); turning one off keeps its
// settings for when it comes back, turning it on the first time takes the tool flag's defaults.
static bool vw_ui_effect_toggle(vw_app *app, int e)
{
    const vw_effect &fx = vw_effects[e];
    unsigned char *at = reinterpret_cast<unsigned char *>(&app->desc) + fx.offset, *saved = app->fx_saved[e];
    int first;
    memcpy(&first, at, sizeof first);
    bool on = first != 0;
    if (!ImGui::Checkbox(fx.name, &on)) return false;
    if (!on) {
        memcpy(saved, at, fx.size);
        memset(at, 0, fx.size);
    } else {
        int was;
        memcpy(&was, saved, sizeof was);
        if (was) memcpy(at, saved, fx.size);
        else tl_tool_effect_flag(&app->desc, fx.flag);
    }
    return true;
}

static void vw_ui_effects(vw_app *app)
{
    bool c = false;
    static_assert(sizeof vw_effects / sizeof vw_effects[0] <= sizeof(vw_app::fx_saved) / sizeof(vw_app::fx_saved[0]),
                  "vw_app.fx_saved: one slot per effect");
    for (int e = 0; e < vw_effect_count; e++) {
        if (vw_effects[e].size > sizeof app->fx_saved[0]) continue; // cannot happen with the rows above
        ImGui::PushID(e);
        c |= vw_ui_effect_toggle(app, e);
        int first;
        memcpy(&first, reinterpret_cast<unsigned char *>(&app->desc) + vw_effects[e].offset, sizeof first);
        for (const vw_param &p : vw_params)
            if (first && !strcmp(p.effect, vw_effects[e].name)) {
                ImGui::Indent();
                c |= vw_ui_param(&app->desc, p);
                ImGui::Unindent();
            }
        ImGui::PopID();
    }
    if (c) app->rebuild = 1;
}

static void vw_ui_views(vw_app *app)
{
    static const char *modes[] = {"thin-lpp", "thin-deferred", "fat", "forward"};
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
    if (vw_combo("##split", &app->split_mode, modes, TL_MODE_THIN_LPP, 4) && app->split_on)
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
    if (ImGui::CollapsingHeader("Effects", ImGuiTreeNodeFlags_DefaultOpen)) vw_ui_effects(app);
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
