// glTF 2.0 import (lidr/scene/io/gltf_importer.h): small files written by the tests themselves (JSON with a
// base64 buffer, a separate .bin, or a .glb), checked for exact positions, lights, cameras, materials and errors;
// and one glTF scene rendered against the same scene written as a lidr JSON file with an OBJ model.
#include <cmath>

#include <catch2/catch.hpp>

#include "lidr/base/colour.h"

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "gltf_file.h"
#include "temp_dir.h"
#include "gl_test_context.h"
#include "lidr/base/error.h"
#include "lidr/eval/image_compare.h"
#include "lidr/modes/render_mode.h"
#include "lidr/scene/camera.h"
#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/io/scene_loader.h"

namespace fs = std::filesystem;
using Catch::Contains;
using Json = nlohmann::json;

using lidr::test::TempDir;

namespace {


using lidr::test::base64;
using lidr::test::GltfFile;

// One triangle (0,0,0) (1,0,0) (0,1,0), indexed, as mesh 0.
GltfFile oneTriangle() {
    GltfFile file;
    const int p = file.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int i = file.indices({0, 1, 2});
    file.mesh({{"attributes", {{"POSITION", p}}}, {"indices", i}});
    return file;
}

void requireNear(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f) {
    INFO("(" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", " << b.y << ", " << b.z << ")");
    REQUIRE(glm::length(a - b) <= tolerance);
}

}  // namespace

TEST_CASE("glTF: node transforms are baked into world space", "[gltf][cpu]") {
    TempDir dir;
    GltfFile file = oneTriangle();
    // parent: translate (10, 0, 0); child: rotate 90 degrees about +y (quaternion x, y, z, w), scale 2.
    const int child = file.node({{"mesh", 0}, {"rotation", {0.0, std::sqrt(0.5), 0.0, std::sqrt(0.5)}}, {"scale", {2, 2, 2}}}, false);
    file.node({{"translation", {10, 0, 0}}, {"children", {child}}}, true);
    // and the mesh again under a matrix node (column-major: translate (0, 0, -5)).
    file.node({{"mesh", 0}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -5, 1}}}, true);
    const lidr::Scene scene = lidr::loadScene(file.writeGltf(dir, "tri.gltf"));
    REQUIRE(scene.meshes.size() == 2);
    const lidr::Mesh& rotated = scene.meshes[0];
    REQUIRE(rotated.indices.size() == 3);
    // (1,0,0) rotated 90 degrees about +y is (0,0,-1); scaled 2, moved by 10 in x.
    requireNear(rotated.positions[rotated.indices[0]], {10, 0, 0});
    requireNear(rotated.positions[rotated.indices[1]], {10, 0, -2});
    requireNear(rotated.positions[rotated.indices[2]], {10, 2, 0});
    // no NORMAL: flat normals, the face's (rotated +z is +x)
    for (const glm::vec3& n : rotated.normals) requireNear(n, {1, 0, 0});
    const lidr::Mesh& moved = scene.meshes[1];
    requireNear(moved.positions[moved.indices[1]], {1, 0, -5});
    CHECK(moved.name == "tri/mesh 0");
    CHECK(scene.lights.empty());
    CHECK(scene.warnings.empty());
}

TEST_CASE("glTF: a mirroring transform keeps triangles counter-clockwise; strips and non-indexed primitives", "[gltf][cpu]") {
    TempDir dir;
    GltfFile file;
    const int p = file.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
    const int n = file.positions({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    file.mesh({{"attributes", {{"POSITION", p}, {"NORMAL", n}}}, {"mode", 5}});  // TRIANGLE_STRIP, not indexed
    file.node({{"mesh", 0}, {"scale", {-1, 1, 1}}}, true);
    const lidr::Scene scene = lidr::loadScene(file.writeGltf(dir, "strip.gltf"));
    REQUIRE(scene.meshes.size() == 1);
    const lidr::Mesh& mesh = scene.meshes[0];
    REQUIRE(mesh.triangleCount() == 2);
    for (size_t t = 0; t < 2; ++t) {
        const glm::vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
                        c = mesh.positions[mesh.indices[3 * t + 2]];
        const glm::vec3 face = glm::cross(b - a, c - a);
        // mirrored in x, the strip faces +z still (its given normals, mirrored through the normal matrix, too)
        CHECK(face.z > 0.0f);
    }
    for (const glm::vec3& normal : mesh.normals) requireNear(normal, {0, 0, 1});
}

TEST_CASE("glTF: KHR_lights_punctual point lights, range -> radius; spot and directional lights down their node's -z",
          "[gltf][cpu]") {
    TempDir dir;
    GltfFile file = oneTriangle();
    file.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    file.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "point"}, {"color", {1.0, 0.5, 0.25}}, {"intensity", 2.0}, {"range", 3.0}},
        {{"type", "point"}, {"intensity", 4.0}},
        {{"type", "spot"}, {"spot", Json::object()}},
        {{"type", "directional"}, {"color", {1.0, 0.8, 0.5}}, {"intensity", 3.0}},
        {{"type", "spot"}, {"range", 5.0}, {"spot", {{"innerConeAngle", 0.25}, {"outerConeAngle", 1.5707963}}}}};
    file.node({{"mesh", 0}}, true);
    const auto lightNode = [&](int light, Json node) {
        node["extensions"]["KHR_lights_punctual"]["light"] = light;
        return node;
    };
    file.node(lightNode(0, {{"translation", {1, 2, 3}}, {"scale", {1, 2, 1}}}), true);
    file.node(lightNode(1, {{"translation", {0, 5, 0}}}), true);
    file.node(lightNode(2, Json::object()), true);
    // -90 degrees about x turns -z to -y (straight down); the translation and scale do not matter.
    file.node(lightNode(3, {{"rotation", {-0.70710678, 0.0, 0.0, 0.70710678}}, {"translation", {4, 4, 4}},
                            {"scale", {3, 3, 3}}}),
              true);
    file.node(lightNode(3, Json::object()), true);  // unrotated: down -z
    file.node(lightNode(4, {{"rotation", {-0.70710678, 0.0, 0.0, 0.70710678}}, {"translation", {0, 3, 0}}}), true);
    const lidr::Scene scene = lidr::loadScene(file.writeGltf(dir, "lights.gltf"));
    REQUIRE(scene.lights.size() == 4);
    // The spot with KHR_lights_punctual's defaults (inner 0, outer pi/4), down -z; the other turned down -y.
    CHECK(scene.lights[2].isSpot());
    requireNear(scene.lights[2].direction, {0, 0, -1});
    CHECK(scene.lights[2].innerConeAngle == 0.0f);
    CHECK(scene.lights[2].outerConeAngle == Approx(0.7853981634f));
    requireNear(scene.lights[3].position, {0, 3, 0});
    requireNear(scene.lights[3].direction, {0, -1, 0});
    CHECK(scene.lights[3].radius == Approx(5.0f));
    CHECK(scene.lights[3].innerConeAngle == Approx(0.25f));
    CHECK(scene.lights[3].outerConeAngle == Approx(1.5707963f));
    REQUIRE_NOTHROW(scene.validate());
    CHECK_FALSE(scene.lights[0].isSpot());
    requireNear(scene.lights[0].position, {1, 2, 3});
    CHECK(scene.lights[0].radius == Approx(6.0f));  // range 3 x the node's largest scale, 2
    // Candela x colour / pi (lidr's colour is what a white Lambert surface shows; it reflects 1/pi of the lux).
    const float pi = 3.14159265f;
    requireNear(scene.lights[0].color, glm::vec3(2.0f, 1.0f, 0.5f) / pi);
    for (const lidr::PointLight& l : scene.lights) CHECK(l.falloff == lidr::LightFalloff::InverseSquare);
    requireNear(scene.lights[1].position, {0, 5, 0});
    // No range: r = sqrt(C / threshold), threshold = half an 8-bit step of the sRGB image at black
    const float threshold = 0.5f / 255.0f / 12.92f;
    CHECK(scene.lights[1].radius == Approx(std::sqrt(4.0f / pi / threshold)));  // 91.6 m for 4 cd
    CHECK(lidr::gltfLightRadiusWithoutRange(1.0f) == Approx(81.17f).epsilon(1e-3));
    CHECK(lidr::gltfLightRadiusWithoutRange(1e12f) == Approx(1000.0f));
    CHECK(lidr::gltfLightRadiusWithoutRange(0.0f) == Approx(0.01f));
    REQUIRE(scene.directionalLights.size() == 2);
    requireNear(scene.directionalLights[0].direction, {0, -1, 0});
    requireNear(scene.directionalLights[0].color, glm::vec3(3.0f, 2.4f, 1.5f) / pi);  // lux x colour / pi
    requireNear(scene.directionalLights[1].direction, {0, 0, -1});
    CHECK(scene.warnings.empty());
}

