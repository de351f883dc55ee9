#pragma once
// Image-based environment light (issue 39): the light arriving from every direction, as every mode adds it once
// per pixel next to the ambient (shaders/common/shading.glsl, lidrEnvironment). CPU only, deterministic, so the
// same data feeds the GPU (lidr/render/environment_maps.h) and the CPU model of the BRDF (lidr/eval/brdf.h):
//   - a radiance cube (linear, GL's face order and orientation), from the built-in studio room
//     (makeRoomEnvironmentCube), an equirectangular image or six faces (lidr/scene/io/environment_file.h);
//   - its GGX prefiltered levels, one per roughness (prefilterEnvironment): the specular term, looked up in the
//     reflected direction at LOD roughness x (levels - 1);
//   - 9 spherical-harmonic coefficients of the cosine-convolved irradiance: the diffuse term;
//   - the split-sum table (splitSumTable): the specular integral's scale and bias per (n.v, roughness).
// doc/colour.md, "Environment light", has the units, sizes and error bounds.
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>

namespace lidr {

// A float RGB image, rows top to bottom (an equirectangular environment, a face read from a file).
struct ImageRGBFloat {
    int width = 0, height = 0;
    std::vector<glm::vec3> pixels;
    ImageRGBFloat() = default;
    ImageRGBFloat(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h), glm::vec3(0.0f)) {}
    glm::vec3& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
    const glm::vec3& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

// Six square faces of linear RGB in GL's order (+X, -X, +Y, -Y, +Z, -Z) and orientation (the major-axis table of
// the GL specification: face +X has s along -z and t along -y, ...). Texel (x, y) of a face is its row y from the
// first row uploaded, t = (y + 0.5) / size.
struct CubeImage {
    int size = 0;
    std::vector<glm::vec3> texels;  // (face x size + y) x size + x
    CubeImage() = default;
    explicit CubeImage(int s) : size(s), texels(size_t(6) * size_t(s) * size_t(s), glm::vec3(0.0f)) {}
    glm::vec3& at(int face, int x, int y) { return texels[(size_t(face) * size_t(size) + size_t(y)) * size_t(size) + size_t(x)]; }
    const glm::vec3& at(int face, int x, int y) const {
        return texels[(size_t(face) * size_t(size) + size_t(y)) * size_t(size) + size_t(x)];
    }
};

// The unit direction of face coordinates (s, t) in [0, 1]; and back: the face GL's major-axis rule picks for
// `direction` (ties: x before y before z) and the coordinates on it.
glm::dvec3 cubeDirection(int face, double s, double t);
void cubeFaceCoordinates(const glm::dvec3& direction, int& face, double& s, double& t);
// The solid angle of texel (x, y) of a face of `size` texels (exact: the area of its projection on the unit sphere).
double cubeTexelSolidAngle(int size, int x, int y);

// Bilinear filtering of one level as GL filters a cube map without seamless filtering: texels of the face the
// direction selects, clamped to its edge (what GL 2.1, OpenGL ES 2.0 and WebGL 1 do).
glm::dvec3 sampleCubeBilinear(const CubeImage& cube, const glm::dvec3& direction);
// Trilinear: levels floor(lod) and the next, mixed by the fraction; lod clamped to [0, levels - 1].
glm::dvec3 sampleCubeTrilinear(const std::vector<CubeImage>& levels, const glm::dvec3& direction, double lod);
// The level below: each texel the mean of the four above it (a cube of size 1 stays).
CubeImage downsampleCube(const CubeImage& cube);
// The cube at another size: halved (box) while at least four times `size` and even, then 4 x 4 bilinear
// samples a texel.
CubeImage resampleCube(const CubeImage& cube, int size);

// Equirectangular mapping as three.js's equirectUv (and so the .hdr panoramas other viewers read): u =
// atan2(z, x) / 2 pi + 0.5 across, v = asin(y) / pi + 0.5 up, so the top row looks up (+y), the image's middle
// column looks along +x and its left edge along -x.
glm::dvec2 equirectCoordinates(const glm::dvec3& direction);
glm::dvec3 equirectDirection(double u, double v);
// The cube of `size` sampled from the panorama, 4 x 4 bilinear samples per texel (wrapping across, clamped at
// the poles); and a panorama of `width` x width / 2 from a cube (bilinear, 2 x 2 samples per pixel).
CubeImage cubeFromEquirect(const ImageRGBFloat& equirect, int size);
ImageRGBFloat equirectFromCube(const CubeImage& cube, int width);

// The built-in environment: a neutral studio room (grey walls, a darker floor, a few bright panels, as three.js's
// RoomEnvironment), made per texel by intersecting the direction from the room's centre with its walls (4 x 4
// samples a texel); deterministic. Mean radiance about 1 (a white Lambert surface reads about 1 in it).
CubeImage makeRoomEnvironmentCube(int size = 128);

// 9 real spherical-harmonic basis functions (l <= 2) at a unit direction, in the order the shader reads them:
// 1, y, z, x, xy, yz, 3z^2 - 1, xz, x^2 - y^2 times their constants.
std::array<double, 9> shBasis(const glm::dvec3& direction);
// The irradiance coefficients of a radiance cube: its projection on the basis (every texel by its solid angle),
// convolved with the clamped cosine (pi, 2 pi / 3, pi / 4 per band), divided by pi and multiplied by the basis
// constants, so that E(n) / pi = c0 + c1 y + c2 z + c3 x + c4 xy + c5 yz + c6 (3 z^2 - 1) + c7 xz + c8 (x^2 - y^2)
// (irradianceOverPi): the diffuse term of a white Lambert surface, what shading.glsl evaluates.
std::array<glm::dvec3, 9> irradianceSh(const CubeImage& radiance);
glm::dvec3 irradianceOverPi(const std::array<glm::dvec3, 9>& sh, const glm::dvec3& normal);

// Throws lidr::Error "`what` must be a finite number >= 0, got X" for a negative or non-finite intensity.
void validateEnvironmentIntensity(float intensity, const std::string& what);

// Progress of a long step, one call per step done ("prefiltering level 2 of 4"); tools print it on stderr.
using EnvironmentProgress = std::function<void(const std::string&)>;

// What the renderer takes: the radiance prefiltered per roughness, the irradiance, where they came from.
struct Environment {
    std::string name;                          // "default" (the room) or the file
    std::vector<CubeImage> specular;           // level k: roughness k / (levels - 1), size halving from level 0
    std::array<glm::dvec3, 9> sh{};            // irradianceSh of the radiance
    float maxRadiance = 0.0f;                  // the brightest channel of level 0
    int levels() const { return int(specular.size()); }
};

constexpr int kEnvironmentSize = 128;       // level 0's face size (the mirror)
constexpr int kEnvironmentLevels = 5;       // roughness 0, 0.25, 0.5, 0.75, 1 at 128, 64, 32, 16, 8 texels
constexpr int kEnvironmentSamples = 96;     // GGX samples per prefiltered texel (Hammersley, filtered importance sampling)

// The GGX prefilter (the split-sum approximation's first sum, n = v = r): level 0 is `radiance` itself (roughness
// 0), level k the mean of radiance x n.l over GGX samples of roughness k / (levels - 1) (alpha = max(r^2, 0.01)
// as shading.glsl), each read from the radiance's box-filtered mip chain at the level its pdf covers (Krivanek
// and Colbert's filtered importance sampling), so few samples give no speckles. Deterministic (Hammersley).
// Throws lidr::Error for a size that is not a power of two of at least 2^(levels - 1) or a texel not finite
// or negative.
Environment prefilterEnvironment(const CubeImage& radiance, const std::string& name, int levels = kEnvironmentLevels,
                                 int samples = kEnvironmentSamples, const EnvironmentProgress& progress = {});

// The built-in environment, made once per process and shared (thread-safe): prefilterEnvironment of
// makeRoomEnvironmentCube().
std::shared_ptr<const Environment> defaultEnvironment();

// The split-sum table: (A, B) with the specular integral of a surface of F0 under uniform white light = F0 A + B,
// for n.v = i / (size - 1) across and roughness j / (size - 1) up (texel centres), GGX importance-sampled with
// shading.glsl's visibility term and alpha. Made once per process (deterministic).
struct SplitSumTable {
    int size = 0;
    std::vector<glm::dvec2> values;  // j x size + i
    glm::dvec2 at(int i, int j) const { return values[size_t(j) * size_t(size) + size_t(i)]; }
};
constexpr int kSplitSumSize = 32;
const SplitSumTable& splitSumTable();
// One entry computed directly (tests; the table's own values), with `samples` GGX samples.
glm::dvec2 splitSumIntegral(double nDotV, double roughness, int samples);

// How the GPU stores the data, and so what the CPU model reads back: half floats (RGB16F cube, RGBA16F table) where
// the context has float textures, else RGBM in RGBA8 (rgb / (m x range), m in 1/255 steps, range a power of two
// from 1 to kRgbmMaxRange: brighter texels are clipped there) and the table's two values in two bytes each.
enum class EnvironmentStorage { HalfFloat, Rgbm8 };
constexpr float kRgbmMaxRange = 64.0f;
float rgbmRange(const Environment& environment);  // the smallest power of two >= maxRadiance, in [1, kRgbmMaxRange]
float roundToHalf(float v);
// An RGBM texel: the four 8-bit channels (0..255); decoded from filtered (fractional) channels as the shader does.
glm::u8vec4 encodeRgbm(const glm::vec3& rgb, float range);
glm::dvec3 decodeRgbm(const glm::dvec4& channels, double range);
// The split-sum table's 16-bit storage in RGBA8: value = (hi x 256 + lo) / 65535, (hi, lo) of A then of B.
glm::u8vec4 encodeSplitSum16(const glm::dvec2& value);
glm::dvec2 decodeSplitSum16(const glm::dvec4& channels);

// The environment as the GPU holds it: every level's texels as stored (half-float RGB in xyz, w 1; or the RGBM
// bytes), the levels below the last roughness down to 1 x 1 (mipmap completeness on OpenGL ES 2.0: box-filtered,
// never read by the LOD lookup), and the split-sum table as stored. The upload (lidr/render/environment_maps.h)
// sends exactly these values and the CPU model (lidr/eval/brdf.h) filters them as GL does, then decodes.
struct StoredCube {
    int size = 0;
    std::vector<glm::vec4> texels;  // as CubeImage's; RGBM: the bytes as 0..255
    const glm::vec4& at(int face, int x, int y) const {
        return texels[(size_t(face) * size_t(size) + size_t(y)) * size_t(size) + size_t(x)];
    }
};
struct StoredEnvironment {
    EnvironmentStorage storage = EnvironmentStorage::HalfFloat;
    float range = 1.0f;              // RGBM's range (1 for half floats)
    int roughnessLevels = 0;         // the levels the lookup reads (LOD 0 .. roughnessLevels - 1)
    std::vector<StoredCube> levels;  // down to 1 x 1
    int tableSize = 0;
    std::vector<glm::vec4> table;    // half floats (A, B, 0, 1) or the 16-bit bytes as 0..255; j x size + i
};
StoredEnvironment storeEnvironment(const Environment& environment, EnvironmentStorage storage);
// The stored cube filtered as GL does (trilinear at `lod`, clamped to [0, roughnessLevels - 1], faces clamped at
// their edges) and decoded: the specular radiance the shader reads in direction `direction`.
glm::dvec3 sampleStoredSpecular(const StoredEnvironment& stored, const glm::dvec3& direction, double lod);
// The stored split-sum table filtered bilinearly at (n.v, roughness) as the shader looks it up, decoded.
glm::dvec2 sampleStoredSplitSum(const StoredEnvironment& stored, double nDotV, double roughness);

}  // namespace lidr
