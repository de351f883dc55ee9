// Colour handled as colour (issue 26, part 1): the output transform's CPU model, every mode's encoded pixels
// against that model, sRGB base-colour textures decoded to linear (in the texture unit on desktop GL, in the
// shader on OpenGL ES 2.0), and multi-pass forward's encode pass over its linear sum.
#include <algorithm>
#include <cmath>
#include <memory>

#include <catch2/catch.hpp>

#include "gl_test_context.h"
#include "lidr/base/error.h"
#include "lidr/eval/image_compare.h"
#include "lidr/gl/shader_source.h"
#include "lidr/modes/render_mode.h"
#include "lidr/render/depth_prepass.h"
#include "lidr/render/output_transform.h"
#include "lidr/render/shading_variants.h"
#include "render_helpers.h"

using namespace lidr;
using namespace lidr::test;

TEST_CASE("output transform model: sRGB curve, tone maps and names", "[cpu][colour]") {
    SECTION("sRGB encode and decode are inverse and hit the standard's points") {
        CHECK(linearToSrgb(0.0) == 0.0);
        CHECK(linearToSrgb(1.0) == Approx(1.0).epsilon(1e-12));
        CHECK(linearToSrgb(0.5) == Approx(0.735356983).epsilon(1e-8));
        CHECK(srgbToLinear(0.5) == Approx(0.214041140).epsilon(1e-8));
        CHECK(linearToSrgb(0.002) == Approx(0.02584));  // the linear toe, slope 12.92
        for (int i = 0; i <= 255; ++i) CHECK(linearToSrgb(srgbToLinear(i / 255.0)) == Approx(i / 255.0).margin(1e-12));
    }
    SECTION("PBR Neutral leaves moderate colours nearly as they are and rolls highlights off below 1") {
        const glm::dvec3 mid = toneMapped(glm::dvec3(0.5, 0.3, 0.2), ToneMap::PbrNeutral);
        CHECK(mid.r == Approx(0.5 - 0.04));  // min channel >= 0.08: a constant 0.04 black-level offset
        CHECK(mid.g == Approx(0.3 - 0.04));
        CHECK(toneMapped(glm::dvec3(0.0), ToneMap::PbrNeutral).r == 0.0);
        double previous = 0.0;
        for (double x = 0.5; x < 1000.0; x *= 1.5) {  // monotonic, below 1
            const double y = toneMapped(glm::dvec3(x), ToneMap::PbrNeutral).r;
            CHECK(y > previous);
            CHECK(y < 1.0);
            previous = y;
        }
    }
    SECTION("ACES fitted maps 0 near 0 and grows towards 1") {
        CHECK(std::abs(toneMapped(glm::dvec3(0.0), ToneMap::AcesFitted).g) < 1e-3);
        CHECK(toneMapped(glm::dvec3(100.0), ToneMap::AcesFitted).g == Approx(1.0).margin(0.03));
    }
    SECTION("exposure is in stops") {
        OutputTransform o = OutputTransform::linear();
        o.exposureStops = 2.0f;
        CHECK(applyOutputTransform(glm::dvec3(0.1), o).r == Approx(0.4));
        CHECK(applyOutputTransform(glm::dvec3(0.5), o).r == 1.0);  // clamped
    }
    SECTION("names") {
        for (ToneMap t : {ToneMap::None, ToneMap::PbrNeutral, ToneMap::AcesFitted})
            CHECK(parseToneMap(toneMapName(t), "--tone-map") == t);
        REQUIRE_THROWS_WITH(parseToneMap("reinhard", "--tone-map"),
                            Catch::Contains("--tone-map") && Catch::Contains("'reinhard'") && Catch::Contains("pbr-neutral"));
    }
}

