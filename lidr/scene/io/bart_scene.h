#pragma once
// BART's Robots with the paper's light set-ups (lidr/scene/bart_lights.h) by name, as lidr-bench and lidr-demo take
// them: "bart-robots-many" (924 static lights) and "bart-robots-few" (one light on each robot).
#include <cstdint>
#include <string>

#include "lidr/scene/scene.h"

namespace lidr {

// Where the Robots are read from: `bart` is a folder holding aff/Robot.aff (../shared/bart-robots), a folder holding
// Robot.aff, or an AFF file itself (any BART scene whose walkers are keyframed). Throws lidr::Error naming what is
// missing.
std::string bartSceneFile(const std::string& bart);

// For "bart-robots-many" and "bart-robots-few": the scene (loadScene of bartSceneFile(bart)) with the set-up's
// lights for `seed`, transparency off (the paper's modes draw opaque surfaces), and true; `description` (when
// given) says what the lights are, with the seed. False for any other name; a name with the prefix and another
// ending throws lidr::Error naming the two.
bool makeBartSceneByName(const std::string& name, Scene& scene, uint32_t seed, const std::string& bart,
                         std::string* description = nullptr);

}  // namespace lidr
