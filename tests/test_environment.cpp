// Image-based environment light (issue 39): the CPU side (lidr/scene/environment.h: the cube's geometry, the
// spherical harmonics, the split-sum table, the GGX prefilter, the equirectangular conversion, the storage) and,
// below, every mode against the reference and the CPU model with an environment on.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>

#include <catch2/catch.hpp>

#include "gl_test_context.h"
#include "lidr/base/error.h"
#include "lidr/base/image.h"
#include "lidr/eval/brdf.h"
#include "lidr/eval/image_compare.h"
#include "lidr/gl/shader_source.h"
#include "lidr/modes/multipass_forward_renderer.h"
#include "lidr/modes/render_mode.h"
#include "lidr/render/depth_prepass.h"
#include "lidr/render/environment_maps.h"
#include "lidr/render/output_transform.h"
#include "lidr/scene/environment.h"
#include "lidr/scene/io/environment_file.h"
#include "lidr/scene/io/scene_file.h"
#include "lidr/scene/primitives.h"
#include "render_helpers.h"
#include "temp_dir.h"

using namespace lidr;
using namespace lidr::test;

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
    CHECK(rgbmRange(env) == 8.0f);  // the brightest panel is 8
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
// Files: an equirectangular .hdr, six faces, scene files; every bad input refused with its cause.


namespace {
ImageRGBFloat panoramaOf(int width, int height, const glm::vec3& value) {
    ImageRGBFloat image(width, height);
    for (glm::vec3& p : image.pixels) p = value;
    return image;
}
}  // namespace

TEST_CASE("environment files: a panorama and six faces load; bad ones are refused naming the cause", "[cpu][environment]") {
    lidr::test::TempDir dir;
    SECTION("an equirectangular .hdr: the cube, its levels and its SH of a constant sky") {
        const std::string file = dir.file("sky.hdr");
        writeHdr(file, panoramaOf(64, 32, glm::vec3(0.5f, 1.0f, 2.0f)));
        std::vector<std::string> steps;
        const auto env = loadEnvironment(file, [&](const std::string& step) { steps.push_back(step); });
        REQUIRE(env);
        CHECK(env->name == file);
        CHECK(env->levels() == kEnvironmentLevels);
        CHECK(env->specular[0].size == kEnvironmentSize);
        CHECK(irradianceOverPi(env->sh, glm::dvec3(0, 1, 0)).b == Approx(2.0).epsilon(0.01));  // RGBE: 1 % steps
        CHECK(steps.size() == size_t(2 + kEnvironmentLevels - 1));  // read, converted, each prefiltered level
        CHECK(loadEnvironment("none") == nullptr);
        CHECK(loadEnvironment("default") == defaultEnvironment());
    }
    SECTION("six faces in a folder, GL's layout: each face's texels land on its side of the cube") {
        const char* names[6] = {"px", "nx", "py", "ny", "pz", "nz"};
        for (int f = 0; f < 6; ++f) writeHdr(dir.file(std::string(names[f]) + ".hdr"), panoramaOf(16, 16, glm::vec3(float(f + 1))));
        const auto env = loadEnvironment(dir.path().string());
        REQUIRE(env);
        const glm::dvec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (int f = 0; f < 6; ++f) CHECK(sampleCubeBilinear(env->specular[0], axes[f]).r == Approx(f + 1.0).epsilon(0.01));
        // A face of another size, a face that is not square, a face missing
        writeHdr(dir.file("nz.hdr"), panoramaOf(8, 8, glm::vec3(1.0f)));
        CHECK_THROWS_WITH(loadEnvironment(dir.path().string()), Catch::Contains("nz.hdr") && Catch::Contains("8 x 8") &&
                                                                    Catch::Contains("the other faces are 16 x 16"));
        writeHdr(dir.file("nz.hdr"), panoramaOf(16, 8, glm::vec3(1.0f)));
        CHECK_THROWS_WITH(loadEnvironment(dir.path().string()), Catch::Contains("nz.hdr") && Catch::Contains("square"));
        std::filesystem::remove(dir.file("nz.hdr"));
        CHECK_THROWS_WITH(loadEnvironment(dir.path().string()), Catch::Contains("no face 'nz'"));
    }
    SECTION("bad files") {
        CHECK_THROWS_WITH(loadEnvironment(dir.file("missing.hdr")), Catch::Contains("missing.hdr") && Catch::Contains("not found"));
        CHECK_THROWS_WITH(loadEnvironment(dir.write("text.hdr", "#?RADIANCE but not really")),
                          Catch::Contains("text.hdr") && Catch::Contains("not a Radiance HDR file"));
        ImageRGBA8 png(8, 4);
        writePng(dir.file("ldr.hdr"), png);
        CHECK_THROWS_WITH(loadEnvironment(dir.file("ldr.hdr")), Catch::Contains("not a Radiance HDR file"));
        writePng(dir.file("ldr.png"), png);
        CHECK_THROWS_WITH(loadEnvironment(dir.file("ldr.png")), Catch::Contains("ldr.png") && Catch::Contains("not an environment"));
        writeHdr(dir.file("square.hdr"), panoramaOf(32, 32, glm::vec3(1.0f)));
        CHECK_THROWS_WITH(loadEnvironment(dir.file("square.hdr")), Catch::Contains("32 x 32") && Catch::Contains("twice as wide"));
        ImageRGBFloat bright = panoramaOf(64, 32, glm::vec3(1.0f));
        bright.at(5, 3) = glm::vec3(1e15f);  // RGBE holds it; lidr's filters' float sums would not
        writeHdr(dir.file("bright.hdr"), bright);
        CHECK_THROWS_WITH(loadEnvironment(dir.file("bright.hdr")),
                          Catch::Contains("pixel (5, 3)") && Catch::Contains("at most 1e12"));
        std::filesystem::create_directories(dir.file("not-a-file.hdr"));
        CHECK_THROWS_WITH(loadEnvironment(dir.file("not-a-file.hdr")), Catch::Contains("no face 'px'"));
    }
    SECTION("intensity") {
        CHECK_THROWS_WITH(validateEnvironmentIntensity(-1.0f, "--environment-intensity"),
                          Catch::Equals("--environment-intensity must be a finite number >= 0, got -1"));
        CHECK_THROWS_WITH(validateEnvironmentIntensity(std::nanf(""), "x"), Catch::Contains("got nan"));
        Scene scene;
        scene.environmentIntensity = std::numeric_limits<float>::infinity();
        CHECK_THROWS_WITH(scene.validate(), Catch::Contains("environment: intensity must be a finite number >= 0"));
    }
}

