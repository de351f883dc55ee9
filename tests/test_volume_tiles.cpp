// Tile-culled light volumes (lidr/technique/volume_tiles.h, LidrOptions::tileCulledVolumes): the CPU tile test
// never rejects a tile where a light reaches a surface; on the GPU the culled pass marks exactly what the volume
// meshes mark, rasterises far less on deep, occluded scenes, and a frame without a reachable light draws no
// volume and reads no index texture.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <random>

#include "gl_test_context.h"
#include "lidr/eval/bench_scenes.h"
#include "lidr/eval/controlled_scenes.h"
#include "lidr/eval/light_coverage.h"
#include "lidr/scene/camera.h"
#include "lidr/scene/default_scene.h"
#include "lidr/scene/primitives.h"
#include "lidr/scene/sphere_bounds.h"
#include "lidr/technique/volume_tiles.h"
#include "render_helpers.h"

using namespace lidr;
using namespace lidr::test;


// The camera the CPU tile tests look at their depth fields with: 8 m away, near 0.1 m, far 60 m.
CameraMatrices fieldCamera(int w, int h) {
    Camera camera;
    camera.position = {0.0f, 2.0f, 8.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    camera.nearPlane = 0.1f;
    camera.farPlane = 60.0f;
    return cameraMatrices(camera, w, h);
}

TEST_CASE("volume tiles: a tile is never rejected where a sphere contains a pixel's surface", "[volume-tiles][cpu]") {
    // Random depth fields (a slanted floor, steps and noise, background holes) and random spheres; for every
    // pixel whose surface point (its depth, or anywhere within the margin) lies inside a sphere, the pixel's
    // tile must be reached. Counted: how many tiles the test rejects, so it is not trivially conservative.
    const int seed = GENERATE(1, 2, 3, 4);
    const int tileSize = GENERATE(8, 16);
    DYNAMIC_SECTION("seed " << seed << ", tiles " << tileSize) {
        const int w = 96, h = 72;
        const CameraMatrices cam = fieldCamera(w, h);
        std::mt19937 random{uint32_t(seed)};
        std::uniform_real_distribution<float> unit(0.0f, 1.0f);
        std::vector<float> depth(size_t(w) * h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const float base = 0.90f + 0.09f * float(y) / float(h) + (x / 20 % 2 ? 0.004f : 0.0f);
                const float d = unit(random) < 0.05f ? 1.0f : std::min(0.9999f, base + 0.002f * unit(random));
                depth[size_t(y) * w + x] = d;
            }
        const float margin = 3.0f / 16777215.0f;
        VolumeTiles tiles(w, h, tileSize);
        tiles.build(depth, margin, cam);
        const glm::mat4 inverseViewProjection = glm::inverse(cam.viewProjection);
        long required = 0, rejected = 0, missed = 0;
        for (int i = 0; i < 300; ++i) {
            const glm::vec3 centre(unit(random) * 16.0f - 8.0f, unit(random) * 3.0f - 1.0f, unit(random) * 16.0f - 10.0f);
            const float radius = 0.2f + 2.5f * unit(random);
            const glm::vec3 viewCentre(cam.view * glm::vec4(centre, 1.0f));
            float nearDepth = 0.0f, farDepth = 1.0f;
            const bool spans = VolumeTiles::sphereDepthSpan(cam, centre, radius, nearDepth, farDepth);
            std::vector<char> reached(size_t(tiles.tileCount()), 0);
            for (int t = 0; t < tiles.tileCount(); ++t)
                reached[size_t(t)] = spans && tiles.slicesReached(t, viewCentre, radius, nearDepth, farDepth) != 0;
            std::vector<char> needed(size_t(tiles.tileCount()), 0);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    const double d = depth[size_t(y) * w + x];
                    if (d >= 1.0) continue;
                    // The pixel centre's ray at the stored depth: the surface point the sphere test rebuilds.
                    const glm::vec4 ndc(2.0f * (float(x) + 0.5f) / float(w) - 1.0f,
                                        2.0f * (float(y) + 0.5f) / float(h) - 1.0f, float(2.0 * d - 1.0), 1.0f);
                    glm::vec4 p = inverseViewProjection * ndc;
                    const glm::vec3 point = glm::vec3(p) / p.w;
                    if (glm::length(point - centre) < radius * 0.999f) needed[size_t((y / tileSize) * tiles.tilesX() + x / tileSize)] = 1;
                }
            for (int t = 0; t < tiles.tileCount(); ++t) {
                required += needed[size_t(t)];
                rejected += !reached[size_t(t)];
                if (needed[size_t(t)] && !reached[size_t(t)]) ++missed;
            }
        }
        CHECK(required > 0);
        CHECK(missed == 0);
        CHECK(rejected > required);  // the test rejects most tiles, not none
    }
}

