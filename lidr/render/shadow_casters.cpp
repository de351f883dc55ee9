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

}  // namespace lidr
