#pragma once
// Pass 1 of LIDR (and of the reference): opaque depth only. Clears depth and stencil of the bound target.
#include "lidr/scene/camera.h"
#include "lidr/render/gpu_scene.h"

namespace lidr {

class DepthPrepass {
public:
    DepthPrepass();
    void run(const GpuScene& scene, const CameraMatrices& camera) const;

private:
    gl::Program program_;
};

// Attribute bindings every geometry program uses.
const std::vector<std::pair<std::string, GLuint>>& geometryAttributes();

}  // namespace lidr
