#include "lidr/scene/sphere_bounds.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "lidr/base/error.h"

namespace lidr {

namespace {

// Range of a / -z over the disk (centre (ca, cz), radius r) clipped to z <= nearZ, in the plane spanned by
// one screen axis and the view axis. The region is convex and lies at z < 0, and a / -z is constant along
// lines through the eye, so its extremes are where such a line supports the region: a tangent point of the
// circle that survives the clip, or an end of the clipping chord. Those candidates are all there is to try.
// (Mara & McGuire 2013 pick the same points per side; trying all of them needs no case analysis.)
bool clippedDiskRange(double ca, double cz, double r, double nearZ, double& lo, double& hi) {
    double cand[4][2];
    int n = 0;
    const double len2 = ca * ca + cz * cz;
    const double t2 = len2 - r * r;
    if (t2 > 0.0) {  // eye outside the disk: two tangent points
        const double len = std::sqrt(len2);
        const double cosT = std::sqrt(t2) / len, sinT = r / len;
        for (double s : {1.0, -1.0}) {
            // Rotate the centre direction by +-theta and scale to the tangent length sqrt(t2) = cosT * len.
            const double qa = cosT * (cosT * ca - s * sinT * cz);
            const double qz = cosT * (s * sinT * ca + cosT * cz);
            if (qz <= nearZ) cand[n][0] = qa, cand[n][1] = qz, ++n;
        }
    }
    const double dz = nearZ - cz;
    if (std::abs(dz) <= r) {  // the near plane cuts the disk: ends of the chord
        const double h = std::sqrt(std::max(0.0, r * r - dz * dz));
        cand[n][0] = ca - h, cand[n][1] = nearZ, ++n;
        cand[n][0] = ca + h, cand[n][1] = nearZ, ++n;
    }
    if (n == 0) return false;
    lo = 1e300, hi = -1e300;
    for (int i = 0; i < n; ++i) {
        const double u = cand[i][0] / -cand[i][1];
        lo = std::min(lo, u), hi = std::max(hi, u);
    }
    return true;
}

}  // namespace

SphereBounds projectSphereBounds(const CameraMatrices& m, const glm::vec3& center, float radius) {
    const glm::mat4& P = m.projection;
    if (P[2][3] != -1.0f || P[3][3] != 0.0f)
        throw Error("projectSphereBounds: the projection is not a perspective projection with w = -z");
    SphereBounds b;
    if (!(radius > 0.0f)) return b;
    const glm::dvec3 c = glm::dvec3(glm::dmat4(m.view) * glm::dvec4(glm::dvec3(center), 1.0));
    const double r = radius, nearZ = -double(m.nearPlane), farZ = -double(m.farPlane);
    if (c.z - r >= nearZ || c.z + r <= farZ) return b;  // wholly before the near or beyond the far plane
    double xlo, xhi, ylo, yhi;
    if (!clippedDiskRange(c.x, c.z, r, nearZ, xlo, xhi) || !clippedDiskRange(c.y, c.z, r, nearZ, ylo, yhi))
        return b;
    // ndc = P00 * x / -z - P20 (P20 is zero for a symmetric frustum; kept for off-centre projections).
    b.ndcMin = glm::vec2(float(P[0][0] * xlo - P[2][0]), float(P[1][1] * ylo - P[2][1]));
    b.ndcMax = glm::vec2(float(P[0][0] * xhi - P[2][0]), float(P[1][1] * yhi - P[2][1]));
    b.viewDepthMin = float(std::max(double(m.nearPlane), -c.z - r));
    b.viewDepthMax = float(std::min(double(m.farPlane), -c.z + r));
    b.visible = b.ndcMax.x >= -1.0f && b.ndcMin.x <= 1.0f && b.ndcMax.y >= -1.0f && b.ndcMin.y <= 1.0f;
    return b;
}

bool spherePixelRect(const CameraMatrices& m, const glm::vec3& center, float radius, glm::ivec4& rect, float margin) {
    const SphereBounds b = projectSphereBounds(m, center, radius);
    if (!b.visible) return false;
    // Pixel i has its centre at i + 0.5 in window coordinates; keep every i whose centre lies within the
    // bounds widened by `margin`.
    const double x0 = (double(b.ndcMin.x) * 0.5 + 0.5) * m.width - margin - 0.5;
    const double x1 = (double(b.ndcMax.x) * 0.5 + 0.5) * m.width + margin - 0.5;
    const double y0 = (double(b.ndcMin.y) * 0.5 + 0.5) * m.height - margin - 0.5;
    const double y1 = (double(b.ndcMax.y) * 0.5 + 0.5) * m.height + margin - 0.5;
    rect.x = int(std::max(0.0, std::ceil(x0)));
    rect.y = int(std::max(0.0, std::ceil(y0)));
    rect.z = int(std::min(double(m.width - 1), std::floor(x1)));
    rect.w = int(std::min(double(m.height - 1), std::floor(y1)));
    return rect.x <= rect.z && rect.y <= rect.w;
}

bool boxPixelRect(const CameraMatrices& m, const glm::vec3& boxMin, const glm::vec3& boxMax, glm::ivec4& rect,
                  float margin) {
    glm::dvec2 lo(1e300), hi(-1e300);
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? boxMax.x : boxMin.x, (c & 2) ? boxMax.y : boxMin.y, (c & 4) ? boxMax.z : boxMin.z);
        const glm::dvec4 clip = glm::dvec4(m.viewProjection * glm::vec4(corner, 1.0f));
        if (!(clip.w > double(m.nearPlane) * 0.999)) {  // at or before the near plane (or not finite): all
            rect = glm::ivec4(0, 0, m.width - 1, m.height - 1);
            return true;
        }
        const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    const double x0 = (lo.x * 0.5 + 0.5) * m.width - margin - 0.5, x1 = (hi.x * 0.5 + 0.5) * m.width + margin + 0.5;
    const double y0 = (lo.y * 0.5 + 0.5) * m.height - margin - 0.5, y1 = (hi.y * 0.5 + 0.5) * m.height + margin + 0.5;
    if (x1 < 0.0 || y1 < 0.0 || x0 > m.width - 1.0 || y0 > m.height - 1.0) return false;  // wholly off screen
    rect.x = int(std::max(0.0, std::floor(x0)));
    rect.y = int(std::max(0.0, std::floor(y0)));
    rect.z = int(std::min(double(m.width - 1), std::ceil(x1)));
    rect.w = int(std::min(double(m.height - 1), std::ceil(y1)));
    return rect.x <= rect.z && rect.y <= rect.w;
}

void checkLightSpheres(const std::vector<PointLight>& lights, const char* who) {
    for (size_t i = 0; i < lights.size(); ++i) {
        const PointLight& l = lights[i];
        bool finite = true;
        for (int k = 0; k < 3; ++k) finite = finite && std::isfinite(l.position[k]) && std::isfinite(l.color[k]);
        if (!finite || !std::isfinite(l.radius) || !(l.radius > 0.0f))
            throw Error(std::string(who) + ": light " + std::to_string(i + 1) +
                        (finite ? " has radius " + std::to_string(l.radius) + ", must be a finite number > 0"
                                : " has a non-finite position or colour"));
    }
}

float viewDepthFromWindowDepth(const CameraMatrices& m, float windowDepth) {
    const double ndc = 2.0 * double(windowDepth) - 1.0;
    return float(double(m.projection[3][2]) / (ndc + double(m.projection[2][2])));
}

}  // namespace lidr
