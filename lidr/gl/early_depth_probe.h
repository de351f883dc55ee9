#pragma once
// Whether the context runs the fragment shader of multisampled fragments its depth test rejects at every sample.
// llvmpipe does (its per-sample early test empties the mask, and the shader runs under it), so under MSAA every
// hidden fragment costs its whole shader there, and work a shader skips for fragments that keep no sample is
// saved (ForwardPass, VisibleSamples); a GPU that culls them before shading would only pay for the test.
// Counted, not guessed from the renderer's name: one full-screen draw behind a cleared depth of 0 into a small
// MSAA target, its fragment shader invocations read with ARB_pipeline_statistics_query. Without the query (or
// without multisample framebuffers of that many samples) it answers false: nothing measured, nothing skipped.
#include "lidr/gl/gl_info.h"

namespace lidr {

bool shadesRejectedMultisampleFragments(const GlInfo& info, int samples);

}  // namespace lidr
