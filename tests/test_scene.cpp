// Scene data, the default room, procedural primitives, light paths and the scene file / OBJ loaders.
#include <catch2/catch.hpp>

#include "lidr/base/colour.h"

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "temp_dir.h"
#include "lidr/scene/default_scene.h"
#include "lidr/base/error.h"
#include "lidr/scene/primitives.h"
#include "lidr/scene/scene.h"
#include "lidr/scene/io/scene_loader.h"

namespace fs = std::filesystem;
using Catch::Contains;

using lidr::test::TempDir;

namespace {

std::string mediaPath(const std::string& relative) { return std::string(LIDR_SOURCE_DIR) + "/media/" + relative; }

// A fresh folder under the system temp folder, removed with everything in it at the end of the test.

// A valid scene file with one box, plus `members` (a JSON fragment starting with a comma, or empty).
std::string sceneWith(const std::string& members) {
    return R"({"primitives": [{"shape": "box", "min": [-1, 0, -1], "max": [1, 1, 1]}])" + members + "}";
}

template <class T>
void appendBytes(std::vector<unsigned char>& bytes, const T& value) {
    const auto* begin = reinterpret_cast<const unsigned char*>(&value);
    bytes.insert(bytes.end(), begin, begin + sizeof(T));
}

// Every number that describes the scene, field by field (structs may have padding).
std::vector<unsigned char> sceneBytes(const lidr::Scene& scene) {
    std::vector<unsigned char> bytes;
    for (const lidr::Mesh& mesh : scene.meshes) {
        for (const glm::vec3& p : mesh.positions) appendBytes(bytes, p);
        for (const glm::vec3& n : mesh.normals) appendBytes(bytes, n);
        for (const glm::vec2& t : mesh.texCoords) appendBytes(bytes, t);
        for (uint32_t i : mesh.indices) appendBytes(bytes, i);
        appendBytes(bytes, mesh.material);
    }
    for (const lidr::PointLight& light : scene.lights) {
        appendBytes(bytes, light.position);
        appendBytes(bytes, light.radius);
        appendBytes(bytes, light.color);
        appendBytes(bytes, light.priority);
    }
    for (const lidr::LightPath& path : scene.lightPaths) {
        appendBytes(bytes, path.kind);
        appendBytes(bytes, path.center);
        appendBytes(bytes, path.orbitRadius);
        appendBytes(bytes, path.angularSpeed);
        appendBytes(bytes, path.phase);
        appendBytes(bytes, path.bobAmplitude);
        appendBytes(bytes, path.velocity);
        appendBytes(bytes, path.boxMin);
        appendBytes(bytes, path.boxMax);
    }
    appendBytes(bytes, scene.time);
    return bytes;
}

// Unit normals, indices in range, and every triangle wound counter-clockwise around its vertex normals.
void checkMeshes(const lidr::Scene& scene) {
    for (const lidr::Mesh& mesh : scene.meshes) {
        INFO("mesh " << mesh.name);
        REQUIRE(mesh.normals.size() == mesh.positions.size());
        REQUIRE((mesh.texCoords.empty() || mesh.texCoords.size() == mesh.positions.size()));
        REQUIRE(mesh.indices.size() % 3 == 0);
        for (const glm::vec3& n : mesh.normals) REQUIRE(glm::length(n) == Approx(1.0f).margin(1e-4));
        for (uint32_t index : mesh.indices) REQUIRE(index < mesh.positions.size());
        for (size_t t = 0; t < mesh.indices.size(); t += 3) {
            const uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
            const glm::vec3 faceNormal =
                glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
            const glm::vec3 vertexNormal = mesh.normals[a] + mesh.normals[b] + mesh.normals[c];
            REQUIRE(glm::length(faceNormal) > 0.0f);
            REQUIRE(glm::dot(faceNormal, vertexNormal) > 0.0f);
        }
    }
}

// Normals point away from `center` (for shapes that are star-shaped around it).
void checkOutward(const lidr::Mesh& mesh, const glm::vec3& center) {
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        if (glm::length(mesh.positions[i] - center) > 1e-4f)
            REQUIRE(glm::dot(mesh.normals[i], mesh.positions[i] - center) > 0.0f);
}

lidr::PointLight lightAt(const glm::vec3& position, float radius = 1.0f) {
    lidr::PointLight light;
    light.position = position;
    light.radius = radius;
    return light;
}

}  // namespace

TEST_CASE("default scene: about 40k triangles of valid geometry", "[scene][cpu]") {
    const lidr::Scene scene = lidr::makeDefaultScene();
    CHECK(scene.triangleCount() >= 38000);
    CHECK(scene.triangleCount() <= 45000);
    CHECK(scene.name == "default-room");
    CHECK(scene.materials.size() >= 4);
    REQUIRE_NOTHROW(scene.validate());
    checkMeshes(scene);
    CHECK(scene.boundsMin().y == Approx(0.0f));
    CHECK(scene.boundsMax().x == Approx(20.5f));
    CHECK(scene.camera.position == glm::vec3(0.0f, 4.5f, 17.0f));
    CHECK(scene.width == 1024);
    CHECK(scene.height == 768);
}

TEST_CASE("default scene: 3 large slow movers and 252 small particle lights", "[scene][cpu]") {
    const lidr::Scene scene = lidr::makeDefaultScene();
    REQUIRE(scene.lights.size() == 255);
    REQUIRE(scene.lightPaths.size() == 255);
    for (size_t i = 0; i < 3; ++i) {
        INFO("large light " << i);
        CHECK(scene.lights[i].radius >= 7.0f);
        CHECK(scene.lights[i].radius <= 9.0f);
        CHECK(scene.lights[i].priority == 10.0f);
        CHECK(scene.lightPaths[i].kind == lidr::LightPath::Kind::Orbit);
        CHECK(std::abs(scene.lightPaths[i].angularSpeed) < 0.5f);
        CHECK(scene.lights[i].color.r > scene.lights[i].color.b);  // warm
        CHECK(glm::all(glm::lessThanEqual(scene.lights[i].color, glm::vec3(1.0f))));
    }
    for (size_t i = 3; i < 255; ++i) {
        INFO("particle light " << i);
        const lidr::PointLight& light = scene.lights[i];
        const lidr::LightPath& path = scene.lightPaths[i];
        CHECK(light.radius >= 0.8f);
        CHECK(light.radius <= 2.2f);
        CHECK(light.priority == 0.0f);
        CHECK(path.kind == lidr::LightPath::Kind::Bounce);
        CHECK(glm::length(path.velocity) >= 1.0f);
        CHECK(glm::length(path.velocity) <= 2.0f);
        CHECK(path.boxMin.y == Approx(0.2f));
        CHECK(path.boxMax.y == Approx(3.5f));
        CHECK(light.position.y >= 0.2f);
        CHECK(light.position.y <= 3.5f);
        const float brightest = std::max({light.color.r, light.color.g, light.color.b});
        const float dimmest = std::min({light.color.r, light.color.g, light.color.b});
        CHECK(dimmest <= 0.25f * brightest);  // saturated
    }
    for (const lidr::PointLight& light : scene.lightsAt(1234.5f)) {
        CHECK(std::abs(light.position.x) <= 20.0f);
        CHECK(std::abs(light.position.z) <= 20.0f);
        CHECK(light.position.y >= 0.0f);
        CHECK(light.position.y <= 10.0f);
    }
}

