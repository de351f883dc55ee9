#include "frame_accuracy.h"

#include "lidr/base/error.h"

#include <algorithm>

#include "lidr/eval/frame_evaluation.h"
#include "lidr/eval/light_coverage.h"
#include "lidr/modes/clustered_renderer.h"
#include "lidr/modes/deferred_renderer.h"
#include "lidr/modes/tiled_deferred_renderer.h"
#include "lidr/modes/tiled_renderer.h"
#include "lidr/scene/camera.h"
#include "lidr/technique/lidr_renderer.h"

namespace lidr::bench {

namespace {
// Deferred shading has no lists: its accumulation target counts the light shaders run per pixel (rows from the
// bottom). A pixel that ran fewer than the lights touching its surface dropped that many.
FrameAccuracy judgeLightCounts(FrameAccuracy a, const CoverageTruth& truth, const std::vector<float>& counts) {
    a.hasLists = true;
    for (int y = 0; y < truth.height; ++y)
        for (int x = 0; x < truth.width; ++x) {
            const size_t p = size_t(y) * size_t(truth.width) + size_t(x);
            const long ran = long(counts[size_t(truth.height - 1 - y) * size_t(truth.width) + size_t(x)] + 0.5f);
            const long dropped = std::max(0L, long(truth.count(p)) - ran);
            a.droppedLightPixels += dropped;
            a.pixelsWithDrops += dropped > 0;
            a.trueLightPixels += truth.count(p);
            if (truth.surface[p]) a.shadedLightPixels += ran;
        }
    // Every light shader run counts, over the background too (without the stencil test a back face in front of
    // the far plane shades it).
    a.lightingComputations = 0;
    for (float c : counts) a.lightingComputations += long(c + 0.5f);
    return a;
}
}  // namespace

namespace {
// Multi-pass forward shades one light per fragment of its light passes (one fragment per pixel and pass): their
// fragment shader invocations, where the context counts them (pipeline statistics, measuring runs); else -1.
long lightPassFragments(const Renderer& renderer) {
    long n = -1;
    for (const PassTime& p : renderer.lastFrame().passes)
        if (p.pass == "light-passes" && p.fragments >= 0) n = std::max(0L, n) + p.fragments;
    return n;
}

long surfacePixels(const CoverageTruth& truth) { return long(std::count(truth.surface.begin(), truth.surface.end(), true)); }
}  // namespace

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
        a.lightingComputations = ev.lists.slotsUsed;  // the forward pass shades every filled slot
        for (size_t p = 0; p < ev.truth.surface.size(); ++p)
            if (ev.truth.surface[p]) a.trueLightPixels += ev.truth.count(p);
        return a;
    }
    a.error = compareImages(image, reference);
    a.errorWithinBudget = a.error;
    const auto* tiled = dynamic_cast<const TiledRenderer*>(&renderer);
    const auto* clustered = dynamic_cast<const ClusteredRenderer*>(&renderer);
    const auto* tiledDeferred = dynamic_cast<const TiledDeferredRenderer*>(&renderer);
    const auto* deferred = dynamic_cast<const DeferredRenderer*>(&renderer);
    const bool brute = renderer.modeName() == "forward-brute", multipass = renderer.modeName() == "forward-multipass";
    if ((!tiled && !clustered && !tiledDeferred && !deferred && !brute && !multipass) || renderer.targets().samples() > 0)
        return a;
    if (deferred && renderer.frame().info.gles) return a;  // ES 2.0 reads no float pixels back
    const int width = image.width, height = image.height;
    const CoverageTruth truth = computeCoverage(renderer.targets().readDepth(), cameraMatrices(camera, width, height), lights);
    if (brute || multipass) {
        for (size_t p = 0; p < truth.surface.size(); ++p)
            if (truth.surface[p]) a.trueLightPixels += truth.count(p);
        // Brute force: every surface pixel loops over every light.
        a.lightingComputations = brute ? surfacePixels(truth) * long(lights.size()) : lightPassFragments(renderer);
        return a;
    }
    if (deferred) return judgeLightCounts(a, truth, deferred->gBuffer().readLightCounts());
    const PixelListCheck check = checkGridLists(renderer, truth, width, height);
    a.hasLists = true;
    a.droppedLightPixels = check.missingPairs;
    a.pixelsWithDrops = check.pixelsWithMissing;
    a.trueLightPixels = check.truthPairs;
    a.shadedLightPixels = check.listPairs;
    a.lightingComputations = check.listPairs;  // each surface pixel loops over its tile's or cluster's list
    return a;
}

PixelListCheck checkGridLists(const Renderer& renderer, const CoverageTruth& truth, int width, int height) {
    if (const auto* clustered = dynamic_cast<const ClusteredRenderer*>(&renderer)) {
        const ClusterGrid& g = clustered->grid();
        return checkPixelLists(truth, clustered->pixelClusters(), g.entries(), g.offsets(), g.counts());
    }
    const auto* tiled = dynamic_cast<const TiledRenderer*>(&renderer);
    const auto* tiledDeferred = dynamic_cast<const TiledDeferredRenderer*>(&renderer);
    if (!tiled && !tiledDeferred) throw Error("checkGridLists: the mode keeps no tile or cluster lists");
    const LightGrid& g = tiled ? tiled->grid() : tiledDeferred->grid();
    std::vector<int> tileOfPixel(size_t(width) * size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) tileOfPixel[size_t(y) * size_t(width) + size_t(x)] = g.tileOf(x, height - 1 - y);
    return checkPixelLists(truth, tileOfPixel, g.entries(), g.opaqueOffsets(), g.opaqueCounts());
}

long countLightingComputations(Renderer& renderer, const Camera& camera, const std::vector<PointLight>& lights) {
    const ImageRGBA8 image = renderer.targets().readColor();
    return judgeFrame(renderer, camera, lights, image, image).lightingComputations;
}

}  // namespace lidr::bench