namespace {

// floorScene with every material unlit and emitting `emissive` (linear): no lights, no ambient, so every surface
// pixel is the output transform of `emissive` alone.
Scene emissiveScene(const glm::vec3& emissive) {
    Scene scene = floorScene();
    for (Material& m : scene.materials) m.diffuse = glm::vec3(0.0f), m.specular = glm::vec3(0.0f), m.emissive = emissive;
    scene.ambient = glm::vec3(0.0f);
    return scene;
}

// "forward-multipass 8-bit": multi-pass summing in its 8-bit target (MultipassOptions::halfFloatAccumulation
// false); "forward-multipass" sums in half float where the context renders to it.
std::vector<std::string> modesOnThisContext() {
    // tiled's default depth bounds are refused on ES 2.0 (doc/contexts.md); auto needs occlusion queries
    if (testGl().gles) return {"lidr", "clustered", "forward-multipass", "forward-multipass 8-bit", "forward-brute"};
    return {"lidr", "tiled", "clustered", "forward-multipass", "forward-multipass 8-bit", "forward-brute"};
}

RenderModeOptions modeOptions(const std::string& mode) {
    RenderModeOptions o;
    o.mode = mode == "forward-multipass 8-bit" ? "forward-multipass" : mode;
    o.multipass.halfFloatAccumulation = mode != "forward-multipass 8-bit";
    return o;
}

// Whether `r` summed its light in an 8-bit target before the output transform (multi-pass without half float).
bool sumsInEightBits(const Renderer& r) {
    const auto* multipass = dynamic_cast<const MultipassForwardRenderer*>(&r);
    return multipass && std::string(multipass->accumulation()) == "8-bit";
}

// Pixels of `image` whose RGB is not the background (0): their count, and the largest distance from `expected`.
struct SurfaceCheck {
    long pixels = 0;
    int maxError = 0;
};
SurfaceCheck checkSurface(const ImageRGBA8& image, const glm::ivec3& expected) {
    SurfaceCheck c;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const uint8_t* p = image.at(x, y);
            if (p[0] == 0 && p[1] == 0 && p[2] == 0) continue;
            ++c.pixels;
            for (int k = 0; k < 3; ++k) c.maxError = std::max(c.maxError, std::abs(int(p[k]) - expected[k]));
        }
    return c;
}

glm::ivec3 expectedPixel(const glm::dvec3& linear, const OutputTransform& output) {
    const glm::dvec3 encoded = applyOutputTransform(linear, output);
    return glm::ivec3(std::lround(encoded.r * 255.0), std::lround(encoded.g * 255.0), std::lround(encoded.b * 255.0));
}

}  // namespace

TEST_CASE("every mode writes the output transform of its linear light (CPU model, 1 step)", "[colour][every-gl]") {
    testContext();
    struct Case {
        const char* name;
        glm::vec3 emissive;
        OutputTransform output;
    };
    const Case cases[] = {
        {"sRGB only, mid grey-blue", {0.2f, 0.35f, 0.6f}, {ToneMap::None, 0.0f, true}},
        {"sRGB toe (dark)", {0.002f, 0.01f, 0.03f}, {ToneMap::None, 0.0f, true}},
        {"PBR Neutral, moderate", {0.2f, 0.35f, 0.6f}, {ToneMap::PbrNeutral, 0.0f, true}},
        {"PBR Neutral, over 1", {3.0f, 1.5f, 0.4f}, {ToneMap::PbrNeutral, 0.0f, true}},
        {"ACES, over 1, -1 stop", {3.0f, 1.5f, 0.4f}, {ToneMap::AcesFitted, -1.0f, true}},
        {"PBR Neutral, +2 stops", {0.1f, 0.05f, 0.2f}, {ToneMap::PbrNeutral, 2.0f, true}},
        {"linear", {0.2f, 0.35f, 0.6f}, OutputTransform::linear()},
    };
    const auto c = GENERATE_COPY(range(size_t(0), sizeof cases / sizeof cases[0]));
    const std::string mode = GENERATE_COPY(from_range(modesOnThisContext()));
    // Representative: each tone map once, each in another mode.
    if (!takeRow((mode == "lidr" && c == 2) || (mode == "tiled" && c == 4) || (mode == "forward-multipass" && c == 3) ||
                 (mode == "forward-brute" && c == 6) || (mode == "clustered" && c == 1)))
        return;
    DYNAMIC_SECTION(mode << ": " << cases[c].name) {
        const Scene scene = emissiveScene(cases[c].emissive);
        ShadingParameters shading{scene.ambient, scene.backgroundColor};
        shading.output = cases[c].output;
        std::unique_ptr<Renderer> r = createRenderer(modeOptions(mode), testGl(), scene, scene.width, scene.height);
        r->render(scene.camera, {}, shading);
        // Multi-pass forward without half float sums in its 8-bit linear target first (clamped, rounded), then
        // encodes: light above 1 is lost before the tone map (doc/colour.md); in half float, and in the other
        // modes, the transform runs over the float sum.
        glm::dvec3 linear(cases[c].emissive);
        if (sumsInEightBits(*r))
            for (int k = 0; k < 3; ++k) linear[k] = std::round(std::clamp(linear[k], 0.0, 1.0) * 255.0) / 255.0;
        const glm::ivec3 expected = expectedPixel(linear, cases[c].output);
        const SurfaceCheck s = checkSurface(r->targets().readColor(), expected);
        INFO("expected " << expected.r << " " << expected.g << " " << expected.b
                         << (sumsInEightBits(*r) ? " (summed in 8 bits)" : ""));
        if (mode == "forward-multipass") REQUIRE(sumsInEightBits(*r) == !testGl().halfFloatColorBuffer);
        REQUIRE(s.pixels > long(scene.width) * scene.height / 2);  // the floor fills most of the view
        REQUIRE(s.maxError <= 1);
    }
}

