// lidr-web-native-frame: the native renderer's frame of a scene file with the web page's options, for CTest
// web.chromium's model check (web/run_chromium_check.py compares the page's frame with it). The page's choices
// (web/lidr_web.cpp): N lights (the file's, then scattered over it with lidr::scatterLights' defaults), bit-shift
// packing with budget 4 and 8-bit indices (16 past 255 lights), transparency on, no tile depth bounds, the scene's own camera and time,
// and for a glTF or OBJ model the default environment in place of the ambient (the page's environment "auto").
// Drawn on OpenGL ES 2.0 (EGL), the API WebGL 1 is. Usage: lidr-web-native-frame SCENE LIGHTS MODE WIDTH HEIGHT OUT.png
#include <cstdio>
#include <exception>
#include <string>

#include "lidr/lidr.h"
#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/light_scatter.h"

int main(int argc, char** argv) {
    if (argc != 7) {
        std::fprintf(stderr, "usage: lidr-web-native-frame SCENE LIGHTS MODE WIDTH HEIGHT OUT.png\n");
        return 2;
    }
    try {
        const int lights = std::stoi(argv[2]), width = std::stoi(argv[4]), height = std::stoi(argv[5]);
        lidr::Scene scene = lidr::loadScene(argv[1]);
        const std::string ext = lidr::lowerCaseExtension(argv[1]);
        if (ext == ".glb" || ext == ".gltf" || ext == ".obj") lidr::giveModelDefaultEnvironment(scene);
        const int extra = lights - int(scene.lights.size());
        if (extra > 0) {
            lidr::LightScatterOptions scatter;
            scatter.count = extra;
            lidr::addScatteredLights(scene, scatter);
        }
        lidr::ContextOptions co;
        co.backend = lidr::ContextBackend::EglGles2;
        const auto context = lidr::GlContext::create(co);
        lidr::RenderModeOptions o;
        o.mode = argv[3];
        o.lidr.packing = {lidr::PackingSchemeKind::BitShift, 4, lights > 255 ? 16 : 8};
        o.transparency = true;
        o.tiled.depthBounds = false;
        const auto renderer = lidr::createRenderer(o, context->info(), scene, width, height);
        std::vector<lidr::PointLight> frameLights = scene.lightsAt(scene.time);
        if (int(frameLights.size()) > lights) frameLights.resize(size_t(lights));
        renderer->render(scene.camera, frameLights, lidr::sceneShading(scene));
        lidr::writePng(argv[6], renderer->targets().readColor());
        std::printf("lidr-web-native-frame: %s, %d lights, %s, %dx%d: %s (%s)\n", argv[1], lights, argv[3], width,
                    height, argv[6], context->info().summary().c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lidr-web-native-frame: %s\n", e.what());
        return 1;
    }
}
