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
