#pragma once
// One volume program per number of index targets a draw writes (1..kMaxIndexTargets), compiled on first use:
// most schemes write one target, so the others are never built. Asking for more targets than the context's draw
// buffers is an UnsupportedError naming the count.
#include <functional>
#include <vector>

#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"

namespace lidr {

constexpr int kMaxIndexTargets = 8;

// The most index targets one draw can write in this context: its draw buffers (1 without them), at most
// kMaxIndexTargets.
int maxDrawTargets(const GlInfo& info);

class DrawTargetPrograms {
public:
    using Build = std::function<gl::Program(int targetCount)>;

    DrawTargetPrograms() = default;
    DrawTargetPrograms(const GlInfo& info, Build build);

    const gl::Program& get(int targetCount) const;

private:
    int maxDrawTargets_ = 1;
    Build build_;
    mutable std::vector<gl::Program> programs_;
};

}  // namespace lidr
