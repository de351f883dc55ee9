#include "lidr/render/present.h"
#include "lidr/base/gl.h"

#include <string>

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/saved_gl_state.h"
#include "lidr/gl/shader_source.h"

namespace lidr {

FramePresenter::FramePresenter() {
    SavedGlState saved;
    program_ = gl::Program::create("present", buildShaderSource("present.vert"), buildShaderSource("present.frag"),
                                   {{"aPosition", gl::kPosition}});
    const float triangle[] = {-1.0f, -1.0f, 0.0f, 3.0f, -1.0f, 0.0f, -1.0f, 3.0f, 0.0f};
    triangle_ = gl::Buffer::create(GL_ARRAY_BUFFER, triangle, sizeof triangle);
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
    targets.color().bind(gl::kUnitPresentedFrame);
    program_.set("uFrame", gl::kUnitPresentedFrame);
    glBindBuffer(GL_ARRAY_BUFFER, triangle_.id());
    glVertexAttribPointer(gl::kPosition, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(gl::kPosition);
    cache.drawArrays(GL_TRIANGLES, 0, 3);
    checkGl("presentFrame");
}

}  // namespace lidr
