#pragma once
// CPU emulation of shader float arithmetic, so unpack code can be run "as a given kind of hardware would":
// fp32 (IEEE single), fp24 (17-bit significand, as on R300-class hardware) and fp16 (11-bit significand,
// half precision). Every operation rounds its exact result to nearest-even in the chosen precision; ranges
// are not modelled except fp16's overflow past 65504 (to infinity).
#include <cmath>
#include <string>

namespace lidr {

enum class FloatPrecision { Fp16, Fp24, Fp32 };
const char* floatPrecisionName(FloatPrecision p);
int significandBits(FloatPrecision p);  // 11, 17, 24
double roundToReducedPrecision(double v, FloatPrecision p);  // by the significand's bits (fp16 and fp24; fp32 inline)
// Inline for fp32, what every desktop GPU runs: the CPU models decode every pixel of every test frame with it.
inline double roundToPrecision(double v, FloatPrecision p) {
    return p == FloatPrecision::Fp32 ? static_cast<double>(static_cast<float>(v)) : roundToReducedPrecision(v, p);
}

// A shader float in precision p: each operation rounds. Comparisons and floor are exact.
struct ShaderFloat {
    double v = 0.0;
    FloatPrecision p = FloatPrecision::Fp32;
    ShaderFloat() = default;
    ShaderFloat(double value, FloatPrecision precision) : v(roundToPrecision(value, precision)), p(precision) {}
    ShaderFloat operator+(ShaderFloat o) const { return {v + o.v, p}; }
    ShaderFloat operator-(ShaderFloat o) const { return {v - o.v, p}; }
    ShaderFloat operator*(ShaderFloat o) const { return {v * o.v, p}; }
    ShaderFloat constant(double c) const { return {c, p}; }  // a literal, as the compiler would round it
};
inline ShaderFloat floorOf(ShaderFloat x) { return {std::floor(x.v), x.p}; }
ShaderFloat stepOf(double edge, ShaderFloat x);  // GLSL step(edge, x): 0 if x < edge, else 1

// shaders/technique/lidr_bytes.glsl, step for step: the byte behind a texel read. lidrBytes is the bit-by-bit
// path the shader takes for fp16 fragments (LIDR_FRAGMENT_FP16); lidrBytesRounded, floor(x * 255 + 0.5), the
// path for fp24 and fp32; lidrBytesFor(read) the one the shader takes for the read's precision.
ShaderFloat lidrBytes(ShaderFloat read);
ShaderFloat lidrBytesRounded(ShaderFloat read);
inline ShaderFloat lidrBytesFor(ShaderFloat read) {
    return read.p == FloatPrecision::Fp16 ? lidrBytes(read) : lidrBytesRounded(read);
}

// The threshold and value constants lidr_bytes.glsl uses for bit j (for the proofs).
double lidrBytesThreshold(int bit);
double lidrBytesValue(int bit);

}  // namespace lidr
