#pragma once
// One GL context for the whole test process (LIDR_CONTEXT picks the backend; CTest sets it to egl).
// Tests that need GL call testContext(); creating it fails the test with the reason if no context exists.
#include <string>

#include "lidr/platform/context.h"

namespace lidr::test {

GlContext& testContext();
// Destroys the context while the GL library is whole: main() calls it after the run. Left to static
// destruction, it ran after Mesa's own exit handlers had stopped llvmpipe's threads, and OSMesa's unbind
// crashed at exit (exit status 139 after every test had passed).
void releaseTestContext();
const GlInfo& testGl();
bool isSoftpipe();
// Test image sizes: smaller on softpipe, whose rasteriser is an interpreter.
int testWidth();
int testHeight();
std::string sourcePath(const std::string& relative);

// Representative runs (doc/stability.md, "Where each test runs"): CTest's softpipe, OSMesa and sanitizer entries run
// only the [every-gl] cases, with LIDR_TEST_ROWS=representative, and those cases run only the rows of their tables
// that stand for the rest (each scheme, volume test, mode, light type, shadow setting and context path at least
// once); every other run takes every row.
bool representativeRun();
// Whether this run takes a table row: always, or in a representative run only where `representative`. A case skips
// the rows it does not take with `if (!takeRow(...)) return;` right after its GENERATEs. takeRow counts the rows
// of the running case: a representative run whose filter left a case no row fails (main.cpp).
bool takeRow(bool representative);
struct RowCount {
    int taken = 0, skipped = 0;
};
RowCount& rowsOfCurrentCase();

}  // namespace lidr::test
