// Clustered forward against ground truth: the exact sphere-cell distance against brute-force sampling, the slicing
// and the CPU assignment against brute-force point sampling of the cells, the occupied slices against the depth
// they come from; then clustered images against the brute-force reference with every light that touches a pixel
// in the list of the cluster the GPU looked up for that pixel (CPU truth, lidr/eval/light_coverage.h), the extra
// pairs the conservative test adds, slice boundaries, growth, index widths, transparency, MSAA and bad input.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <catch2/catch.hpp>

#include "gl_test_context.h"
#include "lidr/base/error.h"
#include "lidr/base/gl.h"
#include "lidr/base/visualize.h"
#include "lidr/eval/image_compare.h"
#include "lidr/eval/light_coverage.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/modes/clustered_renderer.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/modes/render_mode.h"
#include "lidr/scene/default_scene.h"
#include "lidr/scene/io/scene_file.h"
#include "lidr/scene/primitives.h"
#include "lidr/scene/sphere_bounds.h"
#include "render_helpers.h"

using namespace lidr;
using namespace lidr::test;

namespace {



// A point of the cell at parameters (u, v, t) in [0, 1]^3: t along depth, u and v across the cross-section.
glm::vec3 cellPoint(const ClusterCell& c, double u, double v, double t) {
    const double d = c.nearDepth + (c.farDepth - c.nearDepth) * t;
    const double sx = c.slopeX0 + (c.slopeX1 - c.slopeX0) * u, sy = c.slopeY0 + (c.slopeY1 - c.slopeY0) * v;
    return glm::vec3(float(sx * d), float(sy * d), float(-d));
}

bool insideCell(const ClusterCell& c, const glm::vec3& p) {
    const double d = -double(p.z);
    return d >= c.nearDepth && d <= c.farDepth && p.x >= c.slopeX0 * d && p.x <= c.slopeX1 * d &&
           p.y >= c.slopeY0 * d && p.y <= c.slopeY1 * d;
}

// The brute-force reference, transparent meshes included (back to front, alpha blended, every light).
ImageRGBA8 referenceImage(const Scene& scene, const std::vector<PointLight>& lights, bool fixedTable, int samples = 0) {
    ReferenceRenderer reference(testGl(), scene, scene.width, scene.height, std::max<int>(1, int(lights.size())),
                                fixedTable, samples, true);
    reference.render(scene.camera, lights, {scene.ambient, scene.backgroundColor});
    return reference.targets().readColor();
}

struct ClusteredCheck {
    ImageRGBA8 image, reference;
    ImageError error;
    PixelListCheck lists;
    long invalidEntries = 0;  // list entries that name no light, repeat one or are out of order; bad terminators
    ClusteredFrameInfo frame;
};

// Every cluster list ascending, in range and terminated.
long invalidEntries(const ClusterGrid& grid, size_t lightCount) {
    long invalid = 0;
    for (int c = 0; c < grid.clusterCount(); ++c) {
        const std::vector<uint32_t> list = grid.list(c);
        for (size_t k = 0; k < list.size(); ++k)
            if (list[k] == 0 || list[k] > lightCount || (k > 0 && list[k] <= list[k - 1])) ++invalid;
        if (grid.entries()[grid.offsets()[size_t(c)] + list.size()] != 0) ++invalid;
    }
    return invalid;
}

// Renders with the clustered mode and checks it: the lists of the clusters the GPU looked up against the CPU truth.
ClusteredCheck renderClustered(const Scene& scene, const ClusteredOptions& options,
                               const std::vector<PointLight>* lightsIn = nullptr, const ImageRGBA8* reference = nullptr,
                               const GlInfo* info = nullptr) {
    testContext();
    const std::vector<PointLight> lights = lightsIn ? *lightsIn : scene.lightsAt(scene.time);
    ClusteredRenderer renderer(info ? *info : testGl(), scene, options, scene.width, scene.height);
    renderer.render(scene.camera, lights, {scene.ambient, scene.backgroundColor});
    ClusteredCheck c;
    c.image = renderer.targets().readColor();
    c.frame = renderer.frameInfo();
    c.invalidEntries = invalidEntries(renderer.grid(), lights.size());
    if (options.msaaSamples == 0) {
        const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
        const CoverageTruth truth = computeCoverage(renderer.targets().readDepth(), cam, lights);
        const ClusterGrid& g = renderer.grid();
        c.lists = checkPixelLists(truth, renderer.pixelClusters(), g.entries(), g.offsets(), g.counts());
    }
    c.reference = reference ? *reference
                            : referenceImage(scene, lights, options.forceFixedLightTable, options.msaaSamples);
    c.error = compareImages(c.image, c.reference);
    return c;
}

// "Clustered equals the reference": no light missing from the list of any pixel's cluster, and the image within
// one 8-bit step (the same lights summed in the same ascending order; one step covers compilers that reassociate).
void requireEqualsReference(const ClusteredCheck& c) {
    INFO("max error " << c.error.maxAbsError << ", PSNR " << c.error.psnr << ", missing " << c.lists.missingPairs
                      << " of " << c.lists.truthPairs << " (surface pixels without a list " << c.lists.surfaceWithoutList
                      << "), extra pairs " << c.lists.extraPairs << ", invalid entries " << c.invalidEntries
                      << ", longest list " << c.frame.grid.maxLights << ", loop bound " << c.frame.loopBound);
    REQUIRE(c.invalidEntries == 0);
    REQUIRE(c.lists.missingPairs == 0);
    REQUIRE(c.lists.surfaceWithoutList == 0);
    REQUIRE(c.error.maxAbsError <= 1);
    REQUIRE(c.frame.loopBound >= c.frame.grid.maxLights);
}

}  // namespace

// --- the grid on the CPU ------------------------------------------------------------------------------------

