// Which lights cast shadows (issue 30; doc/shadows.md, "Casters, tools and cost"): a scene file's "shadow", glTF's
// extras.lidr.shadow on a KHR_lights_punctual light or its node, each with its errors named by field or JSON path;
// and the library's rule, chooseShadowCasters: the K brightest lights (luminance x range^2) that can touch the view,
// spot lights wider than one map covers never.
#include <string>

#include <catch2/catch.hpp>

#include "gltf_file.h"
#include "lidr/base/error.h"
#include "lidr/render/shadow_atlas.h"
#include "lidr/render/shadow_casters.h"
#include "lidr/scene/io/scene_file.h"
#include "lidr/scene/io/scene_loader.h"
#include "temp_dir.h"

using namespace lidr;
using namespace lidr::test;
using Catch::Matchers::Contains;

namespace {

template <class F>
std::string errorOf(F f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(accepted)";
}

GltfFile litTriangle(const Json& lightExtras, const Json& nodeExtras) {
    GltfFile file;
    const int p = file.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int i = file.indices({0, 1, 2});
    file.mesh({{"attributes", {{"POSITION", p}}}, {"indices", i}});
    file.node({{"mesh", 0}}, true);
    file.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    Json light = {{"type", "point"}, {"range", 4.0}};
    if (!lightExtras.is_null()) light["extras"] = lightExtras;
    file.doc["extensions"]["KHR_lights_punctual"]["lights"] = {light, {{"type", "spot"}, {"spot", Json::object()}}};
    Json node = {{"translation", {0, 2, 0}}};
    node["extensions"]["KHR_lights_punctual"]["light"] = 0;
    if (!nodeExtras.is_null()) node["extras"] = nodeExtras;
    file.node(node, true);
    Json spotNode = {{"translation", {1, 2, 0}}};
    spotNode["extensions"]["KHR_lights_punctual"]["light"] = 1;
    file.node(spotNode, true);
    return file;
}

PointLight lightAt(glm::vec3 position, float radius, glm::vec3 color) {
    PointLight l;
    l.position = position;
    l.radius = radius;
    l.color = color;
    return l;
}

}  // namespace

TEST_CASE("scene files: a light's \"shadow\" says whether it casts, checked like the other fields",
          "[shadows][casters][cpu][bad-input]") {
    const Scene scene = parseSceneJson(R"({"lights": [
        {"position": [0, 4, 0], "radius": 6, "shadow": true},
        {"position": [1, 4, 0], "radius": 6, "type": "spot", "direction": [0, -1, 0], "shadow": true},
        {"position": [2, 4, 0], "radius": 6, "shadow": false},
        {"position": [3, 4, 0], "radius": 6}]})", ".", "casters.json");
    REQUIRE(scene.lights.size() == 4);
    CHECK(scene.lights[0].castsShadow);
    CHECK(scene.lights[1].castsShadow);
    CHECK(scene.lights[1].isSpot());
    CHECK_FALSE(scene.lights[2].castsShadow);
    CHECK_FALSE(scene.lights[3].castsShadow);
    const auto error = [](const std::string& value) {
        return errorOf([&] {
            parseSceneJson(R"({"lights": [{"position": [0, 1, 0], "radius": 2, "shadow": )" + value + "}]}", ".",
                           "bad.json");
        });
    };
    for (const char* wrong : {"1", "\"yes\"", "null", "[true]"}) {
        INFO("\"shadow\": " << wrong);
        CHECK_THAT(error(wrong), Contains("bad.json") && Contains("lights[0].shadow") && Contains("true or false"));
    }
    CHECK_THAT(errorOf([] {
                   parseSceneJson(R"({"lights": [{"position": [0, 1, 0], "radius": 2, "shadows": true}]})", ".", "bad.json");
               }),
               Contains("bad.json") && Contains("shadows"));  // a misspelt key is refused, not ignored
}

