#pragma once
// One GL context for the whole test process (LIDR_CONTEXT picks the backend; CTest sets it to egl).
// Tests that need GL call testContext(); creating it fails the test with the reason if no context exists.
#include <string>

#include "lidr/platform/context.h"

namespace lidr::test {

GlContext& testContext();
const GlInfo& testGl();
bool isSoftpipe();
// Test image sizes: smaller on softpipe, whose rasteriser is an interpreter.
int testWidth();
int testHeight();
std::string sourcePath(const std::string& relative);

}  // namespace lidr::test
