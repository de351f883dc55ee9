#pragma once
// Pass 2 of LIDR: light volumes rasterised into the RGBA8 light-index targets. The pass owns the volume test
// (which pixels a light marks) and the stencil bookkeeping; the packing scheme owns what is written there
// (colour, blend state, slot limits) and calls draw() once per sub-pass.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "lidr/scene/camera.h"
#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/gl_state.h"
#include "lidr/technique/light_volume_mesh.h"
#include "lidr/technique/volume_draw_plan.h"

namespace lidr {

constexpr int kMaxIndexTargets = 8;
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
    // The framebuffer whose COLOR_ATTACHMENT0.. are targets first..: framebuffer() on desktop GL, where
    // glDrawBuffers maps gl_FragData[0] to any attachment; OpenGL ES (EXT_draw_buffers) maps gl_FragData[i] to
    // COLOR_ATTACHMENTi only, so there a draw into targets from `first` on binds a framebuffer of its own (the
    // same textures and depth-stencil).
    const gl::Framebuffer& framebufferFrom(int first) const;
    size_t bytes() const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    std::vector<gl::Texture> textures_;
    gl::Framebuffer fbo_;
    std::vector<gl::Framebuffer> fromFbos_;  // OpenGL ES: [k - 1] has targets k.. at attachments 0..
    int width_ = 0, height_ = 0, samples_ = 0;
};

// Test hook: instead of light volumes, "light" j (VolumeLight::index = j + 1) is a full-target quad that marks
// exactly the pixels whose list has a j-th entry, and writes the colours of THAT entry's index (looked up in a
// table the pass fills from the draw's colors callback). Through it any per-pixel index lists go through the
// real blend and stencil state of a scheme's draws. The quad is a back face; clear depth to 0.5: list entries
// pass the depth test, "decoy" entries (B = 255: a volume in front of the surface) fail it.
struct PixelListSource {
    std::vector<const gl::Texture*> steps;  // RGBA8, target-sized: R, G = index low, high byte (0: none); B decoy
    uint32_t maxIndex = 255;                // colour table covers indices 0..maxIndex
};

class LightVolumePass {
public:
    LightVolumePass() = default;
    // volumeDetail: draw a light with the coarsest of the 20-, 80- and 320-face volumes whose extra reach past
    // the 320-face one stays under a pixel on screen (lidr-bench: about half the volume pass on many small
    // lights); false: always the 320-face volume.
    LightVolumePass(const GlInfo& info, VolumeTest test, bool volumeDetail = false);

    // Binds the targets, clears them to 0 (the null light everywhere) and clears stencil. The shader tests
    // read `depth`, a single-sample depth texture of the pre-pass (not attached to the targets).
    void begin(const IndexTargets& targets, const CameraMatrices& camera, const gl::Texture* depth = nullptr);
    // Draws each light's volume with the sub-pass's state; colors(index) gives the value per target.
    void draw(const VolumeDraw& d, const std::vector<VolumeLight>& lights,
              const std::function<IndexColors(uint32_t index)>& colors);
    void end();
    // Limits the following draws to a pixel rectangle (x, y, width, height; GL window coordinates), e.g. where
    // transparent geometry can be; nullptr: the whole target.
    void setScissor(const glm::ivec4* box) { scissor_ = box ? *box : glm::ivec4(-1); }
    // Draws the lights that follow through the pixel-list test hook (nullptr: light volumes again).
    void setPixelListSource(const PixelListSource* source) { listSource_ = source; }