TEST_CASE("cluster cells: the exact sphere-cell distance equals brute-force sampling of the cell", "[clustered][cpu]") {
    std::mt19937 rng(37);
    std::uniform_real_distribution<double> unit(0.0, 1.0), slope(-1.2, 1.2), offset(-6.0, 6.0);
    int inside = 0, outside = 0;
    for (int trial = 0; trial < 300; ++trial) {
        ClusterCell c;
        const double a = slope(rng), b = slope(rng), e = slope(rng), f = slope(rng);
        c.slopeX0 = float(std::min(a, b)), c.slopeX1 = float(std::max(a, b) + 1e-3);
        c.slopeY0 = float(std::min(e, f)), c.slopeY1 = float(std::max(e, f) + 1e-3);
        c.nearDepth = float(0.1 + 5.0 * unit(rng));
        c.farDepth = float(c.nearDepth * (1.05 + 2.0 * unit(rng)));
        // Points near the cell (around its centre, spread by its size) and far from it.
        const glm::vec3 centre = cellPoint(c, 0.5, 0.5, 0.5);
        const double size = glm::length(cellPoint(c, 1, 1, 1) - cellPoint(c, 0, 0, 0));
        for (int q = 0; q < 8; ++q) {
            const double spread = q < 6 ? size : 4.0 * size;
            const glm::vec3 p = q < 2 ? cellPoint(c, 0.02 + 0.96 * unit(rng), 0.02 + 0.96 * unit(rng), 0.02 + 0.96 * unit(rng))
                                      : centre + glm::vec3(float(offset(rng) * spread / 6.0),
                                                           float(offset(rng) * spread / 6.0),
                                                           float(offset(rng) * spread / 6.0));
            const double exact = std::sqrt(cellDistanceSquared(c, p));
            // Brute force: the nearest of 41^3 points of the cell (the closest point lies on its boundary, so the
            // boundary faces are sampled: u, v or t at 0 or 1).
            constexpr int n = 40;
            double sampled = 1e300, spacing = 0.0;
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n; ++j)
                    for (int k = 0; k <= n; ++k) {
                        if (i != 0 && i != n && j != 0 && j != n && k != 0 && k != n) continue;
                        sampled = std::min(sampled, double(glm::length(p - cellPoint(c, i / double(n), j / double(n), k / double(n)))));
                    }
            // Neighbouring samples lie at most `spacing` apart: the sampled minimum overshoots by at most that.
            spacing = std::max({glm::length(cellPoint(c, 1, 0, 1) - cellPoint(c, 0, 0, 1)),
                                glm::length(cellPoint(c, 0, 1, 1) - cellPoint(c, 0, 0, 1)),
                                glm::length(cellPoint(c, 1, 1, 1) - cellPoint(c, 1, 1, 0)),
                                glm::length(cellPoint(c, 0, 0, 1) - cellPoint(c, 0, 0, 0))}) / n;
            INFO("trial " << trial << " point " << q << ": exact " << exact << ", sampled " << sampled);
            if (insideCell(c, p)) {
                ++inside;
                REQUIRE(exact == 0.0);
                continue;
            }
            ++outside;
            REQUIRE(exact > 0.0);
            REQUIRE(exact <= sampled * (1.0 + 1e-6) + 1e-6);  // no point of the cell is nearer than the exact distance
            REQUIRE(exact >= sampled - 1.5 * spacing);       // ... and a sampled point is as near, up to the spacing
        }
    }
    CHECK(inside > 600);
    CHECK(outside > 1500);
}

TEST_CASE("cluster slices: Doom's and Filament's spacing, their boundaries and the shader's formula", "[clustered][cpu]") {
    const CameraMatrices cam = cameraMatrices(camera({0, 2, 8}, {0, 0, 0}, 0.1f, 120.0f), 1024, 768);
    for (ClusterSlicing kind : {ClusterSlicing::Exponential, ClusterSlicing::NearSlice})
        for (int count : {1, 2, 16, 24, 64}) {
            const ClusterSlices s = clusterSlices(cam, count, kind, 5.0f);
            INFO(clusterSlicingName(kind) << ", " << count << " slices");
            REQUIRE(s.count == count);
            REQUIRE(s.boundary(0) == Approx(0.1));
            REQUIRE(s.boundary(count) == Approx(120.0));
            const bool nearSlice = kind == ClusterSlicing::NearSlice && count > 1;
            if (nearSlice) CHECK(s.boundary(1) == Approx(5.0).epsilon(1e-5));
            // Equal depth ratios (past the near slice).
            for (int k = nearSlice ? 2 : 1; k + 1 < count; ++k)
                REQUIRE(s.boundary(k + 1) / s.boundary(k) ==
                        Approx(s.boundary(nearSlice ? 2 : 1) / s.boundary(nearSlice ? 1 : 0)).epsilon(1e-4));
            // The formula puts a depth just past boundary k in slice k and just before it in slice k - 1; every
            // depth of the view range, and the ends' beyond it, in a slice.
            for (int k = 1; k < count; ++k) {
                REQUIRE(s.sliceOf(s.boundary(k) * (1.0 + 1e-6)) == k);
                REQUIRE(s.sliceOf(s.boundary(k) * (1.0 - 1e-6)) == k - 1);
            }
            REQUIRE(s.sliceOf(0.01) == 0);
            REQUIRE(s.sliceOf(0.1) == 0);
            REQUIRE(s.sliceOf(119.9) == count - 1);
            REQUIRE(s.sliceOf(1000.0) == count - 1);
            REQUIRE(s.sliceOf(-1.0) == 0);
        }
    // Fitted to the frame's depths: the formula spans them, the ends still reach the planes.
    for (ClusterSlicing kind : {ClusterSlicing::Exponential, ClusterSlicing::NearSlice}) {
        const ClusterSlices fitted = clusterSlices(cam, 16, kind, 5.0f, 2.0f, 50.0f);
        INFO(clusterSlicingName(kind) << " fitted to 2..50");
        REQUIRE(fitted.boundary(0) == Approx(0.1));
        REQUIRE(fitted.boundary(16) == Approx(120.0));
        if (kind == ClusterSlicing::Exponential) {
            REQUIRE(fitted.boundary(1) == Approx(2.0 * std::pow(25.0, 1.0 / 16.0)).epsilon(1e-4));
            REQUIRE(fitted.boundary(15) == Approx(50.0 / std::pow(25.0, 1.0 / 16.0)).epsilon(1e-4));
        } else {
            REQUIRE(fitted.boundary(1) == Approx(5.0).epsilon(1e-4));
            REQUIRE(fitted.boundary(15) == Approx(50.0 / std::pow(10.0, 1.0 / 15.0)).epsilon(1e-4));
        }
        REQUIRE(fitted.sliceOf(1.0) == 0);
        REQUIRE(fitted.sliceOf(100.0) == 15);
    }
    // A near slice outside the view range falls back to Doom's spacing.
    const ClusterSlices doom = clusterSlices(cam, 16, ClusterSlicing::Exponential, 5.0f);
    for (float lightNear : {0.05f, 0.1f, 120.0f, 500.0f}) {
        const ClusterSlices s = clusterSlices(cam, 16, ClusterSlicing::NearSlice, lightNear);
        CHECK(s.scale == doom.scale);
        CHECK(s.bias == doom.bias);
    }
    REQUIRE_THROWS_WITH(clusterSlices(cam, 0, ClusterSlicing::Exponential, 5.0f), Catch::Contains("1..64"));
    REQUIRE_THROWS_WITH(clusterSlices(cam, 65, ClusterSlicing::Exponential, 5.0f), Catch::Contains("got 65"));
    REQUIRE(parseClusterSlicing("near-slice") == ClusterSlicing::NearSlice);
    REQUIRE_THROWS_WITH(parseClusterSlicing("linear"), Catch::Contains("exponential, near-slice"));
}

