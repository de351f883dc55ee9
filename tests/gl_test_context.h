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

}  // namespace lidr::test