TEST_CASE("glTF: every number of a light (and of nodes, materials, cameras) must stay finite as a float",
          "[gltf][cpu][bad-input]") {
    // JSON cannot write infinity, but 1e39 is a finite double that becomes +inf as the float lidr keeps: it was
    // read as an infinitely bright light. Each is refused before anything is built, with its JSON pointer.
    TempDir dir;
    struct Case {
        const char* what;
        const char* pointer;  // where 1e39 goes (a vector component: the vector's other values are valid)
        Json light;           // light 0
    };
    const Json point = {{"type", "point"}, {"range", 5.0}};
    const Json spot = {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 0.5}}}};
    const std::vector<Case> cases = {
        {"intensity", "/extensions/KHR_lights_punctual/lights/0/intensity", point},
        {"colour", "/extensions/KHR_lights_punctual/lights/0/color/2", point},
        {"range", "/extensions/KHR_lights_punctual/lights/0/range", point},
        {"inner cone", "/extensions/KHR_lights_punctual/lights/0/spot/innerConeAngle", spot},
        {"outer cone", "/extensions/KHR_lights_punctual/lights/0/spot/outerConeAngle", spot},
        {"node translation", "/nodes/1/translation/0", point},
        {"node scale", "/nodes/1/scale/1", point},
        {"camera zfar", "/cameras/0/perspective/zfar", point},
        {"roughness", "/materials/0/pbrMetallicRoughness/roughnessFactor", point},
        {"emissive strength", "/materials/0/extensions/KHR_materials_emissive_strength/emissiveStrength", point},
    };
    for (const Case& c : cases) {
        DYNAMIC_SECTION(c.what) {
            GltfFile file = oneTriangle();
            file.doc["extensionsUsed"] = {"KHR_lights_punctual", "KHR_materials_emissive_strength"};
            file.doc["extensions"]["KHR_lights_punctual"]["lights"] = Json::array({c.light});  // not {c.light}: clang copies it
            file.doc["extensions"]["KHR_lights_punctual"]["lights"][0]["color"] = {1.0, 1.0, 1.0};
            file.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 50}}}}};
            file.doc["materials"] = {{{"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2}}}}}}};
            file.doc["meshes"][0]["primitives"][0]["material"] = 0;
            file.node({{"mesh", 0}, {"camera", 0}}, true);
            file.node({{"translation", {0, 1, 1}}, {"scale", {1, 1, 1}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
                      true);
            REQUIRE_NOTHROW(lidr::loadScene(file.writeGltf(dir, "valid.gltf")));  // the file without the 1e39 loads
            file.doc[Json::json_pointer(c.pointer)] = 1e39;
            REQUIRE_THROWS_WITH(lidr::loadScene(file.writeGltf(dir, "huge.gltf")),
                                Contains("huge.gltf: " + std::string(c.pointer) + ": 1e+39 is not finite as a 32-bit float"));
            file.doc[Json::json_pointer(c.pointer)] = -1e39;
            REQUIRE_THROWS_WITH(lidr::loadScene(file.writeGltf(dir, "huge.gltf")),
                                Contains(std::string(c.pointer) + ": -1e+39 is not finite as a 32-bit float"));
        }
    }
}

TEST_CASE("glTF: directional lights past the forward shaders' 4, or with no direction, are left out with a warning",
          "[gltf][cpu]") {
    TempDir dir;
    GltfFile file = oneTriangle();
    file.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    file.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "directional"}}};
    file.node({{"mesh", 0}}, true);
    Json sun;
    sun["extensions"]["KHR_lights_punctual"]["light"] = 0;
    Json flat = sun;
    flat["scale"] = {1, 1, 0};  // -z maps to zero
    file.node(flat, true);
    for (int i = 0; i < 5; ++i) file.node(sun, true);
    const lidr::Scene scene = lidr::loadScene(file.writeGltf(dir, "suns.gltf"));
    CHECK(scene.directionalLights.size() == lidr::maxDirectionalLights);
    REQUIRE(scene.warnings.size() == 2);
    CHECK_THAT(scene.warnings[0], Contains("suns.gltf") && Contains("gives no direction"));
    CHECK_THAT(scene.warnings[1], Contains("more than 4 directional lights"));
}