TEST_CASE("cluster grid: sizes are checked; lists ascending, terminated, holding every light that reaches a cell",
          "[clustered][cpu]") {
    REQUIRE_THROWS_WITH(ClusterGrid(64, 48, 3, 16), Catch::Contains("4..256"));
    REQUIRE_THROWS_WITH(ClusterGrid(1024, 768, 257, 16), Catch::Contains("got 257"));
    REQUIRE(ClusterGrid(64, 48, 49, 16).tilesY() == 1);  // a tile taller than the screen: one row of tiles
    REQUIRE_THROWS_WITH(ClusterGrid(64, 48, 16, 0), Catch::Contains("slices must be 1..64"));
    REQUIRE_THROWS_WITH(ClusterGrid(64, 48, 16, 65), Catch::Contains("got 65"));
    REQUIRE_THROWS_WITH(ClusterGrid(0, 48, 16, 8), Catch::Contains("positive"));
    ClusterGrid small(100, 60, 32, 8);
    REQUIRE(small.tilesX() == 4);
    REQUIRE(small.tilesY() == 2);
    REQUIRE(small.clusterCount() == 64);
    REQUIRE(small.tileOf(99, 59) == 7);
    REQUIRE(small.clusterOf(7, 3) == 31);

    const int width = 160, height = 120;
    const CameraMatrices cam = cameraMatrices(camera({0, 1.7f, 11}, {0, 1.2f, 0}, 0.1f, 60.0f), width, height);
    std::vector<PointLight> lights = floorLights(300, 0.2f, 4.0f, 11);
    lights.push_back(light({0, 1.7f, 11}, 0.5f));       // around the eye
    lights.push_back(light({0, 1.7f, 30}, 1.0f));       // wholly behind the eye
    lights.push_back(light({0, 1.0f, 11.2f}, 0.3f));    // crosses the near plane
    lights.push_back(light({0, 1.0f, -60.0f}, 12.0f));  // crosses the far plane
    for (PointLight& l : lights)
        if (&l - lights.data() < 60) {  // spot lights, aimed anywhere
            l.direction = glm::vec3(std::sin(l.position.x), -1.0f, std::cos(l.position.z));
            l.outerConeAngle = 0.2f + 0.02f * float(&l - lights.data());
            l.innerConeAngle = 0.5f * l.outerConeAngle;
        }
    for (ClusterSlicing kind : {ClusterSlicing::Exponential, ClusterSlicing::NearSlice})
        for (int tile : {16, 23}) {
            ClusterGrid grid(width, height, tile, 24);
            const ClusterSlices slices = clusterSlices(cam, 24, kind, 3.0f);
            grid.build(cam, lights, slices);
            INFO(clusterSlicingName(kind) << ", tile " << tile);
            REQUIRE(grid.entries()[0] == 0);
            REQUIRE(invalidEntries(grid, lights.size()) == 0);
            REQUIRE(grid.indexBits() == 16);
            REQUIRE(grid.stats().activeClusters == grid.clusterCount());
            CHECK(grid.stats().assignedLights > 150);
            // Never missed: points sampled in every cell (each light's cone too) are lit only by listed lights.
            std::mt19937 rng(5);
            std::uniform_real_distribution<double> unit(0.0, 1.0);
            long sampledPairs = 0;
            for (int c = 0; c < grid.clusterCount(); ++c) {
                const ClusterCell cell = grid.cell(cam, slices, c);
                const std::vector<uint32_t> list = grid.list(c);
                for (int s = 0; s < 24; ++s) {
                    const glm::vec3 viewPoint = cellPoint(cell, unit(rng), unit(rng), unit(rng));
                    const glm::vec3 world = glm::vec3(glm::inverse(cam.view) * glm::vec4(viewPoint, 1.0f));
                    for (size_t i = 0; i < lights.size(); ++i) {
                        const PointLight& l = lights[i];
                        const glm::vec3 toPoint = world - l.position;
                        if (glm::length(toPoint) >= l.radius * 0.999f) continue;
                        if (l.isSpot() && glm::dot(glm::normalize(toPoint), glm::normalize(l.direction)) <
                                              std::cos(l.outerConeAngle) + 1e-4f)
                            continue;
                        ++sampledPairs;
                        INFO("cluster " << c << ", light " << i + 1);
                        REQUIRE(std::binary_search(list.begin(), list.end(), uint32_t(i + 1)));
                    }
                }
                // Exact, not a box: a listed point light reaches the cell (up to the margins).
                for (uint32_t i : list) {
                    const PointLight& l = lights[i - 1];
                    const glm::vec3 c3 = glm::vec3(cam.view * glm::vec4(l.position, 1.0f));
                    const double d = std::sqrt(cellDistanceSquared(cell, c3));
                    REQUIRE(d <= l.radius * 1.001 + 1e-3 * cell.farDepth);
                }
            }
            CHECK(sampledPairs > 5000);
            // What a light must reach: around the eye, every cluster; behind, none.
            long aroundEye = 0, behind = 0;
            for (int c = 0; c < grid.clusterCount(); ++c) {
                const std::vector<uint32_t> list = grid.list(c);
                aroundEye += std::binary_search(list.begin(), list.end(), uint32_t(301));
                behind += std::binary_search(list.begin(), list.end(), uint32_t(302));
            }
            CHECK(aroundEye > 0);
            CHECK(behind == 0);
        }
    ClusterGrid grid(width, height, 16, 24);
    const ClusterSlices slices = clusterSlices(cam, 24, ClusterSlicing::Exponential, 5.0f);
    lights.resize(255);
    grid.build(cam, lights, slices);
    CHECK(grid.indexBits() == 8);
    const std::vector<PointLight> tooMany(65536, light({0, 0, 0}, 1.0f));
    REQUIRE_THROWS_WITH(grid.build(cam, tooMany, slices), Catch::Contains("65535"));
    REQUIRE_THROWS_WITH(grid.build(cam, lights, clusterSlices(cam, 8, ClusterSlicing::Exponential, 5.0f)),
                        Catch::Contains("8 slices given, the grid has 24"));
}

