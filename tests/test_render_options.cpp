// The renderer settings' table (lidr/modes/render_options.h) and the modes' table (render_mode_names.h): what the
// tools' command lines, the viewer and the web page's URL query are made from. No GL needed.
#include <catch2/catch.hpp>

#include "lidr/base/error.h"
#include "lidr/modes/render_options.h"
#include "lidr/modes/shadow_choice.h"
#include "lidr/scene/default_scene.h"

using namespace lidr;

TEST_CASE("every mode has one row with a description, and the option table names each mode it uses", "[options]") {
    REQUIRE(renderModes().size() == renderModeNames().size());
    for (const RenderModeInfo& m : renderModes()) {
        CHECK(isRenderModeName(m.name));
        CHECK(!std::string(m.description).empty());
        CHECK(renderModeDescription(m.name) == m.description);
    }
    CHECK(renderModeDescription("warp").empty());
    const RenderOption* mode = findRenderOption("mode");
    REQUIRE(mode);
    CHECK(mode->choices == renderModeNames());
    for (const RenderOption& o : renderOptions()) {
        INFO(o.name);
        CHECK(findRenderOption(o.name) == &o);  // names are unique
        CHECK(!o.help.empty());
        for (const std::string& m : o.modes) CHECK(isRenderModeName(m));
        if (!o.defaultValue.empty()) CHECK_NOTHROW(checkRenderOption(o, o.defaultValue));
        if (o.type == RenderOptionType::Choice)
            for (const std::string& c : o.choices) CHECK_NOTHROW(checkRenderOption(o, c));
    }
}

TEST_CASE("setRenderOption checks type, range and choices, naming the option", "[options]") {
    RenderOptionValues v;
    setRenderOption(v, "tile-size", "16");
    setRenderOption(v, "half-z", "on");
    setRenderOption(v, "exposure", "-1.5");
    CHECK(v.at("tile-size") == "16");
    CHECK(v.at("half-z") == "on");
    CHECK_THROWS_WITH(setRenderOption(v, "budget", "3"), "--budget must be auto, 1, 2, 4, 8, 16 or 32, got '3'");
    CHECK_THROWS_WITH(setRenderOption(v, "cluster-slices", "65"), "--cluster-slices must be 1..64, got 65");
    CHECK_THROWS_WITH(setRenderOption(v, "cluster-tile-size", "x"), "--cluster-tile-size must be a whole number, got 'x'");
    CHECK_THROWS_WITH(setRenderOption(v, "exposure", "nan"), Catch::Contains("--exposure must be a finite number"));
    CHECK_THROWS_WITH(setRenderOption(v, "half-z", "maybe"), "--half-z must be on or off, got 'maybe'");
    CHECK_THROWS_WITH(setRenderOption(v, "bogus", "1"), Catch::Contains("unknown renderer setting 'bogus'"));
    CHECK(v.at("tile-size") == "16");  // a refused value changes nothing
    CHECK(renderOptionValue(v, "budget") == "auto");  // left out: the default
}

TEST_CASE("a URL query sets the renderer settings it names and hands back the rest", "[options]") {
    RenderOptionValues v;
    const auto others = setRenderOptionsFromQuery(v, "?mode=tiled&tile-size=16&half-z&model=my%20room.glb&bench=3");
    CHECK(v.at("mode") == "tiled");
    CHECK(v.at("tile-size") == "16");
    CHECK(v.at("half-z") == "on");
    REQUIRE(others.size() == 2);
    CHECK(others[0] == std::make_pair(std::string("model"), std::string("my room.glb")));
    CHECK(others[1] == std::make_pair(std::string("bench"), std::string("3")));
    RenderOptionValues bad;
    CHECK_THROWS_WITH(setRenderOptionsFromQuery(bad, "mode=warp"), Catch::Contains("--mode must be lidr"));
}

TEST_CASE("renderModeOptionsFrom: defaults are the library's, settings reach their mode, contradictions refused",
          "[options]") {
    DefaultSceneOptions so;
    const Scene scene = makeDefaultScene(so);
    const RenderModeOptions defaults = renderModeOptionsFrom({}, scene);
    const RenderModeOptions library;
    CHECK(defaults.mode == scene.renderMode);
    CHECK(defaults.tiled.tileSize == TiledOptions{}.tileSize);
    CHECK(defaults.lidr.packing.autoScheme());
    CHECK(defaults.lidr.tileCulledVolumes == LidrOptions{}.tileCulledVolumes);
    CHECK(defaults.lidr.volumeTileSize == LidrOptions{}.volumeTileSize);
    CHECK(defaults.multipass.halfFloatAccumulation == library.multipass.halfFloatAccumulation);

    RenderOptionValues v;
    setRenderOption(v, "mode", "clustered");
    setRenderOption(v, "cluster-slices", "8");
    setRenderOption(v, "cluster-occupancy", "on");
    const RenderModeOptions clustered = renderModeOptionsFrom(v, scene);
    CHECK(clustered.mode == "clustered");
    CHECK(clustered.clustered.slices == 8);
    CHECK(clustered.clustered.occupiedClusters);

    setRenderOption(v, "mode", "tiled");
    CHECK_THROWS_WITH(renderModeOptionsFrom(v, scene), Catch::Contains("--cluster-* options set the clustered mode's grid"));
    RenderOptionValues packing;
    setRenderOption(packing, "budget", "4");
    CHECK_THROWS_WITH(renderModeOptionsFrom(packing, scene), Catch::Contains("--scheme auto chooses the budget"));
    setRenderOption(packing, "scheme", "bitshift");
    CHECK(renderModeOptionsFrom(packing, scene).lidr.packing.budget == 4);
}

