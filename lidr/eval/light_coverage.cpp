#include "lidr/eval/light_coverage.h"

#include <algorithm>
#include <cmath>

#include "lidr/base/error.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr {

int CoverageTruth::maxOverlap() const {
    int best = 0;
    for (size_t p = 0; p + 1 < offsets.size(); ++p) best = std::max(best, count(p));
    return best;
}

namespace {
// Conservative pixel rectangle of a sphere: projected corners of its bounding box; the whole screen when
// the box reaches behind the eye.
void screenRect(const CameraMatrices& m, const PointLight& l, int& x0, int& y0, int& x1, int& y1) {
    x0 = 0, y0 = 0, x1 = m.width - 1, y1 = m.height - 1;
    float minX = 1e30f, minY = 1e30f, maxX = -1e30f, maxY = -1e30f;
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner = l.position + l.radius * glm::vec3(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1);
        const glm::vec4 clip = m.viewProjection * glm::vec4(corner, 1.0f);
        if (!(clip.w > 1e-6f)) return;  // behind the eye, or not a number: the whole screen
        const float sx = (clip.x / clip.w * 0.5f + 0.5f) * m.width;
        const float sy = (0.5f - clip.y / clip.w * 0.5f) * m.height;  // rows top to bottom
        if (!std::isfinite(sx) || !std::isfinite(sy)) return;  // overflowed: the whole screen (conservative)
        minX = std::min(minX, sx), maxX = std::max(maxX, sx);
        minY = std::min(minY, sy), maxY = std::max(maxY, sy);
    }
    // Clamped in float before converting (a huge coordinate would overflow an int); an off-screen box stays
    // off screen and gives an empty rectangle (x0 > x1 or y0 > y1).
    x0 = clampToInt(std::floor(minX) - 1.0f, 0, m.width, 0);
    y0 = clampToInt(std::floor(minY) - 1.0f, 0, m.height, 0);
    x1 = clampToInt(std::ceil(maxX) + 1.0f, -1, m.width - 1, m.width - 1);
    y1 = clampToInt(std::ceil(maxY) + 1.0f, -1, m.height - 1, m.height - 1);
}
// The surface point of pixel (x, y) at window depth d, in double through the exact inverse of the float
// projection the GPU drew with: distance = P32 / (2d - 1 + P22), x and y along the pixel's ray. Not through the
// float inverse view-projection, whose rounding dominates where far/near is huge (1e5 and up), so the truth is
// the stored depth's surface, as exactly as doubles give it.
glm::vec3 surfacePoint(const CameraMatrices& m, const glm::dmat4& inverseView, int x, int y, float depth) {
    const glm::dmat4 P(m.projection);
    const bool perspective = P[2][3] == -1.0 && P[3][3] == 0.0 && P[2][0] == 0.0 && P[2][1] == 0.0;
    if (!perspective) return unprojectPixel(m, x, y, depth);
    const double distance = P[3][2] / (2.0 * double(depth) - 1.0 + P[2][2]);
    const double xn = (x + 0.5) / m.width * 2.0 - 1.0, yn = 1.0 - (y + 0.5) / m.height * 2.0;
    const glm::dvec4 view(xn * distance / P[0][0], yn * distance / P[1][1], -distance, 1.0);
    return glm::vec3(inverseView * view);
}


// The truth's compressed rows from (pixel, light) pairs.
void fillLists(CoverageTruth& t, std::vector<std::pair<uint32_t, uint32_t>>& pairs) {
    const size_t n = size_t(t.width) * t.height;
    std::sort(pairs.begin(), pairs.end());
    t.offsets.assign(n + 1, 0);
    for (const auto& pr : pairs) ++t.offsets[pr.first + 1];
    for (size_t p = 0; p < n; ++p) t.offsets[p + 1] += t.offsets[p];
    t.lights.reserve(pairs.size());
    for (const auto& pr : pairs) t.lights.push_back(pr.second);
}

}  // namespace

namespace {
// Whether a point `d` from a spot light's apex lies inside its cone by more than `band` of the shader's ramp. At the
// apex itself the shader's direction is 0, its ramp the offset (below 0: no light).
bool insideSpotCone(const glm::vec3& d, const glm::dvec4& cone, float band) {
    const glm::dvec3 fromLight(d);
    const double length = glm::length(fromLight);
    const double ramp = (length > 0.0 ? glm::dot(fromLight / length, glm::dvec3(cone)) : 0.0) + cone.w;
    return ramp > double(band);
}
}  // namespace

