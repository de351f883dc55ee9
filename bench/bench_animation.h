#pragma once
// lidr-bench --animation N: every render mode over an animation, frame by frame, as Olsson and Assarsson time BART's
// Robots (Tiled Shading, section 8: Figure 2's frame times, Tables 2-3's average and min / max, Figure 3's lighting
// computations). The modes render each frame in turn (the first one rotating from frame to frame), the moving meshes
// re-placed (placeAnimatedObjects) and the lights and camera taken at the frame's time; some frames are judged
// against the brute-force reference (PSNR, light-pixels dropped from the modes' lists, lighting computations).
// Writes animation.csv, animation.json, animation.md and gnuplot plots (doc/bart.md).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace lidr::bench {

struct AnimationBenchOptions {
    std::vector<std::string> scenes;  // scene names as loadBenchScene takes them (bart-robots-many, an .aff file, ...)
    int frames = 0;                   // sampled evenly over the animation's range, both ends included
    std::pair<int, int> resolution{1920, 1080};
    // Render modes; empty: every mode of the library's registry (renderModeNames) but forward-brute (the reference)
    // and auto (a chooser among the others), tiled twice (with and without per-tile depth bounds).
    std::vector<std::string> modes;
    int referenceFrames = 8;          // frames judged against forward-brute, spread evenly (0: none)
    uint32_t seed = 1;
    std::string bart;                 // where bart-robots-* are read from (bartSceneFile)
    std::string outDir = "bench-out", context = "auto", commandLine;
    bool plots = true;
};

// The run; returns the process exit status. Throws lidr::Error for bad options or a scene without animation.
int runAnimationBench(const AnimationBenchOptions& options);

}  // namespace lidr::bench
