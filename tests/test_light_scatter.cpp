// Lights scattered over any model's surfaces (lidr/scene/light_scatter.h): deterministic, on the surfaces,
// within limits, refused with a reason where they cannot be made.
#include <catch2/catch.hpp>

#include <cmath>

#include "lidr/base/error.h"
#include "lidr/scene/default_scene.h"
#include "lidr/scene/light_scatter.h"
#include "lidr/scene/primitives.h"

using Catch::Contains;

namespace {

// Distance from p to the nearest triangle's plane among triangles whose projection holds p (a coarse check
// that each light sits over some surface at the expected lift).
float liftAboveSomeTriangle(const lidr::Scene& s, glm::vec3 p, float expected) {
    float best = 1e30f;
    for (const lidr::Mesh& m : s.meshes)
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                            c = m.positions[m.indices[3 * t + 2]];
            const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
            const glm::vec3 q = p - n * expected;  // back down onto the plane
            // barycentric containment of q
            const glm::vec3 v0 = b - a, v1 = c - a, v2 = q - a;
            const float d00 = glm::dot(v0, v0), d01 = glm::dot(v0, v1), d11 = glm::dot(v1, v1);
            const float d20 = glm::dot(v2, v0), d21 = glm::dot(v2, v1), den = d00 * d11 - d01 * d01;
            if (den <= 0.0f) continue;
            const float v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den;
            if (v < -1e-3f || w < -1e-3f || v + w > 1.001f) continue;
            best = std::min(best, std::abs(glm::dot(p - a, n) - expected));
        }
    return best;
}

// A 4 x 1 x 6 box, and 64 lights to scatter over it with seed 7.
lidr::Scene boxScene() {
    lidr::Scene scene;
    scene.materials.push_back({});
    lidr::addBox(scene, glm::vec3(-2.0f, 0.0f, -3.0f), glm::vec3(2.0f, 1.0f, 3.0f), 0, 1);
    return scene;
}

lidr::LightScatterOptions sixtyFourLights() {
    lidr::LightScatterOptions o;
    o.count = 64;
    o.seed = 7;
    return o;
}

}  // namespace

TEST_CASE("scattered lights lie on the surfaces, seeded and within limits", "[cpu][scene][scatter]") {
    const lidr::Scene scene = boxScene();
    lidr::LightScatterOptions o = sixtyFourLights();
    const std::vector<lidr::PointLight> a = lidr::scatterLights(scene, o), b = lidr::scatterLights(scene, o);
    REQUIRE(a.size() == 64);
    for (size_t i = 0; i < a.size(); ++i) {
        CHECK(a[i].position == b[i].position);  // same seed, same lights
        CHECK(a[i].radius == Approx(lidr::defaultScatterRadius(scene, 64)));
        CHECK(std::max({a[i].color.r, a[i].color.g, a[i].color.b}) == Approx(1.0f));
        CHECK(liftAboveSomeTriangle(scene, a[i].position, 0.25f * a[i].radius) < 1e-4f);
    }
    o.seed = 8;
    CHECK(lidr::scatterLights(scene, o)[0].position != a[0].position);
    // The automatic radius: N pi r^2 = 1.5 x area (box area 2 (4x1 + 4x6 + 1x6) = 68).
    CHECK(lidr::defaultScatterRadius(scene, 64) == Approx(std::sqrt(1.5 * 68.0 / (64.0 * M_PI))).epsilon(1e-5));
    o.radius = 0.3f;
    for (const lidr::PointLight& l : lidr::scatterLights(scene, o)) CHECK(l.radius == 0.3f);

    lidr::Scene withPaths = lidr::makeDefaultScene();
    const size_t before = withPaths.lights.size();
    lidr::addScatteredLights(withPaths, o);
    CHECK(withPaths.lights.size() == before + 64);
    CHECK(withPaths.lightPaths.size() == withPaths.lights.size());
    CHECK_NOTHROW(withPaths.validate());
}

