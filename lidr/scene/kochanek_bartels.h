#pragma once
// Kochanek-Bartels splines as BART defines its keyframes (Lext, Assarsson and Moeller; the suite's kbsplpos and
// kbsplrot): keys with a time, a value and tension / continuity / bias. Between keys i and i + 1 the value is the
// Hermite cubic through them with tangents
//   outgoing at i:  Tout = a (1 - t)(1 + c)(1 + b)/2 (P_i - P_{i-1}) + a (1 - t)(1 - c)(1 - b)/2 (P_{i+1} - P_i)
//   incoming at i+1: Tin = a' (1 - t)(1 - c)(1 + b)/2 (P_{i+1} - P_i) + a' (1 - t)(1 + c)(1 - b)/2 (P_{i+2} - P_{i+1})
// (t, c, b of the key the tangent belongs to), each scaled for uneven key spacing: a = 2 (t_{i+1} - t_i) /
// (t_{i+1} - t_{i-1}), a' = 2 (t_{i+1} - t_i) / (t_{i+2} - t_i). So the first and last keys only shape the end
// tangents: the spline runs from key 1 to key n - 2, and at least 4 keys are needed. Rotations are unit quaternions
// joined by Shoemake's squad, the same tangents taken in the logarithm of the relative rotations.
#include <vector>

#include "lidr/scene/animation.h"

namespace lidr {

struct KochanekBartelsKey {
    float time = 0.0f;
    glm::vec3 value{0.0f};  // translation or scale
    float tension = 0.0f, continuity = 0.0f, bias = 0.0f;
};

struct KochanekBartelsRotationKey {
    float time = 0.0f;
    glm::vec3 axis{0.0f, 0.0f, 1.0f};  // normalised here (BART assumes unit axes); a zero axis is no rotation
    float angleRadians = 0.0f;
    float tension = 0.0f, continuity = 0.0f, bias = 0.0f;
};

constexpr size_t kKochanekBartelsMinKeys = 4;

// The track from key 1 to key n - 2 (n >= 4, else lidr::Error; times finite). A zero time span where a tangent is
// scaled by it (keys sharing a time, as BART's files repeat their first and last keys) counts as even spacing.
// Keys out of time order (one of the Robots' tracks restarts its times) are taken as BART's code takes them: at
// time t the first segment in key order that ends after t, so a segment is cut short or skipped where an earlier
// one already reaches past it. keysInTimeOrder says whether that rule was needed.
Vec3Track kochanekBartelsTrack(const std::vector<KochanekBartelsKey>& keys);
// Consecutive key rotations are taken on the same side of the quaternion sphere (q and -q are one rotation), so
// each segment turns the short way.
RotationTrack kochanekBartelsRotationTrack(const std::vector<KochanekBartelsRotationKey>& keys);

template <typename Key>
bool keysInTimeOrder(const std::vector<Key>& keys) {
    for (size_t i = 1; i < keys.size(); ++i)
        if (keys[i].time < keys[i - 1].time) return false;
    return true;
}

// Quaternion helpers the tracks use (unit quaternions; exposed for the tests).
glm::quat quatLog(const glm::quat& q);  // (0, angle x axis) for q = (cos angle, sin angle x axis)
glm::quat quatExp(const glm::quat& q);  // the inverse of quatLog
// Spherical interpolation from p (u = 0) to q (u = 1) along the arc between them as given (no sign flip).
glm::quat quatSlerp(const glm::quat& p, const glm::quat& q, float u);
// Shoemake's squad: slerp(slerp(p, q, u), slerp(a, b, u), 2u(1 - u)).
glm::quat quatSquad(const glm::quat& p, const glm::quat& a, const glm::quat& b, const glm::quat& q, float u);

}  // namespace lidr
