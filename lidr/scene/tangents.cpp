#include "lidr/scene/tangents.h"

#include <cmath>

namespace lidr {

namespace {
glm::vec3 anyPerpendicular(const glm::vec3& n) {
    const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::vec3 t = glm::cross(axis, n);
    const float length = glm::length(t);
    return length > 0.0f ? t / length : glm::vec3(1.0f, 0.0f, 0.0f);
}
}  // namespace

std::vector<glm::vec4> generateTangents(const Mesh& mesh, int texCoordSet) {
    const std::vector<glm::vec2>& uv = texCoordSet == 1 && !mesh.texCoords1.empty() ? mesh.texCoords1 : mesh.texCoords;
    std::vector<glm::dvec3> tangentSum(mesh.positions.size(), glm::dvec3(0.0)), bitangentSum(tangentSum);
    if (!uv.empty())
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const uint32_t i[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
            const glm::dvec3 e1 = glm::dvec3(mesh.positions[i[1]] - mesh.positions[i[0]]);
            const glm::dvec3 e2 = glm::dvec3(mesh.positions[i[2]] - mesh.positions[i[0]]);
            const glm::dvec2 d1 = glm::dvec2(uv[i[1]] - uv[i[0]]), d2 = glm::dvec2(uv[i[2]] - uv[i[0]]);
            const double det = d1.x * d2.y - d2.x * d1.y;
            if (!(std::abs(det) > 1e-20)) continue;  // no UV area: no direction to give
            // dP/du and dP/dv of the triangle's plane, each weighted by the triangle's area (large triangles
            // decide more of a shared vertex's frame).
            const glm::dvec3 dpdu = (e1 * d2.y - e2 * d1.y) / det, dpdv = (e2 * d1.x - e1 * d2.x) / det;
            const double area = 0.5 * glm::length(glm::cross(e1, e2));
            const double lu = glm::length(dpdu), lv = glm::length(dpdv);
            if (!(lu > 0.0 && lv > 0.0 && std::isfinite(lu) && std::isfinite(lv))) continue;
            for (uint32_t v : i) {
                tangentSum[v] += dpdu / lu * area;
                bitangentSum[v] += dpdv / lv * area;
            }
        }
    std::vector<glm::vec4> tangents(mesh.positions.size());
    for (size_t v = 0; v < tangents.size(); ++v) {
        const glm::dvec3 n = glm::dvec3(mesh.normals[v]);
        glm::dvec3 t = tangentSum[v] - n * glm::dot(n, tangentSum[v]);  // Gram-Schmidt against the normal
        const double length = glm::length(t);
        if (!(length > 1e-12)) {
            tangents[v] = glm::vec4(anyPerpendicular(mesh.normals[v]), 1.0f);
            continue;
        }
        t /= length;
        const float w = glm::dot(glm::cross(n, t), bitangentSum[v]) < 0.0 ? -1.0f : 1.0f;
        tangents[v] = glm::vec4(glm::vec3(t), w);
    }
    return tangents;
}

}  // namespace lidr
