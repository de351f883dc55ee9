#pragma once
// Scenes built for measuring: lidr-bench sweeps them, tests may use them.
//  - Controlled overlap: every lit pixel is covered by exactly k lights, so a budget's drops and a scheme's
//    cost can be read against k alone (k = 1, 2, 4, 8, 16 in the bench).
//  - Many lights: the default room's geometry with 1,024 or 4,096 small lights (16-bit indices for LIDR),
//    seen from above or at eye height.
#include <string>

#include "lidr/scene.h"

namespace lidr {

// A floor seen from straight above, lit by 9 groups of k coincident lights (same centre and radius, colours
// differing). Groups are spaced so no two groups' spheres (nor their volume meshes) meet: a floor pixel is
// inside either no light or exactly the k of one group. Each light's colour is scaled by 1/k so the lit
// brightness does not grow with k (no saturation hiding a dropped light). k in [1, 7281] (65,535 lights).
Scene makeControlledOverlapScene(int k, int width = 1024, int height = 768);
constexpr int kControlledOverlapGroups = 9;

enum class ManyLightView { TopDown, FirstPerson };
// The default room's geometry (3 large movers kept) with `lightCount` - 3 particle lights whose radii shrink
// with sqrt(255 / lightCount), so the mean overlap stays near the default room's as the count grows.
// lightCount in [4, 65535].
Scene makeManyLightScene(int lightCount, ManyLightView view, int width = 1024, int height = 768, uint32_t seed = 1);
const char* manyLightViewName(ManyLightView view);  // "top", "fp"

}  // namespace lidr
