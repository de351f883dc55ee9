#include "lidr/render/present.h"
#include "lidr/base/gl.h"

#include <string>

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/saved_gl_state.h"
#include "lidr/gl/shader_source.h"
#include "lidr/render/shading_pass.h"

namespace lidr {

namespace {
gl::Program fullScreenProgram(const char* name, const char* fragmentShader) {
    return gl::Program::create(name, buildShaderSource("present.vert"), buildShaderSource(fragmentShader),
                               {{"aPosition", gl::kPosition}});
}

// Draws `frame` over the current pass's viewport with `program` (in use), no state of its own.
void drawFullScreen(const gl::Program& program, const FullScreenTriangle& triangle, const gl::Texture& frame) {
    frame.bind(gl::kUnitPresentedFrame);
    program.set("uFrame", gl::kUnitPresentedFrame);
    triangle.draw();
}
}  // namespace

FramePresenter::FramePresenter() {
    SavedGlState saved;
    program_ = fullScreenProgram("present", "present.frag");
    triangle_ = FullScreenTriangle::create();
    checkGl("FramePresenter");
}

void FramePresenter::present(const RenderTargets& targets, GLuint framebuffer, int x, int y, int width,
                             int height) const {
    if (width <= 0 || height <= 0)
        throw Error("presentFrame: empty rectangle " + std::to_string(width) + "x" + std::to_string(height));
    SavedGlState saved;
    StateCache& cache = StateCache::current();
    cache.beginPass({framebuffer, glm::ivec4(x, y, width, height), {}, {}});  // the caller's draw buffers
    cache.apply(RenderState{});
    program_.use();
    drawFullScreen(program_, triangle_, targets.color());
    checkGl("presentFrame");
}

OutputEncodePass::OutputEncodePass() {
    SavedGlState saved;
    program_ = fullScreenProgram("output-encode", "output_encode.frag");
    triangle_ = FullScreenTriangle::create();
    checkGl("OutputEncodePass");
}

void OutputEncodePass::run(const RenderTargets& targets, const OutputTransform& output) {
    if (scratch_.width() != targets.width() || scratch_.height() != targets.height())
        scratch_ = gl::Texture::create2D(GL_RGBA8, targets.width(), targets.height(), GL_RGBA, GL_UNSIGNED_BYTE);
    StateCache::current().beginPass(targets.singleSamplePass());
    scratch_.bind(gl::kUnitPresentedFrame);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, targets.width(), targets.height());
    run(targets, output, scratch_);
}

void OutputEncodePass::run(const RenderTargets& targets, const OutputTransform& output, const gl::Texture& linearFrame) {
    if (linearFrame.width() != targets.width() || linearFrame.height() != targets.height())
        throw Error("OutputEncodePass: a " + std::to_string(linearFrame.width()) + "x" +
                    std::to_string(linearFrame.height()) + " frame for " + std::to_string(targets.width()) + "x" +
                    std::to_string(targets.height()) + " targets");
    const bool perSample = linearFrame.samples() > 0;
    if (perSample && linearFrame.samples() != targets.samples())
        throw Error("OutputEncodePass: a " + std::to_string(linearFrame.samples()) + "x frame for " +
                    std::to_string(targets.samples()) + "x targets");
    if (perSample && !perSampleProgram_)
        perSampleProgram_ = gl::Program::create(
            "output-encode-per-sample", perSampleGlsl150(buildShaderSource("present.vert")),
            perSampleGlsl150(buildShaderSource("output_encode.frag", {{"LIDR_FRAME_PER_SAMPLE", "1"}})),
            {{"aPosition", gl::kPosition}});
    const gl::Program& program = perSample ? perSampleProgram_ : program_;
    StateCache& cache = StateCache::current();
    cache.beginPass(perSample ? targets.colorPass() : targets.singleSamplePass());
    RenderState s;
    s.sampleShading = perSample;
    cache.apply(s);
    program.use();
    setOutputUniforms(program, output);
    drawFullScreen(program, triangle_, linearFrame);
    if (perSample) cache.apply(RenderState{});
    checkGl("OutputEncodePass");
}

}  // namespace lidr