    VolumeTest test() const { return test_; }
    const CameraMatrices& camera() const { return camera_; }
    bool drawingPixelLists() const { return listSource_ != nullptr; }
    // True where the light is drawn without its depth test (no depth clamp and its volume reaches the far
    // plane): it then marks its whole screen footprint.
    bool marksWholeFootprint(const VolumeLight& light) const;
    // The largest relative vertex distance of the volumes this pass may draw (a bound for CPU models).
    float volumeOutsideRadius() const { return meshes_[size_t(coarsest_)].outsideRadius; }
    // The volume mesh drawn for `light` in the current pass (0 = 20 faces, 1 = 80, 2 = 320) and its relative
    // vertex distance: a function of the light and the camera alone, the same for every use in a frame.
    int detailFor(const VolumeLight& light) const;
    // The shader tests: kSphereRadiusScale, what they mark, whatever mesh they draw.
    float outsideRadiusFor(const VolumeLight& light) const;
    // Stencil bits that count lights per pixel after the pass (0 if the last draw kept no count).
    int stencilCountBits() const { return countBits_; }
    long drawCalls() const { return drawCalls_; }
    float meshOutsideRadius() const { return volumeOutsideRadius(); }
    // Lights per draw of the shader tests (from the vertex uniform limit); 1 for the stencil tests.
    int batchSize() const { return batch_; }
    // The shader tests keep a light up to this many times its radius: a hair over 1, so rounding in the
    // rebuilt surface point never loses a pixel the forward pass lights (the CPU truth's band lies inside).
    static constexpr float kSphereRadiusScale = 1.0005f;
    // The sphere tests treat the pixel's surface as anywhere within this many steps of the 24-bit depth copy
    // (light_volume_sphere.frag): the stored depth is the true depth within half a step, and rebuilding distance
    // from it in fp32 costs about one more. Negligible at ordinary near/far ratios (about 1 mm at 20 m for near
    // 0.1 m), it keeps a light whose sphere the true surface reaches from being lost where depth precision is
    // coarse (far/near 1e5 and up: doc/stability.md).
    static constexpr float kSphereDepthSteps = 3.0f;

private:
    VolumeLightFacts factsFor(const VolumeLight& light) const;
    bool reachesFarPlane(const VolumeLight& light) const;  // the drawn mesh reaches the far plane
    int batchFor(int targetCount) const;  // lights per draw for this many targets
    static constexpr int kMaxBatch = 256, kReservedVertexUniforms = 12;
    // A plan's program and per-draw uniforms, then each step's light uniforms and draw call.
    void beginSteps(const VolumeDraw& d, const VolumeDrawPlan& plan, const std::function<IndexColors(uint32_t)>& colors);
    void drawStep(const VolumeStep& step, const std::vector<VolumeLight>& lights,
                  const std::function<IndexColors(uint32_t)>& colors);
    const gl::Program& batchProgramFor(int targetCount) const;
    const gl::Program& programFor(int targetCount) const;
    void uploadColorTable(const VolumeDraw& d, const std::function<IndexColors(uint32_t)>& colors);
    VolumeTest test_ = VolumeTest::BackFace;
    bool depthClamp_ = false;
    bool gles_ = false;  // OpenGL ES: draw buffers by framebufferFrom, glDrawBuffers only with EXT_draw_buffers
    static constexpr int kDetailLevels = 3;
    LightVolumeMesh meshes_[kDetailLevels];  // subdivisions 0, 1, 2, in one vertex and one index buffer
    GLsizei firstIndex_[kDetailLevels] = {}, indexCount_[kDetailLevels] = {};
    int coarsest_ = kDetailLevels - 1;      // 0 with volumeDetail, else the finest only
    gl::Buffer vertices_, indices_;
    // One per target count 1..kMaxIndexTargets, compiled on first use (most schemes write one target).
    mutable std::vector<gl::Program> programs_, listPrograms_;  // listPrograms_: the test hook's
    // Shader tests: batch_ copies of the batchLevel_ volume mesh, each vertex (x, y, z, slot).
    int batch_ = 1, batchLevel_ = 0, maxVertexUniformVectors_ = 128;
    GLsizei batchCopyIndices_ = 0;
    gl::Buffer batchVertices_, batchIndices_;
    mutable std::vector<gl::Program> batchPrograms_;
    const gl::Texture* depth_ = nullptr;
    glm::ivec4 scissor_{-1};  // z < 0: none
    // The current plan's program and its per-step uniforms (one light, or a batch's arrays).
    VolumeProgram stepProgram_ = VolumeProgram::PerLight;
    int stepTargets_ = 1;
    gl::Uniform<glm::vec4> lightsUniform_, colorsUniform_;
    gl::Uniform<float> clampUniform_;
    std::vector<glm::vec4> lightData_, colorData_;
    int maxDrawTargets_ = 1;
    gl::Buffer quad_;
    gl::Texture colorTable_;
    const PixelListSource* listSource_ = nullptr;
    const IndexTargets* targets_ = nullptr;
    CameraMatrices camera_;
    int countBits_ = 0;
    mutable long drawCalls_ = 0;
};

}  // namespace lidr
