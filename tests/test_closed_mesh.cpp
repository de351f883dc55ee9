// closedMeshOuterWinding (lidr/scene/closed_mesh.h): which meshes GpuScene may draw with their inner side culled.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "lidr/scene/closed_mesh.h"
#include "lidr/scene/primitives.h"

using namespace lidr;

namespace {
// One mesh made by a primitive, then changed by `edit`.
Mesh made(const std::function<void(Scene&)>& build, const std::function<void(Mesh&)>& edit = {}) {
    Scene s;
    build(s);
    Mesh m = s.meshes.at(0);
    for (size_t i = 1; i < s.meshes.size(); ++i) {  // several primitives: one mesh
        const auto base = uint32_t(m.positions.size());
        m.positions.insert(m.positions.end(), s.meshes[i].positions.begin(), s.meshes[i].positions.end());
        for (uint32_t index : s.meshes[i].indices) m.indices.push_back(base + index);
    }
    if (edit) edit(m);
    return m;
}
void reverseTriangle(Mesh& m, size_t t) { std::swap(m.indices[3 * t + 1], m.indices[3 * t + 2]); }
void reverseAll(Mesh& m) {
    for (size_t t = 0; t < m.triangleCount(); ++t) reverseTriangle(m, t);
}
const char* name(OuterWinding w) {
    return w == OuterWinding::Open ? "open" : w == OuterWinding::CounterClockwise ? "counter-clockwise" : "clockwise";
}
}  // namespace

TEST_CASE("closed meshes: the side seen from outside, or open where both sides may be seen", "[cpu][scene]") {
    const glm::vec3 lo(-1.0f, 0.0f, -1.0f), hi(1.0f, 2.0f, 0.5f);
    auto box = [&](int subdivisions) { return [=](Scene& s) { addBox(s, lo, hi, 0, subdivisions); }; };
    struct Case {
        const char* what;
        Mesh mesh;
        OuterWinding expected;
    };
    const Case cases[] = {
        {"box", made(box(1)), OuterWinding::CounterClockwise},
        {"box, 4 subdivisions (vertices split at every edge)", made(box(4)), OuterWinding::CounterClockwise},
        {"sphere", made([](Scene& s) { addSphere(s, glm::vec3(1.0f, 2.0f, 3.0f), 1.5f, 0, 24); }),
         OuterWinding::CounterClockwise},
        {"torus", made([](Scene& s) { addTorus(s, glm::vec3(0.0f), 2.0f, 0.5f, 0); }), OuterWinding::CounterClockwise},
        {"cylinder with its caps", made([](Scene& s) { addCylinder(s, glm::vec3(1.0f, 0.5f, -2.0f), 0.3f, 4.0f, 0, 24); }),
         OuterWinding::CounterClockwise},
        {"sphere, 3 segments", made([](Scene& s) { addSphere(s, glm::vec3(0.0f), 1.0f, 0, 3); }),
         OuterWinding::CounterClockwise},
        {"two boxes in one mesh", made([&](Scene& s) { addBox(s, lo, hi, 0); addBox(s, hi + 1.0f, hi + 2.0f, 0); }),
         OuterWinding::CounterClockwise},
        {"box wound inside out", made(box(1), reverseAll), OuterWinding::Clockwise},
        {"plane", made([](Scene& s) { addPlane(s, glm::vec3(0.0f), glm::vec2(4.0f), 0, 3); }), OuterWinding::Open},
        {"box with one triangle turned over", made(box(1), [](Mesh& m) { reverseTriangle(m, 5); }), OuterWinding::Open},
        {"box without its last face", made(box(1), [](Mesh& m) { m.indices.resize(m.indices.size() - 6); }),
         OuterWinding::Open},
        {"a box and a box inside out in one mesh",
         made([&](Scene& s) { addBox(s, lo, hi, 0); addBox(s, hi + 1.0f, hi + 2.0f, 0); },
              [](Mesh& m) { for (size_t t = m.triangleCount() / 2; t < m.triangleCount(); ++t) reverseTriangle(m, t); }),
         OuterWinding::Open},
        {"a plane and its copy wound the other way (encloses nothing)",
         made([](Scene& s) { addPlane(s, glm::vec3(0.0f), glm::vec2(4.0f), 0, 2); },
              [](Mesh& m) {
                  const size_t n = m.indices.size();
                  for (size_t i = 0; i < n; i += 3)
                      m.indices.insert(m.indices.end(), {m.indices[i], m.indices[i + 2], m.indices[i + 1]});
              }),
         OuterWinding::Open},
        {"box with a position not finite",
         made(box(1), [](Mesh& m) { m.positions[0].x = std::numeric_limits<float>::quiet_NaN(); }), OuterWinding::Open},
        {"box with an index past its vertices", made(box(1), [](Mesh& m) { m.indices[0] = uint32_t(m.positions.size()); }),
         OuterWinding::Open},
        {"no triangles", made(box(1), [](Mesh& m) { m.indices.clear(); }), OuterWinding::Open},
    };
    for (const Case& c : cases) {
        DYNAMIC_SECTION(c.what) {
            const OuterWinding got = closedMeshOuterWinding(c.mesh.positions, c.mesh.indices);
            INFO("got " << name(got) << ", expected " << name(c.expected));
            CHECK(got == c.expected);
        }
    }
}