TEST_CASE("volume tiles: no pixel is marked by more lights than its tile's candidate bound", "[volume-tiles][cpu]") {
    // The rank windows skip a tile whose bound is at most the window's first rank, so the bound must hold for
    // every pixel: the lights whose sphere meets the pixel's ray anywhere in its widened depth span (what the
    // sphere test keeps) are at most the most lights reaching one run of sliceSpan + 1 slices.
    CHECK(VolumeTiles::candidateWindows(1u << 4, 0) == 1u << 4);
    CHECK(VolumeTiles::candidateWindows(1u << 4, 1) == ((1u << 4) | (1u << 3)));  // runs 3-4 and 4-5
    CHECK(VolumeTiles::candidateWindows(1u << 4, 2) == ((1u << 4) | (1u << 3) | (1u << 2)));
    CHECK(VolumeTiles::candidateWindows(0x80000001u, 40) == 0xFFFFFFFFu);
    const int seed = GENERATE(1, 2, 3);
    // Flat (slices narrower than a pixel's span: every span crosses many) and slanted fields with spheres near
    // the surfaces; and a far flat field (46 m: a pixel's span, 6 depth steps, is 8 mm there) with, per tile, one pair of spheres that each hold one end of a pixel's span
    // and not the other: that pixel has 2 lights where no slice is reached by both (the bound of the fullest single
    // slice, before the eleventh session, said 1 there).
    const int field = GENERATE(0, 1, 2);
    const bool flat = field != 1;
    DYNAMIC_SECTION("seed " << seed << (field == 0 ? ", flat" : field == 1 ? ", slanted" : ", flat, split spans")) {
        const int w = 64, h = 48, tileSize = 16;
        const CameraMatrices cam = fieldCamera(w, h);
        std::mt19937 random{uint32_t(seed)};
        std::uniform_real_distribution<float> unit(0.0f, 1.0f);
        const float step = 1.0f / 16777215.0f;
        std::vector<float> depth(size_t(w) * h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                depth[size_t(y) * w + x] = flat ? (field == 2 ? 0.9995f : 0.995f) + step * float(int(4.0f * unit(random)))
                                                : 0.95f + 0.04f * float(y) / float(h) + 0.001f * unit(random);
        const float margin = 3.0f * step;
        VolumeTiles tiles(w, h, tileSize);
        tiles.build(depth, margin, cam);
        const glm::mat4 inverseViewProjection = glm::inverse(cam.viewProjection);
        auto pointAt = [&](int x, int y, double d) {
            const glm::dvec4 ndc(2.0 * (x + 0.5) / w - 1.0, 2.0 * (y + 0.5) / h - 1.0, 2.0 * d - 1.0, 1.0);
            const glm::dvec4 p = glm::dmat4(inverseViewProjection) * ndc;
            return glm::dvec3(p) / p.w;
        };
        // Spheres whose surface passes near the pixels' surfaces, so that many cut through a span.
        std::vector<glm::vec4> spheres;
        for (int t = 0; field == 2 && t < tiles.tileCount(); ++t) {
            const int x = (t % tiles.tilesX()) * tileSize + tileSize / 2, y = (t / tiles.tilesX()) * tileSize + tileSize / 2;
            const double d = depth[size_t(y) * w + x];
            const glm::dvec3 a = pointAt(x, y, d - margin), b = pointAt(x, y, d + margin);
            const double length = glm::length(b - a), radius = 0.05;
            const glm::dvec3 u = (b - a) / length;
            spheres.push_back(glm::vec4(glm::vec3(a + u * (0.05 * length - radius)), float(radius)));  // the near 5 %
            spheres.push_back(glm::vec4(glm::vec3(a + u * (0.95 * length + radius)), float(radius)));  // the far 5 %
        }
        for (int i = 0; field != 2 && i < 400; ++i) {
            const int x = int(unit(random) * float(w - 1)), y = int(unit(random) * float(h - 1));
            const double d = depth[size_t(y) * w + x] + (unit(random) - 0.5f) * 2.0f * margin;
            const glm::dvec3 onSurface = pointAt(x, y, d);
            const glm::dvec3 direction = glm::normalize(glm::dvec3(unit(random) - 0.5f, unit(random) - 0.5f, unit(random) - 0.5f));
            const double radius = 0.3 + 2.0 * unit(random);
            spheres.push_back(glm::vec4(glm::vec3(onSurface + direction * radius), float(radius)));
        }
        std::vector<int> bound(size_t(tiles.tileCount()), 0);
        for (int t = 0; t < tiles.tileCount(); ++t) {
            std::array<int, 32> runs{};
            for (const glm::vec4& s : spheres) {
                float nearDepth = 0.0f, farDepth = 1.0f;
                if (!VolumeTiles::sphereDepthSpan(cam, glm::vec3(s), s.w, nearDepth, farDepth)) continue;
                const glm::vec3 viewCentre(cam.view * glm::vec4(glm::vec3(s), 1.0f));
                const uint32_t windows = VolumeTiles::candidateWindows(tiles.slicesReached(t, viewCentre, s.w, nearDepth, farDepth), tiles.sliceSpan(t));
                for (int r = 0; r < 32; ++r) runs[size_t(r)] += (windows >> r) & 1u;
            }
            bound[size_t(t)] = *std::max_element(runs.begin(), runs.end());
        }
        long marked = 0, spans = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double d = depth[size_t(y) * w + x];
                const glm::dvec3 a = pointAt(x, y, d - margin), b = pointAt(x, y, d + margin);
                int count = 0;
                for (const glm::vec4& s : spheres) {
                    const glm::dvec3 c(s), ab = b - a;
                    const double t = glm::clamp(glm::dot(c - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
                    count += glm::length(a + ab * t - c) < double(s.w) * 0.9999;
                }
                marked += count;
                const int tile = (y / tileSize) * tiles.tilesX() + x / tileSize;
                spans += tiles.sliceSpan(tile) > 0;
                INFO("pixel " << x << ", " << y << ": " << count << " lights, the tile's bound " << bound[size_t(tile)]);
                REQUIRE(count <= bound[size_t(tile)]);
            }
        CHECK(marked > 0);
        if (flat) CHECK(spans > 0);  // the flat field's spans cross slices
    }
}

TEST_CASE("volume tiles: each tile's depth range and slices are those of its pixels, one by one", "[volume-tiles][cpu]") {
    // The build walks rows a tile span at a time; here every pixel is visited on its own, the definition
    // written out: range = [min(d) - margin, max(d) + margin] over the tile's surface pixels (d < 1), slice
    // mask = the slices [floor((d - margin - min) * 32 / (max - min)), floor((d + margin - min) * ...)] clamped
    // to 31. Sizes that are not multiples of the tile, background, NaN and a one-pixel-wide last column.
    const int w = GENERATE(97, 64, 33);
    const int tileSize = GENERATE(8, 16);
    DYNAMIC_SECTION(w << " px wide, tiles " << tileSize) {
        const int h = 45;
        Camera camera;
        camera.position = {0.0f, 2.0f, 8.0f};
        const CameraMatrices cam = cameraMatrices(camera, w, h);
        std::mt19937 random{uint32_t(w * 31 + tileSize)};
        std::uniform_real_distribution<float> unit(0.0f, 1.0f);
        std::vector<float> depth(size_t(w) * h);
        for (float& d : depth) {
            const float u = unit(random);
            d = u < 0.08f ? 1.0f : u < 0.09f ? std::nanf("") : 0.5f + 0.49f * unit(random) * unit(random);
        }
        for (int y = 0; y < 16; ++y)  // a tile of background only
            for (int x = 0; x < 16; ++x) depth[size_t(y) * w + x] = 1.0f;
        const float margin = 3.0f / 16777215.0f, widened = margin + 4.0f / 16777215.0f;  // + the build's slack
        VolumeTiles tiles(w, h, tileSize);
        tiles.build(depth, margin, cam);
        std::vector<float> lo(size_t(tiles.tileCount()), 2.0f), hi(size_t(tiles.tileCount()), -1.0f);
        std::vector<uint32_t> slices(size_t(tiles.tileCount()), 0u);
        auto tileOf = [&](int x, int y) { return size_t((y / tileSize) * tiles.tilesX() + x / tileSize); };
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const float d = depth[size_t(y) * w + x];
                if (!(d < 1.0f)) continue;
                lo[tileOf(x, y)] = std::min(lo[tileOf(x, y)], d - widened);
                hi[tileOf(x, y)] = std::max(hi[tileOf(x, y)], d + widened);
            }
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const float d = depth[size_t(y) * w + x];
                if (!(d < 1.0f)) continue;
                const size_t t = tileOf(x, y);
                const float scale = 32.0f / (hi[t] - lo[t]);
                const int first = std::clamp(int(std::floor((d - widened - lo[t]) * scale)), 0, 31);
                const int last = std::clamp(int(std::floor((d + widened - lo[t]) * scale)), 0, 31);
                for (int s = first; s <= last; ++s) slices[t] |= 1u << s;
            }
        int empty = 0;
        for (int t = 0; t < tiles.tileCount(); ++t) {
            INFO("tile " << t);
            CHECK(tiles.tileMinDepth(t) == lo[size_t(t)]);
            CHECK(tiles.tileMaxDepth(t) == hi[size_t(t)]);
            CHECK(tiles.tileSlices(t) == slices[size_t(t)]);
            empty += hi[size_t(t)] < lo[size_t(t)];
        }
        CHECK(empty >= 1);  // the background tile
    }
}

