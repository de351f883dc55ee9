// lidr-demo: renders a scene with LIDR (or --mode tiled, clustered, forward-multipass, forward-brute) and writes what a
// person needs to judge it.
//   --headless (default): render the default room (or --scene FILE) offscreen, compare with the brute-force
//   reference, write images and a summary to --out DIR; --dump DIR adds the raw artefacts.
//   --window: an interactive GLFW window (needs a display) that animates the scene.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iomanip>
#include <map>
#include <optional>

#include <nlohmann/json.hpp>

#include "demo_options.h"
#include "demo_soak.h"
#include "headless_runs.h"
#include "frame_views.h"
#include "lidr/base/gl.h"
#include "lidr/eval/artefacts.h"
#include "lidr/base/error.h"
#include "lidr/eval/frame_evaluation.h"
#include "lidr/eval/light_coverage.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/modes/auto_mode_renderer.h"
#include "lidr/modes/render_mode.h"
#include "lidr/render/material_variants.h"
#include "lidr/render/present.h"
#include "lidr/render/shadow_atlas.h"
#include "lidr/scene/sphere_bounds.h"
#include "lidr/base/visualize.h"

#if LIDR_HAVE_GLFW
#include <GLFW/glfw3.h>
#endif

using namespace lidr;

namespace {

// --list-passes MODE|all: each mode's frame as its passes in order (Renderer::passes(): what each reads and writes,
// and when it runs where not every frame), as the other options build the mode for this scene on this context; the
// automatic mode lists each candidate's. Nothing is drawn.
int listPasses(const demo::SceneChoice& sceneChoice, demo::RendererChoice rc, const std::string& which) {
    if (which != "all" && !isRenderModeName(which))
        throw Error("--list-passes takes a render mode (" + renderModeList() + ") or all; got '" + which + "'");
    const Scene scene = sceneChoice.load();
    std::vector<RenderModeOptions> modes;
    for (const std::string& name : which == "all" ? renderModeNames() : std::vector<std::string>{which}) {
        rc.set("mode", name);
        modes.push_back(rc.renderModeOptions(scene));  // checked before the context
    }
    const std::unique_ptr<GlContext> context = GlContext::create(rc.contextOptions());
    std::cout << "GL: " << context->info().summary() << "\n";
    auto print = [&](const std::string& mode, const std::vector<FramePass>& passes) {
        std::cout << "\n" << mode << " (" << scene.width << "x" << scene.height << "): " << passes.size()
                  << " passes in frame order: what each reads -> what it writes ([x]: where the frame has x)\n"
                  << describePasses(passes);
    };
    for (const RenderModeOptions& mo : modes) {
        const std::unique_ptr<Renderer> renderer = createRenderer(mo, context->info(), scene, scene.width, scene.height);
        const auto* automatic = dynamic_cast<const AutoModeRenderer*>(renderer.get());
        if (!automatic) {
            print(mo.mode, renderer->passes());
            continue;
        }
        std::cout << "\nauto: its frames are those of the candidate it picks by time, one of these:\n";
        for (size_t i = 0; i < automatic->candidates().size(); ++i)
            print("auto: " + automatic->candidates()[i], automatic->renderer(i).passes());
    }
    return 0;
}

int runWindow(const demo::SceneChoice& sceneChoice, demo::RendererChoice rc) {
#if LIDR_HAVE_GLFW
    ContextOptions co = rc.contextOptions();
    if (co.backend != ContextBackend::Auto && co.backend != ContextBackend::Glfw && co.backend != ContextBackend::GlfwGles2)
        throw Error("--window opens a GLFW window: --context must be glfw, glfw-gles2 (OpenGL ES 2.0) or auto, got '" +
                    rc.context + "'");
    if (co.backend == ContextBackend::Auto) co.backend = ContextBackend::Glfw;
    Scene scene = sceneChoice.load();
    demo::checkTargetMemory(scene, rc.renderModeOptions(scene));
    const demo::ShadowChoice shadowChoice = rc.shadowChoice(rc.renderModeOptions(scene).mode);  // before the window
    co.visibleWindow = true;
    co.windowWidth = scene.width;
    co.windowHeight = scene.height;
    co.windowTitle = "lidr-demo";
    auto context = GlContext::create(co);
    std::cout << "GL: " << context->info().summary() << std::endl;
    std::unique_ptr<Renderer> renderer = createRenderer(rc.renderModeOptions(scene), context->info(), scene,
                                                        scene.width, scene.height);
    renderer->setTiming(true);  // interactive: GPU times a frame or more late, never stalling
    const ShadingParameters sceneShadingParameters = sceneShading(scene, rc.outputTransform());
    auto* window = static_cast<GLFWwindow*>(context->nativeWindow());
    // ES 2.0 has no glBlitFramebuffer: the frame goes to the window as one textured triangle there.
    std::optional<FramePresenter> presenter;
    if (context->info().gles) presenter.emplace();
    const double start = glfwGetTime();
    double lastReport = start;
    int framesSinceReport = 0;
    while (!context->shouldClose()) {
        const double now = glfwGetTime();
        // A keyframed scene plays its range over and over: moving meshes re-placed, lights and camera at the time.
        const SceneAnimation& animation = scene.animation;
        float t = scene.time + float(now - start);
        if (animation.end > animation.start && t > animation.end)
            t = animation.start + std::fmod(t - animation.start, animation.end - animation.start);
        placeAnimatedObjects(*renderer, scene, t);
        std::vector<PointLight> lights = scene.lightsAt(t);
        ShadingParameters shading = sceneShadingParameters;
        const Camera camera = cameraAt(scene, t);
        shadowChoice.apply(cameraMatrices(camera, scene.width, scene.height), lights, shading);  // K brightest: again
        const FrameStats& st = renderer->render(camera, lights, shading);
        int fw = 0, fh = 0;
        glfwGetFramebufferSize(window, &fw, &fh);
        if (presenter) {
            if (fw > 0 && fh > 0) presenter->present(renderer->targets(), 0, 0, 0, fw, fh);
        } else {
            glBindFramebuffer(GL_READ_FRAMEBUFFER, renderer->targets().colorFramebuffer().id());
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
            glBlitFramebuffer(0, 0, scene.width, scene.height, 0, 0, fw, fh, GL_COLOR_BUFFER_BIT, GL_LINEAR);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        }
        context->swapBuffers();
        context->pollEvents();
        if (glfwGetKey(window, GLFW_KEY_ESCAPE) == GLFW_PRESS) break;
        ++framesSinceReport;
        if (now - lastReport > 1.0) {
            std::printf("%.1f fps, frame %.2f ms (%s), %d lights drawn, %d shadow casters, %d maps drawn\n",
                        framesSinceReport / (now - lastReport), st.frameMilliseconds(), st.timingMethod, st.drawnLights,
                        st.shadowCasters, st.shadowMapsDrawn);
            std::fflush(stdout);
            lastReport = now;
            framesSinceReport = 0;
        }
    }
    return 0;
#else
    (void)sceneChoice;
    (void)rc;
    throw UnsupportedError("lidr-demo was built without GLFW; --window is not available");
#endif
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"lidr-demo: Light Indexed Deferred Rendering on a GL 2.1-class pipeline"};
    demo::SceneChoice sceneChoice;
    demo::RendererChoice rc;
    sceneChoice.addOptions(app);
    rc.addOptions(app);
    bool headless = false, window = false, noReference = false;
    std::string outDir = "out", dumpDir;
    int frames = 5;
    app.add_flag("--headless", headless, "Render offscreen and write images and a summary (the default)");
    app.add_flag("--window", window, "Open an interactive window (needs a display)");
    app.add_option("--out", outDir, "Folder for images and summary")->capture_default_str();
    app.add_option("--dump", dumpDir, "Also write raw artefacts (index targets, depth, lights, camera) here");
    app.add_option("--frames", frames, "Timed frames (median reported); with --time-step up to 1000000 frames")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000000));
    std::optional<double> timeStep;
    app.add_option("--time-step", timeStep,
                   "Soak run: frame k shows time + k * S seconds; writes soak.csv (image hash, memory, GL objects "
                   "per frame) and soak.json instead of the usual images");
    app.add_flag("--no-reference", noReference, "Skip the brute-force reference and the error figures");
    std::string listPassesMode;
    app.add_option("--list-passes", listPassesMode,
                   "Print the passes of MODE's frame (" + renderModeList() + ", or all) in order, with what each reads "
                   "and writes and when it runs, as the other options build it for the scene on this context; then "
                   "exit without drawing");
    bool listOptions = false;
    app.add_flag("--list-options", listOptions,
                 "Print the renderer settings (lidr::renderOptions(): name, type, default, the modes that read each, "
                 "choices) one a line, tab-separated, and exit");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    if (listOptions) {
        demo::printRenderOptions(std::cout);
        return 0;
    }
    try {
        if (window && headless) throw Error("--window and --headless exclude each other");
        if (!listPassesMode.empty()) return listPasses(sceneChoice, rc, listPassesMode);
        if (window) return runWindow(sceneChoice, rc);
        if (timeStep) {
            if (!std::isfinite(*timeStep) || *timeStep < 0.0)
                throw Error("--time-step must be a finite number of seconds >= 0, got " + std::to_string(*timeStep));
            if (!dumpDir.empty()) throw Error("--dump does not apply to a soak run (--time-step)");
            if (rc.get("shadows") != "off") throw Error("--shadows applies to --headless and --window runs, not a soak run (--time-step)");
            return demo::runSoak(sceneChoice, rc, outDir, frames, *timeStep);
        }
        if (frames > 1000) throw Error("--frames must be in [1, 1000] without --time-step, got " + std::to_string(frames));
        // A dump holds one light table for the frame: global numbering (doc/architecture.md, region-local indices).
        if (!dumpDir.empty()) rc.set("regional-indices", "off");
        return demo::runHeadless(sceneChoice, rc, outDir, dumpDir, frames, !noReference);
    } catch (const std::exception& e) {
        std::cerr << "lidr-demo: error: " << e.what() << "\n";
        return 1;
    }
}