TEST_CASE("scene files: \"environment\" names one, relative to the file, with an intensity", "[cpu][environment][scene]") {
    lidr::test::TempDir dir;
    writeHdr(dir.file("sky.hdr"), panoramaOf(64, 32, glm::vec3(0.25f)));
    const std::string base = R"("primitives": [{"shape": "box", "min": [0, 0, 0], "max": [1, 1, 1]}])";
    const Scene none = loadSceneFile(dir.write("none.json", "{" + base + "}"));
    CHECK(none.environment == nullptr);  // today's look unless the file asks
    const Scene room = loadSceneFile(dir.write("room.json", R"({"environment": "default", )" + base + "}"));
    CHECK(room.environment == defaultEnvironment());
    const Scene sky = loadSceneFile(dir.write("sky.json", R"({"environment": {"source": "sky.hdr", "intensity": 2.5}, )" + base + "}"));
    REQUIRE(sky.environment);
    CHECK(sky.environment->name == dir.file("sky.hdr"));
    CHECK(sky.environmentIntensity == 2.5f);
    CHECK_THROWS_WITH(loadSceneFile(dir.write("bad1.json", R"({"environment": "nowhere.hdr", )" + base + "}")),
                      Catch::Contains("environment: ") && Catch::Contains("nowhere.hdr: not found"));
    CHECK_THROWS_WITH(loadSceneFile(dir.write("bad2.json", R"({"environment": {"source": "default", "intensity": -2}, )" + base + "}")),
                      Catch::Contains("environment.intensity: must be >= 0"));
    CHECK_THROWS_WITH(loadSceneFile(dir.write("bad3.json", R"({"environment": {"intensity": 2}, )" + base + "}")),
                      Catch::Contains("environment.source: missing required field"));
    CHECK_THROWS_WITH(loadSceneFile(dir.write("bad4.json", R"({"environment": {"source": "default", "blur": 1}, )" + base + "}")),
                      Catch::Contains("environment.blur: unknown key"));
}

