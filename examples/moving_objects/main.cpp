// Example: objects the program moves, adds and removes while it renders. The renderer keeps each object's
// geometry as uploaded and draws it with the transform the program last gave (Renderer::setObjectTransform);
// light culling follows the moved bounds. Objects are the Scene's meshes by index, then those addObject returns.
//   moving_objects [frames] [out.png]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <lidr/lidr.h>

int main(int argc, char** argv) {
    const int frames = argc > 1 ? std::atoi(argv[1]) : 24;
    const std::string out = argc > 2 ? argv[2] : "moving_objects.png";
    if (frames < 4) return std::fprintf(stderr, "moving_objects: frames must be at least 4, got %d\n", frames), 2;
    try {
        auto context = lidr::GlContext::create();
        lidr::Scene scene;
        scene.materials.push_back(lidr::Material{"floor", glm::vec3(0.8f), "", glm::vec3(0.3f), 24.0f, 1.0f});
        lidr::addPlane(scene, glm::vec3(0.0f), glm::vec2(20.0f), 0, 16);  // object 0
        // Object 1: a unit box around the origin, placed by its transform below.
        lidr::addBox(scene, glm::vec3(-0.5f, 0.0f, -0.5f), glm::vec3(0.5f, 1.0f, 0.5f), 0);
        for (int i = 0; i < 24; ++i) {  // a ring of lights
            const float a = 6.2831853f * float(i) / 24.0f;
            scene.lights.push_back({glm::vec3(6.0f * std::cos(a), 0.8f, 6.0f * std::sin(a)), 3.5f,
                                    glm::vec3(0.5f + 0.5f * std::cos(a), 0.6f, 0.5f + 0.5f * std::sin(a))});
        }
        scene.camera.position = glm::vec3(0.0f, 12.0f, 14.0f);
        scene.camera.target = glm::vec3(0.0f);
        scene.width = 480;
        scene.height = 320;
        scene.validate();

        lidr::LidrRenderer renderer(context->info(), scene, lidr::LidrOptions{}, scene.width, scene.height);
        const lidr::ShadingParameters shading{glm::vec3(0.03f), glm::vec3(0.0f)};
        // A second object made by the program: a sphere of its own material, added after the first frame.
        lidr::Scene spare;
        lidr::addSphere(spare, glm::vec3(0.0f, 1.0f, 0.0f), 1.0f, 0, 16);
        const lidr::Material red{"red", glm::vec3(0.9f, 0.2f, 0.2f), "", glm::vec3(0.5f), 40.0f, 1.0f};
        lidr::ObjectId sphere = 0;
        lidr::ImageRGBA8 first;
        for (int frame = 0; frame < frames; ++frame) {
            const float t = float(frame) / float(frames);
            // The box circles the centre, turning and growing.
            const glm::mat4 box = glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f),
                                                                        glm::vec3(5.0f * std::cos(6.2831853f * t), 0.0f,
                                                                                  5.0f * std::sin(6.2831853f * t))),
                                                         6.2831853f * t, glm::vec3(0.0f, 1.0f, 0.0f)),
                                             glm::vec3(1.0f + t, 1.0f + 2.0f * t, 1.0f + t));
            renderer.setObjectTransform(1, box);
            if (frame == 1) sphere = renderer.addObject(spare.meshes[0], red);  // appears
            if (frame > 1 && frame < frames - 2)  // rises
                renderer.setObjectTransform(sphere, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 2.0f * t, 0.0f)));
            if (frame == frames - 2) renderer.removeObject(sphere);  // and goes again
            renderer.render(scene.camera, scene.lights, shading);
            if (frame == 0) first = renderer.targets().readColor();
        }
        const lidr::ImageRGBA8 last = renderer.targets().readColor();
        lidr::writePng(out, last);
        const lidr::ImageError change = lidr::compareImages(first, last);
        std::printf("%s: %ld of %ld pixels changed between the first and the last frame; %d of %d lights drawn\n",
                    out.c_str(), change.differingPixels, change.comparedPixels, renderer.lastFrame().drawnLights,
                    int(scene.lights.size()));
        return change.differingPixels > 0 ? 0 : 1;  // the box moved: the image must have changed
    } catch (const lidr::Error& e) {
        std::fprintf(stderr, "moving_objects: %s\n", e.what());
        return 1;
    }
}
