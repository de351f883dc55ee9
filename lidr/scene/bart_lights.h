#pragma once
// The two light set-ups of Olsson and Assarsson's evaluation of BART's Robots scene (Tiled Shading, JGT 2011,
// section 8; ../shared/papers/003): many static lights evenly spaced along the robots' animation paths, and few
// dynamic lights, one riding on each robot. Built from the scene's own animation, so they fit any AFF scene whose
// walkers are keyframed transforms: a "walker" is an animated node with no animated ancestor that carries meshes
// (in the Robots, robot_transl1 .. robot_transl10). Deterministic for a seed (splitmix64, the same everywhere).
#include <cstdint>
#include <string>

#include "lidr/scene/scene.h"

namespace lidr {

enum class BartLightSetup {
    ManyStatic,  // the paper's "many static lights": 924 lights of range 12.5 along the walkers' paths
    FewDynamic,  // the paper's "few dynamic lights": one light of range 40 on each walker
};

struct BartLightOptions {
    BartLightSetup setup = BartLightSetup::ManyStatic;
    uint32_t seed = 1;
    int count = 924;         // ManyStatic: lights in all (FewDynamic: one per walker)
    float range = 0.0f;      // <= 0: the paper's, 12.5 (many) or 40 (few)
    float sideways = 10.0f;  // ManyStatic: offsets up to this far either side of the path (the main street: 29.1 wide)
    // The lights' colour scale: what a white Lambert surface facing one at its centre shows (lidr's light units).
    // <= 0: the set-up's default (kBartManyIntensity, kBartFewIntensity), chosen so frames are neither black nor
    // burnt out (doc/bart.md shows them).
    float intensity = 0.0f;
    // The file's ambient term (every material's emission, aff_importer.h: BART's `am` x each material's ambient
    // colour) scaled by this, so the set-up's lights, not the ambient, light the frame. < 0: the default,
    // kBartAmbientScale.
    float ambientScale = -1.0f;
};
constexpr float kBartManyRange = 12.5f, kBartFewRange = 40.0f;
constexpr float kBartManyIntensity = 0.5f, kBartFewIntensity = 3.0f, kBartAmbientScale = 0.3f;

// Replaces the scene's lights with the set-up's (point lights, smooth falloff; the file's own lights go: the paper
// lights the scene with its set-up alone). Returns a line saying what was added, with the seed. Throws lidr::Error
// where the scene has no walkers (no keyframed transform carrying meshes) or their paths have no length (many).
std::string addBartLights(Scene& scene, const BartLightOptions& options);

// The walkers' nodes (indices into scene.animation.nodes), in node order.
std::vector<int> bartWalkers(const Scene& scene);

}  // namespace lidr
