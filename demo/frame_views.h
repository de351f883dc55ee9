#pragma once
// The debug views of one frame, shared by lidr-demo --headless (written as PNGs) and lidr-viewer (shown on
// screen): the brute-force reference a mode is judged against, and LIDR's index-list and heat-map images.
#include <memory>

#include "lidr/base/image.h"
#include "lidr/eval/frame_evaluation.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/modes/render_mode.h"

namespace lidr::demo {

// The reference for a frame of `options.mode`, rendered the way that mode renders: same MSAA, transparency
// where the mode draws it (multi-pass forward never does), per-sample shading with per-sample LIDR lists.
std::unique_ptr<ReferenceRenderer> makeReference(const GlInfo& info, const Scene& scene, const RenderModeOptions& options,
                                                 int width, int height, int lightCount);

// LIDR's views of an evaluated frame: decoded index lists, lights touching each surface (CPU truth) and
// lights the volume test marked (GPU count), the heat maps scaled to `budget`.
struct LidrViews {
    ImageRGBA8 indexLists, overlap, marked;
};
LidrViews lidrViews(const FrameEvaluation& ev, int width, int height, int budget);

}  // namespace lidr::demo
