#include "lidr/scene/environment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>

#include <glm/gtc/packing.hpp>

#include "lidr/base/error.h"

namespace lidr {

namespace {
constexpr double kPi = 3.14159265358979323846;

double clamp01(double v) { return std::min(std::max(v, 0.0), 1.0); }

// Van der Corput's radical inverse in base 2: the second coordinate of the Hammersley set.
double radicalInverse(uint32_t bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return double(bits) * 2.3283064365386963e-10;
}

// A GGX half vector for the Hammersley point (i, n) about +z: cos(theta) from the inverted CDF of D x n.h.
glm::dvec3 ggxHalfVector(int i, int n, double alpha) {
    const double u1 = (double(i) + 0.5) / double(n), u2 = radicalInverse(uint32_t(i));
    const double phi = 2.0 * kPi * u1;
    const double a2 = alpha * alpha;
    const double cosTheta = std::sqrt((1.0 - u2) / (1.0 + (a2 - 1.0) * u2));
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

double ggxD(double nDotH, double alpha) {
    const double a2 = alpha * alpha, d = nDotH * nDotH * (a2 - 1.0) + 1.0;
    return a2 / (kPi * d * d);
}

double alphaOfRoughness(double roughness) { return std::max(roughness * roughness, 0.01); }  // as shading.glsl

// An orthonormal frame about n: tangent, bitangent.
void frameAbout(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
    t = glm::normalize(std::abs(n.z) < 0.999 ? glm::cross(glm::dvec3(0, 0, 1), n) : glm::cross(glm::dvec3(1, 0, 0), n));
    b = glm::cross(n, t);
}

// Bilinear weights and texels along one axis of a face, clamped to its edge as GL's CLAMP_TO_EDGE.
struct Axis {
    int i0, i1;
    double f;
};
Axis axisOf(double s, int size) {
    const double u = s * size - 0.5;
    const double fl = std::floor(u);
    Axis a;
    a.f = u - fl;
    a.i0 = std::clamp(int(fl), 0, size - 1);
    a.i1 = std::clamp(int(fl) + 1, 0, size - 1);
    return a;
}

template <typename Texel, typename Fetch>
Texel bilinearOnFace(int size, int face, double s, double t, const Fetch& fetch) {
    const Axis x = axisOf(s, size), y = axisOf(t, size);
    const Texel a = fetch(face, x.i0, y.i0), b = fetch(face, x.i1, y.i0), c = fetch(face, x.i0, y.i1),
                d = fetch(face, x.i1, y.i1);
    return (a * (1.0 - x.f) + b * x.f) * (1.0 - y.f) + (c * (1.0 - x.f) + d * x.f) * y.f;
}

double lodFraction(double lod, int levels, int& d1, int& d2) {
    lod = std::clamp(lod, 0.0, double(levels - 1));
    d1 = int(std::floor(lod));
    d2 = std::min(d1 + 1, levels - 1);
    return lod - double(d1);
}

bool isPowerOfTwo(int v) { return v > 0 && (v & (v - 1)) == 0; }

// A cube of `size` whose texels are the mean of radiance(direction) over 4 x 4 samples each.
template <typename Radiance>
CubeImage supersampledCube(int size, const Radiance& radiance) {
    CubeImage cube(size);
    constexpr int n = 4;
    for (int f = 0; f < 6; ++f)
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                glm::dvec3 sum(0.0);
                for (int j = 0; j < n; ++j)
                    for (int i = 0; i < n; ++i)
                        sum += radiance(cubeDirection(f, (x + (i + 0.5) / n) / size, (y + (j + 0.5) / n) / size));
                cube.at(f, x, y) = glm::vec3(sum / double(n * n));
            }
    return cube;
}

// body(row) for rows 0 .. rows - 1, on the machine's cores (one thread in the web build: no threads there).
template <typename Body>
void forEachRow(int rows, const Body& body) {
#ifdef __EMSCRIPTEN__
    const int threads = 1;
#else
    const int threads = int(std::clamp(std::thread::hardware_concurrency(), 1u, 8u));
#endif
    if (threads == 1) {
        for (int r = 0; r < rows; ++r) body(r);
        return;
    }
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
            for (int r = t; r < rows; r += threads) body(r);
        });
    for (std::thread& th : pool) th.join();
}
}  // namespace

