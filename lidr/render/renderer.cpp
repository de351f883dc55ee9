#include "lidr/render/renderer.h"

#include "lidr/base/error.h"
#include "lidr/render/frame_resources.h"

namespace lidr {

ShadingParameters sceneShading(const Scene& scene, const OutputTransform& output) {
    ShadingParameters shading{scene.ambient, scene.backgroundColor, output, scene.directionalLights};
    shading.environment.map = scene.environment;
    shading.environment.intensity = scene.environmentIntensity;
    return shading;
}

void checkShadingParameters(const ShadingParameters& shading) {
    validateDirectionalLights(shading.directionalLights);
    validateEnvironmentIntensity(shading.environment.intensity, "the environment's intensity");
}

double FrameStats::frameMilliseconds() const {
    double sum = 0.0;
    for (const PassTime& p : passes) sum += p.milliseconds;
    return sum;
}

const ModeStatistic::Value& ModeStatistics::at(const std::string& name) const {
    for (const ModeStatistic& v : values)
        if (v.name == name) return v.value;
    throw Error("mode statistics '" + section + "' have no value '" + name + "'");
}

const RenderTargets& Renderer::targets() const { return frame().targets; }

const ShadowAtlas* Renderer::shadowAtlas() const { return frame().shadows.atlas(); }

void Renderer::setTiming(bool on, bool waitForResults) { mutableFrame().setTiming(on, waitForResults); }

std::vector<GpuScene*> Renderer::gpuScenes() { return {&mutableFrame().scene}; }

void Renderer::setObjectTransform(ObjectId id, const glm::mat4& objectToWorld) {
    // Every scene holds the same objects: the first one's checks stand for all, so a refusal changes nothing.
    for (GpuScene* scene : gpuScenes()) scene->setTransform(id, objectToWorld);
}

ObjectId Renderer::addObject(const Mesh& mesh, const Material& material) {
    // Checked here first so that the mode's own refusal (checkObjectMaterial) never speaks for a bad value; each
    // scene's add checks again, one pass over the mesh like its upload, so GpuScene stays safe on its own.
    validateObject(mesh, material);
    checkObjectMaterial(material);
    const std::vector<GpuScene*> scenes = gpuScenes();
    ObjectId id = 0;
    for (size_t i = 0; i < scenes.size(); ++i) {
        const ObjectId got = scenes[i]->add(mesh, material);
        if (i == 0) id = got;
        else if (got != id) throw Error("addObject: the renderer's scenes disagree on object ids (a lidr bug)");
    }
    return id;
}

void Renderer::removeObject(ObjectId id) {
    for (GpuScene* scene : gpuScenes()) scene->remove(id);
}

size_t placeAnimatedObjects(Renderer& renderer, const Scene& scene, float t) {
    const std::vector<size_t> moving = movingMeshes(scene);
    if (moving.empty()) return 0;
    const std::vector<glm::mat4> transforms = meshTransformsAt(scene, t);
    for (size_t mesh : moving) renderer.setObjectTransform(ObjectId(mesh), transforms[mesh]);
    return moving.size();
}

}  // namespace lidr
