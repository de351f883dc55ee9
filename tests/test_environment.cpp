// Image-based environment light (issue 39): the CPU side (lidr/scene/environment.h: the cube's geometry, the
// spherical harmonics, the split-sum table, the GGX prefilter, the equirectangular conversion, the storage) and,
// below, every mode against the reference and the CPU model with an environment on.
#include <algorithm>
#include <cmath>

#include <catch2/catch.hpp>

#include "lidr/eval/brdf.h"
#include "lidr/scene/environment.h"

using namespace lidr;

namespace {
constexpr double kPi = 3.14159265358979323846;

// A cube whose every texel is f(texel centre direction).
template <typename F>
CubeImage cubeOf(int size, const F& f) {
    CubeImage cube(size);
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x)
                cube.at(face, x, y) = glm::vec3(f(cubeDirection(face, (x + 0.5) / size, (y + 0.5) / size)));
    return cube;
}
}  // namespace

TEST_CASE("environment cube: GL's face table, texel solid angles", "[cpu][environment]") {
    // GL's major-axis table: each face's centre looks along its axis, and s, t run as the specification says.
    const glm::dvec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int f = 0; f < 6; ++f) CHECK(glm::distance(cubeDirection(f, 0.5, 0.5), axes[f]) < 1e-12);
    CHECK(glm::distance(cubeDirection(0, 1.0, 0.5), glm::normalize(glm::dvec3(1, 0, -1))) < 1e-12);  // +X: s along -z
    CHECK(glm::distance(cubeDirection(0, 0.5, 1.0), glm::normalize(glm::dvec3(1, -1, 0))) < 1e-12);  // t along -y
    CHECK(glm::distance(cubeDirection(2, 0.5, 1.0), glm::normalize(glm::dvec3(0, 1, 1))) < 1e-12);   // +Y: t along +z
    CHECK(glm::distance(cubeDirection(5, 1.0, 0.5), glm::normalize(glm::dvec3(-1, 0, -1))) < 1e-12); // -Z: s along -x
    for (int f = 0; f < 6; ++f)
        for (double s : {0.1, 0.37, 0.5, 0.93})
            for (double t : {0.05, 0.5, 0.71}) {
                int face;
                double s2, t2;
                cubeFaceCoordinates(cubeDirection(f, s, t), face, s2, t2);
                CHECK(face == f);
                CHECK(s2 == Approx(s).margin(1e-12));
                CHECK(t2 == Approx(t).margin(1e-12));
            }
    for (int size : {1, 8, 32}) {
        double sum = 0.0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) sum += cubeTexelSolidAngle(size, x, y);
        CHECK(6.0 * sum == Approx(4.0 * kPi).epsilon(1e-12));
    }
}

