// glTF animations (issue 46): node translation, rotation and scale channels with STEP, LINEAR (slerp for
// rotations) and CUBICSPLINE samplers, against values worked out by hand from the specification's formulas
// (glTF 2.0, appendix C); meshes, a light and a camera carried by animated nodes; a rendered model whose light
// moves, equal to the reference at each time, re-placing only the objects that move.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "gl_test_context.h"
#include "gltf_file.h"
#include "temp_dir.h"
#include "lidr/base/error.h"
#include "lidr/eval/image_compare.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/modes/render_mode.h"
#include "lidr/scene/camera.h"
#include "lidr/scene/io/scene_loader.h"

using Catch::Contains;
using lidr::test::GltfFile;
using lidr::test::Json;
using lidr::test::TempDir;

namespace {

int floats(GltfFile& f, const std::vector<float>& v, const char* type, size_t components) {
    return f.accessor(v.data(), v.size() * 4, 5126, type, v.size() / components);
}

// A channel on `node`: key times and values (3 or 4 floats a value, three values a key for CUBICSPLINE).
void channel(GltfFile& f, int node, const char* path, const char* interpolation, const std::vector<float>& times,
             const std::vector<float>& values) {
    if (!f.doc.contains("animations")) f.doc["animations"] = Json::array({Json{{"samplers", Json::array()}, {"channels", Json::array()}}});
    Json& animation = f.doc["animations"][0];
    const size_t components = std::string(path) == "rotation" ? 4 : 3;
    const int input = floats(f, times, "SCALAR", 1), output = floats(f, values, components == 4 ? "VEC4" : "VEC3", components);
    animation["samplers"].push_back({{"input", input}, {"output", output}, {"interpolation", interpolation}});
    animation["channels"].push_back(
        {{"sampler", animation["samplers"].size() - 1}, {"target", {{"node", node}, {"path", path}}}});
}

int triangleMesh(GltfFile& f) {
    const int p = f.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    return f.mesh({{"attributes", {{"POSITION", p}}}});
}

// Where vertex `vertex` of mesh `mesh` (the triangle's (0,0,0), (1,0,0), (0,1,0)) is at t.
glm::vec3 moved(const lidr::Scene& scene, size_t mesh, float t, size_t vertex) {
    return glm::vec3(lidr::meshTransformsAt(scene, t)[mesh] * glm::vec4(scene.meshes[mesh].positions.at(vertex), 1.0f));
}

}  // namespace

TEST_CASE("glTF animation: LINEAR, STEP and CUBICSPLINE against the specification's formulas", "[gltf][animation][cpu]") {
    TempDir dir;
    GltfFile f;
    const int mesh = triangleMesh(f);
    const int a = f.node({{"mesh", mesh}}, true), b = f.node({{"mesh", mesh}, {"translation", {10, 0, 0}}}, true);
    const int c = f.node({{"mesh", mesh}, {"translation", {0, 10, 0}}}, true);
    // a: LINEAR translation (0,0,0) -> (4,2,0) over t = 0..2.
    channel(f, a, "translation", "LINEAR", {0, 2}, {0, 0, 0, 4, 2, 0});
    // b: STEP scale 1, 2, 3 at t = 0, 1, 2 (translation stays the node's (10, 0, 0)).
    channel(f, b, "scale", "STEP", {0, 1, 2}, {1, 1, 1, 2, 2, 2, 3, 3, 3});
    // c: CUBICSPLINE translation in x, keys t = 0 and 2: v0 = 0 with out-tangent b0 = 3; v1 = 1 with in-tangent
    // a1 = -1. At t = 0.5: s = 0.25, td = 2, p = (2s^3 - 3s^2 + 1) v0 + td (s^3 - 2s^2 + s) b0 + (-2s^3 + 3s^2) v1
    // + td (s^3 - s^2) a1 = 0 + 2 x 0.140625 x 3 + 0.15625 - 2 x 0.046875 x -1 = 1.09375.
    channel(f, c, "translation", "CUBICSPLINE", {0, 2}, {0, 0, 0, 0, 10, 0, 3, 0, 0, -1, 0, 0, 1, 10, 0, 0, 0, 0});
    const lidr::Scene scene = lidr::loadScene(f.writeGltf(dir, "anim.gltf"));
    const lidr::SceneAnimation& anim = scene.animation;
    CHECK(anim.start == 0.0f);
    CHECK(anim.end == 2.0f);
    CHECK(anim.frames == 0);
    REQUIRE(anim.clips.size() == 1);
    CHECK(anim.clips[0] == "glTF animation 0 (3 channels, 0 .. 2 s)");
    REQUIRE(scene.meshes.size() == 3);
    CHECK(scene.time == 0.0f);
    CHECK(moved(scene, 0, 0.5f, 0) == glm::vec3(1.0f, 0.5f, 0.0f));
    CHECK(moved(scene, 0, -1.0f, 0) == glm::vec3(0.0f));  // before the first key: the first value
    CHECK(moved(scene, 0, 5.0f, 0) == glm::vec3(4.0f, 2.0f, 0.0f));
    // STEP: the scale of key k holds until key k + 1; (1, 0, 0) of the mesh is at 10 + scale.
    CHECK(moved(scene, 1, 0.999f, 1).x == Approx(11.0f));
    CHECK(moved(scene, 1, 1.0f, 1).x == Approx(12.0f));
    CHECK(moved(scene, 1, 1.5f, 1).x == Approx(12.0f));
    CHECK(moved(scene, 1, 2.5f, 1).x == Approx(13.0f));
    CHECK(moved(scene, 2, 0.5f, 0).x == Approx(1.09375f));
    CHECK(moved(scene, 2, 0.5f, 0).y == Approx(10.0f));
    CHECK(moved(scene, 2, 2.0f, 0).x == Approx(1.0f));
}

