#include "lidr/scene/io/mesh_split.h"

#include <algorithm>
#include <numeric>

namespace lidr {

namespace {

// Splits triangles [first, last) of `order` until each range holds at most maxTriangles.
void splitRange(const std::vector<glm::vec3>& centroids, std::vector<uint32_t>& order, size_t first, size_t last,
                size_t maxTriangles, std::vector<std::pair<size_t, size_t>>& ranges) {
    if (last - first <= maxTriangles) {
        ranges.emplace_back(first, last);
        return;
    }
    glm::vec3 lo(centroids[order[first]]), hi(lo);
    for (size_t i = first; i < last; ++i) lo = glm::min(lo, centroids[order[i]]), hi = glm::max(hi, centroids[order[i]]);
    const glm::vec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const size_t middle = first + (last - first) / 2;
    // Ties broken by triangle number, so the split does not depend on the sort's implementation.
    std::nth_element(order.begin() + long(first), order.begin() + long(middle), order.begin() + long(last),
                     [&](uint32_t a, uint32_t b) {
                         return centroids[a][axis] < centroids[b][axis] ||
                                (centroids[a][axis] == centroids[b][axis] && a < b);
                     });
    splitRange(centroids, order, first, middle, maxTriangles, ranges);
    splitRange(centroids, order, middle, last, maxTriangles, ranges);
}

}  // namespace

std::vector<Mesh> splitMeshSpatially(Mesh mesh, size_t maxTriangles) {
    const size_t triangles = mesh.triangleCount();
    if (triangles <= maxTriangles || maxTriangles == 0) return {std::move(mesh)};
    std::vector<glm::vec3> centroids(triangles);
    for (size_t t = 0; t < triangles; ++t)
        centroids[t] = (mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
                        mesh.positions[mesh.indices[3 * t + 2]]) / 3.0f;
    std::vector<uint32_t> order(triangles);
    std::iota(order.begin(), order.end(), 0u);
    std::vector<std::pair<size_t, size_t>> ranges;
    splitRange(centroids, order, 0, triangles, maxTriangles, ranges);
    std::vector<Mesh> parts;
    std::vector<uint32_t> newIndex(mesh.positions.size(), ~0u);
    for (const auto& [first, last] : ranges) {
        Mesh part;
        part.name = mesh.name + "#" + std::to_string(parts.size());
        part.material = mesh.material;
        std::sort(order.begin() + long(first), order.begin() + long(last));  // the file's triangle order
        for (size_t i = first; i < last; ++i)
            for (int k = 0; k < 3; ++k) {
                const uint32_t source = mesh.indices[3 * size_t(order[i]) + size_t(k)];
                if (newIndex[source] == ~0u) {
                    newIndex[source] = uint32_t(part.positions.size());
                    part.positions.push_back(mesh.positions[source]);
                    part.normals.push_back(mesh.normals[source]);
                    if (!mesh.texCoords.empty()) part.texCoords.push_back(mesh.texCoords[source]);
                    if (!mesh.texCoords1.empty()) part.texCoords1.push_back(mesh.texCoords1[source]);
                    if (!mesh.tangents.empty()) part.tangents.push_back(mesh.tangents[source]);
                }
                part.indices.push_back(newIndex[source]);
            }
        for (size_t i = first; i < last; ++i)
            for (int k = 0; k < 3; ++k) newIndex[mesh.indices[3 * size_t(order[i]) + size_t(k)]] = ~0u;
        parts.push_back(std::move(part));
    }
    return parts;
}

}  // namespace lidr