TEST_CASE("glTF: extras.lidr.shadow on a KHR_lights_punctual light or its node; bad values name their JSON path",
          "[shadows][casters][gltf][cpu][bad-input]") {
    TempDir dir;
    const Json on = {{"lidr", {{"shadow", true}}}}, off = {{"lidr", {{"shadow", false}}}};
    struct Case {
        const char* name;
        Json light, node;
        bool casts;
    };
    const Case c = GENERATE_COPY(Case{"no extras", Json(), Json(), false}, Case{"the light's", on, Json(), true},
                                 Case{"the node's", Json(), on, true}, Case{"the node's wins over the light's", on, off, false},
                                 Case{"other applications' extras are left alone", Json{{"editor", {{"x", 1}}}},
                                      Json("a string"), false});
    DYNAMIC_SECTION(c.name) {
        const Scene scene = loadScene(litTriangle(c.light, c.node).writeGltf(dir, "casters.gltf"));
        REQUIRE(scene.lights.size() == 2);
        CHECK(scene.lights[0].castsShadow == c.casts);
        CHECK_FALSE(scene.lights[1].castsShadow);  // the spot says nothing
    }
    SECTION("errors") {
        const auto error = [&](const Json& light, const Json& node) {
            return errorOf([&] { loadScene(litTriangle(light, node).writeGltf(dir, "bad.gltf")); });
        };
        CHECK_THAT(error({{"lidr", {{"shadow", 1}}}}, Json()),
                   Contains("bad.gltf") && Contains("/extensions/KHR_lights_punctual/lights/0/extras/lidr/shadow") &&
                       Contains("true or false"));
        CHECK_THAT(error(Json(), {{"lidr", {{"shadow", "yes"}}}}),
                   Contains("/nodes/1/extras/lidr/shadow") && Contains("true or false"));
        CHECK_THAT(error({{"lidr", {{"shadows", true}}}}, Json()),
                   Contains("/extensions/KHR_lights_punctual/lights/0/extras/lidr/shadows") &&
                       Contains("unknown lidr setting"));
        CHECK_THAT(error({{"lidr", true}}, Json()),
                   Contains("/extensions/KHR_lights_punctual/lights/0/extras/lidr") && Contains("an object"));
        // On a node that places no light, it could mean nothing.
        GltfFile file = litTriangle(Json(), Json());
        file.doc["nodes"][0]["extras"] = on;
        CHECK_THAT(errorOf([&] { loadScene(file.writeGltf(dir, "meshnode.gltf")); }),
                   Contains("/nodes/0/extras/lidr") && Contains("only for a node with a KHR_lights_punctual light"));
    }
}

TEST_CASE("chooseShadowCasters: the K brightest lights (luminance x range^2) that can touch the view",
          "[shadows][casters][cpu]") {
    Camera camera;
    camera.position = {0.0f, 2.0f, 10.0f};
    camera.target = {0.0f, 2.0f, 0.0f};
    camera.fovYDegrees = 60.0f;
    camera.nearPlane = 0.1f;
    camera.farPlane = 50.0f;
    const CameraMatrices view = cameraMatrices(camera, 320, 240);
    std::vector<PointLight> lights = {
        lightAt({0, 2, 0}, 2.0f, glm::vec3(1.0f)),            // 0: 4
        lightAt({1, 2, 0}, 1.0f, glm::vec3(10.0f)),           // 1: 10
        lightAt({-1, 2, 0}, 4.0f, glm::vec3(0.0f, 1.0f, 0.0f)),  // 2: 0.7152 x 16 = 11.44
        lightAt({0, 2, 40}, 5.0f, glm::vec3(100.0f)),         // 3: behind the camera, out of reach of the view
        lightAt({2, 2, 0}, 3.0f, glm::vec3(0.0f, 0.0f, 1.0f)),  // 4: 0.0722 x 9 = 0.65
        lightAt({0, 2, -2}, 2.0f, glm::vec3(1.0f)),           // 5: 4, a tie with 0: the lower index first
    };
    PointLight wide = lightAt({0, 3, 0}, 5.0f, glm::vec3(50.0f));  // 6: brightest, but a 85-degree spot cone
    wide.direction = {0, -1, 0};
    wide.outerConeAngle = glm::radians(85.0f);
    lights.push_back(wide);
    PointLight narrow = wide;  // 7: the same light with an 80-degree cone, one map's widest
    narrow.outerConeAngle = kMaxShadowConeAngle;
    narrow.color = glm::vec3(0.01f);
    lights.push_back(narrow);
    CHECK(shadowCasterBrightness(lights[2]) == Approx(0.7152f * 16.0f));

    const auto chosen = [&](int k) {
        std::vector<PointLight> l = lights;
        for (PointLight& x : l) x.castsShadow = true;  // every other flag is cleared
        const int n = chooseShadowCasters(l, view, k);
        std::vector<int> out;
        for (size_t i = 0; i < l.size(); ++i)
            if (l[i].castsShadow) out.push_back(int(i));
        CHECK(int(out.size()) == n);
        return out;
    };
    CHECK(chosen(0).empty());
    CHECK(chosen(1) == std::vector<int>{2});
    CHECK(chosen(2) == std::vector<int>{1, 2});
    CHECK(chosen(3) == std::vector<int>{0, 1, 2});
    CHECK(chosen(4) == std::vector<int>{0, 1, 2, 5});
    CHECK(chosen(5) == std::vector<int>{0, 1, 2, 4, 5});
    CHECK(chosen(100) == std::vector<int>{0, 1, 2, 4, 5, 7});  // never 3 (out of view) nor 6 (too wide)
    CHECK_THAT(errorOf([&] { chooseShadowCasters(lights, view, -1); }), Contains("K must be >= 0"));
}