TEST_CASE("glTF: the first perspective camera is the view, else the default view frames the bounds", "[gltf][cpu]") {
    TempDir dir;
    GltfFile file = oneTriangle();
    file.doc["cameras"] = {{{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}},
                           {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.25}, {"zfar", 40}}}},
                           {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.5}}}}};
    file.node({{"mesh", 0}}, true);
    file.node({{"camera", 0}}, true);
    // rotated 90 degrees about +y: looks down -x
    file.node({{"camera", 1}, {"translation", {5, 1, 0}}, {"rotation", {0.0, std::sqrt(0.5), 0.0, std::sqrt(0.5)}}}, true);
    file.node({{"camera", 2}}, true);
    {
        const lidr::Scene scene = lidr::loadScene(file.writeGltf(dir, "cameras.gltf"));
        requireNear(scene.camera.position, {5, 1, 0});
        requireNear(scene.camera.target, {4, 1, 0});
        requireNear(scene.camera.up, {0, 1, 0});
        CHECK(scene.camera.fovYDegrees == Approx(glm::degrees(0.5f)));
        CHECK(scene.camera.nearPlane == Approx(0.25f));
        CHECK(scene.camera.farPlane == Approx(40.0f));
        REQUIRE(scene.warnings.size() == 1);
        CHECK_THAT(scene.warnings[0], Contains("orthographic cameras are not supported"));
        // Every camera is a view, numbered as the file's `cameras`; the default is camera 1, the first usable one.
        REQUIRE(scene.views.size() == 3);
        CHECK(scene.view == 1);
        CHECK(scene.views[1].name == "camera 1");
        CHECK_THAT(scene.views[0].unusable, Contains("orthographic"));
        CHECK(scene.views[2].unusable.empty());
    }
    SECTION("--camera N: chooseView picks camera N, or names the count") {
        lidr::Scene scene = lidr::loadScene(file.writeGltf(dir, "cameras.gltf"));
        lidr::chooseView(scene, 2);
        CHECK(scene.view == 2);
        requireNear(scene.camera.position, {0, 0, 0});
        requireNear(scene.camera.target, {0, 0, -1});
        CHECK(scene.camera.fovYDegrees == Approx(glm::degrees(1.0f)));
        CHECK(scene.camera.nearPlane == Approx(0.5f));
        CHECK(scene.camera.farPlane == Approx(1.5f * std::sqrt(2.0f)));  // no zfar: past the bounds
        REQUIRE_THROWS_WITH(lidr::chooseView(scene, 3),
                            Contains("camera 3 is out of range: the scene has 3 cameras (0 .. 2"));
        REQUIRE_THROWS_WITH(lidr::chooseView(scene, -1), Contains("camera -1 is out of range"));
        REQUIRE_THROWS_WITH(lidr::chooseView(scene, 0),
                            Contains("camera 0 cannot be the view: it is orthographic; lidr draws perspective cameras only"));
        CHECK(scene.view == 2);  // a refused choice keeps the view
        lidr::chooseView(scene, 1);
        requireNear(scene.camera.position, {5, 1, 0});
    }
    SECTION("no zfar: a far plane past the bounds") {
        file.doc["scenes"][0]["nodes"] = {0, 3};
        lidr::Scene scene = lidr::loadScene(file.writeGltf(dir, "infinite.gltf"));
        CHECK(scene.view == 2);
        CHECK(scene.camera.nearPlane == Approx(0.5f));
        // farthest corner of the triangle's bounds from the origin: sqrt(2); 1.5 x that
        CHECK(scene.camera.farPlane == Approx(1.5f * std::sqrt(2.0f)));
        // camera 1 is placed by no node of the default scene
        REQUIRE_THROWS_WITH(lidr::chooseView(scene, 1), Contains("camera 1 cannot be the view: it is placed by no node"));
    }
    SECTION("no camera") {
        file.doc["scenes"][0]["nodes"] = {0};
        const lidr::Scene scene = lidr::loadScene(file.writeGltf(dir, "nocamera.gltf"));
        CHECK(scene.view == -1);
        const lidr::Camera expected = lidr::cameraFramingBounds({0, 0, 0}, {1, 1, 0});
        requireNear(scene.camera.position, expected.position);
        requireNear(scene.camera.target, {0.5f, 0.5f, 0.0f});
        // the bounding sphere (radius sqrt(0.5)) fits the 60 degree field of view with 10% to spare
        CHECK(glm::length(scene.camera.position - scene.camera.target) == Approx(1.1f * std::sqrt(0.5f) / 0.5f));
        CHECK(scene.camera.nearPlane < glm::length(scene.camera.position - scene.camera.target) - std::sqrt(0.5f));
        CHECK(scene.camera.farPlane > glm::length(scene.camera.position - scene.camera.target) + std::sqrt(0.5f));
    }
}

TEST_CASE("glTF: a camera is placed by its node's world transform, parents included", "[gltf][cpu]") {
    TempDir dir;
    GltfFile file = oneTriangle();
    file.doc["cameras"] = {{{"type", "perspective"}, {"name", "Side"},
                            {"perspective", {{"yfov", 0.7}, {"znear", 0.1}, {"zfar", 100}, {"aspectRatio", 2.0}}}}};
    file.node({{"mesh", 0}}, true);
    // child: 1 along its parent's z, turned 90 degrees about +y (looks down the parent's -x); parent: moved by
    // (0, 2, 0) and turned 90 degrees about +x (its +z is the world's -y, its -x stays -x).
    const int child = file.node({{"camera", 0}, {"translation", {0, 0, 1}},
                                 {"rotation", {0.0, std::sqrt(0.5), 0.0, std::sqrt(0.5)}}}, false);
    file.node({{"children", {child}}, {"translation", {0, 2, 0}}, {"rotation", {std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)}}},
              true);
    const lidr::Scene scene = lidr::loadScene(file.writeGltf(dir, "nested.gltf"));
    CHECK(scene.view == 0);
    CHECK(scene.views[0].name == "camera 0 'Side'");
    requireNear(scene.camera.position, {0, 1, 0});
    requireNear(scene.camera.target, {-1, 1, 0});
    requireNear(scene.camera.up, {0, 0, 1});
    CHECK(scene.camera.fovYDegrees == Approx(glm::degrees(0.7f)));  // yfov kept; the image gives the aspect
    CHECK(scene.camera.farPlane == Approx(100.0f));
}

TEST_CASE("glTF: cameras are validated with their JSON pointer", "[gltf][cpu]") {
    TempDir dir;
    struct Case {
        const char* name;
        Json perspective;
        const char* message;  // empty: loads
    };
    const Case cases[] = {
        {"no zfar, aspect given", {{"yfov", 1.0}, {"znear", 0.1}, {"aspectRatio", 1.5}}, ""},
        {"yfov 0", {{"yfov", 0}, {"znear", 0.1}}, "/cameras/0/perspective/yfov: must be in (0, pi) radians"},
        {"yfov pi", {{"yfov", 3.2}, {"znear", 0.1}}, "/cameras/0/perspective/yfov: must be in (0, pi) radians"},
        {"yfov not finite as a float", {{"yfov", 1e39}, {"znear", 0.1}}, "/cameras/0/perspective/yfov: 1e+39 is not finite"},
        {"znear 0", {{"yfov", 1.0}, {"znear", 0}}, "/cameras/0/perspective/znear: must be > 0"},
        {"zfar below znear", {{"yfov", 1.0}, {"znear", 1}, {"zfar", 0.5}}, "/cameras/0/perspective/zfar: must be > znear (1)"},
        {"aspect 0", {{"yfov", 1.0}, {"znear", 0.1}, {"aspectRatio", 0}}, "/cameras/0/perspective/aspectRatio: must be > 0"},
        {"yfov missing", {{"znear", 0.1}}, "/cameras/0/perspective/yfov: required property missing"},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        GltfFile file = oneTriangle();
        file.doc["cameras"] = {{{"type", "perspective"}, {"perspective", c.perspective}}};
        file.node({{"mesh", 0}}, true);
        file.node({{"camera", 0}, {"translation", {0, 0, 3}}}, true);
        const std::string path = file.writeGltf(dir, "camera.gltf");
        if (std::string(c.message).empty()) {
            const lidr::Scene scene = lidr::loadScene(path);
            CHECK(scene.view == 0);
            requireNear(scene.camera.position, {0, 0, 3});
            CHECK(scene.camera.farPlane > 3.0f);
        } else {
            REQUIRE_THROWS_WITH(lidr::loadScene(path), Contains("camera.gltf: " + std::string(c.message)));
        }
    }
}

