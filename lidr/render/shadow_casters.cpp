#include "lidr/render/shadow_casters.h"

#include <algorithm>
#include <string>

#include "lidr/base/error.h"
#include "lidr/render/shadow_atlas.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr {

float shadowCasterBrightness(const PointLight& light) {
    const float luminance = 0.2126f * light.color.r + 0.7152f * light.color.g + 0.0722f * light.color.b;
    return luminance * light.radius * light.radius;
}

int chooseShadowCasters(std::vector<PointLight>& lights, const CameraMatrices& camera, int k) {
    if (k < 0) throw Error("shadow casters: K must be >= 0, got " + std::to_string(k));
    std::vector<size_t> eligible;
    for (size_t i = 0; i < lights.size(); ++i) {
        PointLight& l = lights[i];
        l.castsShadow = false;
        if (l.isSpot() && !(l.outerConeAngle <= kMaxShadowConeAngle)) continue;
        if (!(l.radius > 0.0f) || !projectSphereBounds(camera, l.position, l.radius).visible) continue;
        eligible.push_back(i);
    }
    const size_t chosen = std::min(eligible.size(), size_t(k));
    std::stable_sort(eligible.begin(), eligible.end(), [&](size_t a, size_t b) {
        return shadowCasterBrightness(lights[a]) > shadowCasterBrightness(lights[b]);
    });
    for (size_t n = 0; n < chosen; ++n) lights[eligible[n]].castsShadow = true;
    return int(chosen);
}

int shadowTileToFit(const std::vector<PointLight>& lights, int atlasSize, int largestTile) {
    long tiles = 0;
    for (const PointLight& l : lights)
        if (l.castsShadow) tiles += shadowTiles(l);
    int tile = std::max(16, std::min(largestTile, atlasSize));
    const auto capacity = [&](int t) { return long(atlasSize / t) * long(atlasSize / t); };
    while (tile > 16 && capacity(tile) < tiles) tile /= 2;
    if (capacity(tile) < tiles)
        throw Error("shadows: the casters need " + std::to_string(tiles) + " shadow maps (a spot light one, a point "
                    "light six); a " + std::to_string(atlasSize) + " atlas holds " + std::to_string(capacity(tile)) +
                    " of 16 texels: a larger atlas or fewer casters");
    return tile;
}

}  // namespace lidr