CoverageTruth computeCoverage(const ImageFloat& depth, const CameraMatrices& camera,
                              const std::vector<PointLight>& lights, float band) {
    if (depth.width != camera.width || depth.height != camera.height)
        throw Error("computeCoverage: depth image and camera sizes differ");
    CoverageTruth t;
    t.width = depth.width;
    t.height = depth.height;
    const size_t n = size_t(t.width) * t.height;
    t.surface.assign(n, 0);
    std::vector<glm::vec3> world(n);
    const glm::dmat4 inverseView = glm::inverse(glm::dmat4(camera.view));
    for (int y = 0; y < t.height; ++y)
        for (int x = 0; x < t.width; ++x) {
            const size_t p = size_t(y) * t.width + x;
            const float d = depth.at(x, y);
            if (d >= 1.0f) continue;
            t.surface[p] = 1;
            world[p] = surfacePoint(camera, inverseView, x, y, d);
        }
    std::vector<std::pair<uint32_t, uint32_t>> pairs;  // (pixel, light)
    for (size_t i = 0; i < lights.size(); ++i) {
        const PointLight& l = lights[i];
        const float inner = l.radius * (1.0f - band);
        const float inner2 = inner * inner;
        // A spot light also needs the point inside its cone: its cone term's ramp (lidr::spotCone, 0 at the
        // outer cone, 1 at the inner) above `band` too, in double, as the CPU model (eval/brdf.h) computes it.
        const glm::dvec4 cone(spotCone(l));
        int x0, y0, x1, y1;
        screenRect(camera, l, x0, y0, x1, y1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const size_t p = size_t(y) * t.width + x;
                if (!t.surface[p]) continue;
                const glm::vec3 d = world[p] - l.position;
                if (!(glm::dot(d, d) < inner2)) continue;
                if (l.isSpot() && !insideSpotCone(d, cone, band)) continue;
                pairs.emplace_back(uint32_t(p), uint32_t(i + 1));
            }
    }
    fillLists(t, pairs);
    return t;
}

CoverageTruth computeSpanCoverage(const std::vector<ImageFloat>& surfaceDepths, const CameraMatrices& camera,
                                  const std::vector<PointLight>& lights, float band) {
    for (const ImageFloat& depth : surfaceDepths)
        if (depth.width != camera.width || depth.height != camera.height)
            throw Error("computeSpanCoverage: depth images and camera sizes differ");
    CoverageTruth t;
    t.width = camera.width;
    t.height = camera.height;
    const size_t n = size_t(t.width) * t.height;
    t.surface.assign(n, 0);
    // Per pixel, the points its samples shade (a window depth of 1 or more: none).
    std::vector<std::vector<glm::vec3>> points(n);
    const glm::dmat4 inverseView = glm::inverse(glm::dmat4(camera.view));
    for (int y = 0; y < t.height; ++y)
        for (int x = 0; x < t.width; ++x) {
            const size_t p = size_t(y) * t.width + x;
            for (const ImageFloat& depth : surfaceDepths) {
                const float d = depth.at(x, y);
                if (!(d < 1.0f)) continue;
                t.surface[p] = 1;
                points[p].push_back(surfacePoint(camera, inverseView, x, y, std::max(d, 0.0f)));
            }
        }
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (size_t i = 0; i < lights.size(); ++i) {
        const PointLight& l = lights[i];
        const float inner = l.radius * (1.0f - band);
        const glm::dvec4 cone(spotCone(l));
        int x0, y0, x1, y1;
        screenRect(camera, l, x0, y0, x1, y1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const size_t p = size_t(y) * t.width + x;
                for (const glm::vec3& point : points[p]) {
                    const glm::vec3 d = point - l.position;
                    if (!(glm::dot(d, d) < inner * inner)) continue;
                    if (l.isSpot() && !insideSpotCone(d, cone, band)) continue;
                    pairs.emplace_back(uint32_t(p), uint32_t(i + 1));
                    break;
                }
            }
    }
    fillLists(t, pairs);
    return t;
}

std::vector<int> frontFaceCounts(const ImageFloat& depth, const CameraMatrices& camera,
                                 const std::vector<PointLight>& lights, float inflate) {
    return frontFaceCounts(depth, camera, lights, std::vector<float>(lights.size(), inflate));
}

