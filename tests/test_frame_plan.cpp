// The frame plan of LIDR (lidr/technique/frame_plan.h) on the CPU: which lights get an index, in which order and
// with which numbers, the regions that number apart, and the index width. The scene's meshes and the frame's
// tiles are stood in for by the tests' own answers (FramePlanQueries). The GL side (the same lists whatever the
// numbering) is in tests/test_auto_configuration.cpp and tests/test_volume_tiles.cpp.
#include <catch2/catch.hpp>

#include "lidr/technique/frame_plan.h"
#include "lidr/technique/tile_decision.h"

using namespace lidr;

namespace {
// Looking down -z from (0, 0, 50): the plane z = 0 is in view within about 28 m of the axis.
CameraMatrices testCamera() {
    Camera camera;
    camera.position = glm::vec3(0.0f, 0.0f, 50.0f);
    camera.target = glm::vec3(0.0f);
    return cameraMatrices(camera, 128, 96);
}

PointLight light(glm::vec3 position, float radius = 1.0f, float priority = 0.0f) {
    PointLight l;
    l.position = position;
    l.radius = radius;
    l.priority = priority;
    return l;
}

std::vector<uint32_t> indicesOf(const std::vector<VolumeLight>& volumes) {
    std::vector<uint32_t> out;
    for (const VolumeLight& v : volumes) out.push_back(v.index);
    return out;
}

// Answers with every mesh reached everywhere, except where a test says otherwise.
FramePlanQueries everywhere() {
    FramePlanQueries q;
    q.touchesScene = [](const glm::vec4&) { return true; };
    q.reachesTransparent = [](const glm::vec4&) { return false; };
    q.reachesTiles = [](const glm::vec4&) { return true; };
    q.regionsReached = [](const glm::vec4&, const IndexRegions&) { return 1u; };
    return q;
}
}  // namespace

TEST_CASE("frame plan: lights in draw order; those that cannot touch a surface get no index", "[frame-plan][cpu]") {
    const std::vector<PointLight> lights = {
        light({0.0f, 0.0f, 0.0f}),              // 1
        light({0.0f, 0.0f, 80.0f}),             // 2: behind the camera
        light({2.0f, 0.0f, 0.0f}, 1.0f, 5.0f),  // 3: priority 5, drawn first
        light({9.0f, 0.0f, 0.0f}),              // 4: touches no mesh (x > 8 below)
        light({-2.0f, 0.0f, 0.0f}),             // 5
        light({4.0f, 1.0f, 0.0f}, 1.0f, 5.0f),  // 6: priority 5, after 3
    };
    REQUIRE(drawOrder(lights) == std::vector<uint32_t>{3, 6, 1, 2, 4, 5});
    const std::vector<int> shadowTiles = {10, 11, 12, 13, 14, 15};
    int meshTests = 0;
    FramePlanQueries q = everywhere();
    q.touchesScene = [&](const glm::vec4& s) {
        ++meshTests;
        return s.x < 8.0f;
    };
    q.reachesTiles = [](const glm::vec4&) -> bool {
        FAIL("tiles asked without tiles");
        return false;
    };
    struct Case {
        const char* name;
        bool cull, autoWidth;
        std::vector<uint32_t> indices, frameLights;
        int indexBits;
    };
    const Case cases[] = {
        {"automatic width: the visible lights numbered 1..n, 4 bits", true, true, {1, 2, 3, 4}, {3, 6, 1, 5}, 4},
        {"fixed width: the scene's own numbers", true, false, {3, 6, 1, 5}, {}, 8},
        {"no culling: every light, in draw order", false, true, {1, 2, 3, 4, 5, 6}, {3, 6, 1, 2, 4, 5}, 4},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        AutoConfiguration width;
        FramePlanSettings s;
        s.cullLights = c.cull;
        s.autoWidth = c.autoWidth ? &width : nullptr;
        s.fixedIndexBits = 8;
        s.shadowTiles = &shadowTiles;
        meshTests = 0;
        const FramePlan plan = planFrame(testCamera(), lights, s, q);
        CHECK(indicesOf(plan.volumes) == c.indices);
        CHECK(plan.frameLights == c.frameLights);
        CHECK(plan.drawnLights == int(c.indices.size()));
        CHECK(plan.widestList == plan.drawnLights);
        CHECK(plan.indexBits == c.indexBits);
        CHECK(plan.compactNumbering == c.autoWidth);
        CHECK_FALSE(plan.regions.on());
        CHECK_FALSE(plan.lightless());
        CHECK(meshTests == (c.cull ? 5 : 0));  // the frustum test first: light 2 never reaches the mesh test
        CHECK(plan.meshLights == 0);            // no tiles: nothing to measure them against
        CHECK(plan.meshRectArea == 0.0);
        // Each entry carries its scene light's sphere, cone and shadow tile, whatever its number.
        const std::vector<uint32_t> scene = c.autoWidth ? c.frameLights : c.indices;
        REQUIRE(plan.volumes.size() == scene.size());
        REQUIRE(plan.tableLights.size() == (c.autoWidth ? scene.size() : 0));
        for (size_t i = 0; i < scene.size(); ++i) {
            const PointLight& l = lights[scene[i] - 1];
            CHECK(plan.volumes[i].posRadius == glm::vec4(l.position, l.radius));
            CHECK(plan.volumes[i].cone == spotCone(l));
            CHECK(plan.volumes[i].shadowTile == shadowTiles[scene[i] - 1]);
            CHECK(plan.volumes[i].region == -1);
            if (c.autoWidth) CHECK(plan.tableLights[i].position == l.position);
        }
    }
    SECTION("no shadow test: no shadow tile") {
        FramePlanSettings s;
        const FramePlan plan = planFrame(testCamera(), lights, s, q);
        for (const VolumeLight& v : plan.volumes) CHECK(v.shadowTile == -1);
    }
    SECTION("no light touches a surface: a lightless plan") {
        AutoConfiguration width;
        FramePlanSettings s;
        s.autoWidth = &width;
        FramePlanQueries none = q;
        none.touchesScene = [](const glm::vec4&) { return false; };
        const FramePlan plan = planFrame(testCamera(), lights, s, none);
        CHECK(plan.lightless());
        CHECK(plan.drawnLights == 0);
        CHECK(plan.frameLights.empty());
        CHECK(plan.indexBits == 4);
    }
}