TEST_CASE("sRGB base-colour textures are decoded to linear before lighting", "[colour][every-gl]") {
    testContext();
    // One texel value over the whole texture, so filtering and mip levels cannot change it. A white base colour
    // times that texture must shade like an untextured base colour of the texel's decoded (linear) value, and
    // unlike one of its raw value (0.5 -> 188 instead of 128 after the encoding).
    const uint8_t texel = GENERATE(as<int>{}, 30, 128, 200);
    if (!takeRow(texel == 128)) return;
    DYNAMIC_SECTION("texel " << int(texel)) {
        Scene textured = floorScene();
        textured.lights = {light({0.0f, 3.0f, 0.0f}, 12.0f, glm::vec3(0.8f))};
        textured.ambient = glm::vec3(0.3f);
        Scene decoded = textured, raw = textured;
        auto image = std::make_shared<ImageRGBA8>(8, 8);
        for (size_t i = 0; i < image->pixels.size(); i += 4)
            image->pixels[i] = image->pixels[i + 1] = image->pixels[i + 2] = texel, image->pixels[i + 3] = 255;
        for (size_t i = 0; i < textured.materials.size(); ++i) {
            textured.materials[i].diffuse = glm::vec3(1.0f);
            textured.materials[i].diffuseTexture = "uniform.png";
            textured.materials[i].diffuseImage = image;
            decoded.materials[i].diffuse = glm::vec3(float(srgbToLinear(texel / 255.0)));
            raw.materials[i].diffuse = glm::vec3(texel / 255.0f);
        }
        const ShadingParameters shading{textured.ambient, textured.backgroundColor, {ToneMap::None, 0.0f, true}};
        const auto render = [&](const Scene& scene, const std::string& mode) {
            RenderModeOptions o;
            o.mode = mode;
            std::unique_ptr<Renderer> r = createRenderer(o, testGl(), scene, scene.width, scene.height);
            r->render(scene.camera, scene.lights, shading);
            return r->targets().readColor();
        };
        for (const std::string& mode : {std::string("forward-brute"), std::string("lidr")}) {
            const ImageRGBA8 a = render(textured, mode), b = render(decoded, mode), c = render(raw, mode);
            const ImageError same = compareImages(a, b), undecoded = compareImages(a, c);
            INFO(mode << (testGl().gles ? " (ES: decoded in the shader)" : " (SRGB8_ALPHA8 texture)") << ": against the "
                      << "decoded colour max " << same.maxAbsError << ", against the raw colour max " << undecoded.maxAbsError);
            REQUIRE(same.maxAbsError <= 1);
            REQUIRE(undecoded.maxAbsError >= 10);  // the test tells decoding from not decoding
        }
    }
}

