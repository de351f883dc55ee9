#include "lidr/eval/frame_evaluation.h"

#include <algorithm>
#include <cmath>

namespace lidr {

namespace {
// The lists against the lights the points in `surfaces` need (computeSpanCoverage).
void checkSpanLists(const LidrRenderer& renderer, const CameraMatrices& cam, const std::vector<PointLight>& lights,
                    const std::vector<ImageFloat>& surfaces, FrameEvaluation& e) {
    e.spanTruth = computeSpanCoverage(surfaces, cam, lights);
    e.spanLists = checkIndexLists(e.spanTruth, renderer.scheme(), renderer.readIndexTargets(),
                                  static_cast<uint32_t>(lights.size()), renderer.frameLightIndices(),
                                  renderer.frameIndexRegions());
}

// sphere-span with the samples' own distances: every sample's point and the centre's are the truth's points;
// an edge pixel has a sample off the centre's depth, on several surfaces where two samples off it differ.
void evaluateSampleSpans(const LidrRenderer& renderer, const CameraMatrices& cam,
                         const std::vector<PointLight>& lights, FrameEvaluation& e) {
    std::vector<ImageFloat> surfaces = renderer.readSampleDepths();
    const ImageFloat centre = renderer.targets().readDepth();
    for (size_t p = 0; p < centre.pixels.size(); ++p) {
        float off = -1.0f;  // the first sample depth off the centre's
        bool edge = false, several = false;
        for (const ImageFloat& s : surfaces) {
            if (std::abs(s.pixels[p] - centre.pixels[p]) <= kEdgeDepthMargin) continue;
            several = several || (edge && std::abs(s.pixels[p] - off) > kEdgeDepthMargin);
            if (!edge) off = s.pixels[p];
            edge = true;
        }
        if (!edge) continue;
        ++e.edgePixels;
        if (several) ++e.edgePixelsSeveralSurfaces;
        e.edgeMarksMax = std::max(e.edgeMarksMax, e.marked[p]);
        e.edgeMarksMean += double(e.marked[p]);
    }
    if (e.edgePixels > 0) e.edgeMarksMean /= double(e.edgePixels);
    surfaces.push_back(centre);
    checkSpanLists(renderer, cam, lights, surfaces, e);
}

// sphere-span: the edge pixels, and the lists against what every sample's surface needs.
void evaluateSpans(const LidrRenderer& renderer, const CameraMatrices& cam, const std::vector<PointLight>& lights,
                   FrameEvaluation& e) {
    if (renderer.options().volumeTest == VolumeTest::SphereSpan && renderer.options().msaaSpans == DepthSpanStorage::Samples) {
        evaluateSampleSpans(renderer, cam, lights, e);
        return;
    }
    const std::vector<DepthSpanPass::Span> spans = renderer.readDepthSpans();
    if (spans.empty()) return;
    // The points the samples shade: the nearest sample's surface, the centre's, the farthest sample's.
    const ImageFloat centre = renderer.targets().readDepth();
    ImageFloat nearest(cam.width, cam.height), farthest(cam.width, cam.height);
    for (size_t p = 0; p < spans.size(); ++p) {
        const DepthSpanPass::Span& s = spans[p];
        nearest.pixels[p] = s.before.samples > 0 ? s.before.surfaceDepth : 1.0f;
        farthest.pixels[p] = s.past.samples > 0 ? s.past.surfaceDepth : 1.0f;
        if (!s.edge(kEdgeDepthMargin)) continue;
        ++e.edgePixels;
        if (s.past.severalSurfaces || s.before.severalSurfaces) ++e.edgePixelsSeveralSurfaces;
        e.edgeMarksMax = std::max(e.edgeMarksMax, e.marked[p]);
        e.edgeMarksMean += double(e.marked[p]);
    }
    if (e.edgePixels > 0) e.edgeMarksMean /= double(e.edgePixels);
    // Where one side's samples lie at several depths, its point (E[x^2] / E[x]) lies between them, maybe in the air:
    // a light touching no opaque mesh's bounds lights no sample (radius 0 here; the frame plan culls it too).
    std::vector<PointLight> reaching = lights;
    for (PointLight& l : reaching)
        if (!renderer.frame().scene.batchesTouchSphere(glm::vec4(l.position, l.radius), DrawFilter::Opaque)) l.radius = 0.0f;
    checkSpanLists(renderer, cam, reaching, {nearest, centre, farthest}, e);
}
}  // namespace

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
    evaluateSpans(renderer, cam, lights, e);
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
        // sphere-span: a pixel whose centre sees background may still have samples on a surface (its span).
        const bool surface = e.truth.surface[p] || (!e.spanTruth.surface.empty() && e.spanTruth.surface[p]);
        if (!surface) {
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
