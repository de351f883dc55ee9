// The web page's URL query (web/page_query.h) and its bench table (web/page_bench.h): plain C++, checked natively.
#include <catch2/catch.hpp>

#include <set>
#include <string>

#include "lidr/base/error.h"
#include "page_bench.h"
#include "page_query.h"

using namespace lidr;
using namespace lidr::web;

TEST_CASE("web page: the URL query's keys, settings in order, page keys read", "[web][cpu]") {
    const PageQuery q = parsePageQuery(
        "?mode=tiled&scene=models%2Fmy%20model.glb&lights=1024&width=800&height=600&bench=3"
        "&bench-modes=lidr,tiled&view=difference&index-bits=16&environment=none");
    // The renderer settings as the option table set them, then the page's own; applied together by the page.
    CHECK(q.options == RenderOptionValues{{"index-bits", "16"}, {"mode", "tiled"}});
    CHECK(q.settings == std::vector<std::pair<std::string, std::string>>{
                            {"index-bits", "16"}, {"mode", "tiled"}, {"view", "difference"}});
    CHECK(q.scene == "models/my model.glb");
    CHECK(q.lights == 1024);
    CHECK(q.width == 800);
    CHECK(q.height == 600);
    CHECK(q.bench == 3);
    CHECK(q.benchModes == std::vector<std::string>{"lidr", "tiled"});
    CHECK(q.environment == "none");
    CHECK_FALSE(q.check);

    const PageQuery empty = parsePageQuery("");
    CHECK(empty.settings.empty());
    CHECK(empty.width == 0);
    CHECK(empty.bench == 0);
    CHECK(parsePageQuery("?check").check);
    CHECK(parsePageQuery("check-model=models/check.glb&lights=256").checkModel == "models/check.glb");
    CHECK(urlDecode("a+b%41%zz%4") == "a bA%zz%4");
}

TEST_CASE("web page: a bad URL query is refused naming the key", "[web][cpu][bad-input]") {
    const auto refusal = [](const std::string& query) {
        try {
            parsePageQuery(query);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    CHECK_THAT(refusal("?modes=lidr"), Catch::Contains("unknown option 'modes'") && Catch::Contains("bench-modes"));
    // Renderer settings: the option table's checks and messages (lidr/modes/render_options.h).
    CHECK_THAT(refusal("?budget=3"), Catch::Contains("--budget must be") && Catch::Contains("got '3'"));
    CHECK_THAT(refusal("?mode=fastest"), Catch::Contains("--mode must be") && Catch::Contains("got 'fastest'"));
    CHECK_THAT(refusal("?tile-size=16"), Catch::Contains("tile-size is a renderer option the page has no control for"));
    CHECK_THAT(refusal("?width=15"), Catch::Contains("width takes a whole number from 16 to 4096, got '15'"));
    CHECK_THAT(refusal("?height=4097"), Catch::Contains("height takes a whole number from 16 to 4096"));
    CHECK_THAT(refusal("?bench=0"), Catch::Contains("bench takes a whole number from 1 to 10000, got '0'"));
    CHECK_THAT(refusal("?bench=2x"), Catch::Contains("bench takes a whole number"));
    CHECK_THAT(refusal("?lights=-3"), Catch::Contains("lights takes a whole number from 1 to 65535"));
    CHECK_THAT(refusal("?mode=lidr&mode=tiled"), Catch::Contains("mode given twice"));
    CHECK_THAT(refusal("?bench=2&bench-modes=,"), Catch::Contains("bench-modes takes a list of modes"));
}

TEST_CASE("web page: the bench table has a row per mode with its figures", "[web][cpu]") {
    const std::string table = benchTable("320x240, built-in room, 255 lights",
                                         {{"lidr", {4.0, 2.0, 3.0}, ""}, {"tiled", {5.0, 7.0}, ""},
                                          {"deferred", {}, "mode 'deferred' needs float targets"}});
    CHECK_THAT(table, Catch::StartsWith("lidr-web bench: 320x240, built-in room, 255 lights\n"));
    // lidr: mean 3, median 3, min 2, max 4, 333.3 fps; tiled: mean 6, median 6 (of two), min 5, max 7
    CHECK_THAT(table, Catch::Contains("lidr                    3      3.00      3.00      2.00      4.00    333.3\n"));
    CHECK_THAT(table, Catch::Contains("tiled                   2      6.00      6.00      5.00      7.00    166.7\n"));
    CHECK_THAT(table, Catch::Contains("deferred           refused: mode 'deferred' needs float targets\n"));
}

TEST_CASE("web page: every option of the library's table is taken or refused by name in the URL query",
          "[web][options][cpu]") {
    // The page's controls: the table's mode, scheme, budget, index-bits, shadows, shadow-filter.
    const std::set<std::string> controls = {"mode", "scheme", "budget", "index-bits", "shadows", "shadow-filter"};
    size_t taken = 0;
    for (const RenderOption& option : renderOptions()) {
        const std::string value = !option.defaultValue.empty() ? option.defaultValue
                                  : !option.choices.empty()    ? option.choices.front()
                                  : option.type == RenderOptionType::Flag ? "on"
                                                                          : "";
        if (value.empty()) continue;  // a Text option without a default or example: nothing to give
        INFO(option.name << "=" << value);
        if (controls.count(option.name)) {
            const PageQuery q = parsePageQuery(option.name + "=" + value);
            CHECK(q.options.at(option.name) == value);
            REQUIRE(q.settings.size() == 1);
            CHECK(q.settings[0].first == option.name);
            ++taken;
        } else {
            CHECK_THROWS_WITH(parsePageQuery(option.name + "=" + value),
                              Catch::Contains(option.name + " is a renderer option the page has no control for"));
        }
    }
    CHECK(taken == controls.size());
}
