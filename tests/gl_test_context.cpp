#include "gl_test_context.h"

#include <cstdlib>
#include <memory>

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

std::string sourcePath(const std::string& relative) { return std::string(LIDR_SOURCE_DIR) + "/" + relative; }

}  // namespace lidr::test
