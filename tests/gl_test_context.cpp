#include "gl_test_context.h"

#include <cstdlib>
#include <memory>
#include <string>

#include <catch2/catch.hpp>

#include "lidr/base/error.h"

namespace lidr::test {

namespace {
std::unique_ptr<GlContext>& contextSlot() {
    static std::unique_ptr<GlContext> context;
    return context;
}
}  // namespace

void releaseTestContext() { contextSlot().reset(); }

GlContext& testContext() {
    std::unique_ptr<GlContext>& context = contextSlot();
    static bool reported = false;
    if (!context) {
        context = GlContext::create();
        if (!reported) {
            reported = true;
            WARN("GL context: " << context->info().summary());
        }
        // CTest states which implementation each run is for; make sure the run really got it.
        if (const char* want = std::getenv("LIDR_EXPECT_RENDERER"))
            REQUIRE(context->info().renderer.find(want) != std::string::npos);
        if (const char* want = std::getenv("LIDR_EXPECT_GL"))
            REQUIRE(context->info().version.rfind(want, 0) == 0);
    }
    context->makeCurrent();
    return *context;
}

const GlInfo& testGl() { return testContext().info(); }

bool isSoftpipe() { return testGl().renderer.find("softpipe") != std::string::npos; }
int testWidth() { return isSoftpipe() ? 128 : 256; }
int testHeight() { return isSoftpipe() ? 96 : 192; }

bool representativeRun() {
    static const bool representative = [] {
        const std::string rows = std::getenv("LIDR_TEST_ROWS") ? std::getenv("LIDR_TEST_ROWS") : "";
        if (rows != "" && rows != "all" && rows != "representative")
            throw Error("LIDR_TEST_ROWS is 'all' (the default) or 'representative', got '" + rows + "'");
        return rows == "representative";
    }();
    return representative;
}

RowCount& rowsOfCurrentCase() {
    static RowCount rows;
    return rows;
}

bool takeRow(bool representative) {
    const bool take = representative || !representativeRun();
    ++(take ? rowsOfCurrentCase().taken : rowsOfCurrentCase().skipped);
    return take;
}

std::string sourcePath(const std::string& relative) { return std::string(LIDR_SOURCE_DIR) + "/" + relative; }

}  // namespace lidr::test
