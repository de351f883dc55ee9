#include "pixel_list_geometry.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "gl_test_context.h"
#include "lidr/base/error.h"
#include "lidr/base/gl.h"
#include "lidr/gl/gl_state.h"

namespace lidr::test {

std::string testShaderSource(const std::string& name, const ShaderDefines& defines) {
    std::ifstream in(sourcePath("tests/shaders/" + name));
    if (!in) throw Error("no test shader tests/shaders/" + name);
    std::stringstream text;
    text << in.rdbuf();
    return buildShaderSourceFromText(name, text.str(), defines);
}

PixelListGeometry::PixelListGeometry(const GlInfo& info)
    : programs_(info, [](int targetCount) {
          const ShaderDefines defs = {{"LIDR_DRAW_TARGETS", std::to_string(targetCount)}};
          return gl::Program::create("pixel_list_volume-" + std::to_string(targetCount),
                                     testShaderSource("pixel_list_volume.vert", defs),
                                     testShaderSource("pixel_list_volume.frag", defs), {{"aPosition", gl::kPosition}});
      }) {
    // Two clockwise triangles over the whole target: back faces, as the volume test draws them.
    const float q[] = {-1, -1, 0, -1, 1, 0, 1, 1, 0, -1, -1, 0, 1, 1, 0, 1, -1, 0};
    quad_ = gl::Buffer::create(GL_ARRAY_BUFFER, q, sizeof(q));
}

void PixelListGeometry::begin(const CameraMatrices&, glm::ivec2 targetSize, const gl::Texture*) {
    if (!source_) throw Error("PixelListGeometry: no lists (setSource)");
    targetSize_ = targetSize;
    glBindBuffer(GL_ARRAY_BUFFER, quad_.id());
    glEnableVertexAttribArray(gl::kPosition);
    glVertexAttribPointer(gl::kPosition, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
}

void PixelListGeometry::end() {
    glDisableVertexAttribArray(gl::kPosition);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

// Row block t (rows t*R .. t*R+R-1, R = rows per target) holds target t's colour of index i at texel
// (i mod 256, t*R + i/256), exactly the bytes the colors callback asks for.
void PixelListGeometry::uploadColorTable(const VolumeDraw& d, const IndexColorsFor& colors) {
    const int rows = static_cast<int>(source_->maxIndex / 256 + 1);
    const int height = rows * d.targetCount;
    std::vector<uint8_t> texels(size_t(256) * height * 4, 0);
    for (uint32_t i = 0; i <= source_->maxIndex; ++i) {
        const IndexColors c = colors(i);
        for (int t = 0; t < d.targetCount; ++t)
            for (int ch = 0; ch < 4; ++ch) {
                const float v = std::clamp(c[t][ch], 0.0f, 1.0f) * 255.0f;
                texels[((size_t(t) * rows + i / 256) * 256 + i % 256) * 4 + ch] = static_cast<uint8_t>(std::lround(v));
            }
    }
    colorTable_ = gl::Texture::create2D(GL_RGBA8, 256, height, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
}

void PixelListGeometry::beginSteps(const VolumeDraw& d, const VolumeDrawPlan& plan, const IndexColorsFor& colors) {
    if (plan.program != VolumeProgram::PerLight)
        throw Error("pixel lists stand in for the stencil tests' volumes, one light per draw");
    const gl::Program& program = programs_.get(plan.programTargets);
    program.use();
    uploadColorTable(d, colors);
    colorTable_.bind(gl::kUnitPixelListColors);
    program.set("uStepIndices", gl::kUnitPixelListStep);
    program.set("uColorTable", gl::kUnitPixelListColors);
    program.set("uInvTargetSize", glm::vec2(1.0f / targetSize_.x, 1.0f / targetSize_.y));
    program.set("uTableRowsPerTarget", float(source_->maxIndex / 256 + 1));
    program.set("uTableHeight", float((source_->maxIndex / 256 + 1) * d.targetCount));
}

void PixelListGeometry::drawStep(const VolumeStep& step, const std::vector<VolumeLight>& lights,
                                 const IndexColorsFor&) {
    const uint32_t index = lights[size_t(step.firstLight)].index;
    if (index == 0 || index - 1 >= source_->steps.size()) throw Error("pixel-list step out of range");
    source_->steps[index - 1]->bind(gl::kUnitPixelListStep);
    StateCache::current().drawArrays(GL_TRIANGLES, 0, 6);
}

}  // namespace lidr::test
