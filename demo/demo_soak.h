#pragma once
// lidr-demo --frames N --time-step S: a long run with time advancing, for memory, determinism and GL object checks.
#include <string>

#include "demo_options.h"

namespace lidr::demo {

// Renders frames 0..frames-1 of `sceneChoice` at times time + k * timeStep with the chosen mode, no reference.
// Writes outDir/soak.csv (frame, time, FNV-1a 64-bit hash of the image, resident memory in KiB, live GL objects)
// and outDir/soak.json (frames, step, memory at the start and end of the run, GL objects left after the renderer
// is destroyed), and prints a summary. Returns 0, or 1 when GL objects outlive the renderer.
int runSoak(const SceneChoice& sceneChoice, const RendererChoice& rc, const std::string& outDir, int frames,
            double timeStep);

}  // namespace lidr::demo