TEST_CASE("environment spherical harmonics: the irradiance of known radiance", "[cpu][environment]") {
    SECTION("constant radiance L: E / pi = L in every direction") {
        const CubeImage cube = cubeOf(16, [](const glm::dvec3&) { return glm::dvec3(0.7, 1.5, 3.0); });
        const auto sh = irradianceSh(cube);
        for (const glm::dvec3& n : {glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(1, -2, 0.5)), glm::dvec3(0, 0, -1)}) {
            const glm::dvec3 e = irradianceOverPi(sh, n);
            CHECK(e.r == Approx(0.7).epsilon(1e-6));
            CHECK(e.b == Approx(3.0).epsilon(1e-6));
        }
    }
    SECTION("linear radiance 1 + d.y: E / pi = 1 + (2/3) n.y (the clamped cosine's first band)") {
        const CubeImage cube = cubeOf(32, [](const glm::dvec3& d) { return glm::dvec3(1.0 + d.y); });
        const auto sh = irradianceSh(cube);
        for (const glm::dvec3& n : {glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0), glm::normalize(glm::dvec3(1, 1, 1))})
            CHECK(irradianceOverPi(sh, n).g == Approx(1.0 + 2.0 / 3.0 * n.y).margin(1e-3));
    }
    SECTION("a quadratic lobe max(0, d.x)^2 against quadrature of its irradiance") {
        // Band-limited to l <= 2 the irradiance is within 2 % of the exact convolution for a smooth lobe.
        auto radiance = [](const glm::dvec3& d) { return glm::dvec3(std::pow(std::max(0.0, d.x), 2.0)); };
        const auto sh = irradianceSh(cubeOf(32, radiance));
        for (const glm::dvec3& n : {glm::dvec3(1, 0, 0), glm::normalize(glm::dvec3(1, 1, 0)), glm::dvec3(0, 1, 0)}) {
            double exact = 0.0;  // E / pi = (1 / pi) x integral of L max(0, n.l) over the sphere
            const CubeImage fine = cubeOf(64, radiance);
            for (int f = 0; f < 6; ++f)
                for (int y = 0; y < 64; ++y)
                    for (int x = 0; x < 64; ++x) {
                        const glm::dvec3 d = cubeDirection(f, (x + 0.5) / 64, (y + 0.5) / 64);
                        exact += double(fine.at(f, x, y).r) * std::max(0.0, glm::dot(n, d)) * cubeTexelSolidAngle(64, x, y);
                    }
            exact /= kPi;
            INFO("n " << n.x << " " << n.y << " " << n.z);
            CHECK(irradianceOverPi(sh, n).r == Approx(exact).margin(0.02 * 0.25 + 0.01 * exact));
        }
    }
}

TEST_CASE("environment split-sum table: known values and the BRDF's own quadrature", "[cpu][environment]") {
    const SplitSumTable& table = splitSumTable();
    REQUIRE(table.size == kSplitSumSize);
    // A mirror seen head-on reflects F0: A = 1, B = 0.
    CHECK(table.at(kSplitSumSize - 1, 0).x == Approx(1.0).margin(2e-3));
    CHECK(table.at(kSplitSumSize - 1, 0).y == Approx(0.0).margin(1e-3));
    // F0 A + B is the specular integral: with F0 = 1 (a white metal) the directional albedo of the BRDF, with F0 = 0
    // (a black, specular-only surface) B alone. The CPU model's quadrature (lidr/eval/brdf.h) is independent of
    // the table's importance sampling.
    for (double roughness : {0.25, 0.5, 1.0})
        for (double nDotV : {1.0, 0.5, 0.2}) {
            const int i = int(std::lround(nDotV * (kSplitSumSize - 1))), j = int(std::lround(roughness * (kSplitSumSize - 1)));
            const double nv = double(i) / (kSplitSumSize - 1), r = double(j) / (kSplitSumSize - 1);
            BrdfSurface s;
            s.metallic = 1.0;
            s.roughness = r;
            s.toEye = glm::dvec3(std::sqrt(1.0 - nv * nv), nv, 0.0);
            s.baseColor = glm::dvec3(1.0);
            const double white = directionalAlbedo(s, 384).g;
            s.baseColor = glm::dvec3(0.0);
            const double black = directionalAlbedo(s, 384).g;
            const glm::dvec2 ab = table.at(i, j);
            INFO("n.v " << nv << ", roughness " << r << ": table A " << ab.x << " B " << ab.y << ", quadrature "
                        << white << " / " << black);
            CHECK(ab.x + ab.y == Approx(white).margin(0.01));
            CHECK(ab.y == Approx(black).margin(0.005));
        }
}

