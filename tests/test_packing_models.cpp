// The packing schemes' CPU models, without a GPU: byte reconstruction proofs in fp16/fp24/fp32, round trips
// of every scheme x budget x width, reads perturbed within +-0.45 step under each precision, blend-hardware
// variants, overflow, and refusal of what a scheme cannot do.
#include <algorithm>
#include <cstdlib>
#include <cmath>
#include <random>
#include <regex>
#include <string>
#include <map>
#include <set>

#include <catch2/catch.hpp>

#include "lidr/technique/bitshift_scheme.h"
#include "lidr/technique/cpu_sorted_scheme.h"
#include "lidr/base/error.h"
#include "lidr/technique/max_stencil_scheme.h"
#include "lidr/technique/packing_scheme.h"
#include "lidr/base/shader_float.h"
#include "lidr/gl/shader_source.h"
#include "config_cases.h"

using namespace lidr;
using namespace lidr::test;

namespace {
const FloatPrecision kPrecisions[] = {FloatPrecision::Fp16, FloatPrecision::Fp24, FloatPrecision::Fp32};

// A context that has everything (the CPU models need none of it).
GlInfo fullContext() {
    GlInfo info;
    info.framebufferObject = true;
    info.drawBuffers = true;
    info.maxDrawBuffers = 8;
    info.maxColorAttachments = 8;
    info.maxTextureUnits = 16;
    return info;
}

// The next representable number above x in precision p.
double nextUp(double x, FloatPrecision p) {
    int e = 0;
    std::frexp(x, &e);
    double up = x + std::ldexp(1.0, e - significandBits(p));
    return roundToPrecision(up, p) > x ? roundToPrecision(up, p) : roundToPrecision(x + std::ldexp(1.0, e - significandBits(p) + 1), p);
}

// A read of byte b offset by about d steps, as precision p delivers it: representable in p and still within
// +-0.45 step of b (rounding to p may not push it out).
float readWithin(int b, double d, FloatPrecision p) {
    double r = roundToPrecision((b + d) / 255.0, p);
    for (int i = 0; i < 64 && r * 255.0 > b + 0.45; ++i) r = roundToPrecision(r - std::ldexp(std::fabs(r), -significandBits(p)), p);
    for (int i = 0; i < 64 && r * 255.0 < b - 0.45; ++i) r = nextUp(r, p);
    return float(r);
}

std::vector<uint32_t> sortedNonNull(const std::vector<uint32_t>& slots) {
    std::vector<uint32_t> v;
    for (uint32_t s : slots)
        if (s) v.push_back(s);
    std::sort(v.begin(), v.end());
    return v;
}
}  // namespace

TEST_CASE("lidrBytes constants are exact in fp16 and every decision threshold lies within (b+0.45, b+0.55) steps",
          "[packing][precision][fp16][fp24][fp32][cpu]") {
    for (int j = 0; j < 8; ++j) {
        REQUIRE(roundToPrecision(lidrBytesThreshold(j), FloatPrecision::Fp16) == lidrBytesThreshold(j));
        REQUIRE(roundToPrecision(lidrBytesValue(j), FloatPrecision::Fp16) == lidrBytesValue(j));
    }
    // The decision for bit j, with the higher bits of b already subtracted, is the real comparison
    // read >= threshold_j + sum(values of the higher set bits): every such breakpoint must lie strictly inside
    // the gap between the reads of (prefix + 2^j - 1) and (prefix + 2^j). Subtractions are exact (Sterbenz:
    // the residual is within [value/2, 2 value] when the bit is set), so this holds in every precision.
    double worst = 1.0;
    for (int b = 0; b < 256; ++b)
        for (int j = 7; j >= 0; --j) {
            double sum = 0.0;
            for (int k = j + 1; k < 8; ++k)
                if ((b >> k) & 1) sum += lidrBytesValue(k);
            const double breakpoint = (lidrBytesThreshold(j) + sum) * 255.0;
            const int prefix = (b >> (j + 1)) << (j + 1);
            const double lo = prefix + (1 << j) - 1 + 0.45, hi = prefix + (1 << j) - 0.45;
            REQUIRE(breakpoint > lo);
            REQUIRE(breakpoint < hi);
            worst = std::min({worst, breakpoint - lo, hi - breakpoint});
            if (j < 7 && ((b >> j) & 1)) {  // Sterbenz for the subtraction of value_j
                const double residualMin = lidrBytesThreshold(j), residualMax = ((1 << (j + 1)) - 0.45) / 255.0;
                REQUIRE(residualMin >= lidrBytesValue(j) / 2);
                REQUIRE(residualMax <= lidrBytesValue(j) * 2);
            }
        }
    CHECK(worst > 0.04);  // every read within +-0.49 step decodes; we claim +-0.45
}

