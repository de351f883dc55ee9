// The page's state and what changes it (web/page_state.h).
#include "page_state.h"

#include "lidr/base/gl.h"

#include <emscripten.h>
#include <emscripten/html5.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "lidr/base/error.h"
#include "lidr/render/shadow_casters.h"
#include "lidr/scene/io/environment_file.h"
#include "lidr/scene/light_scatter.h"
#include "lidr/scene/render_mode_names.h"
#include "page_bench.h"
#include "page_query.h"

namespace lidr::web {

Page* page = nullptr;

int maxLights() {
    return page->model ? kMaxModelLights : int(page->fileScene.lights.size());
}

// The scene for a light count: the room keeps its lights (the count picks the first N when drawing); a model
// gets count - its own lights scattered over it (none when it has enough).
Scene sceneWithLights(const Scene& file, bool model, int count) {
    Scene scene = file;
    const int extra = count - int(file.lights.size());
    if (model && extra > 0) {
        LightScatterOptions o;
        o.count = extra;
        addScatteredLights(scene, o);
    }
    return scene;
}

// The frame's lights, with castsShadow as the shadow setting says, and its shading (shadows on or off).
std::vector<PointLight> currentLights(const Camera& camera, ShadingParameters& shading) {
    std::vector<PointLight> lights = page->scene.lightsAt(page->time);
    if (int(lights.size()) > page->settings.lightCount) lights.resize(size_t(page->settings.lightCount));
    shading = sceneShading(page->scene);
    const Settings& s = page->settings;
    if (s.environment == "auto") {
        Scene lit;  // the tools' rule for models (lidr::giveModelDefaultEnvironment), on the shading alone
        lit.ambient = shading.ambient;
        if (page->model && !shading.environment.on() && giveModelDefaultEnvironment(lit)) {
            shading.environment.map = lit.environment;
            shading.ambient = lit.ambient;
        }
    } else if (s.environment == "none") {
        shading.environment.map = nullptr;
    } else {
        shading.environment.map = s.environment == "default" ? defaultEnvironment() : page->environmentFile;
    }
    shading.environment.intensity = s.environmentIntensity;
    if (s.shadows == "off") return lights;
    if (s.shadows != "scene")
        chooseShadowCasters(lights, cameraMatrices(camera, page->width, page->height), std::stoi(s.shadows));
    shading.shadows.enabled = true;
    shading.shadows.filtered = s.shadowFilter;
    shading.shadows.atlas.size = kShadowAtlasSize;
    shading.shadows.atlas.tileSize = shadowTileToFit(lights, kShadowAtlasSize);
    return lights;
}

std::unique_ptr<Renderer> makeRenderer(const Settings& s) {
    RenderModeOptions o;
    o.mode = s.mode;
    o.lidr.packing = {parsePackingScheme(s.scheme), s.budget, s.indexBits};
    o.transparency = true;
    // WebGL 1 (GLSL ES 1.00) gives gl_FragCoord.z at mediump only, which the tiled mode's depth bounds refuse.
    o.tiled.depthBounds = false;
    return createRenderer(o, page->context->info(), page->scene, page->width, page->height);
}

// Applies new settings; anything the library refuses keeps the old ones and says why (as lidr-viewer does).
bool applySettings(Settings wanted, bool sceneChanged) {
    try {
        if (wanted.lightCount < 1 || wanted.lightCount > maxLights())
            throw Error("light count: 1 to " + std::to_string(maxLights()) + ", got " +
                        std::to_string(wanted.lightCount));
        // A model's light count is its scene's: more lights are scattered over it, so the scene changes.
        const bool lightsChanged = page->model && wanted.lightCount != page->settings.lightCount;
        std::string note;
        if (wanted.mode == "lidr" && wanted.lightCount > (1 << wanted.indexBits) - 1) {
            // (as lidr-viewer's scheme choice does: a choice the library would refuse is made for the user)
            note = std::to_string(wanted.indexBits) + "-bit indices hold " +
                   std::to_string((1 << wanted.indexBits) - 1) + " lights: index bits set to 16 for " +
                   std::to_string(wanted.lightCount);
            wanted.indexBits = 16;
        }
        const bool rebuild = wanted.mode != page->settings.mode || wanted.scheme != page->settings.scheme ||
                             wanted.budget != page->settings.budget ||
                             wanted.indexBits != page->settings.indexBits || !page->renderer || sceneChanged ||
                             lightsChanged;
        if (wanted.view != "frame" && wanted.view != "reference" && wanted.view != "difference" &&
            wanted.view != "index-lists" && wanted.view != "overlap" && wanted.view != "shadow-atlas")
            throw Error("view '" + wanted.view +
                        "' (valid: frame, reference, difference, index-lists, overlap, shadow-atlas)");
        if (wanted.shadows != "off" && wanted.shadows != "scene") {
            const bool digits = !wanted.shadows.empty() && wanted.shadows.size() <= 5 &&
                                wanted.shadows.find_first_not_of("0123456789") == std::string::npos;
            if (!digits) throw Error("shadows: off, scene or a number of lights K, got '" + wanted.shadows + "'");
        }
        if (wanted.environment != page->settings.environment && wanted.environment != "auto" &&
            wanted.environment != "none" && wanted.environment != "default") {
            // A file the page wrote: read (and checked) now; a refusal keeps the environment shown.
            page->environmentFile = loadEnvironment(wanted.environment);
            page->environmentFileName = wanted.environment;
        }
        validateEnvironmentIntensity(wanted.environmentIntensity, "environment intensity");
        if (wanted.view == "shadow-atlas" && wanted.shadows == "off")
            throw Error("the shadow-atlas view shows the shadow maps: turn shadows on");
        if ((wanted.view == "index-lists" || wanted.view == "overlap") && wanted.mode != "lidr")
            throw Error("the " + wanted.view + " view shows LIDR's index lists: choose mode lidr");
        if (rebuild) {
            Scene oldScene;
            if (lightsChanged || sceneChanged) {
                oldScene = std::move(page->scene);
                page->scene = sceneWithLights(page->fileScene, page->model, wanted.lightCount);
            }
            if (lightsChanged || sceneChanged) {  // the old scene's GL objects go before the new ones are made
                page->reference.reset();
                page->depthReadback.reset();
            }
            try {
                // Untimed passes: the frame is timed whole, finished by a 1-pixel read (frame()).
                std::unique_ptr<Renderer> r = makeRenderer(wanted);
                page->renderer = std::move(r);
            } catch (...) {
                if (lightsChanged || sceneChanged) page->scene = std::move(oldScene);
                throw;
            }
            if (lightsChanged || sceneChanged) {
                page->reference.reset();
                page->depthReadback.reset();
            }
        }
        page->settings = wanted;
        page->message = note;
        return true;
    } catch (const std::exception& e) {
        page->message = e.what();
        return false;
    }
}

// One frame of the page's renderer, in milliseconds. WebGL returns from draw calls at once and runs them later; a
// 1-pixel glReadPixels of the frame's own target returns only when every command before it has run, so the clock
// from the first call to it is the frame's time on the GPU (plus one small read). EXT_disjoint_timer_query is not
// used: lidr's ES path has no timer queries, headless Chromium does not offer it, and the read works everywhere.
double renderTimed(const Camera& camera, const std::vector<PointLight>& lights, const ShadingParameters& shading) {
    const double start = emscripten_get_now();
    page->renderer->render(camera, lights, shading);
    glBindFramebuffer(GL_FRAMEBUFFER, page->renderer->targets().colorFramebuffer().id());
    uint8_t pixel[4];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return emscripten_get_now() - start;
}

// One setting by its name and text (lidr_web_set's names); throws lidr::Error for an unknown name or a number
// that is not one. The value itself is checked by applySettings and the library.
void setFromText(Settings& s, const std::string& n, const std::string& v) {
    if ((n == "budget" || n == "index-bits") && v == "auto")  // the option table's value, not the page's
        throw Error(n + ": the page takes a number, not auto (the automatic budget measures the overlap with "
                        "occlusion queries, which WebGL 1 does not have)");
    try {
        if (n == "mode") s.mode = v;
        else if (n == "scheme") s.scheme = v;
        else if (n == "budget") s.budget = std::stoi(v);
        else if (n == "index-bits") s.indexBits = std::stoi(v);
        else if (n == "view") s.view = v;
        else if (n == "lights") s.lightCount = std::stoi(v);
        else if (n == "paused") s.paused = v == "1" || v == "true";
        else if (n == "shadows") s.shadows = v;
        else if (n == "shadow-filter") s.shadowFilter = v == "pcf";
        else if (n == "environment") s.environment = v;
        else if (n == "environment-intensity") s.environmentIntensity = std::stof(v);
        else throw Error("unknown setting '" + n +
                         "' (mode, scheme, budget, index-bits, view, lights, paused, shadows, shadow-filter, "
                         "environment, environment-intensity, time, follow-camera)");
    } catch (const std::logic_error&) {  // std::stoi / std::stof
        throw Error("setting " + n + ": a number, got '" + v + "'");
    }
}

// The image at `width` x `height` (the canvases and every renderer's targets); false, keeping the old size, where
// it is out of range or the library refuses the renderer at that size (the reason in page->message).
bool resizePage(int width, int height) {
    if (width < web::kMinPageSide || width > web::kMaxPageSide || height < web::kMinPageSide ||
        height > web::kMaxPageSide) {
        page->message = "image size " + std::to_string(width) + "x" + std::to_string(height) + ": each side " +
                        std::to_string(web::kMinPageSide) + " to " + std::to_string(web::kMaxPageSide);
        return false;
    }
    if (width == page->width && height == page->height && page->renderer) return true;
    const int oldWidth = page->width, oldHeight = page->height;
    std::unique_ptr<Renderer> old = std::move(page->renderer);  // applySettings builds one at the new size
    page->width = width;
    page->height = height;
    if (!applySettings(page->settings)) {
        page->width = oldWidth;
        page->height = oldHeight;
        page->renderer = std::move(old);
        return false;
    }
    page->reference.reset();  // made again at the new size when a view needs them
    page->depthReadback.reset();
    emscripten_set_canvas_element_size("#canvas", width, height);
    EM_ASM({
        const view = document.getElementById('view');
        view.width = $0;
        view.height = $1;
    }, width, height);
    return true;
}

// bench=N: N frames of each mode in `modes` (empty: every mode but auto) from the page's camera, at its time and
// settings, each finished by a 1-pixel read (renderTimed); a first frame per mode is drawn untimed (its shader
// variants compiled, its tables uploaded). The settings are put back after. Returns the table (web/page_bench.h).
std::string runBench(int frames, std::vector<std::string> modes) {
    if (modes.empty())
        for (const std::string& m : renderModeNames())
            if (m != "auto") modes.push_back(m);
    const Settings kept = page->settings;
    const Camera camera = page->camera.camera();
    std::vector<web::BenchRow> rows;
    for (const std::string& mode : modes) {
        web::BenchRow row{mode, {}, ""};
        Settings wanted = kept;
        wanted.mode = mode;
        wanted.view = "frame";
        if (!applySettings(wanted)) {
            row.refused = page->message;
            rows.push_back(row);
            continue;
        }
        try {
            placeAnimatedObjects(*page->renderer, page->scene, page->time);
            ShadingParameters shading;
            const std::vector<PointLight> lights = currentLights(camera, shading);
            for (int i = -1; i < frames; ++i) {
                const double ms = renderTimed(camera, lights, shading);
                if (i >= 0) row.frameMs.push_back(ms);
            }
        } catch (const std::exception& e) {
            row.frameMs.clear();
            row.refused = e.what();
        }
        rows.push_back(row);
    }
    applySettings(kept);
    page->message.clear();
    const std::string what = std::to_string(frames) + " frames per mode (each finished by a 1-pixel glReadPixels; "
                             "one untimed frame before), " + std::to_string(page->width) + "x" +
                             std::to_string(page->height) + ", " + page->sceneName + ", " +
                             std::to_string(std::min(page->settings.lightCount, int(page->scene.lights.size()))) +
                             " lights, shadows " + page->settings.shadows + ", " + page->context->info().summary();
    return web::benchTable(what, rows);
}

}  // namespace lidr::web
