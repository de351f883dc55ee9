#include "lidr/scene/default_scene.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/constants.hpp>

#include "lidr/base/colour.h"
#include "lidr/base/error.h"
#include "lidr/scene/primitives.h"
#include "lidr/scene/random.h"

namespace lidr {

namespace {

constexpr int maxLights = 65535;

using Random = SplitMix64;

// A fully bright colour of the given hue in [0, 1), saturation in [0, 1].
glm::vec3 saturatedColor(float hue, float saturation) {
    const glm::vec3 offsets(0.0f, 4.0f, 2.0f);
    const glm::vec3 pure = glm::clamp(glm::abs(glm::mod(hue * 6.0f + offsets, 6.0f) - 3.0f) - 1.0f, 0.0f, 1.0f);
    return glm::mix(glm::vec3(1.0f), pure, saturation);
}

glm::vec3 randomDirection(Random& random) {
    const float y = random.uniform(-1.0f, 1.0f);
    const float angle = random.uniform(0.0f, glm::two_pi<float>());
    const float horizontal = std::sqrt(std::max(0.0f, 1.0f - y * y));
    return {horizontal * std::cos(angle), y, horizontal * std::sin(angle)};
}

void requireValid(bool condition, const std::string& problem) {
    if (!condition) throw Error("generateLights: " + problem);
}

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Room layout, in metres: floor 40 x 40 at y = 0, walls and ceiling 0.5 thick outside that, 10 high.
constexpr float halfRoom = 20.0f, roomHeight = 10.0f, wallThickness = 0.5f;

enum MaterialId { Floor, Wall, Ceiling, Stone, Red, Blue, Gold, Green, Glass };

std::vector<Material> roomMaterials() {
    const auto material = [](const char* name, glm::vec3 diffuse, glm::vec3 specular, float shininess,
                             float opacity = 1.0f) { return Material{name, diffuse, "", specular, shininess, opacity}; };
    return {
        material("floor", {0.55f, 0.52f, 0.48f}, glm::vec3(0.15f), 24.0f),
        material("wall", {0.62f, 0.60f, 0.56f}, glm::vec3(0.05f), 8.0f),
        material("ceiling", {0.45f, 0.45f, 0.47f}, glm::vec3(0.05f), 8.0f),
        material("stone", {0.70f, 0.67f, 0.60f}, glm::vec3(0.30f), 40.0f),
        material("red plastic", {0.75f, 0.12f, 0.10f}, glm::vec3(0.60f), 64.0f),
        material("blue plastic", {0.12f, 0.25f, 0.75f}, glm::vec3(0.60f), 64.0f),
        material("gold", {0.80f, 0.60f, 0.22f}, {0.90f, 0.75f, 0.45f}, 96.0f),
        material("green", {0.20f, 0.60f, 0.25f}, glm::vec3(0.30f), 32.0f),
        material("glass", {0.60f, 0.80f, 0.90f}, glm::vec3(0.90f), 128.0f, 0.35f),
    };
}

void addRoomShell(Scene& scene) {
    const float outer = halfRoom + wallThickness;
    addPlane(scene, glm::vec3(0.0f), glm::vec2(2.0f * halfRoom), Floor, 20);
    addBox(scene, {-outer, roomHeight, -outer}, {outer, roomHeight + wallThickness, outer}, Ceiling, 4);
    addBox(scene, {-outer, 0.0f, -outer}, {outer, roomHeight, -halfRoom}, Wall, 4);
    addBox(scene, {-outer, 0.0f, halfRoom}, {outer, roomHeight, outer}, Wall, 4);
    addBox(scene, {-outer, 0.0f, -halfRoom}, {-halfRoom, roomHeight, halfRoom}, Wall, 4);
    addBox(scene, {halfRoom, 0.0f, -halfRoom}, {outer, roomHeight, halfRoom}, Wall, 4);
}

// Two rows of six floor-to-ceiling pillars on plinths, framing a central nave.
void addPillars(Scene& scene) {
    for (float x : {-8.0f, 8.0f})
        for (int row = 0; row < 6; ++row) {
            const glm::vec3 base(x, 0.0f, -15.0f + 6.0f * float(row));
            addBox(scene, base - glm::vec3(0.8f, 0.0f, 0.8f), base + glm::vec3(0.8f, 0.4f, 0.8f), Stone);
            addCylinder(scene, base, 0.6f, roomHeight, Stone, 32);
        }
}

// A grid of objects on the floor, cycling through four kinds; sizes vary with the slot, not the seed.
void addObjects(Scene& scene) {
    const float rows[] = {-16.0f, -12.0f, -8.0f, -4.0f, 0.0f, 4.0f, 8.0f, 12.0f};
    const float columns[] = {-16.0f, -12.0f, -4.0f, 0.0f, 4.0f, 12.0f, 16.0f};
    const MaterialId colors[] = {Red, Blue, Gold, Green};
    int slot = 0;
    for (float z : rows)
        for (float x : columns) {
            const glm::vec3 spot(x, 0.0f, z);
            const float size = 0.8f + 0.1f * float(slot % 5);
            const MaterialId color = colors[slot % 4];
            switch ((slot + slot / 7) % 4) {  // the row offset staggers the kinds between rows
            case 0:
                addSphere(scene, spot + glm::vec3(0.0f, size, 0.0f), size, color, 32);
                break;
            case 1:
                addTorus(scene, spot + glm::vec3(0.0f, 0.35f * size, 0.0f), size, 0.35f * size, color, 32, 16);
                break;
            case 2:
                addBox(scene, spot - glm::vec3(size, 0.0f, 0.6f * size), spot + glm::vec3(size, 1.4f * size, 0.6f * size),
                       color, 2);
                break;
            default: {
                const float pedestal = 1.0f + 0.2f * float(slot % 3);
                addBox(scene, spot - glm::vec3(0.5f, 0.0f, 0.5f), spot + glm::vec3(0.5f, pedestal, 0.5f), Stone);
                addSphere(scene, spot + glm::vec3(0.0f, pedestal + 0.6f, 0.0f), 0.6f, slot % 2 ? Glass : Gold, 24);
            }
            }
            ++slot;
        }
}

// The three large slow movers: warm, wide, and kept first when a pixel has too many lights.
void addLargeMovers(Scene& scene, int count, uint32_t seed) {
    Random random((uint64_t(seed) << 32) ^ 0x4C617267ull);  // a stream apart from the particles'
    const glm::vec3 colors[] = {{1.0f, 0.78f, 0.55f}, {1.0f, 0.62f, 0.38f}, {0.95f, 0.85f, 0.65f}};
    const float orbitRadii[] = {5.0f, 10.0f, 14.0f};
    const float angularSpeeds[] = {0.25f, -0.18f, 0.12f};
    for (int i = 0; i < count; ++i) {
        LightPath path;
        path.kind = LightPath::Kind::Orbit;
        path.center = {0.0f, 5.0f, 0.0f};
        path.orbitRadius = orbitRadii[i];
        path.angularSpeed = angularSpeeds[i];
        path.phase = random.uniform(0.0f, glm::two_pi<float>());
        path.bobAmplitude = random.uniform(1.0f, 1.5f);
        PointLight light;
        light.position = evaluatePath(path, glm::vec3(0.0f), 0.0f);
        light.radius = random.uniform(7.0f, 9.0f);
        light.color = 1.0f * colors[i];
        light.priority = 10.0f;
        scene.lights.push_back(light);
        scene.lightPaths.push_back(path);
    }
}

}  // namespace

Scene makeDefaultScene(const DefaultSceneOptions& options) {
    if (options.lightCount < 0 || options.lightCount > maxLights)
        throw Error("makeDefaultScene: lightCount must be in [0, " + std::to_string(maxLights) + "], got " +
                    std::to_string(options.lightCount));
    Scene scene;
    scene.name = "default-room";
    scene.materials = roomMaterials();
    addRoomShell(scene);
    addPillars(scene);
    addObjects(scene);

    scene.camera.position = {0.0f, 4.5f, 17.0f};
    scene.camera.target = {0.0f, 1.0f, 0.0f};
    scene.camera.fovYDegrees = 60.0f;
    scene.camera.nearPlane = 0.1f;
    scene.camera.farPlane = 60.0f;
    scene.width = options.width;
    scene.height = options.height;
    scene.time = options.time;
    // The room's colours were chosen as display values when frames were written linear: decoded here, so that
    // shading in linear light and the sRGB output keep its look (ambient 0.06 still shows as 0.06).
    scene.ambient = srgbToLinear(glm::vec3(0.06f));
    for (Material& m : scene.materials)
        m.diffuse = srgbToLinear(m.diffuse), m.specular = srgbToLinear(m.specular), m.emissive = srgbToLinear(m.emissive);

    const int largeCount = std::min(options.lightCount, 3);
    addLargeMovers(scene, largeCount, options.seed);
    LightGeneratorOptions particles;
    particles.seed = options.seed;
    particles.count = options.lightCount - largeCount;
    particles.boundsMin = {-halfRoom + 0.5f, 0.2f, -halfRoom + 0.5f};
    particles.boundsMax = {halfRoom - 0.5f, 3.5f, halfRoom - 0.5f};
    particles.radiusMin = 0.8f;
    particles.radiusMax = 2.2f;
    particles.intensity = 1.5f;
    particles.speed = 1.5f;
    generateLights(scene, particles);
    // The lights' colours were picked as display values too (strength above 1 kept linear).
    for (PointLight& light : scene.lights) light.color = displayColourToLinear(light.color);

    scene.validate();
    return scene;
}

void generateLights(Scene& scene, const LightGeneratorOptions& options) {
    requireValid(options.count >= 0, "count must be >= 0, got " + std::to_string(options.count));
    requireValid(scene.lights.size() + size_t(options.count) <= size_t(maxLights),
                 std::to_string(scene.lights.size()) + " + " + std::to_string(options.count) +
                     " lights exceed the maximum of " + std::to_string(maxLights));
    requireValid(isFinite(options.boundsMin) && isFinite(options.boundsMax) &&
                     glm::all(glm::lessThanEqual(options.boundsMin, options.boundsMax)),
                 "bounds must be finite with min <= max");
    requireValid(isFinite(options.boundsMax - options.boundsMin) && isFinite(options.boundsMin - glm::vec3(options.radiusMax)) &&
                     isFinite(options.boundsMax + glm::vec3(options.radiusMax)),
                 "bounds overflow float (their extent, or the bounds +- radius max, is not finite)");
    requireValid(!(options.radiusMax > maxLightRadius), "radius max " + std::to_string(options.radiusMax) +
                                                             " is above the limit of 1e+18");
    requireValid(std::isfinite(options.radiusMax) && options.radiusMin > 0.0f && options.radiusMin <= options.radiusMax,
                 "radii must be finite with 0 < min <= max");
    requireValid(std::isfinite(options.intensity) && options.intensity >= 0.0f, "intensity must be finite and >= 0");
    requireValid(std::isfinite(options.speed) && options.speed >= 0.0f, "speed must be finite and >= 0");
    requireValid(scene.lightPaths.empty() || scene.lightPaths.size() == scene.lights.size(),
                 "the scene has " + std::to_string(scene.lightPaths.size()) + " paths for " +
                     std::to_string(scene.lights.size()) + " lights");

    if (options.speed > 0.0f && scene.lightPaths.empty()) scene.lightPaths.assign(scene.lights.size(), LightPath{});
    const bool withPaths = !scene.lightPaths.empty();
    Random random(options.seed);
    for (int i = 0; i < options.count; ++i) {
        // Every light draws the same numbers in the same order, so speed does not change positions or colours.
        PointLight light;
        light.position = {random.uniform(options.boundsMin.x, options.boundsMax.x),
                          random.uniform(options.boundsMin.y, options.boundsMax.y),
                          random.uniform(options.boundsMin.z, options.boundsMax.z)};
        light.radius = random.uniform(options.radiusMin, options.radiusMax);
        const float hue = random.uniform();
        light.color = options.intensity * saturatedColor(hue, random.uniform(0.75f, 1.0f));
        const glm::vec3 direction = randomDirection(random);
        scene.lights.push_back(light);
        if (!withPaths) continue;
        LightPath path;
        if (options.speed > 0.0f) {
            path.kind = LightPath::Kind::Bounce;
            path.velocity = options.speed * direction;
            path.boxMin = options.boundsMin;
            path.boxMax = options.boundsMax;
        }
        scene.lightPaths.push_back(path);
    }
}

}  // namespace lidr