TEST_CASE("lidrBytes: every fp16 and every fp24 read within +-0.45 step gives the exact byte (exhaustive)",
          "[packing][precision][fp16][fp24][cpu]") {
    for (FloatPrecision p : {FloatPrecision::Fp16, FloatPrecision::Fp24}) {
        long reads = 0;
        for (int b = 0; b < 256; ++b) {
            const double lo = (b - 0.45) / 255.0, hi = (b + 0.45) / 255.0;
            // Below the smallest threshold every bit is 0: reads of b = 0 (and negative ones) all give 0.
            double x = std::max(roundToPrecision(lo, p), b == 0 ? lidrBytesThreshold(0) / 2 : 0.0);
            if (x < lo) x = nextUp(x, p);
            for (; x <= hi; x = nextUp(x, p), ++reads) {
                const ShaderFloat got = lidrBytes(ShaderFloat(x, p));
                if (got.v != b) FAIL(floatPrecisionName(p) << " read " << x * 255.0 << " steps gave " << got.v << ", not " << b);
            }
        }
        INFO(floatPrecisionName(p) << ": " << reads << " reads");
        CHECK(reads > 256 * (p == FloatPrecision::Fp16 ? 4 : 200));
    }
}

TEST_CASE("the GLSL ES text lidr emits for mediump fragments is the fp16 model's lidrBytes, step for step",
          "[packing][precision][fp16][cpu]") {
    // The forward pass's fragment shader exactly as an ES 2.0 context compiles it (gl::Program makes the same
    // call): the proofs above hold for the GPU only if this text is the arithmetic the model runs.
    const std::string es = glslEs100FromGlsl120(
        buildShaderSource("lidr_forward.frag", {{"LIDR_SLOTS", "4"}}, {{"lidr_unpack.glsl", "unpack_bitshift.glsl"}}),
        ShaderStage::Fragment, "lidr_forward.frag");
    // 1. Without GL_FRAGMENT_PRECISION_HIGH the default float precision is mediump and LIDR_FRAGMENT_FP16 is set.
    const size_t high = es.find("#ifdef GL_FRAGMENT_PRECISION_HIGH\n");
    REQUIRE(high != std::string::npos);
    const size_t otherwise = es.find("#else\n", high), endif = es.find("#endif\n", otherwise);
    REQUIRE((otherwise != std::string::npos && endif != std::string::npos));
    const std::string mediumBranch = es.substr(otherwise, endif - otherwise);
    REQUIRE(mediumBranch.find("precision mediump float;") != std::string::npos);
    REQUIRE(mediumBranch.find("#define LIDR_FRAGMENT_FP16 1") != std::string::npos);
    const std::regex precisionStatement(R"(precision\s+(lowp|mediump|highp)\s+float\s*;)");
    REQUIRE_FALSE(std::regex_search(es.substr(endif), precisionStatement));  // no later statement overrides it
    // 2. lidrBytes as compiled with LIDR_FRAGMENT_FP16: the #else of lidr_bytes.glsl's #ifndef, parsed.
    const size_t guard = es.find("#ifndef LIDR_FRAGMENT_FP16");
    REQUIRE(guard != std::string::npos);
    const size_t from = es.find("#else", guard), to = es.find("#endif", from);
    REQUIRE((from != std::string::npos && to != std::string::npos));
    const std::string body = es.substr(from, to - from);
    const std::regex stepLine(R"(bit = step\(vec4\(([0-9.]+)\), x\);\s*(?:x -= bit \* ([0-9.]+);)?\s*b \+= bit(?: \* ([0-9.]+))?;)");
    struct Step {
        double threshold, value, weight;
    };
    std::vector<Step> steps;
    for (auto m = std::sregex_iterator(body.begin(), body.end(), stepLine); m != std::sregex_iterator(); ++m)
        steps.push_back({std::stod((*m)[1]), (*m)[2].matched ? std::stod((*m)[2]) : 0.0,
                         (*m)[3].matched ? std::stod((*m)[3]) : 1.0});
    size_t assignments = 0;
    for (size_t p = body.find("bit = "); p != std::string::npos; p = body.find("bit = ", p + 1)) ++assignments;
    REQUIRE(assignments == 8);  // every step of the emitted function was parsed
    REQUIRE(steps.size() == 8);
    for (int i = 0; i < 8; ++i) {
        const int j = 7 - i;  // most significant bit first
        INFO("bit " << j);
        CHECK(steps[size_t(i)].threshold == lidrBytesThreshold(j));
        CHECK(steps[size_t(i)].value == (j == 0 ? 0.0 : lidrBytesValue(j)));  // bit 0 subtracts nothing
        CHECK(steps[size_t(i)].weight == double(1 << j));
    }
    // 3. The parsed text run in fp16 gives the model's byte for every fp16 read in [0, 1] (and so, by the
    //    proofs above, the exact byte for every read within +-0.45 step).
    const FloatPrecision p = FloatPrecision::Fp16;
    long reads = 0;
    for (double x = 0.0; x <= 1.0; x = nextUp(x, p), ++reads) {
        ShaderFloat r(x, p), b(0.0, p);
        for (const Step& s : steps) {
            const ShaderFloat bit = stepOf(roundToPrecision(s.threshold, p), r);
            if (s.value != 0.0) r = r - bit * ShaderFloat(s.value, p);
            b = b + bit * ShaderFloat(s.weight, p);
        }
        const double model = lidrBytes(ShaderFloat(x, p)).v;
        if (b.v != model) FAIL("read " << x << ": the emitted text gives " << b.v << ", the model " << model);
    }
    CHECK(reads > 11000);  // 0 and every fp16 number from 2^-11 (below the smallest threshold, 2^-9) to 1
}