TEST_CASE("volume tiles: refused sizes name the rule", "[volume-tiles][cpu][bad-input]") {
    CHECK_THROWS_WITH(VolumeTiles(64, 48, 2), Catch::Contains("tile size must be in [4, 256]"));
    CHECK_THROWS_WITH(VolumeTiles(64, 48, 512), Catch::Contains("tile size must be in [4, 256]"));
    CHECK_THROWS_WITH(VolumeTiles(0, 48, 16), Catch::Contains("at least 1 x 1"));
}

// A scene of these tests by name at w x h, opaque: "room", "overlap-K" (K coincident lights per cluster on a floor
// seen from above) or an occluded bench scene (hall-N, city-N).
Scene namedScene(const std::string& name, int w, int h) {
    Scene scene;
    if (name == "room") {
        scene = makeDefaultScene();
    } else if (name.rfind("overlap-", 0) == 0) {
        ControlledOverlapOptions o;
        o.overlap = std::stoi(name.substr(8));
        o.width = w;
        o.height = h;
        scene = makeControlledOverlapScene(o);
    } else {
        REQUIRE(makeOccludedSceneByName(name, scene));
    }
    scene.width = w;
    scene.height = h;
    scene.transparency = false;
    return scene;
}

TEST_CASE("tile-culled volumes mark the same lists as the volume meshes", "[volume-tiles][lidr][every-gl]") {
    struct Case {
        const char* scene;
        int budget, bits;
    };
    const Case c = GENERATE(Case{"room", 4, 8}, Case{"room", 16, 8}, Case{"hall-255", 8, 8}, Case{"hall-255", 16, 8},
                            Case{"city-255", 4, 8}, Case{"hall-1024", 16, 16});
    if (!takeRow(std::string(c.scene) == "room" && c.budget == 4)) return;
    DYNAMIC_SECTION(c.scene << " bitshift b" << c.budget << " " << c.bits << "-bit") {
        const Scene scene = namedScene(c.scene, 192, 144);
        LidrOptions o;
        o.packing = {PackingSchemeKind::BitShift, c.budget, c.bits};
        o.transparency = false;
        const RenderResult tiled = renderAndEvaluate(scene, o);
        o.tileCulledVolumes = false;
        const RenderResult meshes = renderAndEvaluate(scene, o, tiled.reference);
        REQUIRE(tiled.indexTargets.size() == meshes.indexTargets.size());
        for (size_t t = 0; t < tiled.indexTargets.size(); ++t) CHECK(tiled.indexTargets[t].pixels == meshes.indexTargets[t].pixels);
        CHECK(tiled.lidr.pixels == meshes.lidr.pixels);
        requireExactWithinBudget(tiled.evaluation, c.scene);
        // Tiles are used where the lights' pixel rectangles add up to a screen or more (LidrRenderer::kTileCullingMinArea).
        // OpenGL ES keeps the volume meshes (no depth read-back).
        if (testGl().gles) CHECK(tiled.stats.autoDecision.volumeAreaPerPixel < 0.0);
        else if (std::string(c.scene) != "city-255") CHECK(tiled.stats.autoDecision.volumeAreaPerPixel >= 0.0);
        CHECK(meshes.stats.autoDecision.volumeAreaPerPixel < 0.0);
    }
}

