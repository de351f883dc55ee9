#pragma once
// Scenes with a known light overlap, for the packing-scheme tests and lidr-bench.
#include <cstdint>

#include "lidr/scene/scene.h"

namespace lidr {

struct ControlledOverlapOptions {
    int overlap = 4;         // k: lights covering every lit pixel
    int maxLights = 255;     // the index width's limit; clusters are dropped (and k capped) to fit
    int clusters = 9;        // up to 9 clusters on a 3 x 3 grid
    int width = 320, height = 240;
    uint32_t seed = 1;       // light colours and priorities
};

// A floor seen from above with clusters of k coincident lights (same centre and radius, different colours
// and distinct priorities): every pixel a cluster's light touches or marks is touched or marked by exactly
// the cluster's k lights, under either volume test, and clusters share no pixel (their screen footprints are
// apart). k is capped at maxLights (a 4-bit width holds 15 lights), clusters at maxLights / k.
Scene makeControlledOverlapScene(const ControlledOverlapOptions& options);

// The back-face trap for CPU sorting: a wall, light 1 in front of it lighting it, light 2 behind it, spheres
// apart but screen footprints overlapping. Under the back-face test light 2 also marks the wall pixels in
// front of it, where light 1 marks them too.
Scene makeOccludedLightScene(int width, int height);

}  // namespace lidr