TEST_CASE("lidrBytes: fp32 reads within +-0.45 step give the exact byte (interval ends, every breakpoint's "
          "neighbours, 4,000 reads per byte)", "[packing][precision][fp32][cpu]") {
    const FloatPrecision p = FloatPrecision::Fp32;
    for (int b = 0; b < 256; ++b) {
        std::vector<float> reads = {float((b - 0.45) / 255.0), float((b + 0.45) / 255.0), float(b / 255.0)};
        reads[0] = std::nextafter(reads[0], 2.0f);  // inside the interval
        reads[1] = std::nextafter(reads[1], -2.0f);
        for (int i = 0; i <= 4000; ++i) reads.push_back(float((b - 0.45 + 0.9 * i / 4000.0) / 255.0));
        for (float r : reads) {
            if (r * 255.0 < b - 0.45 || r * 255.0 > b + 0.45) continue;
            REQUIRE(lidrBytes(ShaderFloat(r, p)).v == b);
        }
    }
}

TEST_CASE("lidrBytes, rounded path: every fp24 read within +-0.45 step gives the exact byte (exhaustive), fp32 "
          "at interval ends and 4,000 reads per byte", "[packing][precision][fp24][fp32][cpu]") {
    long reads = 0;
    const FloatPrecision p24 = FloatPrecision::Fp24;
    for (int b = 0; b < 256; ++b) {
        const double lo = (b - 0.45) / 255.0, hi = (b + 0.45) / 255.0;
        double x = std::max(roundToPrecision(lo, p24), 0.0);
        if (x < lo) x = nextUp(x, p24);
        for (; x <= hi; x = nextUp(x, p24), ++reads) {
            const ShaderFloat got = lidrBytesRounded(ShaderFloat(x, p24));
            if (got.v != b) FAIL("fp24 read " << x * 255.0 << " steps gave " << got.v << ", not " << b);
        }
        for (int i = 0; i <= 4000; ++i) {
            float r = float((b - 0.45 + 0.9 * i / 4000.0) / 255.0);
            if (r * 255.0 < b - 0.45 || r * 255.0 > b + 0.45) continue;
            REQUIRE(lidrBytesRounded(ShaderFloat(r, FloatPrecision::Fp32)).v == b);
        }
    }
    CHECK(reads > 256 * 200);
    // And the shader takes it only where it holds: fp16 reads go bit by bit.
    CHECK(lidrBytesFor(ShaderFloat(0.5, FloatPrecision::Fp16)).v == lidrBytes(ShaderFloat(0.5, FloatPrecision::Fp16)).v);
}