TEST_CASE("glTF: materials: base colour, BLEND is transparent, MASK an alpha test, embedded texture", "[gltf][cpu]") {
    TempDir dir;
    GltfFile file;
    const int p = file.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const std::vector<float> uv = {0, 0, 1, 0, 0, 1};
    const int t = file.accessor(uv.data(), uv.size() * 4, 5126, "VEC2", 3);
    for (int m = 0; m < 3; ++m) file.mesh({{"attributes", {{"POSITION", p}, {"TEXCOORD_0", t}}}, {"material", m}});
    // a 2x1 PNG: red, green (written by lidr, embedded as a data URI)
    lidr::ImageRGBA8 image(2, 1);
    const uint8_t pixels[8] = {255, 0, 0, 255, 0, 255, 0, 255};
    std::memcpy(image.pixels.data(), pixels, 8);
    lidr::writePng(dir.file("tex.png"), image);
    std::ifstream in(dir.file("tex.png"), std::ios::binary);
    const std::vector<unsigned char> png((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    file.doc["images"] = {{{"uri", "data:image/png;base64," + base64(png)}}};
    file.doc["textures"] = {{{"source", 0}}};
    file.doc["materials"] = {
        {{"name", "glass"}, {"alphaMode", "BLEND"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 0.5}}}}},
        {{"name", "leaves"}, {"alphaMode", "MASK"}, {"alphaCutoff", 0.25}, {"doubleSided", true},
         {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0.3}}}}},
        {{"name", "painted"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.5}}}}};
    for (int m = 0; m < 3; ++m) file.node({{"mesh", m}}, true);
    const lidr::Scene scene = lidr::loadScene(file.writeGltf(dir, "materials.gltf"));
    REQUIRE(scene.meshes.size() == 3);
    const lidr::Material& glass = scene.materials[size_t(scene.meshes[0].material)];
    CHECK(glass.name == "glass");
    requireNear(glass.diffuse, {0.2f, 0.4f, 0.6f});
    CHECK(glass.opacity == 0.5f);  // transparent: drawn after the opaque geometry, blended
    const lidr::Material& leaves = scene.materials[size_t(scene.meshes[1].material)];
    CHECK(leaves.opacity == 1.0f);
    CHECK(leaves.alphaMode == lidr::AlphaMode::Mask);
    CHECK(leaves.alphaCutoff == Approx(0.25f / 0.3f));  // factor alpha 0.3 x texel alpha < 0.25: texel < 0.833
    CHECK(leaves.doubleSided);
    CHECK(glass.alphaMode == lidr::AlphaMode::Opaque);
    CHECK_FALSE(glass.doubleSided);  // glTF's default
    CHECK(scene.warnings.empty());
    const lidr::Material& painted = scene.materials[size_t(scene.meshes[2].material)];
    REQUIRE(painted.diffuseImage);
    REQUIRE(painted.diffuseImage->width == 2);
    CHECK(std::memcmp(painted.diffuseImage->pixels.data(), pixels, 8) == 0);
    // the BRDF is glTF's: the factors go through as they are
    CHECK(painted.metallicRoughness);
    CHECK(painted.metallic == 0.0f);
    CHECK(painted.roughness == 0.5f);
    // texture coordinates: glTF's v runs down the image, lidr's up
    const lidr::Mesh& mesh = scene.meshes[2];
    CHECK(mesh.texCoords[mesh.indices[2]] == glm::vec2(0.0f, 0.0f));
    CHECK(mesh.texCoords[mesh.indices[0]] == glm::vec2(0.0f, 1.0f));
}

TEST_CASE("glTF: a .glb and a .gltf with a separate .bin give the same scene", "[gltf][cpu]") {
    TempDir dir;
    GltfFile file = oneTriangle();
    file.node({{"mesh", 0}, {"translation", {0, 0, 2}}}, true);
    const lidr::Scene fromGltf = lidr::loadScene(file.writeGltf(dir, "model.gltf"));
    const lidr::Scene fromGlb = lidr::loadScene(file.writeGlb(dir, "model.glb"));
    dir.write("model.bin", std::string(file.bin.begin(), file.bin.end()));
    file.doc["buffers"] = {{{"byteLength", file.bin.size()}, {"uri", "model.bin"}}};
    const lidr::Scene fromBin = lidr::loadScene(dir.write("separate.gltf", file.doc.dump()));
    for (const lidr::Scene* scene : {&fromGlb, &fromBin}) {
        REQUIRE(scene->meshes.size() == 1);
        CHECK(scene->meshes[0].positions == fromGltf.meshes[0].positions);
        CHECK(scene->meshes[0].indices == fromGltf.meshes[0].indices);
    }
    requireNear(fromGlb.meshes[0].positions[fromGlb.meshes[0].indices[2]], {0, 1, 2});
}

