// lidr-viewer's script runner (--script; doc/viewer.md): each action of a parsed script (script.h) acted out on
// the viewer, and each check judged; a failed check is a ScriptFailure.
#include "lidr/base/gl.h"  // GLEW before anything that includes GL/gl.h (GLFW does)

#include "viewer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

#include <GLFW/glfw3.h>

#include "lidr/gl/render_targets.h"
#include "lidr/modes/auto_mode_renderer.h"
#include "viewer_internal.h"

namespace lidr::viewer {
namespace {

int keyFromName(const std::string& n) {
    std::string u;
    for (char c : n) u += char(std::toupper(static_cast<unsigned char>(c)));
    if (u.size() == 1 && u[0] >= 'A' && u[0] <= 'Z') return GLFW_KEY_A + (u[0] - 'A');
    if (u.size() == 1 && u[0] >= '0' && u[0] <= '9') return GLFW_KEY_0 + (u[0] - '0');
    if (u.size() >= 2 && u[0] == 'F' && std::all_of(u.begin() + 1, u.end(), ::isdigit)) {
        const int f = std::stoi(u.substr(1));
        if (f >= 1 && f <= 12) return GLFW_KEY_F1 + f - 1;
    }
    if (u == "ESC" || u == "ESCAPE") return GLFW_KEY_ESCAPE;
    if (u == "SPACE") return GLFW_KEY_SPACE;
    if (u == "TAB") return GLFW_KEY_TAB;
    if (u == "PERIOD" || u == ".") return GLFW_KEY_PERIOD;
    if (u == "SHIFT") return GLFW_KEY_LEFT_SHIFT;
    return -1;
}

bool compareOp(double a, const std::string& op, double b) {
    if (op == "==") return a == b;
    if (op == "!=") return a != b;
    if (op == "<") return a < b;
    if (op == "<=") return a <= b;
    if (op == ">") return a > b;
    return a >= b;
}

}  // namespace

void Viewer::runAction(const ScriptAction& a, int fbw, int fbh) {
    auto fail = [&](const std::string& why) {
        throw ScriptFailure("script line " + std::to_string(a.line) + " '" + a.text + "' failed: " + why);
    };
    const std::string& v = a.verb;
    if (v == "wait") {
        scriptWait_ = scriptInt(a, 0);
    } else if (v == "key") {
        const int k = keyFromName(a.args[0]);
        if (k < 0) fail("unknown key '" + a.args[0] + "'");
        scriptHeld_.insert(k);
        scriptWait_ = scriptInt(a, 1);
    } else if (v == "press") {
        const int k = keyFromName(a.args[0]);
        if (k < 0) fail("unknown key '" + a.args[0] + "'");
        onKeyPress(k, 0);
    } else if (v == "mouse") {
        camera_.turn(float(scriptNumber(a, 0)) * 0.004f, -float(scriptNumber(a, 1)) * 0.004f);
        markDirty();
    } else if (v == "set") {
        try {
            changeSetting(a.args[0], a.args[1]);
        } catch (const GlError&) {
            throw;
        } catch (const std::exception& e) {
            fail(e.what());
        }
    } else if (v == "compute") {
        computeViews();
    } else if (v == "screenshot") {
        saveScreenshot(a.args[0]);
    } else if (v == "capture") {
        writePng(a.args[0], renderer_->targets().readColor());
    } else if (v == "save") {
        saveAll(a.args[0]);
    } else if (v == "mark") {
        markPosition_ = camera_.position();
        markForward_ = camera_.forward();
        markRight_ = camera_.right();
        markFrame_ = renderer_->targets().readColor();
        marked_ = true;
    } else if (v == "expect-moved") {
        if (!marked_) fail("no 'mark' before it");
        const glm::vec3 d = camera_.position() - markPosition_;
        const std::string& dir = a.args[0];
        float along = 0.0f;
        if (dir == "forward") along = glm::dot(d, markForward_);
        else if (dir == "back") along = -glm::dot(d, markForward_);
        else if (dir == "right") along = glm::dot(d, markRight_);
        else if (dir == "left") along = -glm::dot(d, markRight_);
        else if (dir == "up") along = d.y;
        else if (dir == "down") along = -d.y;
        else fail("direction must be forward, back, left, right, up or down");
        const double min = scriptNumber(a, 1);
        if (along < min)
            fail("the camera moved " + std::to_string(along) + " " + dir + " (of " + std::to_string(glm::length(d)) +
                 " in all), less than " + a.args[1]);
        const ImageError e = compareImages(renderer_->targets().readColor(), markFrame_);
        std::cout << "lidr-viewer: " << a.text << ": moved " << along << " " << dir << " (" << glm::length(d)
                  << " in all), " << e.differingPixels << " pixels changed" << std::endl;
        if (e.differingPixels < long(width_) * height_ / 100)
            fail("the frame hardly changed: " + std::to_string(e.differingPixels) + " pixels differ");
    } else if (v == "expect-match") {
        // "{drawn}" in the file name: the mode that drew the frame (auto's choice), whose demo image it must equal
        static const std::string kDrawn = "{drawn}";
        std::string file = a.args[0];
        for (size_t at; (at = file.find(kDrawn)) != std::string::npos;)
            file.replace(at, kDrawn.size(), drawingRenderer().modeName());
        const ImageRGBA8 want = readPng(file);
        const ImageRGBA8 got = renderer_->targets().readColor();
        if (want.width != got.width || want.height != got.height)
            fail("size " + std::to_string(got.width) + "x" + std::to_string(got.height) + " against " +
                 std::to_string(want.width) + "x" + std::to_string(want.height));
        const ImageError e = compareImages(got, want);
        const double psnr = std::isinf(e.psnr) ? 999.0 : e.psnr;
        std::cout << "lidr-viewer: " << a.text << ": " << file << ": max error " << e.maxAbsError << ", PSNR " << psnr
                  << " dB, " << e.differingPixels << " pixels differ" << std::endl;
        if (e.maxAbsError > scriptInt(a, 1) || psnr < scriptNumber(a, 2))
            fail("max error " + std::to_string(e.maxAbsError) + ", PSNR " + std::to_string(psnr) + " dB");
    } else if (v == "expect-view-match") {
        if (!eval_.valid && view_ != View::TileHeatMap && view_ != View::ShadowAtlas) fail("no debug view computed");
        const ImageRGBA8* got = view_ == View::TileHeatMap   ? &tileHeat_
                                : view_ == View::ShadowAtlas ? &shadowAtlasView_
                                : eval_.images.count(view_)  ? &eval_.images.at(view_)
                                                             : nullptr;
        if (!got || got->width == 0) fail(std::string("view ") + viewName(view_) + " has no image");
        const ImageRGBA8 want = readPng(a.args[0]);
        if (want.width != got->width || want.height != got->height) fail("image sizes differ");
        const ImageError e = compareImages(*got, want);
        std::cout << "lidr-viewer: " << a.text << ": max error " << e.maxAbsError << ", " << e.differingPixels
                  << " pixels differ" << std::endl;
        if (e.maxAbsError > scriptInt(a, 1)) fail("max error " + std::to_string(e.maxAbsError));
    } else if (v == "expect-ui") {
        const auto it = screenshots_.find(a.args[0]);
        if (it == screenshots_.end()) fail("no screenshot was written to that file by this script");
        const ImageRGBA8 shot = readPng(a.args[0]);  // from disk: the file is what is judged
        const ImageRGBA8& frame = it->second.second;
        if (shot.width != fbw || shot.height != fbh) fail("the screenshot is not the window's size");
        if (frame.width != shot.width || frame.height != shot.height)
            fail("window " + std::to_string(shot.width) + "x" + std::to_string(shot.height) + " is not the frame's size");
        const int x0 = int(panelMin_[0]) + 2, y0 = int(panelMin_[1]) + 2;
        const int x1 = std::min(int(panelMax_[0]) - 2, shot.width), y1 = std::min(int(panelMax_[1]) - 2, shot.height);
        if (x1 - x0 < 50 || y1 - y0 < 50) fail("the UI panel is not on screen");
        long inside = 0, insideDiff = 0, outside = 0, outsideDiff = 0;
        for (int y = 0; y < shot.height; ++y)
            for (int x = 0; x < shot.width; ++x) {
                const uint8_t* s = shot.at(x, y);
                const uint8_t* f = frame.at(x, y);
                const int d = std::max({std::abs(s[0] - f[0]), std::abs(s[1] - f[1]), std::abs(s[2] - f[2])});
                const bool in = x >= x0 && x < x1 && y >= y0 && y < y1;
                const bool near = x >= x0 - 6 && x < x1 + 6 && y >= y0 - 6 && y < y1 + 6;
                if (in) inside++, insideDiff += d > 8;
                else if (!near) outside++, outsideDiff += d > 1;
            }
        std::cout << "lidr-viewer: " << a.text << ": panel " << x0 << "," << y0 << "-" << x1 << "," << y1 << ", "
                  << insideDiff << " of " << inside << " panel pixels differ from what is shown under it, " << outsideDiff << " of "
                  << outside << " outside" << std::endl;
        if (insideDiff < inside / 2) fail("the panel's pixels look like the frame's: no UI drawn");
        if (outsideDiff > outside / 1000) fail("outside the panel the window does not show the frame (or the debug view) it should");
    } else if (v == "expect-stat") {
        const std::string& n = a.args[0];
        double value = 0.0;
        const bool needEval = n == "max-error" || n == "psnr" || n == "dropped" || n == "max-overlap" || n == "max-marked";
        if (needEval && (!eval_.valid || dirty_)) fail("no up-to-date figures: add 'compute' first");
        if ((n == "dropped" || n == "max-overlap" || n == "max-marked") && !eval_.listsChecked)
            fail("no index lists checked in this mode");
        if (n == "drawn-lights") value = renderer_->lastFrame().drawnLights;
        else if (n == "lights") value = double(currentLights().size());
        else if (n == "scene-lights") value = double(scene_.lights.size());
        else if (n == "file-lights") value = double(fileScene_.lights.size());
        else if (n == "warnings") value = double(fileScene_.warnings.size());
        else if (n == "meshes") value = double(scene_.meshes.size());
        else if (n == "time") value = animTime_;
        else if (n == "frames") value = double(frameNumber_);
        else if (n == "volume-draws") value = double(renderer_->lastFrame().volumeDrawCalls);
        else if (n == "max-error") value = eval_.error.maxAbsError;
        else if (n == "psnr") value = std::isinf(eval_.error.psnr) ? 999.0 : eval_.error.psnr;
        else if (n == "dropped") value = double(eval_.droppedLightPixels);
        else if (n == "max-overlap") value = eval_.maxOverlap;
        else if (n == "max-marked") value = eval_.maxMarked;
        else fail("unknown figure '" + n + "' (drawn-lights, lights, scene-lights, file-lights, warnings, meshes, time, frames, volume-draws, max-error, psnr, dropped, max-overlap, max-marked)");
        std::cout << "lidr-viewer: " << a.text << ": " << n << " = " << value << std::endl;
        if (!compareOp(value, a.args[1], scriptNumber(a, 2))) fail(n + " is " + std::to_string(value));
    } else if (v == "expect-setting") {
        std::string got;
        try {
            got = setting(a.args[0]);
        } catch (const Error& e) {
            fail(e.what());
        }
        if (got != a.args[1]) fail(a.args[0] + " is " + got);
    } else if (v == "expect-refused") {
        if (!lastRefused_) fail("the last change was applied: " + status_);
        std::cout << "lidr-viewer: " << a.text << ": " << status_ << std::endl;
    } else if (v == "expect-applied") {
        if (lastRefused_) fail(status_);
    } else if (v == "expect-file") {
        if (!std::filesystem::is_regular_file(a.args[0]) || std::filesystem::file_size(a.args[0]) == 0)
            fail("no such file, or it is empty");
    } else if (v == "resize") {
        const int w = scriptInt(a, 0), h = scriptInt(a, 1);
        if (w < 1 || h < 1) fail("the size must be positive");
        glfwSetWindowSize(window_, w, h);
    } else if (v == "expect-size") {
        const RenderTargets& t = renderer_->targets();
        std::cout << "lidr-viewer: " << a.text << ": frame " << t.width() << "x" << t.height() << ", window " << fbw
                  << "x" << fbh << std::endl;
        if (t.width() != scriptInt(a, 0) || t.height() != scriptInt(a, 1))
            fail("the frame is " + std::to_string(t.width()) + "x" + std::to_string(t.height()));
    } else if (v == "expect-mode-views") {
        // In the automatic mode the views follow the candidate that drew the frame.
        const Renderer& drawing = drawingRenderer();
        const bool lidrDrew = dynamic_cast<const LidrRenderer*>(&drawing) != nullptr;
        const bool tiledDrew = dynamic_cast<const TiledRenderer*>(&drawing) != nullptr ||
                               dynamic_cast<const ClusteredRenderer*>(&drawing) != nullptr;
        std::cout << "lidr-viewer: " << a.text << ": " << renderer_->modeName() << " drew with " << drawing.modeName()
                  << std::endl;
        std::string why;
        for (View view : {View::IndexLists, View::Overlap, View::Marked})
            if (viewAvailable(view, &why) != (lidrDrew && rc_.get("msaa-per-sample") != "on"))
                fail(std::string("view ") + viewName(view) + (lidrDrew ? " not offered: " + why : " offered"));
        if (viewAvailable(View::TileHeatMap, &why) != tiledDrew)
            fail(std::string("the light-list heat map ") + (tiledDrew ? "not offered: " + why : "offered"));
        if (!eval_.valid || dirty_) fail("no up-to-date figures: add 'compute' first");
        if (eval_.listsChecked != (lidrDrew && rc_.get("msaa-per-sample") != "on"))
            fail(lidrDrew ? "the index lists of the LIDR frame were not checked" : "index lists checked without LIDR");
        if (lidrDrew && (eval_.images.count(View::IndexLists) == 0 || eval_.images.at(View::IndexLists).width != width_))
            fail("no index-list image of the frame's size");
    } else if (v == "drop") {
        onDrop(a.args);
        openPendingFile();  // (the frame loop opens it before its next frame; a check on the next line sees it)
    } else if (v == "quit") {
        quit_ = true;
    }
}

void Viewer::stepScript(int fbw, int fbh) {
    if (scriptWait_ > 0 && --scriptWait_ > 0) return;
    scriptHeld_.clear();
    while (scriptWait_ == 0 && scriptPos_ < script_.size() && !quit_) runAction(script_[scriptPos_++], fbw, fbh);
    if (scriptPos_ >= script_.size() && scriptWait_ == 0) quit_ = true;  // a script ends the viewer
}

}  // namespace lidr::viewer
