#pragma once
// The brute-force reference: every light evaluated at every pixel with lidr's one shading function, after
// the same depth pre-pass. It is the accuracy reference for every other mode, and the "forward-brute"
// baseline.
#include "lidr/render/frame_resources.h"
#include "lidr/render/shading_pass.h"

namespace lidr {

class ReferenceRenderer final : public Renderer {
public:
    // `lightCapacity`: the most lights a frame may have (the loop bound compiled into the shader).
    // MSAA and transparency as in LidrOptions: the reference is rendered the way the mode it judges is.
    ReferenceRenderer(const GlInfo& info, const Scene& scene, int width, int height, int lightCapacity,
                      bool forceFixedLightTable = false, int msaaSamples = 0, bool transparency = true,
                      bool sampleShading = false);
    std::string modeName() const override { return "forward-brute"; }
    const FrameStats& render(const Camera& camera, const std::vector<PointLight>& lights,
                             const ShadingParameters& shading) override;
    const char* timingMethod() const { return frame_.timer.method(); }
    const FrameResources& frame() const override { return frame_; }

    std::vector<FramePass> passes() const override;

private:
    // The passes of render() after the pre-pass (passes() says what each reads and writes).
    const gl::Program& shade(const CameraMatrices& cam, const std::vector<PointLight>& lights,
                             const ShadingParameters& shading);
    void shadeTransparent(const CameraMatrices& cam, const ShadingParameters& shading, const gl::Program& program);

    FrameResources frame_;
    gl::Program program_;
    ShaderDefines defines_;
    bool transparency_ = false;  // transparent meshes drawn where the scene has them (objects come and go)
    bool sampleShading_ = false;  // shade every MSAA sample, as LIDR's per-sample path does
};

}  // namespace lidr
