#include "lidr/render/forward_renderer_base.h"

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/render/shading_pass.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr {

ForwardRendererBase::ForwardRendererBase(const GlInfo& info, const Scene& scene, const ForwardRendererSetup& setup)
    : info_(info),
      scene_(scene, setup.drawOrder),
      targets_(info, setup.width, setup.height, setup.msaaSamples),
      lightTable_(info, setup.lightCapacity, setup.forceFixedLightTable),
      shadows_(info),
      environment_(info, !setup.forceFixedLightTable),
      timer_(info, setup.timingMethod),
      forceFixedLightTable_(setup.forceFixedLightTable) {
    timer_.setEnabled(setup.timing);
}

void ForwardRendererBase::setTiming(bool on, bool waitForResults) {
    timer_.setEnabled(on);
    timer_.setWaitForResults(waitForResults);
}

CameraMatrices ForwardRendererBase::checkFrame(const Camera& camera, const std::vector<PointLight>& lights,
                                               const ShadingParameters& shading, const char* mode) const {
    if (lights.size() > 65535)
        throw Error(std::string(mode) + ": " + std::to_string(lights.size()) +
                    " lights, 16-bit light indices and the light table hold 65535");
    checkLightSpheres(lights, mode);
    checkShadingParameters(shading);
    return cameraMatrices(camera, targets_.width(), targets_.height());
}

void ForwardRendererBase::prepareLights(const std::vector<PointLight>& lights, const ShadingParameters& shading) {
    prepareEnvironment(shading);
    growLightTable(lights.size());
    updateLights(lights, shading);
}

void ForwardRendererBase::prepareEnvironment(const ShadingParameters& shading) {
    environment_.prepare(shading.environment);
    stats_.environment = environment_.describe();
}

void ForwardRendererBase::growLightTable(size_t lights) {
    if (static_cast<int>(lights) > lightTable_.capacity())
        lightTable_ = LightTable(info_, static_cast<int>(lights), forceFixedLightTable_);
}

void ForwardRendererBase::updateLights(const std::vector<PointLight>& lights, const ShadingParameters& shading) {
    const std::vector<int>& shadowTiles =
        drawShadowMaps(shadows_, timer_, stats_, scene_, lights, shading, lightTable_.format());
    TimedPass lightTableTime(timer_, "light-table");
    lightTable_.update(lights, shadowTiles);
    lightTableTime.end();
}

void ForwardRendererBase::drawDepthPrepass(const CameraMatrices& camera, const PassDescription* pass) {
    TimedPass depthPrepassTime(timer_, "depth-prepass");
    if (pass)
        StateCache::current().beginPass(*pass);
    else
        targets_.bindColor();  // the MSAA target when multisampled
    depthPrepass_.run(scene_, camera);
    depthPrepassTime.end();
}

void ForwardRendererBase::finishFrame(const char* where) {
    StateCache::current().bindFramebuffer(0);
    checkGl(where);
    stats_.passes = timer_.collect();
    stats_.timingLag = timer_.lag();
}

}  // namespace lidr