TEST_CASE("tile culling is skipped where the lights cover less than a screen", "[volume-tiles][lidr][every-gl]") {
    Scene scene = floorScene();
    scene.lights = {light(glm::vec3(0.0f, 0.5f, 0.0f), 1.0f), light(glm::vec3(2.0f, 0.5f, 1.0f), 1.5f)};
    const RenderResult small = renderAndEvaluate(scene, LidrOptions{});
    CHECK(small.stats.autoDecision.volumeAreaPerPixel < 0.0);  // volume meshes: no read-back
    CHECK(small.stats.drawnLights == 2);
    requireExactWithinBudget(small.evaluation, "two small lights");
    for (int i = 0; i < 40; ++i) scene.lights.push_back(light(glm::vec3(-10.0f + 0.5f * float(i), 0.5f, 0.0f), 4.0f));
    const RenderResult many = renderAndEvaluate(scene, LidrOptions{});
    CHECK((many.stats.autoDecision.volumeAreaPerPixel >= 0.0) == !testGl().gles);  // ES: no depth read-back
    requireExactWithinBudget(many.evaluation, "42 large lights");
}

TEST_CASE("tile-culled volumes rasterise at most 3x the true light-pixel pairs on the hall", "[volume-tiles][lidr]") {
    // The issue-25 target, as a count (not a time), at the bench's size and the defaults: the pixels the volume
    // quads cover against the CPU truth's list lengths (doc/benchmarks.md has the measured ratios).
    Scene scene;
    REQUIRE(makeOccludedSceneByName("hall-255", scene));
    LidrRenderer renderer(testGl(), scene, LidrOptions{}, scene.width, scene.height);
    const std::vector<PointLight> lights = scene.lightsAt(scene.time);
    renderer.render(scene.camera, lights, {scene.ambient, scene.backgroundColor});  // the budget settles
    const FrameStats stats = renderer.render(scene.camera, lights, {scene.ambient, scene.backgroundColor});
    CHECK(stats.autoDecision.repacks == 0);
    const CoverageTruth truth =
        computeCoverage(renderer.targets().readDepth(), cameraMatrices(scene.camera, scene.width, scene.height), lights);
    long pairs = 0;
    for (size_t p = 0; p < truth.surface.size(); ++p)
        if (truth.surface[p]) pairs += truth.count(p);
    REQUIRE(pairs > 0);
    if (testGl().gles) {  // OpenGL ES keeps the volume meshes: no depth read-back
        CHECK(stats.autoDecision.volumeAreaPerPixel < 0.0);
        return;
    }
    const double quads = stats.autoDecision.volumeAreaPerPixel * double(scene.width) * double(scene.height);
    INFO("volume quad pixels " << quads << ", true light-pixel pairs " << pairs);
    CHECK(quads <= 3.0 * double(pairs));
    CHECK(quads >= double(pairs));  // every true pair is a fragment
}

