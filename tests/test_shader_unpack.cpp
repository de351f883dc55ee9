// Shader-unpack tests: index lists go through each scheme's REAL volume draws (blend, colour masks, stencil
// rank windows, both volume tests) via the light-volume pass drawing pixel lists (pixel_list_geometry.h), one
// list per pixel; the index targets are then decoded by the scheme's REAL unpack shader. Checked per pixel:
// the bytes against the CPU blend/stencil model, the stencil count against the list length, the shader's slots
// against the CPU unpack model, and the kept lights against the truth (the first `budget` lights in draw order).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <set>

#include <catch2/catch.hpp>

#include "config_cases.h"
#include "gl_test_context.h"
#include "pixel_list_geometry.h"
#include "lidr/base/gl.h"
#include "lidr/base/error.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/gl_state.h"
#include "lidr/technique/light_volume_pass.h"
#include "lidr/technique/packing_scheme.h"
#include "lidr/gl/shader_source.h"

using namespace lidr;
using namespace lidr::test;

namespace {

using Lists = std::vector<std::vector<uint32_t>>;

struct UnpackRun {
    int width = 0, height = 0;
    std::vector<std::vector<uint8_t>> targets;  // per target, RGBA8, GL row order
    std::vector<uint8_t> stencil;
    std::vector<std::vector<uint32_t>> slots;   // per pixel, what the unpack shader returned slot by slot
};

std::vector<uint8_t> readRaw(int w, int h, GLenum format, int channels) {
    std::vector<uint8_t> raw(size_t(w) * h * channels);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, format, GL_UNSIGNED_BYTE, raw.data());
    checkGl("unpack test readback");
    return raw;
}

