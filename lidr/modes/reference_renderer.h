#pragma once
// The brute-force reference: every light evaluated at every pixel with lidr's one shading function, after
// the same depth pre-pass. It is the accuracy reference for every other mode, and the "forward-brute"
// baseline.
#include "lidr/render/depth_prepass.h"
#include "lidr/render/shading_pass.h"
#include "lidr/gl/frame_timer.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/render/light_table.h"
#include "lidr/gl/render_targets.h"
#include "lidr/render/renderer.h"
#include "lidr/render/environment_maps.h"
#include "lidr/render/shadow_maps.h"

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
    const ShadowAtlas* shadowAtlas() const override { return shadows_.atlas(); }
    const RenderTargets& targets() const override { return targets_; }
    void setTiming(bool on, bool waitForResults = false) override {
        timer_.setEnabled(on);
        timer_.setWaitForResults(waitForResults);
    }
    const char* timingMethod() const { return timer_.method(); }

    std::vector<GpuScene*> gpuScenes() override { return {&scene_}; }

private:
    GpuScene scene_;
    RenderTargets targets_;
    LightTable lightTable_;
    DepthPrepass depthPrepass_;
    gl::Program program_;
    ShaderDefines defines_;
    ShadowMaps shadows_;
    EnvironmentMaps environment_;
    FrameTimer timer_;
    bool transparency_ = false;  // transparent meshes drawn where the scene has them (objects come and go)
    bool sampleShading_ = false;  // shade every MSAA sample, as LIDR's per-sample path does
};

}  // namespace lidr
