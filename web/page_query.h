#pragma once
// The web page's URL query (doc/web.md, "Options by URL"), read by one function: parsePageQuery. The renderer's
// settings in it go through the library's option table (lidr/modes/render_options.h, setRenderOptionsFromQuery:
// the same names, checks and messages as lidr-demo's and lidr-viewer's command lines); the other keys are the
// page's. Plain C++ (no emscripten), so the native tests check it (tests/test_web_query.cpp).
#include <string>
#include <utility>
#include <vector>

#include "lidr/modes/render_options.h"

namespace lidr::web {

struct PageQuery {
    // The renderer settings given, as the option table checked them (its names: mode, scheme, budget, ...).
    RenderOptionValues options;
    // The settings lidr_web_set takes, unchecked beyond the table's checks: the table's options the page has
    // controls for (mode, scheme, budget, index-bits, shadows, shadow-filter), then the page's own (view,
    // environment-intensity, paused). Applied together, by the page's applySettings and the library.
    std::vector<std::pair<std::string, std::string>> settings;
    std::string scene;        // a model to open, by URL relative to the page; empty: the built-in room
    std::string environment;  // auto, default, none or the URL of a .hdr; empty: not given
    int lights = 0;           // 0: a model's own lights (256 when it has none), the room's 255
    int width = 0, height = 0;  // the image's size; 0: it follows the window
    int bench = 0;              // a timing run of this many frames per mode; 0: none
    std::vector<std::string> benchModes;  // the modes it times (bench-modes=a,b); empty: every mode
    // CTest web.chromium's runs (web/run_chromium_check.py): the page's own check, the model check's files.
    bool check = false;
    std::string checkModel, checkLarge, checkHuge;
};

// Limits of the query's numbers.
constexpr int kMinPageSide = 16, kMaxPageSide = 4096;
constexpr int kMaxBenchFrames = 10000;

// "%41+b" -> "A b" (application/x-www-form-urlencoded, as URLSearchParams reads it); a bad escape is kept as it is.
std::string urlDecode(const std::string& text);

// "lidr,,tiled" -> {"lidr", "tiled"}: the items of a comma-separated list, empty ones left out.
std::vector<std::string> commaList(const std::string& value);

// The query ("?mode=tiled&lights=1024", the '?' optional; keys and values URL-decoded). Throws lidr::Error naming
// the key for a renderer setting the table refuses (its message), one the page has no control for, an unknown key
// (listing the page's keys), a key given twice, or a number out of its range.
PageQuery parsePageQuery(const std::string& query);

}  // namespace lidr::web