TEST_CASE("environment prefilter: a constant environment stays constant at every roughness", "[cpu][environment]") {
    const CubeImage constant = cubeOf(32, [](const glm::dvec3&) { return glm::dvec3(0.25, 0.5, 2.0); });
    const Environment env = prefilterEnvironment(constant, "constant", 4, 64);
    REQUIRE(env.levels() == 4);
    for (int level = 0; level < env.levels(); ++level) {
        CHECK(env.specular[size_t(level)].size == 32 >> level);
        for (const glm::vec3& t : env.specular[size_t(level)].texels) {
            CHECK(t.r == Approx(0.25f).epsilon(1e-5));
            CHECK(t.b == Approx(2.0f).epsilon(1e-5));
        }
    }
    CHECK(env.maxRadiance == 2.0f);
    // A one-sided environment (bright above, dark below): the mirror level keeps the edge, roughness spreads it,
    // the mean radiance seen by the rough levels falls between, and nothing rises above the brightest texel.
    const CubeImage half = cubeOf(32, [](const glm::dvec3& d) { return glm::dvec3(d.y > 0.0 ? 1.0 : 0.0); });
    const Environment blurred = prefilterEnvironment(half, "half", 4, 64);
    const glm::dvec3 sideways = glm::normalize(glm::dvec3(1.0, 0.05, 0.0));
    const double mirror = sampleCubeBilinear(blurred.specular[0], sideways).r;
    const double rough = sampleCubeBilinear(blurred.specular[3], sideways).r;
    CHECK(mirror == Approx(1.0).margin(1e-6));
    CHECK(rough > 0.4);
    CHECK(rough < 0.8);
    for (const CubeImage& level : blurred.specular)
        for (const glm::vec3& t : level.texels) CHECK(t.r <= 1.0f + 1e-5f);
    // Bad input: a texel not finite, a size that cannot hold the levels.
    CubeImage bad = constant;
    bad.at(3, 4, 5).g = std::nanf("");
    CHECK_THROWS_WITH(prefilterEnvironment(bad, "bad.hdr", 4, 64), Catch::Contains("bad.hdr") && Catch::Contains("not finite"));
    bad.at(3, 4, 5).g = -1.0f;
    CHECK_THROWS_WITH(prefilterEnvironment(bad, "bad.hdr", 4, 64), Catch::Contains("negative"));
    CHECK_THROWS_WITH(prefilterEnvironment(cubeOf(4, [](const glm::dvec3&) { return glm::dvec3(1.0); }), "small", 4, 64),
                      Catch::Contains("cannot hold"));
}

TEST_CASE("environment equirectangular conversion: three.js's mapping, both ways", "[cpu][environment]") {
    // The mapping's landmarks: the top row looks up, the middle column along +x, a quarter to the right +z.
    CHECK(glm::distance(equirectDirection(0.5, 0.5), glm::dvec3(1, 0, 0)) < 1e-12);
    CHECK(glm::distance(equirectDirection(0.75, 0.5), glm::dvec3(0, 0, 1)) < 1e-12);
    CHECK(equirectDirection(0.3, 1.0).y == Approx(1.0));
    const glm::dvec2 uv = equirectCoordinates(glm::normalize(glm::dvec3(-0.3, 0.4, -0.8)));
    CHECK(glm::distance(equirectDirection(uv.x, uv.y), glm::normalize(glm::dvec3(-0.3, 0.4, -0.8))) < 1e-12);
    // A smooth panorama f(direction) becomes a cube holding f at its texels (bilinear error of a smooth function).
    auto f = [](const glm::dvec3& d) { return glm::dvec3(1.0 + d.x, 1.0 + d.y, 1.0 + 0.5 * d.z); };
    ImageRGBFloat pano(256, 128);
    for (int y = 0; y < pano.height; ++y)
        for (int x = 0; x < pano.width; ++x)
            pano.at(x, y) = glm::vec3(f(equirectDirection((x + 0.5) / pano.width, 1.0 - (y + 0.5) / pano.height)));
    const CubeImage cube = cubeFromEquirect(pano, 16);
    double worst = 0.0;
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                const glm::dvec3 d = cubeDirection(face, (x + 0.5) / 16, (y + 0.5) / 16);
                const glm::dvec3 e = glm::abs(glm::dvec3(cube.at(face, x, y)) - f(d));
                worst = std::max({worst, e.x, e.y, e.z});
            }
    INFO("worst texel error " << worst);
    CHECK(worst < 0.01);
    // ... and back: the panorama of that cube is the function again.
    const ImageRGBFloat back = equirectFromCube(cube, 64);
    REQUIRE(back.height == 32);
    double worstBack = 0.0;
    for (int y = 2; y < back.height - 2; ++y)
        for (int x = 0; x < back.width; ++x) {
            const glm::dvec3 d = equirectDirection((x + 0.5) / back.width, 1.0 - (y + 0.5) / back.height);
            const glm::dvec3 e = glm::abs(glm::dvec3(back.at(x, y)) - f(d));
            worstBack = std::max({worstBack, e.x, e.y, e.z});
        }
    CHECK(worstBack < 0.03);
}

