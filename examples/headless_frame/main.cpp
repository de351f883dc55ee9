// Example: render one frame of lidr's default room headless and save it as a PNG.
//   headless_frame [out.png] [width height]
// Build: find_package(lidr) + target_link_libraries(app PRIVATE lidr::lidr) (this folder is built by lidr's
// own CMake when LIDR_BUILD_EXAMPLES is ON, and run by CTest as example.headless_frame).
#include <cstdio>
#include <cstdlib>
#include <string>

#include <lidr/lidr.h>

int main(int argc, char** argv) {
    const std::string out = argc > 1 ? argv[1] : "frame.png";
    const int width = argc > 3 ? std::atoi(argv[2]) : 640, height = argc > 3 ? std::atoi(argv[3]) : 480;
    try {
        // 1. A GL context: headless EGL (Mesa llvmpipe, or a GPU's EGL device), GL 2.1 or newer.
        auto context = lidr::GlContext::create();
        std::printf("GL: %s\n", context->info().summary().c_str());

        // 2. A scene: meshes, materials, point lights (moving along paths) and a camera. Here the built-in room;
        //    lidr::loadSceneFile("scene.json") reads a scene file, lidr/scene/primitives.h builds your own.
        lidr::Scene scene = lidr::makeDefaultScene();
        scene.width = width;
        scene.height = height;
        scene.validate();  // throws lidr::Error naming what is wrong (here: a bad width or height)

        // 3. The renderer: depth pre-pass, light volumes into the light-index texture, forward pass.
        lidr::LidrOptions options;  // defaults: automatic (bit-shift; budget and index width chosen per frame)
        lidr::LidrRenderer renderer(context->info(), scene, options, width, height);

        // 4. One frame: the camera and the lights at time t (light i has index i + 1); sceneShading gives the
        //    scene's ambient, background and directional lights (not indexed: every mode adds them as uniforms).
        const float t = 2.0f;
        const lidr::FrameStats& stats =
            renderer.render(scene.camera, scene.lightsAt(t), lidr::sceneShading(scene));

        // 5. Read the image back and save it.
        lidr::writePng(out, renderer.targets().readColor());
        std::printf("%s: %dx%d, %d of %d lights drawn\n", out.c_str(), width, height, stats.drawnLights,
                    stats.sceneLights);
        return 0;
    } catch (const lidr::Error& e) {  // every failure lidr reports: no context, bad scene, GL errors
        std::fprintf(stderr, "headless_frame: %s\n", e.what());
        return 1;
    }
}