TEST_CASE("glTF animation: LINEAR rotations slerp along the shorter arc", "[gltf][animation][cpu]") {
    TempDir dir;
    GltfFile f;
    const int mesh = triangleMesh(f);
    const int a = f.node({{"mesh", mesh}}, true);
    // Identity to 90 degrees about +y; the second key written as -q (the same rotation): still the short way, so at
    // t = 0.25 the node has turned 22.5 degrees and (1, 0, 0) is at (cos 22.5, 0, -sin 22.5).
    const float h = std::sqrt(0.5f);
    channel(f, a, "rotation", "LINEAR", {0, 1}, {0, 0, 0, 1, 0, -h, 0, -h});
    const lidr::Scene scene = lidr::loadScene(f.writeGltf(dir, "turn.gltf"));
    const glm::vec3 p = moved(scene, 0, 0.25f, 1);
    CHECK(p.x == Approx(std::cos(glm::radians(22.5f))));
    CHECK(p.z == Approx(-std::sin(glm::radians(22.5f))));
    CHECK(p.y == Approx(0.0f).margin(1e-6));
}

TEST_CASE("glTF animation: a light and a camera on animated nodes move with them", "[gltf][animation][cpu]") {
    TempDir dir;
    GltfFile f;
    const int mesh = triangleMesh(f);
    f.doc["extensionsUsed"] = Json::array({"KHR_lights_punctual"});
    f.doc["extensions"]["KHR_lights_punctual"]["lights"] =
        Json::array({Json{{"type", "point"}, {"color", {1, 1, 1}}, {"intensity", 10}, {"range", 3}}});
    f.doc["cameras"] = Json::array({Json{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}});
    // The carrier moves (0,0,0) -> (2,0,0) over t = 0..1 and is scaled 2x; its child holds the light 1 up (in the
    // carrier's space: 2 up in the world), and a camera child sits 5 back.
    const int lamp = f.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", {0, 1, 0}}}, false);
    const int eye = f.node({{"camera", 0}, {"translation", {0, 0, 5}}}, false);
    const int carrier = f.node({{"mesh", mesh}, {"scale", {2, 2, 2}}, {"children", {lamp, eye}}}, true);
    channel(f, carrier, "translation", "LINEAR", {0, 1}, {0, 0, 0, 2, 0, 0});
    lidr::Scene scene = lidr::loadScene(f.writeGltf(dir, "lamp.gltf"));
    REQUIRE(scene.lights.size() == 1);
    CHECK(scene.lights[0].radius == Approx(6.0f));  // range x the node's scale
    const lidr::PointLight l = scene.lightsAt(0.5f)[0];
    CHECK(l.position.x == Approx(1.0f));
    CHECK(l.position.y == Approx(2.0f));
    CHECK(l.radius == Approx(6.0f));
    CHECK(scene.lightsAt(1.0f)[0].position.x == Approx(2.0f));
    const lidr::Camera c = lidr::cameraAt(scene, 0.5f);
    CHECK(c.position.x == Approx(1.0f));
    CHECK(c.position.z == Approx(10.0f));
    CHECK(glm::normalize(c.target - c.position).z == Approx(-1.0f));
    lidr::poseScene(scene, 1.0f);
    CHECK(scene.camera.position.x == Approx(2.0f));
    CHECK(scene.meshes[0].positions[1].x == Approx(4.0f));  // (1, 0, 0) x 2 + (2, 0, 0)
    // chooseView keeps the camera on its node, at the scene's time.
    lidr::chooseView(scene, 0);
    CHECK(scene.camera.position.x == Approx(2.0f));
}

