// Example: a glTF 2.0 scene (meshes, node transforms, base colours and textures, KHR_lights_punctual point
// lights, its first perspective camera) loaded with lidr::loadScene and lit by LIDR, with its lights moved by
// the program every frame. The last frame is checked against lidr's brute-force reference.
//   gltf_scene scene.gltf [frames] [out.png]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <lidr/lidr.h>

int main(int argc, char** argv) {
    if (argc < 2) return std::fprintf(stderr, "usage: gltf_scene scene.gltf [frames] [out.png]\n"), 2;
    const std::string path = argv[1];
    const int frames = argc > 2 ? std::atoi(argv[2]) : 24;
    const std::string out = argc > 3 ? argv[3] : "gltf_scene.png";
    if (frames < 2) return std::fprintf(stderr, "gltf_scene: frames must be at least 2, got %d\n", frames), 2;
    try {
        auto context = lidr::GlContext::create();
        // .gltf / .glb by the extension (scene files and OBJ work the same way); errors name the file and field.
        const lidr::Scene scene = lidr::loadScene(path);
        std::printf("%s: %zu meshes, %zu lights, %dx%d\n", path.c_str(), scene.meshes.size(), scene.lights.size(),
                    scene.width, scene.height);

        lidr::RenderModeOptions options;  // mode "lidr", the automatic configuration
        auto renderer = lidr::createRenderer(options, context->info(), scene, scene.width, scene.height);
        const lidr::ShadingParameters shading = lidr::sceneShading(scene);
        std::vector<lidr::PointLight> lights;
        lidr::ImageRGBA8 first;
        for (int frame = 0; frame < frames; ++frame) {
            // The file's lights, each circling its own position: the program owns the light list per frame.
            lights = scene.lightsAt(scene.time);
            for (size_t i = 0; i < lights.size(); ++i) {
                const float a = 0.3f * float(frame) + 1.7f * float(i);
                lights[i].position += 0.25f * lights[i].radius * glm::vec3(std::cos(a), 0.0f, std::sin(a));
            }
            renderer->render(scene.camera, lights, shading);
            if (frame == 0) first = renderer->targets().readColor();
        }
        const lidr::ImageRGBA8 last = renderer->targets().readColor();
        lidr::writePng(out, last);

        // The same lights through the brute-force reference (every light at every pixel).
        lidr::RenderModeOptions brute;
        brute.mode = "forward-brute";
        auto reference = lidr::createRenderer(brute, context->info(), scene, scene.width, scene.height);
        reference->render(scene.camera, lights, shading);
        const lidr::ImageError error = lidr::compareImages(last, reference->targets().readColor());
        const lidr::ImageError change = lidr::compareImages(first, last);
        std::printf("%s: %ld of %ld pixels changed as the lights moved; against the reference max error %d, PSNR %.1f dB\n",
                    out.c_str(), change.differingPixels, change.comparedPixels, error.maxAbsError, error.psnr);
        // The lights moved, so the image changed; LIDR and the reference agree within a step.
        return change.differingPixels > 0 && error.maxAbsError <= 1 ? 0 : 1;
    } catch (const lidr::Error& e) {
        std::fprintf(stderr, "gltf_scene: %s\n", e.what());
        return 1;
    }
}