TEST_CASE("glTF: malformed files are errors naming the file and the cause", "[gltf][cpu][bad-input]") {
    TempDir dir;
    const auto load = [&](GltfFile file, const std::string& name) { return lidr::loadScene(file.writeGltf(dir, name)); };
    SECTION("index out of range") {
        GltfFile file;
        const int p = file.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        file.mesh({{"attributes", {{"POSITION", p}}}, {"indices", file.indices({0, 1, 7})}});
        file.node({{"mesh", 0}}, true);
        REQUIRE_THROWS_WITH(load(file, "index.gltf"),
                            Contains("index.gltf: ") && Contains("index 7 (element 2) out of range (3 vertices)"));
    }
    SECTION("accessor larger than its buffer view") {
        GltfFile file = oneTriangle();
        file.doc["accessors"][0]["count"] = 1000;
        file.node({{"mesh", 0}}, true);
        REQUIRE_THROWS_WITH(load(file, "count.gltf"),
                            Contains("count.gltf: /accessors/0/count: 1000 elements of 12 bytes (stride 12) from byte 0 do not fit "
                                     "bufferView 0 (36 bytes)"));
    }
    SECTION("accessor index out of range") {
        GltfFile file = oneTriangle();
        file.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 9;
        file.node({{"mesh", 0}}, true);
        REQUIRE_THROWS_WITH(load(file, "accessor.gltf"), Contains("accessor.gltf: /meshes/0/primitives/0/attributes/POSITION: index 9 is out "
                                                                  "of range (2 accessors)"));
    }
    SECTION("positions that are not float VEC3") {
        GltfFile file = oneTriangle();
        file.doc["accessors"][0]["type"] = "VEC2";
        file.node({{"mesh", 0}}, true);
        REQUIRE_THROWS_WITH(load(file, "type.gltf"), Contains("POSITION accessor 0: type"));
    }
    SECTION("missing buffer file") {
        GltfFile file = oneTriangle();
        file.node({{"mesh", 0}}, true);
        file.doc["buffers"] = {{{"byteLength", file.bin.size()}, {"uri", "missing.bin"}}};
        REQUIRE_THROWS_WITH(lidr::loadScene(dir.write("nobuffer.gltf", file.doc.dump())),
                            Contains("nobuffer.gltf: /buffers/0/uri: buffer file '") && Contains("missing.bin' not found"));
    }
    SECTION("lines are not triangles") {
        GltfFile file = oneTriangle();
        file.doc["meshes"][0]["primitives"][0]["mode"] = 1;
        file.node({{"mesh", 0}}, true);
        REQUIRE_THROWS_WITH(load(file, "lines.gltf"),
                            Contains("lines.gltf: ") && Contains("primitive mode 1 (LINES) is not triangles"));
    }
    SECTION("truncated .glb") {
        GltfFile file = oneTriangle();
        file.node({{"mesh", 0}}, true);
        const std::string whole = file.writeGlb(dir, "whole.glb");
        std::ifstream in(whole, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        // The header's length no longer matches the file (the GLB rule the cut breaks first).
        for (size_t keep : {size_t(4), size_t(20), bytes.size() - 10}) {
            INFO("kept " << keep << " of " << bytes.size() << " bytes");
            REQUIRE_THROWS_WITH(lidr::loadScene(dir.write("cut.glb", bytes.substr(0, keep))),
                                Contains("cut.glb: GLB header: ") &&
                                    (Contains("a GLB header has 12") || Contains("differs from the file size " + std::to_string(keep))));
        }
    }
    SECTION("not JSON") {
        REQUIRE_THROWS_WITH(lidr::loadScene(dir.write("text.gltf", "{\"asset\": ")), Contains("text.gltf: /: malformed JSON: "));
    }
    SECTION("a node that is its own child") {
        GltfFile file = oneTriangle();
        file.node({{"mesh", 0}, {"children", {0}}}, true);
        REQUIRE_THROWS_WITH(load(file, "cycle.gltf"), Contains("cycle.gltf: /nodes/0/children/0: node 0 is its own child"));
    }
    SECTION("missing file, other model formats") {
        REQUIRE_THROWS_WITH(lidr::loadScene(dir.file("none.gltf")), Contains("none.gltf: glTF file not found"));
        REQUIRE_THROWS_WITH(lidr::loadScene(dir.write("x.ply", "ply")), Contains("x.ply: format not supported (PLY)"));
    }
}

TEST_CASE("glTF: scene files reference glTF models like OBJ ones", "[gltf][cpu]") {
    TempDir dir;
    GltfFile file = oneTriangle();
    file.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"range", 2.0}}};
    file.node({{"mesh", 0}}, true);
    file.node({{"translation", {0, 1, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}, true);
    file.writeGltf(dir, "part.gltf");
    const lidr::Scene scene = lidr::loadScene(dir.write("scene.json", R"({
        "materials": [{"name": "red", "diffuse": [1, 0, 0]}],
        "models": [{"file": "part.gltf", "translate": [5, 0, 0], "scale": 3, "material": "red"}],
        "lights": [{"position": [0, 9, 0], "radius": 1}]})"));
    REQUIRE(scene.meshes.size() == 1);
    requireNear(scene.meshes[0].positions[scene.meshes[0].indices[1]], {8, 0, 0});
    CHECK(scene.materials[size_t(scene.meshes[0].material)].name == "red");
    REQUIRE(scene.lights.size() == 2);  // the model's light first (models come before lights)
    requireNear(scene.lights[0].position, {5, 3, 0});
    CHECK(scene.lights[0].radius == Approx(6.0f));
    requireNear(scene.camera.position, lidr::Camera().position);  // no cameras: the scene file's (default) camera
    CHECK(scene.views.empty());
}

TEST_CASE("glTF: a scene file is seen through its models' first camera unless it gives \"camera\"", "[gltf][cpu]") {
    TempDir dir;
    GltfFile file = oneTriangle();
    file.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.2}}}},
                           {{"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.3}, {"zfar", 30}}}}};
    file.node({{"mesh", 0}}, true);
    file.node({{"camera", 1}, {"translation", {0, 0, 4}}}, true);
    file.node({{"camera", 0}, {"translation", {0, 1, 4}}}, true);
    file.writeGltf(dir, "seen.gltf");
    const std::string models = R"("models": [{"file": "seen.gltf", "translate": [10, 0, 0]}, {"file": "seen.gltf"}])";
    lidr::Scene scene = lidr::loadScene(dir.write("scene.json", "{" + models + "}"));
    // the first model's camera 1 (first in node order), moved with the model
    REQUIRE(scene.views.size() == 4);
    CHECK(scene.view == 1);
    CHECK(scene.views[3].name == "seen.gltf camera 1");
    requireNear(scene.camera.position, {10, 0, 4});
    CHECK(scene.camera.fovYDegrees == Approx(glm::degrees(0.9f)));
    CHECK(scene.camera.farPlane == Approx(30.0f));
    lidr::chooseView(scene, 2);  // the second model's camera 0: no zfar, a far plane past the whole scene's bounds
    requireNear(scene.camera.position, {0, 1, 4});
    CHECK(scene.camera.farPlane == Approx(1.5f * glm::length(glm::vec3(11, -1, -4))));
    REQUIRE_THROWS_WITH(lidr::chooseView(scene, 4), Contains("the scene has 4 cameras (0 .. 3"));
    SECTION("\"camera\" given: the file's camera is the view") {
        const lidr::Scene own = lidr::loadScene(dir.write("own.json", R"({"camera": {"position": [1, 2, 3]}, )" + models + "}"));
        requireNear(own.camera.position, {1, 2, 3});
        CHECK(own.view == -1);
        CHECK(own.views.size() == 4);
    }
}

TEST_CASE("glTF: a glTF scene renders like the same scene as a lidr JSON file with an OBJ model", "[gltf][every-gl]") {
    TempDir dir;
    // A floor quad and a box-like tent, with a red material, two point lights and a camera.
    GltfFile file;
    const int p = file.positions({{-4, 0, -4}, {4, 0, -4}, {4, 0, 4}, {-4, 0, 4}, {-1, 0, 0}, {1, 0, 0}, {0, 1.5f, 0.5f}});
    const int i = file.indices({0, 2, 1, 0, 3, 2, 4, 5, 6});
    file.doc["materials"] = {{{"name", "red"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.2, 0.2, 1}}, {"metallicFactor", 0.0}, {"roughnessFactor", std::pow(2.0 / 3.0, 0.25)}}}}};
    // (the roughness the OBJ's Blinn-Phong "Ns 1" maps to: alpha^2 = 2 / (1 + 2), doc/colour.md)
    file.mesh({{"attributes", {{"POSITION", p}}}, {"indices", i}, {"material", 0}});
    file.node({{"mesh", 0}}, true);
    // pi candela: a scene file's inverse-square light of colour 1 (doc/scene-format.md's conversion)
    const double candela = 3.14159265358979;
    file.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "point"}, {"color", {1, 0.9, 0.8}}, {"intensity", candela}, {"range", 5.0}},
        {{"type", "point"}, {"color", {0.2, 0.4, 1}}, {"intensity", candela}, {"range", 3.0}}};
    file.node({{"translation", {0, 2, 1}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}, true);
    file.node({{"translation", {2, 0.5, -1}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}}, true);
    file.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", glm::radians(60.0)}, {"znear", 0.1}, {"zfar", 50}}}}};
    // at (0, 4, 8) looking at the origin: rotate about +x by -atan(4/8)
    const float angle = -std::atan(0.5f);
    file.node({{"camera", 0}, {"translation", {0, 4, 8}}, {"rotation", {std::sin(angle / 2), 0.0, 0.0, std::cos(angle / 2)}}}, true);
    lidr::Scene fromGltf = lidr::loadScene(file.writeGltf(dir, "tent.gltf"));

    dir.write("tent.obj", "mtllib tent.mtl\nv -4 0 -4\nv 4 0 -4\nv 4 0 4\nv -4 0 4\nv -1 0 0\nv 1 0 0\nv 0 1.5 0.5\n"
                          "usemtl red\nf 1 3 2\nf 1 4 3\nf 5 6 7\n");
    // MTL colours are display values (decoded on load), glTF factors linear: the same linear red written both ways
    dir.write("tent.mtl", "newmtl red\nKd " + std::to_string(lidr::linearToSrgb(0.8)) + " " + std::to_string(lidr::linearToSrgb(0.2)) +
                              " " + std::to_string(lidr::linearToSrgb(0.2)) + "\nKs 0 0 0\nNs 1\n");
    lidr::Scene fromJson = lidr::loadScene(dir.write("tent.json", R"({
        "camera": {"position": [0, 4, 8], "target": [0, 0, 0], "fov": 60, "near": 0.1, "far": 50},
        "models": [{"file": "tent.obj"}],
        "lights": [{"position": [0, 2, 1], "radius": 5, "color": [1, 0.9, 0.8], "falloff": "inverse_square"},
                   {"position": [2, 0.5, -1], "radius": 3, "color": [0.2, 0.4, 1], "falloff": "inverse_square"}]})"));
    for (lidr::Scene* scene : {&fromGltf, &fromJson}) {
        scene->width = lidr::test::testWidth();
        scene->height = lidr::test::testHeight();
    }
    // the OBJ's face normals and the glTF's flat normals are the same; so are the materials' terms
    const lidr::MetallicRoughness gltfRed = lidr::metallicRoughnessOf(fromGltf.materials[size_t(fromGltf.meshes[0].material)]);
    const lidr::MetallicRoughness objRed = lidr::metallicRoughnessOf(fromJson.materials[size_t(fromJson.meshes[0].material)]);
    REQUIRE(gltfRed.metallic == objRed.metallic);
    REQUIRE(gltfRed.roughness == Approx(objRed.roughness).epsilon(1e-6));
    REQUIRE(glm::all(glm::lessThan(glm::abs(gltfRed.baseColor - objRed.baseColor), glm::vec3(1e-5f))));
    const auto render = [&](const lidr::Scene& scene) {
        lidr::RenderModeOptions options;
        auto renderer = lidr::createRenderer(options, lidr::test::testGl(), scene, scene.width, scene.height);
        renderer->render(scene.camera, scene.lightsAt(scene.time), {scene.ambient});
        return renderer->targets().readColor();
    };
    const lidr::ImageRGBA8 a = render(fromGltf), b = render(fromJson);
    const lidr::ImageError error = lidr::compareImages(a, b);
    INFO("max " << error.maxAbsError << ", differing pixels " << error.differingPixels);
    // The camera comes through a quaternion, so a few edge pixels may differ by rasterisation.
    CHECK(error.maxAbsError <= 2);
    CHECK(error.differingPixels <= long(a.width) * long(a.height) / 200);
    // and the frame is not empty: the lights reach the red floor
    size_t lit = 0;
    for (size_t k = 0; k < a.pixels.size(); k += 4) lit += a.pixels[k] > 40;
    CHECK(lit > size_t(a.width) * size_t(a.height) / 10);
}