// ------------------------------------------------------------------------------------------------------------
// GL: every mode with the environment on, against the reference and the CPU model.



namespace {

// The metallic x roughness sweep of flat tiles (test_brdf.cpp's) in the default environment: metallic along x,
// roughness 0 to 1 along z, an orange-ish base colour; one light, no uniform ambient, so the environment is most of
// what the tiles show (their reflections sweep the room's walls, floor and panels).
Scene environmentSweep(int width, int height) {
    Scene scene = metallicRoughnessSweep([](int j) { return float(j) / 3.0f; }, glm::vec3(0.5f, 5.0f, 8.5f));
    scene.name = "environment-sweep";
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
    if (testGl().gles) return {"lidr", "clustered", "forward-brute", "forward-multipass"};  // tiled's depth bounds: desktop only
    return {"lidr", "tiled", "clustered", "forward-brute", "forward-multipass"};
}

// Whether multi-pass sums its passes in 8 bits on this context (MultipassForwardRenderer::accumulation): its
// linear sum is clamped there before the tone map, so it is no longer the reference's image nor the model's.
bool multipassSumsIn8Bits(const Renderer& r) {
    const auto* multipass = dynamic_cast<const MultipassForwardRenderer*>(&r);
    return multipass && std::string(multipass->accumulation()) == "8-bit";
}

ImageRGBA8 renderWith(const Scene& scene, const std::string& mode, const ShadingParameters& shading, bool fixedTable,
                      FrameStats* stats = nullptr, bool* eightBitSum = nullptr) {
    RenderModeOptions o;
    o.mode = mode;
    o.forceFixedLightTable = fixedTable;
    std::unique_ptr<Renderer> r = createRenderer(o, testGl(), scene, scene.width, scene.height);
    r->render(scene.camera, scene.lightsAt(scene.time), shading);
    if (stats) *stats = r->lastFrame();
    if (eightBitSum) *eightBitSum = multipassSumsIn8Bits(*r);
    return r->targets().readColor();
}

// The sweep against the CPU model (checkSweep): the environment read from what the GPU holds
// (EnvironmentMaps::stored), the ambient and the light, through the output transform.
SweepCheck checkSweepAgainstModel(const Scene& scene, const ImageRGBA8& image, const ImageFloat& depth,
                                  const ShadingParameters& shading, const StoredEnvironment& stored, bool diffuseOnly) {
    return checkSweep(
        scene, image, depth, shading.output,
        [&](const BrdfSurface& s, const glm::vec3&) {
            glm::dvec3 linear = shadeAmbient(s, glm::dvec3(scene.ambient));
            linear += shadeEnvironment(s, *scene.environment, stored, scene.environmentIntensity, diffuseOnly);
            for (const PointLight& l : scene.lights) linear += shadePointLight(s, l);
            return linear;
        },
        1, 60.0);
}

}  // namespace

TEST_CASE("environment light: every mode equals the reference, the frame says how it looked the environment up",
          "[environment][every-gl]") {
    testContext();
    const bool fixedTable = GENERATE(false, true);  // half floats / RGBM (the path of contexts without float textures)
    if (!takeRow(!fixedTable)) return;  // representative: the half floats (where the context filters them)
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
        CHECK(referenceStats.environment.find(fixedTable || !testGl().halfFloatLinear ? "RGBM8" : "half-float") !=
              std::string::npos);
        // Without the environment the image is darker: the environment is really there.
        ShadingParameters without = shading;
        without.environment = {};
        const ImageError lit = compareImages(renderWith(scene, "forward-brute", without, fixedTable), reference);
        CHECK(lit.maxAbsError > 40);
        for (const std::string& mode : environmentModes()) {
            if (mode == "forward-brute") continue;
            FrameStats stats;
            bool eightBitSum = false;
            const ImageError e =
                compareImages(renderWith(scene, mode, shading, fixedTable, &stats, &eightBitSum), reference);
            INFO(mode << ": " << stats.environment << ": max " << e.maxAbsError << ", PSNR " << e.psnr
                      << (eightBitSum ? ", 8-bit sum" : ""));
            CHECK(stats.environment == referenceStats.environment);
            if (eightBitSum)
                CHECK(e.psnr > 30.0);  // its 8-bit linear sum, clamped before the tone map (doc/colour.md)
            else if (mode == "forward-multipass")
                CHECK(e.maxAbsError <= 1);  // the half-float sum, encoded once: rounded once more than one pass
            else
                CHECK(e.maxAbsError == 0);
        }
    }
}

