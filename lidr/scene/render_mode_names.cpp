#include "lidr/scene/render_mode_names.h"

#include <algorithm>

namespace lidr {

const std::vector<RenderModeInfo>& renderModes() {
    static const std::vector<RenderModeInfo> modes = {
        {"lidr", "light indexed deferred: light volumes write each pixel's light indices, the forward pass reads them"},
        {"tiled", "tiled forward: a CPU-built light list per screen tile, bounded by the tile's depth range"},
        {"clustered", "clustered forward: a CPU-built light list per cluster (screen tile x view-depth slice)"},
        {"forward-multipass", "multi-pass forward: each mesh drawn once per batch of the lights that touch it"},
        {"forward-brute", "brute-force forward: every pixel shades every light (the reference)"},
        {"auto", "the fastest of lidr, tiled, clustered and forward-multipass for this scene, measured"},
    };
    return modes;
}

const std::vector<std::string>& renderModeNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const RenderModeInfo& m : renderModes()) n.push_back(m.name);
        return n;
    }();
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

std::string renderModeDescription(const std::string& name) {
    for (const RenderModeInfo& m : renderModes())
        if (name == m.name) return m.description;
    return "";
}

}  // namespace lidr
