#include "lidr/reference_renderer.h"

#include "lidr/error.h"
#include "lidr/gl_state.h"
#include "lidr/shader_source.h"

namespace lidr {

ReferenceRenderer::ReferenceRenderer(const GlInfo& info, const Scene& scene, int width, int height, int lightCapacity,
                                     bool forceFixedLightTable)
    : scene_(scene),
      targets_(info, width, height),
      lightTable_(info, lightCapacity, forceFixedLightTable),
      timer_(info) {
    ShaderDefines defines = lightTable_.defines();
    defines.push_back({"LIDR_MAX_LIGHTS", std::to_string(std::max(lightCapacity, 1))});
    program_ = gl::Program::create("reference-forward", buildShaderSource("geometry.vert"),
                                   buildShaderSource("reference_forward.frag", defines), geometryAttributes());
}

const FrameStats& ReferenceRenderer::render(const Camera& camera, const std::vector<PointLight>& lights,
                                            const ShadingParameters& shading) {
    if (static_cast<int>(lights.size()) > lightTable_.capacity())
        throw Error("the reference was built for " + std::to_string(lightTable_.capacity()) + " lights, got " +
                    std::to_string(lights.size()));
    stats_ = FrameStats{};
    stats_.timingMethod = timer_.method();
    stats_.sceneLights = stats_.drawnLights = static_cast<int>(lights.size());
    const CameraMatrices cam = cameraMatrices(camera, targets_.width(), targets_.height());
    timer_.begin("light-table");
    lightTable_.update(lights);
    timer_.end();

    timer_.begin("depth-prepass");
    targets_.bindColor();
    depthPrepass_.run(scene_, cam);
    timer_.end();

    timer_.begin("brute-force");
    applyRenderState(RenderState{});
    glClearColor(shading.background.r, shading.background.g, shading.background.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    RenderState s;
    s.depthTest = true;
    s.depthFunc = GL_EQUAL;
    applyRenderState(s);
    program_.use();
    setShadingUniforms(program_, cam, shading);
    program_.set("uLightCount", float(lights.size()));
    lightTable_.bind(program_);
    scene_.draw(program_, DrawFilter::Opaque, true);
    timer_.end();
    if (drawTransparent_ && scene_.hasTransparent()) {
        timer_.begin("brute-force-transparent");
        RenderState t;
        t.depthTest = true;
        t.depthFunc = GL_LESS;  // hidden behind opaque geometry; no depth writes, layers blend back to front
        t.blend = true;
        t.blendSrcRgb = GL_SRC_ALPHA, t.blendDstRgb = GL_ONE_MINUS_SRC_ALPHA;
        t.blendSrcAlpha = GL_ZERO, t.blendDstAlpha = GL_ONE;  // the image stays opaque
        applyRenderState(t);
        scene_.drawTransparentSorted(program_, cam.eye);
        timer_.end();
    }
    applyRenderState(RenderState{});
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGl("reference render");
    stats_.passes = timer_.collect();
    return stats_;
}

}  // namespace lidr