glm::dvec3 cubeDirection(int face, double s, double t) {
    const double sc = 2.0 * s - 1.0, tc = 2.0 * t - 1.0;
    glm::dvec3 d;
    switch (face) {
    case 0: d = {1.0, -tc, -sc}; break;
    case 1: d = {-1.0, -tc, sc}; break;
    case 2: d = {sc, 1.0, tc}; break;
    case 3: d = {sc, -1.0, -tc}; break;
    case 4: d = {sc, -tc, 1.0}; break;
    default: d = {-sc, -tc, -1.0}; break;
    }
    return glm::normalize(d);
}

void cubeFaceCoordinates(const glm::dvec3& d, int& face, double& s, double& t) {
    const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    double sc, tc, ma;
    if (ax >= ay && ax >= az) {
        ma = ax;
        if (d.x >= 0.0) face = 0, sc = -d.z, tc = -d.y;
        else face = 1, sc = d.z, tc = -d.y;
    } else if (ay >= az) {
        ma = ay;
        if (d.y >= 0.0) face = 2, sc = d.x, tc = d.z;
        else face = 3, sc = d.x, tc = -d.z;
    } else {
        ma = az;
        if (d.z >= 0.0) face = 4, sc = d.x, tc = -d.y;
        else face = 5, sc = -d.x, tc = -d.y;
    }
    s = 0.5 * (sc / ma + 1.0);
    t = 0.5 * (tc / ma + 1.0);
}

double cubeTexelSolidAngle(int size, int x, int y) {
    // The projection of [x0, x1] x [y0, y1] on the face plane at distance 1 onto the unit sphere.
    auto area = [](double a, double b) { return std::atan2(a * b, std::sqrt(a * a + b * b + 1.0)); };
    const double x0 = 2.0 * x / size - 1.0, x1 = 2.0 * (x + 1) / size - 1.0;
    const double y0 = 2.0 * y / size - 1.0, y1 = 2.0 * (y + 1) / size - 1.0;
    return area(x0, y0) - area(x0, y1) - area(x1, y0) + area(x1, y1);
}

glm::dvec3 sampleCubeBilinear(const CubeImage& cube, const glm::dvec3& direction) {
    int face;
    double s, t;
    cubeFaceCoordinates(direction, face, s, t);
    return bilinearOnFace<glm::dvec3>(cube.size, face, s, t,
                                      [&](int f, int x, int y) { return glm::dvec3(cube.at(f, x, y)); });
}

glm::dvec3 sampleCubeTrilinear(const std::vector<CubeImage>& levels, const glm::dvec3& direction, double lod) {
    int d1, d2;
    const double f = lodFraction(lod, int(levels.size()), d1, d2);
    const glm::dvec3 a = sampleCubeBilinear(levels[size_t(d1)], direction);
    if (f == 0.0) return a;
    return a * (1.0 - f) + sampleCubeBilinear(levels[size_t(d2)], direction) * f;
}

CubeImage downsampleCube(const CubeImage& cube) {
    if (cube.size <= 1) return cube;
    CubeImage out(cube.size / 2);
    for (int f = 0; f < 6; ++f)
        for (int y = 0; y < out.size; ++y)
            for (int x = 0; x < out.size; ++x)
                out.at(f, x, y) = 0.25f * (cube.at(f, 2 * x, 2 * y) + cube.at(f, 2 * x + 1, 2 * y) +
                                           cube.at(f, 2 * x, 2 * y + 1) + cube.at(f, 2 * x + 1, 2 * y + 1));
    return out;
}

