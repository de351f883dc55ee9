#include "lidr/gl/full_screen_triangle.h"
#include "lidr/base/gl.h"

#include "lidr/gl/bindings.h"
#include "lidr/gl/gl_state.h"

namespace lidr {

FullScreenTriangle FullScreenTriangle::create() {
    const float triangle[] = {-1.0f, -1.0f, 0.0f, 3.0f, -1.0f, 0.0f, -1.0f, 3.0f, 0.0f};
    FullScreenTriangle t;
    t.buffer_ = gl::Buffer::create(GL_ARRAY_BUFFER, triangle, sizeof triangle);
    return t;
}

void FullScreenTriangle::bind() const {
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    glEnableVertexAttribArray(gl::kPosition);
    glVertexAttribPointer(gl::kPosition, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
}

void FullScreenTriangle::unbind() const {
    glDisableVertexAttribArray(gl::kPosition);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void FullScreenTriangle::draw() const {
    bind();
    StateCache::current().drawArrays(GL_TRIANGLES, 0, 3);
    unbind();
}

}  // namespace lidr
