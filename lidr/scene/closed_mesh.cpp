#include "lidr/scene/closed_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

namespace lidr {

namespace {
// Vertices at exactly the same position (bit for bit) are one corner: meshes split vertices at hard edges and
// seams. (-0.0 and 0.0 differ: a mesh that mixes them at a corner counts as open, which only costs the culling.)
// An open-addressing table keeps this fast on millions of vertices.
std::vector<uint32_t> cornersOf(const std::vector<glm::vec3>& positions, uint32_t& count) {
    size_t size = 16;
    while (size < positions.size() * 2) size *= 2;
    std::vector<uint32_t> slot(size, UINT32_MAX);  // vertex index holding the slot's position
    std::vector<uint32_t> corner(positions.size());
    count = 0;
    for (uint32_t i = 0; i < positions.size(); ++i) {
        uint32_t bits[3];
        std::memcpy(bits, &positions[i], sizeof bits);
        const uint64_t h =
            (bits[0] * 0x9E3779B97F4A7C15ull) ^ (bits[1] * 0xC2B2AE3D27D4EB4Full) ^ (bits[2] * 0x165667B19E3779F9ull);
        size_t at = size_t(h ^ (h >> 29)) & (size - 1);
        while (slot[at] != UINT32_MAX && std::memcmp(&positions[slot[at]], &positions[i], sizeof(glm::vec3)) != 0)
            at = (at + 1) & (size - 1);
        if (slot[at] == UINT32_MAX) {
            slot[at] = i;
            corner[i] = count++;
        } else {
            corner[i] = corner[slot[at]];
        }
    }
    return corner;
}

}  // namespace

OuterWinding closedMeshOuterWinding(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices) {
    if (indices.size() < 12 || indices.size() % 3 != 0) return OuterWinding::Open;  // a closed mesh has 4+ triangles
    for (const glm::vec3& p : positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return OuterWinding::Open;
    uint32_t corners = 0;
    const std::vector<uint32_t> corner = cornersOf(positions, corners);
    // The directed edges a -> b of the triangles with area, grouped by a (counted, then placed). Closed and
    // consistently wound exactly when no edge is run twice the same way and each is run once the other way.
    std::vector<uint32_t> start(size_t(corners) + 1, 0);
    for (size_t t = 0; t < indices.size(); t += 3) {
        uint32_t v[3];
        for (int k = 0; k < 3; ++k) {
            if (indices[t + size_t(k)] >= positions.size()) return OuterWinding::Open;
            v[k] = corner[indices[t + size_t(k)]];
        }
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;  // no area
        for (int k = 0; k < 3; ++k) ++start[v[k] + 1];
    }
    for (size_t c = 0; c < corners; ++c) start[c + 1] += start[c];
    if (start[corners] == 0) return OuterWinding::Open;
    std::vector<uint32_t> to(start[corners]), filled(start.begin(), start.end() - 1);
    for (size_t t = 0; t < indices.size(); t += 3) {
        const uint32_t v[3] = {corner[indices[t]], corner[indices[t + 1]], corner[indices[t + 2]]};
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;
        for (int k = 0; k < 3; ++k) to[filled[v[k]]++] = v[(k + 1) % 3];
    }
    for (size_t c = 0; c < corners; ++c) {
        std::sort(to.begin() + start[c], to.begin() + start[c + 1]);
        if (std::adjacent_find(to.begin() + start[c], to.begin() + start[c + 1]) != to.begin() + start[c + 1])
            return OuterWinding::Open;  // an edge run twice the same way (shared by more than two triangles)
    }
    for (uint32_t a = 0; a < corners; ++a)
        for (uint32_t e = start[a]; e < start[a + 1]; ++e) {
            const uint32_t b = to[e];
            if (!std::binary_search(to.begin() + start[b], to.begin() + start[b + 1], a)) return OuterWinding::Open;
        }
    // Connected parts (corners joined by edges) may be wound differently: each part's volume is summed apart.
    std::vector<uint32_t> parent(corners);
    std::iota(parent.begin(), parent.end(), 0u);
    auto root = [&](uint32_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    for (uint32_t a = 0; a < corners; ++a)
        for (uint32_t e = start[a]; e < start[a + 1]; ++e) parent[root(a)] = root(to[e]);
    // Six times each part's signed volume: positive where its triangles wind counter-clockwise seen from outside.
    std::vector<double> volume(parent.size(), 0.0);
    std::vector<uint8_t> used(parent.size(), 0);
    glm::dvec3 lo(positions[indices[0]]), hi = lo;
    for (size_t t = 0; t < indices.size(); t += 3) {
        const uint32_t a = corner[indices[t]], b = corner[indices[t + 1]], c = corner[indices[t + 2]];
        if (a == b || b == c || c == a) continue;
        const glm::dvec3 pa(positions[indices[t]]), pb(positions[indices[t + 1]]), pc(positions[indices[t + 2]]);
        const uint32_t part = root(a);
        volume[part] += glm::dot(pa, glm::cross(pb, pc));
        used[part] = 1;
        lo = glm::min(lo, glm::min(pa, glm::min(pb, pc)));
        hi = glm::max(hi, glm::max(pa, glm::max(pb, pc)));
    }
    // A part that encloses nothing (a surface and its copy wound the other way) has no outside to speak of.
    const glm::dvec3 size = hi - lo;
    const double extent = std::max(size.x, std::max(size.y, size.z));
    const double least = 1e-9 * 6.0 * extent * extent * extent;  // far above rounding, far below any real solid
    int sign = 0;
    for (size_t part = 0; part < volume.size(); ++part) {
        if (!used[part]) continue;
        if (!(std::abs(volume[part]) > least)) return OuterWinding::Open;
        const int s = volume[part] > 0.0 ? 1 : -1;
        if (sign != 0 && s != sign) return OuterWinding::Open;  // parts wound both ways: no one side to cull
        sign = s;
    }
    return sign > 0 ? OuterWinding::CounterClockwise : OuterWinding::Clockwise;
}

}  // namespace lidr