CubeImage resampleCube(const CubeImage& source, int size) {
    CubeImage from = source;
    while (from.size >= 4 * size && from.size % 2 == 0) from = downsampleCube(from);
    if (from.size == size) return from;
    return supersampledCube(size, [&](const glm::dvec3& d) { return sampleCubeBilinear(from, d); });
}

glm::dvec2 equirectCoordinates(const glm::dvec3& d) {
    return {std::atan2(d.z, d.x) / (2.0 * kPi) + 0.5, std::asin(std::clamp(d.y, -1.0, 1.0)) / kPi + 0.5};
}

glm::dvec3 equirectDirection(double u, double v) {
    const double phi = (u - 0.5) * 2.0 * kPi, theta = (v - 0.5) * kPi;
    return {std::cos(theta) * std::cos(phi), std::sin(theta), std::cos(theta) * std::sin(phi)};
}

namespace {
glm::dvec3 sampleEquirect(const ImageRGBFloat& image, const glm::dvec2& uv) {
    const double x = uv.x * image.width - 0.5, y = (1.0 - uv.y) * image.height - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double ax = x - fx, ay = y - fy;
    auto px = [&](int i) { return ((i % image.width) + image.width) % image.width; };
    auto py = [&](int j) { return std::clamp(j, 0, image.height - 1); };
    const int x0 = px(int(fx)), x1 = px(int(fx) + 1), y0 = py(int(fy)), y1 = py(int(fy) + 1);
    const glm::dvec3 a(image.at(x0, y0)), b(image.at(x1, y0)), c(image.at(x0, y1)), d(image.at(x1, y1));
    return (a * (1.0 - ax) + b * ax) * (1.0 - ay) + (c * (1.0 - ax) + d * ax) * ay;
}
}  // namespace

CubeImage cubeFromEquirect(const ImageRGBFloat& equirect, int size) {
    return supersampledCube(size, [&](const glm::dvec3& d) { return sampleEquirect(equirect, equirectCoordinates(d)); });
}

ImageRGBFloat equirectFromCube(const CubeImage& cube, int width) {
    const int height = std::max(1, width / 2);
    ImageRGBFloat image(width, height);
    constexpr int n = 2;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            glm::dvec3 sum(0.0);
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const double u = (x + (i + 0.5) / n) / width, v = 1.0 - (y + (j + 0.5) / n) / height;
                    sum += sampleCubeBilinear(cube, equirectDirection(u, v));
                }
            image.at(x, y) = glm::vec3(sum / double(n * n));
        }
    return image;
}

namespace {
// The studio room: a box around the viewer, its walls lit by the panels (baked as plain radiance: grey walls
// brighter towards the ceiling), and emissive panels. Units: linear radiance; the mean over all directions is
// about 1, so a white Lambert surface in the room reads about 1 before the tone map.
struct Panel {
    int axis;          // the wall's axis: 0 x, 1 y, 2 z
    double side;       // -1 or +1: which wall
    glm::dvec2 min, max;  // the rectangle on the wall in the other two axes (in order: x, y, z without `axis`)
    double radiance;
};
constexpr glm::dvec3 kRoomMin(-6.0, -2.5, -8.0), kRoomMax(6.0, 6.0, 8.0);
const Panel kPanels[] = {
    {1, +1.0, {-2.5, -3.0}, {2.5, 3.0}, 6.0},   // the ceiling's large softbox
    {0, -1.0, {1.0, -5.0}, {4.5, -1.0}, 8.0},   // a tall panel on the left wall (y, z)
    {0, +1.0, {0.5, 1.5}, {3.0, 5.5}, 5.0},     // a smaller one on the right wall
    {2, -1.0, {-4.0, 2.0}, {-1.0, 4.5}, 7.0},   // on the back wall (x, y)
    {2, +1.0, {2.0, 0.0}, {4.5, 2.0}, 3.0},     // a low strip behind the viewer
};

glm::dvec3 roomRadiance(const glm::dvec3& d) {
    // The nearest wall the ray from the centre (the origin) meets.
    double tHit = 1e30;
    int axis = 0;
    double side = 1.0;
    for (int a = 0; a < 3; ++a) {
        if (std::abs(d[a]) < 1e-12) continue;
        const double wall = d[a] > 0.0 ? kRoomMax[a] : kRoomMin[a];
        const double t = wall / d[a];
        if (t > 0.0 && t < tHit) tHit = t, axis = a, side = d[a] > 0.0 ? 1.0 : -1.0;
    }
    const glm::dvec3 p = d * tHit;
    for (const Panel& panel : kPanels) {
        if (panel.axis != axis || panel.side != side) continue;
        const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
        if (p[u] >= panel.min.x && p[u] <= panel.max.x && p[v] >= panel.min.y && p[v] <= panel.max.y)
            return glm::dvec3(panel.radiance);
    }
    if (axis == 1 && side < 0.0) {  // the floor: darker, a little lighter under the softbox
        const double r = std::sqrt(p.x * p.x + p.z * p.z);
        return glm::dvec3(0.25 + 0.15 * std::exp(-r * r / 30.0));
    }
    if (axis == 1) return glm::dvec3(0.55);  // the ceiling around the softbox
    // walls: brighter towards the ceiling
    const double h = (p.y - kRoomMin.y) / (kRoomMax.y - kRoomMin.y);
    return glm::dvec3(0.35 + 0.3 * h);
}
}  // namespace

