#pragma once
// A frame as a list of named passes (Filament's FrameGraph in a light form): each pass says what it reads and what it
// writes and, where it does not run every frame, when it runs. A mode's Renderer::passes() lists its passes in frame
// order and its render() runs them top to bottom, a member function each; a pass's time and counts
// (FrameStats::passes: lidr-demo's "per pass" line, lidr-bench's passes.csv) carry the pass's name, so the list names
// what the timings show. `lidr-demo --list-passes MODE` prints the list.
#include <string>
#include <vector>

namespace lidr {

struct FramePass {
    const char* name;       // as FrameStats::passes names it
    // What it reads, comma separated ("scene, depth, light grid"); [x]: where the configuration or the frame has x.
    const char* reads;
    const char* writes;     // what it writes
    const char* when = "";  // empty: every frame; else when it runs (or does its work)
};

// The passes of FrameResources' shared steps (lidr/render/frame_resources.h), in the order a frame takes them. Their
// names are the timings' (RenderTargets::resolve names "msaa-resolve" itself, in the gl layer below).
namespace pass {
inline constexpr FramePass kShadowMaps{"shadow-maps", "scene, lights", "shadow atlas",
                                       "draws the maps that changed, where lights cast shadows"};
inline constexpr FramePass kLightTable{"light-table", "lights, [shadow atlas]", "light table"};
inline constexpr FramePass kDepthPrepass{"depth-prepass", "scene", "depth"};
inline constexpr FramePass kMsaaResolve{"msaa-resolve", "colour (MSAA)", "colour", "MSAA"};
}  // namespace pass

// The list as text, a pass a line: "  3 depth-prepass      scene -> depth" and its condition, for lidr-demo.
std::string describePasses(const std::vector<FramePass>& passes);

}  // namespace lidr
