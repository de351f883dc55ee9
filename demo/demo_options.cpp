#include "demo_options.h"

#include "lidr/default_scene.h"
#include "lidr/error.h"
#include "lidr/packing_scheme.h"
#include "lidr/scene_loader.h"

namespace lidr::demo {

void SceneChoice::addOptions(CLI::App& app) {
    app.add_option("--scene", sceneFile, "Scene file (JSON, see doc/scene-format.md); default: the built-in room");
    app.add_option("--width", width, "Override the scene's width in pixels");
    app.add_option("--height", height, "Override the scene's height in pixels");
    app.add_option("--time", time, "Animation time in seconds (default: the scene's)");
    app.add_option("--seed", seed, "Seed of the built-in room's lights");
}

Scene SceneChoice::load() const {
    Scene scene;
    if (sceneFile.empty()) {
        DefaultSceneOptions o;
        o.seed = seed;
        if (time >= 0.0) o.time = float(time);
        scene = makeDefaultScene(o);
    } else {
        scene = loadSceneFile(sceneFile);
        if (time >= 0.0) scene.time = float(time);
    }
    if (width != 0) scene.width = width;
    if (height != 0) scene.height = height;
    scene.validate();
    return scene;
}

void RendererChoice::addOptions(CLI::App& app) {
    std::string schemes;
    for (const std::string& n : packingSchemeNames()) schemes += (schemes.empty() ? "" : ", ") + n;
    app.add_option("--scheme", scheme,
                   "Packing scheme: " + schemes +
                       " (bitshift: CONSTANT_COLOR bit shifting; max-stencil: MAX blend + stencil rank windows; "
                       "cpu-sorted: CPU overlap sorting into colour-masked groups; see doc/packing.md)");
    app.add_option("--budget", budget, "Light slots per pixel (1, 2, 4, 8, 16)");
    app.add_option("--index-bits", indexBits, "Light index width: 4, 8 or 16 bits");
    app.add_option("--volume-test", volumeTest, "Light volume test: backface (cheap) or exact (stencil)");
    app.add_option("--context", context, "GL context: auto, egl, egl-device, glfw, osmesa (env LIDR_CONTEXT)");
    app.add_flag("--fixed-light-table", fixedLightTable, "Use the RGBA8 fixed-point light table (no float textures)");
}

LidrOptions RendererChoice::lidrOptions() const {
    LidrOptions o;
    o.packing.scheme = scheme;
    o.packing.budget = budget;
    o.packing.indexBits = indexBits;
    o.volumeTest = parseVolumeTest(volumeTest);
    o.forceFixedLightTable = fixedLightTable;
    return o;
}

ContextOptions RendererChoice::contextOptions() const {
    ContextOptions o;
    o.backend = parseContextBackend(context);
    return o;
}

}  // namespace lidr::demo