TEST_CASE("glTF animation: what is not played is a warning naming it", "[gltf][animation][cpu]") {
    TempDir dir;
    GltfFile f;
    const int mesh = triangleMesh(f);
    const int a = f.node({{"mesh", mesh}}, true);
    const int hidden = f.node({{"mesh", mesh}}, false);  // in no scene
    channel(f, a, "translation", "LINEAR", {0, 1}, {0, 0, 0, 1, 0, 0});
    channel(f, a, "translation", "LINEAR", {0, 1}, {0, 0, 0, 5, 0, 0});
    channel(f, hidden, "scale", "LINEAR", {0, 1}, {1, 1, 1, 2, 2, 2});
    f.doc["animations"][0]["channels"].push_back({{"sampler", 0}, {"target", {{"node", a}, {"path", "weights"}}}});
    const std::string file = f.writeGltf(dir, "partial.gltf");
    const lidr::Scene scene = lidr::loadScene(file);
    const auto warned = [&](const std::string& text) {
        for (const std::string& w : scene.warnings)
            if (w.find(text) != std::string::npos) return true;
        return false;
    };
    CHECK(warned(file + ": animation 0 channel 1: node 0's translation is moved by an earlier channel already"));
    CHECK(warned(file + ": animation 0 channel 2: node 1 is not in the default scene; its scale is not played"));
    CHECK(warned(file + ": animation 0: 1 morph target weight channel not played (the base shape is drawn)"));
    CHECK(moved(scene, 0, 1.0f, 0).x == Approx(1.0f));  // the first channel plays
}

TEST_CASE("glTF animation: a model whose light moves, equal to the reference at each time", "[gltf][animation][every-gl]") {
    if (!lidr::test::takeRow(true)) return;
    TempDir dir;
    GltfFile f;
    // A 4 x 4 floor (two triangles, normal +y) and a small box-less marker triangle riding with the light; the lamp
    // (range 1.5) moves from x = -1 to x = 1 over t = 0..1, 0.5 above the floor.
    const int floor = f.mesh({{"attributes", {{"POSITION", f.positions({{-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, {-2, 0, -2}})},
                                              {"NORMAL", f.positions({{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}})}}},
                              {"indices", f.indices({0, 1, 2, 0, 2, 3})}});
    f.node({{"mesh", floor}}, true);
    f.doc["extensionsUsed"] = Json::array({"KHR_lights_punctual"});
    f.doc["extensions"]["KHR_lights_punctual"]["lights"] =
        Json::array({Json{{"type", "point"}, {"color", {1, 1, 1}}, {"intensity", 3}, {"range", 1.5}}});
    const int lamp = f.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", {-1, 0.5, 0}}}, true);
    channel(f, lamp, "translation", "LINEAR", {0, 1}, {-1, 0.5, 0, 1, 0.5, 0});
    lidr::Scene scene = lidr::loadScene(f.writeGltf(dir, "moving-lamp.gltf"));
    scene.width = 64;
    scene.height = 48;
    scene.camera.position = {0, 4, 3};
    scene.camera.target = {0, 0, 0};
    scene.ambient = glm::vec3(0.0f);
    const lidr::GlInfo& gl = lidr::test::testGl();
    lidr::RenderModeOptions options;
    options.mode = "lidr";
    auto renderer = lidr::createRenderer(options, gl, scene, scene.width, scene.height);
    lidr::ReferenceRenderer reference(gl, scene, scene.width, scene.height, 1, false, 0, true, false);
    const lidr::CameraMatrices m = lidr::cameraMatrices(scene.camera, scene.width, scene.height);
    const auto pixelOf = [&](const glm::vec3& p) {
        const glm::vec4 clip = m.viewProjection * glm::vec4(p, 1.0f);
        return glm::ivec2(int((clip.x / clip.w * 0.5f + 0.5f) * float(scene.width)),
                          int((0.5f - clip.y / clip.w * 0.5f) * float(scene.height)));
    };
    const uint64_t versionBefore = renderer->gpuScenes()[0]->version();
    for (float t : {0.0f, 1.0f}) {
        // Nothing but the lights moves in this model: no object is re-placed.
        CHECK(lidr::placeAnimatedObjects(*renderer, scene, t) == 0);
        const std::vector<lidr::PointLight> lights = scene.lightsAt(t);
        REQUIRE(lights[0].position.x == Approx(t == 0.0f ? -1.0f : 1.0f));
        renderer->render(lidr::cameraAt(scene, t), lights, lidr::sceneShading(scene));
        reference.render(lidr::cameraAt(scene, t), lights, lidr::sceneShading(scene));
        const lidr::ImageRGBA8 image = renderer->targets().readColor(), truth = reference.targets().readColor();
        CHECK(lidr::compareImages(image, truth).pixelsOverThreshold == 0);
        // Lit under the lamp, dark under where it is not.
        const glm::ivec2 under = pixelOf({lights[0].position.x, 0, 0}), away = pixelOf({-lights[0].position.x, 0, 0});
        INFO("t " << t << ": under the lamp " << int(image.at(under.x, under.y)[0]) << ", away " << int(image.at(away.x, away.y)[0]));
        CHECK(image.at(under.x, under.y)[0] > 60);
        CHECK(image.at(away.x, away.y)[0] < 8);
    }
    CHECK(renderer->gpuScenes()[0]->version() == versionBefore);
}
