#include "lidr/modes/render_mode.h"

#include <algorithm>

#include "lidr/base/error.h"
#include "lidr/modes/auto_mode_renderer.h"
#include "lidr/modes/reference_renderer.h"

namespace lidr {

std::unique_ptr<Renderer> createRenderer(const RenderModeOptions& o, const GlInfo& info, const Scene& scene,
                                         int width, int height) {
    // The settings every mode shares come from the common fields.
    auto shared = [&](auto modeOptions) {
        modeOptions.forceFixedLightTable = modeOptions.forceFixedLightTable || o.forceFixedLightTable;
        modeOptions.msaaSamples = o.msaaSamples;
        modeOptions.timingMethod = o.timingMethod;
        return modeOptions;
    };
    if (o.mode == "lidr") {
        LidrOptions lo = shared(o.lidr);
        lo.transparency = o.transparency;
        return std::make_unique<LidrRenderer>(info, scene, lo, width, height);
    }
    if (o.mode == "tiled") {
        TiledOptions to = shared(o.tiled);
        to.transparency = o.transparency;
        return std::make_unique<TiledRenderer>(info, scene, to, width, height);
    }
    if (o.mode == "clustered") {
        ClusteredOptions co = shared(o.clustered);
        co.transparency = o.transparency;
        return std::make_unique<ClusteredRenderer>(info, scene, co, width, height);
    }
    if (o.mode == "forward-multipass")  // draws no transparent meshes (additive passes cannot blend a layer)
        return std::make_unique<MultipassForwardRenderer>(info, scene, shared(o.multipass), width, height);
    if (o.mode == "deferred") {
        DeferredOptions d = shared(o.deferred);
        d.transparency = o.transparency;
        return std::make_unique<DeferredRenderer>(info, scene, d, width, height);
    }
    if (o.mode == "tiled-deferred") {
        TiledDeferredOptions d = shared(o.tiledDeferred);
        d.transparency = o.transparency;
        return std::make_unique<TiledDeferredRenderer>(info, scene, d, width, height);
    }
    if (o.mode == "forward-brute")
        return std::make_unique<ReferenceRenderer>(info, scene, width, height,
                                                   std::max<int>(1, int(scene.lights.size())), o.forceFixedLightTable,
                                                   o.msaaSamples, o.transparency);
    if (o.mode == "auto") return std::make_unique<AutoModeRenderer>(info, scene, o, width, height);
    throw Error("unknown render mode '" + o.mode + "' (valid: " + renderModeList() + ")");
}

}  // namespace lidr