TEST_CASE("environment light: the sweep matches the CPU model (forward-brute, small)", "[environment][every-gl]") {
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
        const SweepCheck c = checkSweepAgainstModel(scene, r->targets().readColor(), r->targets().readDepth(), shading,
                                                    *maps.stored(), false);
        INFO(c.compared << " compared, " << c.withinOne << " within one step, worst " << c.worst << ", bright " << c.bright);
        REQUIRE(c.compared > long(scene.width) * scene.height / 8);
        REQUIRE(c.bright > c.compared / 4);
        CHECK(c.withinOne >= c.compared * 99 / 100);
        CHECK(c.worst <= 3);
    }
}

TEST_CASE("environment light: no environment is the code without it; the keys and defines of each lookup", "[environment]") {
    testContext();
    Scene scene = environmentFloor();
    scene.width = isSoftpipe() ? 64 : 96;
    scene.height = isSoftpipe() ? 48 : 72;
    // Intensity 0 adds exactly nothing: the environment term is additive, and off is the frame without it.
    ShadingParameters zero = sceneShading(scene);
    zero.environment.intensity = 0.0f;
    ShadingParameters none = sceneShading(scene);
    none.environment = {};
    FrameStats stats;
    const ImageRGBA8 withNone = renderWith(scene, "lidr", none, false, &stats);
    CHECK(stats.environment == "none");
    CHECK(compareImages(renderWith(scene, "lidr", zero, false), withNone).maxAbsError == 0);
    // The keys: a program that calls lidrAmbient gets LIDR_ENVIRONMENT (0 without one), one that does not gets nothing.
    auto program = [](const char* fragment) {
        return gl::Program::create(fragment, buildShaderSource("geometry.vert"), buildShaderSource(fragment), geometryAttributes());
    };
    const gl::Program ambient = program("forward_ambient.frag"), light = program("forward_light.frag"),
                      depth = program("depth_only.frag");
    for (EnvironmentLookup lookup : {EnvironmentLookup::None, EnvironmentLookup::Lod, EnvironmentLookup::Bias,
                                     EnvironmentLookup::DiffuseOnly})
        for (bool rgbm : {false, true}) {
            CHECK(environmentVariantKey(light, lookup, rgbm) == 0);
            CHECK(environmentVariantKey(depth, lookup, rgbm) == 0);
            const uint32_t key = environmentVariantKey(ambient, lookup, rgbm);
            const ShaderDefines defines = shadingVariantDefines(key);
            REQUIRE(defines.size() == 2);
            CHECK(defines[0] == std::make_pair(std::string("LIDR_ENVIRONMENT"), std::to_string(int(lookup))));
            CHECK(defines[1].second == (rgbm && lookup != EnvironmentLookup::None ? "1" : "0"));
            if (lookup != EnvironmentLookup::Lod || testGl().textureLod) CHECK(ambient.variant(key, defines).id() != 0);
        }
}

