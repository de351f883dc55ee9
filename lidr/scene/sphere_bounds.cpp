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
    // Clamped in double before the conversion to float: a sphere at a grazing angle (or near the float range)
    // projects far beyond any float; +-2^20 is still off screen on the same side, so the bounds stay
    // conservative. A non-finite value (a non-finite view matrix) makes the whole viewport the bounds.
    const double lim = 1048576.0;
    const double nd[4] = {P[0][0] * xlo - P[2][0], P[1][1] * ylo - P[2][1], P[0][0] * xhi - P[2][0], P[1][1] * yhi - P[2][1]};
    float nf[4];
    for (int i = 0; i < 4; ++i) {
        if (!std::isfinite(nd[i])) {
            b.ndcMin = glm::vec2(-1.0f), b.ndcMax = glm::vec2(1.0f);
            b.viewDepthMin = m.nearPlane, b.viewDepthMax = m.farPlane;
            b.visible = true;
            return b;
        }
        nf[i] = float(std::clamp(nd[i], -lim, lim));
    }
    b.ndcMin = glm::vec2(nf[0], nf[1]);
    b.ndcMax = glm::vec2(nf[2], nf[3]);
    b.viewDepthMin = float(std::clamp(-c.z - r, double(m.nearPlane), double(m.farPlane)));
    b.viewDepthMax = float(std::clamp(-c.z + r, double(m.nearPlane), double(m.farPlane)));
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
    rect.x = clampToInt(std::ceil(x0), 0, m.width, 0);
    rect.y = clampToInt(std::ceil(y0), 0, m.height, 0);
    rect.z = clampToInt(std::floor(x1), -1, m.width - 1, m.width - 1);
    rect.w = clampToInt(std::floor(y1), -1, m.height - 1, m.height - 1);
    return rect.x <= rect.z && rect.y <= rect.w;
}

bool boxPixelRect(const CameraMatrices& m, const glm::vec3& boxMin, const glm::vec3& boxMax, glm::ivec4& rect,
                  float margin) {
    glm::dvec2 lo(1e300), hi(-1e300);
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? boxMax.x : boxMin.x, (c & 2) ? boxMax.y : boxMin.y, (c & 4) ? boxMax.z : boxMin.z);
        const glm::dvec4 clip = glm::dvec4(m.viewProjection * glm::vec4(corner, 1.0f));
        const bool finite = std::isfinite(clip.x) && std::isfinite(clip.y) && std::isfinite(clip.w);
        if (!finite || !(clip.w > double(m.nearPlane) * 0.999)) {  // at or before the near plane (or not finite): all
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
    rect.x = clampToInt(std::floor(x0), 0, m.width - 1, 0);
    rect.y = clampToInt(std::floor(y0), 0, m.height - 1, 0);
    rect.z = clampToInt(std::ceil(x1), 0, m.width - 1, m.width - 1);
    rect.w = clampToInt(std::ceil(y1), 0, m.height - 1, m.height - 1);
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

double spotBoundingConeAngle(float outerConeAngle) {
    return std::min(1.5707963267948966, std::acos(std::clamp(std::cos(double(outerConeAngle)) - 2e-5, 0.0, 1.0)) + 1e-3);
}

void spotLightBox(const PointLight& l, float range, glm::vec3& boxMin, glm::vec3& boxMax) {
    boxMin = l.position - glm::vec3(range);
    boxMax = l.position + glm::vec3(range);
    if (!l.isSpot()) return;
    const double angle = spotBoundingConeAngle(l.outerConeAngle);
    const glm::dvec3 apex(l.position), axis = glm::normalize(glm::dvec3(l.direction));
    const double r = double(range), cosA = std::cos(angle), rim = r * std::sin(angle);
    const glm::dvec3 rimCentre = apex + axis * (r * cosA);
    glm::dvec3 lo = glm::min(apex, rimCentre), hi = glm::max(apex, rimCentre);
    for (int i = 0; i < 3; ++i) {
        const double extent = rim * std::sqrt(std::max(0.0, 1.0 - axis[i] * axis[i]));
        lo[i] = std::min(lo[i], rimCentre[i] - extent);
        hi[i] = std::max(hi[i], rimCentre[i] + extent);
        if (axis[i] >= cosA) hi[i] = apex[i] + r;   // +axis i lies within the cone: the cap reaches the range
        if (-axis[i] >= cosA) lo[i] = apex[i] - r;
    }
    // Rounded outwards, and never beyond the sphere's box.
    const glm::vec3 slack(float(1e-6 * r) + 1e-6f);
    boxMin = glm::max(boxMin, glm::vec3(lo) - slack);
    boxMax = glm::min(boxMax, glm::vec3(hi) + slack);
}

}  // namespace lidr
