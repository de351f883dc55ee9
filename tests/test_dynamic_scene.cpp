// Dynamic scenes (doc/embedding.md, "Moving, adding and removing objects"): an object moved, added or removed
// after the renderer was built renders exactly as the same scene built that way from the start, in every mode;
// light culling follows the moved bounds (no light dropped); refusals change nothing.
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "gl_test_context.h"
#include "lidr/base/error.h"
#include "lidr/eval/frame_evaluation.h"
#include "lidr/eval/image_compare.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/modes/render_mode.h"
#include "render_helpers.h"

using namespace lidr;
using namespace lidr::test;

namespace {

constexpr ObjectId kBox = 1, kSphere = 2;  // floorScene(): floor, box, sphere

// The floor scene with a light that touches only the box, and only where exactMove() puts it (above its top at
// x 6..9, z -4..-1; no other mesh's bounds): a renderer that culled lights against the box's old bounds would
// drop it.
Scene sceneWithLights() {
    Scene s = floorScene();
    s.lights.push_back(light(glm::vec3(7.5f, 3.2f, -2.5f), 1.2f, glm::vec3(1.0f, 0.6f, 0.3f)));
    s.lights.push_back(light(glm::vec3(-2.0f, 3.0f, -2.0f), 4.0f, glm::vec3(0.4f, 0.7f, 1.0f)));
    s.lights.push_back(light(glm::vec3(4.0f, 3.5f, 2.0f), 3.0f, glm::vec3(0.9f, 0.9f, 0.5f)));
    s.lights.push_back(light(glm::vec3(0.0f, 1.0f, 3.0f), 5.0f, glm::vec3(0.5f, 1.0f, 0.5f)));
    return s;
}

// The same object with its transform applied to its vertices (as an importer bakes node transforms).
void bake(Mesh& mesh, const glm::mat4& t) {
    const glm::mat3 n = glm::transpose(glm::inverse(glm::mat3(t)));
    for (glm::vec3& p : mesh.positions) p = glm::vec3(t * glm::vec4(p, 1.0f));
    for (glm::vec3& v : mesh.normals) v = n * v;
}

ImageRGBA8 renderOnce(Renderer& r, const Scene& s) {
    r.render(s.camera, s.lightsAt(s.time), ShadingParameters{s.ambient, s.backgroundColor});
    return r.targets().readColor();
}

RenderModeOptions modeOptions(const std::string& mode) {
    RenderModeOptions o;
    o.mode = mode;
    return o;
}

// A quarter turn about y and a move to (6, 0, -5): every matrix entry is 0, 1 or -1 or a whole number, so the
// GPU's transform and the CPU's bake give the same floats.
glm::mat4 exactMove() {
    glm::mat4 t(0.0f);
    t[0] = glm::vec4(0.0f, 0.0f, -1.0f, 0.0f);
    t[1] = glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
    t[2] = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
    t[3] = glm::vec4(8.0f, 0.0f, -3.0f, 1.0f);  // the box (x -2..1, z -2..1) lands on x 6..9, z -4..-1
    return t;
}

}  // namespace

TEST_CASE("dynamic scene: a moved, added or removed object renders as the scene built that way", "[dynamic][gl][every-gl]") {
    testContext();
    const std::string mode =
        GENERATE(as<std::string>{}, "lidr", "tiled", "clustered", "forward-multipass", "forward-brute", "auto");
    if (!takeRow(mode == "lidr")) return;
    INFO("mode " << mode);
    const Scene scene = sceneWithLights();
    const RenderModeOptions options = modeOptions(mode);

    SECTION("moved exactly: identical to the baked scene") {
        auto moved = createRenderer(options, testGl(), scene, scene.width, scene.height);
        moved->setObjectTransform(kBox, exactMove());
        Scene baked = scene;
        bake(baked.meshes[kBox], exactMove());
        auto reference = createRenderer(options, testGl(), baked, baked.width, baked.height);
        const ImageRGBA8 got = renderOnce(*moved, scene), want = renderOnce(*reference, baked);
        const ImageError e = compareImages(got, want);
        INFO("max error " << e.maxAbsError << ", " << e.differingPixels << " pixels differ");
        CHECK(e.maxAbsError == 0);
        // The frame did change: the box is somewhere else.
        auto still = createRenderer(options, testGl(), scene, scene.width, scene.height);
        CHECK(compareImages(renderOnce(*still, scene), got).differingPixels > 200);
    }
    SECTION("moved by a rotation and a non-uniform scale: within rounding of the baked scene") {
        const glm::mat4 t = glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(7.0f, 0.0f, -3.0f)),
                                                   glm::radians(30.0f), glm::vec3(0.0f, 1.0f, 0.0f)),
                                       glm::vec3(1.5f, 0.6f, 1.0f));
        auto moved = createRenderer(options, testGl(), scene, scene.width, scene.height);
        moved->setObjectTransform(kBox, t);
        Scene baked = scene;
        bake(baked.meshes[kBox], t);
        auto reference = createRenderer(options, testGl(), baked, baked.width, baked.height);
        const ImageError e = compareImages(renderOnce(*moved, scene), renderOnce(*reference, baked));
        INFO("max error " << e.maxAbsError << ", " << e.differingPixels << " pixels differ, PSNR " << e.psnr);
        // Vertices differ by a rounding step between the two paths: a few silhouette pixels may flip.
        CHECK(e.differingPixels <= long(scene.width) * scene.height / 500);
        CHECK(e.psnr >= 45.0);
    }
    SECTION("removed: identical to the scene without it") {
        auto r = createRenderer(options, testGl(), scene, scene.width, scene.height);
        r->removeObject(kSphere);
        CHECK_THROWS_WITH(r->removeObject(kSphere), Catch::Contains("no object 2"));
        Scene without = scene;
        without.meshes.erase(without.meshes.begin() + long(kSphere));
        auto reference = createRenderer(options, testGl(), without, without.width, without.height);
        CHECK(compareImages(renderOnce(*r, scene), renderOnce(*reference, without)).maxAbsError == 0);
    }
    SECTION("added: identical to the scene built with it, and placed by its transform") {
        Scene without = scene;
        without.meshes.erase(without.meshes.begin() + long(kSphere));
        auto r = createRenderer(options, testGl(), without, without.width, without.height);
        const Material shiny{"added", glm::vec3(0.3f, 0.6f, 0.9f), "", glm::vec3(0.6f), 48.0f, 1.0f};
        const ObjectId id = r->addObject(scene.meshes[kSphere], shiny);
        CHECK(id == without.meshes.size());  // ids continue after the scene's meshes
        Scene with = without;
        with.materials.push_back(shiny);
        with.meshes.push_back(scene.meshes[kSphere]);
        with.meshes.back().material = int(with.materials.size()) - 1;
        auto reference = createRenderer(options, testGl(), with, with.width, with.height);
        CHECK(compareImages(renderOnce(*r, without), renderOnce(*reference, with)).maxAbsError == 0);
        // The new object moves like any other.
        r->setObjectTransform(id, exactMove());
        bake(with.meshes.back(), exactMove());
        auto movedReference = createRenderer(options, testGl(), with, with.width, with.height);
        CHECK(compareImages(renderOnce(*r, without), renderOnce(*movedReference, with)).maxAbsError == 0);
    }
}

