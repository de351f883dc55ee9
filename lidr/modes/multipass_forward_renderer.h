#pragma once
// Multi-pass forward ("forward-multipass"): the classic forward renderer the LIDR paper compares with
// (Trebilco 2007). After a depth pre-pass, an ambient pass, then per light one additive pass (blend ONE, ONE,
// depth EQUAL) over the meshes that light's sphere touches, scissored to the light's screen rectangle
// (lidr/scene/sphere_bounds.h). Same scene, camera, light table and shading function as every other mode.
// Each pass shades one fragment per pixel (sample): stencil stamps let the first through, and the scene is
// drawn in reverse so that it is the fragment single-pass modes keep (doc/tiled.md, "One fragment per pixel
// and pass"). Under MSAA meshes are culled by screen rectangles (exactMsaaCulling).
//
// Accuracy: every pass writes the 8-bit target, so each term is rounded on its own; at a pixel lit by n
// lights the image can differ from the single-pass reference by up to floor(n / 2) + 1 steps (doc/tiled.md).
// Transparent meshes are not drawn: additive light passes cannot alpha-blend a surface over what is behind it.
#include <string>
#include <vector>

#include "lidr/render/depth_prepass.h"
#include "lidr/gl/frame_timer.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/render/light_table.h"
#include "lidr/render/present.h"
#include "lidr/gl/render_targets.h"
#include "lidr/render/renderer.h"
#include "lidr/render/environment_maps.h"
#include "lidr/render/shadow_maps.h"

namespace lidr {

struct MultipassOptions {
    bool scissor = true;                // scissor each light pass to the light's screen rectangle
    bool cullMeshes = true;             // draw only the meshes whose bounds the light's sphere touches
    // Under MSAA, cull by screen rectangles instead (exact; see render()). false: by mesh bounds as without
    // MSAA, faster, but a sample shaded off its triangle (at the pixel centre) can miss a light.
    bool exactMsaaCulling = true;
    bool forceFixedLightTable = false;
    int msaaSamples = 0;                // 0, or 2..GL_MAX_SAMPLES: shading multisampled, then resolved
    bool timing = false;  // as LidrOptions::timing
    TimingMethod timingMethod = TimingMethod::Auto;
};

class MultipassForwardRenderer final : public Renderer {
public:
    MultipassForwardRenderer(const GlInfo& info, const Scene& scene, const MultipassOptions& options, int width,
                             int height);
    std::string modeName() const override { return "forward-multipass"; }
    const FrameStats& render(const Camera& camera, const std::vector<PointLight>& lights,
                             const ShadingParameters& shading) override;
    const ShadowAtlas* shadowAtlas() const override { return shadows_.atlas(); }
    const RenderTargets& targets() const override { return targets_; }
    void setTiming(bool on, bool waitForResults = false) override {
        timer_.setEnabled(on);
        timer_.setWaitForResults(waitForResults);
    }
    long meshDrawCalls() const { return meshDraws_; }  // light-pass mesh draws of the last frame

    std::vector<GpuScene*> gpuScenes() override { return {&scene_}; }

private:
    MultipassOptions options_;
    GpuScene scene_;
    RenderTargets targets_;
    LightTable lightTable_;
    DepthPrepass depthPrepass_;
    gl::Program ambient_, light_;
    ShaderDefines lightDefines_;  // light_'s, for its shadowed twin (ShadowMaps::program)
    ShadowMaps shadows_;
    EnvironmentMaps environment_;
    OutputEncodePass outputEncode_;  // its passes sum linear light; the output transform runs over the sum
    FrameTimer timer_;
    const GlInfo info_;
    long meshDraws_ = 0;
};

}  // namespace lidr