// bitByBitBytes: the unpack shader compiled with LIDR_FRAGMENT_FP16, the byte decode an ES context without
// fragment highp takes (lidr_bytes.glsl's bit-by-bit path), whatever the context's precision.
UnpackRun runLists(const PackingScheme& scheme, VolumeTest test, const Lists& lists, bool bitByBitBytes = false) {
    testContext();
    const int width = std::min<int>(1024, std::max<int>(1, static_cast<int>(lists.size())));
    const int height = static_cast<int>((lists.size() + width - 1) / width);
    // Each pixel's steps: its list, with decoys (volumes in front of the surface: they must neither write nor
    // count) before about a third of the entries and after the last, seeded by the pixel.
    constexpr uint32_t kDecoy = 0x10000u;
    std::vector<std::vector<uint32_t>> sequences(lists.size());
    size_t steps = 0;
    for (size_t p = 0; p < lists.size(); ++p) {
        uint32_t h = uint32_t(p) * 2654435761u + 12345u;
        for (uint32_t index : lists[p]) {
            h = h * 1664525u + 1013904223u;
            // CPU sorting maps step j to group j, so there a decoy may only follow the list.
            if ((h >> 28) < 5 && scheme.keepsFirstMarks()) sequences[p].push_back(kDecoy | index);
            sequences[p].push_back(index);
        }
        if ((h >> 20) & 1) sequences[p].push_back(kDecoy | 1u);
        if ((h >> 21) & 1) sequences[p].push_back(kDecoy | 2u);
        steps = std::max(steps, sequences[p].size());
    }
    std::vector<gl::Texture> stepTextures;
    for (size_t j = 0; j < steps; ++j) {
        std::vector<uint8_t> texels(size_t(width) * height * 4, 0);
        for (size_t p = 0; p < lists.size(); ++p)
            if (j < sequences[p].size()) {
                texels[p * 4 + 0] = uint8_t(sequences[p][j] & 0xFF);
                texels[p * 4 + 1] = uint8_t((sequences[p][j] >> 8) & 0xFF);
                texels[p * 4 + 2] = (sequences[p][j] & kDecoy) ? 255 : 0;
            }
        stepTextures.push_back(gl::Texture::create2D(GL_RGBA8, width, height, GL_RGBA, GL_UNSIGNED_BYTE, texels.data()));
    }
    PixelListSource source;
    for (const auto& t : stepTextures) source.steps.push_back(&t);
    source.maxIndex = scheme.maxLights();

    gl::Renderbuffer depthStencil = gl::Renderbuffer::create(GL_DEPTH24_STENCIL8, width, height);
    IndexTargets targets(scheme.targetCount(), width, height, depthStencil);
    static std::map<VolumeTest, std::unique_ptr<LightVolumePass>> passes;  // programs compiled once
    auto& cached = passes[test];
    if (!cached) cached = std::make_unique<LightVolumePass>(testGl(), test);
    LightVolumePass& pass = *cached;
    static PixelListGeometry geometry(testGl());
    geometry.setSource(&source);
    pass.setGeometry(&geometry);
    targets.framebuffer().bind();
    RenderState depthClear;
    depthClear.depthWrite = true;
    applyRenderState(depthClear);
    setClearDepth(0.5f);  // list entries (depth 1) pass the volume test's GEQUAL, decoys (0.25) fail it
    glClear(GL_DEPTH_BUFFER_BIT);
    setClearDepth(1.0f);
    CameraMatrices camera;
    camera.width = width;
    camera.height = height;
    pass.begin(targets, camera);
    std::vector<VolumeLight> lights;
    for (size_t j = 0; j < steps; ++j) lights.push_back({uint32_t(j + 1), glm::vec4(0.0f, 0.0f, -10.0f, 1.0f)});
    scheme.encode(pass, lights);
    pass.end();
    pass.setGeometry(nullptr);

    UnpackRun run;
    run.width = width;
    run.height = height;
    targets.framebuffer().bind();
    for (int t = 0; t < targets.count(); ++t) {
        if (testGl().gles) {  // ES 2.0 reads COLOR_ATTACHMENT0 only
            targets.framebufferFrom(t).bind();
            run.targets.push_back(readRaw(width, height, GL_RGBA, 4));
            continue;
        }
        glReadBuffer(GL_COLOR_ATTACHMENT0 + t);
        run.targets.push_back(readRaw(width, height, GL_RGBA, 4));
    }
    targets.framebuffer().bind();
    if (testGl().gles) {  // NV_read_depth_stencil: depth and stencil together, stencil in the low byte
        std::vector<GLuint> packed(size_t(width) * height);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, 0, width, height, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed.data());
        checkGl("unpack test stencil readback");
        for (GLuint v : packed) run.stencil.push_back(uint8_t(v & 0xFFu));
    } else {
        readFromColorAttachment0();
        run.stencil = readRaw(width, height, GL_STENCIL_INDEX, 1);
    }

    // Decode with the real unpack shader, two slots per draw.
    static std::map<std::string, gl::Program> probes;  // one per configuration
    gl::Program& probe = probes[scheme.describe() + (bitByBitBytes ? ", bit-by-bit bytes" : "")];
    if (!probe) {
        ShaderDefines defines = scheme.unpackDefines();
        if (bitByBitBytes) defines.push_back({"LIDR_FRAGMENT_FP16", "1"});
        probe = gl::Program::create(
            std::string("unpack-probe-") + packingSchemeName(scheme.config().scheme),
            testShaderSource("pixel_list_volume.vert", {{"LIDR_DRAW_TARGETS", "1"}}),
            buildShaderSource("unpack_probe.frag", defines, {{"lidr_unpack.glsl", scheme.unpackShaderFile()}}),
            {{"aPosition", gl::kPosition}});
    }
    gl::Texture out = gl::Texture::create2D(GL_RGBA8, width, height, GL_RGBA, GL_UNSIGNED_BYTE);
    gl::Framebuffer fbo = gl::Framebuffer::create();
    fbo.attachTexture(GL_COLOR_ATTACHMENT0, out);
    fbo.checkComplete("unpack probe");
    const float quad[] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, -1, 0, 1, 1, 0, -1, 1, 0};
    gl::Buffer quadBuffer = gl::Buffer::create(GL_ARRAY_BUFFER, quad, sizeof(quad));
    fbo.bind();
    GLenum buffer = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &buffer);
    glViewport(0, 0, width, height);
    applyRenderState(RenderState{});
    probe.use();
    for (int t = 0; t < targets.count(); ++t) {
        targets.texture(t).bind(t);
        probe.set(("uIndexTex" + std::to_string(t)).c_str(), t);
    }
    probe.set("uInvTargetSize", glm::vec2(1.0f / width, 1.0f / height));
    glBindBuffer(GL_ARRAY_BUFFER, quadBuffer.id());
    glEnableVertexAttribArray(gl::kPosition);
    glVertexAttribPointer(gl::kPosition, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    const int budget = scheme.config().budget;
    run.slots.assign(lists.size(), std::vector<uint32_t>(size_t(budget), 0));
    for (int base = 0; base < budget; base += 2) {
        probe.set("uSlotBase", float(base));
        glDrawArrays(GL_TRIANGLES, 0, 6);
        const std::vector<uint8_t> raw = readRaw(width, height, GL_RGBA, 4);
        for (size_t p = 0; p < lists.size(); ++p) {
            run.slots[p][size_t(base)] = raw[p * 4] | (uint32_t(raw[p * 4 + 1]) << 8);
            if (base + 1 < budget) run.slots[p][size_t(base) + 1] = raw[p * 4 + 2] | (uint32_t(raw[p * 4 + 3]) << 8);
        }
    }
    glDisableVertexAttribArray(gl::kPosition);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    for (int t = 0; t < targets.count(); ++t) {
        glActiveTexture(GL_TEXTURE0 + t);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    glActiveTexture(GL_TEXTURE0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGl("unpack probe");
    return run;
}

struct Mismatches {
    long bytes = 0, counts = 0, unpack = 0, kept = 0, order = 0;
    std::string first;
    long total() const { return bytes + counts + unpack + kept + order; }
};

// Every check for every pixel; the first failure is described.
Mismatches checkRun(const PackingScheme& scheme, VolumeTest test, const Lists& lists, const UnpackRun& run) {
    Mismatches m;
    const int targets = scheme.targetCount();
    const int countMax = test == VolumeTest::BackFace ? 255 : 127;
    const int countMask = test == VolumeTest::BackFace ? 0xFF : 0x7F;
    std::vector<uint8_t> texel(size_t(targets) * 4);
    auto note = [&](size_t p, const char* what) {
        if (!m.first.empty()) return;
        m.first = std::string(what) + " at list " + std::to_string(p) + " [";
        for (uint32_t i : lists[p]) m.first += std::to_string(i) + " ";
        m.first += "] slots [";
        for (uint32_t i : run.slots[p]) m.first += std::to_string(i) + " ";
        m.first += "] bytes [";
        for (uint8_t b : texel) m.first += std::to_string(b) + " ";
        m.first += "]";
    };
    for (size_t p = 0; p < lists.size(); ++p) {
        for (int t = 0; t < targets; ++t) std::copy_n(&run.targets[size_t(t)][p * 4], 4, &texel[size_t(t) * 4]);
        const std::vector<uint8_t> expected = scheme.encodePixel(lists[p]);
        if (expected != texel) ++m.bytes, note(p, "bytes differ from the CPU blend/stencil model");
        if ((run.stencil[p] & countMask) != std::min<int>(int(lists[p].size()), countMax))
            ++m.counts, note(p, "stencil count differs from the list length");
        if (scheme.decodePixel(texel.data()) != run.slots[p]) ++m.unpack, note(p, "shader unpack differs from the CPU model");
        std::vector<uint32_t> nonNull;
        bool nullSeen = false, afterNull = false;
        for (uint32_t s : run.slots[p]) {
            if (s == 0) nullSeen = true;
            else {
                afterNull = afterNull || nullSeen;
                nonNull.push_back(s);
            }
        }
        std::sort(nonNull.begin(), nonNull.end());
        if (nonNull != scheme.keptLights(lists[p])) ++m.kept, note(p, "kept lights differ from the truth");
        if (scheme.nullEndsList() && afterNull) ++m.order, note(p, "a light after a null slot (LIDR_NULL_ENDS_LIST)");
    }
    return m;
}

void runAndCheck(const PackingScheme& scheme, VolumeTest test, const Lists& lists, const char* what,
                 bool bitByBitBytes = false) {
    const auto t0 = std::chrono::steady_clock::now();
    const UnpackRun run = runLists(scheme, test, lists, bitByBitBytes);
    const Mismatches m = checkRun(scheme, test, lists, run);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (std::getenv("LIDR_TEST_TIMING"))
        std::fprintf(stderr, "%s, %s, %s: %zu lists, %.2f s\n", scheme.describe().c_str(), volumeTestName(test), what,
                     lists.size(), s);
    INFO(scheme.describe() << ", " << volumeTestName(test) << ", " << what << ": " << lists.size() << " lists, " << s
                           << " s; " << m.first);
    CHECK(m.bytes == 0);
    CHECK(m.counts == 0);
    CHECK(m.unpack == 0);
    CHECK(m.kept == 0);
    CHECK(m.order == 0);
}

// Distinct fillers around a chosen value.
uint32_t filler(uint32_t maxIndex, uint32_t seed, uint32_t avoid) {
    uint32_t f = 1 + seed % maxIndex;
    return f == avoid ? 1 + f % maxIndex : f;
}

// Every index value in every slot (16-bit: every value of each byte with the other byte 0, 1, 0x55, 0xFF, when
// not `everyValue`), the other slots filled with distinct lights; plus the empty list.
Lists everyIndexInEverySlot(const PackingScheme& s, bool everyValue) {
    const uint32_t maxIndex = s.maxLights();
    std::vector<uint32_t> values;
    if (maxIndex <= 255 || everyValue) {
        for (uint32_t v = 1; v <= maxIndex; ++v) values.push_back(v);
    } else {
        std::set<uint32_t> v;
        for (uint32_t b = 0; b < 256; ++b)
            for (uint32_t other : {0u, 1u, 0x55u, 0xFFu}) {
                v.insert(b | (other << 8));
                v.insert(other | (b << 8));
            }
        v.erase(0u);
        values.assign(v.begin(), v.end());
    }
    const int budget = std::min<int>(s.config().budget, int(maxIndex));  // a 4-bit width has 15 lights
    Lists lists{{}};
    for (int slot = 0; slot < budget; ++slot)
        for (uint32_t v : values) {
            std::vector<uint32_t> l;
            std::set<uint32_t> used{v};
            for (int k = 0; k < budget; ++k) {
                if (k == slot) {
                    l.push_back(v);
                    continue;
                }
                uint32_t f = filler(maxIndex, v * 7919u + uint32_t(k) * 104729u, v);
                while (used.count(f)) f = 1 + f % maxIndex;
                used.insert(f);
                l.push_back(f);
            }
            lists.push_back(l);
        }
    return lists;
}

// everyIndexInEverySlot(s, false), every fifth list of it on softpipe (it interprets every fragment) where it
// has more than 4096.
Lists everyIndexInEverySlotThinned(const PackingScheme& s) {
    Lists lists = everyIndexInEverySlot(s, false);
    if (!isSoftpipe() || lists.size() <= 4096) return lists;
    Lists thin;
    for (size_t i = 0; i < lists.size(); i += 5) thin.push_back(lists[i]);
    return thin;
}

// Every ordered pair of distinct indices from `values`, and every single index.
Lists everyPair(const std::vector<uint32_t>& values) {
    Lists lists{{}};
    for (uint32_t a : values) {
        lists.push_back({a});
        for (uint32_t b : values)
            if (a != b) lists.push_back({a, b});
    }
    return lists;
}

std::vector<uint32_t> range(uint32_t first, uint32_t last) {
    std::vector<uint32_t> v(last - first + 1);
    std::iota(v.begin(), v.end(), first);
    return v;
}

// Every order of n distinct lights (n <= 8).
Lists everyOrder(const PackingScheme& s, int n) {
    std::vector<uint32_t> l;
    for (int i = 0; i < n; ++i) l.push_back(1 + (uint32_t(i) * 97u + 3u) % s.maxLights());
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
    Lists lists;
    do lists.push_back(l);
    while (std::next_permutation(l.begin(), l.end()));
    return lists;
}

Lists randomLists(const PackingScheme& s, size_t count, int maxLength, uint32_t seed) {
    std::mt19937 rng(seed);
    const uint32_t maxIndex = s.maxLights();
    std::uniform_int_distribution<int> length(0, std::min<int>(maxLength, int(maxIndex)));
    std::uniform_int_distribution<uint32_t> index(1, maxIndex);
    Lists lists(count);
    for (auto& l : lists) {
        const int n = length(rng);
        while (int(l.size()) < n) {
            const uint32_t i = index(rng);
            if (std::find(l.begin(), l.end(), i) == l.end()) l.push_back(i);
        }
    }
    return lists;
}

}  // namespace

TEST_CASE("shader unpack: every index in every slot, every pair, every order; all schemes, budgets, widths",
          "[unpack][gpu][every-gl]") {
    const bool soft = isSoftpipe();
    const ConfigCase c = GENERATE(from_range(packingCases()));
    // Representative: each scheme at budget 4, 8-bit, and bit-shift's widest (budget 16, 16-bit: two targets).
    if (!takeRow((c.packing.budget == 4 && c.packing.indexBits == 8) ||
                 (c.packing.budget == 16 && c.packing.indexBits == 16 && c.packing.scheme == PackingSchemeKind::BitShift)))
        return;
    DYNAMIC_SECTION(c.name) {
        const int bits = c.packing.indexBits, budget = c.packing.budget;
        const auto scheme = createPackingScheme(c.packing, testGl());
        runAndCheck(*scheme, VolumeTest::BackFace, everyIndexInEverySlotThinned(*scheme), "every index in every slot");
        const uint32_t pairMax = std::min<uint32_t>(scheme->maxLights(), soft ? 40u : 255u);
        std::vector<uint32_t> pairValues = range(1, pairMax);
        if (bits == 16)  // high bytes too
            for (uint32_t v : {256u, 257u, 511u, 0x1234u, 0x8000u, 0xFF00u, 0xFFFEu, 0xFFFFu}) pairValues.push_back(v);
        runAndCheck(*scheme, VolumeTest::BackFace, everyPair(pairValues), "every pair");
        runAndCheck(*scheme, VolumeTest::ExactStencil, everyPair(range(1, std::min<uint32_t>(scheme->maxLights(), 24))),
                    "every pair (exact test)");
        const int orderOf = std::min(budget + 1, soft ? 5 : 7);  // one past the budget: overflow too
        runAndCheck(*scheme, VolumeTest::BackFace, everyOrder(*scheme, std::min<int>(orderOf, int(scheme->maxLights()))),
                    "every order");
        // Overflowing lists through the exact test's stencil bookkeeping.
        runAndCheck(*scheme, VolumeTest::ExactStencil, randomLists(*scheme, soft ? 500 : 4000, budget + 4, 7u + budget),
                    "random overflowing lists (exact test)");
    }
}

// The byte decode of mediump (ES without fragment highp: LIDR_FRAGMENT_FP16) has no GPU here that computes fp16
// (llvmpipe has highp; SwiftShader computes mediump in fp32, doc/web.md), so its fp16 exactness is the CPU
// model's proof ([precision]). This runs that branch's GLSL through the driver's compiler and the real unpack
// shaders, in the driver's own precision: every byte value in every channel of every target, decoded exactly.
TEST_CASE("shader unpack with the mediump byte decode (LIDR_FRAGMENT_FP16): every index in every slot; all "
          "schemes, budgets, widths", "[unpack][gpu][every-gl]") {
    const ConfigCase c = GENERATE(from_range(packingCases()));
    if (!takeRow(c.packing.budget == 4 && c.packing.indexBits == 8)) return;  // representative: each scheme once
    DYNAMIC_SECTION(c.name) {
        const auto scheme = createPackingScheme(c.packing, testGl());
        runAndCheck(*scheme, VolumeTest::BackFace, everyIndexInEverySlotThinned(*scheme),
                    "every index in every slot, bit-by-bit bytes", true);
    }
}

TEST_CASE("shader unpack: every 16-bit index in every slot", "[unpack][gpu][slow]") {
    const ConfigCase c = GENERATE(from_range(packingCases(kBudgets, {16})));
    DYNAMIC_SECTION(c.name) {
        const auto scheme = createPackingScheme(c.packing, testGl());
        Lists lists = everyIndexInEverySlot(*scheme, true);
        runAndCheck(*scheme, VolumeTest::BackFace, lists, "every 16-bit index in every slot");
    }
}

TEST_CASE("shader unpack: every order of 8 lights", "[unpack][gpu][slow]") {
    const ConfigCase c = GENERATE(from_range(packingCases({4, 8, 16})));
    DYNAMIC_SECTION(c.name) {
        const auto scheme = createPackingScheme(c.packing, testGl());
        runAndCheck(*scheme, VolumeTest::BackFace, everyOrder(*scheme, 8), "every order of 8");
    }
}

TEST_CASE("shader unpack: a million seeded random lists per deep configuration, overflowing ones included",
          "[unpack][gpu][slow]") {
    const ConfigCase c = GENERATE(from_range(packingCasesFor({{8, 8}, {8, 16}, {16, 16}, {4, 16}})));  // (width, budget)
    DYNAMIC_SECTION(c.name) {
        const int bits = c.packing.indexBits, budget = c.packing.budget;
        const auto scheme = createPackingScheme(c.packing, testGl());
        runAndCheck(*scheme, VolumeTest::BackFace,
                    randomLists(*scheme, 1u << 20, budget + 4, 1000u + uint32_t(bits * 31 + budget)),
                    "1,048,576 random lists, lengths 0..budget+4");
    }
}

TEST_CASE("shader unpack: bit-shift budget 32 (four rank windows, the automatic budget's widest) at 4- and 8-bit "
          "indices: every index in every slot, random lists up to 36 lights", "[unpack][gpu][every-gl]") {
    const ConfigCase c = GENERATE(from_range(packingCasesFor({{4, 32}, {8, 32}}, {PackingSchemeKind::BitShift})));
    DYNAMIC_SECTION(c.name) {
        std::unique_ptr<PackingScheme> scheme;
        try {
            scheme = createPackingScheme(c.packing, testGl());
        } catch (const UnsupportedError& e) {  // OpenGL ES 2.0 without enough draw buffers
            WARN("skipped: " << e.what());
            return;
        }
        REQUIRE(scheme->geometryPasses() == 4);
        runAndCheck(*scheme, VolumeTest::BackFace, everyIndexInEverySlotThinned(*scheme), "every index in every slot");
        // Lists past 16 read the third and fourth windows; past 32 they overflow (kept: the first 32 drawn).
        runAndCheck(*scheme, VolumeTest::BackFace, randomLists(*scheme, isSoftpipe() ? 300 : 4000, 36, 32u + uint32_t(c.packing.indexBits)),
                    "random lists, lengths 0..36");
    }
}