TEST_CASE("the naive floor(x * 255 + 0.5) is not exact in fp16 for reads within +-0.45 step (why lidrBytes exists)",
          "[packing][precision][fp16][cpu]") {
    const FloatPrecision p = FloatPrecision::Fp16;
    int wrong = 0;
    for (int b = 0; b < 256; ++b)
        for (double d : {-0.45, -0.3, 0.3, 0.45}) {
            const ShaderFloat x((b + d) / 255.0, p);
            const ShaderFloat naive = floorOf(x * x.constant(255.0) + x.constant(0.5));
            wrong += naive.v != b;
        }
    CHECK(wrong > 0);
}

TEST_CASE("every scheme x budget x width: the CPU model round-trips every index in every slot, empty and "
          "overflowing lists", "[packing][cpu]") {
    const ConfigCase c = GENERATE(from_range(packingCases()));
    DYNAMIC_SECTION(c.name) {
        const int bits = c.packing.indexBits, budget = c.packing.budget;
        const auto s = createPackingScheme(c.packing, fullContext());
        INFO(s->describe());
        const uint32_t maxIndex = s->maxLights();
        const std::vector<uint8_t> zero(size_t(s->targetCount()) * 4, 0);
        for (uint32_t slot : s->decodePixel(zero.data())) REQUIRE(slot == 0);  // unlit: the null light
        REQUIRE(s->encodePixel({}) == zero);
        const uint32_t stride = bits == 16 ? 251 : 1;
        for (int at = 0; at < budget; ++at)
            for (uint32_t v = 1; v <= maxIndex; v += stride) {
                std::vector<uint32_t> list;
                for (int k = 0; k < std::min<int>(budget, int(maxIndex)); ++k)
                    list.push_back(k == at ? v : 1 + (v + uint32_t(k) * 5u) % maxIndex);
                std::sort(list.begin(), list.end());
                list.erase(std::unique(list.begin(), list.end()), list.end());
                const std::vector<uint32_t> slots = s->decodePixel(s->encodePixel(list).data());
                REQUIRE(slots.size() == size_t(budget));
                REQUIRE(sortedNonNull(slots) == s->keptLights(list));
            }
        // Overflow: the first `budget` in draw order are kept, the rest counted by the stencil.
        std::mt19937 rng(uint32_t(bits * 100 + budget));
        for (int trial = 0; trial < 300; ++trial) {
            std::vector<uint32_t> list;
            const int n = std::min<int>(budget + 1 + trial % 7, int(maxIndex));
            while (int(list.size()) < n) {
                const uint32_t i = 1 + rng() % maxIndex;
                if (std::find(list.begin(), list.end(), i) == list.end()) list.push_back(i);
            }
            int count = 0;
            const std::vector<uint32_t> slots = s->decodePixel(s->encodePixel(list, {}, &count).data());
            REQUIRE(count == n);
            REQUIRE(sortedNonNull(slots) == s->keptLights(list));
        }
    }
}