TEST_CASE("environment light: a constant environment lights like the uniform ambient", "[environment]") {
    // Radiance a from every direction is the ambient a: the same diffuse term exactly (SH of a constant), the
    // specular from the table where the ambient uses Karis' analytic fit of it.
    testContext();
    Scene scene = environmentFloor();
    scene.width = isSoftpipe() ? 64 : 128;
    scene.height = isSoftpipe() ? 48 : 96;
    scene.lights.clear();
    CubeImage constant(16);
    for (glm::vec3& t : constant.texels) t = glm::vec3(0.6f, 0.5f, 0.4f);
    scene.environment = std::make_shared<const Environment>(prefilterEnvironment(constant, "constant", 5, 16));
    scene.environmentIntensity = 1.0f;
    scene.ambient = glm::vec3(0.0f);
    const ImageRGBA8 lit = renderWith(scene, "forward-brute", sceneShading(scene), false);
    Scene uniform = scene;
    uniform.environment = nullptr;
    uniform.ambient = glm::vec3(0.6f, 0.5f, 0.4f);
    const ImageError e = compareImages(lit, renderWith(uniform, "forward-brute", sceneShading(uniform), false));
    INFO("max " << e.maxAbsError << ", PSNR " << e.psnr);
    // Measured on llvmpipe: max 8 steps (rough metal at grazing views, where the fit and the table differ most),
    // PSNR 33.7 dB; the same on Mesa's ES 2.0.
    CHECK(e.maxAbsError <= 10);
    CHECK(e.psnr > 32.0);
}

TEST_CASE("environment light: where the texture units are few it takes the index targets' top units, or gives way",
          "[environment]") {
    testContext();
    if (testGl().maxTextureUnits < 19) {
        SUCCEED("this context has " << testGl().maxTextureUnits << " units: the low units are its default, tested as is");
        return;
    }
    Scene scene = environmentFloor();
    scene.width = isSoftpipe() ? 64 : 128;
    scene.height = isSoftpipe() ? 48 : 96;
    GlInfo sixteen = testGl();
    sixteen.maxTextureUnits = 16;  // WebGL's usual count (and many ES 2.0 parts'): units 6 and 7
    const ShadingParameters shading = sceneShading(scene);
    auto render = [&](const GlInfo& info, RenderModeOptions o, const ShadingParameters& s, FrameStats& stats) {
        std::unique_ptr<Renderer> r = createRenderer(o, info, scene, scene.width, scene.height);
        r->render(scene.camera, scene.lights, s);
        stats = r->lastFrame();
        return r->targets().readColor();
    };
    RenderModeOptions reference;
    reference.mode = "forward-brute";
    FrameStats high, low;
    const ImageRGBA8 a = render(testGl(), reference, shading, high), b = render(sixteen, reference, shading, low);
    INFO(high.environment << " / " << low.environment);
    CHECK(high.environment.find("units 17 and 18") != std::string::npos);
    CHECK(low.environment.find("units 6 and 7") != std::string::npos);
    CHECK(compareImages(a, b).maxAbsError == 0);
    // LIDR with 8 index targets (16 lights of 16 bits) needs units 6 and 7 itself: the environment's diffuse term alone.
    RenderModeOptions wide;
    wide.mode = "lidr";
    wide.lidr.packing.scheme = PackingSchemeKind::BitShift;
    wide.lidr.packing.budget = 16;
    wide.lidr.packing.indexBits = 16;
    FrameStats lidrStats, diffuseStats;
    const ImageRGBA8 lidr = render(sixteen, wide, shading, lidrStats);
    INFO(lidrStats.environment);
    CHECK(lidrStats.environment.find("diffuse-only (16 texture units and 8 index targets") != std::string::npos);
    ShadingParameters diffuse = shading;
    diffuse.environment.lookup = EnvironmentLight::Lookup::DiffuseOnly;
    const ImageRGBA8 expected = render(sixteen, reference, diffuse, diffuseStats);
    CHECK(compareImages(lidr, expected).maxAbsError == 0);
    CHECK(compareImages(lidr, a).maxAbsError > 20);  // the specular term is really gone
    // 4 targets (budget 8 of 16 bits) leave units 6 and 7 to the environment.
    wide.lidr.packing.budget = 8;
    const ImageRGBA8 four = render(sixteen, wide, shading, lidrStats);
    CHECK(lidrStats.environment.find("units 6 and 7") != std::string::npos);
    CHECK(compareImages(four, b).maxAbsError == 0);
}

