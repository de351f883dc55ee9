#include "frame_accuracy.h"

#include "lidr/eval/frame_evaluation.h"
#include "lidr/eval/light_coverage.h"
#include "lidr/modes/clustered_renderer.h"
#include "lidr/modes/tiled_renderer.h"
#include "lidr/scene/camera.h"
#include "lidr/technique/lidr_renderer.h"

namespace lidr::bench {

FrameAccuracy judgeFrame(Renderer& renderer, const Camera& camera, const std::vector<PointLight>& lights,
                         const ImageRGBA8& image, const ImageRGBA8& reference) {
    FrameAccuracy a;
    if (auto* lidrRenderer = dynamic_cast<LidrRenderer*>(&renderer)) {
        const FrameEvaluation ev = evaluateFrame(*lidrRenderer, camera, lights, image, reference);
        a.error = ev.error;
        a.errorWithinBudget = ev.errorWithinBudget;
        a.pixelsOverBudget = ev.pixelsOverBudget;
        a.hasLists = !lidrRenderer->options().perSampleIndices;  // multisample index textures: the image only
        if (!a.hasLists) return a;
        // sphere-span (MSAA): drops against what every sample's surface needs, not the pixel centre's alone.
        const ListCheck& lists = ev.spanTruth.offsets.empty() ? ev.lists : ev.spanLists;
        a.droppedLightPixels = lists.droppedLightPixels;
        a.pixelsWithDrops = lists.pixelsWithDrops;
        a.shadedLightPixels = ev.lists.slotsUsed;
        for (size_t p = 0; p < ev.truth.surface.size(); ++p)
            if (ev.truth.surface[p]) a.trueLightPixels += ev.truth.count(p);
        return a;
    }
    a.error = compareImages(image, reference);
    a.errorWithinBudget = a.error;
    const auto* tiled = dynamic_cast<const TiledRenderer*>(&renderer);
    const auto* clustered = dynamic_cast<const ClusteredRenderer*>(&renderer);
    if ((!tiled && !clustered) || renderer.targets().samples() > 0) return a;
    const int width = image.width, height = image.height;
    const CoverageTruth truth = computeCoverage(renderer.targets().readDepth(), cameraMatrices(camera, width, height), lights);
    PixelListCheck check;
    if (clustered) {
        const ClusterGrid& g = clustered->grid();
        check = checkPixelLists(truth, clustered->pixelClusters(), g.entries(), g.offsets(), g.counts());
    } else {
        const LightGrid& g = tiled->grid();
        std::vector<int> tileOfPixel(size_t(width) * size_t(height));
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) tileOfPixel[size_t(y) * size_t(width) + size_t(x)] = g.tileOf(x, height - 1 - y);
        check = checkPixelLists(truth, tileOfPixel, g.entries(), g.opaqueOffsets(), g.opaqueCounts());
    }
    a.hasLists = true;
    a.droppedLightPixels = check.missingPairs;
    a.pixelsWithDrops = check.pixelsWithMissing;
    a.trueLightPixels = check.truthPairs;
    a.shadedLightPixels = check.listPairs;
    return a;
}

}  // namespace lidr::bench