TEST_CASE("default scene: deterministic for a seed and time", "[scene][cpu]") {
    lidr::DefaultSceneOptions options;
    options.seed = 42;
    options.time = 3.5f;
    const lidr::Scene first = lidr::makeDefaultScene(options);
    const lidr::Scene second = lidr::makeDefaultScene(options);
    CHECK(sceneBytes(first) == sceneBytes(second));
    CHECK(first.time == 3.5f);

    options.seed = 43;
    const lidr::Scene otherSeed = lidr::makeDefaultScene(options);
    CHECK(sceneBytes(first) != sceneBytes(otherSeed));
    CHECK(otherSeed.triangleCount() == first.triangleCount());  // the seed moves lights, not geometry

    // Lights hold rest positions: the time only says when the scene is shown.
    options.seed = 42;
    options.time = 0.0f;
    const lidr::Scene atZero = lidr::makeDefaultScene(options);
    CHECK(sceneBytes(atZero) != sceneBytes(first));
    REQUIRE(atZero.lights.size() == first.lights.size());
    for (size_t i = 0; i < first.lights.size(); ++i) CHECK(atZero.lights[i].position == first.lights[i].position);
    const std::vector<lidr::PointLight> now = first.lightsAt(first.time);
    CHECK(now[0].position != first.lights[0].position);
    CHECK(now[100].position != first.lights[100].position);
}

TEST_CASE("default scene: light count option", "[scene][cpu]") {
    lidr::DefaultSceneOptions options;
    options.lightCount = 2;
    CHECK(lidr::makeDefaultScene(options).lights.size() == 2);
    options.lightCount = 1000;
    const lidr::Scene many = lidr::makeDefaultScene(options);
    CHECK(many.lights.size() == 1000);
    CHECK(many.lightPaths.size() == 1000);
    options.lightCount = 70000;
    REQUIRE_THROWS_WITH(lidr::makeDefaultScene(options), Contains("lightCount") && Contains("70000"));
}

TEST_CASE("primitives: counts, outward normals, counter-clockwise winding", "[scene][cpu]") {
    lidr::Scene scene;
    scene.materials.resize(1);
    lidr::addBox(scene, {-1, 0, -2}, {1, 3, 2}, 0, 2);
    lidr::addPlane(scene, {0, 1, 0}, {4, 2}, 0, 3);
    lidr::addSphere(scene, {5, 1, 0}, 2.0f, 0, 16);
    lidr::addCylinder(scene, {-5, 0, 0}, 1.0f, 4.0f, 0, 16);
    lidr::addTorus(scene, {0, 0, 8}, 3.0f, 1.0f, 0, 24, 12);
    REQUIRE(scene.meshes.size() == 5);
    CHECK(scene.meshes[0].triangleCount() == 6 * 2 * 2 * 2);
    CHECK(scene.meshes[1].triangleCount() == 2 * 3 * 3);
    CHECK(scene.meshes[2].triangleCount() == 2 * 16 * (8 - 1));
    CHECK(scene.meshes[3].triangleCount() == 4 * 16);
    CHECK(scene.meshes[4].triangleCount() == 2 * 24 * 12);
    for (const lidr::Mesh& mesh : scene.meshes) CHECK(mesh.texCoords.size() == mesh.positions.size());
    REQUIRE_NOTHROW(scene.validate());
    checkMeshes(scene);
    checkOutward(scene.meshes[0], {0, 1.5f, 0});
    for (const glm::vec3& n : scene.meshes[1].normals) CHECK(n == glm::vec3(0, 1, 0));
    checkOutward(scene.meshes[2], {5, 1, 0});
    checkOutward(scene.meshes[3], {-5, 2, 0});
    const lidr::Mesh& torus = scene.meshes[4];
    for (size_t i = 0; i < torus.positions.size(); ++i) {
        const glm::vec3 local = torus.positions[i] - glm::vec3(0, 0, 8);
        const glm::vec3 tubeCenter = 3.0f * glm::normalize(glm::vec3(local.x, 0, local.z));
        CHECK(glm::dot(torus.normals[i], local - tubeCenter) > 0.0f);
    }
    const glm::vec3 low = scene.boundsMin(), high = scene.boundsMax();
    CHECK(low.x == Approx(-6.0f));
    CHECK(low.y == Approx(-1.0f));
    CHECK(low.z == Approx(-2.0f));
    CHECK(high.x == Approx(7.0f));
    CHECK(high.y == Approx(4.0f));
    CHECK(high.z == Approx(12.0f));

    REQUIRE_THROWS_WITH(lidr::addSphere(scene, {}, 1.0f, 0, 2), Contains("segments"));
    REQUIRE_THROWS_WITH(lidr::addBox(scene, {0, 0, 0}, {1, 0, 1}, 0), Contains("size y"));
}

TEST_CASE("light paths: orbit closed form", "[scene][cpu]") {
    lidr::LightPath orbit;
    orbit.kind = lidr::LightPath::Kind::Orbit;
    orbit.center = {1, 2, 3};
    orbit.orbitRadius = 4.0f;
    orbit.angularSpeed = 0.5f;
    orbit.phase = 0.25f;
    orbit.bobAmplitude = 0.3f;
    // a = 0.25 + 0.5 * 2 = 1.25: cos 1.25 = 0.3153224, sin 1.25 = 0.9489846, sin(0.7 * 1.25) = 0.7675435
    const glm::vec3 p = lidr::evaluatePath(orbit, glm::vec3(100.0f), 2.0f);
    CHECK(p.x == Approx(2.2612894f).margin(1e-5));
    CHECK(p.y == Approx(2.2302631f).margin(1e-5));
    CHECK(p.z == Approx(6.7959385f).margin(1e-5));
    CHECK(lidr::evaluatePath(lidr::LightPath{}, glm::vec3(7, 8, 9), 5.0f) == glm::vec3(7, 8, 9));
}

