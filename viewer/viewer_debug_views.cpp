// lidr-viewer's debug views and saved artefacts: the reference and difference images, the index lists, overlap
// and marked-light views (LIDR), the light-list heat map (tiled: per tile; clustered: per pixel's cluster),
// screenshots (F12) and everything at once (F11).
#include "lidr/base/gl.h"  // GLEW before anything that includes GL/gl.h (GLFW does)

#include "viewer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

#include "frame_views.h"
#include "lidr/eval/artefacts.h"
#include "lidr/eval/frame_evaluation.h"
#include "lidr/modes/auto_mode_renderer.h"
#include "viewer_internal.h"

namespace lidr::viewer {

const char* viewName(View v) {
    switch (v) {
        case View::Frame: return "frame";
        case View::Difference: return "difference";
        case View::IndexLists: return "index-lists";
        case View::Overlap: return "overlap";
        case View::Marked: return "marked";
        case View::TileHeatMap: return "tile-heatmap";
        case View::ShadowAtlas: return "shadow-atlas";
    }
    return "?";
}

bool Viewer::viewAvailable(View v, std::string* why) const {
    auto no = [&](const char* reason) {
        if (why) *why = reason;
        return false;
    };
    const bool lidrMode = dynamic_cast<const LidrRenderer*>(&drawingRenderer()) != nullptr;
    switch (v) {
        case View::Frame:
        case View::Difference: return true;
        case View::IndexLists:
        case View::Overlap:
        case View::Marked:
            if (!lidrMode) return no("index lists and light counts exist in the lidr mode only");
            if (rc_.get("msaa-per-sample") == "on") return no("per-sample index targets are multisample textures: they cannot be read back");
            return true;
        case View::TileHeatMap:
            if (!dynamic_cast<const TiledRenderer*>(&drawingRenderer()) &&
                !dynamic_cast<const ClusteredRenderer*>(&drawingRenderer()))
                return no("the light-list heat map is the tiled and clustered modes'");
            return true;
        case View::ShadowAtlas: {
            const ShadowAtlas* atlas = drawingRenderer().shadowAtlas();
            if (!atlas) return no("no frame has drawn shadow maps yet: turn shadows on (scene or K brightest)");
            if (gles_ && !atlas->packed()) return no("OpenGL ES 2.0 cannot read a depth texture back");
            return true;
        }
    }
    return false;
}

void Viewer::computeViews() {
    ShadingParameters shading;
    const auto lights = currentLights(&shading);
    const Camera cam = camera_.camera();
    Evaluation ev;
    ev.frame = frameNumber_;
    const ImageRGBA8 frame = renderer_->targets().readColor();
    auto reference = demo::makeReference(context_->info(), scene_, modeOptions_, width_, height_, int(lights.size()));
    placeAnimatedObjects(*reference, scene_, animTime_);  // the frame's meshes where the animation has them
    reference->render(cam, lights, shading);
    ev.reference = reference->targets().readColor();
    reference.reset();
    ev.error = compareImages(frame, ev.reference);
    ev.images[View::Difference] = differenceImage(frame, ev.reference);
    if (const auto* lidr = dynamic_cast<const LidrRenderer*>(&drawingRenderer()); lidr && !lidr->options().perSampleIndices) {
        const FrameEvaluation fe = evaluateFrame(*lidr, cam, lights, frame, ev.reference);
        const demo::LidrViews lv = demo::lidrViews(fe, width_, height_, lidr->scheme().config().budget);
        ev.images[View::IndexLists] = lv.indexLists;
        ev.images[View::Overlap] = lv.overlap;
        ev.images[View::Marked] = lv.marked;
        ev.listsChecked = true;
        ev.droppedLightPixels = fe.lists.droppedLightPixels;
        ev.invalidSlots = fe.lists.invalidSlots;
        ev.pixelsOverBudget = fe.pixelsOverBudget;
        ev.maxOverlap = fe.maxTruthOverlap;
        ev.maxMarked = fe.maxMarked;
        ev.errorWithinBudget = fe.errorWithinBudget;
    }
    if (const auto* tiled = dynamic_cast<const TiledRenderer*>(&drawingRenderer()))
        ev.images[View::TileHeatMap] = tiled->tileHeatMap(16);
    if (const auto* clustered = dynamic_cast<const ClusteredRenderer*>(&drawingRenderer()))
        ev.images[View::TileHeatMap] = clustered->clusterHeatMap(16);
    checkGl("viewer: computing the debug views");
    ev.valid = true;
    eval_ = std::move(ev);
    dirty_ = false;
}

const ImageRGBA8* Viewer::shownView() const {
    if (view_ == View::TileHeatMap && tileHeat_.width > 0) return &tileHeat_;
    if (view_ == View::ShadowAtlas) return shadowAtlasView_.width > 0 ? &shadowAtlasView_ : nullptr;
    if (view_ != View::Frame && view_ != View::TileHeatMap && eval_.valid && eval_.images.count(view_))
        return &eval_.images.at(view_);
    return nullptr;
}

void Viewer::saveScreenshot(const std::string& file) {
    int fbw = 0, fbh = 0;
    glfwGetFramebufferSize(window_, &fbw, &fbh);
    const std::filesystem::path p(file);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    ImageRGBA8 shot = readWindow(fbw, fbh);
    for (size_t i = 3; i < shot.pixels.size(); i += 4) shot.pixels[i] = 255;  // the window's alpha is not an image's
    writePng(file, shot);
    // What the window shows under the panel: the debug view's image, else the frame.
    const ImageRGBA8* view = shownView();
    screenshots_[file] = {shot, view ? *view : renderer_->targets().readColor()};
    std::cout << "lidr-viewer: wrote " << file << std::endl;
}

void Viewer::saveAll(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw Error("cannot create folder '" + dir + "': " + ec.message());
    auto path = [&](const char* f) { return (std::filesystem::path(dir) / f).string(); };
    saveScreenshot(path("screenshot.png"));
    writePng(path("frame.png"), renderer_->targets().readColor());
    if (!eval_.valid || dirty_) computeViews();
    writePng(path("reference.png"), eval_.reference);
    for (const auto& [v, img] : eval_.images) {
        std::string f = viewName(v);
        std::replace(f.begin(), f.end(), '-', '_');
        writePng(path((f + ".png").c_str()), img);
    }
    if (const auto* lidr = dynamic_cast<const LidrRenderer*>(&drawingRenderer()); lidr && !lidr->options().perSampleIndices) {
        const auto lights = currentLights();
        FrameArtefacts a;
        a.indexTargets = lidr->readIndexTargets();
        a.depth = lidr->targets().readDepth();
        a.lightCounts = lidr->readLightCounts();
        a.camera = cameraMatrices(camera_.camera(), width_, height_);
        a.lights = lights;
        if (lidr->frameIndexRegions().on())
            throw Error("the dump writes one light table for the whole frame; this frame numbers its lights per "
                        "screen region (LidrOptions::regionalIndices)");
        if (!lidr->frameLightIndices().empty()) {  // compact numbering (automatic width), as lidr-demo --dump
            a.lights.clear();
            for (uint32_t sceneIndex : lidr->frameLightIndices())
                a.lights.push_back(sceneIndex ? lights[sceneIndex - 1] : PointLight{glm::vec3(0.0f), 1.0f, glm::vec3(0.0f), 0.0f});
        }
        a.drawOrder = LidrRenderer::drawOrder(a.lights);
        writeFrameArtefacts(path("dump"), a, lidr->scheme());
    }
    checkGl("viewer: saving artefacts");
    const Camera c = camera_.camera();
    nlohmann::json j;
    for (const char* s : {"mode", "scheme", "budget", "index-bits", "volume-test", "msaa", "per-sample", "transparency",
                          "tile-size", "depth-bounds", "half-z", "cluster-tile-size", "cluster-slices",
                          "cluster-slicing", "cluster-occupancy", "shadows", "shadow-filter", "shadow-lookup", "lights",
                          "view", "paused"})
        j["settings"][s] = setting(s);
    j["camera"] = {{"position", {c.position.x, c.position.y, c.position.z}},
                   {"target", {c.target.x, c.target.y, c.target.z}}};
    j["time"] = animTime_;
    j["gl"] = {{"renderer", context_->info().renderer}, {"version", context_->info().version}};
    j["drawn_lights"] = renderer_->lastFrame().drawnLights;
    j["error"] = {{"max_abs_error", eval_.error.maxAbsError},
                  {"psnr_db", std::isinf(eval_.error.psnr) ? 999.0 : eval_.error.psnr}};
    if (eval_.listsChecked)
        j["error"]["within_budget"] = {{"max_abs_error", eval_.errorWithinBudget.maxAbsError},
                                       {"psnr_db", std::isinf(eval_.errorWithinBudget.psnr) ? 999.0 : eval_.errorWithinBudget.psnr}};
    if (eval_.listsChecked)
        j["lights"] = {{"dropped_light_pixels", eval_.droppedLightPixels}, {"max_overlap_touching", eval_.maxOverlap},
                       {"max_marked", eval_.maxMarked}};
    std::ofstream(path("state.json")) << j.dump(2) << "\n";
    std::cout << "lidr-viewer: saved " << dir << std::endl;
}

}  // namespace lidr::viewer
