#include "lidr/eval/bench_scenes.h"

#include <algorithm>
#include <cmath>

#include "lidr/scene/default_scene.h"
#include "lidr/base/error.h"
#include "lidr/scene/primitives.h"
#include "lidr/scene/random.h"

namespace lidr {

const char* manyLightViewName(ManyLightView view) { return view == ManyLightView::TopDown ? "top" : "fp"; }

bool makeManyLightSceneByName(const std::string& name, Scene& scene, uint32_t seed) {
    if (name.compare(0, 5, "many-") != 0) return false;
    const size_t dash = name.find('-', 5);
    const std::string digits = name.substr(5, dash == std::string::npos ? std::string::npos : dash - 5);
    const std::string view = dash == std::string::npos ? "" : name.substr(dash + 1);
    const bool numeric = !digits.empty() && digits.size() <= 5 &&
                         std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
    const int n = numeric ? std::stoi(digits) : 0;
    if (n < 4 || n > 65535 || (view != "top" && view != "fp"))
        throw Error("bad scene name '" + name + "': use many-N-top or many-N-fp with N lights, 4..65535 (e.g. "
                    "many-4096-top)");
    scene = makeManyLightScene(n, view == "top" ? ManyLightView::TopDown : ManyLightView::FirstPerson, 1024, 768, seed);
    return true;
}

Scene makeManyLightScene(int lightCount, ManyLightView view, int width, int height, uint32_t seed) {
    if (lightCount < 4 || lightCount > 65535)
        throw Error("many-light scene: light count must be in [4, 65535], got " + std::to_string(lightCount));
    DefaultSceneOptions room;
    room.seed = seed;
    room.lightCount = 3;  // the large movers only; the particles follow, smaller
    room.width = width;
    room.height = height;
    Scene scene = makeDefaultScene(room);
    scene.name = "many-" + std::to_string(lightCount) + "-" + manyLightViewName(view);
    const float shrink = std::sqrt(255.0f / float(lightCount));
    LightGeneratorOptions particles;
    particles.seed = seed;
    particles.count = lightCount - 3;
    particles.boundsMin = {-19.5f, 0.2f, -19.5f};  // the default room's particle box
    particles.boundsMax = {19.5f, 3.5f, 19.5f};
    particles.radiusMin = 0.8f * shrink;
    particles.radiusMax = 2.2f * shrink;
    particles.intensity = 1.0f;
    particles.speed = 1.5f;
    generateLights(scene, particles);
    if (view == ManyLightView::TopDown) {
        // Just under the ceiling (y = 10), looking straight down over the middle of the floor.
        scene.camera.position = {0.0f, 9.5f, 0.0f};
        scene.camera.target = {0.0f, 0.0f, 0.0f};
        scene.camera.up = {0.0f, 0.0f, -1.0f};
        scene.camera.fovYDegrees = 100.0f;
    } else {
        // Eye height at one end of the nave, looking down its length.
        scene.camera.position = {0.0f, 1.7f, 18.0f};
        scene.camera.target = {0.0f, 1.4f, 0.0f};
        scene.camera.fovYDegrees = 70.0f;
    }
    scene.validate();
    return scene;
}

long sceneTriangleCount(const Scene& scene) {
    long n = 0;
    for (const Mesh& m : scene.meshes) n += long(m.triangleCount());
    return n;
}

Scene makeHeavyScene(long totalTriangles, int width, int height, uint32_t seed) {
    if (totalTriangles < 1 || totalTriangles > 20000000)
        throw Error("heavy scene: triangle count must be in [1, 20000000], got " + std::to_string(totalTriangles));
    DefaultSceneOptions room;
    room.seed = seed;
    room.width = width;
    room.height = height;
    Scene scene = makeDefaultScene(room);
    scene.name = "heavy-" + std::to_string(totalTriangles);
    // A sphere of S segments has S * S triangles (S around, S / 2 rings, two triangles a quad).
    const long extra = totalTriangles - sceneTriangleCount(scene);
    const double perMesh = double(std::max(0L, extra)) / heavyMeshCount;
    int segments = 2 * int(std::lround(std::sqrt(perMesh) / 2.0));
    segments = std::max(8, segments);
    // 8 x 8 x 3 lattice over the floor (x, z in [-16, 17.5]), layers at 0.9, 2.3 and 3.7 m, the middle one
    // shifted in x and the top one in z; radius 0.45 m keeps neighbours apart. Materials cycle through the room's opaque ones (no glass: forward-multipass
    // draws no transparent meshes).
    const int materials[] = {3, 4, 5, 6, 7};
    int i = 0;
    for (int layer = 0; layer < 3; ++layer)
        for (int zi = 0; zi < 8; ++zi)
            for (int xi = 0; xi < 8; ++xi, ++i) {
                const glm::vec3 center(-16.0f + 4.5f * float(xi) + (layer == 1 ? 2.0f : 0.0f), 0.9f + 1.4f * float(layer),
                                       -16.0f + 4.5f * float(zi) + (layer == 2 ? 2.0f : 0.0f));
                addSphere(scene, center, 0.45f, materials[i % 5], segments);
                scene.meshes.back().name = "heavy-sphere";
            }
    scene.validate();
    return scene;
}

namespace {

using SceneRandom = SplitMix64;

// A half ring standing in a vertical plane: the arch between two pillar tops. `center` is the middle of the
// span at the springing height, `along` the unit horizontal direction of the span, `across` the unit
// direction of its thickness; radii inner < outer; `segments` quads around. Closed (ends capped), outward normals.
void addArch(Mesh& mesh, glm::vec3 center, glm::vec3 along, glm::vec3 across, float inner, float outer,
             float thickness, int segments) {
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    auto point = [&](float angle, float r, float side) {
        return center + along * (r * std::cos(angle)) + up * (r * std::sin(angle)) + across * (side * 0.5f * thickness);
    };
    auto quad = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 outward) {
        glm::vec3 n = glm::normalize(glm::cross(b - a, d - a));
        if (glm::dot(n, outward) < 0.0f) {
            std::swap(b, d);
            n = -n;
        }
        const uint32_t base = uint32_t(mesh.positions.size());
        for (const glm::vec3& p : {a, b, c, d}) {
            mesh.positions.push_back(p);
            mesh.normals.push_back(n);
            mesh.texCoords.push_back(glm::vec2(0.0f));
        }
        for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
    };
    const float pi = 3.14159265f;
    for (int s = 0; s < segments; ++s) {
        const float a0 = pi * float(s) / float(segments), a1 = pi * float(s + 1) / float(segments);
        const float mid = 0.5f * (a0 + a1);
        const glm::vec3 radial = along * std::cos(mid) + up * std::sin(mid);
        quad(point(a0, outer, -1), point(a1, outer, -1), point(a1, outer, 1), point(a0, outer, 1), radial);
        quad(point(a0, inner, -1), point(a0, inner, 1), point(a1, inner, 1), point(a1, inner, -1), -radial);
        quad(point(a0, inner, 1), point(a0, outer, 1), point(a1, outer, 1), point(a1, inner, 1), across);
        quad(point(a0, inner, -1), point(a1, inner, -1), point(a1, outer, -1), point(a0, outer, -1), -across);
    }
    // The two feet, facing down.
    quad(point(0, inner, -1), point(0, outer, -1), point(0, outer, 1), point(0, inner, 1), -up);
    quad(point(pi, inner, -1), point(pi, outer, -1), point(pi, outer, 1), point(pi, inner, 1), -up);
}

// One mesh per material: the primitives' meshes of `parts` concatenated (a model's handful of draws).
void mergeByMaterial(Scene& scene, std::vector<Mesh>&& parts) {
    std::vector<int> meshOf(scene.materials.size(), -1);
    for (Mesh& part : parts) {
        int& m = meshOf[size_t(part.material)];
        if (m < 0) {
            m = int(scene.meshes.size());
            Mesh mesh;
            mesh.name = scene.materials[size_t(part.material)].name;
            mesh.material = part.material;
            scene.meshes.push_back(std::move(mesh));
        }
        Mesh& into = scene.meshes[size_t(m)];
        const uint32_t base = uint32_t(into.positions.size());
        into.positions.insert(into.positions.end(), part.positions.begin(), part.positions.end());
        into.normals.insert(into.normals.end(), part.normals.begin(), part.normals.end());
        if (part.texCoords.empty()) part.texCoords.assign(part.positions.size(), glm::vec2(0.0f));
        into.texCoords.insert(into.texCoords.end(), part.texCoords.begin(), part.texCoords.end());
        for (uint32_t i : part.indices) into.indices.push_back(base + i);
    }
}

Material occluderMaterial(const char* name, glm::vec3 diffuse, float specular, float shininess) {
    Material m;
    m.name = name;
    m.diffuse = diffuse;
    m.specular = glm::vec3(specular);
    m.shininess = shininess;
    return m;
}

void buildHall(Scene& scene, Scene& parts) {
    enum { Floor, Wall, Pillar, Arch };
    // Nave x in [-5, 5], aisles out to x = +-12, floor z in [-40, 30], ceiling at 14 m.
    addPlane(parts, {0.0f, 0.0f, -5.0f}, {24.0f, 70.0f}, Floor, 48);
    addBox(parts, {-12.5f, 14.0f, -40.5f}, {12.5f, 14.5f, 30.5f}, Wall, 16);  // ceiling slab
    addBox(parts, {-12.5f, 0.0f, -40.5f}, {-12.0f, 14.0f, 30.5f}, Wall, 16);  // outer walls
    addBox(parts, {12.0f, 0.0f, -40.5f}, {12.5f, 14.0f, 30.5f}, Wall, 16);
    addBox(parts, {-12.0f, 0.0f, -40.5f}, {12.0f, 14.0f, -40.0f}, Wall, 16);  // end walls
    addBox(parts, {-12.0f, 0.0f, 30.0f}, {12.0f, 14.0f, 30.5f}, Wall, 16);
    addBox(parts, {-5.3f, 9.0f, -40.0f}, {-4.7f, 14.0f, 30.0f}, Wall, 16);   // clerestory walls over the arcades
    addBox(parts, {4.7f, 9.0f, -40.0f}, {5.3f, 14.0f, 30.0f}, Wall, 16);
    for (int row = 0; row < 2; ++row) {
        const float x = row == 0 ? -5.0f : 5.0f;
        for (int i = 0; i < 16; ++i) {
            const float z = -36.0f + 4.0f * float(i);
            addBox(parts, {x - 0.6f, 0.0f, z - 0.6f}, {x + 0.6f, 0.6f, z + 0.6f}, Pillar, 2);  // plinth
            for (int k = 0; k < 3; ++k) addCylinder(parts, {x, 0.6f + 2.0f * float(k), z}, 0.45f, 2.0f, Pillar, 48);
            addBox(parts, {x - 0.6f, 6.6f, z - 0.6f}, {x + 0.6f, 7.0f, z + 0.6f}, Pillar, 2);  // capital
            if (i < 15) {  // arch along the row to the next pillar: span 4 m centre to centre
                parts.meshes.push_back(Mesh{"arch", {}, {}, {}, {}, Arch});
                addArch(parts.meshes.back(), {x, 7.0f, z + 2.0f}, {0, 0, 1}, {1, 0, 0}, 1.4f, 2.0f, 0.8f, 16);
            }
            if (i % 4 == 1) {  // chapel walls across the aisles, and an arch across the nave
                addBox(parts, {row == 0 ? -12.0f : 5.6f, 0.0f, z - 0.15f}, {row == 0 ? -5.6f : 12.0f, 6.0f, z + 0.15f},
                       Wall, 8);
                if (row == 0) {
                    parts.meshes.push_back(Mesh{"arch", {}, {}, {}, {}, Arch});
                    addArch(parts.meshes.back(), {0.0f, 7.0f, z}, {1, 0, 0}, {0, 0, 1}, 4.4f, 5.0f, 0.8f, 32);
                }
            }
        }
    }
    (void)scene;
}

void buildCity(Scene& scene, Scene& parts, SceneRandom& random) {
    enum { Floor, Wall, Pillar, Arch };
    // 8 x 8 blocks of 12 m with 6 m streets: x, z in [-72, 72].
    addPlane(parts, {0.0f, 0.0f, 0.0f}, {150.0f, 150.0f}, Floor, 64);
    for (int bz = 0; bz < 8; ++bz)
        for (int bx = 0; bx < 8; ++bx) {
            const float x0 = -72.0f + 18.0f * float(bx) + 3.0f, z0 = -72.0f + 18.0f * float(bz) + 3.0f;
            const float height = random.uniform(6.0f, 30.0f);
            addBox(parts, {x0, 0.0f, z0}, {x0 + 12.0f, height, z0 + 12.0f}, (bx + bz) % 2 ? Wall : Pillar, 6);
            // A ledge all round at first-floor height.
            addBox(parts, {x0 - 0.3f, 3.5f, z0 - 0.3f}, {x0 + 12.3f, 3.9f, z0 + 12.3f}, Arch, 2);
        }
    (void)scene;
}

}  // namespace