TEST_CASE("light paths: bounce is a triangle wave inside its box", "[scene][cpu]") {
    lidr::LightPath bounce;
    bounce.kind = lidr::LightPath::Kind::Bounce;
    bounce.velocity = {3, 0, -1};
    bounce.boxMin = {-2, 0, -2};
    bounce.boxMax = {2, 2, 2};
    const glm::vec3 rest(0, 1, 0);
    CHECK(lidr::evaluatePath(bounce, rest, 0.0f) == rest);
    // x: reaches the wall at 2 after 2/3 s and comes back: 3 - 2 = 1 short of it at t = 1.
    const glm::vec3 at1 = lidr::evaluatePath(bounce, rest, 1.0f);
    CHECK(at1.x == Approx(1.0f));
    CHECK(at1.y == Approx(1.0f));
    CHECK(at1.z == Approx(-1.0f));
    // t = 2: x has crossed the box back to -2; z just touches -2.
    const glm::vec3 at2 = lidr::evaluatePath(bounce, rest, 2.0f);
    CHECK(at2.x == Approx(-2.0f));
    CHECK(at2.z == Approx(-2.0f));
    // t = 3: both reflected off the low walls.
    const glm::vec3 at3 = lidr::evaluatePath(bounce, rest, 3.0f);
    CHECK(at3.x == Approx(1.0f));
    CHECK(at3.z == Approx(-1.0f));
    // The period is 2 * 4 / 3 s in x; negative times run the path backwards.
    CHECK(lidr::evaluatePath(bounce, rest, 1.0f + 8.0f / 3.0f * 100.0f).x == Approx(1.0f).margin(1e-3));
    CHECK(lidr::evaluatePath(bounce, rest, -1.0f).x == Approx(-1.0f));
    // A flat box axis pins the light.
    bounce.boxMin.y = bounce.boxMax.y = 0.5f;
    CHECK(lidr::evaluatePath(bounce, rest, 1.0f).y == 0.5f);

    lidr::Scene scene;
    scene.lights = {lightAt(rest), lightAt({5, 5, 5})};
    bounce.boxMin.y = 0.0f;
    scene.lightPaths = {bounce, lidr::LightPath{}};
    const std::vector<lidr::PointLight> lights = scene.lightsAt(1.0f);
    CHECK(lights[0].position.x == Approx(1.0f));
    CHECK(lights[1].position == glm::vec3(5, 5, 5));
    CHECK(scene.lightsAt(1.0f)[0].position == lights[0].position);
}

TEST_CASE("generateLights: ranges, paths and determinism", "[scene][cpu]") {
    lidr::Scene scene;
    scene.lights.push_back(lightAt({0, 0, 0}));
    lidr::LightGeneratorOptions options;
    options.seed = 9;
    options.count = 50;
    options.boundsMin = {-1, 0, -3};
    options.boundsMax = {1, 2, 3};
    options.radiusMin = 0.5f;
    options.radiusMax = 0.75f;
    options.intensity = 2.0f;

    lidr::generateLights(scene, options);
    REQUIRE(scene.lights.size() == 51);
    CHECK(scene.lightPaths.empty());
    for (size_t i = 1; i < scene.lights.size(); ++i) {
        const lidr::PointLight& light = scene.lights[i];
        CHECK(glm::all(glm::greaterThanEqual(light.position, options.boundsMin)));
        CHECK(glm::all(glm::lessThanEqual(light.position, options.boundsMax)));
        CHECK(light.radius >= 0.5f);
        CHECK(light.radius <= 0.75f);
        CHECK(std::max({light.color.r, light.color.g, light.color.b}) == Approx(2.0f));
    }

    lidr::Scene moving;
    moving.lights.push_back(lightAt({0, 0, 0}));
    options.speed = 1.5f;
    lidr::generateLights(moving, options);
    REQUIRE(moving.lightPaths.size() == 51);
    CHECK(moving.lightPaths[0].kind == lidr::LightPath::Kind::Static);
    for (size_t i = 1; i < moving.lights.size(); ++i) {
        CHECK(moving.lightPaths[i].kind == lidr::LightPath::Kind::Bounce);
        CHECK(glm::length(moving.lightPaths[i].velocity) == Approx(1.5f));
        CHECK(moving.lights[i].position == scene.lights[i].position);  // speed does not change the draws
    }
    options.speed = 0.0f;
    options.count = 5;
    lidr::generateLights(moving, options);
    REQUIRE(moving.lightPaths.size() == 56);
    CHECK(moving.lightPaths.back().kind == lidr::LightPath::Kind::Static);

    lidr::Scene again;
    again.lights.push_back(lightAt({0, 0, 0}));
    options.count = 50;
    lidr::generateLights(again, options);
    CHECK(sceneBytes(again) == sceneBytes(scene));

    options.count = 65535;
    REQUIRE_THROWS_WITH(lidr::generateLights(again, options), Contains("65535"));
    options.count = 1;
    options.radiusMin = 0.0f;
    REQUIRE_THROWS_WITH(lidr::generateLights(again, options), Contains("radii"));
}

