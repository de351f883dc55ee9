#include "lidr/modes/reference_renderer.h"
#include "lidr/base/gl.h"
#include "lidr/gl/saved_gl_state.h"

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"

namespace lidr {

ReferenceRenderer::ReferenceRenderer(const GlInfo& info, const Scene& scene, int width, int height, int lightCapacity,
                                     bool forceFixedLightTable, int msaaSamples, bool transparency,
                                     bool sampleShading)
    // Timing off: Renderer::setTiming turns it on.
    : frame_(info, scene, {width, height, msaaSamples, lightCapacity, forceFixedLightTable}),
      transparency_(transparency),
      sampleShading_(sampleShading) {
    if (sampleShading && !info.sampleShading)
        throw UnsupportedError("sample shading (GL 4.0 / ARB_sample_shading) is not available in this context");
    ShaderDefines defines = frame_.lightTable.defines();
    defines.push_back({"LIDR_MAX_LIGHTS", std::to_string(std::max(lightCapacity, 1))});
    program_ = gl::Program::create("reference-forward", buildShaderSource("geometry.vert"),
                                   buildShaderSource("reference_forward.frag", defines), geometryAttributes());
    defines_ = defines;
}

namespace {
// The reference's own passes, between FrameResources' (passes(), render()).
constexpr FramePass kBruteForce{"brute-force", "scene, depth, light table, [shadow atlas], [environment]", "colour"};
constexpr FramePass kBruteForceTransparent{"brute-force-transparent",
                                           "transparent meshes, depth, light table, [shadow atlas], [environment]",
                                           "colour", "transparent meshes in the scene"};
}  // namespace

std::vector<FramePass> ReferenceRenderer::passes() const {
    std::vector<FramePass> p{pass::kShadowMaps, pass::kLightTable, pass::kDepthPrepass, kBruteForce};
    if (transparency_) p.push_back(kBruteForceTransparent);
    if (frame_.targets.samples() > 0) p.push_back(pass::kMsaaResolve);
    return p;
}

const FrameStats& ReferenceRenderer::render(const Camera& camera, const std::vector<PointLight>& lights,
                                            const ShadingParameters& shading) {
    if (static_cast<int>(lights.size()) > frame_.lightTable.capacity())  // its loop bound is compiled in: no growing
        throw Error("the reference was built for " + std::to_string(frame_.lightTable.capacity()) + " lights, got " +
                    std::to_string(lights.size()));
    const CameraMatrices cam = frame_.checkFrame(camera, lights, shading, "forward-brute");
    const FrameScope scope(stats_, frame_.timer, lights.size());
    stats_.drawnLights = stats_.sceneLights;
    // shadow-maps, light-table: the table never grows here, it holds the capacity checked above.
    frame_.prepareLights(lights, shading, stats_);
    frame_.drawDepthPrepass(cam);  // into the MSAA target when multisampled: the reference has no index pass to feed
    const gl::Program& program = shade(cam, lights, shading);
    if (transparency_ && frame_.scene.hasTransparent()) shadeTransparent(cam, shading, program);
    frame_.resolve();  // msaa-resolve
    frame_.finishFrame(stats_, "reference render");
    return stats_;
}

const gl::Program& ReferenceRenderer::shade(const CameraMatrices& cam, const std::vector<PointLight>& lights,
                                            const ShadingParameters& shading) {
    TimedPass bruteForceTime(frame_.timer, kBruteForce.name);
    beginOpaqueShading(frame_.targets, shading, true, sampleShading_);
    // Shadows: the same shading with the lookups compiled in (shadow_lookup.glsl), reading the maps drawn above.
    const gl::Program& program =
        frame_.shadows.shadingProgram(program_, "reference_forward.frag", defines_, shading.shadows);
    useShadingProgram(program, cam, shading, frame_.lightTable, frame_.environment);
    frame_.shadows.bind(program, shading.shadows);
    program.set("uLightCount", float(lights.size()));
    frame_.scene.draw(program, DrawFilter::Opaque, true, &cam, shadingVariantKey(program, shading, frame_.environment));
    return program;
}

void ReferenceRenderer::shadeTransparent(const CameraMatrices& cam, const ShadingParameters& shading,
                                         const gl::Program& program) {
    TimedPass bruteForceTransparentTime(frame_.timer, kBruteForceTransparent.name);
    beginTransparentShading(sampleShading_);  // the state every mode draws its layers with
    frame_.scene.drawTransparentSorted(program, cam.eye, shadingVariantKey(program, shading, frame_.environment));
}

}  // namespace lidr