bool makeOccludedSceneByName(const std::string& name, Scene& scene, uint32_t seed) {
    for (OccludedSceneKind kind : {OccludedSceneKind::Hall, OccludedSceneKind::City}) {
        const std::string prefix = std::string(occludedSceneName(kind)) + "-";
        if (name.compare(0, prefix.size(), prefix) != 0) continue;
        const std::string digits = name.substr(prefix.size());
        const bool numeric = !digits.empty() && digits.size() <= 5 &&
                             std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
        const int n = numeric ? std::stoi(digits) : 0;
        if (n < 1 || n > 65535)
            throw Error("bad scene name '" + name + "': use " + prefix + "N with N lights, 1..65535 (e.g. " + prefix +
                        "255)");
        scene = makeOccludedScene(kind, n, 1024, 768, seed);
        return true;
    }
    return false;
}

const char* occludedSceneName(OccludedSceneKind kind) { return kind == OccludedSceneKind::Hall ? "hall" : "city"; }

Scene makeOccludedScene(OccludedSceneKind kind, int lightCount, int width, int height, uint32_t seed) {
    if (lightCount < 1 || lightCount > 65535)
        throw Error(std::string(occludedSceneName(kind)) + " scene: light count must be in [1, 65535], got " +
                    std::to_string(lightCount));
    Scene scene;
    scene.name = std::string(occludedSceneName(kind)) + "-" + std::to_string(lightCount);
    scene.width = width;
    scene.height = height;
    scene.materials = {occluderMaterial("floor", {0.55f, 0.5f, 0.45f}, 0.2f, 24.0f),
                       occluderMaterial("wall", {0.7f, 0.66f, 0.6f}, 0.1f, 16.0f),
                       occluderMaterial("pillar", {0.6f, 0.6f, 0.62f}, 0.35f, 48.0f),
                       occluderMaterial("arch", {0.65f, 0.5f, 0.4f}, 0.15f, 24.0f)};
    Scene parts;
    parts.materials = scene.materials;
    SceneRandom random((uint64_t(seed) << 32) ^ (kind == OccludedSceneKind::Hall ? 0x4841u : 0x4349u));
    glm::vec3 lo, hi;
    if (kind == OccludedSceneKind::Hall) {
        buildHall(scene, parts);
        lo = {-11.5f, 0.3f, -39.5f};
        hi = {11.5f, 9.0f, 29.5f};
        scene.camera.position = {0.0f, 1.7f, 28.0f};
        scene.camera.target = {0.0f, 2.5f, -40.0f};
        scene.camera.fovYDegrees = 70.0f;
        scene.camera.farPlane = 120.0f;
    } else {
        buildCity(scene, parts, random);
        lo = {-72.0f, 0.3f, -72.0f};
        hi = {72.0f, 8.0f, 72.0f};
        // In the street between the 4th and 5th block columns, looking down it.
        scene.camera.position = {0.0f, 1.7f, 70.0f};
        scene.camera.target = {0.0f, 3.0f, -72.0f};
        scene.camera.fovYDegrees = 70.0f;
        scene.camera.farPlane = 200.0f;
    }
    scene.camera.nearPlane = 0.1f;
    mergeByMaterial(scene, std::move(parts.meshes));
    for (int i = 0; i < lightCount; ++i) {
        PointLight light;
        light.position = {random.uniform(lo.x, hi.x), random.uniform(lo.y, hi.y), random.uniform(lo.z, hi.z)};
        light.radius = random.uniform(1.0f, 4.0f);
        const float hue = random.uniform();
        const glm::vec3 offsets(0.0f, 4.0f, 2.0f);
        const glm::vec3 pure =
            glm::clamp(glm::abs(glm::mod(hue * 6.0f + offsets, 6.0f) - 3.0f) - 1.0f, 0.0f, 1.0f);
        light.color = glm::mix(glm::vec3(1.0f), pure, 0.6f);
        scene.lights.push_back(light);
    }
    scene.validate();
    return scene;
}

bool makeSpotSceneByName(const std::string& name, Scene& scene, uint32_t seed) {
    if (name.compare(0, 6, "spots-") != 0) return false;
    std::string digits = name.substr(6);
    const bool points = digits.size() > 7 && digits.compare(digits.size() - 7, 7, "-points") == 0;
    if (points) digits.resize(digits.size() - 7);
    const bool numeric = !digits.empty() && digits.size() <= 5 &&
                         std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
    const int n = numeric ? std::stoi(digits) : 0;
    if (n < 4 || n > 65535)
        throw Error("bad scene name '" + name + "': use spots-N or spots-N-points with N lights, 4..65535 (e.g. spots-1024)");
    scene = makeManyLightScene(n, ManyLightView::TopDown, 1024, 768, seed);
    scene.name = name;
    for (size_t i = 3; i < scene.lights.size(); ++i) {  // the particles; the 3 large movers stay points
        PointLight& l = scene.lights[i];
        l.direction = {0.0f, -1.0f, 0.0f};
        l.outerConeAngle = points ? 0.0f : glm::radians(kBenchSpotOuterDegrees);
        l.innerConeAngle = points ? 0.0f : glm::radians(kBenchSpotInnerDegrees);
    }
    return true;
}

}  // namespace lidr
