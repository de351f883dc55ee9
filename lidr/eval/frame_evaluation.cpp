#include "lidr/eval/frame_evaluation.h"

#include <algorithm>

namespace lidr {

FrameEvaluation evaluateFrame(const LidrRenderer& renderer, const Camera& camera,
                              const std::vector<PointLight>& lights, const ImageRGBA8& image,
                              const ImageRGBA8& reference) {
    FrameEvaluation e;
    const RenderTargets& t = renderer.targets();
    if (renderer.options().perSampleIndices) {
        // Multisample index targets and no single-sample depth: only the image can be judged, everywhere.
        const size_t n = size_t(t.width()) * t.height();
        e.withinBudget.assign(n, 1);
        e.marked.assign(n, 0);
        e.error = compareImages(image, reference);
        e.errorWithinBudget = e.error;
        return e;
    }
    const CameraMatrices cam = cameraMatrices(camera, t.width(), t.height());
    e.truth = computeCoverage(t.readDepth(), cam, lights);
    e.maxTruthOverlap = e.truth.maxOverlap();
    e.lists = checkIndexLists(e.truth, renderer.scheme(), renderer.readIndexTargets(),
                              static_cast<uint32_t>(lights.size()), renderer.frameLightIndices(),
                              renderer.frameIndexRegions());
    const std::vector<uint8_t> counts = renderer.readLightCounts();
    const size_t n = size_t(t.width()) * t.height();
    e.marked.assign(n, 0);
    for (size_t p = 0; p < n; ++p) e.marked[p] = counts.empty() ? e.truth.count(p) : counts[p];
    const int budget = renderer.scheme().config().budget;
    const int transparentBudget = renderer.transparentScheme().config().budget;
    const bool wholeLights = !renderer.scheme().keepsFirstMarks();
    if (renderer.drawsTransparency())
        e.frontFaceMarked = frontFaceCounts(t.readDepth(), cam, lights, renderer.volumeOutsideRadii(lights));
    e.withinBudget.assign(n, 0);
    e.droppedMarks.assign(n, 0);
    for (size_t p = 0; p < n; ++p)
        e.droppedMarks[p] = std::max(0, e.marked[p] - static_cast<int>(e.lists.decoded[p].size()));
    for (size_t p = 0; p < n; ++p) {
        if (!e.truth.surface[p]) {
            // Background: no opaque surface, but transparent layers in front of it read front-face lists.
            e.withinBudget[p] = e.frontFaceMarked.empty() || e.frontFaceMarked[p] <= transparentBudget;
            continue;
        }
        e.maxMarked = std::max(e.maxMarked, e.marked[p]);
        if (e.marked[p] > budget || (wholeLights && e.droppedMarks[p] > 0))
            ++e.pixelsOverBudget;
        else if (e.frontFaceMarked.empty() || e.frontFaceMarked[p] <= transparentBudget)
            e.withinBudget[p] = 1;
    }
    e.error = compareImages(image, reference);
    e.errorWithinBudget = compareImages(image, reference, 1, &e.withinBudget);
    return e;
}

}  // namespace lidr
