#pragma once
// Pass 2 of LIDR: light volumes rasterised into the RGBA8 light-index targets. The pass owns the volume test
// (which pixels a light marks) and the stencil bookkeeping; the packing scheme owns what is written there
// (colour, blend state, slot limits) and calls draw() once per sub-pass.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "lidr/camera.h"
#include "lidr/context.h"
#include "lidr/gl_resources.h"
#include "lidr/gl_state.h"
#include "lidr/light_volume_mesh.h"

namespace lidr {

enum class VolumeTest {
    BackFace,      // back faces, depth GEQUAL: cheap; also marks surfaces in front of a light (wastes slots)
    ExactStencil,  // per light: front faces mark the pixels in front of the volume in stencil, then back
                   // faces GEQUAL where unmarked: exactly the surfaces inside the volume
    FrontFace,     // front faces, depth LEQUAL: every light whose volume crosses the eye ray in front of the
                   // opaque surface, so transparent surfaces and MSAA edge samples in front find their lights
};
const char* volumeTestName(VolumeTest t);
VolumeTest parseVolumeTest(const std::string& name);  // "backface", "exact", "frontface"

constexpr int kMaxIndexTargets = 4;
using IndexColors = std::array<glm::vec4, kMaxIndexTargets>;

// A light as the volume pass sees it: its 1-based index and where it is.
struct VolumeLight {
    uint32_t index = 0;
    glm::vec4 posRadius{0.0f};
};

// The index textures of one frame plus the FBO that renders into them (depth-stencil shared with the scene).
class IndexTargets {
public:
    IndexTargets() = default;
    // samples > 0: multisample textures (the per-sample MSAA path); depthStencil must have as many samples.
    IndexTargets(int count, int width, int height, const gl::Renderbuffer& depthStencil, int samples = 0);
    int samples() const { return samples_; }
    int count() const { return static_cast<int>(textures_.size()); }
    const gl::Texture& texture(int i) const { return textures_[i]; }
    const gl::Framebuffer& framebuffer() const { return fbo_; }
    size_t bytes() const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    std::vector<gl::Texture> textures_;
    gl::Framebuffer fbo_;
    int width_ = 0, height_ = 0, samples_ = 0;
};

// One sub-pass of a packing scheme: which targets, how to blend, and how stencil limits the writes.
struct VolumeDraw {
    std::string name = "light-volumes";
    int firstTarget = 0, targetCount = 1;  // written together (draw buffers) when targetCount > 1
    glm::bvec4 colorMask{true, true, true, true};
    bool blend = false;
    GLenum blendEquation = GL_FUNC_ADD;
    GLenum blendSrc = GL_ONE, blendDst = GL_ZERO;
    glm::vec4 blendColor{0.0f};
    // slotLimit > 0: a pixel takes at most slotLimit lights, the first ones in draw order; the stencil
    // then counts every light that marks the pixel (saturating), so overflow is counted, not written.
    int slotLimit = 0;
};

class LightVolumePass {
public:
    LightVolumePass() = default;
    LightVolumePass(const GlInfo& info, VolumeTest test);

    // Binds the targets, clears them to 0 (the null light everywhere) and clears stencil.
    void begin(const IndexTargets& targets, const CameraMatrices& camera);
    // Draws each light's volume with the sub-pass's state; colors(index) gives the value per target.
    void draw(const VolumeDraw& d, const std::vector<VolumeLight>& lights,
              const std::function<IndexColors(uint32_t index)>& colors);
    void end();

    VolumeTest test() const { return test_; }
    // Stencil bits that count lights per pixel after the pass (0 if the last draw kept no count).
    int stencilCountBits() const { return countBits_; }
    long drawCalls() const { return drawCalls_; }
    float meshOutsideRadius() const { return mesh_.outsideRadius; }

private:
    void drawVolume(const VolumeLight& light) const;
    const gl::Program& programFor(int targetCount) const;
    VolumeTest test_ = VolumeTest::BackFace;
    bool depthClamp_ = false;
    LightVolumeMesh mesh_;
    gl::Buffer vertices_, indices_;
    std::vector<gl::Program> programs_;  // one per target count 1..kMaxIndexTargets
    const IndexTargets* targets_ = nullptr;
    CameraMatrices camera_;
    int countBits_ = 0;
    mutable long drawCalls_ = 0;
};

}  // namespace lidr
