#pragma once
// Pass 2 of LIDR: light volumes rasterised into the RGBA8 light-index targets. The pass owns the volume test
// (which pixels a light marks) and the stencil bookkeeping; the packing scheme owns what is written there
// (colour, blend state, slot limits) and calls draw() once per sub-pass. Which state each draw takes is
// planned on the CPU (volume_draw_plan.h); what is drawn is the geometry's (light_volume_geometry.h).
#include <string>
#include <vector>

#include "lidr/scene/camera.h"
#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/gl_state.h"
#include "lidr/technique/light_volume_geometry.h"
#include "lidr/technique/volume_draw_plan.h"

namespace lidr {

// The index textures of one frame plus the FBO that renders into them (depth-stencil shared with the scene).
class IndexTargets {
public:
    IndexTargets() = default;
    // samples > 0: multisample textures (the per-sample MSAA path); depthStencil must have as many samples.
    // separateStencil: the stencil beside a 16-bit depth (RenderTargets::separateStencil()); nullptr when
    // depthStencil is a packed depth-stencil.
    IndexTargets(int count, int width, int height, const gl::Renderbuffer& depthStencil, int samples = 0,
                 const gl::Renderbuffer* separateStencil = nullptr);
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

class LightVolumePass {
public:
    LightVolumePass() = default;
    // volumeDetail: draw a light with the coarsest of the 20-, 80- and 320-face volumes whose extra reach past
    // the 320-face one stays under a pixel on screen (lidr-bench: about half the volume pass on many small
    // lights); false: always the 320-face volume. depth: the depth precision the volume shaders emulate
    // (LidrOptions::emulatedDepthBits).
    // depthSpans: a sphere-ray pass beside a sphere-span one, whose rays end at the far end of the samples' depth
    // span instead of the pixel centre's surface (setDepthSpans); sphere-span always reads the spans.
    // spanSamples > 0: the spans are the distances of this many samples (DepthSpanStorage::Samples, the driver's
    // count; GLSL 1.50 programs that loop over them unrolled).
    LightVolumePass(const GlInfo& info, VolumeTest test, bool volumeDetail = false, DepthEmulation depth = {},
                    bool depthSpans = false, int spanSamples = 0);

    // Binds the targets, clears them to 0 (the null light everywhere) and clears stencil. The shader tests
    // read `depth`, a single-sample depth texture of the pre-pass (not attached to the targets).
    void begin(const IndexTargets& targets, const CameraMatrices& camera, const gl::Texture* depth = nullptr);
    // Draws each light's volume with the sub-pass's state (planVolumeDraw); colors(index) gives the value per
    // target.
    void draw(const VolumeDraw& d, const std::vector<VolumeLight>& lights, const IndexColorsFor& colors);
    // The plan draw() runs for these lights (the camera and scissor of the current pass); CPU only.
    VolumeDrawPlan planFor(const VolumeDraw& d, const std::vector<VolumeLight>& lights) const;
    void end();
    // Limits the following draws to a pixel rectangle (x, y, width, height; GL window coordinates), e.g. where
    // transparent geometry can be; nullptr: the whole target.
    void setScissor(const glm::ivec4* box) { scissor_ = box ? *box : glm::ivec4(-1); }
    // Draws the passes that follow (from begin() to end()) with another geometry, which outlives them; nullptr:
    // the lights' volumes again. Tests draw exact per-pixel lists this way (tests/pixel_list_geometry.h).
    void setGeometry(VolumeGeometry* geometry) { geometry_ = geometry; }
    const VolumeGeometry& geometry() const {
        return geometry_ ? *geometry_ : static_cast<const VolumeGeometry&>(volumes_);
    }

