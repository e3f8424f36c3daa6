// The viewer's panel: Dear ImGui (Debian's libimgui-dev) with its GLFW and OpenGL 3 back ends.
// Edits vw_app's settings (a change sets app->rebuild, or goes through vw_update_view) and shows
// the smoothed per-pass times, the bytes per pixel and the frame plan. The view image is drawn
// behind the panel with the background draw list.
#include <stdint.h>
#include <stdio.h>

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

static void vw_ui_settings(vw_app *app)
{
    static const char *modes[] = {"thin-lpp", "thin-deferred", "fat", "forward"};
    static const char *strategies[] = {"auto", "volumes", "tiled"};
    static const char *depths[] = {"d24", "d32f", "d32f-reversed"};
    static const char *rt0s[] = {"rgba8 (oct 2x12 + gloss 8)", "rgb10a2 (oct 2x10 + gloss 10)"};
    static const char *buffers[] = {"exact (diffuse + specular)", "compact (one RGBA16F)"};
    static const char *fxaas[] = {"off", "12", "29", "39"};
    tl_renderer_desc *d = &app->desc;
    bool c = vw_combo("mode", &d->mode, modes, TL_MODE_THIN_LPP, 4);
    c |= vw_combo("light strategy", &d->light_strategy, strategies, TL_LIGHT_STRATEGY_DEFAULT, 3);
    ImGui::TextDisabled("  planned: %s (%s)", tl_light_strategy_name(app->plan.light_strategy), app->plan.strategy_reason);
    c |= vw_combo("depth", &d->depth_format, depths, TL_DEPTH_FORMAT_D24, 3);
    c |= vw_combo("RT0 packing", &d->rt0, rt0s, TL_RT0_RGBA8, 2);
    c |= vw_combo("light buffer", &d->light_buffer, buffers, TL_LIGHT_BUFFER_EXACT, 2);
    c |= vw_combo("FXAA", &d->fxaa, fxaas, TL_FXAA_OFF, 4);
    if (d->exposure <= 0) d->exposure = 1.0f;
    ImGui::SliderFloat("exposure", &d->exposure, 0.05f, 20.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
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
        app->rebuild = 1; // a new right-hand renderer
    ImGui::SliderFloat("difference scale", &app->diff_scale, 1.0f, 64.0f, "x%.0f", ImGuiSliderFlags_Logarithmic);
    if (c) vw_update_view(app);
}

static void vw_ui_timings(const vw_app *app)
{
    const vw_timings *t = &app->timings;
    ImGui::Text("GPU %.2f ms, CPU %.2f ms (smoothed)", t->gpu_ms, t->cpu_ms);
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

// A heat-scale bar with its range, bottom left.
static void vw_ui_legend(ImDrawList *dl, ImVec2 size, const char *lo, const char *hi)
{
    ImVec2 o(16, size.y - 40);
    const int steps = 64;
    for (int i = 0; i < steps; i++) {
        uint8_t c[3];
        vw_heat(static_cast<float>(i) / (steps - 1), c);
        dl->AddRectFilled(ImVec2(o.x + i * 4.0f, o.y), ImVec2(o.x + i * 4.0f + 4, o.y + 14), IM_COL32(c[0], c[1], c[2], 255));
    }
    dl->AddText(ImVec2(o.x, o.y + 16), IM_COL32_WHITE, lo);
    dl->AddText(ImVec2(o.x + steps * 4.0f - ImGui::CalcTextSize(hi).x, o.y + 16), IM_COL32_WHITE, hi);
}

static void vw_ui_labels(vw_app *app, ImDrawList *dl, ImVec2 size)
{
    char a[64], b[64];
    if (app->grid) {
        for (int v = 0; v < VW_VIEW_COUNT; v++)
            dl->AddText(ImVec2((v % 4) * size.x / 4 + 4, (v / 4) * size.y / 4 + 2), IM_COL32_WHITE,
                        vw_view_name(static_cast<vw_view>(v)));
    } else if (app->split_on) {
        const char *left = tl_render_mode_name(app->desc.mode); // beside the dividing line
        dl->AddText(ImVec2(size.x / 2 - 8 - ImGui::CalcTextSize(left).x, size.y - 24), IM_COL32_WHITE, left);
        dl->AddText(ImVec2(size.x / 2 + 8, size.y - 24), IM_COL32_WHITE, tl_render_mode_name(app->split_mode));
    } else if (app->view == VW_VIEW_DIFF_FAT) {
        snprintf(a, sizeof a, "0");
        snprintf(b, sizeof b, "%.1f / 255 (x%.0f)", 255.0 / app->diff_scale, app->diff_scale);
        vw_ui_legend(dl, size, a, b);
    } else if (app->view == VW_VIEW_DEPTH && !app->view_note[0]) {
        snprintf(a, sizeof a, "white %.3g m ... dark %.3g m (log)", app->depth_range[0], app->depth_range[1]);
        dl->AddText(ImVec2(16, size.y - 24), IM_COL32_WHITE, a);
    } else if (app->view == VW_VIEW_TILE_LIGHTS && !app->view_note[0]) {
        snprintf(b, sizeof b, "%u lights (magenta: overflow)", app->tile_max);
        vw_ui_legend(dl, size, "0", b);
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