CubeImage makeRoomEnvironmentCube(int size) { return supersampledCube(size, roomRadiance); }

std::array<double, 9> shBasis(const glm::dvec3& d) {
    return {0.282094791773878, 0.488602511902920 * d.y, 0.488602511902920 * d.z, 0.488602511902920 * d.x,
            1.092548430592079 * d.x * d.y, 1.092548430592079 * d.y * d.z,
            0.315391565252520 * (3.0 * d.z * d.z - 1.0), 1.092548430592079 * d.x * d.z,
            0.546274215296040 * (d.x * d.x - d.y * d.y)};
}

std::array<glm::dvec3, 9> irradianceSh(const CubeImage& radiance) {
    std::array<glm::dvec3, 9> projection{};
    for (int f = 0; f < 6; ++f)
        for (int y = 0; y < radiance.size; ++y)
            for (int x = 0; x < radiance.size; ++x) {
                const glm::dvec3 d = cubeDirection(f, (x + 0.5) / radiance.size, (y + 0.5) / radiance.size);
                const double w = cubeTexelSolidAngle(radiance.size, x, y);
                const std::array<double, 9> basis = shBasis(d);
                const glm::dvec3 l(radiance.at(f, x, y));
                for (int i = 0; i < 9; ++i) projection[size_t(i)] += l * (basis[size_t(i)] * w);
            }
    // Convolved with the clamped cosine (Ramamoorthi and Hanrahan: pi, 2 pi / 3, pi / 4), over pi, and times the
    // basis constants, so the shader multiplies by the polynomials alone.
    const double band[9] = {1.0, 2.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0, 0.25, 0.25, 0.25, 0.25, 0.25};
    const double constant[9] = {0.282094791773878, 0.488602511902920, 0.488602511902920, 0.488602511902920,
                                1.092548430592079, 1.092548430592079, 0.315391565252520, 1.092548430592079,
                                0.546274215296040};
    std::array<glm::dvec3, 9> sh{};
    for (int i = 0; i < 9; ++i) sh[size_t(i)] = projection[size_t(i)] * (band[i] * constant[i]);
    return sh;
}

glm::dvec3 irradianceOverPi(const std::array<glm::dvec3, 9>& c, const glm::dvec3& n) {
    const glm::dvec3 e = c[0] + c[1] * n.y + c[2] * n.z + c[3] * n.x + c[4] * (n.x * n.y) + c[5] * (n.y * n.z) +
                         c[6] * (3.0 * n.z * n.z - 1.0) + c[7] * (n.x * n.z) + c[8] * (n.x * n.x - n.y * n.y);
    return glm::max(e, glm::dvec3(0.0));  // a band-limited bright panel rings below zero opposite it
}