TEST_CASE("Scene::validate names the offending item", "[scene][cpu]") {
    lidr::Scene scene;
    scene.materials.resize(1);
    lidr::addBox(scene, {0, 0, 0}, {1, 1, 1}, 0);
    scene.lights = {lightAt({0, 2, 0}), lightAt({1, 2, 0})};
    REQUIRE_NOTHROW(scene.validate());

    SECTION("light radius") {
        scene.lights[1].radius = -1.0f;
        REQUIRE_THROWS_WITH(scene.validate(), Contains("light 1: radius must be finite and > 0, got -1"));
    }
    SECTION("light colour") {
        scene.lights[0].color = {1, -0.5f, 0};
        REQUIRE_THROWS_WITH(scene.validate(), Contains("light 0: color"));
    }
    SECTION("non-finite position") {
        scene.meshes[0].positions[3].y = INFINITY;
        REQUIRE_THROWS_WITH(scene.validate(), Contains("mesh 0") && Contains("position 3"));
    }
    SECTION("index out of range") {
        scene.meshes[0].indices[5] = 1000;
        REQUIRE_THROWS_WITH(scene.validate(), Contains("mesh 0") && Contains("index 5 is 1000"));
    }
    SECTION("index count") {
        scene.meshes[0].indices.pop_back();
        REQUIRE_THROWS_WITH(scene.validate(), Contains("not a multiple of 3"));
    }
    SECTION("mesh material") {
        scene.meshes[0].material = 1;
        REQUIRE_THROWS_WITH(scene.validate(), Contains("mesh 0") && Contains("material 1 out of range"));
    }
    SECTION("texCoords") {
        scene.meshes[0].texCoords.pop_back();
        REQUIRE_THROWS_WITH(scene.validate(), Contains("texCoords"));
    }
    SECTION("light paths") {
        scene.lightPaths.resize(1);
        REQUIRE_THROWS_WITH(scene.validate(), Contains("1 paths for 2 lights"));
    }
    SECTION("camera") {
        scene.camera.farPlane = scene.camera.nearPlane;
        REQUIRE_THROWS_WITH(scene.validate(), Contains("camera: far"));
        scene.camera.farPlane = 100.0f;
        scene.camera.fovYDegrees = 180.0f;
        REQUIRE_THROWS_WITH(scene.validate(), Contains("camera: fov"));
        scene.camera.fovYDegrees = 60.0f;
        scene.camera.target = scene.camera.position;
        REQUIRE_THROWS_WITH(scene.validate(), Contains("camera: position and target"));
    }
    SECTION("resolution") {
        scene.width = 0;
        REQUIRE_THROWS_WITH(scene.validate(), Contains("resolution"));
        scene.width = 100000;
        REQUIRE_THROWS_WITH(scene.validate(), Contains("resolution"));
    }
    SECTION("materials") {
        scene.materials[0].opacity = 1.5f;
        REQUIRE_THROWS_WITH(scene.validate(), Contains("material 0") && Contains("opacity"));
        scene.materials[0].opacity = 1.0f;
        scene.materials[0].shininess = 0.0f;
        REQUIRE_THROWS_WITH(scene.validate(), Contains("shininess"));
        scene.materials[0].shininess = 8.0f;
        scene.materials[0].specular.g = NAN;
        REQUIRE_THROWS_WITH(scene.validate(), Contains("specular"));
    }
    SECTION("too many lights") {
        scene.lights.resize(65536, lightAt({0, 1, 0}));
        REQUIRE_THROWS_WITH(scene.validate(), Contains("65536 lights") && Contains("65535"));
    }
    SECTION("light radius too large (issue 13)") {
        scene.lights[1].radius = 1e38f;
        REQUIRE_THROWS_WITH(scene.validate(), Contains("light 1: radius 1e+38 is too large (limit 1e+18)"));
        scene.lights[1].radius = lidr::maxLightRadius;  // the limit itself is accepted
        REQUIRE_NOTHROW(scene.validate());
        scene.lights[1].position = {3e38f, 0, 0};  // position + radius is still finite; 3.4e38 + 1e18 rounds
        REQUIRE_NOTHROW(scene.validate());
    }
    SECTION("camera whose view basis overflows float (issue 13)") {
        scene.camera.position = {-3e38f, 0, 0};
        scene.camera.target = {3e38f, 0, 0};  // target - position is +inf: not "parallel to up"
        REQUIRE_THROWS_WITH(scene.validate(), Contains("camera: target - position overflows float") &&
                                                  !Contains("parallel"));
        scene.camera.position = {0, 1, 0};
        scene.camera.target = {1e20f, 1, 0};  // finite, but its length^2 overflows in normalize
        REQUIRE_THROWS_WITH(scene.validate(), Contains("camera: target - position overflows float") &&
                                                  !Contains("parallel"));
        scene.camera.position = {3e38f, -3e38f, 0};
        scene.camera.target = {3e38f, -3e38f, -1};  // a unit direction, but dot(side, position) overflows
        scene.camera.up = {1, 1, 0};
        REQUIRE_THROWS_WITH(scene.validate(), Contains("camera: position") && Contains("overflow float in the view basis"));
    }
    SECTION("too many triangles (issue 13)") {
        scene.meshes[0].indices.resize((lidr::maxSceneTriangles + 1) * 3, 0);
        REQUIRE_THROWS_WITH(scene.validate(), Contains("20000001 triangles") && Contains("at most 20000000"));
    }
}

TEST_CASE("scene files: every file in media/scenes loads (JSON and glTF)", "[scene][cpu]") {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(mediaPath("scenes"))) {
        if (entry.path().extension() != ".json" && entry.path().extension() != ".gltf") continue;
        INFO(entry.path().string());
        lidr::Scene scene;
        REQUIRE_NOTHROW(scene = lidr::loadScene(entry.path().string()));
        CHECK(scene.triangleCount() > 0);
        CHECK(!scene.lights.empty());
        checkMeshes(scene);
        ++count;
    }
    CHECK(count >= 4);
}

TEST_CASE("scene files: the full example in doc/scene-format.md loads", "[scene][cpu]") {
    std::ifstream in(std::string(LIDR_SOURCE_DIR) + "/doc/scene-format.md");
    std::stringstream doc;
    doc << in.rdbuf();
    const std::string text = doc.str();
    const size_t begin = text.find("```json\n");
    REQUIRE(begin != std::string::npos);
    const size_t end = text.find("\n```", begin);
    REQUIRE(end != std::string::npos);
    const std::string json = text.substr(begin + 8, end - begin - 8);
    const lidr::Scene scene = lidr::parseSceneJson(json, mediaPath("scenes"), "doc example");
    CHECK(scene.name == "gallery");
    CHECK(scene.time == 2.5f);
    CHECK(scene.lights.size() == 4 + 100 + 20);
    CHECK(scene.lightPaths.size() == scene.lights.size());
    CHECK(scene.triangleCount() > 38000);
    checkMeshes(scene);
}

TEST_CASE("scene files: room-default matches makeDefaultScene", "[scene][cpu]") {
    const lidr::Scene fromFile = lidr::loadSceneFile(mediaPath("scenes/room-default.json"));
    lidr::Scene built = lidr::makeDefaultScene();
    built.name = fromFile.name;
    CHECK(sceneBytes(fromFile) == sceneBytes(built));
}

TEST_CASE("scene files: simple-floor", "[scene][cpu]") {
    const lidr::Scene scene = lidr::loadSceneFile(mediaPath("scenes/simple-floor.json"));
    CHECK(scene.name == "simple-floor");
    CHECK(scene.width == 800);
    CHECK(scene.height == 600);
    CHECK(scene.camera.fovYDegrees == 55.0f);
    CHECK(scene.ambient == glm::vec3(0.03f));
    REQUIRE(scene.materials.size() == 3);
    CHECK(scene.materials[1].name == "red");
    CHECK(scene.materials[2].shininess == 96.0f);
    REQUIRE(scene.meshes.size() == 3);
    CHECK(scene.meshes[1].material == 1);
    REQUIRE(scene.lights.size() == 4);
    REQUIRE(scene.lightPaths.size() == 4);
    CHECK(scene.lightPaths[0].kind == lidr::LightPath::Kind::Static);
    CHECK(scene.lightPaths[1].kind == lidr::LightPath::Kind::Orbit);
    CHECK(scene.lightPaths[2].kind == lidr::LightPath::Kind::Bounce);
    CHECK(scene.lights[0].priority == 10.0f);
    // An orbiting light rests where its orbit puts it at t = 0: center + radius * (cos 0, 0, sin 0).
    CHECK(scene.lights[1].position.x == Approx(3.5f));
    CHECK(scene.lights[1].position.y == Approx(1.2f));
    CHECK(scene.lights[1].position.z == Approx(0.0f).margin(1e-6));
}