TEST_CASE("the overlap probe over the tiles' candidate bounds measures what it measures over the whole screen",
          "[volume-tiles][lidr]") {
    // With tiles the probe draws each threshold only over the tiles whose bound on a pixel's count exceeds it
    // (none: the answer is 0 without a draw); with volume meshes it draws the whole screen. The lists are the same,
    // so the measured overlap and the pixels over the budget must be too (the automatic budget's first frame asks
    // every threshold, 1 to 16).
    const char* name = GENERATE("room", "hall-255", "hall-1024", "overlap-16");
    DYNAMIC_SECTION(name) {
        if (testGl().gles) return;  // no tiles on OpenGL ES
        const Scene scene = namedScene(name, 192, 144);
        LidrOptions o;
        o.transparency = false;
        const RenderResult tiled = renderAndEvaluate(scene, o);
        o.tileCulledVolumes = false;
        const RenderResult meshes = renderAndEvaluate(scene, o, tiled.reference);
        REQUIRE(tiled.stats.autoDecision.volumeAreaPerPixel >= 0.0);
        CHECK(tiled.stats.autoDecision.measuredBudget == meshes.stats.autoDecision.measuredBudget);
        CHECK(tiled.stats.autoDecision.overflowPixels == meshes.stats.autoDecision.overflowPixels);
        CHECK(tiled.stats.autoDecision.budget == meshes.stats.autoDecision.budget);
        CHECK(tiled.lidr.pixels == meshes.lidr.pixels);
        INFO("measured budget " << tiled.stats.autoDecision.measuredBudget);
        CHECK(tiled.stats.autoDecision.measuredBudget > 1);  // the thresholds below it were exceeded: not all 0
    }
}

