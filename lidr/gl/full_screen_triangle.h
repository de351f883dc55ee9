#pragma once
// One triangle covering the viewport (clip-space corners (-1, -1), (3, -1), (-1, 3)): what every screen-space pass
// draws (G-buffer lighting, the depth spans' read-backs, tile depth reductions, the overlap probe, presenting).
// Its positions go to attribute gl::kPosition (shaders/common/fullscreen.vert and the passes' own vertex shaders).
#include "lidr/gl/gl_resources.h"

namespace lidr {

class FullScreenTriangle {
public:
    FullScreenTriangle() = default;
    static FullScreenTriangle create();
    explicit operator bool() const { return bool(buffer_); }
    // bind() .. unbind() around several draws (drawArrays(GL_TRIANGLES, 0, 3) each); draw(): one, bound and unbound.
    void bind() const;
    void unbind() const;
    void draw() const;

private:
    gl::Buffer buffer_;
};

}  // namespace lidr