Environment prefilterEnvironment(const CubeImage& radiance, const std::string& name, int levels, int samples,
                                 const EnvironmentProgress& progress) {
    if (levels < 1 || !isPowerOfTwo(radiance.size) || radiance.size < (1 << (levels - 1)))
        throw Error("environment '" + name + "': a cube of " + std::to_string(radiance.size) + " texels cannot hold " +
                    std::to_string(levels) + " roughness levels (a power of two of at least 2^(levels - 1))");
    float maxRadiance = 0.0f;
    for (const glm::vec3& t : radiance.texels) {
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(t[k]) || t[k] < 0.0f)
                throw Error("environment '" + name + "': a texel is " + (std::isfinite(t[k]) ? "negative" : "not finite") +
                            " (radiance must be finite and >= 0)");
        maxRadiance = std::max({maxRadiance, t.r, t.g, t.b});
    }
    Environment env;
    env.name = name;
    env.maxRadiance = maxRadiance;
    env.sh = irradianceSh(radiance);
    // The radiance's box-filtered chain, read by the samples at the level their pdf covers.
    std::vector<CubeImage> chain{radiance};
    while (chain.back().size > 1) chain.push_back(downsampleCube(chain.back()));
    const double texelSolidAngle = 4.0 * kPi / (6.0 * double(radiance.size) * double(radiance.size));
    env.specular.push_back(radiance);
    for (int level = 1; level < levels; ++level) {
        const double roughness = double(level) / double(levels - 1), alpha = alphaOfRoughness(roughness);
        const int size = radiance.size >> level;
        // The samples' half vectors about +z, their weights and source levels: the same for every texel.
        struct Sample {
            glm::dvec3 h;
            double lod;
        };
        std::vector<Sample> lobe;
        for (int i = 0; i < samples; ++i) {
            const glm::dvec3 h = ggxHalfVector(i, samples, alpha);
            const double pdf = ggxD(h.z, alpha) * 0.25;  // D n.h / (4 v.h) with n = v
            const double sampleSolidAngle = 1.0 / (double(samples) * pdf);
            lobe.push_back({h, std::max(0.0, 0.5 * std::log2(sampleSolidAngle / texelSolidAngle) + 1.0)});
        }
        CubeImage out(size);
        // Rows in parallel (each texel on its own: the result does not depend on the thread count).
        forEachRow(6 * size, [&](int row) {
            const int f = row / size, y = row % size;
                for (int x = 0; x < size; ++x) {
                    const glm::dvec3 n = cubeDirection(f, (x + 0.5) / size, (y + 0.5) / size);
                    glm::dvec3 t, b;
                    frameAbout(n, t, b);
                    glm::dvec3 sum(0.0);
                    double weight = 0.0;
                    for (const Sample& s : lobe) {
                        const glm::dvec3 h = t * s.h.x + b * s.h.y + n * s.h.z;
                        const glm::dvec3 l = 2.0 * s.h.z * h - n;  // v = n, so v.h = n.h
                        const double nDotL = glm::dot(n, l);
                        if (nDotL <= 0.0) continue;
                        sum += sampleCubeTrilinear(chain, l, s.lod) * nDotL;
                        weight += nDotL;
                    }
                    out.at(f, x, y) = glm::vec3(weight > 0.0 ? sum / weight : glm::dvec3(sampleCubeBilinear(radiance, n)));
                }
        });
        env.specular.push_back(std::move(out));
        if (progress)
            progress("prefiltered roughness " + std::to_string(roughness).substr(0, 4) + " (" + std::to_string(size) +
                     " texels a face, level " + std::to_string(level) + " of " + std::to_string(levels - 1) + ")");
    }
    return env;
}

