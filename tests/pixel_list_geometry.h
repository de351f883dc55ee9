#pragma once
// The light-volume pass drawing per-pixel light lists instead of light volumes (LightVolumePass::setGeometry), so
// any lists go through the real blend and stencil state of a scheme's draws (tests/test_shader_unpack.cpp).
// "Light" j (VolumeLight::index = j + 1) is a full-target quad that marks exactly the pixels whose list has a
// j-th entry, and writes the colours of THAT entry's index (looked up in a table filled from the draw's colors
// callback). The quad is a back face; clear depth to 0.5: list entries pass the depth test, "decoy" entries
// (B = 255: a volume in front of the surface) fail it. Stands in for the stencil tests' volumes (one light per
// draw); a batched plan (the shader tests) is refused.
#include <string>
#include <vector>

#include "lidr/gl/gl_resources.h"
#include "lidr/gl/shader_source.h"
#include "lidr/technique/light_volume_geometry.h"

namespace lidr::test {

struct PixelListSource {
    std::vector<const gl::Texture*> steps;  // RGBA8, target-sized: R, G = index low, high byte (0: none); B decoy
    uint32_t maxIndex = 255;                // colour table covers indices 0..maxIndex
};

class PixelListGeometry final : public VolumeGeometry {
public:
    explicit PixelListGeometry(const GlInfo& info);
    // The lists of the passes that follow; it outlives them.
    void setSource(const PixelListSource* source) { source_ = source; }

    // Quads in clip space: no near or far plane to reach, and any step may mark any pixel.
    VolumeLightFacts factsFor(const VolumeLight&, const CameraMatrices&) const override { return {}; }
    bool marksWithinLightFootprints() const override { return false; }
    void begin(const CameraMatrices& camera, glm::ivec2 targetSize, const gl::Texture* depth) override;
    void end() override;
    void beginSteps(const VolumeDraw& d, const VolumeDrawPlan& plan, const IndexColorsFor& colors) override;
    void drawStep(const VolumeStep& step, const std::vector<VolumeLight>& lights,
                  const IndexColorsFor& colors) override;

private:
    void uploadColorTable(const VolumeDraw& d, const IndexColorsFor& colors);
    DrawTargetPrograms programs_;
    gl::Buffer quad_;
    gl::Texture colorTable_;
    const PixelListSource* source_ = nullptr;
    glm::ivec2 targetSize_{1};
};

// tests/shaders/<name> as buildShaderSource builds lidr's own (defines after #version, #line directives).
std::string testShaderSource(const std::string& name, const ShaderDefines& defines = {});

}  // namespace lidr::test
