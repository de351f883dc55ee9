#pragma once
// The render modes by name, in one table (renderModes()), so scene files (Scene::renderMode) are checked where they
// are read without the scene layer knowing any renderer; lidr/modes/render_mode.h builds a mode from its name. A new
// mode is one line in render_mode_names.cpp and one branch in createRenderer.
#include <string>
#include <vector>

namespace lidr {

struct RenderModeInfo {
    const char* name;         // "lidr", what --mode, a scene file's "mode" and Renderer::modeName() say
    const char* description;  // one line for help texts, --list and the viewer
};

// Every mode in the order tools list them: lidr, tiled, clustered, forward-multipass, forward-brute, auto (the
// fastest of the first four, measured).
const std::vector<RenderModeInfo>& renderModes();
const std::vector<std::string>& renderModeNames();  // the names of renderModes(), in order
bool isRenderModeName(const std::string& name);
// "lidr, tiled, clustered, forward-multipass, forward-brute, auto": for error messages and help texts.
std::string renderModeList();
// The description of `name`; "" for an unknown name.
std::string renderModeDescription(const std::string& name);

}  // namespace lidr