TEST_CASE("environment storage: half floats, RGBM and the 16-bit table decode within their steps", "[cpu][environment]") {
    for (float v : {0.0f, 0.001f, 0.37f, 1.0f, 7.5f, 60.0f}) {
        const glm::u8vec4 c = encodeRgbm(glm::vec3(v, v * 0.5f, 0.01f), 64.0f);
        const glm::dvec3 d = decodeRgbm(glm::dvec4(c), 64.0);
        // m x range / 255 per step of the colour bytes, m >= the brightest channel over the range.
        const double step = double(c.w) / 255.0 * 64.0 / 255.0;
        CHECK(std::abs(d.r - v) <= 0.5 * step + 1e-9);
        CHECK(std::abs(d.b - 0.01) <= 0.5 * step + 1e-9);
    }
    CHECK(decodeRgbm(glm::dvec4(encodeRgbm(glm::vec3(500.0f), 64.0f)), 64.0).r == Approx(64.0));  // clipped at the range
    for (double a : {0.0, 0.1234567, 0.999})
        CHECK(decodeSplitSum16(glm::dvec4(encodeSplitSum16({a, 1.0 - a}))).x == Approx(a).margin(0.5 / 65535.0 + 1e-12));
    Environment env = prefilterEnvironment(makeRoomEnvironmentCube(16), "room", 3, 32);
    CHECK(rgbmRange(env) == 16.0f);  // the brightest panel is 12
    for (EnvironmentStorage storage : {EnvironmentStorage::HalfFloat, EnvironmentStorage::Rgbm8}) {
        const StoredEnvironment stored = storeEnvironment(env, storage);
        CHECK(stored.roughnessLevels == 3);
        REQUIRE(stored.levels.size() == 5);  // 16, 8, 4 and the padding 2, 1
        CHECK(stored.levels.back().size == 1);
        // At a texel centre the stored level decodes to the texel within its storage's step.
        const glm::dvec3 d = cubeDirection(2, 4.5 / 16, 9.5 / 16);
        const glm::dvec3 got = sampleStoredSpecular(stored, d, 0.0), want(env.specular[0].at(2, 4, 9));
        CHECK(glm::distance(got, want) < (storage == EnvironmentStorage::Rgbm8 ? 16.0 / 255.0 : 1e-2 * want.r + 1e-4));
        const glm::dvec2 ab = sampleStoredSplitSum(stored, 0.5, 0.5), exact = splitSumTable().at(16, 16);
        CHECK(glm::distance(ab, exact) < 0.02);  // between texel centres (n.v 15.5 / 31): linear in between
    }
}

// ------------------------------------------------------------------------------------------------------------
// GL: every mode with the environment on, against the reference and the CPU model.

#include <memory>

#include "gl_test_context.h"
#include "lidr/eval/image_compare.h"
#include "lidr/modes/render_mode.h"
#include "lidr/render/environment_maps.h"
#include "lidr/render/output_transform.h"
#include "lidr/scene/primitives.h"
#include "render_helpers.h"

using namespace lidr::test;