void validateEnvironmentIntensity(float intensity, const std::string& what) {
    if (!(std::isfinite(intensity) && intensity >= 0.0f)) {
        char value[32];
        std::snprintf(value, sizeof value, "%g", double(intensity));
        throw Error(what + " must be a finite number >= 0, got " + value);
    }
}

std::shared_ptr<const Environment> defaultEnvironment() {
    static std::once_flag once;
    static std::shared_ptr<const Environment> environment;
    std::call_once(once, [] {
        environment = std::make_shared<const Environment>(prefilterEnvironment(makeRoomEnvironmentCube(kEnvironmentSize), "default"));
    });
    return environment;
}

glm::dvec2 splitSumIntegral(double nDotV, double roughness, int samples) {
    const double alpha = alphaOfRoughness(roughness), a2 = alpha * alpha;
    const double nv = std::max(nDotV, 1e-4);  // as shading.glsl's visibility term
    const glm::dvec3 v(std::sqrt(std::max(0.0, 1.0 - nv * nv)), 0.0, nv);
    glm::dvec2 sum(0.0);
    for (int i = 0; i < samples; ++i) {
        const glm::dvec3 h = ggxHalfVector(i, samples, alpha);
        const double vDotH = glm::dot(v, h);
        const glm::dvec3 l = 2.0 * vDotH * h - v;
        const double nDotL = l.z, nDotH = h.z;
        if (nDotL <= 0.0 || nDotH <= 0.0) continue;
        const double vh = clamp01(vDotH);
        const double visibility = 0.5 / (nDotL * std::sqrt(nv * nv * (1.0 - a2) + a2) + nv * std::sqrt(nDotL * nDotL * (1.0 - a2) + a2));
        // f n.l / pdf with pdf = D n.h / (4 v.h): the D cancels.
        const double g = visibility * 4.0 * nDotL * vh / nDotH;
        const double fc = std::pow(1.0 - vh, 5.0);
        sum += glm::dvec2((1.0 - fc) * g, fc * g);
    }
    return sum / double(samples);
}

const SplitSumTable& splitSumTable() {
    static std::once_flag once;
    static SplitSumTable table;
    std::call_once(once, [] {
        table.size = kSplitSumSize;
        table.values.resize(size_t(kSplitSumSize) * kSplitSumSize);
        for (int j = 0; j < kSplitSumSize; ++j)
            for (int i = 0; i < kSplitSumSize; ++i)
                table.values[size_t(j) * kSplitSumSize + size_t(i)] =
                    splitSumIntegral(double(i) / (kSplitSumSize - 1), double(j) / (kSplitSumSize - 1), 1024);
    });
    return table;
}

float rgbmRange(const Environment& environment) {
    float range = 1.0f;
    while (range < environment.maxRadiance && range < kRgbmMaxRange) range *= 2.0f;
    return range;
}

float roundToHalf(float v) { return glm::unpackHalf1x16(glm::packHalf1x16(v)); }

glm::u8vec4 encodeRgbm(const glm::vec3& rgb, float range) {
    const glm::vec3 c = glm::clamp(rgb / range, glm::vec3(0.0f), glm::vec3(1.0f));
    const float m = std::max(std::ceil(std::max({c.r, c.g, c.b, 1e-6f}) * 255.0f), 1.0f);  // in 1/255 steps, >= 1
    const glm::vec3 scaled = c * (255.0f / m);
    return {uint8_t(std::lround(std::min(scaled.r, 1.0f) * 255.0f)), uint8_t(std::lround(std::min(scaled.g, 1.0f) * 255.0f)),
            uint8_t(std::lround(std::min(scaled.b, 1.0f) * 255.0f)), uint8_t(m)};
}

glm::dvec3 decodeRgbm(const glm::dvec4& c, double range) {
    return glm::dvec3(c) / 255.0 * (c.w / 255.0 * range);
}

