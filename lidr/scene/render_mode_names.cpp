#include "lidr/scene/render_mode_names.h"

#include <algorithm>

namespace lidr {

const std::vector<std::string>& renderModeNames() {
    static const std::vector<std::string> names = {"lidr", "tiled", "clustered", "forward-multipass", "deferred", "tiled-deferred",
                                                         "forward-brute", "auto"};
    return names;
}

bool isRenderModeName(const std::string& name) {
    const auto& n = renderModeNames();
    return std::find(n.begin(), n.end(), name) != n.end();
}

std::string renderModeList() {
    std::string s;
    for (const std::string& n : renderModeNames()) s += (s.empty() ? "" : ", ") + n;
    return s;
}

}  // namespace lidr