TEST_CASE("cluster grid: occupied slices hold every slice a pixel's depth can be in, and the transparent reach",
          "[clustered][cpu]") {
    const int width = 64, height = 48;
    const CameraMatrices cam = cameraMatrices(camera({0, 1.7f, 11}, {0, 1.2f, 0}, 0.1f, 60.0f), width, height);
    ClusterGrid grid(width, height, 16, 16);
    const ClusterSlices slices = clusterSlices(cam, 16, ClusterSlicing::Exponential, 5.0f);
    const glm::mat4& P = cam.projection;
    const auto window = [&](double d) { return float(0.5 * (-double(P[2][2]) + double(P[3][2]) / d) + 0.5); };
    // Depths at, just before and just after every boundary, and random ones; the top rows empty (1.0).
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> depth(0.1, 60.0);
    std::vector<float> w(size_t(width) * height, 1.0f);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < width; ++x) {
            const int i = y * width + x, k = 1 + i % 15;
            const double d = i % 4 == 3 ? depth(rng) : slices.boundary(k) * (1.0 + ((i % 4) - 1) * 1e-6);
            w[size_t(i)] = window(d);
        }
    const std::vector<uint64_t> masks = grid.markOccupiedSlices(w, cam, slices, false);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float wd = w[size_t(y) * width + x];
            if (wd >= 1.0f) continue;
            const double d = viewDepthFromWindowDepth(cam, wd);
            const int exact = slices.sliceOf(d);
            const uint64_t m = masks[size_t(grid.tileOf(x, y))];
            INFO("pixel " << x << "," << y << " depth " << d << " slice " << exact);
            REQUIRE(((m >> exact) & 1u) == 1u);
            // Next to a boundary both sides are marked.
            if (exact > 0 && d < slices.boundary(exact) * (1.0 + 1e-6)) REQUIRE(((m >> (exact - 1)) & 1u) == 1u);
            if (exact < 15 && d > slices.boundary(exact + 1) * (1.0 - 1e-6)) REQUIRE(((m >> (exact + 1)) & 1u) == 1u);
        }
    // The packed read-back (24-bit depth over an 8-bit stencil, no float conversion) marks at least the same.
    std::vector<uint32_t> packed(w.size());
    std::vector<float> unpacked(w.size());
    for (size_t i = 0; i < w.size(); ++i) {
        const uint32_t d = uint32_t(std::lround(double(w[i]) * 16777215.0));
        packed[i] = (d << 8) | 0x5Au;
        unpacked[i] = float(double(d) / 16777215.0);
    }
    const std::vector<uint64_t> fromFloats = grid.markOccupiedSlices(unpacked, cam, slices, false);
    const std::vector<uint64_t> fromPacked = grid.markOccupiedSlicesPacked(packed, cam, slices, false);
    for (size_t t = 0; t < masks.size(); ++t) REQUIRE((fromPacked[t] & fromFloats[t]) == fromFloats[t]);
    REQUIRE(grid.markOccupiedSlicesPacked(packed, cam, slices, true).back() == 0xFFFFu);  // the top rows are empty
    // Only those: a tile of one depth marks one slice (or two at a boundary).
    std::vector<float> flat(size_t(width) * height, window(7.0));
    for (uint64_t m : grid.markOccupiedSlices(flat, cam, slices, false))
        REQUIRE(m == (uint64_t(1) << slices.sliceOf(7.0)));
    // Transparent reach: every slice in front of the tile's farthest surface; everything over empty pixels.
    const std::vector<uint64_t> reach = grid.markOccupiedSlices(flat, cam, slices, true);
    for (uint64_t m : reach) REQUIRE(m == (uint64_t(2) << slices.sliceOf(7.0)) - 1);
    flat[5] = 1.0f;
    REQUIRE(grid.markOccupiedSlices(flat, cam, slices, true)[0] == 0xFFFFu);
    // Assignment with the masks: only occupied clusters get lists, each the dense grid's list.
    std::vector<PointLight> lights = floorLights(200, 0.3f, 3.0f, 4);
    ClusterGrid dense(width, height, 16, 16);
    dense.build(cam, lights, slices);
    grid.build(cam, lights, slices, &masks);
    long popcount = 0;
    for (uint64_t m : masks) popcount += __builtin_popcountll(m);
    REQUIRE(grid.stats().activeClusters == popcount);
    for (int c = 0; c < grid.clusterCount(); ++c) {
        const bool occupied = (masks[size_t(c % grid.tileCount())] >> (c / grid.tileCount())) & 1u;
        REQUIRE(grid.list(c) == (occupied ? dense.list(c) : std::vector<uint32_t>{}));
    }
    CHECK(grid.stats().entries < dense.stats().entries);
}

// --- GPU ----------------------------------------------------------------------------------------------------

namespace {
// The rows of the occupancy tables: the dense grid, then occupied clusters where the context reads depth back.
std::vector<bool> occupancyRows() {
    return testGl().readDepthStencil ? std::vector<bool>{false, true} : std::vector<bool>{false};
}
// A row's options: 16 px tiles, occupied clusters as it asks.
ClusteredOptions occupancyRowOptions(bool occupancy) {
    ClusteredOptions c;
    c.tileSize = 16;
    c.occupiedClusters = occupancy;
    return c;
}
}  // namespace

