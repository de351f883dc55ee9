#pragma once
// The page's own check (web.chromium): fixed frames of the room rendered with LIDR in the browser, their index
// lists decoded with the scheme's CPU model against the CPU truth of which lights touch each pixel, and the
// image against the brute-force reference, with the native tests' bounds (tests/test_lidr_core.cpp).
#include <string>

#include "lidr/gl/gl_info.h"

namespace lidr::web {

struct CheckResult {
    bool passed = false;
    std::string report;  // one line per case, then "PASS ..." or "FAIL ..." with the figures
};

// Renders and checks; never throws (a library error is a FAIL naming it).
CheckResult runPageCheck(const GlInfo& info, int width, int height);

}  // namespace lidr::web
