#pragma once
// Pass 3 of LIDR: the ordinary forward pass. Each fragment unpacks its light indices from the index
// targets (the scheme's unpack shader) and shades with those lights from the light table.
#include "lidr/camera.h"
#include "lidr/gpu_scene.h"
#include "lidr/light_table.h"
#include "lidr/light_volume_pass.h"
#include "lidr/packing_scheme.h"
#include "lidr/render_targets.h"
#include "lidr/renderer.h"

namespace lidr {

class ForwardPass {
public:
    ForwardPass(const PackingScheme& scheme, const LightTable& table);
    // Draws opaque geometry with depth EQUAL against the pre-pass depth.
    void run(const RenderTargets& targets, const IndexTargets& indices, const GpuScene& scene,
             const LightTable& table, const CameraMatrices& camera, const ShadingParameters& shading) const;

private:
    gl::Program program_;
};

// Sets the per-frame uniforms of shading.glsl (eye, ambient).
void setShadingUniforms(const gl::Program& program, const CameraMatrices& camera, const ShadingParameters& shading);

}  // namespace lidr
