#pragma once
// Choosing a render mode by name: "lidr", "tiled", "clustered", "forward-multipass", "deferred", "tiled-deferred",
// "forward-brute", or "auto" (the
// fastest of the first four, measured: lidr/modes/auto_mode_renderer.h). lidr-demo's --mode
// and a scene file's "mode" key both come through here, so every mode is built the same way everywhere.
#include <memory>
#include <string>
#include <vector>

#include "lidr/gl/gl_info.h"
#include "lidr/modes/clustered_renderer.h"
#include "lidr/modes/deferred_renderer.h"
#include "lidr/technique/lidr_renderer.h"
#include "lidr/modes/multipass_forward_renderer.h"
#include "lidr/render/renderer.h"
#include "lidr/scene/render_mode_names.h"  // renderModeNames(), isRenderModeName(), renderModeList()
#include "lidr/scene/scene.h"
#include "lidr/modes/tiled_deferred_renderer.h"
#include "lidr/modes/tiled_renderer.h"

namespace lidr {

struct RenderModeOptions {
    std::string mode = "lidr";
    LidrOptions lidr;            // mode "lidr"
    TiledOptions tiled;          // mode "tiled"
    ClusteredOptions clustered;  // mode "clustered"
    MultipassOptions multipass;  // mode "forward-multipass"
    DeferredOptions deferred;    // mode "deferred"
    TiledDeferredOptions tiledDeferred;  // mode "tiled-deferred"
    // These apply to every mode and replace the per-mode fields of the same name.
    bool forceFixedLightTable = false;  // the RGBA8 fixed-point light table
    int msaaSamples = 0;                // 0, or 2..GL_MAX_SAMPLES
    bool transparency = true;           // draw transparent materials (forward-multipass never does)
    TimingMethod timingMethod = TimingMethod::Auto;
};

// Builds the renderer for options.mode at width x height. Throws lidr::Error naming the valid modes for an
// unknown name, and whatever the mode's constructor throws for bad settings (before any drawing).
std::unique_ptr<Renderer> createRenderer(const RenderModeOptions& options, const GlInfo& info, const Scene& scene,
                                         int width, int height);

}  // namespace lidr