TEST_CASE("scene files: obj-demo with OBJ, MTL and texture", "[scene][cpu]") {
    const lidr::Scene scene = lidr::loadSceneFile(mediaPath("scenes/obj-demo.json"));
    REQUIRE(scene.lights.size() == 25);
    REQUIRE(scene.lightPaths.size() == 25);
    CHECK(scene.lightPaths[0].kind == lidr::LightPath::Kind::Static);
    CHECK(scene.lightPaths[1].kind == lidr::LightPath::Kind::Bounce);
    int crateMaterial = -1;
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name == "crate") crateMaterial = int(i);
    REQUIRE(crateMaterial >= 0);
    const lidr::Material& crate = scene.materials[size_t(crateMaterial)];
    CHECK(crate.diffuse.r == Approx(lidr::srgbToLinear(0.9)));  // MTL colours are decoded (doc/colour.md)
    CHECK(crate.specular.g == Approx(lidr::srgbToLinear(0.1)));
    CHECK(crate.shininess == 16.0f);
    CHECK(fs::equivalent(crate.diffuseTexture, mediaPath("models/checker.ppm")));
    size_t crateMeshes = 0;
    for (const lidr::Mesh& mesh : scene.meshes)
        if (mesh.material == crateMaterial) {
            ++crateMeshes;
            CHECK(mesh.triangleCount() == 12);  // 6 quads
            CHECK(mesh.positions.size() == 24);  // flat faces share their corners
            CHECK(mesh.texCoords.size() == 24);
        }
    CHECK(crateMeshes == 2);  // the third crate uses the "painted" override
}

TEST_CASE("OBJ: triangulation, normals, transforms", "[scene][cpu]") {
    TempDir dir;
    lidr::Scene scene;
    // A unit quad in the xz plane facing +y, and a tetrahedron-like fan with a smoothing group.
    const std::string quad = dir.write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 0 -1\nv 0 0 -1\nf 1 2 3 4\n");
    lidr::appendObj(scene, quad, glm::mat4(1.0f));
    REQUIRE(scene.meshes.size() == 1);
    CHECK(scene.meshes[0].triangleCount() == 2);
    CHECK(scene.meshes[0].texCoords.empty());
    for (const glm::vec3& n : scene.meshes[0].normals) CHECK(n == glm::vec3(0, 1, 0));
    CHECK(scene.materials.size() == 1);  // "default", for faces without a material
    CHECK(scene.materials[0].name == "default");

    // Mirroring keeps the triangles counter-clockwise around the (mirrored) normals.
    const glm::mat4 mirror = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0, 5, 0)), glm::vec3(1, -1, 1));
    lidr::appendObj(scene, quad, mirror);
    for (const glm::vec3& n : scene.meshes[1].normals) CHECK(n == glm::vec3(0, -1, 0));
    for (const glm::vec3& p : scene.meshes[1].positions) CHECK(p.y == 5.0f);

    const std::string roof = dir.write("roof.obj",
                                       "v -1 0 0\nv 0 1 0\nv 1 0 0\nv -1 0 -1\nv 0 1 -1\nv 1 0 -1\n"
                                       "s 1\nf 1 2 5 4\nf 2 3 6 5\n");
    lidr::appendObj(scene, roof, glm::mat4(1.0f));
    const lidr::Mesh& smooth = scene.meshes[2];
    CHECK(smooth.triangleCount() == 4);
    CHECK(smooth.positions.size() == 6);  // smooth corners are shared across faces
    for (size_t i = 0; i < smooth.positions.size(); ++i)
        if (smooth.positions[i].y == 1.0f) CHECK(smooth.normals[i].y == Approx(1.0f));

    const std::string withNormals = dir.write("n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nvt 0.5 0.25\n"
                                                       "f 1/1/1 2/1/1 3/1/1\n");
    lidr::appendObj(scene, withNormals, glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 1, 0)));
    const lidr::Mesh& rotated = scene.meshes[3];
    CHECK(rotated.normals[0].x == Approx(1.0f));
    CHECK(rotated.texCoords[0] == glm::vec2(0.5f, 0.25f));
    REQUIRE_NOTHROW(scene.validate());
    checkMeshes(scene);
}