std::vector<int> frontFaceCounts(const ImageFloat& depth, const CameraMatrices& camera,
                                 const std::vector<PointLight>& lights, const std::vector<float>& inflate) {
    if (inflate.size() != lights.size()) throw Error("frontFaceCounts: one inflation factor per light");
    if (depth.width != camera.width || depth.height != camera.height)
        throw Error("frontFaceCounts: depth image and camera sizes differ");
    std::vector<int> counts(size_t(depth.width) * depth.height, 0);
    std::vector<glm::vec3> nearPoint(counts.size()), farPoint(counts.size());
    for (int y = 0; y < depth.height; ++y)
        for (int x = 0; x < depth.width; ++x) {
            const size_t p = size_t(y) * depth.width + x;
            nearPoint[p] = unprojectPixel(camera, x, y, 0.0f);
            farPoint[p] = unprojectPixel(camera, x, y, std::min(depth.at(x, y), 1.0f));
        }
    for (size_t i = 0; i < lights.size(); ++i) {
        PointLight grown = lights[i];
        grown.radius *= inflate[i];
        const float r2 = grown.radius * grown.radius;
        int x0, y0, x1, y1;
        screenRect(camera, grown, x0, y0, x1, y1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const size_t p = size_t(y) * depth.width + x;
                // Closest point of the segment near -> surface to the centre.
                const glm::vec3 a = nearPoint[p], ab = farPoint[p] - a;
                const float len2 = glm::dot(ab, ab);
                const float t = len2 > 0.0f ? std::clamp(glm::dot(grown.position - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
                const glm::vec3 d = a + t * ab - grown.position;
                if (glm::dot(d, d) <= r2) ++counts[p];
            }
    }
    return counts;
}

ListCheck checkIndexLists(const CoverageTruth& truth, const PackingScheme& scheme,
                          const std::vector<ImageRGBA8>& indexTargets, uint32_t lightCount,
                          const std::vector<uint32_t>& sceneIndexOf, const IndexRegions& regions) {
    const int targets = scheme.targetCount();
    if (static_cast<int>(indexTargets.size()) != targets) throw Error("checkIndexLists: wrong number of targets");
    for (const auto& img : indexTargets)
        if (img.width != truth.width || img.height != truth.height) throw Error("checkIndexLists: size mismatch");
    const size_t n = size_t(truth.width) * truth.height;
    ListCheck c;
    c.droppedPerPixel.assign(n, 0);
    c.decoded.resize(n);
    std::vector<uint8_t> texels(size_t(targets) * 4);
    for (size_t p = 0; p < n; ++p) {
        for (int t = 0; t < targets; ++t)
            std::copy_n(&indexTargets[t].pixels[p * 4], 4, &texels[size_t(t) * 4]);
        std::vector<uint32_t>& list = c.decoded[p];
        // Region-local numbering: the pixel's region is its row of entries (images run top to bottom, GL's y up).
        const uint32_t row = regions.on() ? uint32_t(regions.regionOfPixel(int(p % size_t(truth.width)),
                                                                            truth.height - 1 - int(p / size_t(truth.width))))
                                          : 0u;
        for (uint32_t idx : scheme.decodePixel(texels.data())) {
            if (idx == 0) continue;
            if (regions.on()) {
                idx = idx < 256 ? row * 256 + idx : 0xFFFFFFFFu;
                if (idx <= sceneIndexOf.size() && sceneIndexOf[idx - 1] == 0) idx = 0xFFFFFFFFu;  // an unused entry
            }
            // Compact numbering: back to scene indices (an index past the frame's lights stays invalid).
            if (!sceneIndexOf.empty())
                idx = idx != 0xFFFFFFFFu && idx <= sceneIndexOf.size() ? sceneIndexOf[idx - 1] : lightCount + 1;
            list.push_back(idx);
        }
        c.slotsUsed += static_cast<long>(list.size());
        c.maxSlotsUsed = std::max(c.maxSlotsUsed, static_cast<int>(list.size()));
        std::vector<uint32_t> sorted = list;
        std::sort(sorted.begin(), sorted.end());
        for (size_t i = 0; i < sorted.size(); ++i)
            if (sorted[i] > lightCount || (i > 0 && sorted[i] == sorted[i - 1])) ++c.invalidSlots;
        int dropped = 0;
        for (uint32_t k = truth.offsets[p]; k < truth.offsets[p + 1]; ++k)
            if (!std::binary_search(sorted.begin(), sorted.end(), truth.lights[k])) ++dropped;
        c.droppedPerPixel[p] = static_cast<uint8_t>(std::min(dropped, 255));
        c.droppedLightPixels += dropped;
        if (dropped) ++c.pixelsWithDrops;
        c.maxDroppedPerPixel = std::max(c.maxDroppedPerPixel, dropped);
    }
    return c;
}

PixelListCheck checkPixelLists(const CoverageTruth& truth, const std::vector<int>& listOfPixel,
                               const std::vector<uint32_t>& entries, const std::vector<uint32_t>& offsets,
                               const std::vector<int>& counts) {
    const size_t pixels = size_t(truth.width) * size_t(truth.height);
    if (listOfPixel.size() != pixels)
        throw Error("checkPixelLists: " + std::to_string(listOfPixel.size()) + " pixels' lists for " +
                    std::to_string(pixels) + " pixels");
    if (offsets.size() != counts.size()) throw Error("checkPixelLists: offsets and counts differ in length");
    PixelListCheck c;
    for (size_t p = 0; p < pixels; ++p) {
        if (!truth.surface[p]) continue;
        const int list = listOfPixel[p];
        const long truePairs = long(truth.offsets[p + 1] - truth.offsets[p]);
        c.truthPairs += truePairs;
        if (list < 0 || size_t(list) >= offsets.size()) {
            ++c.surfaceWithoutList;
            c.missingPairs += truePairs;
            if (truePairs > 0) ++c.pixelsWithMissing;
            continue;
        }
        const uint32_t* first = entries.data() + offsets[size_t(list)];
        const uint32_t* last = first + counts[size_t(list)];
        c.listPairs += counts[size_t(list)];
        long missing = 0;
        for (uint32_t k = truth.offsets[p]; k < truth.offsets[p + 1]; ++k)
            if (!std::binary_search(first, last, truth.lights[k])) ++missing;
        c.missingPairs += missing;
        if (missing > 0) ++c.pixelsWithMissing;
    }
    c.extraPairs = c.listPairs - (c.truthPairs - c.missingPairs);
    return c;
}

}  // namespace lidr