TEST_CASE("decoding is exact for reads perturbed within +-0.45 step: fp16, fp24 and fp32 for all widths",
          "[packing][precision][fp16][fp24][fp32][cpu]") {
    const ConfigCase c = GENERATE(from_range(packingCases()));
    DYNAMIC_SECTION(c.name) {
        const int bits = c.packing.indexBits, budget = c.packing.budget;
        const auto s = createPackingScheme(c.packing, fullContext());
        std::mt19937 rng(uint32_t(budget * 7 + bits));
        std::uniform_real_distribution<double> offset(-0.45, 0.45);
        for (FloatPrecision p : kPrecisions) {
            INFO(s->describe() << ", " << floatPrecisionName(p));
            for (int trial = 0; trial < 400; ++trial) {
                std::vector<uint32_t> list;
                const int n = std::min<int>(trial % (budget + 3), int(s->maxLights()));
                while (int(list.size()) < n) {
                    const uint32_t i = 1 + rng() % s->maxLights();
                    if (std::find(list.begin(), list.end(), i) == list.end()) list.push_back(i);
                }
                const std::vector<uint8_t> bytes = s->encodePixel(list);
                std::vector<float> reads;
                for (uint8_t b : bytes) {
                    const double d = trial % 3 == 0 ? (trial % 2 ? 0.45 : -0.45) : offset(rng);
                    reads.push_back(readWithin(b, d, p));
                }
                REQUIRE(s->decodeReads(reads.data(), p) == s->decodePixel(bytes.data()));
            }
        }
    }
}

TEST_CASE("fp16: every 16-bit index decodes exactly in every slot, as two bytes that are never one float",
          "[packing][precision][fp16][cpu]") {
    // One fp16 value cannot hold an index above 2048 (4097 rounds to 4096), so the unpack shaders return the
    // index as (low byte, high byte) and the light table is looked up at (column, row) = (low, high)
    // (doc/packing.md, "Precision"). Exhaustive: every index 1..65535 drawn first and drawn last into a full list
    // of every scheme at budget 1 (every 13th index at 2..16, every index with LIDR_FP16_EXHAUSTIVE=1; the other
    // lights random), read at the byte exactly and at +-0.45 step.
    SECTION("one fp16 value cannot hold 4097") { CHECK(roundToPrecision(4097.0, FloatPrecision::Fp16) != 4097.0); }
    SECTION("every scheme and budget, 16-bit") {
        const FloatPrecision p = FloatPrecision::Fp16;
        const ConfigCase c = GENERATE(from_range(packingCases(kBudgets, {16})));
        DYNAMIC_SECTION(c.name) {
            const int budget = c.packing.budget;
            const auto s = createPackingScheme(c.packing, fullContext());
            INFO(s->describe());
            long checked = 0, wrong = 0;
            std::mt19937 rng{uint32_t(budget)};
            // Every index at budget 1; every 13th at the larger budgets (all of them with LIDR_FP16_EXHAUSTIVE=1,
            // about 40 s of CPU).
            const uint32_t stride = (budget == 1 || std::getenv("LIDR_FP16_EXHAUSTIVE")) ? 1u : 13u;
            for (uint32_t index = 1; index <= 65535u; index += stride)
                for (int slot : budget == 1 ? std::vector<int>{0} : std::vector<int>{0, budget - 1}) {
                    // A full list in draw order whose light at draw position `slot` is `index`.
                    std::vector<uint32_t> list;
                    while (int(list.size()) < budget) {
                        const uint32_t other = int(list.size()) == slot ? index : 1 + rng() % 65535u;
                        if (std::find(list.begin(), list.end(), other) == list.end() &&
                            (int(list.size()) == slot || other != index))
                            list.push_back(other);
                    }
                    const std::vector<uint8_t> bytes = s->encodePixel(list);
                    const std::vector<uint32_t> exact = s->decodePixel(bytes.data());
                    std::vector<float> reads;
                    const double d = index % 3 == 0 ? 0.0 : (index % 3 == 1 ? 0.45 : -0.45);
                    for (uint8_t b : bytes) reads.push_back(readWithin(b, d, p));
                    const std::vector<uint32_t> got = s->decodeReads(reads.data(), p);
                    ++checked;
                    if (got != exact || sortedNonNull(got) != s->keptLights(list)) ++wrong;
                }
            CHECK(checked >= long(65535 / stride));
            CHECK(wrong == 0);
        }
    }
}