TEST_CASE("scene files: bad input is an lidr::Error naming the problem", "[scene][cpu]") {
    TempDir dir;
    const auto load = [&](const std::string& json) { return lidr::loadSceneFile(dir.write("scene.json", json)); };

    SECTION("missing scene file") {
        REQUIRE_THROWS_WITH(lidr::loadSceneFile("/nonexistent/lidr/scene.json"),
                            Contains("/nonexistent/lidr/scene.json") && Contains("not found"));
    }
    SECTION("malformed JSON") {
        REQUIRE_THROWS_WITH(load(R"({"name": "x",})"), Contains("scene.json") && Contains("malformed JSON"));
        REQUIRE_THROWS_WITH(load(""), Contains("malformed JSON"));
        REQUIRE_THROWS_WITH(load(R"({"lights": [{"radius": 1 "color": 2}]})"), Contains("lights[0].radius"));
    }
    SECTION("unknown keys") {
        REQUIRE_THROWS_WITH(load(R"({"nmae": "typo"})"), Contains("nmae") && Contains("unknown key"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "camera": {"fovy": 50})")), Contains("camera.fovy: unknown key"));
    }
    SECTION("duplicate keys") {
        REQUIRE_THROWS_WITH(load(R"({"name": "a", "name": "b"})"), Contains("name: duplicate key"));
    }
    SECTION("wrong types and missing fields") {
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "lights": [{"position": [0, 1, 0], "radius": "big"}])")),
                            Contains("lights[0].radius: expected a number, got string"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "lights": [{"position": [0, 1, 0]}])")),
                            Contains("lights[0].radius: missing required field"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "lights": [{"position": [0, 1], "radius": 1}])")),
                            Contains("lights[0].position: expected 3 elements"));
        REQUIRE_THROWS_WITH(load(R"([1, 2])"), Contains("expected an object"));
    }
    SECTION("negative radius and colour") {
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "lights": [{"position": [0, 1, 0], "radius": -1}])")),
                            Contains("lights[0].radius: must be > 0, got -1"));
        REQUIRE_THROWS_WITH(
            load(sceneWith(R"(, "lights": [{"position": [0, 1, 0], "radius": 1, "color": [1, -1, 0]}])")),
            Contains("lights[0].color"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "materials": [{"name": "m", "diffuse": -0.5}])")),
                            Contains("materials[0].diffuse"));
    }
    SECTION("infinite numbers") {
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "lights": [{"position": [0, 1, 0], "radius": 1e999}])")),
                            Contains("lights[0].radius") && Contains("1e999"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "lights": [{"position": [0, 1e39, 0], "radius": 1}])")),
                            Contains("lights[0].position[1]") && Contains("out of range"));
    }
    SECTION("resolution") {
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "resolution": [0, 600])")), Contains("resolution[0]"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "resolution": [800, 100000])")),
                            Contains("resolution[1]") && Contains("100000"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "resolution": [800.5, 600])")), Contains("expected an integer"));
    }
    SECTION("too many lights") {
        REQUIRE_THROWS_WITH(
            load(sceneWith(R"(, "generate": {"count": 70000, "bounds_min": [0, 0, 0], "bounds_max": [1, 1, 1]})")),
            Contains("generate.count") && Contains("70000"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "lights": [{"position": [0, 1, 0], "radius": 1}],
                                   "generate": [{"count": 65535, "bounds_min": [0, 0, 0], "bounds_max": [1, 1, 1]}])")),
                            Contains("generate[0].count") && Contains("at most 65535"));
    }
    SECTION("bad camera") {
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "camera": {"near": 10, "far": 1})")),
                            Contains("camera") && Contains("near"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "camera": {"fov": 0})")), Contains("camera: fov"));
    }
    SECTION("primitives") {
        REQUIRE_THROWS_WITH(load(R"({"primitives": [{"shape": "cone", "radius": 1}]})"),
                            Contains("primitives[0].shape") && Contains("cone"));
        REQUIRE_THROWS_WITH(load(R"({"primitives": [{"shape": "sphere", "center": [0, 0, 0], "radius": 1,
                                                     "segments": 2}]})"),
                            Contains("primitives[0].segments"));
        REQUIRE_THROWS_WITH(load(R"({"primitives": [{"shape": "box", "min": [0, 0, 0], "max": [1, 0, 1]}]})"),
                            Contains("primitives[0].max"));
        REQUIRE_THROWS_WITH(load(R"({"primitives": [{"shape": "sphere", "center": [0, 0, 0], "radius": 1,
                                                     "material": "nope"}]})"),
                            Contains("primitives[0].material") && Contains("unknown material 'nope'"));
    }
    SECTION("light paths") {
        REQUIRE_THROWS_WITH(
            load(sceneWith(R"(, "lights": [{"position": [0, 1, 0], "radius": 1, "path": {"kind": "spiral"}}])")),
            Contains("lights[0].path.kind") && Contains("spiral"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "lights": [{"position": [0, 1, 0], "radius": 1, "path":
                                   {"kind": "bounce", "velocity": [1, 0, 0], "box_min": [0, 0, 0], "box_max": [-1, 1, 1]}}])")),
                            Contains("lights[0].path.box_max"));
    }
    SECTION("base scene") {
        REQUIRE_THROWS_WITH(load(R"({"base": "castle"})"), Contains("base") && Contains("castle"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "seed": 3)")), Contains("seed") && Contains("base"));
    }
    SECTION("missing and bad textures") {
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "materials": [{"name": "m", "texture": "nope.png"}])")),
                            Contains("materials[0].texture") && Contains("nope.png") && Contains("not found"));
        dir.write("garbage.png", "this is not an image");
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "materials": [{"name": "m", "texture": "garbage.png"}])")),
                            Contains("materials[0].texture") && Contains("cannot be read"));
    }
    SECTION("missing OBJ") {
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "missing.obj"}])")),
                            Contains("models[0].file") && Contains("missing.obj") && Contains("not found"));
    }
    SECTION("malformed OBJ") {
        dir.write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 5\n");
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "range.obj"}])")),
                            Contains("models[0].file") && Contains("range.obj") && Contains("out of range"));
        struct Case {
            const char *file, *content, *error;
        };
        for (const Case& c : {Case{"zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "malformed OBJ"},
                              Case{"empty.obj", "# nothing here\nv 0 0 0\n", "no triangles"},
                              Case{"huge.obj", "v 1e999 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "not finite"}}) {
            dir.write(c.file, c.content);
            REQUIRE_THROWS_WITH(load(sceneWith(std::string(R"(, "models": [{"file": ")") + c.file + "\"}]")),
                                Contains(c.file) && Contains(c.error));
        }
    }
    SECTION("OBJ with a missing texture in its MTL") {
        dir.write("textured.obj", "mtllib textured.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl t\nf 1 2 3\n");
        dir.write("textured.mtl", "newmtl t\nKd 1 1 1\nmap_Kd missing.ppm\n");
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "textured.obj"}])")),
                            Contains("models[0].file") && Contains("material 't'") && Contains("missing.ppm"));
    }
    SECTION("OBJ whose MTL has values the renderer cannot use (found by fuzz.obj)") {
        dir.write("neg.obj", "mtllib neg.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl n\nf 1 2 3\n");
        dir.write("neg.mtl", "newmtl n\nKd 0 0 -0.5\n");
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "neg.obj"}])")),
                            Contains("material 'n'") && Contains("Kd must be finite and >= 0"));
        dir.write("neg.mtl", "newmtl n\nKd 1 1 1\nd 2\n");
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "neg.obj"}])")),
                            Contains("material 'n'") && Contains("d (dissolve) must be in [0, 1]"));
    }
    SECTION("OBJ without an MTL loads with the default material") {
        dir.write("nomtl.obj", "mtllib absent.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n");
        const lidr::Scene scene = load(sceneWith(R"(, "models": [{"file": "nomtl.obj"}])"));
        CHECK(scene.triangleCount() == 13);
        CHECK(scene.materials.size() == 1);
        CHECK(scene.materials[0].name == "default");
    }
}

