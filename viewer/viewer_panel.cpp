// lidr-viewer's Dear ImGui panel: settings, per-pass times and figures, the debug views, animation and camera.
#include "lidr/base/gl.h"  // GLEW before anything that includes GL/gl.h (GLFW does)

#include "viewer.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "lidr/gl/render_targets.h"
#include "lidr/modes/auto_mode_renderer.h"
#include "viewer_internal.h"

namespace lidr::viewer {
namespace {

std::string bytesText(double b) {
    char s[64];
    if (b >= 1024.0 * 1024.0)
        std::snprintf(s, sizeof s, "%.2f MiB", b / (1024.0 * 1024.0));
    else
        std::snprintf(s, sizeof s, "%.1f KiB", b / 1024.0);
    return s;
}

// A setting's values for its menu, from the library's table of options (lidr/modes/render_options.h).
const std::vector<std::string>& choices(const char* name) { return findRenderOption(name)->choices; }

}  // namespace

void Viewer::uiSettings() {
    auto combo = [&](const char* label, const std::string& current, const auto& items, const std::string& setting,
                     auto text, auto enabled) {
        if (ImGui::BeginCombo(label, current.c_str())) {
            for (const auto& item : items) {
                const std::string t = text(item);
                std::string why;
                const bool ok = enabled(item, &why);
                if (ImGui::Selectable(t.c_str(), t == current, ok ? 0 : ImGuiSelectableFlags_Disabled) && t != current)
                    changeSetting(setting, t);
                if (!ok && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", why.c_str());
            }
            ImGui::EndCombo();
        }
    };
    auto str = [](const auto& v) {
        std::ostringstream s;
        s << v;
        return s.str();
    };
    auto always = [](const auto&, std::string*) { return true; };
    const GlInfo& info = context_->info();
    combo("mode (M)", rc_.mode(), renderModeNames(), "mode", str, always);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", renderModeDescription(rc_.mode()).c_str());
    const std::string mode = rc_.mode(), scheme = rc_.get("scheme");
    const bool lidrMode = mode == "lidr";
    ImGui::BeginDisabled(!lidrMode);
    combo("scheme", scheme, choices("scheme"), "scheme", str, always);
    ImGui::BeginDisabled(scheme == "auto");
    combo("budget", rc_.get("budget"), choices("budget"), "budget", str, [&](const std::string& b, std::string* why) {
        if (b == "auto" && scheme != "bitshift" && scheme != "auto") {
            *why = "an automatic budget is measured from bit-shift packing's stencil count";
            return false;
        }
        return true;
    });
    combo("index bits", rc_.get("index-bits"), choices("index-bits"), "index-bits", str, always);
    ImGui::EndDisabled();
    if (scheme == "auto" && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("the automatic scheme chooses budget and index width per frame: name a scheme to fix them");
    combo("volume test", rc_.get("volume-test"), choices("volume-test"), "volume-test", str, always);
    bool detail = rc_.get("volume-detail") == "on";
    if (ImGui::Checkbox("coarse volumes for small lights", &detail)) changeSetting("volume-detail", detail ? "on" : "off");
    ImGui::EndDisabled();
    if (!lidrMode && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("scheme, budget, index width and volume test are the lidr mode's");
    ImGui::BeginDisabled(mode != "tiled");
    combo("tile size", rc_.get("tile-size"), choices("tile-size"), "tile-size", str, always);
    bool bounds = rc_.get("no-depth-bounds") != "on", halfZ = rc_.get("half-z") == "on";
    if (ImGui::Checkbox("tile depth bounds", &bounds)) changeSetting("depth-bounds", bounds ? "on" : "off");
    ImGui::SameLine();
    if (ImGui::Checkbox("half-Z", &halfZ)) changeSetting("half-z", halfZ ? "on" : "off");
    ImGui::EndDisabled();
    ImGui::BeginDisabled(!findRenderOption("cluster-slices")->usedBy(mode));
    combo("cluster tile size", setting("cluster-tile-size"), choices("cluster-tile-size"), "cluster-tile-size", str, always);
    combo("depth slices", setting("cluster-slices"), choices("cluster-slices"), "cluster-slices", str, always);
    combo("slicing", setting("cluster-slicing"), choices("cluster-slicing"), "cluster-slicing", str, always);
    bool occupied = setting("cluster-occupancy") == "on";
    ImGui::BeginDisabled(!info.readDepthStencil);
    if (ImGui::Checkbox("occupied clusters only", &occupied)) changeSetting("cluster-occupancy", occupied ? "on" : "off");
    ImGui::EndDisabled();
    if (!info.readDepthStencil && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("occupied clusters read the depth back, which this context cannot");
    ImGui::EndDisabled();
    combo("MSAA", setting("msaa"), choices("msaa"), "msaa", str, [&](const std::string& text, std::string* why) {
        const int s = std::stoi(text);
        if (s == 0) return true;
        if (!info.multisampleFbo) {
            *why = "this context has no multisample framebuffers";
            return false;
        }
        if (s > info.maxSamples) {
            *why = "GL_MAX_SAMPLES is " + std::to_string(info.maxSamples);
            return false;
        }
        return true;
    });
    bool perSample = rc_.get("msaa-per-sample") == "on";
    const bool perSampleOk = info.multisampleTexture && info.sampleShading;
    ImGui::BeginDisabled(!lidrMode || !perSampleOk);
    if (ImGui::Checkbox("per-sample index lists", &perSample)) changeSetting("per-sample", perSample ? "on" : "off");
    ImGui::EndDisabled();
    if (!perSampleOk && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("needs GL 3.2 multisample textures and sample shading; this context has GL %s", info.version.c_str());
    bool transparency = rc_.get("transparency") == "on";
    if (ImGui::Checkbox("transparency", &transparency)) changeSetting("transparency", transparency ? "on" : "off");
    combo("shadows", rc_.get("shadows"), choices("shadows"), "shadows", str, always);
    bool pcf = rc_.get("shadow-filter") == "pcf";
    if (ImGui::Checkbox("filtered shadow edges", &pcf)) changeSetting("shadow-filter", pcf ? "pcf" : "nearest");
    ImGui::BeginDisabled(!lidrMode);
    combo("shadow lookup", rc_.get("shadow-lookup"), choices("shadow-lookup"), "shadow-lookup", str, always);
    ImGui::EndDisabled();
    if (!lidrMode && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("where LIDR applies shadows: the volume pass's test or the forward pass's lookup");
    if (!status_.empty()) {
        if (lastRefused_) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", status_.c_str());
        if (lastRefused_) ImGui::PopStyleColor();
    }
}

void Viewer::uiStats() {
    const FrameStats& st = renderer_->lastFrame();
    const bool gpu = std::string(st.timingMethod) == "gpu-timer-query";
    ImGui::Text("times: %s", gpu ? "GPU timer queries" : "CPU clock around glFinish per pass");
    std::vector<float> values(frameHistory_.begin(), frameHistory_.end());
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "frame %.2f ms", values.empty() ? 0.0 : double(values.back()));
    // (PlotLines takes a width of 0 as "item width" but no negative one: give the pixels.)
    ImGui::PlotLines("##frame", values.data(), int(values.size()), 0, overlay, 0.0f, FLT_MAX,
                     ImVec2(ImGui::GetContentRegionAvail().x, 50));
    if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthStretch, 2.0f);
        ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthFixed, ImGui::GetFontSize() * 5.0f);
        ImGui::TableSetupColumn("history", ImGuiTableColumnFlags_WidthStretch, 1.0f);
        for (const std::string& p : passOrder_) {
            const auto& h = history_[p];
            std::vector<float> v(h.begin(), h.end());
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(p.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%.2f ms", v.empty() ? 0.0 : double(v.back()));
            ImGui::TableNextColumn();
            ImGui::PlotLines(("##" + p).c_str(), v.data(), int(v.size()), 0, nullptr, 0.0f, FLT_MAX,
                             ImVec2(std::max(20.0f, ImGui::GetContentRegionAvail().x), 16));
        }
        ImGui::EndTable();
    }
    ImGui::Text("lights: %d of %d visible (drawn), %ld volume draws", st.drawnLights, int(currentLights().size()),
                st.volumeDrawCalls);
    const bool fresh = eval_.valid && !dirty_;
    if (!eval_.valid) {
        ImGui::TextDisabled("dropped / overlap / error: press C (compute)");
    } else {
        if (!fresh) ImGui::TextDisabled("(figures of an earlier frame: press C)");
        const double psnr = std::isinf(eval_.error.psnr) ? 999.0 : eval_.error.psnr;
        if (eval_.listsChecked) {
            ImGui::Text("max overlap %d (marked %d), dropped light-pixels %ld", eval_.maxOverlap, eval_.maxMarked,
                        eval_.droppedLightPixels);
            ImGui::Text("pixels over budget %ld, invalid slots %ld", eval_.pixelsOverBudget, eval_.invalidSlots);
        }
        ImGui::Text("vs reference: max error %d, PSNR %.1f dB", eval_.error.maxAbsError, psnr);
        if (eval_.listsChecked)
            ImGui::Text("  lists within budget: max error %d, PSNR %.1f dB",
                        eval_.errorWithinBudget.maxAbsError,
                        std::isinf(eval_.errorWithinBudget.psnr) ? 999.0 : eval_.errorWithinBudget.psnr);
    }
    const auto* lidrRenderer = dynamic_cast<const LidrRenderer*>(&drawingRenderer());
    if (lidrRenderer) {
        const AutoDecision& d = st.autoDecision;
        const PackingConfig& c = lidrRenderer->scheme().config();
        if (d.autoBudget || d.autoIndexBits)
            ImGui::TextWrapped("automatic: budget %d%s, %d-bit indices for %d visible lights, re-packed %d times", c.budget,
                               d.autoBudget ? (d.overflowPixels > 0 ? " (overlap above it)" : " (measured)") : " (fixed)",
                               c.indexBits, d.visibleLights, d.repacks);
    }
    if (const auto* autoMode = dynamic_cast<const AutoModeRenderer*>(renderer_.get()))
        ImGui::TextWrapped("auto mode: drawing with %s; %s", autoMode->lastMode().c_str(), autoMode->reason().c_str());
    // The index targets the last frame used (an automatic budget and width change them).
    const unsigned long long targets = estimateRenderTargetBytes(
        width_, height_, std::stoi(setting("msaa")),
        lidrRenderer ? indexBytesPerPixel(lidrRenderer->scheme().config().budget, lidrRenderer->scheme().config().indexBits) : 0,
        lidrRenderer && rc_.get("msaa-per-sample") == "on");
    size_t table = 0;
    if (auto* l = dynamic_cast<const LidrRenderer*>(&drawingRenderer())) table = l->frame().lightTable.bytes();
    if (auto* t = dynamic_cast<const TiledRenderer*>(&drawingRenderer())) table = t->frame().lightTable.bytes();
    if (auto* c = dynamic_cast<const ClusteredRenderer*>(&drawingRenderer())) table = c->frame().lightTable.bytes();
    ImGui::Text("memory: targets %s (estimate), light data %s", bytesText(double(targets)).c_str(),
                bytesText(double(renderer_->lightDataBytes())).c_str());
    if (table) ImGui::Text("light table %s", bytesText(double(table)).c_str());
}

void Viewer::uiViews() {
    for (int i = 0; i < kViewCount; ++i) {
        std::string why;
        const bool ok = viewAvailable(View(i), &why);
        ImGui::BeginDisabled(!ok);
        if (ImGui::RadioButton(viewName(View(i)), view_ == View(i))) changeSetting("view", viewName(View(i)));
        ImGui::EndDisabled();
        if (!ok && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", why.c_str());
        if (i % 3 != 2) ImGui::SameLine();
    }
    if (ImGui::Button("compute (C)")) computeRequested_ = true;
    ImGui::SameLine();
    ImGui::TextDisabled("reference, difference, lists: on demand");
}

void Viewer::buildUi(int fbw, int fbh) {
    if (!showUi_) return;
    const GlInfo& info = context_->info();
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(std::min(400.0f, fbw * 0.5f), std::max(200.0f, fbh - 16.0f)), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.88f);
    ImGui::Begin("lidr-viewer (Tab hides)");
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 7.5f);  // room for the labels
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    panelMin_[0] = pos.x, panelMin_[1] = pos.y, panelMax_[0] = pos.x + size.x, panelMax_[1] = pos.y + size.y;
    ImGui::TextWrapped("%s", info.renderer.c_str());
    ImGui::TextWrapped("GL %s, GLSL %s, %s", info.version.c_str(), info.glslVersion.c_str(), info.backend.c_str());
    ImGui::Text("%s, %dx%d, %d lights", scene_.name.c_str(), width_, height_, int(scene_.lights.size()));
    if (ImGui::CollapsingHeader("file (drop one on the window)", ImGuiTreeNodeFlags_DefaultOpen)) uiFile();
    if (ImGui::CollapsingHeader("settings", ImGuiTreeNodeFlags_DefaultOpen)) {
        uiSettings();
        // The environment light (--environment): its intensity is a uniform, changed without a rebuild.
        if (shading_.environment.on())
            ImGui::SliderFloat("environment", &shading_.environment.intensity, 0.0f, 4.0f, "%.2f x");
        if (renderer_) ImGui::TextWrapped("environment: %s", renderer_->lastFrame().environment.c_str());
    }
    if (ImGui::CollapsingHeader("frame", ImGuiTreeNodeFlags_DefaultOpen)) uiStats();
    if (ImGui::CollapsingHeader("debug view (V)", ImGuiTreeNodeFlags_DefaultOpen)) uiViews();
    if (ImGui::CollapsingHeader("animation and camera", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Checkbox("pause (P)", &paused_);
        ImGui::SameLine();
        if (ImGui::Button("step (N)")) onKeyPress(GLFW_KEY_N, 0);
        ImGui::SameLine();
        ImGui::Text("t = %.2f s", double(animTime_));
        const SceneAnimation& a = scene_.animation;
        if (a.end > a.start) {  // a keyframed scene: its time range as a slider
            if (ImGui::SliderFloat("time", &animTime_, a.start, a.end, "%.2f s")) markDirty();
            if (a.frames > 1)
                ImGui::Text("frame %d of %d", int(std::lround((animTime_ - a.start) / (a.end - a.start) * float(a.frames - 1))),
                            a.frames);
        }
        if (a.cameraNode >= 0 && ImGui::Checkbox("follow the scene's camera", &followSceneCamera_)) markDirty();
        ImGui::SliderFloat("speed", &animSpeed_, 0.0f, 4.0f, "%.2fx");
        int lights = lightCount_;
        const int maxL = maxLightsFor(rc_);
        if (ImGui::SliderInt("lights", &lights, 0, maxL) && lights != lightCount_) changeSetting("lights", std::to_string(lights));
        if (maxL < int(scene_.lights.size()))
            ImGui::TextDisabled("%s-bit indices hold %d lights: the slider stops there", rc_.get("index-bits").c_str(), maxL);
        const glm::vec3 p = camera_.position();
        ImGui::Text("camera (%.2f, %.2f, %.2f), yaw %.0f, pitch %.0f", double(p.x), double(p.y), double(p.z),
                    double(glm::degrees(camera_.yaw())), double(glm::degrees(camera_.pitch())));
        ImGui::SliderFloat("move speed", &moveSpeed_, 0.1f, 50.0f, "%.1f /s", ImGuiSliderFlags_Logarithmic);
        if (ImGui::Button("reset (R)")) resetAll();
        ImGui::SameLine();
        if (ImGui::Button("screenshot (F12)")) pendingScreenshot_ = "";
        ImGui::SameLine();
        if (ImGui::Button("save all (F11)")) pendingSave_ = "";
    }
    if (ImGui::CollapsingHeader("controls")) {
        ImGui::TextWrapped(
            "WASD move, Q/E down/up, Shift faster; drag with the right mouse button (or the left one outside this "
            "panel) to look. P/Space pause, N step, M next mode, V next view, C compute the debug views, R reset, "
            "F5 reload the file (drop a .glb, .gltf, .obj or scene .json on the window to open it), "
            "F12 screenshot, F11 save screenshot + frame + views + raw artefacts, Tab hide the panel, Esc quit.");
    }
    ImGui::PopItemWidth();
    ImGui::End();
}

}  // namespace lidr::viewer
