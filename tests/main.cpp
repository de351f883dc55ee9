// Catch2 v2 runner for the lidr suite. The GL context is made once per process (gl_test_context.cpp).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "gl_test_context.h"

int main(int argc, char* argv[]) {
    const int result = Catch::Session().run(argc, argv);
    lidr::test::releaseTestContext();
    return result;
}
