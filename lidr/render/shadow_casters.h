#pragma once
// Which lights cast shadows when the scene does not say (issue 30; doc/shadows.md, "Casters, tools and cost"):
// the K brightest lights that can touch the view. A light's brightness here is its colour's luminance (Rec. 709
// weights, lidr's linear colour) times its range squared: what it gives at a fixed fraction of its range (a
// smooth-falloff light gives luminance x (1 - d^2 / r^2)), weighted by the area it lights, so a wide dim light
// can outrank a small bright one. A light can touch the view when its sphere reaches the camera's frustum
// (projectSphereBounds): nothing outside it lights a visible point, so its shadow could not show. Spot lights
// wider than kMaxShadowConeAngle are never chosen (one map cannot cover them). Ties go to the lower index.
#include <vector>

#include "lidr/scene/camera.h"
#include "lidr/scene/scene.h"

namespace lidr {

// The rule's measure of a light (see above).
float shadowCasterBrightness(const PointLight& light);

// Sets castsShadow on the k brightest lights that can touch the view of `camera` and clears it on every other
// light. Returns how many were chosen (min(k, eligible lights)). Throws lidr::Error for k < 0.
int chooseShadowCasters(std::vector<PointLight>& lights, const CameraMatrices& camera, int k);

}  // namespace lidr