// The header reader the glTF validator and the texture checks use to refuse huge images before decoding
// (lidr/scene/io/file_checks.h): kind and size from the first bytes of a PNG or JPEG, nothing for anything else.
TEST_CASE("image headers: PNG and JPEG kind and size read without decoding", "[gltf][cpu]") {
    const auto be32 = [](uint32_t v) {
        return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
    };
    const auto pngHeader = [&](uint32_t width, uint32_t height) {
        return std::string("\x89PNG\r\n\x1a\n", 8) + be32(13) + "IHDR" + be32(width) + be32(height) + std::string("\x08\x06\0\0\0", 5);
    };
    const auto jpegHeader = [](int width, int height, const std::string& before) {
        const std::string app0 = std::string("\xFF\xE0\x00\x10JFIF\0\x01\x01\0\0\x01\0\x01\0\0", 18);
        return std::string("\xFF\xD8", 2) + app0 + before + std::string("\xFF\xC0\x00\x11\x08", 5) + char(height >> 8) +
               char(height & 255) + char(width >> 8) + char(width & 255) + std::string("\x01\x01\x11\x00", 4);
    };
    struct Case {
        const char* what;
        std::string bytes;
        const char* kind;
        bool sized;
        uint64_t width, height;
    };
    const Case cases[] = {
        {"PNG 2x3", pngHeader(2, 3), "image/png", true, 2, 3},
        {"PNG 100000x100000 (stb_image refuses it without a size)", pngHeader(100000, 100000), "image/png", true, 100000, 100000},
        {"PNG 4294967295 wide", pngHeader(0xFFFFFFFFu, 1), "image/png", true, 0xFFFFFFFFu, 1},
        {"PNG cut before IHDR", pngHeader(2, 3).substr(0, 16), "image/png", false, 0, 0},
        {"JPEG 20000x100", jpegHeader(20000, 100, ""), "image/jpeg", true, 20000, 100},
        {"JPEG after a DHT segment and fill bytes", jpegHeader(640, 480, std::string("\xFF\xC4\x00\x04\x00\x00\xFF\xFF", 8)),
         "image/jpeg", true, 640, 480},
        {"JPEG cut inside its frame header", jpegHeader(640, 480, "").substr(0, 25), "image/jpeg", false, 0, 0},
        {"text", "hello, world", "", false, 0, 0},
        {"empty", "", "", false, 0, 0},
    };
    for (const Case& c : cases) {
        DYNAMIC_SECTION(c.what) {
            const lidr::ImageHeader header = lidr::pngOrJpegHeader(c.bytes);
            CHECK(header.kind == c.kind);
            CHECK(header.sized == c.sized);
            CHECK(header.width == c.width);
            CHECK(header.height == c.height);
        }
    }
}