TEST_CASE("frame plan: with tiles, a light that reaches no tile's surface keeps an index only for a transparent mesh",
          "[frame-plan][volume-tiles][cpu]") {
    std::vector<PointLight> lights;
    for (int i = 0; i < 20; ++i) lights.push_back(light({float(i) - 10.0f, 0.0f, 0.0f}, 0.5f));
    FramePlanQueries q = everywhere();
    q.reachesTiles = [](const glm::vec4& s) { return s.x < 0.0f; };              // lights 1..10
    q.reachesTransparent = [](const glm::vec4& s) { return s.x == 5.0f; };       // light 16
    const CameraMatrices cam = testCamera();
    const double rectArea = lightRectArea(cam, lights);
    struct Case {
        const char* name;
        bool transparentLists, autoWidth;
        std::vector<uint32_t> sceneIndices;
        bool narrowed;
    };
    std::vector<uint32_t> reaching{1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
    std::vector<uint32_t> withTransparent = reaching;
    withTransparent.push_back(16);
    const Case cases[] = {
        {"opaque: the 10 that reach a tile, 4-bit where meshes needed 8", false, true, reaching, true},
        {"transparent layers: and the one that reaches a transparent mesh", true, true, withTransparent, true},
        {"fixed width: nothing to narrow", false, false, reaching, false},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        AutoConfiguration width;
        FramePlanSettings s;
        s.tiles = true;
        s.transparentLists = c.transparentLists;
        s.autoWidth = c.autoWidth ? &width : nullptr;
        const FramePlan plan = planFrame(cam, lights, s, q);
        CHECK((c.autoWidth ? plan.frameLights : indicesOf(plan.volumes)) == c.sceneIndices);
        // Volume meshes would have drawn all 20: the tile decision measures the tiles against them.
        CHECK(plan.meshLights == 20);
        CHECK(plan.meshRectArea == rectArea);
        CHECK(plan.tilesNarrowed() == c.narrowed);
        CHECK(plan.indexBits == (c.autoWidth ? 4 : 8));
    }
    SECTION("no culling: the tiles are not asked") {
        FramePlanSettings s;
        s.tiles = true;
        s.cullLights = false;
        FramePlanQueries never = q;
        never.reachesTiles = [](const glm::vec4&) -> bool {
            FAIL("tiles asked without culling");
            return false;
        };
        CHECK(planFrame(cam, lights, s, never).drawnLights == 20);
    }
}

TEST_CASE("frame plan: over 255 lights, regions of tiles number their own lights in 8 bits", "[frame-plan][regions][cpu]") {
    // 8 x 1 tiles. Lights 1..150 reach tile 1, lights 151..300 tile 6, and light 1 (wider) tiles 1 to 6: one
    // split of the 8 tiles into halves gives regions of 151 and 150 lights.
    std::vector<PointLight> lights;
    for (int i = 0; i < 300; ++i)
        lights.push_back(light({i < 150 ? -5.0f : 5.0f, float(i % 150) * 0.1f - 7.5f, 0.0f}, i == 0 ? 2.0f : 1.0f));
    auto tilesOf = [](const glm::vec4& s) {
        if (s.w == 2.0f) return std::vector<int>{1, 2, 3, 4, 5, 6};
        return std::vector<int>{s.x < 0.0f ? 1 : 6};
    };
    FramePlanQueries q = everywhere();
    q.regionsReached = [&](const glm::vec4& s, const IndexRegions& regions) {
        uint32_t bits = 0;
        for (int tile : tilesOf(s)) bits |= 1u << regions.regionOfTile(tile);
        return bits;
    };
    auto settings = [](AutoConfiguration& width) {
        FramePlanSettings s;
        s.tiles = true;
        s.autoWidth = &width;
        s.regionalIndices = true;
        s.tilesX = 8;
        s.tilesY = 1;
        s.tileSize = 16;
        s.tableCapacity = (32 + 1) * 256 - 1;  // the regions' rows and the tile map's
        return s;
    };
    SECTION("two regions") {
        AutoConfiguration width;
        const FramePlan plan = planFrame(testCamera(), lights, settings(width), q);
        REQUIRE(plan.regions.on());
        CHECK(plan.regions.count == 2);
        CHECK(plan.regions.regionOfTiles == std::vector<uint8_t>{0, 0, 0, 0, 1, 1, 1, 1});
        CHECK(plan.regions.tilesX == 8);
        CHECK(plan.drawnLights == 300);
        CHECK(plan.widestList == 151);
        CHECK(plan.indexBits == 8);
        CHECK(plan.tilesNarrowed());
        // Entries in draw order, light 1 once per region; region r's index k is table entry r * 256 + k - 1.
        REQUIRE(plan.volumes.size() == 301);
        CHECK(plan.volumes[0].region == 0);
        CHECK(plan.volumes[1].region == 1);
        CHECK(plan.volumes[0].index == 1);
        CHECK(plan.volumes[1].index == 1);
        REQUIRE(plan.tableLights.size() == 256 + 151);
        REQUIRE(plan.frameLights.size() == plan.tableLights.size());
        int perRegion[2] = {0, 0};
        for (const VolumeLight& v : plan.volumes) {
            REQUIRE((v.region == 0 || v.region == 1));
            CHECK(v.index == uint32_t(++perRegion[v.region]));  // 1..n in draw order within each region
            const uint32_t scene = plan.frameLights[size_t(v.region) * 256 + v.index - 1];
            REQUIRE(scene >= 1);
            CHECK(v.posRadius == glm::vec4(lights[scene - 1].position, lights[scene - 1].radius));
            CHECK(plan.tableLights[size_t(v.region) * 256 + v.index - 1].position == lights[scene - 1].position);
        }
        CHECK(perRegion[0] == 150);
        CHECK(perRegion[1] == 151);
        for (size_t e = 150; e < 256; ++e) {  // between the rows: unused, black
            CHECK(plan.frameLights[e] == 0u);
            CHECK(plan.tableLights[e].color == glm::vec3(0.0f));
        }
    }
    struct Refusal {
        const char* name;
        bool oneTile, regional;
        int tableCapacity;
    };
    const Refusal refusals[] = {
        {"every light in one tile", true, true, (32 + 1) * 256 - 1},
        {"regional indices off", false, false, (32 + 1) * 256 - 1},
        {"a light table without room for the regions' rows", false, true, 300},
    };
    for (const Refusal& r : refusals) {
        DYNAMIC_SECTION("global numbering: " << r.name) {
            AutoConfiguration width;
            FramePlanSettings s = settings(width);
            s.regionalIndices = r.regional;
            s.tableCapacity = r.tableCapacity;
            FramePlanQueries one = q;
            if (r.oneTile) one.regionsReached = [](const glm::vec4&, const IndexRegions& regions) { return 1u << regions.regionOfTile(3); };
            const FramePlan plan = planFrame(testCamera(), lights, s, one);
            CHECK_FALSE(plan.regions.on());
            CHECK(plan.widestList == 300);
            CHECK(plan.indexBits == 16);
            REQUIRE(plan.volumes.size() == 300);
            for (size_t i = 0; i < plan.volumes.size(); ++i) CHECK(plan.volumes[i].index == uint32_t(i + 1));
            CHECK(plan.frameLights.size() == 300);
        }
    }
}
