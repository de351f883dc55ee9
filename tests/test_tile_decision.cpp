// The tile decision of a LIDR frame (lidr/technique/tile_decision.h) on the CPU: tiles from a screen of the
// lights' rectangles, giving way to volume meshes where a tile frame measured too small a saving, until the
// re-measure; the saving scales with the lights' area and narrowing keeps the tiles. The GL side (the same
// lists and images either way, the decision taken frame by frame) is in tests/test_volume_tiles.cpp.
#include <catch2/catch.hpp>

#include "lidr/technique/tile_decision.h"

using namespace lidr;

namespace {
constexpr double kScreen = 512.0 * 384.0;  // pixels

// A tile frame that saved `saving` screens at `rectArea` screens of the lights' rectangles (one draw per light).
TileDecision::TileFrame tileFrame(double saving, double rectArea, bool narrower = false) {
    TileDecision::TileFrame f;
    f.rectArea = rectArea * kScreen;
    f.meshRectArea = (saving + 1.0) * kScreen;
    f.quadPixels = long(kScreen);
    f.volumes = 100;
    f.stepLights = 100;
    f.narrower = narrower;
    return f;
}
}  // namespace

TEST_CASE("tile decision: tiles from a screen of the lights' rectangles", "[tile-decision][volume-tiles][cpu]") {
    const TileDecision d;
    CHECK_FALSE(d.measured());
    CHECK(d.lastSavingScreens() == -1.0);
    const TileDecision::Choice below = d.decide(0.99 * kScreen, kScreen);
    CHECK_FALSE(below.tiles);
    CHECK_FALSE(below.skippedForSaving);  // too small an area is no measured saving
    CHECK(below.rectArea == 0.99 * kScreen);
    const TileDecision::Choice at = d.decide(TileDecision::kMinArea * kScreen, kScreen);
    CHECK(at.tiles);
    CHECK_FALSE(at.skippedForSaving);
}

TEST_CASE("tile decision: the saving is the meshes' rectangles in every draw, less the quads", "[tile-decision][volume-tiles][cpu]") {
    struct Case {
        const char* name;
        double meshRectArea;  // screens
        long quadPixels;      // screens
        long stepLights;
        size_t volumes;
        double saving;        // screens
    };
    const Case cases[] = {
        {"one draw per light", 3.0, 1, 100, 100, 2.0},
        {"two rank windows: every light twice", 3.0, 1, 200, 100, 5.0},
        {"quads over what the meshes cover: negative", 1.0, 2, 50, 50, -1.0},
        {"no volume drawn (the tiles culled every light): the meshes' rectangles once", 4.0, 0, 0, 0, 4.0},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        TileDecision::TileFrame f;
        f.meshRectArea = c.meshRectArea * kScreen;
        f.quadPixels = long(c.quadPixels * kScreen);
        f.stepLights = c.stepLights;
        f.volumes = c.volumes;
        CHECK(TileDecision::savingScreens(f, kScreen) == Approx(c.saving));
        TileDecision d;
        d.recordTileFrame(f, kScreen);
        CHECK(d.measured());
        CHECK(d.lastSavingScreens() == Approx(c.saving));
    }
}

TEST_CASE("tile decision: a small saving gives way to volume meshes until the re-measure", "[tile-decision][volume-tiles][cpu]") {
    TileDecision d;
    d.recordMeshFrame();  // before any tile frame: nothing to count from
    CHECK(d.framesSinceMeasured() == 0);
    d.recordTileFrame(tileFrame(0.5, 2.0), kScreen);
    REQUIRE(d.lastSavingScreens() == Approx(0.5));
    for (int frame = 1; frame <= TileDecision::kRecheckFrames; ++frame) {
        INFO("frame " << frame << " after the tile frame");
        const TileDecision::Choice c = d.decide(2.0 * kScreen, kScreen);
        CHECK_FALSE(c.tiles);
        CHECK(c.skippedForSaving);
        d.recordMeshFrame();
        CHECK(d.lastSavingScreens() == Approx(0.5));  // the last measurement stands
    }
    const TileDecision::Choice again = d.decide(2.0 * kScreen, kScreen);  // kRecheckFrames later: measure again
    CHECK(again.tiles);
    CHECK_FALSE(again.skippedForSaving);
    d.recordTileFrame(tileFrame(2.0, 2.0), kScreen);  // it saves more now: tiles stay
    CHECK(d.framesSinceMeasured() == 0);
    CHECK(d.decide(2.0 * kScreen, kScreen).tiles);
}

TEST_CASE("tile decision: the saving scales with the lights' area; tiles that narrow the index stay", "[tile-decision][volume-tiles][cpu]") {
    struct Case {
        const char* name;
        double saving, measuredArea;  // the tile frame's
        bool narrower;
        double area;                  // this frame's, screens
        bool tiles, skipped;
    };
    const Case cases[] = {
        {"saving 0.5 at 2 screens, now 3: 0.75", 0.5, 2.0, false, 3.0, true, false},
        {"saving 0.5 at 2 screens, now 2.9: under 0.75", 0.5, 2.0, false, 2.9, false, true},
        {"saving 1 at 2 screens, now 1.4: 0.7", 1.0, 2.0, false, 1.4, false, true},
        {"no saving, but the tiles narrowed the width", 0.0, 2.0, true, 2.0, true, false},
        {"narrowed, but under a screen of rectangles", 0.0, 2.0, true, 0.9, false, false},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        TileDecision d;
        d.recordTileFrame(tileFrame(c.saving, c.measuredArea, c.narrower), kScreen);
        const TileDecision::Choice choice = d.decide(c.area * kScreen, kScreen);
        CHECK(choice.tiles == c.tiles);
        CHECK(choice.skippedForSaving == c.skipped);
    }
}

TEST_CASE("tile decision: a light's rectangle is what its sphere covers on screen", "[tile-decision][volume-tiles][cpu]") {
    Camera camera;
    camera.position = glm::vec3(0.0f, 0.0f, 10.0f);
    const CameraMatrices cam = cameraMatrices(camera, 64, 48);
    PointLight around;  // the eye inside: the whole screen
    around.position = camera.position;
    around.radius = 2.0f;
    PointLight behind;  // wholly behind the eye: nothing
    behind.position = glm::vec3(0.0f, 0.0f, 20.0f);
    behind.radius = 1.0f;
    PointLight small;
    small.radius = 0.5f;
    CHECK(sphereRectPixels(cam, around) == 64.0 * 48.0);
    CHECK(sphereRectPixels(cam, behind) == 0.0);
    const double smallPixels = sphereRectPixels(cam, small);
    CHECK(smallPixels > 0.0);
    CHECK(smallPixels < 64.0 * 48.0 / 4.0);
    CHECK(lightRectArea(cam, {around, behind, small}) == 64.0 * 48.0 + smallPixels);
}