TEST_CASE("dynamic scene: LIDR culls lights against the moved bounds and drops none", "[dynamic][lidr][gl][every-gl]") {
    testContext();
    const Scene scene = sceneWithLights();
    LidrRenderer r(testGl(), scene, LidrOptions{}, scene.width, scene.height);
    const std::vector<PointLight> lights = scene.lightsAt(scene.time);
    const ShadingParameters shading{scene.ambient, scene.backgroundColor};
    // The first light touches no mesh's bounds until the box is moved under it.
    {
        LidrRenderer unmoved(testGl(), scene, LidrOptions{}, scene.width, scene.height);
        unmoved.render(scene.camera, lights, shading);
        REQUIRE(unmoved.lastFrame().drawnLights == int(lights.size()) - 1);
    }
    r.setObjectTransform(kBox, exactMove());
    r.render(scene.camera, lights, shading);
    const ImageRGBA8 image = r.targets().readColor();
    ReferenceRenderer ref(testGl(), scene, scene.width, scene.height, int(lights.size()));
    ref.setObjectTransform(kBox, exactMove());
    ref.render(scene.camera, lights, shading);
    const FrameEvaluation ev = evaluateFrame(r, scene.camera, lights, image, ref.targets().readColor());
    CHECK(ev.lists.droppedLightPixels == 0);
    CHECK(ev.lists.invalidSlots == 0);
    CHECK(ev.error.maxAbsError <= 1);
    CHECK(r.lastFrame().drawnLights == int(lights.size()));
}

TEST_CASE("dynamic scene: bad objects and transforms are refused and change nothing", "[dynamic][gl][every-gl]") {
    testContext();
    const Scene scene = sceneWithLights();
    LidrRenderer r(testGl(), scene, LidrOptions{}, scene.width, scene.height);
    const ImageRGBA8 before = renderOnce(r, scene);
    const float nan = std::numeric_limits<float>::quiet_NaN();

    CHECK_THROWS_WITH(r.setObjectTransform(99, glm::mat4(1.0f)), Catch::Contains("no object 99"));
    glm::mat4 t(1.0f);
    t[3].x = nan;
    CHECK_THROWS_WITH(r.setObjectTransform(kBox, t), Catch::Contains("not finite"));
    CHECK_THROWS_WITH(r.setObjectTransform(kBox, glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, 1.0f))),
                      Catch::Contains("not invertible"));
    glm::mat4 projective(1.0f);
    projective[2][3] = -1.0f;
    CHECK_THROWS_WITH(r.setObjectTransform(kBox, projective), Catch::Contains("affine"));

    Mesh broken = scene.meshes[kBox];
    broken.indices.push_back(9999);
    broken.indices.push_back(0);
    broken.indices.push_back(1);
    CHECK_THROWS_WITH(r.addObject(broken, scene.materials[1]), Catch::Contains("out of range"));
    Material glass = scene.materials[1];
    glass.opacity = 0.5f;
    CHECK_THROWS_WITH(r.addObject(scene.meshes[kBox], glass), Catch::Contains("transparent"));
    Material badColour = scene.materials[1];
    badColour.diffuse.r = -1.0f;
    CHECK_THROWS_WITH(r.addObject(scene.meshes[kBox], badColour), Catch::Contains("diffuse"));

    CHECK(compareImages(renderOnce(r, scene), before).maxAbsError == 0);
}