TEST_CASE("clustered equals the reference on the default room, dense and with occupied clusters", "[clustered][every-gl]") {
    DefaultSceneOptions o;
    o.width = testWidth();
    o.height = testHeight();
    o.time = 2.0f;
    const Scene scene = makeDefaultScene(o);
    const ImageRGBA8 reference = referenceImage(scene, scene.lightsAt(scene.time), false);
    long denseClusters = -1;
    for (bool occupancy : occupancyRows()) {
        const ClusteredOptions c = occupancyRowOptions(occupancy);
        const ClusteredCheck check = renderClustered(scene, c, nullptr, &reference);
        INFO("occupancy " << occupancy);
        requireEqualsReference(check);
        CHECK(check.lists.truthPairs > 1000);
        CHECK(check.frame.occupancyUsed == occupancy);
        CHECK(check.frame.indexBits == 8);  // 255 lights
        // Occupancy: lists only where surfaces are (the slices fitted to the frame's depths, so the entries may
        // even grow: thinner slices).
        if (!occupancy) denseClusters = check.frame.grid.activeClusters;
        if (occupancy) CHECK(check.frame.grid.activeClusters < denseClusters);
        CHECK(check.frame.grid.listedClusters <= check.frame.grid.activeClusters);
    }
}

namespace {
void checkViews(const std::vector<int>& tileSizes, const std::vector<int>& sliceCounts) {
    const std::vector<PointLight> lights = floorLights(120, 0.4f, 3.5f, 3);
    for (const Scene& base : {topDownScene(), firstPersonScene()}) {
        Scene scene = base;
        scene.lights = lights;
        const ImageRGBA8 reference = referenceImage(scene, lights, false);
        for (int tile : tileSizes)
            for (int slices : sliceCounts)
                for (ClusterSlicing slicing : {ClusterSlicing::Exponential, ClusterSlicing::NearSlice})
                    for (bool occupancy : {false, true}) {
                        if (occupancy && !testGl().readDepthStencil) continue;
                        ClusteredOptions c;
                        c.tileSize = tile;
                        c.slices = slices;
                        c.slicing = slicing;
                        c.lightNear = 4.0f;
                        c.occupiedClusters = occupancy;
                        const ClusteredCheck check = renderClustered(scene, c, nullptr, &reference);
                        INFO("camera y " << scene.camera.position.y << ", tile " << tile << ", " << slices << " "
                                         << clusterSlicingName(slicing) << " slices, occupancy " << occupancy);
                        requireEqualsReference(check);
                        CHECK(check.lists.truthPairs > 500);
                    }
    }
}
}  // namespace

TEST_CASE("clustered equals the reference in top-down and first-person views, both slicings", "[clustered]") {
    checkViews({16}, {16});
}

TEST_CASE("clustered equals the reference in both views with other tile sizes and slice counts", "[clustered][slow]") {
    checkViews({8, 13, 64}, {1, 7, 32, 64});
}

TEST_CASE("clustered: depth slices cut the extra pairs of the 2D tile lists in a first-person view",
          "[clustered][slow]") {
    Scene scene = firstPersonScene();
    scene.lights = floorLights(200, 0.3f, 2.0f, 21);
    const ImageRGBA8 reference = referenceImage(scene, scene.lights, false);
    long previous = -1;
    for (int slices : {1, 4, 16, 64}) {
        ClusteredOptions c;
        c.tileSize = 16;
        c.slices = slices;
        const ClusteredCheck check = renderClustered(scene, c, nullptr, &reference);
        INFO(slices << " slices: extra pairs " << check.lists.extraPairs << ", true pairs " << check.lists.truthPairs);
        requireEqualsReference(check);
        if (previous >= 0) CHECK(check.lists.extraPairs < previous);
        previous = check.lists.extraPairs;
    }
}

TEST_CASE("clustered: pixels next to slice boundaries find lights whose spheres end at the boundaries",
          "[clustered][boundaries]") {
    // A first-person view down the floor: every slice boundary crosses the floor along a row of pixels. Lights lie
    // on the floor with spheres whose view-depth extent ends at a boundary, just short of it or just past it
    // (relative 1e-4), from either side, so a slice picked one off next to a boundary would miss them.
    Scene scene = firstPersonScene();
    const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
    ClusteredOptions c;
    c.tileSize = 16;
    c.slices = 32;
    const ClusterSlices slices = clusterSlices(cam, c.slices, c.slicing, c.lightNear);
    const glm::vec3 eye = cam.eye, fwd = cam.forward;
    std::vector<PointLight> lights;
    for (int k = 1; k < c.slices; ++k) {
        const double d = slices.boundary(k);
        if (d < 2.0 || d > 22.0) continue;  // where the floor is seen
        const float radius = float(0.12 * d);
        int variant = 0;
        for (float towards : {-1.0f, 1.0f})  // the sphere's far end (-1) or near end (+1) at the boundary
            for (float off : {-1e-4f, 0.0f, 1e-4f}) {
                const double centreDepth = d * (1.0 + double(off)) + double(towards * radius);
                const float x = 1.4f * float(variant++) - 3.5f + 0.3f * float(k % 3);
                // The floor point at view depth centreDepth in this column: dot(fwd, p - eye) = centreDepth.
                const float z = eye.z + float((centreDepth - fwd.x * (x - eye.x) + fwd.y * eye.y) / fwd.z);
                lights.push_back(light({x, 0.0f, z}, radius, glm::vec3(0.2f + 0.02f * float(k), 0.5f, 0.4f)));
            }
    }
    REQUIRE(lights.size() > 30);
    scene.lights = lights;
    ClusteredRenderer renderer(testGl(), scene, c, scene.width, scene.height);
    renderer.render(scene.camera, lights, {scene.ambient, scene.backgroundColor});
    // Pixels whose GPU slice differs from the slice of their depth buffer's view depth: how close to a boundary
    // they lie (the margins cover them; doc/clustered.md).
    const std::vector<int> gpu = renderer.pixelSlices();
    const ImageFloat depth = renderer.targets().readDepth();
    long surface = 0, differing = 0;
    double worst = 0.0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            const size_t p = size_t(y) * size_t(scene.width) + size_t(x);
            if (depth.pixels[p] >= 1.0f) continue;
            ++surface;
            REQUIRE(gpu[p] >= 0);
            const double d = viewDepthFromWindowDepth(cam, depth.pixels[p]);
            const int cpu = slices.sliceOf(d);
            if (cpu == gpu[p]) continue;
            ++differing;
            REQUIRE(std::abs(cpu - gpu[p]) == 1);
            const double boundary = slices.boundary(std::max(cpu, gpu[p]));
            worst = std::max(worst, std::abs(d / boundary - 1.0));
        }
    WARN("slice boundaries: " << differing << " of " << surface << " surface pixels in another slice than their "
                              << "depth buffer's view depth; at most " << worst << " (relative) from the boundary");
    CHECK(worst < 1e-3);  // the depth buffer's own rounding; the shaded point itself is within the slice margins
    const ClusteredCheck check = renderClustered(scene, c, &lights);
    requireEqualsReference(check);
    CHECK(check.lists.truthPairs > 100);
}