    VolumeTest test() const { return test_; }
    // The pre-pass depth precision, 24 (default) or 16 bits (real or emulated): the shader tests' margin is in
    // its steps.
    void setDepthBits(int bits) { volumes_.setDepthBits(bits); }
    void setDepthSpans(const DepthSpanPass* spans) { volumes_.setDepthSpans(spans); }
    // The sphere test's shadow test (LightVolumeGeometry::setShadows): lights with a VolumeLight::shadowTile are
    // kept only where their maps leave the surface lit. nullptr: none (the front-face tests never have one).
    void setShadows(const ShadowMaps* maps, const ShadowSettings& settings) { volumes_.setShadows(maps, settings); }
    // The sphere test's tile culling (LightVolumeGeometry::setTiles); its margin for VolumeTiles::build.
    void setTiles(const VolumeTiles* tiles, const CameraMatrices& camera) { volumes_.setTiles(tiles, camera); }
    bool drawsScreenTiles() const { return volumes_.drawsScreenTiles(); }
    // With tiles: whether the sphere may mark any pixel this frame (LightVolumeGeometry::sphereReachesTiles).
    bool sphereReachesTiles(const glm::vec4& posRadius) { return volumes_.sphereReachesTiles(posRadius); }
    uint32_t sphereRegions(const glm::vec4& posRadius, const IndexRegions& regions) {
        return volumes_.sphereRegions(posRadius, regions);
    }
    void setRegions(const IndexRegions& regions) { volumes_.setRegions(regions); }
    float tileDepthMargin() const { return volumes_.depthMargin(); }
    // Pixels the tile quads of the last pass covered (0 without tile culling).
    long tileQuadPixels() const { return volumes_.tileQuadPixels(); }
    // The tile-culled pass's bound: where pixels marked by more than `count` lights can be
    // (LightVolumeGeometry::candidateArea; width -1: unknown, 0: nowhere).
    glm::ivec4 tileCandidateArea(int count) const { return volumes_.candidateArea(count); }
    // Lights asked for by the last pass's tile-quad draws, once per draw (0 without tile culling).
    long tileStepLights() const { return volumes_.tileStepLights(); }
    const CameraMatrices& camera() const { return camera_; }
    // True where the light is drawn without its depth test (no depth clamp and its volume reaches the far
    // plane): it then marks its whole screen footprint.
    bool marksWholeFootprint(const VolumeLight& light) const;
    // The largest relative vertex distance of the volumes this pass may draw (a bound for CPU models).
    float volumeOutsideRadius() const { return volumes_.volumeOutsideRadius(); }
    // The volume mesh drawn for `light` in the current pass (0 = 20 faces, 1 = 80, 2 = 320) and its relative
    // vertex distance: a function of the light and the camera alone, the same for every use in a frame.
    int detailFor(const VolumeLight& light) const { return volumes_.detailFor(light, camera_); }
    // The shader tests: kSphereRadiusScale, what they mark, whatever mesh they draw.
    float outsideRadiusFor(const VolumeLight& light) const { return volumes_.outsideRadiusFor(light, camera_); }
    // Stencil bits that count lights per pixel after the pass (0 if the last draw kept no count).
    int stencilCountBits() const { return countBits_; }
    long drawCalls() const { return drawCalls_; }
    float meshOutsideRadius() const { return volumeOutsideRadius(); }
    // Lights per draw of the shader tests (from the vertex uniform limit); 1 for the stencil tests.
    int batchSize() const { return volumes_.batchSize(); }
    static constexpr float kSphereRadiusScale = LightVolumeGeometry::kSphereRadiusScale;
    static constexpr float kSphereDepthSteps = LightVolumeGeometry::kSphereDepthSteps;

private:
    VolumeGeometry& activeGeometry() { return geometry_ ? *geometry_ : static_cast<VolumeGeometry&>(volumes_); }
    VolumeTest test_ = VolumeTest::BackFace;
    bool depthClamp_ = false;
    bool gles_ = false;  // OpenGL ES: draw buffers by framebufferFrom, glDrawBuffers only with EXT_draw_buffers
    int maxDrawTargets_ = 1;
    LightVolumeGeometry volumes_;
    VolumeGeometry* geometry_ = nullptr;  // setGeometry's, else volumes_
    glm::ivec4 scissor_{-1};  // z < 0: none
    const IndexTargets* targets_ = nullptr;
    CameraMatrices camera_;
    int countBits_ = 0;
    long drawCalls_ = 0;
};

}  // namespace lidr
