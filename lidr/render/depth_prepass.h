#pragma once
// Every mode's depth pre-pass (FrameResources::drawDepthPrepass): opaque depth only; clears the bound depth-stencil.
#include "lidr/scene/camera.h"
#include "lidr/gl/shader_source.h"
#include "lidr/render/gpu_scene.h"

namespace lidr {

// Depth precision emulated inside the DEPTH24_STENCIL8 buffer (LidrOptions::emulatedDepthBits): every LIDR
// fragment shader that writes or tests depth includes lidr_depth.glsl, and bits 16 substitutes
// lidr_depth_emulated.glsl (the fragment depth rounded to 16-bit levels). 0: the buffer's own precision.
struct DepthEmulation {
    int bits = 0;
    // The define and the include substitution for a fragment shader's build (nothing where bits is 0).
    void apply(ShaderDefines& defines, ShaderIncludes& includes) const;
};

class DepthPrepass {
public:
    explicit DepthPrepass(DepthEmulation depth = {});
    void run(const GpuScene& scene, const CameraMatrices& camera) const;

private:
    gl::Program program_;
};

// Draws the opaque meshes' depth (LESS, depth writes, no colour) seen by `camera` with `program` (geometry.vert
// + depth_only.frag) into the bound target, then restores the default state: the pre-pass and the shadow maps.
// slopeBias > 0: every depth written is pushed back by slopeBias x the polygon's depth slope per texel
// (glPolygonOffset; the shadow maps' bias for surfaces slanted towards their light).
// colorWrites: the program writes colour too (depth packed into RGBA8: depth_rgba8.frag).
void drawOpaqueDepth(const gl::Program& program, const GpuScene& scene, const CameraMatrices& camera,
                     float slopeBias = 0.0f, bool colorWrites = false);

// Attribute bindings every geometry program uses.
const std::vector<std::pair<std::string, GLuint>>& geometryAttributes();

}  // namespace lidr