glm::u8vec4 encodeSplitSum16(const glm::dvec2& value) {
    const int a = int(std::lround(clamp01(value.x) * 65535.0)), b = int(std::lround(clamp01(value.y) * 65535.0));
    return {uint8_t(a >> 8), uint8_t(a & 255), uint8_t(b >> 8), uint8_t(b & 255)};
}

glm::dvec2 decodeSplitSum16(const glm::dvec4& c) {
    return glm::dvec2(c.x * 256.0 + c.y, c.z * 256.0 + c.w) / 65535.0;
}

StoredEnvironment storeEnvironment(const Environment& environment, EnvironmentStorage storage) {
    StoredEnvironment stored;
    stored.storage = storage;
    stored.range = storage == EnvironmentStorage::Rgbm8 ? rgbmRange(environment) : 1.0f;
    stored.roughnessLevels = environment.levels();
    std::vector<CubeImage> levels = environment.specular;
    while (levels.back().size > 1) levels.push_back(downsampleCube(levels.back()));
    for (const CubeImage& level : levels) {
        StoredCube cube;
        cube.size = level.size;
        cube.texels.reserve(level.texels.size());
        for (const glm::vec3& t : level.texels) {
            if (storage == EnvironmentStorage::Rgbm8) cube.texels.push_back(glm::vec4(encodeRgbm(t, stored.range)));
            else cube.texels.push_back({roundToHalf(t.r), roundToHalf(t.g), roundToHalf(t.b), 1.0f});
        }
        stored.levels.push_back(std::move(cube));
    }
    const SplitSumTable& table = splitSumTable();
    stored.tableSize = table.size;
    for (const glm::dvec2& v : table.values) {
        if (storage == EnvironmentStorage::Rgbm8) stored.table.push_back(glm::vec4(encodeSplitSum16(v)));
        else stored.table.push_back({roundToHalf(float(v.x)), roundToHalf(float(v.y)), 0.0f, 1.0f});
    }
    return stored;
}

namespace {
glm::dvec4 sampleStoredLevel(const StoredCube& cube, const glm::dvec3& direction) {
    int face;
    double s, t;
    cubeFaceCoordinates(direction, face, s, t);
    return bilinearOnFace<glm::dvec4>(cube.size, face, s, t, [&](int f, int x, int y) { return glm::dvec4(cube.at(f, x, y)); });
}
}  // namespace

glm::dvec3 sampleStoredSpecular(const StoredEnvironment& stored, const glm::dvec3& direction, double lod) {
    int d1, d2;
    const double f = lodFraction(lod, stored.roughnessLevels, d1, d2);
    glm::dvec4 texel = sampleStoredLevel(stored.levels[size_t(d1)], direction);
    if (f > 0.0) texel = texel * (1.0 - f) + sampleStoredLevel(stored.levels[size_t(d2)], direction) * f;
    return stored.storage == EnvironmentStorage::Rgbm8 ? decodeRgbm(texel, stored.range) : glm::dvec3(texel);
}

glm::dvec2 sampleStoredSplitSum(const StoredEnvironment& stored, double nDotV, double roughness) {
    const int n = stored.tableSize;
    // Texel centres hold n.v = i / (n - 1): the shader's coordinate (x (n - 1) + 0.5) / n lands on them.
    const double s = (clamp01(nDotV) * (n - 1) + 0.5) / n, t = (clamp01(roughness) * (n - 1) + 0.5) / n;
    const Axis x = axisOf(s, n), y = axisOf(t, n);
    auto at = [&](int i, int j) { return glm::dvec4(stored.table[size_t(j) * size_t(n) + size_t(i)]); };
    const glm::dvec4 v = (at(x.i0, y.i0) * (1.0 - x.f) + at(x.i1, y.i0) * x.f) * (1.0 - y.f) +
                         (at(x.i0, y.i1) * (1.0 - x.f) + at(x.i1, y.i1) * x.f) * y.f;
    return stored.storage == EnvironmentStorage::Rgbm8 ? decodeSplitSum16(v) : glm::dvec2(v.x, v.y);
}

}  // namespace lidr
