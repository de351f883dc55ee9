#include "lidr/render/frame_pass.h"

#include <algorithm>
#include <cstring>
#include <sstream>

namespace lidr {

std::string describePasses(const std::vector<FramePass>& passes) {
    size_t nameWidth = 0;
    for (const FramePass& p : passes) nameWidth = std::max(nameWidth, std::strlen(p.name));
    std::ostringstream s;
    for (size_t i = 0; i < passes.size(); ++i) {
        const FramePass& p = passes[i];
        s << (i < 9 ? "   " : "  ") << i + 1 << "  " << p.name << std::string(nameWidth - std::strlen(p.name), ' ')
          << "  " << p.reads << " -> " << p.writes << "\n";
        if (*p.when) s << std::string(8 + nameWidth, ' ') << "when: " << p.when << "\n";
    }
    return s.str();
}

}  // namespace lidr
