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

Camera camera(glm::vec3 position, glm::vec3 target, float nearPlane = 0.1f, float farPlane = 60.0f,
              float fov = 60.0f) {
    Camera c;
    c.position = position;
    c.target = target;
    c.nearPlane = nearPlane;
    c.farPlane = farPlane;
    c.fovYDegrees = fov;
    return c;
}

// Random lights over the test floor (24 x 24 m), radii in [rMin, rMax].
std::vector<PointLight> scatteredLights(int count, float rMin, float rMax, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> xz(-11.0f, 11.0f), y(0.05f, 3.0f), r(rMin, rMax), c(0.2f, 1.0f);
    std::vector<PointLight> lights;
    for (int i = 0; i < count; ++i) lights.push_back(light({xz(rng), y(rng), xz(rng)}, r(rng), {c(rng), c(rng), c(rng)}));
    return lights;
}

Scene firstPersonScene() {
    Scene s = floorScene();
    s.camera = camera({0.0f, 1.7f, 11.0f}, {0.0f, 1.2f, 0.0f}, 0.1f, 60.0f);
    return s;
}

Scene topDownScene() {
    Scene s = floorScene();
    s.camera = camera({0.0f, 22.0f, 1.0f}, {0.0f, 0.0f, 0.0f}, 1.0f, 60.0f);
    return s;
}

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
    std::vector<PointLight> lights = scatteredLights(300, 0.2f, 4.0f, 11);
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
    std::vector<PointLight> lights = scatteredLights(200, 0.3f, 3.0f, 4);
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
