// lidr-viewer: the interactive viewer. Flies through a scene (the built-in room or --scene FILE) rendered by
// any lidr mode, switches modes, schemes and settings live, shows per-pass times and the debug views.
// --script FILE drives it with scripted inputs and checks (the viewer.script test; doc/viewer.md).
#include <iostream>

#include <CLI/CLI.hpp>

#include "demo_options.h"
#include "lidr/base/error.h"
#include "viewer.h"

int main(int argc, char** argv) {
    CLI::App app{"lidr-viewer: interactive viewer for Light Indexed Deferred Rendering (GLFW + Dear ImGui)"};
    lidr::demo::SceneChoice sceneChoice;
    lidr::demo::RendererChoice rc;
    lidr::viewer::ViewerOptions options;
    sceneChoice.addOptions(app);
    rc.addOptions(app);
    app.add_option("--out", options.outDir, "Folder for screenshots (F12) and saved artefacts (F11)")->capture_default_str();
    app.add_option("--script", options.scriptFile, "Run a script of timed inputs and checks, then exit (doc/viewer.md)");
    app.add_flag("--hidden", options.hidden, "Open the window hidden (scripted runs)");
    app.add_flag("--fixed-size", options.fixedSize,
                 "Render at --width x --height whatever the window's size (default: the frame follows the window)");
    app.add_flag("--paused", options.startPaused, "Start with the light animation paused at the scene's time");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    try {
        lidr::viewer::Viewer viewer(sceneChoice, rc, options);
        return viewer.run();
    } catch (const std::exception& e) {
        std::cerr << "lidr-viewer: error: " << e.what() << "\n";
        return 1;
    }
}
