#pragma once
// The CPU twin of shaders/common/shadow_lookup.glsl's lidrShadowMapCoord (tests, the doc's error bounds): where
// a world point falls in a light's shadow maps, derived from the light as the shader derives it. It must agree
// with ShadowAtlas::Slot::worldToAtlas (the cameras the maps are drawn with): tests/test_shadow_atlas.cpp.
#include <glm/glm.hpp>

#include "lidr/scene/scene.h"

namespace lidr {

struct ShadowMapCoord {
    bool seen = false;      // false: outside the map's view (the lookup says lit)
    int tile = 0;           // first tile + cube face
    glm::vec2 ndc{0.0f};    // in [-1, 1] across the tile
    float viewDepth = 0.0f; // along the map's axis
    float tanHalfFov = 1.0f;
    float windowDepth = 0.0f;  // what the map stores for a surface at this point: (d - n) f / ((f - n) d)
};
ShadowMapCoord shadowMapCoord(const PointLight& light, int firstTile, const glm::vec3& point);

}  // namespace lidr
