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
    : ForwardRendererBase(info, scene, {width, height, msaaSamples, lightCapacity, forceFixedLightTable}),
      transparency_(transparency),
      sampleShading_(sampleShading) {
    if (sampleShading && !info.sampleShading)
        throw UnsupportedError("sample shading (GL 4.0 / ARB_sample_shading) is not available in this context");
    ShaderDefines defines = lightTable_.defines();
    defines.push_back({"LIDR_MAX_LIGHTS", std::to_string(std::max(lightCapacity, 1))});
    program_ = gl::Program::create("reference-forward", buildShaderSource("geometry.vert"),
                                   buildShaderSource("reference_forward.frag", defines), geometryAttributes());
    defines_ = defines;
}

const FrameStats& ReferenceRenderer::render(const Camera& camera, const std::vector<PointLight>& lights,
                                            const ShadingParameters& shading) {
    if (static_cast<int>(lights.size()) > lightTable_.capacity())  // its loop bound is compiled in: no growing
        throw Error("the reference was built for " + std::to_string(lightTable_.capacity()) + " lights, got " +
                    std::to_string(lights.size()));
    const CameraMatrices cam = checkFrame(camera, lights, shading, "forward-brute");
    const FrameScope frame(stats_, timer_, lights.size());
    stats_.drawnLights = stats_.sceneLights;
    prepareLights(lights, shading);  // the table never grows here: it holds the capacity checked above
    drawDepthPrepass(cam);  // into the MSAA target when multisampled: the reference has no index pass to feed

    TimedPass bruteForceTime(timer_, "brute-force");
    beginOpaqueShading(targets_, shading, true, sampleShading_);
    // Shadows: the same shading with the lookups compiled in (shadow_lookup.glsl), reading the maps drawn above.
    const gl::Program& program = shadows_.active() ? shadows_.program("reference-forward", "geometry.vert",
                                                                      "reference_forward.frag", defines_, shading.shadows)
                                                   : program_;
    useShadingProgram(program, cam, shading, lightTable_, environment_);
    shadows_.bind(program, shading.shadows);
    program.set("uLightCount", float(lights.size()));
    scene_.draw(program, DrawFilter::Opaque, true, &cam, shadingVariantKey(program, shading, environment_));
    bruteForceTime.end();
    if (transparency_ && scene_.hasTransparent()) {
        TimedPass bruteForceTransparentTime(timer_, "brute-force-transparent");
        beginTransparentShading(sampleShading_);  // the state every mode draws its layers with
        scene_.drawTransparentSorted(program, cam.eye, shadingVariantKey(program, shading, environment_));
    }
    StateCache& cache = StateCache::current();
    cache.apply(RenderState{});
    targets_.resolve(timer_);
    finishFrame("reference render");
    return stats_;
}

}  // namespace lidr
