// Example: lights the program moves itself every frame. A renderer takes the frame's light list in each
// render() call (light i has index i + 1), so lights can move, appear and disappear without rebuilding it;
// only the most a frame may hold is fixed (the scene's light count at construction, within the index width).
//   dynamic_lights [frames] [out.png]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <lidr/lidr.h>

int main(int argc, char** argv) {
    const int frames = argc > 1 ? std::atoi(argv[1]) : 24;
    const std::string out = argc > 2 ? argv[2] : "dynamic_lights.png";
    if (frames < 2) return std::fprintf(stderr, "dynamic_lights: frames must be at least 2, got %d\n", frames), 2;
    try {
        auto context = lidr::GlContext::create();
        // A floor and a few boxes; the scene's lights only set how many a frame may hold (64 here).
        lidr::Scene scene;
        scene.materials.push_back(lidr::Material{"floor", glm::vec3(0.8f), "", glm::vec3(0.3f), 24.0f, 1.0f});
        lidr::addPlane(scene, glm::vec3(0.0f), glm::vec2(20.0f), 0, 16);
        for (int i = 0; i < 5; ++i)
            lidr::addBox(scene, glm::vec3(-7.0f + 3.0f * i, 0.0f, -1.0f), glm::vec3(-6.0f + 3.0f * i, 1.5f, 0.0f), 0);
        scene.lights.assign(64, lidr::PointLight{});
        scene.camera.position = glm::vec3(0.0f, 12.0f, 14.0f);
        scene.camera.target = glm::vec3(0.0f);
        scene.width = 480;
        scene.height = 320;
        scene.validate();

        lidr::LidrOptions options;
        options.timing = true;  // per-pass GPU times, a frame or more late (never stalling); CPU times on Mesa
        lidr::LidrRenderer renderer(context->info(), scene, options, scene.width, scene.height);
        lidr::ImageRGBA8 first, last;
        for (int frame = 0; frame < frames; ++frame) {
            // This frame's lights: a ring of coloured lights turning, and one more light every frame.
            std::vector<lidr::PointLight> lights;
            const int count = std::min(64, 16 + frame);
            for (int i = 0; i < count; ++i) {
                const float a = 6.2831853f * float(i) / float(count) + 0.15f * float(frame);
                lidr::PointLight l;
                l.position = glm::vec3(7.0f * std::cos(a), 0.7f, 7.0f * std::sin(a));
                l.radius = 3.0f;
                l.color = glm::vec3(0.5f + 0.5f * std::cos(a), 0.5f + 0.5f * std::sin(a), 0.6f);
                lights.push_back(l);
            }
            const lidr::FrameStats& stats = renderer.render(scene.camera, lights, {glm::vec3(0.03f), glm::vec3(0.0f)});
            if (!stats.passes.empty() && frame + 1 == frames)
                std::printf("frame %d: %.2f ms (%s, measured %d frame(s) earlier)\n", frame, stats.frameMilliseconds(),
                            stats.timingMethod, stats.timingLag);
            if (frame == 0) first = renderer.targets().readColor();
        }
        last = renderer.targets().readColor();
        lidr::writePng(out, last);
        const lidr::ImageError change = lidr::compareImages(first, last);
        std::printf("%s: %ld of %ld pixels changed between the first and the last frame\n", out.c_str(),
                    change.differingPixels, change.comparedPixels);
        return change.differingPixels > 0 ? 0 : 1;  // the lights moved: the image must have changed
    } catch (const lidr::Error& e) {
        std::fprintf(stderr, "dynamic_lights: %s\n", e.what());
        return 1;
    }
}