TEST_CASE("clustered: lights crossing the near plane, containing the camera, behind it, huge and tiny",
          "[clustered][slow]") {
    Scene low = floorScene();  // low over the floor, so a light crossing the near plane lights what is seen
    low.camera = camera({0.0f, 0.6f, 4.0f}, {0.0f, 0.0f, -6.0f}, 0.5f, 12.0f);
    for (const Scene& base : {firstPersonScene(), low}) {
        Scene scene = base;
        const glm::vec3 eye = scene.camera.position;
        const glm::vec3 fwd = glm::normalize(scene.camera.target - eye);
        const bool isLow = eye.y < 1.0f;
        scene.lights = {
            isLow ? light({0.0f, 0.3f, 3.35f}, 0.65f, {1.0f, 0.5f, 0.2f})
                  : light(eye + fwd * 0.3f + glm::vec3(0, -0.25f, 0), 0.3f, {1.0f, 0.4f, 0.2f}),
            light(eye + glm::vec3(0.3f, -0.5f, 0), isLow ? 1.2f : 2.5f, {0.3f, 0.9f, 0.4f}),  // contains the camera
            light(eye - fwd * 2.0f + glm::vec3(0, -1.0f, 0), 3.5f, {0.4f, 0.4f, 1.0f}),      // behind, reaches in
            light(eye - fwd * 6.0f, 1.0f, {1.0f, 1.0f, 1.0f}),                               // wholly behind
            light({0.0f, 5.0f, 0.0f}, 200.0f, {0.15f, 0.12f, 0.1f}),                         // huge: everything
            light({1.0f, 0.01f, isLow ? 1.0f : 4.0f}, 0.05f, {1.0f, 1.0f, 1.0f}),            // tiny, on the floor
            light({-1.0f, 0.02f, isLow ? 0.0f : 6.0f}, 0.08f, {1.0f, 0.2f, 0.2f}),
            light({0.0f, 0.5f, 5.0f}, 60.0f, {0.05f, 0.05f, 0.05f}),                         // past the far plane
        };
        for (bool occupancy : {false, true})
            for (bool fixedTable : {false, true}) {
                ClusteredOptions c;
                c.tileSize = 16;
                c.occupiedClusters = occupancy;
                c.forceFixedLightTable = fixedTable;
                INFO("low camera " << isLow << ", occupancy " << occupancy << ", fixed table " << fixedTable);
                const ClusteredCheck check = renderClustered(scene, c);
                requireEqualsReference(check);
            }
    }
}

TEST_CASE("clustered: transparent meshes find their own clusters; with occupancy, the clusters in front of the "
          "opaque surface keep lists", "[clustered][transparency][every-gl]") {
    Scene scene = firstPersonScene();
    const int glass = addGlassMaterial(scene);
    addSphere(scene, {-1.5f, 1.2f, 6.0f}, 0.8f, glass, 24);
    addSphere(scene, {1.0f, 1.0f, 4.0f}, 0.6f, glass, 24);
    addSphere(scene, {0.2f, 1.3f, 2.0f}, 1.0f, glass, 24);
    scene.lights = floorLights(80, 0.5f, 3.0f, 5);
    scene.lights.push_back(light({-1.0f, 1.5f, 7.5f}, 2.0f, {1.0f, 0.8f, 0.5f}));  // in front of the glass
    scene.lights.push_back(light({0.8f, 1.0f, 4.9f}, 1.0f, {0.5f, 1.0f, 0.5f}));
    scene.lights.push_back(light({0.2f, 1.3f, 3.4f}, 0.5f, {1.0f, 0.3f, 0.3f}));   // lights only the glass
    const ImageRGBA8 reference = referenceImage(scene, scene.lights, false);
    for (bool occupancy : occupancyRows()) {
        const ClusteredOptions c = occupancyRowOptions(occupancy);
        const ClusteredCheck check = renderClustered(scene, c, nullptr, &reference);
        INFO("occupancy " << occupancy);
        requireEqualsReference(check);
        // The glass is drawn: the image differs from the same frame without transparency.
        ClusteredOptions opaqueOnly = c;
        opaqueOnly.transparency = false;
        ClusteredRenderer r(testGl(), scene, opaqueOnly, scene.width, scene.height);
        r.render(scene.camera, scene.lights, {scene.ambient, scene.backgroundColor});
        CHECK(compareImages(r.targets().readColor(), check.image).differingPixels > 500);
        if (occupancy) {
            // Without the transparent reach the glass would find empty clusters: fewer clusters hold lists.
            CHECK(r.frameInfo().grid.activeClusters < check.frame.grid.activeClusters);
            CHECK(compareImages(r.targets().readColor(), reference).differingPixels > 500);
        }
    }
}

TEST_CASE("clustered: MSAA with transparency equals the reference rendered the same way",
          "[clustered][msaa][transparency][every-gl]") {
    const GlInfo& info = testGl();
    if (!info.multisampleFbo || info.maxSamples < 2) {
        WARN("no multisample FBOs in this context; MSAA not tested");
        return;
    }
    const Scene scene = firstPersonGlassScene();
    const ShadingParameters shading{scene.ambient, scene.backgroundColor};
    const ImageRGBA8 single = [&] {
        ClusteredRenderer r(info, scene, ClusteredOptions{}, scene.width, scene.height);
        r.render(scene.camera, scene.lights, shading);
        return r.targets().readColor();
    }();
    for (int samples : {2, 4}) {
        if (samples > info.maxSamples) continue;
        for (bool occupancy : {false, true}) {
            ClusteredOptions c;
            c.tileSize = 16;
            c.msaaSamples = samples;
            c.occupiedClusters = occupancy && info.readDepthStencil;
            ClusteredRenderer r(info, scene, c, scene.width, scene.height);
            r.render(scene.camera, scene.lights, shading);
            const ImageRGBA8 image = r.targets().readColor();
            const ImageError e = compareImages(image, referenceImage(scene, scene.lights, false, samples));
            INFO(samples << "x MSAA, occupancy asked " << occupancy << ": max " << e.maxAbsError << ", differing "
                         << e.differingPixels);
            REQUIRE(e.maxAbsError <= 1);
            CHECK_FALSE(r.frameInfo().occupancyUsed);  // per-sample depth is not read back: the dense grid
            CHECK(compareImages(image, single).differingPixels > 50);  // the edges really are antialiased
            REQUIRE_THROWS_WITH(r.pixelSlices(), Catch::Contains("MSAA"));
        }
    }
}

