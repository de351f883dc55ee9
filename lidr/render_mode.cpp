#include "lidr/render_mode.h"

#include <algorithm>

#include "lidr/error.h"
#include "lidr/reference_renderer.h"

namespace lidr {

const std::vector<std::string>& renderModeNames() {
    static const std::vector<std::string> names = {"lidr", "tiled", "forward-multipass", "forward-brute"};
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

std::unique_ptr<Renderer> createRenderer(const RenderModeOptions& o, const GlInfo& info, const Scene& scene,
                                         int width, int height) {
    if (o.mode == "lidr") {
        LidrOptions lo = o.lidr;
        lo.forceFixedLightTable = lo.forceFixedLightTable || o.forceFixedLightTable;
        lo.msaaSamples = o.msaaSamples;
        lo.transparency = o.transparency;
        lo.timingMethod = o.timingMethod;
        return std::make_unique<LidrRenderer>(info, scene, lo, width, height);
    }
    if (o.mode == "tiled") {
        TiledOptions to = o.tiled;
        to.forceFixedLightTable = to.forceFixedLightTable || o.forceFixedLightTable;
        to.msaaSamples = o.msaaSamples;
        to.transparency = o.transparency;
        to.timingMethod = o.timingMethod;
        return std::make_unique<TiledRenderer>(info, scene, to, width, height);
    }
    if (o.mode == "forward-multipass") {
        MultipassOptions mo = o.multipass;
        mo.forceFixedLightTable = mo.forceFixedLightTable || o.forceFixedLightTable;
        mo.msaaSamples = o.msaaSamples;
        mo.timingMethod = o.timingMethod;
        return std::make_unique<MultipassForwardRenderer>(info, scene, mo, width, height);
    }
    if (o.mode == "forward-brute")
        return std::make_unique<ReferenceRenderer>(info, scene, width, height,
                                                   std::max<int>(1, int(scene.lights.size())), o.forceFixedLightTable,
                                                   o.msaaSamples, o.transparency);
    throw Error("unknown render mode '" + o.mode + "' (valid: " + renderModeList() + ")");
}

}  // namespace lidr
