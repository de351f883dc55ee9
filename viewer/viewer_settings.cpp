// lidr-viewer's settings: building a renderer for a choice (reverted, with the reason, when the library refuses
// it), the settings by name (the panel and the script use the same names) and the light count.
#include "lidr/base/gl.h"  // GLEW before anything that includes GL/gl.h (GLFW does)

#include "viewer.h"

#include <iostream>

#include "lidr/modes/auto_mode_renderer.h"
#include "viewer_internal.h"

namespace lidr::viewer {

int Viewer::maxLightsFor(const demo::RendererChoice& rc) const {
    const int sceneLights = int(scene_.lights.size());
    // (An automatic index width widens to what the visible lights need, up to 16 bits.)
    if (rc.mode != "lidr" || rc.scheme == "auto") return sceneLights;
    for (int bits : {4, 8, 16})
        if (rc.indexBits == std::to_string(bits)) return std::min(sceneLights, (1 << bits) - 1);
    return sceneLights;
}

demo::ShadowChoice Viewer::shadowChoice(const demo::RendererChoice& rc) const {
    demo::RendererChoice c = rc;
    if (c.mode != "lidr") c.shadowLookup.reset();  // where LIDR looks up: kept for when the mode comes back
    return c.shadowChoice(c.mode);
}

std::vector<PointLight> Viewer::currentLights(ShadingParameters* shading) const {
    std::vector<PointLight> l = scene_.lightsAt(animTime_);
    if (int(l.size()) > lightCount_) l.resize(size_t(lightCount_));
    ShadingParameters frame = shading_;
    shadowChoice(rc_).apply(cameraMatrices(camera_.camera(), width_, height_), l, frame);
    if (shading) *shading = frame;
    return l;
}

bool Viewer::apply(const demo::RendererChoice& next, const std::string& what) {
    const int oldCount = lightCount_;
    try {
        const RenderModeOptions mo = next.renderModeOptions(scene_);
        demo::checkTargetMemory(scene_, mo);
        // An index width holds (1 << bits) - 1 lights: the renderer is built for the lights the slider allows.
        const int maxLights = maxLightsFor(next);
        Scene renderScene = scene_;
        if (int(renderScene.lights.size()) > maxLights) {
            renderScene.lights.resize(size_t(maxLights));
            if (!renderScene.lightPaths.empty()) renderScene.lightPaths.resize(size_t(maxLights));
        }
        // All the lights the old configuration allowed stays "all"; a smaller count stays, within the new limit.
        lightCount_ = lightCount_ >= maxLightsFor(rc_) ? maxLights : std::min(lightCount_, maxLights);
        std::unique_ptr<Renderer> r = createRenderer(mo, context_->info(), renderScene, width_, height_);
        r->setTiming(true);  // the panel's per-pass times: read a frame or more late, never stalling
        const demo::RendererChoice old = rc_;
        rc_ = next;  // the frame's shadows are the new choice's
        ShadingParameters shading;
        std::vector<PointLight> lights;
        try {
            lights = currentLights(&shading);
            r->render(camera_.camera(), lights, shading);  // a refusal at draw time reverts too
        } catch (...) {
            rc_ = old;
            throw;
        }
        checkGl("viewer: first frame of the new configuration");
        renderer_ = std::move(r);
        rc_ = next;
        modeOptions_ = mo;
        history_.clear();
        passOrder_.clear();
        frameHistory_.clear();
        status_ = what + " applied";
        std::cout << "lidr-viewer: " << status_ << std::endl;
        lastRefused_ = false;
        eval_ = {};
        markDirty();
        return true;
    } catch (const std::exception& e) {
        while (glGetError() != GL_NO_ERROR) {
        }
        lightCount_ = oldCount;
        status_ = what + " refused: " + e.what();
        lastRefused_ = true;
        std::cerr << "lidr-viewer: " << status_ << std::endl;
        return false;
    }
}

bool Viewer::changeSetting(const std::string& name, const std::string& value) {
    auto toInt = [&](const std::string& v) {
        size_t used = 0;
        int i = 0;
        try {
            i = std::stoi(v, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != v.size()) throw Error("setting " + name + ": '" + v + "' is not a whole number");
        return i;
    };
    auto toBool = [&](const std::string& v) {
        if (v == "on" || v == "true" || v == "1") return true;
        if (v == "off" || v == "false" || v == "0") return false;
        throw Error("setting " + name + ": '" + v + "' is not on or off");
    };
    if (name == "lights") {
        const int n = toInt(value);
        const int maxL = maxLightsFor(rc_);
        if (n < 0 || n > maxL)
            throw Error("setting lights: " + value + " is outside 0.." + std::to_string(maxL) +
                        (maxL < int(scene_.lights.size()) ? " (the index width's limit)" : ""));
        lightCount_ = n;
        markDirty();
        return true;
    }
    if (name == "scatter") {
        const int n = toInt(value);
        const int maxScatter = int(maxSceneLights) - int(fileScene_.lights.size());
        if (n < 0 || n > maxScatter)
            throw Error("setting scatter: " + value + " is outside 0.." + std::to_string(maxScatter) +
                        " (a scene holds at most " + std::to_string(maxSceneLights) + " lights)");
        const int old = scatteredLights_;
        scatterOver(n);  // throws (e.g. a scene without triangles) before anything changed
        lightCount_ = int(scene_.lights.size());
        if (apply(rc_, "scatter " + value)) return true;
        scatterOver(old);
        lightCount_ = std::min(int(scene_.lights.size()), maxLightsFor(rc_));
        return false;
    }
    if (name == "view") {
        for (int i = 0; i < kViewCount; ++i)
            if (value == viewName(View(i))) {
                std::string why;
                if (!viewAvailable(View(i), &why)) {
                    status_ = std::string("view ") + value + " refused: " + why;
                    lastRefused_ = true;
                    return false;
                }
                view_ = View(i);
                if (view_ != View::Frame && view_ != View::TileHeatMap && view_ != View::ShadowAtlas) computeRequested_ = true;
                return true;
            }
        throw Error("setting view: unknown view '" + value +
                    "' (frame, difference, index-lists, overlap, marked, tile-heatmap, shadow-atlas)");
    }
    if (name == "paused") {
        paused_ = toBool(value);
        return true;
    }
    if (name == "speed") {
        const int percent = toInt(value);
        if (percent < 0 || percent > 400) throw Error("setting speed: a percentage from 0 to 400, got " + value);
        animSpeed_ = float(percent) / 100.0f;
        return true;
    }
    demo::RendererChoice next = rc_;
    if (name == "mode") {
        next.mode = value;
        if (value != "clustered" && value != "auto")  // the grid is the clustered mode's: its defaults next time
            next.clusterTileSize.reset(), next.clusterSlices.reset(), next.clusterSlicing.reset(),
                next.clusterOccupancy.reset(), next.clusterLightNear.reset();
    }
    else if (name == "scheme") {
        next.scheme = value;
        // The automatic scheme chooses budget and width itself; a named scheme other than bit-shift needs a fixed
        // budget (only bit-shift's stencil count measures one): the choices the library would refuse are made
        // for the user, who can change them after.
        if (value == "auto") next.budget = next.indexBits = "auto";
        else if (value != "bitshift" && next.budget == "auto") next.budget = "8";
    }
    else if (name == "budget") next.budget = value;
    else if (name == "index-bits") next.indexBits = value;
    else if (name == "volume-test") next.volumeTest = value;
    else if (name == "msaa") next.msaa = toInt(value);
    else if (name == "per-sample") next.msaaPerSample = toBool(value);
    else if (name == "transparency") next.transparency = toBool(value) ? "on" : "off";
    else if (name == "volume-detail") next.volumeDetail = toBool(value);
    else if (name == "tile-size") next.tileSize = toInt(value);
    else if (name == "depth-bounds") next.noDepthBounds = !toBool(value);
    else if (name == "half-z") next.halfZ = toBool(value);
    else if (name == "cluster-tile-size") next.clusterTileSize = toInt(value);
    else if (name == "cluster-slices") next.clusterSlices = toInt(value);
    else if (name == "cluster-slicing") next.clusterSlicing = value;
    else if (name == "cluster-occupancy") next.clusterOccupancy = toBool(value) ? "on" : "off";
    else if (name == "shadows") next.shadows = value;
    else if (name == "shadow-filter") next.shadowFilter = value;
    else if (name == "shadow-lookup") next.shadowLookup = value;
    else
        throw Error("unknown setting '" + name +
                    "' (mode, scheme, budget, index-bits, volume-test, msaa, per-sample, transparency, volume-detail, "
                    "tile-size, depth-bounds, half-z, cluster-tile-size, cluster-slices, cluster-slicing, "
                    "cluster-occupancy, shadows, shadow-filter, shadow-lookup, lights, scatter, view, paused, speed)");
    if (name.rfind("shadow", 0) == 0) {
        try {
            shadowChoice(next);  // the value checked as lidr-demo checks --shadows, --shadow-filter, --shadow-lookup
        } catch (const std::exception& e) {  // refused, as a choice the library refuses is: the old one stays
            status_ = name + " " + value + " refused: " + e.what();
            lastRefused_ = true;
            std::cerr << "lidr-viewer: " << status_ << std::endl;
            return false;
        }
    }
    return apply(next, name + " " + value);
}

std::string Viewer::setting(const std::string& name) const {
    if (name == "mode") return rc_.mode;
    if (name == "scheme") return rc_.scheme;
    if (name == "budget") return rc_.budget;
    if (name == "index-bits") return rc_.indexBits;
    if (name == "volume-test") return rc_.volumeTest;
    if (name == "msaa") return std::to_string(rc_.msaa.value_or(0));
    if (name == "per-sample") return rc_.msaaPerSample ? "on" : "off";
    if (name == "transparency") return rc_.transparency;
    if (name == "volume-detail") return rc_.volumeDetail ? "on" : "off";
    if (name == "tile-size") return std::to_string(rc_.tileSize);
    if (name == "depth-bounds") return rc_.noDepthBounds ? "off" : "on";
    if (name == "half-z") return rc_.halfZ ? "on" : "off";
    const ClusteredOptions clustered;  // the library's defaults, where the choice leaves them
    if (name == "cluster-tile-size") return std::to_string(rc_.clusterTileSize.value_or(clustered.tileSize));
    if (name == "cluster-slices") return std::to_string(rc_.clusterSlices.value_or(clustered.slices));
    if (name == "cluster-slicing") return rc_.clusterSlicing.value_or(clusterSlicingName(clustered.slicing));
    if (name == "cluster-occupancy") return rc_.clusterOccupancy.value_or(clustered.occupiedClusters ? "on" : "off");
    if (name == "shadows") return rc_.shadows;
    if (name == "shadow-filter") return rc_.shadowFilter.value_or("nearest");
    if (name == "shadow-lookup") return rc_.shadowLookup.value_or("forward");
    if (name == "lights") return std::to_string(lightCount_);
    if (name == "scatter") return std::to_string(scatteredLights_);
    if (name == "file") return scenePath_.empty() ? "built-in" : scenePath_;
    if (name == "view") return viewName(view_);
    if (name == "paused") return paused_ ? "on" : "off";
    throw Error("unknown setting '" + name + "'");
}

}  // namespace lidr::viewer