TEST_CASE("clustered: a list longer than the loop bound grows the shader, a full list texture grows, 8-bit indices "
          "become 16-bit", "[clustered][growth]") {
    Scene scene = topDownScene();
    // 70 lights all covering the middle of the floor: the longest cluster list has 70 entries.
    for (int i = 0; i < 70; ++i)
        scene.lights.push_back(light({std::cos(i * 0.3f), 0.5f, std::sin(i * 0.3f)}, 4.0f,
                                     glm::vec3(0.02f + 0.01f * (i % 5), 0.02f, 0.03f)));
    ClusteredOptions c;
    c.initialLoopBound = 4;
    c.tileSize = 4;  // many small clusters: the lists need more than one row of the list texture
    c.slices = 8;
    ClusteredRenderer r(testGl(), scene, c, scene.width, scene.height);
    const ShadingParameters shading{scene.ambient, scene.backgroundColor};
    r.render(scene.camera, scene.lights, shading);
    CHECK(r.frameInfo().grid.maxLights == 70);
    CHECK(r.frameInfo().loopBound == 128);
    CHECK(r.frameInfo().shaderRebuilds == 2);  // the first program and the grown one
    CHECK(r.frameInfo().indexBits == 8);
    CHECK(r.frameInfo().listTextureRows > 1);
    CHECK(long(r.frameInfo().listTextureRows) * ClusterGridTextures::kListWidth >= r.frameInfo().grid.entries);
    const size_t bytes8 = r.listBytes();
    const ClusteredCheck check = renderClustered(scene, c);
    requireEqualsReference(check);
    // 300 lights (the 70 and 230 far away): light indices above 255, so 16-bit lists, same image.
    std::vector<PointLight> more = scene.lights;
    for (int i = 0; i < 230; ++i) more.push_back(light({50.0f + float(i), 0.5f, 0.0f}, 1.0f));
    std::rotate(more.begin(), more.begin() + 70, more.end());  // the lit ones get indices 231..300
    r.render(scene.camera, more, shading);
    CHECK(r.frameInfo().indexBits == 16);
    CHECK(r.frameInfo().shaderRebuilds == 3);
    CHECK(r.listBytes() >= 2 * bytes8 / 2);
    const ImageError e = compareImages(r.targets().readColor(), referenceImage(scene, more, false));
    INFO("16-bit lists: max error " << e.maxAbsError);
    REQUIRE(e.maxAbsError <= 1);
    // Back to 8 bits.
    r.render(scene.camera, scene.lights, shading);
    CHECK(r.frameInfo().indexBits == 8);
    REQUIRE(compareImages(r.targets().readColor(), check.reference).maxAbsError <= 1);
}

TEST_CASE("clustered: 65,535 lights, the last ones lit, equal the reference with those lights alone",
          "[clustered][growth][slow]") {
    Scene scene = topDownScene();
    scene.width = 64;
    scene.height = 48;
    std::vector<PointLight> lit = floorLights(12, 1.0f, 3.0f, 17);
    std::vector<PointLight> lights;
    for (int i = 0; i < 65535 - 12; ++i)  // tiny lights all over the floor, under it: they light nothing
        lights.push_back(light({-11.0f + 22.0f * float(i % 256) / 255.0f, -0.5f, -11.0f + 22.0f * float(i / 256) / 255.0f},
                               0.2f, glm::vec3(1.0f)));
    lights.insert(lights.end(), lit.begin(), lit.end());
    REQUIRE(lights.size() == 65535);
    ClusteredOptions c;
    c.tileSize = 8;
    ClusteredRenderer r(testGl(), scene, c, scene.width, scene.height);
    r.render(scene.camera, lights, {scene.ambient, scene.backgroundColor});
    CHECK(r.frameInfo().indexBits == 16);
    CHECK(r.frameInfo().grid.assignedLights >= 12);
    const ImageError e = compareImages(r.targets().readColor(), referenceImage(scene, lit, false));
    INFO("max error " << e.maxAbsError);
    REQUIRE(e.maxAbsError <= 1);
    // The lit lights' indices are 65524..65535: their lists name them.
    bool named = false;
    for (uint32_t entry : r.grid().entries()) named = named || entry == 65535u;
    CHECK(named);
}

TEST_CASE("clustered: spot lights go on a cluster only where the cone may reach its cell; no light lost",
          "[clustered][lights][cones][slow]") {
    std::vector<PointLight> spots = floorLights(120, 1.0f, 4.5f, 29);
    std::mt19937 rng(2029);
    std::uniform_real_distribution<float> tilt(-0.8f, 0.8f), angle(0.05f, 1.5f);
    for (PointLight& l : spots) {
        l.position.y += 1.0f;
        l.direction = {tilt(rng), -1.0f, tilt(rng)};
        l.outerConeAngle = angle(rng);
        l.innerConeAngle = 0.5f * l.outerConeAngle;
    }
    spots[0].outerConeAngle = 1.5707963f;
    Scene scene = firstPersonScene();
    spots[1].position = scene.camera.position + glm::vec3(0.0f, 0.5f, 0.5f);
    spots[1].direction = scene.camera.target - spots[1].position;
    scene.lights = spots;
    std::vector<PointLight> points = spots;
    for (PointLight& l : points) l.outerConeAngle = 0.0f;
    for (bool fixedTable : {false, true}) {
        ClusteredOptions c;
        c.tileSize = 16;
        c.forceFixedLightTable = fixedTable;
        const ClusteredCheck cones = renderClustered(scene, c, &spots);
        INFO("fixed table " << fixedTable);
        requireEqualsReference(cones);
        ClusteredRenderer r(testGl(), scene, c, scene.width, scene.height);
        r.render(scene.camera, points, {scene.ambient, scene.backgroundColor});
        INFO("light-cluster pairs: cones " << cones.frame.grid.entries << ", the same lights as spheres "
                                           << r.frameInfo().grid.entries);
        CHECK(cones.lists.truthPairs > 1000);
        REQUIRE(cones.frame.grid.entries < r.frameInfo().grid.entries);
    }
}

