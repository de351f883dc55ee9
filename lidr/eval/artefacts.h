#pragma once
// Raw frame artefacts for independent checking (lidr-demo --dump DIR): index targets as lossless RGBA8
// PNG, depth as one-channel float PFM, the light table and camera matrices as JSON.
#include <string>
#include <vector>

#include "lidr/scene/camera.h"
#include "lidr/base/image.h"
#include "lidr/technique/packing_scheme.h"
#include "lidr/scene/scene.h"

namespace lidr {

struct FrameArtefacts {
    std::vector<ImageRGBA8> indexTargets;
    ImageFloat depth;
    std::vector<uint8_t> lightCounts;  // may be empty
    CameraMatrices camera;
    std::vector<PointLight> lights;
    std::vector<uint32_t> drawOrder;
};

// Writes into `dir` (created if missing): index_target<i>.png, depth.pfm, light_counts.png (if any),
// lights.json, camera.json, packing.json. Throws lidr::Error if the folder cannot be written.
void writeFrameArtefacts(const std::string& dir, const FrameArtefacts& a, const PackingScheme& scheme);

}  // namespace lidr