TEST_CASE("scene files: limits are checked before any work, naming the value and the limit (issue 13)",
          "[scene][cpu]") {
    TempDir dir;
    const auto load = [&](const std::string& json) { return lidr::loadSceneFile(dir.write("scene.json", json)); };
    SECTION("subdivisions") {
        REQUIRE_THROWS_WITH(load(R"({"primitives": [{"shape": "box", "min": [0, 0, 0], "max": [1, 1, 1],
                                                     "subdivisions": 100000}]})"),
                            Contains("primitives[0].subdivisions") && Contains("[1, 256]") && Contains("100000"));
        REQUIRE_NOTHROW(load(R"({"primitives": [{"shape": "plane", "center": [0, 0, 0], "size": [1, 1],
                                                 "subdivisions": 256}]})"));
        lidr::Scene scene;
        scene.materials.resize(1);
        REQUIRE_THROWS_WITH(lidr::addBox(scene, {0, 0, 0}, {1, 1, 1}, 0, 257),
                            Contains("addBox: subdivisions 257 is above the limit of 256"));
        REQUIRE_THROWS_WITH(lidr::addTorus(scene, {0, 0, 0}, 2, 1, 0, 1025, 12),
                            Contains("majorSegments 1025 is above the limit of 1024"));
        CHECK(scene.meshes.empty());
    }
    SECTION("light radius and generator bounds") {
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "lights": [{"position": [0, 1, 0], "radius": 1e38}])")),
                            Contains("lights[0].radius: radius 1e+38 is too large (limit 1e+18)"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "generate": {"count": 4, "bounds_min": [-3e38, 0, 0],
                                                               "bounds_max": [3e38, 1, 1]})")),
                            Contains("generate: light generator bounds") && Contains("overflow float") &&
                                !Contains("light 1"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "generate": [{"count": 4, "bounds_min": [0, 0, 0],
                                   "bounds_max": [1, 1, 1], "radius_max": 1e30}])")),
                            Contains("generate[0].radius_max") && Contains("too large (limit 1e+18)"));
        lidr::Scene scene;
        lidr::LightGeneratorOptions options;
        options.count = 3;
        options.boundsMin = glm::vec3(-3e38f);
        options.boundsMax = glm::vec3(3e38f);
        REQUIRE_THROWS_WITH(lidr::generateLights(scene, options), Contains("generateLights: bounds overflow float"));
    }
    SECTION("deep nesting and huge keys or strings give short messages") {
        // 200,000 open arrays gave a 600 KB message (the path of every level).
        std::string message;
        try {
            load(std::string(200000, '['));
        } catch (const lidr::Error& error) {
            message = error.what();
        }
        CHECK_THAT(message, Contains("nested deeper than 64 arrays and objects"));
        CHECK(message.size() < 400);
        // The limit counts the top-level object: 63 arrays inside it are allowed, 64 are not.
        const std::string deep = R"({"lights": )" + std::string(64, '[') + std::string(64, ']') + "}";
        CHECK_THROWS_WITH(load(deep), Contains("lights") && Contains("nested deeper than 64"));
        const std::string fine = R"({"lights": )" + std::string(63, '[') + std::string(63, ']') + "}";
        CHECK_THROWS_WITH(load(fine), !Contains("nested deeper") && Contains("lights"));
        const std::string longKey(1000000, 'k');
        message.clear();
        try {
            load("{\"" + longKey + "\": 1}");
        } catch (const lidr::Error& error) {
            message = error.what();
        }
        CHECK_THAT(message, Contains("unknown key") && Contains("(1000000 characters)"));
        CHECK(message.size() < 400);
        message.clear();
        try {
            load(R"({"mode": ")" + longKey + R"("})");
        } catch (const lidr::Error& error) {
            message = error.what();
        }
        CHECK_THAT(message, Contains("mode") && Contains("characters left out"));
        CHECK(message.size() <= 2100);
    }
}

TEST_CASE("scene files: files that are not regular, unsupported formats and huge textures say so (issue 13)",
          "[scene][cpu]") {
    TempDir dir;
    const auto load = [&](const std::string& json) { return lidr::loadSceneFile(dir.write("scene.json", json)); };
    fs::create_directories(dir.path() / "folder.obj");
    fs::create_directories(dir.path() / "folder.json");
    fs::create_directories(dir.path() / "folder.png");
    fs::create_symlink("loop-b.obj", dir.path() / "loop-a.obj");
    fs::create_symlink("loop-a.obj", dir.path() / "loop-b.obj");
    SECTION("scene file") {
        REQUIRE_THROWS_WITH(lidr::loadSceneFile((dir.path() / "folder.json").string()),
                            Contains("folder.json: scene file is a directory"));
        REQUIRE_THROWS_WITH(lidr::loadSceneFile("/dev/null"), Contains("/dev/null: scene file is not a regular file"));
        REQUIRE_THROWS_WITH(lidr::loadSceneFile((dir.path() / "loop-a.obj").string()),
                            Contains(std::strerror(ELOOP)) && !Contains("not found"));
    }
    SECTION("OBJ") {
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "folder.obj"}])")),
                            Contains("models[0].file") && Contains("OBJ file is a directory"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "/dev/null"}])")),
                            Contains("OBJ file is not a regular file"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "loop-a.obj"}])")),
                            Contains(std::strerror(ELOOP)) && !Contains("not found"));
        dir.write("mesh.ply", "ply\nformat ascii 1.0\nend_header\n");
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "mesh.ply"}])")),
                            Contains("format not supported (PLY)") && !Contains("no triangles"));
        // glTF is read (tests/test_gltf_import.cpp): a 4-byte .glb is a malformed one, not an unsupported format
        dir.write("mesh.glb", "glTF");
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "mesh.glb"}])")),
                            Contains("models[0].file: ") && Contains("mesh.glb: GLB header: the file has 4 bytes"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "mesh.gltf"}])")), Contains("mesh.gltf: glTF file not found"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "mesh.FBX"}])")), Contains("format not supported (FBX)"));
    }
    SECTION("OBJ numbers tinyobjloader would read as 0") {
        dir.write("nan.obj", "v 0 0 0\nv 1 0 0\n# comment\nv 0 nan 0\nf 1 2 3\n");
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "nan.obj"}])")),
                            Contains("nan.obj") && Contains("line 4: vertex 3 coordinate 'nan' is not finite"));
        dir.write("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 -inf\nf 1 2 3\n");
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "inf.obj"}])")),
                            Contains("inf.obj") && Contains("line 3: vertex 3 coordinate '-inf' is not finite"));
        dir.write("big.obj", "v 0 0 0\nv 1 0 0\nv 0 1e39 0\nf 1 2 3\n");
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "big.obj"}])")),
                            Contains("line 3: vertex 3 coordinate '1e39' is not finite"));
        dir.write("vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 NaN\nf 1//1 2//1 3//1\n");
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "vn.obj"}])")),
                            Contains("line 4: normal 1 coordinate 'NaN' is not finite"));
        dir.write("word.obj", "v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n");
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "models": [{"file": "word.obj"}])")),
                            Contains("line 3: vertex 3 coordinate 'zero' is not a number"));
    }
    SECTION("textures") {
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "materials": [{"name": "m", "texture": "folder.png"}])")),
                            Contains("materials[0].texture") && Contains("is a directory"));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "materials": [{"name": "m", "texture": "/dev/null"}])")),
                            Contains("is not a regular file"));
        // A PNG signature and IHDR chunk claiming 100000 x 100000 (the rest is missing).
        const unsigned char header[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                        0, 1, 0x86, 0xa0, 0, 1, 0x86, 0xa0, 8, 6, 0, 0, 0, 0, 0, 0, 0};
        dir.write("huge.png", std::string(reinterpret_cast<const char*>(header), sizeof header));
        REQUIRE_THROWS_WITH(load(sceneWith(R"(, "materials": [{"name": "m", "texture": "huge.png"}])")),
                            Contains("huge.png' is 100000x100000, over the texture limit of 16384 per side"));
    }
}