TEST_CASE("glTF: every material texture is read with its set, strength, scale and transform; samplers warn", "[gltf][cpu]") {
    // The flat-white helmet: emissiveFactor [1, 1, 1] with an emissive texture that is mostly black. Drawn as the
    // factor alone, every pixel of the material saturates; lidr reads the texture per pixel (the factor stays).
    TempDir dir;
    GltfFile file;
    const int p = file.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const std::vector<float> uv = {0, 0, 1, 0, 0, 1};
    const int t = file.accessor(uv.data(), uv.size() * 4, 5126, "VEC2", 3);
    for (int m = 0; m < 2; ++m) file.mesh({{"attributes", {{"POSITION", p}, {"TEXCOORD_0", t}}}, {"material", m}});
    // 2x2: three black texels and one sRGB-white one (mean 0.25 linear); and an ORM-style texture (G 128, B 255)
    lidr::ImageRGBA8 emission(2, 2), orm(2, 2);
    for (size_t i = 0; i < 16; i += 4) {
        for (int c = 0; c < 3; ++c) emission.pixels[i + size_t(c)] = i == 0 ? 255 : 0;
        emission.pixels[i + 3] = 255;
        orm.pixels[i] = 255, orm.pixels[i + 1] = 128, orm.pixels[i + 2] = 255, orm.pixels[i + 3] = 255;
    }
    std::vector<std::string> uris;
    for (const auto& [name, image] : {std::pair<const char*, const lidr::ImageRGBA8*>{"e.png", &emission}, {"orm.png", &orm}}) {
        lidr::writePng(dir.file(name), *image);
        std::ifstream in(dir.file(name), std::ios::binary);
        const std::vector<unsigned char> png((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        uris.push_back("data:image/png;base64," + base64(png));
    }
    file.doc["images"] = {{{"uri", uris[0]}}, {{"uri", uris[1]}}};
    file.doc["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33071}}};  // CLAMP_TO_EDGE: lidr repeats
    file.doc["textures"] = {{{"source", 0}}, {{"source", 1}, {"sampler", 0}}};
    file.doc["materials"] = {
        {{"name", "helmet"}, {"emissiveFactor", {1, 1, 1}}, {"emissiveTexture", {{"index", 0}}},
         {"normalTexture", {{"index", 1}, {"scale", 0.5}}}, {"occlusionTexture", {{"index", 1}, {"strength", 0.75}, {"texCoord", 1}}},
         {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}}}, {"metallicRoughnessTexture", {{"index", 1}}},
                                   {"metallicFactor", 1.0}, {"roughnessFactor", 0.8}}}},
        {{"name", "lamp"}, {"emissiveFactor", {1, 0.5, 0.25}},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}}};
    for (int m = 0; m < 2; ++m) file.node({{"mesh", m}}, true);
    file.doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    const lidr::Scene scene = lidr::loadScene(file.writeGltf(dir, "helmet.gltf"));
    const lidr::Material& helmet = scene.materials[size_t(scene.meshes[0].material)];
    requireNear(helmet.emissive, glm::vec3(1.0f));  // the factor; the texture multiplies it per pixel
    REQUIRE(helmet.emissiveTexture.present());
    CHECK(helmet.emissiveTexture.image->width == 2);
    CHECK(std::memcmp(helmet.emissiveTexture.image->pixels.data(), emission.pixels.data(), 16) == 0);
    CHECK(helmet.roughness == 0.8f);
    CHECK(helmet.metallic == 1.0f);
    REQUIRE(helmet.metallicRoughnessTexture.present());
    CHECK(helmet.metallicRoughnessTexture.image == helmet.normalTexture.image);  // one image, decoded once
    CHECK(helmet.normalTexture.scale == 0.5f);
    CHECK(helmet.occlusionTexture.scale == 0.75f);
    CHECK(helmet.occlusionTexture.mapping.texCoord == 1);
    CHECK(helmet.normalTexture.mapping.texCoord == 0);
    CHECK(helmet.diffuseImage == helmet.normalTexture.image);
    const lidr::Material& lamp = scene.materials[size_t(scene.meshes[1].material)];
    requireNear(lamp.emissive, glm::vec3(4.0f, 2.0f, 1.0f));  // emissiveFactor x emissiveStrength
    std::string all;
    for (const std::string& w : scene.warnings) all += w + "\n";
    INFO(all);
    CHECK_THAT(all, Contains("sampler wrap 33071") && Contains("helmet.gltf") && Contains("'helmet'"));
    // the occlusion texture reads TEXCOORD_1, which the primitive lacks: drawn with TEXCOORD_0, said so
    CHECK_THAT(all, Contains("occlusion texture reads TEXCOORD_1"));
    CHECK_THAT(all, !Contains("drawn as its mean") && !Contains("is not drawn"));
}

TEST_CASE("glTF: KHR_materials_ior and KHR_materials_specular set the dielectric's F0 and F90; their textures warn",
          "[gltf][cpu]") {
    TempDir dir;
    GltfFile file = oneTriangle();
    for (int m = 1; m < 3; ++m) file.mesh(file.doc["meshes"][0]["primitives"][0]);
    file.doc["images"] = {{{"uri", "white.png"}}};
    lidr::ImageRGBA8 white(1, 1);
    white.pixels = {255, 255, 255, 255};
    lidr::writePng(dir.file("white.png"), white);
    file.doc["textures"] = {{{"source", 0}}};
    file.doc["materials"] = {
        {{"name", "plain"}},
        {{"name", "diamond"}, {"extensions", {{"KHR_materials_ior", {{"ior", 2.4}}}}}},
        {{"name", "tinted"},
         {"extensions", {{"KHR_materials_ior", {{"ior", 0}}},
                         {"KHR_materials_specular", {{"specularFactor", 0.5}, {"specularColorFactor", {0.9, 0.6, 0.2}},
                                                     {"specularTexture", {{"index", 0}}},
                                                     {"specularColorTexture", {{"index", 0}}}}}}}}};
    for (int m = 0; m < 3; ++m) {
        file.doc["meshes"][size_t(m)]["primitives"][0]["material"] = m;
        file.node({{"mesh", m}}, true);
    }
    file.doc["extensionsUsed"] = {"KHR_materials_ior", "KHR_materials_specular"};
    file.doc["extensionsRequired"] = {"KHR_materials_ior", "KHR_materials_specular"};  // lidr reads them
    const lidr::Scene scene = lidr::loadScene(file.writeGltf(dir, "dielectric.gltf"));
    const auto material = [&](int mesh) { return scene.materials[size_t(scene.meshes[size_t(mesh)].material)]; };
    CHECK(material(0).dielectric.isDefault());
    CHECK(material(1).dielectric.ior == 2.4f);
    CHECK(material(1).dielectric.f0().g == Approx(std::pow(1.4 / 3.4, 2.0)));
    CHECK(material(1).dielectric.f90() == 1.0f);
    const lidr::DielectricSpecular& tinted = material(2).dielectric;
    CHECK(tinted.ior == 0.0f);
    CHECK(tinted.weight == 0.5f);
    requireNear(tinted.color, {0.9f, 0.6f, 0.2f});
    requireNear(tinted.f0(), glm::vec3(0.45f, 0.3f, 0.1f));  // ior 0: F0 1 x colour x weight
    CHECK(tinted.f90() == 0.5f);
    std::string all;
    for (const std::string& w : scene.warnings) all += w + "\n";
    INFO(all);
    REQUIRE(scene.warnings.size() == 2);
    CHECK_THAT(all, Contains("material 2 'tinted': KHR_materials_specular specularTexture is not drawn") &&
                        Contains("specularColorTexture is not drawn") && Contains("its factors are"));
}

