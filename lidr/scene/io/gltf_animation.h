#pragma once
// glTF animations (issue 46): the channels that move nodes (translation, rotation, scale; STEP, LINEAR with slerp
// for rotations, CUBICSPLINE), read into lidr's SceneAnimation (lidr/scene/animation.h). What is not played is a
// warning naming it: morph target weights (the base shape is drawn), channels on nodes outside the default scene,
// a second animation's channel on a property an earlier one already moves (every animation plays at once, from
// t = 0, as a viewer that plays all of a file's clips together). Every malformed channel or sampler is an
// lidr::Error naming the file, the animation and the channel.
#include <string>
#include <vector>

#include "lidr/scene/animation.h"

namespace tinygltf {
class Model;
}

namespace lidr {

// `nodeOf[n]`: the AnimationNode (index into animation.nodes) of glTF node n, -1 where the default scene does not
// place it. The nodes it names get their tracks and `animated`; their rest translation, rotation and scale must
// already be the node's. animation.start / end grow to cover every track, animation.clips lists the animations.
void readGltfAnimations(const tinygltf::Model& model, const std::string& path, const std::vector<int>& nodeOf,
                        SceneAnimation& animation, std::vector<std::string>& warnings);

}  // namespace lidr
