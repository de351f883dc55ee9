#pragma once
// BART's AFF scenes (Lext, Assarsson and Moeller, "BART: A Benchmark for Animated Ray Tracing"; a superset of Eric
// Haines' NFF), such as the Robots scene of ../shared/bart-robots: the whole scene with its includes, PPM
// textures, materials, lights, camera and keyframe animation. Every problem is an lidr::Error "<file>:<line>:
// <problem>" naming the file it is in; what the format has and lidr does not draw is refused by name. What is read
// and how it maps onto lidr: doc/scene-format.md, "AFF (BART)".
#include <string>

#include "lidr/scene/scene.h"

namespace lidr {

struct AffImportOptions {
    // `i LEVEL FILE` includes a file when LEVEL <= this (BART's detail level; `d LEVEL` in a file sets it too).
    int detailLevel = 0;
};

// The scene: geometry posed at the animation's start (`a START END FRAMES`; 0 without it), Scene::time that start,
// Scene::animation its nodes, keyframes, carried lights and camera. Not yet validated (loadScene validates).
Scene loadAff(const std::string& path, const AffImportOptions& options = {});

// Limits a file is checked against while it is read, so a small file cannot ask for unbounded work.
constexpr int maxAffIncludeDepth = 32;
constexpr size_t maxAffIncludes = 100000;   // files included in all (BART's Robots: 835)
constexpr size_t maxAffNodes = 1000000;     // transforms (xs, x) in all
constexpr size_t maxAffKeys = 1000000;      // keyframes in one track

}  // namespace lidr
