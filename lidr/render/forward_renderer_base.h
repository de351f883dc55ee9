#pragma once
// What the forward-shading modes hold and do alike (tiled forward, multi-pass forward and the brute-force
// reference; a new forward mode derives from it the same way): the scene on the GPU, the render targets, the
// light table, the depth pre-pass, the shadow maps, the environment light's maps and the pass timer; the Renderer overrides that only read
// them; and the steps of a frame every such mode takes in the same way, in the order a frame takes them:
//
//   render():  checkFrame -> FrameScope -> prepareLights (environment, growLightTable, shadow-maps, light-table)
//              -> drawDepthPrepass (depth-prepass) -> the mode's own passes -> targets_.resolve -> finishFrame
//
// A mode adds its light lists and programs, and draws its shading passes between the pre-pass and the resolve.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "lidr/gl/frame_timer.h"
#include "lidr/gl/gl_info.h"
#include "lidr/gl/render_targets.h"
#include "lidr/render/depth_prepass.h"
#include "lidr/render/environment_maps.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/render/light_table.h"
#include "lidr/render/renderer.h"
#include "lidr/render/shadow_maps.h"
#include "lidr/scene/camera.h"
#include "lidr/scene/scene.h"

namespace lidr {

// How a mode sets up what it shares with the others.
struct ForwardRendererSetup {
    int width = 0, height = 0;
    int msaaSamples = 0;                      // 0, or 2..GL_MAX_SAMPLES: shading multisampled, then resolved
    int lightCapacity = 1;                    // lights the light table holds at first
    bool forceFixedLightTable = false;        // the RGBA8 fixed-point light table even with float textures
    DrawOrder drawOrder = DrawOrder::AsGiven;
    TimingMethod timingMethod = TimingMethod::Auto;
    bool timing = false;                      // per-pass times on from the start (Renderer::setTiming)

    // From a mode's options struct (its msaaSamples, forceFixedLightTable, timing and timingMethod), with a light
    // table sized for the scene's lights.
    template <typename ModeOptions>
    static ForwardRendererSetup of(const ModeOptions& options, const Scene& scene, int width, int height,
                                   DrawOrder drawOrder = DrawOrder::AsGiven) {
        ForwardRendererSetup setup;
        setup.width = width;
        setup.height = height;
        setup.msaaSamples = options.msaaSamples;
        setup.lightCapacity = std::max<int>(1, int(scene.lights.size()));
        setup.forceFixedLightTable = options.forceFixedLightTable;
        setup.drawOrder = drawOrder;
        setup.timingMethod = options.timingMethod;
        setup.timing = options.timing;
        return setup;
    }
};

class ForwardRendererBase : public Renderer {
public:
    const RenderTargets& targets() const override { return targets_; }
    const ShadowAtlas* shadowAtlas() const override { return shadows_.atlas(); }
    void setTiming(bool on, bool waitForResults = false) override;
    std::vector<GpuScene*> gpuScenes() override { return {&scene_}; }
    const LightTable& lightTable() const { return lightTable_; }
    const ShadowMaps& shadowMaps() const { return shadows_; }

protected:
    // Builds the shared objects in the order of the members below; `info` is copied (growLightTable uses it).
    ForwardRendererBase(const GlInfo& info, const Scene& scene, const ForwardRendererSetup& setup);

    // Everything checked before any drawing (lidr::Error naming `mode`): at most 65,535 lights (16-bit
    // indices, the light table's rows), finite light spheres, the shading parameters; returns the camera's
    // matrices at the targets' size. A FrameScope follows it, then prepareLights.
    CameraMatrices checkFrame(const Camera& camera, const std::vector<PointLight>& lights,
                              const ShadingParameters& shading, const char* mode) const;
    // The frame's lights on the GPU: prepareEnvironment, growLightTable, updateLights.
    void prepareLights(const std::vector<PointLight>& lights, const ShadingParameters& shading);
    // The frame's environment light uploaded where it changed (EnvironmentMaps::prepare) and stats_.environment
    // saying how it is looked up; its shading passes then bind environment_ with their programs.
    void prepareEnvironment(const ShadingParameters& shading);
    // A light table that holds `lights` where the current one holds fewer: a frame with more lights than the
    // scene had grows it rather than being refused.
    void growLightTable(size_t lights);
    // The frame's shadow maps (drawShadowMaps: the timed "shadow-maps" pass where shadows are on), then the light
    // table with the lights' atlas tiles (the "light-table" pass).
    void updateLights(const std::vector<PointLight>& lights, const ShadingParameters& shading);
    // The depth pre-pass into targets_'s colour pass, or into `pass` where given (a mode that shades into a target
    // of its own sharing targets_' depth), as the "depth-prepass" pass: the depth shading then tests EQUAL, so each
    // pixel is shaded once.
    void drawDepthPrepass(const CameraMatrices& camera, const PassDescription* pass = nullptr);
    // The end of render() once the passes are drawn and targets_ resolved: the default framebuffer bound, GL
    // errors checked (lidr::Error naming `where`), the passes' times collected into stats_.
    void finishFrame(const char* where);

    const GlInfo info_;
    GpuScene scene_;
    RenderTargets targets_;
    LightTable lightTable_;
    DepthPrepass depthPrepass_;
    ShadowMaps shadows_;
    EnvironmentMaps environment_;  // half floats unless the fixed light table is forced (the 8-bit storage then)
    FrameTimer timer_;

private:
    bool forceFixedLightTable_ = false;
};

}  // namespace lidr
