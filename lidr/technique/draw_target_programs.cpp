#include "lidr/technique/draw_target_programs.h"

#include <algorithm>
#include <string>
#include <utility>

#include "lidr/base/error.h"

namespace lidr {

int maxDrawTargets(const GlInfo& info) {
    return std::min(kMaxIndexTargets, info.drawBuffers ? std::max(1, info.maxDrawBuffers) : 1);
}

DrawTargetPrograms::DrawTargetPrograms(const GlInfo& info, Build build)
    : maxDrawTargets_(maxDrawTargets(info)),
      build_(std::move(build)),
      programs_(kMaxIndexTargets) {}

const gl::Program& DrawTargetPrograms::get(int targetCount) const {
    if (targetCount < 1 || targetCount > maxDrawTargets_)
        throw UnsupportedError("writing " + std::to_string(targetCount) +
                               " index targets at once needs that many draw buffers");
    gl::Program& p = programs_[size_t(targetCount - 1)];
    if (!p) p = build_(targetCount);
    return p;
}

}  // namespace lidr
