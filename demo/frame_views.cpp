#include "frame_views.h"

#include <algorithm>

#include "lidr/base/visualize.h"

namespace lidr::demo {

std::unique_ptr<ReferenceRenderer> makeReference(const GlInfo& info, const Scene& scene, const RenderModeOptions& o,
                                                 int width, int height, int lightCount) {
    const bool lidrMode = o.mode == "lidr";
    return std::make_unique<ReferenceRenderer>(info, scene, width, height, std::max(1, lightCount),
                                               o.forceFixedLightTable, o.msaaSamples,
                                               o.transparency && o.mode != "forward-multipass",
                                               lidrMode && o.lidr.perSampleIndices);
}

LidrViews lidrViews(const FrameEvaluation& ev, int width, int height, int budget) {
    LidrViews v;
    v.indexLists = indexListImage(width, height, ev.lists.decoded);
    std::vector<int> truthCounts(ev.truth.surface.size());
    for (size_t p = 0; p < truthCounts.size(); ++p) truthCounts[p] = ev.truth.count(p);
    v.overlap = overlapHeatMap(width, height, truthCounts, budget, &ev.truth.surface);
    v.marked = overlapHeatMap(width, height, ev.marked, budget, &ev.truth.surface);
    return v;
}

}  // namespace lidr::demo