namespace {

// The metallic x roughness sweep of flat tiles (test_brdf.cpp's) in the default environment: metallic along x,
// roughness 0 to 1 along z, an orange-ish base colour; one light, no uniform ambient, so the environment is most of
// what the tiles show (their reflections sweep the room's walls, floor and panels).
Scene environmentSweep(int width, int height) {
    Scene scene;
    scene.name = "environment-sweep";
    for (int mi = 0; mi < 4; ++mi)
        for (int ri = 0; ri < 4; ++ri) {
            Material m;
            m.name = "m" + std::to_string(mi) + "r" + std::to_string(ri);
            m.metallicRoughness = true;
            m.diffuse = glm::vec3(0.9f, 0.6f, 0.3f);
            m.metallic = float(mi) / 3.0f;
            m.roughness = float(ri) / 3.0f;
            scene.materials.push_back(m);
            addPlane(scene, glm::vec3(-3.3f + 2.2f * float(mi), 0.0f, -3.3f + 2.2f * float(ri)), glm::vec2(2.0f),
                     int(scene.materials.size() - 1), 4);
        }
    scene.camera.position = glm::vec3(0.5f, 5.0f, 8.5f);
    scene.camera.target = glm::vec3(0.0f, 0.0f, 0.0f);
    scene.camera.fovYDegrees = 55.0f;
    scene.camera.nearPlane = 0.5f;
    scene.camera.farPlane = 40.0f;
    scene.width = width;
    scene.height = height;
    scene.ambient = glm::vec3(0.0f);
    scene.lights = {light({-1.0f, 2.5f, 1.0f}, 7.0f, {0.6f, 0.55f, 0.5f})};
    scene.environment = defaultEnvironment();
    return scene;
}

// floorScene with shiny and rough metals and dielectrics, in the default environment: curved surfaces (the
// sphere) and a box, for the image comparisons between modes.
Scene environmentFloor() {
    Scene scene = floorScene();
    const float metallic[] = {1.0f, 0.0f, 1.0f, 0.0f}, roughness[] = {0.15f, 0.4f, 0.6f, 0.9f};
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        Material& m = scene.materials[i];
        m.metallicRoughness = true;
        m.metallic = metallic[i % 4];
        m.roughness = roughness[i % 4];
    }
    scene.lights = {light({0.0f, 3.0f, 0.0f}, 9.0f, {0.8f, 0.7f, 0.6f}), light({3.0f, 1.0f, 2.0f}, 5.0f, {0.3f, 0.5f, 1.0f})};
    scene.ambient = glm::vec3(0.02f);
    scene.environment = defaultEnvironment();
    scene.environmentIntensity = 0.8f;
    return scene;
}

std::vector<std::string> environmentModes() {
    if (testGl().gles) return {"lidr", "forward-brute", "forward-multipass"};  // tiled's depth bounds: desktop only
    return {"lidr", "tiled", "forward-brute", "forward-multipass"};
}

ImageRGBA8 renderWith(const Scene& scene, const std::string& mode, const ShadingParameters& shading, bool fixedTable,
                      FrameStats* stats = nullptr) {
    RenderModeOptions o;
    o.mode = mode;
    o.forceFixedLightTable = fixedTable;
    std::unique_ptr<Renderer> r = createRenderer(o, testGl(), scene, scene.width, scene.height);
    r->render(scene.camera, scene.lightsAt(scene.time), shading);
    if (stats) *stats = r->lastFrame();
    return r->targets().readColor();
}

struct ModelCheck {
    long compared = 0, withinOne = 0, bright = 0;
    int worst = 0;
};

// Every pixel of the sweep's tiles away from their edges against the CPU model: the environment read from what
// the GPU holds (EnvironmentMaps::stored), plus the light, through the output transform.
ModelCheck checkSweepAgainstModel(const Scene& scene, const ImageRGBA8& image, const ImageFloat& depth,
                                  const ShadingParameters& shading, const StoredEnvironment& stored, bool diffuseOnly) {
    const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
    ModelCheck c;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            const float d = depth.at(x, y);
            if (d >= 1.0f) continue;
            const glm::vec3 p = unprojectPixel(cam, x, y, d);
            const float u = (p.x + 4.4f) / 2.2f, v = (p.z + 4.4f) / 2.2f;
            const int mi = int(std::floor(u)), ri = int(std::floor(v));
            if (mi < 0 || mi > 3 || ri < 0 || ri > 3) continue;
            const float fu = u - float(mi), fv = v - float(ri);
            if (fu < 0.08f || fu > 0.83f || fv < 0.08f || fv > 0.83f) continue;
            const Material& m = scene.materials[size_t(mi * 4 + ri)];
            const BrdfSurface s = brdfSurface(m, glm::dvec3(p), glm::dvec3(0, 1, 0), glm::dvec3(cam.eye));
            glm::dvec3 linear = shadeAmbient(s, glm::dvec3(scene.ambient));
            linear += shadeEnvironment(s, *scene.environment, stored, scene.environmentIntensity, diffuseOnly);
            for (const PointLight& l : scene.lights) linear += shadePointLight(s, l);
            const glm::dvec3 expected = 255.0 * applyOutputTransform(linear, shading.output);
            const uint8_t* got = image.at(x, y);
            int e = 0;
            for (int k = 0; k < 3; ++k) e = std::max(e, int(std::lround(std::abs(double(got[k]) - expected[k]))));
            ++c.compared;
            if (e <= 1) ++c.withinOne;
            if (expected.g > 60.0) ++c.bright;
            c.worst = std::max(c.worst, e);
        }
    return c;
}

}  // namespace