TEST_CASE("shadow settings are read and checked by the library (shadowChoiceFrom)", "[options][shadows]") {
    const auto refusal = [](const RenderOptionValues& values, const std::string& mode) {
        try {
            shadowChoiceFrom(values, mode);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    CHECK(shadowChoiceFrom({}, "lidr").casters == ShadowChoice::Casters::Off);
    const ShadowChoice eight = shadowChoiceFrom({{"shadows", "8"}, {"shadow-atlas", "2048:256"}}, "lidr");
    CHECK(eight.casters == ShadowChoice::Casters::Brightest);
    CHECK(eight.brightest == 8);
    CHECK(eight.settings.enabled);
    CHECK(eight.settings.atlas.size == 2048);
    CHECK(eight.settings.atlas.tileSize == 256);
    CHECK_FALSE(eight.automaticTile);
    CHECK(shadowChoiceFrom({{"shadows", "scene"}, {"shadow-filter", "pcf"}}, "tiled").settings.filtered);
    CHECK_THAT(refusal({{"shadows", "many"}}, "lidr"), Catch::Contains("--shadows must be off, scene or a number"));
    CHECK_THAT(refusal({{"shadow-filter", "pcf"}}, "lidr"), Catch::Contains("add --shadows scene"));
    CHECK_THAT(refusal({{"shadows", "4"}, {"shadow-lookup", "volume"}}, "tiled"),
               Catch::Contains("--shadow-lookup says where LIDR applies shadows"));
    CHECK_THAT(refusal({{"shadows", "4"}, {"shadow-atlas", "3000"}}, "lidr"),
               Catch::Contains("SIZE must be a power of two"));
    CHECK_THAT(refusal({{"shadows", "4"}, {"shadow-atlas", "1024:2048"}}, "lidr"),
               Catch::Contains("TILE must be a power of two from 16 to SIZE"));
}

TEST_CASE("the deferred modes' settings are table rows that reach their options", "[options][deferred]") {
    const RenderOption* stencil = findRenderOption("deferred-stencil");
    const RenderOption* gBuffer = findRenderOption("g-buffer");
    REQUIRE(stencil);
    REQUIRE(gBuffer);
    CHECK(stencil->usedBy("deferred"));
    CHECK(!stencil->usedBy("tiled-deferred"));
    CHECK(gBuffer->usedBy("deferred"));
    CHECK(gBuffer->usedBy("tiled-deferred"));
    CHECK(!gBuffer->usedBy("lidr"));
    CHECK(findRenderOption("tile-size")->usedBy("tiled-deferred"));
    RenderOptionValues v;
    CHECK_THROWS_WITH(setRenderOption(v, "deferred-stencil", "maybe"), "--deferred-stencil must be on or off, got 'maybe'");
    CHECK_THROWS_WITH(setRenderOption(v, "g-buffer", "rgba12"),
                      "--g-buffer must be auto, rgba16f, rgba32f or rgba8, got 'rgba12'");
    const Scene scene = makeDefaultScene();
    CHECK(!renderModeOptionsFrom(v, scene).deferred.stencil);  // the default: off (measured, doc/deferred.md)
    CHECK(renderModeOptionsFrom(v, scene).deferred.format == GBufferFormat::Auto);  // rgba16f or rgba8 by context
    setRenderOption(v, "mode", "deferred");
    setRenderOption(v, "deferred-stencil", "on");
    setRenderOption(v, "g-buffer", "rgba32f");
    setRenderOption(v, "tile-size", "16");
    const RenderModeOptions o = renderModeOptionsFrom(v, scene);
    CHECK(o.deferred.stencil);
    CHECK(o.deferred.format == GBufferFormat::Float);
    CHECK(o.tiledDeferred.format == GBufferFormat::Float);
    CHECK(o.tiledDeferred.tileSize == 16);
    setRenderOption(v, "g-buffer", "rgba8");
    CHECK(renderModeOptionsFrom(v, scene).tiledDeferred.format == GBufferFormat::Unorm8);
}
