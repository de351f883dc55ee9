#pragma once
// The per-pixel light count LIDR's volume pass leaves in the stencil (what lidr::LidrRenderer::readLightCounts
// reads with glReadPixels on desktop GL), read back where glReadPixels cannot read stencil (WebGL 1): eight
// full-screen draws, one per stencil bit, each adding the bit's value to a cleared colour target where the bit
// is set. Overwrites the targets' colour image: read that first.
#include <cstdint>
#include <vector>

#include "lidr/gl/gl_resources.h"
#include "lidr/gl/render_targets.h"

namespace lidr::web {

class StencilReadback {
public:
    StencilReadback();  // compiles its program; needs the context current
    // Stencil values per pixel, rows top to bottom as lidr::readStencil gives them.
    std::vector<uint8_t> read(const RenderTargets& targets) const;

private:
    gl::Program program_;
    gl::Buffer triangle_;
};

}  // namespace lidr::web