TEST_CASE("environment light: the mip-bias lookup against the LOD lookup (measured)", "[environment][slow]") {
    // Contexts without ARB/EXT_shader_texture_lod look the cube up with textureCube(dir, roughness x levels) as a
    // bias over the implicit LOD minus an estimate of that LOD from the reflection's derivatives (shading.glsl), so
    // the sum is about the roughness's LOD. doc/colour.md gives the figures.
    testContext();
    if (!testGl().textureLod) {
        SUCCEED("no explicit LOD on this context: the bias lookup is its only one");
        return;
    }
    for (const bool sweep : {true, false}) {
        Scene scene = sweep ? environmentSweep(256, 192) : environmentFloor();
        const ShadingParameters lod = sceneShading(scene);
        ShadingParameters bias = lod;
        bias.environment.lookup = EnvironmentLight::Lookup::Bias;
        FrameStats stats;
        const ImageRGBA8 biased = renderWith(scene, "forward-brute", bias, false, &stats);
        const ImageRGBA8 exact = renderWith(scene, "forward-brute", lod, false);
        const ImageError e = compareImages(biased, exact);
        INFO((sweep ? "sweep" : "floor scene") << ", " << stats.environment << ": max " << e.maxAbsError << ", RMSE "
                                               << e.rmse << ", PSNR " << e.psnr);
        CHECK(stats.environment.find("bias (mip bias as asked)") != std::string::npos);
        // Measured on llvmpipe: the sweep (flat tiles) 50.6 dB, max 7; the floor scene (a smooth metal floor at
        // grazing views, a sphere) 30.3 dB, max 29: GL's implicit LOD takes the larger of the two screen axes' footprints, the
        // estimate their length, and the anisotropy at grazing views shifts the two.
        CHECK(e.psnr > (sweep ? 45.0 : 28.0));
        CHECK(e.maxAbsError > 0);  // really another lookup
    }
}

TEST_CASE("environment light: every mode against the CPU model, both storages (metallic x roughness sweep)",
          "[environment][slow]") {
    testContext();
    if (!testGl().textureLod) {
        SUCCEED("the CPU model is of the LOD lookup; this context has none");
        return;
    }
    const std::string mode = GENERATE_COPY(from_range(environmentModes()));
    const bool fixedTable = GENERATE(false, true);
    const float intensity = GENERATE(1.0f, 2.5f);
    DYNAMIC_SECTION(mode << ", " << (fixedTable ? "RGBM8" : "half-float") << ", intensity " << intensity) {
        Scene scene = environmentSweep(testWidth(), testHeight());
        scene.environmentIntensity = intensity;
        const ShadingParameters shading = sceneShading(scene);
        RenderModeOptions o;
        o.mode = mode;
        o.forceFixedLightTable = fixedTable;
        std::unique_ptr<Renderer> r = createRenderer(o, testGl(), scene, scene.width, scene.height);
        if (multipassSumsIn8Bits(*r)) {
            SUCCEED("multi-pass sums in 8 bits here: its clamped linear sum is not this model's (doc/colour.md)");
            return;
        }
        r->render(scene.camera, scene.lights, shading);
        EnvironmentMaps maps(testGl(), !fixedTable);
        maps.prepare(shading.environment);
        const SweepCheck c = checkSweepAgainstModel(scene, r->targets().readColor(), r->targets().readDepth(), shading,
                                                    *maps.stored(), false);
        INFO(c.compared << " compared, " << c.withinOne << " within one step, worst " << c.worst);
        REQUIRE(c.compared > long(scene.width) * scene.height / 8);
        if (!fixedTable && testGl().halfFloatLinear) {
            // Half floats: measured all within one step on llvmpipe, worst 1.
            CHECK(c.withinOne >= c.compared * 995 / 1000);
            CHECK(c.worst <= 3);
        } else {
            // RGBM: GL filters the 8-bit channels at the implementation's precision (llvmpipe: 8 bits), and the
            // multiplier's rounding is up to 1 / (2 m) of the value (3 % for radiance 0.5 under the range 8: m =
            // 16 / 255). Measured on llvmpipe: 94.7 % within one step, worst 4 (the metal tiles).
            CHECK(c.withinOne >= c.compared * 93 / 100);
            CHECK(c.worst <= 6);
        }
    }
}
