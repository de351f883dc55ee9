#include "lidr/base/shader_float.h"

#include <cmath>
#include <limits>

namespace lidr {

const char* floatPrecisionName(FloatPrecision p) {
    switch (p) {
    case FloatPrecision::Fp16: return "fp16";
    case FloatPrecision::Fp24: return "fp24";
    case FloatPrecision::Fp32: return "fp32";
    }
    return "?";
}

int significandBits(FloatPrecision p) {
    switch (p) {
    case FloatPrecision::Fp16: return 11;
    case FloatPrecision::Fp24: return 17;
    case FloatPrecision::Fp32: return 24;
    }
    return 24;
}

double roundToReducedPrecision(double v, FloatPrecision p) {
    if (v == 0.0 || !std::isfinite(v)) return v;
    int e = 0;
    const double m = std::frexp(v, &e);  // v = m * 2^e, 0.5 <= |m| < 1
    const int bits = significandBits(p);
    const double r = std::ldexp(std::nearbyint(std::ldexp(m, bits)), e - bits);  // ties to even
    if (p == FloatPrecision::Fp16 && std::fabs(r) > 65504.0) return std::copysign(std::numeric_limits<double>::infinity(), r);
    return r;
}

ShaderFloat stepOf(double edge, ShaderFloat x) { return {x.v < roundToPrecision(edge, x.p) ? 0.0 : 1.0, x.p}; }

namespace {
// 257 / 2^(16 - j) ~ 2^j / 255 and the thresholds ~ (2^j - 0.5) / 255, all exact in fp16 (see lidr_bytes.glsl).
constexpr double kThreshold[8] = {0.00196075439453125, 0.00588226318359375, 0.01372528076171875, 0.0294189453125,
                                  0.060791015625,      0.12353515625,       0.2490234375,        0.5};
}  // namespace

double lidrBytesThreshold(int bit) { return kThreshold[bit]; }
double lidrBytesValue(int bit) { return std::ldexp(257.0, bit - 16); }

ShaderFloat lidrBytesRounded(ShaderFloat x) { return floorOf(x * x.constant(255.0) + x.constant(0.5)); }

ShaderFloat lidrBytes(ShaderFloat x) {
    ShaderFloat b = x.constant(0.0);
    for (int j = 7; j >= 0; --j) {
        const ShaderFloat bit = stepOf(kThreshold[j], x);
        if (j > 0) x = x - bit * x.constant(lidrBytesValue(j));
        b = b + bit * x.constant(std::ldexp(1.0, j));
    }
    return b;
}

}  // namespace lidr