TEST_CASE("multi-pass forward encodes its finished linear sum: the encoded image is the model of the linear one",
          "[colour][forward][every-gl]") {
    // The 8-bit path, where the linear image read back is the sum the encode pass reads; the half-float path's
    // sum is not readable as 8 bits: it is held to the reference below.
    testContext();
    Scene scene = floorScene();
    scene.lights = {light({0.0f, 1.0f, 0.0f}, 6.0f, {1.0f, 0.8f, 0.6f}), light({3.0f, 0.5f, 2.0f}, 4.0f, {0.3f, 0.5f, 1.0f}),
                    light({-3.0f, 2.0f, -1.0f}, 5.0f, {2.0f, 1.0f, 0.5f})};
    const OutputTransform output = GENERATE(OutputTransform{ToneMap::PbrNeutral, 0.0f, true},
                                            OutputTransform{ToneMap::AcesFitted, 1.0f, true});
    DYNAMIC_SECTION(toneMapName(output.toneMap) << ", " << output.exposureStops << " stops") {
        std::unique_ptr<Renderer> r =
            createRenderer(modeOptions("forward-multipass 8-bit"), testGl(), scene, scene.width, scene.height);
        ShadingParameters shading{scene.ambient, scene.backgroundColor};
        shading.output = OutputTransform::linear();
        r->render(scene.camera, scene.lights, shading);
        const ImageRGBA8 linear = r->targets().readColor();
        shading.output = output;
        r->render(scene.camera, scene.lights, shading);
        const ImageRGBA8 encoded = r->targets().readColor();
        ImageRGBA8 model(linear.width, linear.height);
        for (size_t p = 0; p < linear.pixels.size(); p += 4) {
            const glm::dvec3 l(linear.pixels[p] / 255.0, linear.pixels[p + 1] / 255.0, linear.pixels[p + 2] / 255.0);
            const glm::dvec3 e = applyOutputTransform(l, output);
            for (int k = 0; k < 3; ++k) model.pixels[p + size_t(k)] = uint8_t(std::lround(e[k] * 255.0));
            model.pixels[p + 3] = 255;
        }
        const ImageError e = compareImages(encoded, model);
        INFO("max " << e.maxAbsError << ", differing " << e.differingPixels);
        REQUIRE(e.maxAbsError <= 1);
        // and the encoding really changed the image (lit pixels brighter than their linear values)
        REQUIRE(compareImages(encoded, linear).differingPixels > long(scene.width) * scene.height / 4);
        // In half float the encode pass transforms the float sum: the reference's image within 1 step.
        std::unique_ptr<Renderer> half = createRenderer(modeOptions("forward-multipass"), testGl(), scene, scene.width,
                                                        scene.height);
        std::unique_ptr<Renderer> reference = createRenderer(modeOptions("forward-brute"), testGl(), scene, scene.width,
                                                             scene.height);
        half->render(scene.camera, scene.lights, shading);
        reference->render(scene.camera, scene.lights, shading);
        const ImageError h = compareImages(half->targets().readColor(), reference->targets().readColor());
        INFO((sumsInEightBits(*half) ? "8-bit (no half-float colour buffers)" : "half float") << ": max "
                                                                                            << h.maxAbsError);
        if (!sumsInEightBits(*half)) REQUIRE(h.maxAbsError <= 1);
    }
}

TEST_CASE("shading variants: the frame's suns, tone map and encoding are compiled in; depth passes get none", "[colour][every-gl]") {
    // A uniform branch or a uniform-bounded loop costs its body on a SIMD rasteriser even when not taken
    // (doc/benchmarks.md), so every shading program is drawn as the variant of its frame's features.
    testContext();
    auto program = [](const char* fragment, const char* vertex) {
        return gl::Program::create(fragment, buildShaderSource(vertex), buildShaderSource(fragment), geometryAttributes());
    };
    // Multi-pass forward's first pass: the suns, no output transform (its encode pass runs over the sum).
    const gl::Program suns = program("forward_ambient.frag", "geometry.vert");
    const gl::Program encode = program("output_encode.frag", "present.vert");  // the output transform alone
    const gl::Program depth = program("depth_only.frag", "geometry.vert");  // includes it for MASK variants only
    const OutputTransform srgbAces{ToneMap::AcesFitted, 0.0f, true};
    CHECK(shadingVariantKey(depth, 2, srgbAces) == 0);
    CHECK(shadingVariantDefines(0).empty());
    std::vector<uint32_t> keys;
    for (size_t count = 0; count <= 4; ++count)
        for (const OutputTransform& output : {OutputTransform::linear(), OutputTransform{}, srgbAces}) {
            for (const gl::Program* p : {&suns, &encode}) {
                const uint32_t key = shadingVariantKey(*p, count, output);
                CHECK(key != 0);
                CHECK((key & 0xffffu) == 0);  // above the material bits (material_variants.h)
                const ShaderDefines defines = shadingVariantDefines(key);
                auto value = [&](const char* name) {
                    for (const auto& [k, v] : defines)
                        if (k == name) return v;
                    return std::string("(none)");
                };
                const bool lit = p == &suns;
                CHECK(value("LIDR_DIRECTIONAL_LIGHTS") == (lit ? std::to_string(count) : "(none)"));
                CHECK(value("LIDR_TONE_MAP") == (lit ? "(none)" : std::to_string(int(output.toneMap))));
                CHECK(value("LIDR_SRGB_OUTPUT") == (lit ? "(none)" : output.srgb ? "1" : "0"));
                CHECK(p->variant(key, defines).id() != 0);  // compiles
                keys.push_back(key);
            }
        }
    std::sort(keys.begin(), keys.end());
    // Every combination its own program: 5 counts for the suns, 3 transforms for the encode pass.
    CHECK(std::unique(keys.begin(), keys.end()) - keys.begin() == 5 + 3);
}
