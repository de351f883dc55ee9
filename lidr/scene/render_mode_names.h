#pragma once
// The names of lidr's render modes, so scene files (Scene::renderMode) are checked where they are read without
// the scene layer knowing any renderer; lidr/modes/render_mode.h builds a mode from its name.
#include <string>
#include <vector>

namespace lidr {

// "lidr", "tiled", "clustered", "forward-multipass", "deferred", "tiled-deferred", "forward-brute", "auto" (the
// fastest of lidr, tiled, clustered and forward-multipass, measured).
const std::vector<std::string>& renderModeNames();
bool isRenderModeName(const std::string& name);
// "lidr, tiled, clustered, forward-multipass, deferred, tiled-deferred, forward-brute, auto": for error messages and help texts.
std::string renderModeList();

}  // namespace lidr
