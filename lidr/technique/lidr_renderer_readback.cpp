// LidrRenderer's read-backs of its last frame (index targets, per-pixel light counts, the volumes' radii): what the
// tests, lidr-demo's dump and the viewer read; no frame needs them.
#include "lidr/technique/lidr_renderer.h"
#include "lidr/base/gl.h"

#include "lidr/gl/gl_state.h"

namespace lidr {

std::vector<ImageRGBA8> LidrRenderer::readIndexTargets() const {
    std::vector<ImageRGBA8> out;
    if (lightlessFrame_) {  // no volume pass: every list is empty (index 0)
        for (int i = 0; i < indexTargets_->count(); ++i) out.emplace_back(indexTargets_->width(), indexTargets_->height());
        return out;
    }
    indexTargets_->framebuffer().bind();
    for (int i = 0; i < indexTargets_->count(); ++i) {
        if (frame_.info.gles) {
            // OpenGL ES 2.0 reads COLOR_ATTACHMENT0 only (no glReadBuffer): each target in turn is attached
            // there to a framebuffer of its own.
            gl::Framebuffer single = gl::Framebuffer::create();
            single.attachTexture(GL_COLOR_ATTACHMENT0, indexTargets_->texture(i));
            single.checkComplete("index target read-back");
            out.push_back(readPixelsRGBA8(indexTargets_->width(), indexTargets_->height()));
            continue;
        }
        glReadBuffer(GL_COLOR_ATTACHMENT0 + i);
        out.push_back(readPixelsRGBA8(indexTargets_->width(), indexTargets_->height()));
    }
    StateCache::current().bindFramebuffer(0);
    return out;
}

std::vector<float> LidrRenderer::volumeOutsideRadii(const std::vector<PointLight>& lights) const {
    std::vector<float> radii;
    radii.reserve(lights.size());
    for (size_t i = 0; i < lights.size(); ++i)
        radii.push_back(volumePass_.outsideRadiusFor(
            {uint32_t(i + 1), glm::vec4(lights[i].position, lights[i].radius), -1, spotCone(lights[i])}));
    return radii;
}

std::vector<uint8_t> LidrRenderer::readLightCounts() const {
    const int bits = volumePass_.stencilCountBits();
    if (bits == 0) return {};
    if (lightlessFrame_) return std::vector<uint8_t>(size_t(frame_.targets.width()) * size_t(frame_.targets.height()), 0);
    std::vector<uint8_t> s = frame_.targets.readStencil();
    const uint8_t mask = static_cast<uint8_t>((1u << bits) - 1u);
    for (uint8_t& v : s) v &= mask;
    StateCache::current().bindFramebuffer(0);
    return s;
}

}  // namespace lidr

namespace lidr {

std::vector<DepthSpanPass::Span> LidrRenderer::readDepthSpans() const {
    if (!depthSpans_ || depthSpans_.storesSamples()) return {};
    return depthSpans_.readSpans(frame_.targets.readDepth());
}

std::vector<ImageFloat> LidrRenderer::readSampleDepths() const {
    if (!depthSpans_.storesSamples()) return {};
    return depthSpans_.readSampleDepths();
}

}  // namespace lidr
