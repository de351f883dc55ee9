#pragma once
// Many-light scenes for lidr-bench: the default room's geometry with 1,024 or 4,096 small lights (16-bit
// indices for LIDR), seen from above or at eye height. (The controlled-overlap scenes are in controlled_scenes.h.)
#include <string>

#include "lidr/scene/scene.h"

namespace lidr {

enum class ManyLightView { TopDown, FirstPerson };
// The default room's geometry (3 large movers kept) with `lightCount` - 3 particle lights whose radii shrink
// with sqrt(255 / lightCount), so the mean overlap stays near the default room's as the count grows.
// lightCount in [4, 65535].
Scene makeManyLightScene(int lightCount, ManyLightView view, int width = 1024, int height = 768, uint32_t seed = 1);
const char* manyLightViewName(ManyLightView view);  // "top", "fp"

}  // namespace lidr
