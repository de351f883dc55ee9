// Catch2 v2 runner for the lidr suite. The GL context is made once per process (gl_test_context.cpp).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

int main(int argc, char* argv[]) {
    return Catch::Session().run(argc, argv);
}
