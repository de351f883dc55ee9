#include "lidr/scene/primitives.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/constants.hpp>

#include "lidr/base/error.h"

namespace lidr {

namespace {

struct Vertex {
    glm::vec3 position, normal;
};

void requireAtLeast(const char* function, const char* parameter, int value, int minimum) {
    if (value < minimum)
        throw Error(std::string(function) + ": " + parameter + " must be >= " + std::to_string(minimum) + ", got " +
                    std::to_string(value));
}

// Checked before any vertex is made, so an oversized request fails at once instead of after the allocation.
void requireAtMost(const char* function, const char* parameter, int value, int maximum) {
    if (value > maximum)
        throw Error(std::string(function) + ": " + parameter + " " + std::to_string(value) + " is above the limit of " +
                    std::to_string(maximum));
}

void requirePositive(const char* function, const char* parameter, float value) {
    if (!std::isfinite(value) || value <= 0.0f)
        throw Error(std::string(function) + ": " + parameter + " must be finite and > 0, got " + std::to_string(value));
}

Mesh& newMesh(Scene& scene, const char* name, int material) {
    scene.meshes.emplace_back();
    Mesh& mesh = scene.meshes.back();
    mesh.name = name;
    mesh.material = material;
    return mesh;
}

uint32_t addVertex(Mesh& mesh, const Vertex& vertex, const glm::vec2& texCoord) {
    mesh.positions.push_back(vertex.position);
    mesh.normals.push_back(vertex.normal);
    mesh.texCoords.push_back(texCoord);
    return uint32_t(mesh.positions.size() - 1);
}

// A (uSteps + 1) x (vSteps + 1) vertex grid over a surface f(u, v), u and v in [0, 1]. The surface must be
// oriented so that d/du x d/dv points outwards: the triangles are then counter-clockwise seen from outside.
// A row that collapses to a point (a sphere's pole) gets one triangle per quad instead of two.
template <class Surface>
void addGrid(Mesh& mesh, int uSteps, int vSteps, Surface surface, bool collapsedFirstRow = false,
             bool collapsedLastRow = false) {
    const uint32_t first = uint32_t(mesh.positions.size());
    for (int j = 0; j <= vSteps; ++j)
        for (int i = 0; i <= uSteps; ++i) {
            const glm::vec2 uv(float(i) / float(uSteps), float(j) / float(vSteps));
            addVertex(mesh, surface(uv.x, uv.y), uv);
        }
    const auto index = [&](int i, int j) { return first + uint32_t(j * (uSteps + 1) + i); };
    for (int j = 0; j < vSteps; ++j)
        for (int i = 0; i < uSteps; ++i) {
            const uint32_t a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
            if (!(collapsedFirstRow && j == 0)) mesh.indices.insert(mesh.indices.end(), {a, b, c});
            if (!(collapsedLastRow && j == vSteps - 1)) mesh.indices.insert(mesh.indices.end(), {a, c, d});
        }
}

// A flat parallelogram origin + u * uEdge + v * vEdge; its normal is uEdge x vEdge.
void addQuadGrid(Mesh& mesh, const glm::vec3& origin, const glm::vec3& uEdge, const glm::vec3& vEdge,
                 int subdivisions) {
    const glm::vec3 normal = glm::normalize(glm::cross(uEdge, vEdge));
    addGrid(mesh, subdivisions, subdivisions,
            [&](float u, float v) { return Vertex{origin + u * uEdge + v * vEdge, normal}; });
}

// cos and sin of `turns` full turns, exact at 0 and 1: a closed surface's seam (u = 0 and u = 1) and a sphere's
// poles then meet at exactly the same positions, so the mesh is watertight where its vertices are split
// (closedMeshOuterWinding welds only equal positions).
glm::vec2 cosSinTurns(float turns) {
    if (turns == 0.0f || turns == 1.0f) return {1.0f, 0.0f};
    const float angle = glm::two_pi<float>() * turns;
    return {std::cos(angle), std::sin(angle)};
}

// Horizontal direction `turns` of the way round, counter-clockwise seen from +y: with v pointing up, d/du x d/dv
// then points away from the y axis.
glm::vec3 around(float turns) {
    const glm::vec2 cs = cosSinTurns(turns);
    return {cs.x, 0.0f, -cs.y};
}

// A flat disc cap at height y, facing up or down, as a fan around its centre.
void addCap(Mesh& mesh, const glm::vec3& center, float radius, int segments, bool facingUp) {
    const glm::vec3 normal(0.0f, facingUp ? 1.0f : -1.0f, 0.0f);
    const uint32_t middle = addVertex(mesh, {center, normal}, glm::vec2(0.5f));
    const uint32_t ring = uint32_t(mesh.positions.size());
    for (int i = 0; i <= segments; ++i) {
        const glm::vec3 direction = around(float(i) / float(segments));  // as the side's grid has it
        addVertex(mesh, {center + radius * direction, normal}, 0.5f + 0.5f * glm::vec2(direction.x, -direction.z));
    }
    for (uint32_t i = 0; i < uint32_t(segments); ++i) {
        if (facingUp)
            mesh.indices.insert(mesh.indices.end(), {middle, ring + i, ring + i + 1});
        else
            mesh.indices.insert(mesh.indices.end(), {middle, ring + i + 1, ring + i});
    }
}

}  // namespace

void addBox(Scene& scene, const glm::vec3& min, const glm::vec3& max, int material, int subdivisions) {
    requireAtLeast("addBox", "subdivisions", subdivisions, 1);
    requireAtMost("addBox", "subdivisions", subdivisions, maxPrimitiveSubdivisions);
    const glm::vec3 size = max - min;
    requirePositive("addBox", "size x", size.x);
    requirePositive("addBox", "size y", size.y);
    requirePositive("addBox", "size z", size.z);
    Mesh& mesh = newMesh(scene, "box", material);
    const glm::vec3 dx(size.x, 0, 0), dy(0, size.y, 0), dz(0, 0, size.z);
    addQuadGrid(mesh, {max.x, min.y, max.z}, -dz, dy, subdivisions);  // +x
    addQuadGrid(mesh, min, dz, dy, subdivisions);                      // -x
    addQuadGrid(mesh, {min.x, max.y, max.z}, dx, -dz, subdivisions);  // +y
    addQuadGrid(mesh, min, dx, dz, subdivisions);                      // -y
    addQuadGrid(mesh, {min.x, min.y, max.z}, dx, dy, subdivisions);   // +z
    addQuadGrid(mesh, {max.x, min.y, min.z}, -dx, dy, subdivisions);  // -z
}

void addPlane(Scene& scene, const glm::vec3& center, const glm::vec2& size, int material, int subdivisions) {
    requireAtLeast("addPlane", "subdivisions", subdivisions, 1);
    requireAtMost("addPlane", "subdivisions", subdivisions, maxPrimitiveSubdivisions);
    requirePositive("addPlane", "size x", size.x);
    requirePositive("addPlane", "size z", size.y);
    Mesh& mesh = newMesh(scene, "plane", material);
    addQuadGrid(mesh, center + glm::vec3(-0.5f * size.x, 0.0f, 0.5f * size.y), {size.x, 0, 0}, {0, 0, -size.y},
                subdivisions);
}

void addSphere(Scene& scene, const glm::vec3& center, float radius, int material, int segments) {
    requireAtLeast("addSphere", "segments", segments, 3);
    requireAtMost("addSphere", "segments", segments, maxPrimitiveSegments);
    requirePositive("addSphere", "radius", radius);
    Mesh& mesh = newMesh(scene, "sphere", material);
    const int rings = std::max(2, segments / 2);
    // v runs from the south pole (v = 0) to the north pole (v = 1).
    addGrid(
        mesh, segments, rings,
        [&](float u, float v) {
            // Half a turn from pole to pole; at the poles exactly (0, -1, 0) and (0, 1, 0) whatever u is.
            const glm::vec2 cs = cosSinTurns(0.5f * v - 0.25f);
            const glm::vec3 normal = v == 0.0f || v == 1.0f ? glm::vec3(0.0f, v == 0.0f ? -1.0f : 1.0f, 0.0f)
                                                            : cs.x * around(u) + glm::vec3(0, cs.y, 0);
            return Vertex{center + radius * normal, normal};
        },
        true, true);
}

void addCylinder(Scene& scene, const glm::vec3& base, float radius, float height, int material, int segments) {
    requireAtLeast("addCylinder", "segments", segments, 3);
    requireAtMost("addCylinder", "segments", segments, maxPrimitiveSegments);
    requirePositive("addCylinder", "radius", radius);
    requirePositive("addCylinder", "height", height);
    Mesh& mesh = newMesh(scene, "cylinder", material);
    addGrid(mesh, segments, 1, [&](float u, float v) {
        const glm::vec3 normal = around(u);
        // In the caps' order (their centre, then the rim), so the rims meet exactly.
        return Vertex{base + glm::vec3(0, v * height, 0) + radius * normal, normal};
    });
    addCap(mesh, base + glm::vec3(0, height, 0), radius, segments, true);
    addCap(mesh, base, radius, segments, false);
}

void addTorus(Scene& scene, const glm::vec3& center, float majorRadius, float minorRadius, int material,
              int majorSegments, int minorSegments) {
    requireAtLeast("addTorus", "majorSegments", majorSegments, 3);
    requireAtMost("addTorus", "majorSegments", majorSegments, maxPrimitiveSegments);
    requireAtLeast("addTorus", "minorSegments", minorSegments, 3);
    requireAtMost("addTorus", "minorSegments", minorSegments, maxPrimitiveSegments);
    requirePositive("addTorus", "majorRadius", majorRadius);
    requirePositive("addTorus", "minorRadius", minorRadius);
    Mesh& mesh = newMesh(scene, "torus", material);
    // v goes round the tube from the outer equator over the top; with u going round the y axis this keeps
    // d/du x d/dv pointing out of the tube.
    addGrid(mesh, majorSegments, minorSegments, [&](float u, float v) {
        const glm::vec3 outward = around(u);
        const glm::vec2 tube = cosSinTurns(v);
        const glm::vec3 normal = tube.x * outward + glm::vec3(0, tube.y, 0);
        return Vertex{center + majorRadius * outward + minorRadius * normal, normal};
    });
}

}  // namespace lidr