TEST_CASE("clustered: heat map of lights per pixel's cluster", "[clustered][heatmap]") {
    Scene scene = topDownScene();
    scene.lights = {light({0, 0, 0}, 3.0f), light({0.5f, 0, 0}, 3.0f), light({8, 0, 8}, 1.0f)};
    ClusteredOptions c;
    c.tileSize = 16;
    ClusteredRenderer r(testGl(), scene, c, scene.width, scene.height);
    r.render(scene.camera, scene.lights, {});
    const ImageRGBA8 heat = r.clusterHeatMap(2);
    REQUIRE(heat.width == scene.width);
    REQUIRE(heat.height == scene.height);
    const std::vector<int> clusters = r.pixelClusters();
    for (int count : {0, 1, 2}) {
        const ImageRGBA8 one = overlapHeatMap(1, 1, {count}, 2);
        long pixels = 0;
        for (int y = 0; y < heat.height; ++y)
            for (int x = 0; x < heat.width; ++x) {
                const int cluster = clusters[size_t(y) * size_t(heat.width) + size_t(x)];
                if (cluster < 0) continue;
                const bool same = std::equal(one.pixels.begin(), one.pixels.end(), heat.at(x, y));
                REQUIRE(same == (r.grid().counts()[size_t(cluster)] == count));
                pixels += same;
            }
        CHECK(pixels > 0);
    }
}

TEST_CASE("clustered: bad input is refused before drawing", "[clustered][bad-input]") {
    Scene scene = floorScene();
    scene.lights = {light({0, 1, 0}, 2.0f)};
    const auto refused = [&](const ClusteredOptions& c) {
        return ClusteredRenderer(testGl(), scene, c, scene.width, scene.height);
    };
    ClusteredOptions c;
    c.tileSize = 3;
    REQUIRE_THROWS_WITH(refused(c), Catch::Contains("cluster tile size must be 4..256"));
    c.tileSize = 300;
    REQUIRE_THROWS_WITH(refused(c), Catch::Contains("got 300"));
    c = ClusteredOptions{};
    c.slices = 0;
    REQUIRE_THROWS_WITH(refused(c), Catch::Contains("depth slices must be 1..64"));
    c.slices = 65;
    REQUIRE_THROWS_WITH(refused(c), Catch::Contains("got 65"));
    c = ClusteredOptions{};
    c.occupiedClusters = true;
    c.preZ = false;
    REQUIRE_THROWS_WITH(refused(c), Catch::Contains("pre-Z"));
    c = ClusteredOptions{};
    c.slicing = ClusterSlicing::NearSlice;
    c.lightNear = -1.0f;
    REQUIRE_THROWS_WITH(refused(c), Catch::Contains("positive view depth"));
    c = ClusteredOptions{};
    c.initialLoopBound = 0;
    REQUIRE_THROWS_WITH(refused(c), Catch::Contains("loop bound"));
    GlInfo noReadBack = testGl();
    noReadBack.readDepthStencil = false;
    c = ClusteredOptions{};
    c.occupiedClusters = true;
    REQUIRE_THROWS_AS(ClusteredRenderer(noReadBack, scene, c, scene.width, scene.height), UnsupportedError);
    // No pre-Z and no occupancy is a valid mode: LEQUAL with depth writes in the shading pass.
    c = ClusteredOptions{};
    c.preZ = false;
    c.tileSize = 16;
    Scene lit = scene;
    lit.lights = floorLights(40, 0.5f, 3.0f, 2);
    requireEqualsReference(renderClustered(lit, c));
    ClusteredRenderer r(testGl(), scene, ClusteredOptions{}, scene.width, scene.height);
    REQUIRE_THROWS_WITH(r.pixelSlices(), Catch::Contains("before a frame"));
    const std::vector<PointLight> tooMany(65536, light({0, 0, 0}, 1.0f));
    REQUIRE_THROWS_WITH(r.render(scene.camera, tooMany, {}), Catch::Contains("65535"));
    std::vector<PointLight> bad = {light({0, 1, 0}, 2.0f), light({0, 1, 0}, -1.0f)};
    REQUIRE_THROWS_WITH(r.render(scene.camera, bad, {}), Catch::Contains("light 2") && Catch::Contains("radius"));
    bad[1] = light({std::nanf(""), 1, 0}, 1.0f);
    REQUIRE_THROWS_WITH(r.render(scene.camera, bad, {}), Catch::Contains("non-finite"));
    REQUIRE(glGetError() == GL_NO_ERROR);
    RenderModeOptions mo;
    mo.mode = "clustered";
    mo.clustered.slices = 100;
    REQUIRE_THROWS_WITH(createRenderer(mo, testGl(), scene, scene.width, scene.height), Catch::Contains("got 100"));
}

TEST_CASE("clustered: without highp fragment floats the grid has one slice, and still equals the reference",
          "[clustered][precision]") {
    GlInfo mediump = testGl();
    mediump.fragmentHighp = false;
    Scene scene = firstPersonScene();
    scene.lights = floorLights(60, 0.5f, 3.0f, 12);
    ClusteredOptions c;
    c.tileSize = 16;
    const ClusteredCheck check = renderClustered(scene, c, nullptr, nullptr, &mediump);
    requireEqualsReference(check);
    CHECK(check.frame.slicing.count == 1);
}

TEST_CASE("clustered: every GL object is released with its renderer", "[clustered][resources]") {
    testContext();
    const int before = gl::liveGlObjects();
    {
        Scene scene = floorScene();
        scene.lights = {light({0, 1, 0}, 3.0f)};
        for (bool occupancy : {false, true}) {
            ClusteredOptions c;
            c.occupiedClusters = occupancy && testGl().readDepthStencil;
            ClusteredRenderer r(testGl(), scene, c, scene.width, scene.height);
            r.render(scene.camera, scene.lights, {});
            r.pixelSlices();
            CHECK(gl::liveGlObjects() > before);
            CHECK(r.lightDataBytes() > 0);
        }
    }
    REQUIRE(gl::liveGlObjects() == before);
}
