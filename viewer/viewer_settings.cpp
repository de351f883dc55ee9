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
    if (rc.mode() != "lidr" || rc.get("scheme") == "auto") return sceneLights;
    for (int bits : {4, 8, 16})
        if (rc.get("index-bits") == std::to_string(bits)) return std::min(sceneLights, (1 << bits) - 1);
    return sceneLights;
}

demo::ShadowChoice Viewer::shadowChoice(const demo::RendererChoice& rc) const {
    demo::RendererChoice c = rc;
    if (c.mode() != "lidr") c.values.erase("shadow-lookup");  // where LIDR looks up: kept for when the mode comes back
    return c.shadowChoice(c.mode());
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

namespace {
std::string settingNames() {
    std::string names;
    for (const RenderOption& o : renderOptions()) names += (names.empty() ? "" : ", ") + o.name;
    return names;
}
}  // namespace

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
    // The renderer's settings: lidr::renderOptions()' names (two kept from the viewer's first scripts: per-sample,
    // depth-bounds), checked by the library as lidr-demo's command line is.
    const bool depthBounds = name == "depth-bounds";
    const std::string option = name == "per-sample" ? "msaa-per-sample" : depthBounds ? "no-depth-bounds" : name;
    if (!findRenderOption(option))
        throw Error("unknown setting '" + name + "' (the renderer's: " + settingNames() +
                    ", per-sample, depth-bounds; the viewer's: lights, scatter, view, paused, speed)");
    demo::RendererChoice next = rc_;
    try {
        next.set(option, depthBounds ? (toBool(value) ? "off" : "on") : value);
    } catch (const Error& e) {  // refused, as a choice the library refuses is: the old one stays
        status_ = name + " " + value + " refused: " + e.what();
        lastRefused_ = true;
        std::cerr << "lidr-viewer: " << status_ << std::endl;
        return false;
    }
    if (name == "mode" && value != "clustered" && value != "auto")  // the grid is the clustered mode's: its defaults next time
        for (const char* c : {"cluster-tile-size", "cluster-slices", "cluster-slicing", "cluster-occupancy", "cluster-light-near"})
            next.values.erase(c);
    // The automatic scheme chooses budget and width itself; a named scheme other than bit-shift needs a fixed
    // budget (only bit-shift's stencil count measures one): the choices the library would refuse are made for the
    // user, who can change them after.
    if (name == "scheme" && value == "auto") next.set("budget", "auto"), next.set("index-bits", "auto");
    else if (name == "scheme" && value != "bitshift" && next.get("budget") == "auto") next.set("budget", "8");
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
    if (name == "per-sample") return rc_.get("msaa-per-sample") == "on" ? "on" : "off";
    if (name == "depth-bounds") return rc_.get("no-depth-bounds") == "on" ? "off" : "on";
    if (name == "msaa") return rc_.given("msaa") ? rc_.get("msaa") : "0";
    const ClusteredOptions clustered;  // the library's defaults, where the choice leaves them
    if (name == "cluster-tile-size" && !rc_.given(name)) return std::to_string(clustered.tileSize);
    if (name == "cluster-slices" && !rc_.given(name)) return std::to_string(clustered.slices);
    if (name == "cluster-slicing" && !rc_.given(name)) return clusterSlicingName(clustered.slicing);
    if (name == "cluster-occupancy" && !rc_.given(name)) return clustered.occupiedClusters ? "on" : "off";
    if (const RenderOption* option = findRenderOption(name)) {
        const std::string v = rc_.get(name);
        return option->type == RenderOptionType::Flag && v.empty() ? "off" : v;
    }
    if (name == "lights") return std::to_string(lightCount_);
    if (name == "scatter") return std::to_string(scatteredLights_);
    if (name == "file") return scenePath_.empty() ? "built-in" : scenePath_;
    if (name == "view") return viewName(view_);
    if (name == "paused") return paused_ ? "on" : "off";
    throw Error("unknown setting '" + name + "'");
}

}  // namespace lidr::viewer
