#include "lidr/render/frame_resources.h"

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/render/shading_pass.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr {

FrameResources::FrameResources(const GlInfo& glInfo, const Scene& sceneIn, const FrameSetup& setup)
    : info(glInfo),
      scene(sceneIn, setup.drawOrder),
      targets(glInfo, setup.width, setup.height, setup.msaaSamples, setup.depthBits),
      lightTable(glInfo, setup.lightCapacity, setup.forceFixedLightTable),
      depthPrepass(setup.prepassDepth),
      shadows(glInfo),
      environment(glInfo, !setup.forceFixedLightTable),
      timer(glInfo, setup.timingMethod),
      forceFixedLightTable_(setup.forceFixedLightTable) {
    timer.setEnabled(setup.timing);
}

void FrameResources::setTiming(bool on, bool waitForResults) {
    timer.setEnabled(on);
    timer.setWaitForResults(waitForResults);
}

CameraMatrices FrameResources::checkFrame(const Camera& camera, const std::vector<PointLight>& lights,
                                          const ShadingParameters& shading, const char* mode) const {
    if (lights.size() > 65535)
        throw Error(std::string(mode) + ": " + std::to_string(lights.size()) +
                    " lights, 16-bit light indices and the light table hold 65535");
    checkLightSpheres(lights, mode);
    checkShadingParameters(shading);
    return cameraMatrices(camera, targets.width(), targets.height());
}

void FrameResources::prepareLights(const std::vector<PointLight>& lights, const ShadingParameters& shading,
                                   FrameStats& stats) {
    prepareEnvironment(shading, stats);
    growLightTable(lights.size());
    updateLights(lights, shading, stats);
}

void FrameResources::prepareEnvironment(const ShadingParameters& shading, FrameStats& stats, int indexTargets) {
    environment.prepare(shading.environment, indexTargets);
    stats.environment = environment.describe();
}

void FrameResources::growLightTable(size_t lights) {
    if (static_cast<int>(lights) > lightTable.capacity())
        lightTable = LightTable(info, static_cast<int>(lights), forceFixedLightTable_);
}

const std::vector<int>& FrameResources::drawShadowMaps(const std::vector<PointLight>& lights,
                                                       const ShadingParameters& shading, FrameStats& stats) {
    return lidr::drawShadowMaps(shadows, timer, stats, scene, lights, shading, lightTable.format());
}

void FrameResources::updateLights(const std::vector<PointLight>& lights, const ShadingParameters& shading,
                                  FrameStats& stats) {
    const std::vector<int>& shadowTiles = drawShadowMaps(lights, shading, stats);
    TimedPass lightTableTime(timer, pass::kLightTable.name);
    lightTable.update(lights, shadowTiles);
    lightTableTime.end();
}

void FrameResources::drawDepthPrepass(const CameraMatrices& camera, const PassDescription* pass) {
    TimedPass depthPrepassTime(timer, pass::kDepthPrepass.name);
    if (pass)
        StateCache::current().beginPass(*pass);
    else
        targets.bindColor();  // the MSAA target when multisampled
    depthPrepass.run(scene, camera);
    depthPrepassTime.end();
}

void FrameResources::resolve() {
    StateCache::current().apply(RenderState{});
    targets.resolve(timer);
}

void FrameResources::finishFrame(FrameStats& stats, const char* where) {
    StateCache::current().bindFramebuffer(0);
    checkGl(where);
    stats.passes = timer.collect();
    stats.timingLag = timer.lag();
}

}  // namespace lidr
