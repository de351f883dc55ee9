#pragma once
// Screen-space bounds of a light sphere, for assigning lights to tiles. The 2D bounds are the exact bounds
// of the sphere clipped at the near plane and perspective-projected (Mara & McGuire 2013, "2D Polyhedral
// Bounds of a Clipped, Perspective-Projected 3D Sphere"), so spheres that cross the near plane or contain the
// camera are handled, and nothing that lies in front of the near plane can widen them. The pixel rectangle
// adds a margin for float rounding, so it is conservative: a pixel whose centre's view ray meets the sphere
// between the near and far planes is always inside it.
#include <vector>

#include <glm/glm.hpp>

#include "lidr/scene/camera.h"
#include "lidr/scene/scene.h"

namespace lidr {

struct SphereBounds {
    bool visible = false;         // false: the sphere lies wholly before the near, beyond the far plane or
                                  // outside the view frustum, so it can touch no pixel
    glm::vec2 ndcMin{0.0f}, ndcMax{0.0f};  // exact bounds of the clipped, projected sphere in NDC (x, y)
    float viewDepthMin = 0.0f;    // distance along the view direction, clamped to [near, far]
    float viewDepthMax = 0.0f;
};

// Exact NDC bounds of the part of the sphere beyond the near plane. `camera.projection` must be a
// perspective projection (w = -z_view), as cameraMatrices() builds.
SphereBounds projectSphereBounds(const CameraMatrices& camera, const glm::vec3& center, float radius);

// Pixels (GL window coordinates: x right, y UP from the bottom row, inclusive bounds) whose centres may see
// the sphere, clamped to the viewport. Returns false when no pixel can. `margin` pixels are added on every
// side (1 covers rounding in the projection; the result stays conservative for any margin >= 0.5).
bool spherePixelRect(const CameraMatrices& camera, const glm::vec3& center, float radius, glm::ivec4& rect,
                     float margin = 1.0f);

// Pixels (as spherePixelRect) that any fragment of geometry inside the box [boxMin, boxMax] can reach: the
// rectangle of its projected corners widened by `margin`, the whole viewport when the box reaches the near
// plane. Conservative for fragments covering any sample of a pixel, not only its centre. False: none.
bool boxPixelRect(const CameraMatrices& camera, const glm::vec3& boxMin, const glm::vec3& boxMax, glm::ivec4& rect,
                  float margin = 1.0f);

// `v` clamped to [lo, hi] and converted to int; NaN gives `ifNaN`. Converts only in-range values, so a huge or
// non-finite projected coordinate (camera or light near the float range) never overflows an int.
inline int clampToInt(double v, int lo, int hi, int ifNaN) {
    if (v != v) return ifNaN;
    return v <= double(lo) ? lo : v >= double(hi) ? hi : int(v);
}

// Throws lidr::Error naming the first light (1-based index) with a non-finite position or colour, or a radius
// that is not a finite number > 0; `who` starts the message ("tiled", "forward-multipass").
void checkLightSpheres(const std::vector<PointLight>& lights, const char* who);

// View-space distance along the view direction of a window depth in [0, 1] (inverse of the projection's
// depth mapping).
float viewDepthFromWindowDepth(const CameraMatrices& camera, float windowDepth);

// The widest cone the shading may light for this outer cone angle (radians): its cosine lowered by 2e-5 (the
// fixed-point light table stores cosines in 16 bits) and the angle widened by 1e-3 rad, at most a right angle.
// What every conservative cone bound widens a spot light to (volume meshes, tile and mesh culling).
double spotBoundingConeAngle(float outerConeAngle);

// The axis-aligned box around a spot light's cone capped at `range` (a spherical sector): the apex, the rim
// circle, and the cap's extreme along each axis the cone holds, for the cone spotBoundingConeAngle gives.
// A point light's box is its sphere's.
void spotLightBox(const PointLight& light, float range, glm::vec3& boxMin, glm::vec3& boxMax);

}  // namespace lidr