TEST_CASE("scattered spot lights: a share of the same lights, aimed back at their surface", "[cpu][scene][scatter][lights]") {
    const lidr::Scene scene = boxScene();
    lidr::LightScatterOptions o = sixtyFourLights();
    const std::vector<lidr::PointLight> points = lidr::scatterLights(scene, o);
    o.spotShare = 0.25f;
    const std::vector<lidr::PointLight> mixed = lidr::scatterLights(scene, o);
    REQUIRE(mixed.size() == points.size());
    int spots = 0;
    for (size_t i = 0; i < mixed.size(); ++i) {
        CHECK(mixed[i].position == points[i].position);  // the same lights; some become spots
        CHECK(mixed[i].color == points[i].color);
        if (!mixed[i].isSpot()) continue;
        ++spots;
        CHECK(mixed[i].outerConeAngle == Approx(glm::radians(lidr::kScatterSpotOuterDegrees)));
        CHECK(mixed[i].innerConeAngle == Approx(glm::radians(lidr::kScatterSpotInnerDegrees)));
        // Down its own lift: a quarter radius along the axis lands back on a triangle's plane.
        CHECK(liftAboveSomeTriangle(scene, mixed[i].position + 0.25f * mixed[i].radius * mixed[i].direction, 0.0f) < 1e-4f);
    }
    CHECK(spots == 16);
    o.spotShare = 1.0f;
    for (const lidr::PointLight& l : lidr::scatterLights(scene, o)) CHECK(l.isSpot());
    lidr::Scene lit = scene;
    lidr::addScatteredLights(lit, o);
    CHECK_NOTHROW(lit.validate());
    o.spotShare = 1.5f;
    CHECK_THROWS_WITH(lidr::scatterLights(scene, o), Contains("spot share must be in [0, 1]"));
}

TEST_CASE("scattering refuses what it cannot make, with the reason", "[cpu][scene][scatter][bad-input]") {
    lidr::Scene empty;
    lidr::LightScatterOptions o;
    o.count = 4;
    CHECK_THROWS_WITH(lidr::scatterLights(empty, o), Contains("no triangle"));
    lidr::Scene scene = lidr::makeDefaultScene();
    o.count = 0;
    CHECK_THROWS_WITH(lidr::scatterLights(scene, o), Contains("count must be 1.."));
    o.count = int(lidr::maxSceneLights);
    CHECK_THROWS_WITH(lidr::scatterLights(scene, o), Contains("count must be 1.."));
    o.count = 4;
    o.radius = -1.0f;
    CHECK_THROWS_WITH(lidr::scatterLights(scene, o), Contains("radius"));
    o.radius = NAN;
    CHECK_THROWS_WITH(lidr::scatterLights(scene, o), Contains("radius"));
}

TEST_CASE("default light rig: a scene without lights gets a key light at the eye reaching the whole model", "[cpu][scene]") {
    lidr::Scene scene;
    scene.materials.push_back(lidr::Material{});
    lidr::addBox(scene, glm::vec3(-1.0f, 0.0f, -2.0f), glm::vec3(3.0f, 1.0f, 2.0f), 0);
    scene.camera.position = glm::vec3(0.0f, 2.0f, 6.0f);
    scene.ambient = glm::vec3(0.04f);
    REQUIRE(lidr::addDefaultLightRig(scene));
    REQUIRE(scene.lights.size() == 1);
    CHECK(scene.lights[0].position == scene.camera.position);
    const float diagonal = glm::length(glm::vec3(4.0f, 1.0f, 4.0f));
    CHECK(scene.lights[0].radius == Approx(3.0f * diagonal));
    CHECK(scene.ambient == glm::vec3(0.1f));
    // every corner of the model is inside the light's range, so every point of it is lit
    for (const lidr::Mesh& m : scene.meshes)
        for (const glm::vec3& p : m.positions) CHECK(glm::length(p - scene.lights[0].position) < scene.lights[0].radius);
    // a scene with lights keeps them, and its ambient
    scene.ambient = glm::vec3(0.02f);
    REQUIRE_FALSE(lidr::addDefaultLightRig(scene));
    CHECK(scene.lights.size() == 1);
    CHECK(scene.ambient == glm::vec3(0.02f));
}