TEST_CASE("glTF: KHR_texture_transform in lidr's texture space; required extensions lidr reads load", "[gltf][cpu]") {
    TempDir dir;
    GltfFile file = oneTriangle();
    lidr::ImageRGBA8 image(1, 1);
    image.pixels = {255, 255, 255, 255};
    lidr::writePng(dir.file("white.png"), image);
    file.doc["images"] = {{{"uri", "white.png"}}};
    file.doc["textures"] = {{{"source", 0}}};
    // the extension's own example: offset (0, 1), rotation pi/2, scale 0.5 reads the lower left quadrant
    const Json transform = {{"offset", {0, 1}}, {"rotation", 1.57079632679}, {"scale", {0.5, 0.5}}, {"texCoord", 1}};
    file.doc["materials"] = {{{"emissiveTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}}};
    file.doc["meshes"][0]["primitives"][0]["material"] = 0;
    file.node({{"mesh", 0}}, true);
    const std::vector<std::vector<std::string>> requiredLists = {
        {"KHR_texture_transform"}, {"KHR_materials_emissive_strength", "KHR_lights_punctual", "KHR_texture_transform"}};
    for (const std::vector<std::string>& required : requiredLists) {
        file.doc["extensionsUsed"] = required;
        file.doc["extensionsRequired"] = required;
        const lidr::Scene scene = lidr::loadScene(file.writeGltf(dir, "transform.gltf"));
        const lidr::Material& m = scene.materials[size_t(scene.meshes[0].material)];
        CHECK(m.emissiveTexture.mapping.texCoord == 1);  // the extension's texCoord overrides the textureInfo's
        // glTF (u, v) -> (0.5 v, 1 - 0.5 u) on these: lidr's (u, 1 - v) in and out
        const auto lidrUv = [&](glm::vec2 gltf) {
            const glm::vec3 out = m.emissiveTexture.mapping.transform * glm::vec3(gltf.x, 1.0f - gltf.y, 1.0f);
            return glm::vec2(out.x, 1.0f - out.y);  // back to glTF's, to compare with the extension's formula
        };
        for (const glm::vec2 uv : {glm::vec2(0.0f), glm::vec2(1.0f, 0.0f), glm::vec2(0.0f, 1.0f), glm::vec2(1.0f)}) {
            const glm::vec2 expected(0.5f * uv.y, 1.0f - 0.5f * uv.x);
            const glm::vec2 got = lidrUv(uv);
            INFO("(" << uv.x << ", " << uv.y << ") -> (" << got.x << ", " << got.y << ")");
            CHECK(glm::length(got - expected) < 1e-5f);
        }
    }
    // Every texture slot lidr reads takes its own transform and set (a different transform each here).
    const std::vector<std::pair<std::string, std::string>> slots = {
        {"/pbrMetallicRoughness/baseColorTexture", "base colour"},
        {"/pbrMetallicRoughness/metallicRoughnessTexture", "metallic-roughness"},
        {"/normalTexture", "normal"}, {"/occlusionTexture", "occlusion"}, {"/emissiveTexture", "emissive"}};
    file.doc["materials"] = Json::array({Json::object()});  // {Json::object()} is the object itself with clang
    for (size_t k = 0; k < slots.size(); ++k) {
        const Json t = {{"offset", {0.25 * double(k), -0.5}}, {"rotation", 0.3 * double(k + 1)},
                        {"scale", {1.0 + double(k), 2.0}}, {"texCoord", int(k % 2)}};
        file.doc["materials"][0][Json::json_pointer(slots[k].first)] = {
            {"index", 0}, {"texCoord", 1 - int(k % 2)}, {"extensions", {{"KHR_texture_transform", t}}}};
    }
    file.doc["extensionsUsed"] = {"KHR_texture_transform"};
    file.doc.erase("extensionsRequired");
    {
        const lidr::Scene scene = lidr::loadScene(file.writeGltf(dir, "slots.gltf"));
        const lidr::Material& m = scene.materials[size_t(scene.meshes[0].material)];
        const lidr::TextureMapping* mappings[] = {&m.diffuseMapping, &m.metallicRoughnessTexture.mapping,
                                                  &m.normalTexture.mapping, &m.occlusionTexture.mapping,
                                                  &m.emissiveTexture.mapping};
        for (size_t k = 0; k < slots.size(); ++k) {
            INFO(slots[k].second);
            CHECK(mappings[k]->texCoord == int(k % 2));  // the override, not the texture info's own set
            const double offsetU = 0.25 * double(k), offsetV = -0.5, angle = 0.3 * double(k + 1);
            const double scaleU = 1.0 + double(k), scaleV = 2.0;
            for (const glm::dvec2 uv : {glm::dvec2(0.0), glm::dvec2(1.0, 0.0), glm::dvec2(0.3, 0.7)}) {
                // The extension's formula in glTF's space: translation x rotation x scale, counter-clockwise.
                const glm::dvec2 scaled(uv.x * scaleU, uv.y * scaleV);
                const glm::dvec2 expected(std::cos(angle) * scaled.x + std::sin(angle) * scaled.y + offsetU,
                                          -std::sin(angle) * scaled.x + std::cos(angle) * scaled.y + offsetV);
                const glm::vec3 out = mappings[k]->transform * glm::vec3(float(uv.x), 1.0f - float(uv.y), 1.0f);
                const glm::dvec2 got(out.x, 1.0 - out.y);
                INFO("(" << uv.x << ", " << uv.y << ") -> (" << got.x << ", " << got.y << "), expected (" << expected.x
                         << ", " << expected.y << ")");
                CHECK(glm::length(got - expected) < 1e-5);
            }
        }
    }
    file.doc["extensionsUsed"] = {"KHR_texture_transform", "EXT_unknown_thing"};
    file.doc["extensionsRequired"] = {"KHR_texture_transform", "EXT_unknown_thing"};
    REQUIRE_THROWS_WITH(lidr::loadScene(file.writeGltf(dir, "unknown.gltf")),
                        Contains("unknown.gltf") && Contains("required extension EXT_unknown_thing is not implemented"));
}
