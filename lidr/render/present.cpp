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

gl::Buffer fullScreenTriangle() {
    const float triangle[] = {-1.0f, -1.0f, 0.0f, 3.0f, -1.0f, 0.0f, -1.0f, 3.0f, 0.0f};
    return gl::Buffer::create(GL_ARRAY_BUFFER, triangle, sizeof triangle);
}

// Draws `frame` over the current pass's viewport with `program` (in use), no state of its own.
void drawFullScreen(const gl::Program& program, const gl::Buffer& triangle, const gl::Texture& frame) {
    frame.bind(gl::kUnitPresentedFrame);
    program.set("uFrame", gl::kUnitPresentedFrame);
    glBindBuffer(GL_ARRAY_BUFFER, triangle.id());
    glVertexAttribPointer(gl::kPosition, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(gl::kPosition);
    StateCache::current().drawArrays(GL_TRIANGLES, 0, 3);
}
}  // namespace

FramePresenter::FramePresenter() {
    SavedGlState saved;
    program_ = fullScreenProgram("present", "present.frag");
    triangle_ = fullScreenTriangle();
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
    triangle_ = fullScreenTriangle();
    checkGl("OutputEncodePass");
}

void OutputEncodePass::run(const RenderTargets& targets, const OutputTransform& output) {
    if (scratch_.width() != targets.width() || scratch_.height() != targets.height())
        scratch_ = gl::Texture::create2D(GL_RGBA8, targets.width(), targets.height(), GL_RGBA, GL_UNSIGNED_BYTE);
    StateCache& cache = StateCache::current();
    cache.beginPass(targets.singleSamplePass());
    cache.apply(RenderState{});
    scratch_.bind(gl::kUnitPresentedFrame);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, targets.width(), targets.height());
    program_.use();
    setOutputUniforms(program_, output);
    drawFullScreen(program_, triangle_, scratch_);
    glDisableVertexAttribArray(gl::kPosition);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    checkGl("OutputEncodePass");
}

}  // namespace lidr
