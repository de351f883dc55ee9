// Catch2 v2 runner for the lidr suite. The GL context is made once per process (gl_test_context.cpp).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "gl_test_context.h"

#include <cstdio>
#include <string>
#include <vector>

namespace {
// Cases whose table rows the representative run's filter (takeRow) skipped, every one: a renamed row or a
// mistyped filter would otherwise leave a case checking nothing, and passing.
std::vector<std::string>& casesWithoutRows() {
    static std::vector<std::string> cases;
    return cases;
}

struct RowListener : Catch::TestEventListenerBase {
    using TestEventListenerBase::TestEventListenerBase;
    void testCaseStarting(const Catch::TestCaseInfo&) override { lidr::test::rowsOfCurrentCase() = {}; }
    void testCaseEnded(const Catch::TestCaseStats& stats) override {
        const lidr::test::RowCount rows = lidr::test::rowsOfCurrentCase();
        if (rows.skipped > 0 && rows.taken == 0) casesWithoutRows().push_back(stats.testInfo.name);
    }
};
CATCH_REGISTER_LISTENER(RowListener)
}  // namespace

int main(int argc, char* argv[]) {
    int result = Catch::Session().run(argc, argv);
    lidr::test::releaseTestContext();
    for (const std::string& name : casesWithoutRows()) {
        std::fprintf(stderr, "lidr-tests: '%s' ran none of its table's rows (takeRow left every row out)\n", name.c_str());
        result = result ? result : 1;
    }
    return result;
}