TEST_CASE("tile culling gives way to volume meshes where a tile frame measured too small a saving", "[volume-tiles][lidr]") {
    if (testGl().gles) return;  // OpenGL ES keeps the volume meshes (no depth read-back)
    // A floor seen from above, clusters of 8 coincident lights: over a screen of sphere rectangles, nothing
    // occluded, so the tiles save only the rectangles' corners (the bench's overlap-8: the read-back cost more).
    // The hall: they save many screens. Either way every frame's image is the first frame's.
    struct Case {
        const char* name;
        bool tilesSaveLittle;
    };
    const Case c = GENERATE(Case{"overlap-8", true}, Case{"hall-255", false});
    DYNAMIC_SECTION(c.name) {
        const Scene scene = namedScene(c.name, 256, 192);
        LidrOptions options;
        options.transparency = false;
        LidrRenderer renderer(testGl(), scene, options, scene.width, scene.height);
        const std::vector<PointLight> lights = scene.lightsAt(scene.time);
        const ShadingParameters shading{scene.ambient, scene.backgroundColor};
        const FrameStats first = renderer.render(scene.camera, lights, shading);
        const ImageRGBA8 firstImage = renderer.targets().readColor();
        INFO("tile saving " << first.autoDecision.tileSavingScreens << " screens");
        REQUIRE(first.autoDecision.volumeAreaPerPixel >= 0.0);  // the first frame measures with tiles
        CHECK_FALSE(first.autoDecision.tilesSkippedForSaving);
        CHECK((first.autoDecision.tileSavingScreens < LidrRenderer::kTileCullingMinSaving) == c.tilesSaveLittle);
        for (int frame = 2; frame <= LidrRenderer::kTileCullingRecheckFrames + 2; ++frame) {
            const FrameStats stats = renderer.render(scene.camera, lights, shading);
            INFO("frame " << frame);
            // Little saving: volume meshes until kTileCullingRecheckFrames frames have passed, then tiles again.
            const bool tiles = !c.tilesSaveLittle || frame == LidrRenderer::kTileCullingRecheckFrames + 2;
            CHECK((stats.autoDecision.volumeAreaPerPixel >= 0.0) == tiles);
            CHECK(stats.autoDecision.tilesSkippedForSaving == !tiles);
            CHECK(stats.autoDecision.repacks == 0);
            if (frame == 2 || frame == LidrRenderer::kTileCullingRecheckFrames + 2)
                CHECK(renderer.targets().readColor().pixels == firstImage.pixels);
        }
    }
}

TEST_CASE("a frame without a reachable light draws no light volume and reads no index texture", "[volume-tiles][lidr][every-gl]") {
    const bool tiles = GENERATE(true, false);
    const int lightSet = GENERATE(0, 1);  // no lights at all; lights only behind the camera
    DYNAMIC_SECTION((tiles ? "tile-culled" : "volume meshes") << (lightSet ? ", lights behind the camera" : ", no lights")) {
        Scene scene = floorScene();
        if (lightSet == 1)
            for (int i = 0; i < 5; ++i) scene.lights.push_back(light(scene.camera.position - 3.0f * glm::normalize(scene.camera.target - scene.camera.position) + glm::vec3(float(i), 0.0f, 0.0f), 1.0f));
        LidrOptions o;
        o.tileCulledVolumes = tiles;
        const RenderResult r = renderAndEvaluate(scene, o);
        CHECK(r.stats.volumePassSkipped);
        CHECK(r.stats.volumeDrawCalls == 0);
        CHECK(r.stats.drawnLights == 0);
        for (const ImageRGBA8& t : r.indexTargets)
            for (uint8_t b : t.pixels) REQUIRE(b == 0);
        CHECK(r.lidr.pixels == r.reference.pixels);
    }
}

