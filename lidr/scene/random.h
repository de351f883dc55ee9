#pragma once
// splitmix64: a tiny seeded generator whose stream is the same on every platform and library (std::
// distributions are not), for scenes and lights that must be the same for the same seed everywhere.
#include <cstdint>

namespace lidr {

class SplitMix64 {
public:
    explicit SplitMix64(uint64_t seed) : state_(seed) {}
    uint64_t next() {
        uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    // Uniform in [0, 1): the top 24 bits, exactly representable as a float.
    float uniform() { return float(next() >> 40) * (1.0f / 16777216.0f); }
    float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
    // Uniform in [0, 1) with 53 bits.
    double uniformDouble() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }

private:
    uint64_t state_;
};

}  // namespace lidr