TEST_CASE("bit-shift within its slots is exact on every blend hardware variant; an uncapped overflow corrupts "
          "kept indices under round-to-nearest", "[packing][bitshift][cpu]") {
    SECTION("within the slots, every width and budget") {
        const ConfigCase c = GENERATE(from_range(packingCases({2, 4, 8, 16}, kIndexWidths, {PackingSchemeKind::BitShift})));
        DYNAMIC_SECTION(c.name) {
            const int budget = c.packing.budget, bits = c.packing.indexBits;
            const BitShiftScheme s(c.packing, fullContext());
            std::mt19937 rng(uint32_t(budget + bits));
            for (BlendModel m : {BlendModel{false, false}, BlendModel{true, false}, BlendModel{false, true}, BlendModel{true, true}}) {
                INFO(s.describe() << ", quantised constant " << m.quantisedConstant << ", truncate " << m.truncate);
                for (int trial = 0; trial < 300; ++trial) {
                    std::vector<uint32_t> list;
                    const int n = std::min<int>(1 + trial % (budget + 4), int(s.maxLights()));
                    while (int(list.size()) < n) {
                        const uint32_t i = 1 + rng() % s.maxLights();
                        if (std::find(list.begin(), list.end(), i) == list.end()) list.push_back(i);
                    }
                    REQUIRE(sortedNonNull(s.decodePixel(s.encodePixel(list, m).data())) == s.keptLights(list));
                }
            }
        }
    }
    SECTION("an uncapped overflow") {
        // Without the stencil window, a fifth light into 2-bit groups (budget 4) shifts the oldest group out;
        // round-to-nearest carries its top bit into the kept bits.
        const BitShiftScheme s({PackingSchemeKind::BitShift, 4, 8}, fullContext());
        int corrupted = 0;
        for (uint32_t oldest = 1; oldest < 256; ++oldest) {
            std::vector<uint32_t> list = {oldest, 17, 34, 51, 68};
            uint8_t texel[4] = {0, 0, 0, 0};
            for (uint32_t index : list) {
                const IndexColors c = s.colorsFor(index);
                for (int ch = 0; ch < 4; ++ch)
                    texel[ch] = uint8_t(std::min(255.0, std::nearbyint(std::nearbyint(c[0][ch] * 255.0) + texel[ch] / 4.0)));
            }
            const std::vector<uint32_t> kept = sortedNonNull(s.decodePixel(texel));
            corrupted += kept != std::vector<uint32_t>{17, 34, 51, 68};
        }
        CHECK(corrupted > 0);
    }
}

TEST_CASE("MAX scheme: an unlit pixel and a one-light window decode to null slots, never 255 or a duplicate",
          "[packing][max-stencil][cpu]") {
    const ConfigCase c = GENERATE(from_range(packingCases({2, 4, 8, 16}, {8}, {PackingSchemeKind::MaxStencil})));
    DYNAMIC_SECTION(c.name) {
        const MaxStencilScheme s(c.packing, fullContext());
        const std::vector<uint8_t> unlit(size_t(s.targetCount()) * 4, 0);
        for (uint32_t v : s.decodePixel(unlit.data())) REQUIRE(v == 0);
        for (uint32_t a = 1; a <= 255; ++a) {
            const std::vector<uint32_t> slots = s.decodePixel(s.encodePixel({a}).data());
            REQUIRE(slots[0] == a);
            for (size_t i = 1; i < slots.size(); ++i) REQUIRE(slots[i] == 0);
            const std::vector<uint32_t> three = s.decodePixel(s.encodePixel({a, 1 + a % 255, 1 + (a + 1) % 255}).data());
            REQUIRE(std::count(three.begin(), three.end(), a) == 1);
        }
    }
}