TEST_CASE("environment light: every mode equals the reference, the frame says how it looked the environment up",
          "[environment]") {
    testContext();
    const bool fixedTable = GENERATE(false, true);  // half floats / RGBM (the path of contexts without float textures)
    DYNAMIC_SECTION((fixedTable ? "RGBM8" : "half-float") << " storage") {
        Scene scene = environmentFloor();
        scene.width = isSoftpipe() ? 96 : 160;
        scene.height = isSoftpipe() ? 72 : 120;
        const ShadingParameters shading = sceneShading(scene);
        FrameStats referenceStats;
        const ImageRGBA8 reference = renderWith(scene, "forward-brute", shading, fixedTable, &referenceStats);
        INFO("reference: " << referenceStats.environment);
        const bool lod = testGl().textureLod;
        CHECK(referenceStats.environment.find(lod ? ", lod" : ", bias") != std::string::npos);
        CHECK(referenceStats.environment.find(fixedTable || testGl().gles ? "RGBM8" : "half-float") != std::string::npos);
        // Without the environment the image is darker: the environment is really there.
        ShadingParameters without = shading;
        without.environment = {};
        const ImageError lit = compareImages(renderWith(scene, "forward-brute", without, fixedTable), reference);
        CHECK(lit.maxAbsError > 40);
        for (const std::string& mode : environmentModes()) {
            if (mode == "forward-brute") continue;
            FrameStats stats;
            const ImageError e = compareImages(renderWith(scene, mode, shading, fixedTable, &stats), reference);
            INFO(mode << ": " << stats.environment << ": max " << e.maxAbsError << ", PSNR " << e.psnr);
            CHECK(stats.environment == referenceStats.environment);
            if (mode == "forward-multipass")
                CHECK(e.psnr > 30.0);  // its 8-bit linear sum, clamped before the tone map (doc/colour.md)
            else
                CHECK(e.maxAbsError == 0);
        }
    }
}

TEST_CASE("environment light: the sweep matches the CPU model (forward-brute, small)", "[environment]") {
    testContext();
    Scene scene = environmentSweep(isSoftpipe() ? 96 : 128, isSoftpipe() ? 72 : 96);
    const ShadingParameters shading = sceneShading(scene);
    RenderModeOptions o;
    o.mode = "forward-brute";
    std::unique_ptr<Renderer> r = createRenderer(o, testGl(), scene, scene.width, scene.height);
    r->render(scene.camera, scene.lights, shading);
    if (!testGl().textureLod) SUCCEED("no explicit LOD here: the bias lookup, compared with the LOD path in [slow]");
    else {
        EnvironmentMaps maps(testGl(), true);
        maps.prepare(shading.environment);
        const ModelCheck c = checkSweepAgainstModel(scene, r->targets().readColor(), r->targets().readDepth(), shading,
                                                    *maps.stored(), false);
        INFO(c.compared << " compared, " << c.withinOne << " within one step, worst " << c.worst << ", bright " << c.bright);
        REQUIRE(c.compared > long(scene.width) * scene.height / 8);
        REQUIRE(c.bright > c.compared / 4);
        CHECK(c.withinOne >= c.compared * 99 / 100);
        CHECK(c.worst <= 3);
    }
}
