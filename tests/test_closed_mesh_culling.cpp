// GpuScene culls the inner side of closed meshes (lidr/scene/closed_mesh.h) when the eye and the near plane are
// outside their bounds: every mode draws the same image with and without it, from outside, from inside a closed
// mesh's bounds, with the near plane cutting one open, and with a mirroring transform.
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "gl_test_context.h"
#include "lidr/base/gl.h"
#include "lidr/eval/image_compare.h"
#include "lidr/modes/render_mode.h"
#include "lidr/scene/primitives.h"
#include "render_helpers.h"

using namespace lidr;
using namespace lidr::test;

namespace {
// Per batch in draw order (the test floor: floor, box, sphere, then what a view adds): B back faces culled, F front
// faces culled, - both sides drawn; returns how many are culled.
int culledBatches(GpuScene& scene, const CameraMatrices& cam, std::string& sides) {
    int culled = 0;
    sides.clear();
    for (size_t b = 0; b < scene.batchCount(); ++b) {
        const GLenum side = scene.culledSide(b, cam);
        sides += side == GL_BACK ? 'B' : side == GL_FRONT ? 'F' : '-';
        culled += side != 0;
    }
    return culled;
}
}  // namespace

TEST_CASE("closed meshes: the inner side culled, the same image in every mode", "[render][culling][every-gl]") {
    testContext();
    struct View {
        const char* name;
        void (*setUp)(Scene&);
        const char* sides;  // per batch: B back culled, F front culled, - both sides drawn
    };
    const View views[] = {
        {"outside every mesh", [](Scene&) {}, "-BB"},
        {"inside a closed box",
         [](Scene& s) { addBox(s, s.camera.position - glm::vec3(2.0f), s.camera.position + glm::vec3(2.0f), 1); },
         "-BB-"},
        {"near plane cutting the sphere open",
         [](Scene& s) {
             s.camera.position = glm::vec3(4.0f, 1.6f, 2.0f + 1.5f + 0.3f);  // the sphere: centre (4, 1.5, 2), radius 1.5
             s.camera.target = glm::vec3(4.0f, 1.5f, -10.0f);
         },
         "-B-"},
        {"a mirrored box (the winding turned over)", [](Scene&) {}, "-FB"},
    };
    const char* modes[] = {"lidr", "tiled", "clustered", "forward-multipass", "forward-brute"};
    for (const View& v : views) {
        for (const char* mode : modes) {
            if (!takeRow(std::string(mode) == "lidr")) continue;
            DYNAMIC_SECTION(v.name << ", " << mode) {
                Scene scene = floorScene();
                scene.lights = {light(glm::vec3(0.0f, 1.0f, 0.0f), 5.0f), light(glm::vec3(3.0f, 3.5f, 3.5f), 4.0f),
                                light(glm::vec3(-2.0f, 2.8f, 1.5f), 3.0f)};
                v.setUp(scene);
                const bool mirror = std::string(v.name).find("mirrored") != std::string::npos;
                RenderModeOptions o;
                o.mode = mode;
                o.tiled.depthBounds = !testGl().gles;  // ES 2.0 refuses tiled's depth bounds (mediump gl_FragCoord)
                const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
                ImageRGBA8 images[2];
                for (int cull = 0; cull < 2; ++cull) {
                    const auto renderer = createRenderer(o, testGl(), scene, scene.width, scene.height);
                    GpuScene& gpu = *renderer->gpuScenes().at(0);
                    if (mirror) {  // the box mirrored in x about its own centre (-0.5, ., -0.5)
                        const glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(-0.5f, 0.0f, 0.0f)) *
                                            glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)) *
                                            glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.0f, 0.0f));
                        gpu.setTransform(1, m);
                    }
                    gpu.setCullClosedMeshes(cull == 1);
                    std::string sides;
                    const int culled = culledBatches(gpu, cam, sides);
                    if (cull == 1) {
                        std::string expected = v.sides;
                        if (std::string(mode) == "forward-multipass")  // draws the scene in reverse (DrawOrder)
                            expected.assign(expected.rbegin(), expected.rend());
                        CHECK(sides == expected);
                    } else {
                        CHECK(culled == 0);
                    }
                    renderer->render(scene.camera, scene.lights, {});
                    images[cull] = renderer->targets().readColor();
                }
                const ImageError e = compareImages(images[0], images[1]);
                INFO("both sides against inner side culled: max " << e.maxAbsError << ", pixels differing "
                                                                    << e.differingPixels);
                CHECK(e.differingPixels == 0);
                REQUIRE(glGetError() == GL_NO_ERROR);
            }
        }
    }
}
