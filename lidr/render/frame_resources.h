#pragma once
// What every mode's frame is drawn with, one object each mode holds (LIDR, tiled, clustered, multi-pass and the
// reference; a new mode, forward or deferred, holds one the same way): the scene on the GPU, the render targets, the
// light table, the depth pre-pass, the shadow maps, the environment light's maps and the pass timer; and the steps of
// a frame the modes take alike, in the order a frame takes them:
//
//   render():  checkFrame -> FrameScope -> prepareLights (prepareEnvironment, growLightTable, updateLights:
//              shadow-maps, light-table) -> drawDepthPrepass (depth-prepass) -> the mode's own passes
//              -> resolve (msaa-resolve) -> finishFrame
//
// A mode adds its light lists and programs and draws its own passes between the pre-pass and the resolve. LIDR takes
// the steps it needs in its own order (the shadow maps first, the light table from its frame plan); a mode without a
// pre-pass leaves drawDepthPrepass out.
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

// How a mode sets up its FrameResources.
struct FrameSetup {
    int width = 0, height = 0;
    int msaaSamples = 0;                      // 0, or 2..GL_MAX_SAMPLES: shading multisampled, then resolved
    int lightCapacity = 1;                    // lights the light table holds at first
    bool forceFixedLightTable = false;        // the RGBA8 fixed-point light table even with float textures
    DrawOrder drawOrder = DrawOrder::AsGiven;
    TimingMethod timingMethod = TimingMethod::Auto;
    bool timing = false;                      // per-pass times on from the start (Renderer::setTiming)
    int depthBits = 24;                       // of the depth-stencil target (RenderTargets; LidrOptions::depthBits)
    DepthEmulation prepassDepth{};            // the pre-pass's depth rounding (LidrOptions::emulatedDepthBits)

    // From a mode's options struct (its msaaSamples, forceFixedLightTable, timing and timingMethod), with a light
    // table sized for the scene's lights.
    template <typename ModeOptions>
    static FrameSetup of(const ModeOptions& options, const Scene& scene, int width, int height,
                         DrawOrder drawOrder = DrawOrder::AsGiven) {
        FrameSetup setup;
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

class FrameResources {
public:
    // Builds the shared objects in the order of the members below; `info` is copied (growLightTable uses it).
    FrameResources(const GlInfo& info, const Scene& scene, const FrameSetup& setup);
    FrameResources(const FrameResources&) = delete;
    FrameResources& operator=(const FrameResources&) = delete;

    void setTiming(bool on, bool waitForResults);  // Renderer::setTiming

    // Everything checked before any drawing (lidr::Error naming `mode`): at most 65,535 lights (16-bit
    // indices, the light table's rows), finite light spheres, the shading parameters; returns the camera's
    // matrices at the targets' size. A FrameScope follows it, then prepareLights.
    CameraMatrices checkFrame(const Camera& camera, const std::vector<PointLight>& lights,
                              const ShadingParameters& shading, const char* mode) const;
    // The frame's lights on the GPU: prepareEnvironment, growLightTable, updateLights.
    void prepareLights(const std::vector<PointLight>& lights, const ShadingParameters& shading, FrameStats& stats);
    // The frame's environment light uploaded where it changed (EnvironmentMaps::prepare, with the index targets a
    // LIDR forward pass binds) and stats.environment saying how it is looked up; the shading passes then bind
    // `environment` with their programs.
    void prepareEnvironment(const ShadingParameters& shading, FrameStats& stats, int indexTargets = 0);
    // A light table that holds `lights` where the current one holds fewer: a frame with more lights than the
    // scene had grows it rather than being refused.
    void growLightTable(size_t lights);
    // The frame's shadow maps (lidr::drawShadowMaps: the timed "shadow-maps" pass where shadows are on); returns the
    // lights' first atlas tiles for the light table (empty: no light casts).
    const std::vector<int>& drawShadowMaps(const std::vector<PointLight>& lights, const ShadingParameters& shading,
                                           FrameStats& stats);
    // drawShadowMaps, then the light table with the lights' atlas tiles (the "light-table" pass).
    void updateLights(const std::vector<PointLight>& lights, const ShadingParameters& shading, FrameStats& stats);
    // The depth pre-pass into the targets' colour pass, or into `pass` where given (a mode that shades into a target
    // of its own sharing the targets' depth), as the "depth-prepass" pass: the depth shading then tests EQUAL, so
    // each pixel is shaded once.
    void drawDepthPrepass(const CameraMatrices& camera, const PassDescription* pass = nullptr);
    // The fixed-function state back to its defaults (no scissor or masks on the blit), then the MSAA colour resolved
    // into the single-sample target as the "msaa-resolve" pass (nothing without MSAA).
    void resolve();
    // The end of render() once the passes are drawn and the targets resolved: the default framebuffer bound, GL
    // errors checked (lidr::Error naming `where`), the passes' times collected into `stats`.
    void finishFrame(FrameStats& stats, const char* where);

    const GlInfo info;
    GpuScene scene;
    RenderTargets targets;
    LightTable lightTable;
    DepthPrepass depthPrepass;
    ShadowMaps shadows;
    EnvironmentMaps environment;  // half floats unless the fixed light table is forced (the 8-bit storage then)
    FrameTimer timer;

private:
    bool forceFixedLightTable_ = false;
};

}  // namespace lidr