TEST_CASE("region-local indices: 8-bit lists of over 255 lights, the same lists and image as 16-bit global ones",
          "[volume-tiles][regions][lidr]") {
    // hall-1024 at 384 x 288: about 700 lights reach the view, so global numbering needs 16-bit indices; split
    // into regions of whole tiles, each region's lights fit 8 bits. Exactness is judged against the CPU truth
    // (every list, decoded through the frame's regions) and the image against the 16-bit frame, byte for byte.
    if (testGl().gles) {
        WARN("OpenGL ES keeps the volume meshes (no depth read-back): no tiles, no regions");
        return;
    }
    const char* name = GENERATE("hall-1024", "hall-255");
    DYNAMIC_SECTION(name) {
        Scene scene;
        REQUIRE(makeOccludedSceneByName(name, scene));
        scene.width = 384;
        scene.height = 288;
        scene.transparency = false;
        LidrOptions o;  // automatic scheme, budget and width
        o.transparency = false;
        const RenderResult regional = renderAndEvaluate(scene, o);
        o.regionalIndices = false;
        const RenderResult global = renderAndEvaluate(scene, o, regional.reference);
        requireExactWithinBudget(regional.evaluation, name);
        CHECK(regional.evaluation.lists.droppedLightPixels == 0);
        CHECK(regional.evaluation.lists.invalidSlots == 0);
        CHECK(regional.lidr.pixels == global.lidr.pixels);
        CHECK(regional.stats.drawnLights == global.stats.drawnLights);
        if (std::string(name) == "hall-1024") {
            REQUIRE(global.stats.drawnLights > 255);
            CHECK(global.stats.autoDecision.indexBits == 16);
            CHECK(regional.stats.autoDecision.indexBits == 8);
            CHECK(regional.indexTargets.size() * 2 == global.indexTargets.size());
        } else {  // under 256 lights: one numbering, nothing changes
            CHECK(regional.stats.autoDecision.indexBits == global.stats.autoDecision.indexBits);
            for (size_t t = 0; t < regional.indexTargets.size(); ++t)
                CHECK(regional.indexTargets[t].pixels == global.indexTargets[t].pixels);
        }
    }
}

TEST_CASE("tile culling stays where its tiles culled every light (a frame with nothing to draw saved all the meshes)",
          "[volume-tiles][lidr]") {
    if (testGl().gles) return;  // OpenGL ES keeps the volume meshes (no depth read-back)
    // A wall fills the view; the lights stand on the floor behind it, their spheres reaching the floor's bounds
    // (so the plan keeps them) but no visible surface: the tiles cull all of them and the volume pass draws
    // nothing. That saved every sphere rectangle the meshes would have drawn: the saving was once counted as 0
    // (the summary said the tiles saved nothing, and where they did not also narrow the index width the volume
    // meshes would have taken over for kTileCullingRecheckFrames frames); the next frames keep the tiles.
    Scene scene = firstPersonScene();
    addBox(scene, {-12.0f, 0.0f, 6.0f}, {12.0f, 8.0f, 6.5f}, 1, 4);
    for (int i = 0; i < 48; ++i)
        scene.lights.push_back(light({-9.0f + 0.4f * float(i), 0.5f, 0.0f - 0.1f * float(i % 5)}, 1.5f));
    LidrOptions options;
    options.transparency = false;
    LidrRenderer renderer(testGl(), scene, options, scene.width, scene.height);
    const ShadingParameters shading{scene.ambient, scene.backgroundColor};
    const FrameStats first = renderer.render(scene.camera, scene.lights, shading);
    const ImageRGBA8 firstImage = renderer.targets().readColor();
    INFO("tile saving " << first.autoDecision.tileSavingScreens << " screens, " << first.drawnLights << " lights drawn");
    REQUIRE(first.autoDecision.volumeAreaPerPixel >= 0.0);  // tiles: the lights' rectangles cover over a screen
    REQUIRE(first.drawnLights == 0);                        // ... and they culled every light
    CHECK(first.autoDecision.tileSavingScreens >= LidrRenderer::kTileCullingMinSaving);
    for (int frame = 2; frame <= 4; ++frame) {
        const FrameStats stats = renderer.render(scene.camera, scene.lights, shading);
        INFO("frame " << frame);
        CHECK(stats.autoDecision.volumeAreaPerPixel >= 0.0);
        CHECK_FALSE(stats.autoDecision.tilesSkippedForSaving);
        CHECK(compareImages(renderer.targets().readColor(), firstImage).differingPixels == 0);
    }
    const RenderResult checked = renderAndEvaluate(scene, options);  // the same frame against the reference
    CHECK(compareImages(checked.lidr, firstImage).differingPixels == 0);
    CHECK(compareImages(checked.lidr, checked.reference).maxAbsError == 0);
}
