#pragma once
// lidr-demo --headless: one frame of the chosen mode drawn offscreen, timed, judged against the brute-force
// reference, and written as images, summary.json and summary.txt. LIDR's run adds its index lists, debug views and
// --dump; every other mode goes through the Renderer interface.
#include <string>

#include "demo_options.h"

namespace lidr::demo {

// Loads the scene, checks every setting before any context, and runs the mode's headless run; returns the exit code.
int runHeadless(const SceneChoice& sceneChoice, const RendererChoice& rc, const std::string& outDir,
                const std::string& dumpDir, int frames, bool withReference);

}  // namespace lidr::demo