TEST_CASE("materials: metallic / roughness in scene files, Blinn-Phong mapped onto them", "[scene][cpu][brdf]") {
    TempDir dir;
    const lidr::Scene scene = lidr::loadScene(dir.write("pbr.json", R"({
        "materials": [{"name": "steel", "diffuse": [0.6, 0.6, 0.62], "metallic": 1, "roughness": 0.3},
                      {"name": "matte", "diffuse": 0.5, "roughness": 0.9},
                      {"name": "plastic", "diffuse": [0.75, 0.12, 0.1], "specular": 0.6, "shininess": 64},
                      {"name": "gold", "diffuse": [0.8, 0.6, 0.22], "specular": [0.9, 0.75, 0.45], "shininess": 96}],
        "primitives": [{"shape": "box", "min": [0, 0, 0], "max": [1, 1, 1], "material": "steel"}]})"));
    const auto of = [&](const char* name) {
        for (const lidr::Material& m : scene.materials)
            if (m.name == name) return lidr::metallicRoughnessOf(m);
        FAIL("no material " << name);
        return lidr::MetallicRoughness{};
    };
    CHECK(of("steel").metallic == 1.0f);
    CHECK(of("steel").roughness == Approx(0.3f));
    CHECK(of("steel").baseColor.b == Approx(lidr::srgbToLinear(0.62)));  // colours still display values
    CHECK(of("matte").metallic == 0.0f);
    CHECK(of("matte").roughness == Approx(0.9f));
    // Blinn-Phong: alpha^2 = 2 / (n + 2), roughness = alpha^(1/2); a grey specular stays dielectric
    CHECK(of("plastic").metallic == 0.0f);
    CHECK(of("plastic").roughness == Approx(std::pow(2.0 / 66.0, 0.25)));
    CHECK(of("plastic").baseColor.r == Approx(lidr::srgbToLinear(0.75)));
    // a strong chromatic specular is a metal of that colour
    CHECK(of("gold").metallic == 1.0f);
    CHECK(of("gold").baseColor.b == Approx(lidr::srgbToLinear(0.45)));
    REQUIRE_THROWS_WITH(lidr::loadScene(dir.write("both.json", R"({
        "materials": [{"name": "x", "metallic": 0.5, "shininess": 8}]})")),
                        Catch::Contains("materials[0]") && Catch::Contains("not both"));
    REQUIRE_THROWS_WITH(lidr::loadScene(dir.write("range.json", R"({
        "materials": [{"name": "x", "roughness": 1.5}]})")),
                        Catch::Contains("roughness") && Catch::Contains("[0, 1]"));
}

TEST_CASE("scene files: scatter_lights adds seeded lights over the surfaces read before it", "[cpu][scene][scatter]") {
    TempDir dir;
    const auto load = [&](const std::string& json) { return lidr::loadSceneFile(dir.write("scene.json", json)); };
    const std::string floor = R"({"primitives": [{"shape": "box", "min": [-10, -0.1, -10], "max": [10, 0.1, 10]}],
                                  "lights": [{"position": [0, 3, 0], "radius": 2}])";
    const lidr::Scene a = load(floor + R"(, "scatter_lights": {"count": 100, "seed": 7}})");
    const lidr::Scene b = load(floor + R"(, "scatter_lights": {"count": 100, "seed": 7}})");
    const lidr::Scene c = load(floor + R"(, "scatter_lights": {"count": 100, "seed": 8, "radius": 0.5, "spot_share": 0.5}})");
    REQUIRE(a.lights.size() == 101);
    REQUIRE(c.lights.size() == 101);
    CHECK(a.lights[0].position == glm::vec3(0, 3, 0));  // the file's own lights first
    for (size_t i = 1; i < a.lights.size(); ++i) {
        CHECK(a.lights[i].position == b.lights[i].position);  // seeded: the same file, the same lights
        CHECK(std::abs(a.lights[i].position.x) <= 10.5f);     // over the box
        CHECK(std::abs(a.lights[i].position.z) <= 10.5f);
        CHECK(c.lights[i].radius == 0.5f);
    }
    CHECK(a.lights[1].position != c.lights[1].position);
    int spots = 0;
    for (const lidr::PointLight& l : c.lights) spots += l.isSpot() ? 1 : 0;
    CHECK(spots == 50);
    REQUIRE_THROWS_WITH(load(floor + R"(, "scatter_lights": {"count": 0}})"), Contains("scatter_lights.count"));
    REQUIRE_THROWS_WITH(load(floor + R"(, "scatter_lights": {"count": 70000}})"), Contains("scatter_lights.count"));
    REQUIRE_THROWS_WITH(load(floor + R"(, "scatter_lights": {"count": 10, "radius": -1}})"),
                        Contains("scatter_lights.radius: must be > 0"));
    REQUIRE_THROWS_WITH(load(floor + R"(, "scatter_lights": {"count": 10, "spot_share": 2}})"),
                        Contains("scatter_lights.spot_share: must be in [0, 1]"));
    REQUIRE_THROWS_WITH(load(floor + R"(, "scatter_lights": {"count": 10, "cnt": 1}})"),
                        Contains("scatter_lights.cnt: unknown key"));
    REQUIRE_THROWS_WITH(load(R"({"lights": [{"position": [0, 3, 0], "radius": 2}], "scatter_lights": {"count": 10}})"),
                        Contains("scatter_lights: needs surfaces"));
}