TEST_CASE("configurations: targets, passes, memory per pixel, and refusal of what cannot be done",
          "[packing][bad-input][cpu]") {
    const GlInfo full = fullContext();
    // Paper's bit-shift table: targets per (width, budget).
    const std::map<std::pair<int, int>, int> bitshiftTargets = {
        {{4, 1}, 1}, {{4, 2}, 1}, {{4, 4}, 1}, {{4, 8}, 1}, {{4, 16}, 2}, {{8, 1}, 1}, {{8, 2}, 1}, {{8, 4}, 1},
        {{8, 8}, 2}, {{8, 16}, 4}, {{16, 1}, 1}, {{16, 2}, 1}, {{16, 4}, 2}, {{16, 8}, 4}, {{16, 16}, 8}};
    for (const auto& [key, targets] : bitshiftTargets) {
        const BitShiftScheme s({PackingSchemeKind::BitShift, key.second, key.first}, full);
        INFO(s.describe());
        CHECK(s.targetCount() == targets);
        CHECK(s.geometryPasses() == (key.second == 16 ? 2 : 1));
        CHECK(s.indexBytes(100, 10) == size_t(targets) * 4000);
    }
    CHECK(MaxStencilScheme({PackingSchemeKind::MaxStencil, 4, 8}, full).geometryPasses() == 2);  // the paper's two passes
    CHECK(MaxStencilScheme({PackingSchemeKind::MaxStencil, 16, 8}, full).targetCount() == 4);
    CHECK(MaxStencilScheme({PackingSchemeKind::MaxStencil, 16, 16}, full).geometryPasses() == 16);
    CHECK(CpuSortedScheme({PackingSchemeKind::CpuSorted, 16, 4}, full).targetCount() == 2);
    CHECK(CpuSortedScheme({PackingSchemeKind::CpuSorted, 16, 16}, full).targetCount() == 8);

    for (PackingSchemeKind scheme : packingSchemes()) {
        REQUIRE_THROWS_WITH(createPackingScheme({scheme, 3, 8}, full), Catch::Contains("1, 2, 4, 8, 16 or 32"));
        if (scheme == PackingSchemeKind::BitShift) {
            // Budget 32: bit-shift's four rank windows, 4- and 8-bit indices only (16 bits would need 16 targets).
            REQUIRE(createPackingScheme({scheme, 32, 8}, full)->targetCount() == 8);
            REQUIRE(createPackingScheme({scheme, 32, 8}, full)->geometryPasses() == 4);
            REQUIRE(createPackingScheme({scheme, 32, 4}, full)->targetCount() == 4);
            REQUIRE_THROWS_WITH(createPackingScheme({scheme, 32, 16}, full), Catch::Contains("16 index targets"));
        } else {
            REQUIRE_THROWS_WITH(createPackingScheme({scheme, 32, 8}, full), Catch::Contains("budget 32 is bit-shift"));
        }
        REQUIRE_THROWS_WITH(createPackingScheme({scheme, 64, 8}, full), Catch::Contains("1, 2, 4, 8, 16 or 32"));
        REQUIRE_THROWS_WITH(createPackingScheme({scheme, 4, 12}, full), Catch::Contains("4, 8 or 16"));
        GlInfo fewAttachments = full;
        fewAttachments.maxColorAttachments = 4;
        REQUIRE_THROWS_AS(createPackingScheme({scheme, 16, 16}, fewAttachments), UnsupportedError);
        REQUIRE_NOTHROW(createPackingScheme({scheme, 8, 8}, fewAttachments));
        GlInfo fewUnits = full;
        fewUnits.maxTextureUnits = 8;
        REQUIRE_THROWS_WITH(createPackingScheme({scheme, 1, 8}, fewUnits), Catch::Contains("texture units"));
    }
    GlInfo oneDrawBuffer = full;
    oneDrawBuffer.maxDrawBuffers = 1;
    REQUIRE_THROWS_WITH(createPackingScheme({PackingSchemeKind::BitShift, 8, 8}, oneDrawBuffer), Catch::Contains("draw buffers"));
    REQUIRE_NOTHROW(createPackingScheme({PackingSchemeKind::MaxStencil, 16, 16}, oneDrawBuffer));  // one target per draw
    REQUIRE_THROWS_WITH(parsePackingScheme("nonsense"),
                        Catch::Contains("bitshift") && Catch::Contains("max-stencil") && Catch::Contains("cpu-sorted"));
}
