#pragma once
// How many lights overlap on screen, measured on the GPU without reading pixels back: after a volume pass
// the stencil holds each pixel's count of lights that mark it (saturating at 255). One full-screen
// triangle per threshold t, stencil-tested "count > t" with colour and depth off, inside an occlusion query,
// counts the pixels over t. The automatic budget (lidr/technique/auto_configuration.h) reads them.
#include <array>

#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/gl_state.h"

namespace lidr {

class OverlapProbe {
public:
    static constexpr int kThresholds = 5;
    static constexpr std::array<int, kThresholds> kThreshold = {1, 2, 4, 8, 16};  // the budgets lidr has

    OverlapProbe() = default;
    explicit OverlapProbe(const GlInfo& info);
    explicit operator bool() const { return static_cast<bool>(program_); }
    // Issues the queries over the bound framebuffer (its stencil holds the counts), within `scissor` when given
    // (x, y, width, height). Leaves the stencil unchanged.
    void issue(const glm::ivec4* scissor = nullptr);
    bool issued() const { return issued_; }
    // Pixels whose count exceeds kThreshold[i], for every threshold; waits for the GPU.
    std::array<long, kThresholds> pixelsAbove() const;
    // The smallest budget of kThreshold that no pixel exceeds; 0 when even the largest is exceeded.
    static int smallestBudget(const std::array<long, kThresholds>& above);
    long drawCalls() const { return drawCalls_; }

private:
    gl::Program program_;
    gl::Buffer triangle_;
    std::array<gl::Object, kThresholds> queries_;
    bool issued_ = false;
    long drawCalls_ = 0;
};

}  // namespace lidr
