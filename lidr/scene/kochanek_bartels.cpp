#include "lidr/scene/kochanek_bartels.h"

#include <cmath>

#include "lidr/base/error.h"

namespace lidr {

namespace {

// 2 (t_{i+1} - t_i) / span, the tangent scale for uneven spacing; even spacing (1) where the span is empty.
float spacing(float segment, float span) { return span > 0.0f ? 2.0f * segment / span : 1.0f; }

template <typename Key>
void checkKeys(const std::vector<Key>& keys, const char* what) {
    if (keys.size() < kKochanekBartelsMinKeys)
        throw Error(std::string("a Kochanek-Bartels ") + what + " track needs at least " +
                    std::to_string(kKochanekBartelsMinKeys) + " keys (the first and last only shape the end tangents), got " +
                    std::to_string(keys.size()));
    for (size_t i = 0; i < keys.size(); ++i)
        if (!std::isfinite(keys[i].time))
            throw Error(std::string("Kochanek-Bartels ") + what + " key " + std::to_string(i) + ": time is not finite");
}

// The Hermite tangents' weights of the segment from k1 to k2 (kochanek_bartels.h): Tout = out0 (P1 - P0) + out1
// (P2 - P1), Tin = in0 (P2 - P1) + in1 (P3 - P2), in the relative rotations' logarithms for rotations.
struct TangentWeights {
    float out0, out1, in0, in1;
};

template <typename Key>
TangentWeights tangentWeights(const Key& k0, const Key& k1, const Key& k2, const Key& k3) {
    const float a = spacing(k2.time - k1.time, k2.time - k0.time);
    const float b = spacing(k2.time - k1.time, k3.time - k1.time);
    return {0.5f * a * (1.0f - k1.tension) * (1.0f + k1.continuity) * (1.0f + k1.bias),
            0.5f * a * (1.0f - k1.tension) * (1.0f - k1.continuity) * (1.0f - k1.bias),
            0.5f * b * (1.0f - k2.tension) * (1.0f - k2.continuity) * (1.0f + k2.bias),
            0.5f * b * (1.0f - k2.tension) * (1.0f + k2.continuity) * (1.0f - k2.bias)};
}

// BART's choice of segment at t (kbsplpos's ComputeIAndU): before segment 0's start, segment 0 at u = 0; from the
// last segment's end on, the last at u = 1; else the first segment in key order whose end is after t. With keys
// in time order that is the segment around t; with keys out of order a segment may be cut short or never used.
// The pieces: segment i used over [the largest end before it, its own end). Calls add(segment, from, to).
template <typename Key, typename Add>
void pieces(const std::vector<Key>& keys, const Add& add) {
    const size_t segments = keys.size() - 3;  // between keys 1 .. n - 2
    const float last = keys[keys.size() - 2].time;
    float reached = keys[1].time;  // the largest segment end so far, at least the first segment's start
    for (size_t i = 0; i < segments && reached < last; ++i) {
        const float end = std::min(keys[i + 2].time, last);
        if (end > reached) add(i, reached, end);
        reached = std::max(reached, end);
    }
}

// The track from the segments' four values each, in pieces by BART's rule; where no segment has a length (every key
// at one time), a STEP track holding `first`. `last`: the value from the last segment's end on.
template <typename Track, typename Key, typename Value>
Track assemble(const std::vector<Key>& keys, const std::vector<Value>& perSegment, const Value& first, const Value& last) {
    Track track;
    track.interpolation = Interpolation::KochanekBartels;
    pieces(keys, [&](size_t segment, float from, float to) {
        if (track.times.empty()) track.times.push_back(from);
        track.times.push_back(to);
        track.segments.insert(track.segments.end(), perSegment.begin() + long(4 * segment),
                              perSegment.begin() + long(4 * segment + 4));
        track.spans.start.push_back(keys[segment + 1].time);
        track.spans.length.push_back(keys[segment + 2].time - keys[segment + 1].time);
    });
    if (track.times.empty()) {
        track.interpolation = Interpolation::Step;
        track.times = {keys[1].time};
        track.values = {first};
        return track;
    }
    track.values = {first, last};
    return track;
}

}  // namespace

glm::quat quatLog(const glm::quat& q) {
    const glm::vec3 v(q.x, q.y, q.z);
    const float s = glm::length(v);
    if (s < 1e-7f) return glm::quat(0.0f, v.x, v.y, v.z);  // sin(A)/A -> 1
    const float angle = std::atan2(s, q.w);
    const glm::vec3 r = v * (angle / s);
    return glm::quat(0.0f, r.x, r.y, r.z);
}

glm::quat quatExp(const glm::quat& q) {
    const glm::vec3 v(q.x, q.y, q.z);
    const float angle = glm::length(v);
    if (angle < 1e-7f) return glm::normalize(glm::quat(1.0f, v.x, v.y, v.z));
    const glm::vec3 r = v * (std::sin(angle) / angle);
    return glm::quat(std::cos(angle), r.x, r.y, r.z);
}

glm::quat quatSlerp(const glm::quat& p, const glm::quat& q, float u) {
    const float cosine = glm::clamp(glm::dot(p, q), -1.0f, 1.0f);
    const float angle = std::acos(cosine);
    const float sine = std::sin(angle);
    if (sine < 1e-5f) return glm::normalize(p * (1.0f - u) + q * u);  // nearly the same rotation: a straight line
    return p * (std::sin((1.0f - u) * angle) / sine) + q * (std::sin(u * angle) / sine);
}

glm::quat quatSquad(const glm::quat& p, const glm::quat& a, const glm::quat& b, const glm::quat& q, float u) {
    return quatSlerp(quatSlerp(p, q, u), quatSlerp(a, b, u), 2.0f * u * (1.0f - u));
}

Vec3Track kochanekBartelsTrack(const std::vector<KochanekBartelsKey>& keys) {
    checkKeys(keys, "vector");
    // Each segment's Hermite cubic in its own fraction u: P(0) = P1, P(1) = P2, P'(0) = Tout, P'(1) = Tin.
    std::vector<glm::vec3> cubic;
    for (size_t i = 1; i + 2 < keys.size(); ++i) {
        const KochanekBartelsKey &k0 = keys[i - 1], &k1 = keys[i], &k2 = keys[i + 1], &k3 = keys[i + 2];
        const glm::vec3 d = k2.value - k1.value;
        const TangentWeights w = tangentWeights(k0, k1, k2, k3);
        const glm::vec3 tangentOut = w.out0 * (k1.value - k0.value) + w.out1 * d;
        const glm::vec3 tangentIn = w.in0 * d + w.in1 * (k3.value - k2.value);
        cubic.insert(cubic.end(), {k1.value, tangentOut, 3.0f * d - 2.0f * tangentOut - tangentIn, -2.0f * d + tangentOut + tangentIn});
    }
    const size_t last = cubic.size() / 4 - 1;
    const glm::vec3 end = cubic[4 * last] + cubic[4 * last + 1] + cubic[4 * last + 2] + cubic[4 * last + 3];
    return assemble<Vec3Track>(keys, cubic, keys[1].value, end);
}

RotationTrack kochanekBartelsRotationTrack(const std::vector<KochanekBartelsRotationKey>& keys) {
    checkKeys(keys, "rotation");
    std::vector<glm::quat> q(keys.size());
    for (size_t i = 0; i < keys.size(); ++i) {
        const float length = glm::length(keys[i].axis);
        if (!std::isfinite(length) || !std::isfinite(keys[i].angleRadians))
            throw Error("Kochanek-Bartels rotation key " + std::to_string(i) + ": axis or angle is not finite");
        q[i] = length > 0.0f ? glm::angleAxis(keys[i].angleRadians, keys[i].axis / length) : glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
        if (i > 0 && glm::dot(q[i - 1], q[i]) < 0.0f) q[i] = -q[i];  // the same rotation, the short way from the last
    }
    std::vector<glm::quat> squad;  // p, a, b, q per segment
    for (size_t i = 1; i + 2 < keys.size(); ++i) {
        const glm::quat logD = quatLog(glm::inverse(q[i]) * q[i + 1]);
        const TangentWeights w = tangentWeights(keys[i - 1], keys[i], keys[i + 1], keys[i + 2]);
        const glm::quat tangentOut = logD * w.out1 + quatLog(glm::inverse(q[i - 1]) * q[i]) * w.out0;
        const glm::quat tangentIn = logD * w.in0 + quatLog(glm::inverse(q[i + 1]) * q[i + 2]) * w.in1;
        squad.insert(squad.end(), {q[i], q[i] * quatExp((tangentOut - logD) * 0.5f),
                                   q[i + 1] * quatExp((logD - tangentIn) * 0.5f), q[i + 1]});
    }
    return assemble<RotationTrack>(keys, squad, q[1], squad.back());
}

}  // namespace lidr
