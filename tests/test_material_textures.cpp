// Per-pixel material textures (issue 26): test models written as glTF by the test and loaded back, rendered in
// every mode; pixels checked against the CPU model of the BRDF (lidr/eval/brdf.h) with the texel the pixel
// reads, and every mode against the brute-force reference.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>

#include <catch2/catch.hpp>

#include "gl_test_context.h"
#include "gltf_file.h"
#include "lidr/base/colour.h"
#include "lidr/eval/brdf.h"
#include "lidr/modes/render_mode.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/render/output_transform.h"
#include "lidr/scene/io/scene_loader.h"
#include "render_helpers.h"
#include "temp_dir.h"

using namespace lidr;
using namespace lidr::test;

namespace {

// A 4 x 1 texture: texels 0 and 1 `left`, 2 and 3 `right`. Sampled (bilinear, REPEAT) at u in [0.15, 0.35]
// it is `left` exactly, at u in [0.65, 0.85] `right`.
ImageRGBA8 twoHalves(glm::u8vec4 left, glm::u8vec4 right) {
    ImageRGBA8 image(4, 1);
    for (int x = 0; x < 4; ++x)
        for (int c = 0; c < 4; ++c) image.pixels[size_t(4 * x + c)] = x < 2 ? left[c] : right[c];
    return image;
}

// The 2 x 2 m quad z = 0 facing +z, glTF texture coordinates with the image upright ((x + 1) / 2, (1 - y) / 2),
// with `material` (glTF JSON) using the images; the camera looks at it from z = +3 (or from behind: z = -3).
Scene quadScene(const TempDir& dir, const Json& material, const std::vector<ImageRGBA8>& images, bool fromBehind = false,
                const Json& extraAttributes = Json::object()) {
    GltfFile file;
    const int p = file.positions({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
    const std::vector<glm::vec3> normals(4, glm::vec3(0, 0, 1));
    const int n = file.accessor(normals.data(), 48, 5126, "VEC3", 4);
    const std::vector<float> uv = {0, 1, 1, 1, 1, 0, 0, 0};
    const int t = file.accessor(uv.data(), uv.size() * 4, 5126, "VEC2", 4);
    const int i = file.indices({0, 1, 2, 0, 2, 3});
    Json attributes = {{"POSITION", p}, {"NORMAL", n}, {"TEXCOORD_0", t}};
    for (auto it = extraAttributes.begin(); it != extraAttributes.end(); ++it) {
        const std::vector<float> values = it.value().get<std::vector<float>>();
        const int components = int(values.size() / 4);
        attributes[it.key()] = file.accessor(values.data(), values.size() * 4, 5126,
                                             components == 4 ? "VEC4" : "VEC2", 4);
    }
    file.mesh({{"attributes", attributes}, {"indices", i}, {"material", 0}});
    file.node({{"mesh", 0}}, true);
    for (const ImageRGBA8& image : images) file.pngImage(dir, image);
    file.doc["textures"] = Json::array();
    for (size_t k = 0; k < images.size(); ++k) file.doc["textures"].push_back({{"source", k}});
    file.doc["materials"] = Json::array({material});  // not {material}: clang takes that as a copy of the object
    Scene scene = loadScene(file.writeGltf(dir, "quad.gltf"));
    scene.camera.position = glm::vec3(0.0f, 0.0f, fromBehind ? -3.0f : 3.0f);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.fovYDegrees = 45.0f;
    scene.camera.nearPlane = 0.5f;
    scene.camera.farPlane = 10.0f;
    scene.width = testWidth();
    scene.height = testHeight();
    scene.ambient = glm::vec3(0.1f);
    scene.backgroundColor = glm::vec3(0.2f, 0.6f, 0.3f);
    scene.lights = {light({0.3f, 0.5f, 1.5f}, 6.0f, {1.0f, 0.9f, 0.8f})};
    return scene;
}

std::vector<std::string> testedModes() {
    std::vector<std::string> modes = {"forward-brute", "lidr", "clustered", "tiled"};
    if (testGl().gles) modes.pop_back();  // tiled's default depth bounds are refused on ES 2.0
    return modes;
}

ImageRGBA8 render(const Scene& scene, const std::string& mode, ImageFloat* depth = nullptr) {
    RenderModeOptions o;
    o.mode = mode;
    std::unique_ptr<Renderer> r = createRenderer(o, testGl(), scene, scene.width, scene.height);
    r->render(scene.camera, scene.lights, ShadingParameters{scene.ambient, scene.backgroundColor});
    if (depth) *depth = r->targets().readDepth();
    return r->targets().readColor();
}

// The expected 8-bit pixel of a surface point (linear light through lidr's output transform).
glm::dvec3 expectedPixel(const BrdfSurface& s, const Scene& scene, const glm::dvec3& emission = glm::dvec3(0.0),
                         double occlusion = 1.0) {
    glm::dvec3 linear = shadeAmbient(s, glm::dvec3(scene.ambient)) * occlusion + emission;
    for (const PointLight& l : scene.lights) linear += shadePointLight(s, l);
    return 255.0 * applyOutputTransform(linear, OutputTransform{});
}

int stepsApart(const uint8_t* got, const glm::dvec3& expected) {
    int e = 0;
    for (int k = 0; k < 3; ++k) e = std::max(e, int(std::lround(std::abs(double(got[k]) - expected[k]))));
    return e;
}

// For every pixel of the quad in the band of texture u in [lo, hi] (and v in [0.1, 0.9]): f(x, y, world position).
template <typename F>
long forBand(const Scene& scene, const ImageFloat& depth, double lo, double hi, F f) {
    const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
    long count = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            const float d = depth.at(x, y);
            if (d >= 1.0f) continue;
            const glm::vec3 p = unprojectPixel(cam, x, y, d);
            const double u = (p.x + 1.0) / 2.0, v = (p.y + 1.0) / 2.0;
            if (u < lo || u > hi || v < 0.1 || v > 0.9) continue;
            f(x, y, p);
            ++count;
        }
    return count;
}

// A 4 x 4 texture of four 2 x 2 quadrants, in image order (rows top to bottom): top left, top right, bottom left,
// bottom right.
ImageRGBA8 quadrants(const std::array<glm::u8vec4, 4>& colours) {
    ImageRGBA8 image(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            for (int c = 0; c < 4; ++c) image.pixels[size_t(4 * (4 * y + x) + c)] = colours[size_t(2 * (y / 2) + x / 2)][c];
    return image;
}

// The quadrant whose colour a bilinear, REPEAT lookup of quadrants() at glTF's (u, v) (v down the image) gives
// alone, or -1 where the lookup mixes two quadrants: per axis, both texels it blends lie in one half.
int cleanQuadrant(const glm::dvec2& uv) {
    int half[2];
    for (int a = 0; a < 2; ++a) {
        const double t = uv[a] * 4.0 - 0.5;  // texel centres at 0.5, 1.5, ...
        const int i0 = ((int(std::floor(t)) % 4) + 4) % 4, i1 = (i0 + 1) % 4;
        if (i0 / 2 != i1 / 2) return -1;
        half[a] = i0 / 2;
    }
    return 2 * half[1] + half[0];
}

// KHR_texture_transform's formula in glTF's texture space (the extension's text, not lidr's matrix):
// translation x rotation x scale, rotating counter-clockwise by `rotation` (v points down).
glm::dvec2 gltfTextureTransform(const glm::dvec2& uv, const glm::dvec2& offset, double rotation, const glm::dvec2& scale) {
    const glm::dvec2 s = uv * scale;
    return offset + glm::dvec2(std::cos(rotation) * s.x + std::sin(rotation) * s.y,
                               -std::sin(rotation) * s.x + std::cos(rotation) * s.y);
}

// What a slot's texel does to the surface the CPU model shades: base colour (sRGB), emission (sRGB), roughness
// and metallic (G, B), occlusion (R); the factors are 1 (emission: `emissive`).
struct TexelEffect {
    BrdfSurface surface;
    glm::dvec3 emission{0.0};
    double occlusion = 1.0;
};
TexelEffect texelEffect(const std::string& slot, const glm::u8vec4& texel, const glm::dvec3& emissive) {
    TexelEffect e;
    e.surface.baseColor = glm::dvec3(0.5), e.surface.metallic = 0.0, e.surface.roughness = 0.6;
    const glm::dvec3 decoded(srgbToLinear(texel.r / 255.0), srgbToLinear(texel.g / 255.0), srgbToLinear(texel.b / 255.0));
    if (slot == "base colour") e.surface.baseColor = decoded;
    if (slot == "emissive") e.emission = emissive * decoded;
    if (slot == "metallic-roughness") e.surface.roughness = texel.g / 255.0, e.surface.metallic = texel.b / 255.0;
    if (slot == "occlusion") e.occlusion = texel.r / 255.0;
    return e;
}

// The glTF material JSON of texelEffect's slot reading texture 0 through `transform` (KHR_texture_transform).
Json transformedSlotMaterial(const std::string& slot, const Json& transform, const glm::dvec3& emissive) {
    Json material = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1}}, {"metallicFactor", 0.0},
                                               {"roughnessFactor", 0.6}}}};
    const Json info = {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}};
    if (slot == "base colour") {
        material["pbrMetallicRoughness"]["baseColorFactor"] = {1, 1, 1, 1};
        material["pbrMetallicRoughness"]["baseColorTexture"] = info;
    } else if (slot == "emissive") {
        material["emissiveFactor"] = {emissive.r, emissive.g, emissive.b};
        material["emissiveTexture"] = info;
    } else if (slot == "metallic-roughness") {
        material["pbrMetallicRoughness"]["metallicFactor"] = 1.0;
        material["pbrMetallicRoughness"]["roughnessFactor"] = 1.0;
        material["pbrMetallicRoughness"]["metallicRoughnessTexture"] = info;
    } else {
        material["occlusionTexture"] = info;
    }
    return material;
}

// Every pixel of the quad whose transformed lookup lies in one quadrant, against the CPU model of that texel, and
// every mode against the reference. The quad reads TEXCOORD_1 = (1 - u, (1 + v) / 2) through the transform's
// texCoord override (the texture info itself names set 0).
// `extraMaterial` is merged into the material (other extensions); `adjust` changes the CPU model's surface and
// emission to match. Returns how many checked pixels the model shades more than 4 steps away from its
// unadjusted self (how much the other extensions show).
long checkTransformedSlot(const std::string& slot, const Json& extraMaterial = Json::object(),
                          const std::function<void(TexelEffect&)>& adjust = {},
                          const std::function<void(Scene&)>& setup = {}) {
    TempDir dir;
    const std::array<glm::u8vec4, 4> colours = {glm::u8vec4(255, 64, 0, 255), glm::u8vec4(0, 128, 255, 255),
                                                glm::u8vec4(32, 200, 64, 255), glm::u8vec4(220, 220, 120, 255)};
    const glm::dvec2 offset(0.3, -0.2), scale(1.7, 1.3);
    const double rotation = 0.7;
    const Json transform = {{"offset", {offset.x, offset.y}}, {"rotation", rotation}, {"scale", {scale.x, scale.y}},
                            {"texCoord", 1}};
    const glm::dvec3 emissive(0.5, 1.0, 0.25);
    Json material = transformedSlotMaterial(slot, transform, emissive);
    material.merge_patch(extraMaterial);
    Json extra = Json::object();
    extra["TEXCOORD_1"] = std::vector<float>{1, 1, 0, 1, 0, 0.5f, 1, 0.5f};  // (1 - u, (1 + v) / 2) of TEXCOORD_0
    Scene scene = quadScene(dir, material, {quadrants(colours)}, false, extra);
    if (slot == "occlusion") scene.ambient = glm::vec3(0.8f);
    if (setup) setup(scene);
    ImageFloat depth;
    const ImageRGBA8 reference = render(scene, "forward-brute", &depth);
    const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
    long count = 0, within = 0, perQuadrant[4] = {0, 0, 0, 0}, adjusted = 0;
    int worst = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            const float d = depth.at(x, y);
            if (d >= 1.0f) continue;
            const glm::vec3 p = unprojectPixel(cam, x, y, d);
            const glm::dvec2 uv0((p.x + 1.0) / 2.0, (1.0 - p.y) / 2.0);  // glTF's TEXCOORD_0 (v down)
            if (uv0.x < 0.02 || uv0.x > 0.98 || uv0.y < 0.02 || uv0.y > 0.98) continue;
            const glm::dvec2 uv1(1.0 - uv0.x, 0.5 + 0.5 * uv0.y);
            const int quadrant = cleanQuadrant(gltfTextureTransform(uv1, offset, rotation, scale));
            if (quadrant < 0) continue;
            TexelEffect e = texelEffect(slot, colours[size_t(quadrant)], emissive);
            e.surface.position = glm::dvec3(p);
            e.surface.normal = glm::dvec3(0, 0, 1);
            e.surface.toEye = glm::normalize(glm::dvec3(scene.camera.position) - e.surface.position);
            const glm::dvec3 unadjusted = expectedPixel(e.surface, scene, e.emission, e.occlusion);
            if (adjust) adjust(e);
            const glm::dvec3 expected = expectedPixel(e.surface, scene, e.emission, e.occlusion);
            adjusted += glm::length(expected - unadjusted) > 4.0;
            const int error = stepsApart(reference.at(x, y), expected);
            worst = std::max(worst, error);
            within += error <= 1;
            ++count, ++perQuadrant[quadrant];
        }
    INFO(slot << ": " << count << " pixels, " << within << " within 1 step, worst " << worst << "; per quadrant "
              << perQuadrant[0] << " " << perQuadrant[1] << " " << perQuadrant[2] << " " << perQuadrant[3] << "; "
              << adjusted << " moved more than 4 steps by the other extensions");
    REQUIRE(count > 400);
    for (long q : perQuadrant) CHECK(q > 20);  // the transform reaches every quadrant: offset, rotation and scale all act
    CHECK(within >= count * 99 / 100);
    CHECK(worst <= 3);
    for (const std::string& mode : testedModes()) {
        if (mode == "forward-brute") continue;
        INFO(mode);
        CHECK(render(scene, mode).pixels == reference.pixels);
    }
    return adjusted;
}

// KHR_materials_ior and KHR_materials_specular (JSON, merged into a material) with the surface's F0 and F90 that
// the extensions' text gives them (not lidr's DielectricSpecular::f0()).
struct DielectricCase {
    const char* what;
    Json extensions;
    glm::dvec3 f0;
    double f90;
};
std::vector<DielectricCase> dielectricCases() {
    const auto f0 = [](double ior) { return std::pow((ior - 1.0) / (ior + 1.0), 2.0); };
    return {
        {"ior 2.4", {{"KHR_materials_ior", {{"ior", 2.4}}}}, glm::dvec3(f0(2.4)), 1.0},
        {"ior 1 (no reflection at normal incidence)", {{"KHR_materials_ior", {{"ior", 1.0}}}}, glm::dvec3(0.0), 1.0},
        {"specular 0 (diffuse only)", {{"KHR_materials_specular", {{"specularFactor", 0.0}}}}, glm::dvec3(0.0), 0.0},
        {"specular 0.5, colour",
         {{"KHR_materials_specular", {{"specularFactor", 0.5}, {"specularColorFactor", {3.0, 1.0, 0.25}}}}},
         0.5 * glm::dvec3(0.12, 0.04, 0.01), 0.5},
        {"ior 0 with a specular colour (the specular-glossiness conversion)",
         {{"KHR_materials_ior", {{"ior", 0.0}}}, {"KHR_materials_specular", {{"specularColorFactor", {0.9, 0.6, 0.2}}}}},
         glm::dvec3(0.9, 0.6, 0.2), 1.0},
        {"ior 1.8 and specular 0.7 clamped", {{"KHR_materials_ior", {{"ior", 1.8}}},
                                              {"KHR_materials_specular", {{"specularFactor", 0.7}, {"specularColorFactor", {20.0, 1.0, 1.0}}}}},
         0.7 * glm::dvec3(1.0, f0(1.8), f0(1.8)), 0.7},
    };
}

}  // namespace

TEST_CASE("glTF extensions together: emissive strength, texture transform, ior and specular against the BRDF model, "
          "every mode as the reference", "[material-textures][every-gl]") {
    // One small quad: an emissive texture through KHR_texture_transform (offset, rotation, scale, the TEXCOORD_1
    // override), emissiveStrength 3 (the emission 3 times brighter in linear light), ior 2 and a coloured
    // specular at weight 0.6: F0 = min(((2 - 1) / (2 + 1))^2 x (2, 1, 0.5), 1) x 0.6, F90 = 0.6.
    testContext();
    const Json extensions = {{"KHR_materials_emissive_strength", {{"emissiveStrength", 3.0}}},
                             {"KHR_materials_ior", {{"ior", 2.0}}},
                             {"KHR_materials_specular", {{"specularFactor", 0.6}, {"specularColorFactor", {2.0, 1.0, 0.5}}}}};
    const long moved = checkTransformedSlot("emissive", {{"extensions", extensions}}, [](TexelEffect& e) {
        e.emission *= 3.0;
        e.surface.dielectricF0 = glm::dvec3(2.0, 1.0, 0.5) / 9.0 * 0.6;
        e.surface.dielectricF90 = 0.6;
    });
    CHECK(moved > 500);  // the extensions change most of the quad
}

TEST_CASE("KHR_materials_ior and KHR_materials_specular: F0 and F90 per the extensions, every mode as the reference",
          "[material-textures][slow]") {
    // Seen and lit at grazing angles from opposite sides, where F90 shows: v.h down to about 0.2, so the
    // Fresnel weight (1 - v.h)^5 reaches 0.3.
    testContext();
    const auto grazing = [](Scene& scene) {
        scene.camera.position = glm::vec3(0.0f, -3.2f, 0.9f);
        scene.camera.target = glm::vec3(0.0f, 0.2f, 0.0f);
        scene.lights.push_back(light({0.0f, 4.0f, 0.6f}, 12.0f, {3.0f, 3.0f, 3.0f}));
    };
    for (const DielectricCase& c : dielectricCases()) {
        DYNAMIC_SECTION(c.what) {
            const long moved = checkTransformedSlot("base colour", {{"extensions", c.extensions}}, [&](TexelEffect& e) {
                e.surface.dielectricF0 = c.f0;
                e.surface.dielectricF90 = c.f90;
            }, grazing);
            CHECK(moved > 100);
        }
    }
}

TEST_CASE("KHR_texture_transform: each slot's texture through offset, rotation, scale and texCoord, against a CPU "
          "lookup", "[material-textures][slow]") {
    testContext();
    const std::string slot = GENERATE(as<std::string>(), "base colour", "emissive", "metallic-roughness", "occlusion");
    DYNAMIC_SECTION(slot) { checkTransformedSlot(slot); }
}

TEST_CASE("material textures: each texture per pixel against the BRDF model, every mode as the reference",
          "[material-textures][every-gl]") {
    testContext();
    TempDir dir;
    const std::string texture = GENERATE(as<std::string>(), "emissive", "metallic-roughness", "occlusion");
    DYNAMIC_SECTION(texture) {
        Json material;
        std::vector<ImageRGBA8> images;
        // per half: the surface the CPU model shades, its emission and occlusion
        BrdfSurface halves[2];
        glm::dvec3 emission[2] = {glm::dvec3(0.0), glm::dvec3(0.0)};
        double occlusion[2] = {1.0, 1.0};
        for (BrdfSurface& s : halves) s.baseColor = glm::dvec3(0.5), s.metallic = 0.0, s.roughness = 0.6;
        if (texture == "emissive") {
            // a two-colour emissive texture gives two colours, not their mean; x factor x strength
            images = {twoHalves({255, 64, 0, 255}, {0, 128, 255, 255})};
            material = {{"emissiveFactor", {0.5, 1.0, 0.25}}, {"emissiveTexture", {{"index", 0}}},
                        {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2.0}}}}},
                        {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1}}, {"metallicFactor", 0.0},
                                                  {"roughnessFactor", 0.6}}}};
            const glm::dvec3 factor = glm::dvec3(0.5, 1.0, 0.25) * 2.0;
            emission[0] = factor * glm::dvec3(srgbToLinear(1.0), srgbToLinear(64 / 255.0), 0.0);
            emission[1] = factor * glm::dvec3(0.0, srgbToLinear(128 / 255.0), 1.0);
        } else if (texture == "metallic-roughness") {
            // G roughness, B metallic (linear): a rough dielectric and a smooth metal side by side
            images = {twoHalves({0, 255, 0, 255}, {0, 77, 255, 255})};
            material = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.6, 0.3, 1}}, {"metallicFactor", 1.0},
                                                  {"roughnessFactor", 1.0}, {"metallicRoughnessTexture", {{"index", 0}}}}}};
            for (BrdfSurface& s : halves) s.baseColor = glm::dvec3(0.9, 0.6, 0.3);
            halves[0].metallic = 0.0, halves[0].roughness = 1.0;
            halves[1].metallic = 1.0, halves[1].roughness = 77.0 / 255.0;
        } else {
            // R occlusion (linear) at strength 0.8, ambient light only; a strong ambient to see it
            images = {twoHalves({255, 0, 0, 255}, {51, 0, 0, 255})};
            material = {{"occlusionTexture", {{"index", 0}, {"strength", 0.8}}},
                        {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1}}, {"metallicFactor", 0.0},
                                                  {"roughnessFactor", 0.6}}}};
            occlusion[1] = 1.0 + 0.8 * (51.0 / 255.0 - 1.0);
        }
        if (texture == "emissive") material["emissiveTexture"]["index"] = 0;
        Scene scene = quadScene(dir, material, images);
        if (texture == "occlusion") scene.ambient = glm::vec3(0.8f);
        if (texture == "emissive") {
            std::string all;
            for (const std::string& w : scene.warnings) all += w + "\n";
            CHECK(all.find("mean") == std::string::npos);
        }
        ImageFloat depth;
        const ImageRGBA8 reference = render(scene, "forward-brute", &depth);
        glm::dvec3 sum[2] = {glm::dvec3(0.0), glm::dvec3(0.0)};
        for (int half = 0; half < 2; ++half) {
            long within = 0;
            int worst = 0;
            const long count = forBand(scene, depth, half ? 0.65 : 0.15, half ? 0.85 : 0.35, [&](int x, int y, glm::vec3 p) {
                BrdfSurface s = halves[half];
                s.position = glm::dvec3(p);
                s.normal = glm::dvec3(0, 0, 1);
                s.toEye = glm::normalize(glm::dvec3(scene.camera.position) - s.position);
                const int e = stepsApart(reference.at(x, y), expectedPixel(s, scene, emission[half], occlusion[half]));
                worst = std::max(worst, e);
                within += e <= 1;
                for (int k = 0; k < 3; ++k) sum[half][k] += reference.at(x, y)[k];
            });
            INFO(texture << " half " << half << ": " << count << " pixels, " << within << " within 1 step, worst " << worst);
            REQUIRE(count > 200);
            CHECK(within >= count * 99 / 100);
            CHECK(worst <= 3);
            sum[half] /= double(count);
        }
        // the two halves really differ (a texture drawn as its mean would not)
        CHECK(glm::length(sum[0] - sum[1]) > 20.0);
        for (const std::string& mode : testedModes()) {
            if (mode == "forward-brute") continue;
            INFO(mode);
            const ImageRGBA8 image = render(scene, mode);
            CHECK(image.pixels == reference.pixels);
        }
    }
}

TEST_CASE("normal texture: a normal-mapped plane lit from a known direction is the BRDF model's with the bent normal",
          "[material-textures][every-gl]") {
    testContext();
    TempDir dir;
    // Tangent-space normal (0.5, -0.3, 0.81) (normalised after 8-bit quantisation), scale 0.75, tangents from the
    // file or made from the UVs: +x along u, +y along the image's up.
    const bool fileTangents = GENERATE(false, true);
    DYNAMIC_SECTION((fileTangents ? "tangents from the file" : "generated tangents")) {
        const glm::dvec3 wanted = glm::normalize(glm::dvec3(0.5, -0.3, 0.81));
        glm::u8vec4 texel(0, 0, 0, 255);
        for (int k = 0; k < 3; ++k) texel[k] = uint8_t(std::lround((wanted[k] * 0.5 + 0.5) * 255.0));
        const Json material = {{"normalTexture", {{"index", 0}, {"scale", 0.75}}},
                               {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1}}, {"metallicFactor", 0.0},
                                                         {"roughnessFactor", 0.4}}}};
        Json extra = Json::object();
        if (fileTangents) extra["TANGENT"] = std::vector<float>{1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
        Scene scene = quadScene(dir, material, {twoHalves(texel, texel)}, false, extra);
        REQUIRE(scene.meshes[0].tangents.size() == (fileTangents ? 4u : 0u));
        glm::dvec3 m = glm::dvec3(texel) / 255.0 * 2.0 - 1.0;
        m.x *= 0.75, m.y *= 0.75;
        const glm::dvec3 bent = glm::normalize(m);  // tangent +x, bitangent +y, normal +z
        ImageFloat depth;
        const ImageRGBA8 reference = render(scene, "forward-brute", &depth);
        long within = 0, differs = 0;
        int worst = 0;
        const long count = forBand(scene, depth, 0.1, 0.9, [&](int x, int y, glm::vec3 p) {
            BrdfSurface s;
            s.baseColor = glm::dvec3(0.8);
            s.metallic = 0.0, s.roughness = 0.4;
            s.position = glm::dvec3(p);
            s.toEye = glm::normalize(glm::dvec3(scene.camera.position) - s.position);
            s.normal = bent;
            const int e = stepsApart(reference.at(x, y), expectedPixel(s, scene));
            worst = std::max(worst, e);
            within += e <= 1;
            s.normal = glm::dvec3(0, 0, 1);
            differs += stepsApart(reference.at(x, y), expectedPixel(s, scene)) > 4;
        });
        INFO(count << " pixels, " << within << " within 1 step, worst " << worst << ", " << differs
                   << " more than 4 steps from the unbent normal's");
        REQUIRE(count > 1000);
        CHECK(within >= count * 99 / 100);
        CHECK(worst <= 3);
        CHECK(differs > count / 2);  // the normal texture really bends the light
        for (const std::string& mode : testedModes()) {
            if (mode == "forward-brute") continue;
            INFO(mode);
            CHECK(render(scene, mode).pixels == reference.pixels);
        }
    }
}

TEST_CASE("alpha MASK and doubleSided: cut-out pixels and the back of a one-sided quad show the background",
          "[material-textures][every-gl]") {
    testContext();
    TempDir dir;
    const glm::u8vec3 background(uint8_t(std::lround(255.0 * applyOutputTransform(glm::dvec3(0.2, 0.6, 0.3), OutputTransform{}).r)),
                                 uint8_t(std::lround(255.0 * applyOutputTransform(glm::dvec3(0.2, 0.6, 0.3), OutputTransform{}).g)),
                                 uint8_t(std::lround(255.0 * applyOutputTransform(glm::dvec3(0.2, 0.6, 0.3), OutputTransform{}).b)));
    const auto isBackground = [&](const uint8_t* p) {
        return std::abs(p[0] - background.r) <= 1 && std::abs(p[1] - background.g) <= 1 && std::abs(p[2] - background.b) <= 1;
    };
    const std::string what = GENERATE(as<std::string>(), "cut-out", "one-sided from behind", "double-sided from behind");
    DYNAMIC_SECTION(what) {
        Json material = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.9, 0.9, 1}}, {"metallicFactor", 0.0},
                                                   {"roughnessFactor", 0.5}}}};
        std::vector<ImageRGBA8> images;
        if (what == "cut-out") {  // left half opaque white, right half alpha 0.2 < cutoff 0.4: cut out
            images = {twoHalves({255, 255, 255, 255}, {255, 255, 255, 51})};
            material["alphaMode"] = "MASK";
            material["alphaCutoff"] = 0.4;
            material["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
        }
        material["doubleSided"] = what != "one-sided from behind";
        const bool behind = what != "cut-out";
        Scene scene = quadScene(dir, material, images, behind);
        if (behind) scene.lights[0].position.z = -1.5f;  // the light on the eye's side
        // every mode, multi-pass forward too, against the background (the reference's depth names the pixels)
        ImageFloat depth;
        const ImageRGBA8 reference = render(scene, "forward-brute", &depth);
        std::vector<std::string> modes = testedModes();
        modes.push_back("forward-multipass");
        const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
        for (const std::string& mode : modes) {
            INFO(mode);
            const ImageRGBA8 image = mode == "forward-brute" ? reference : render(scene, mode);
            long quadPixels = 0, shown = 0, cut = 0, cutShown = 0;
            for (int y = 0; y < scene.height; ++y)
                for (int x = 0; x < scene.width; ++x) {
                    // where the quad's plane z = 0 lies under the pixel: the ray from the eye
                    const glm::vec3 nearPoint = unprojectPixel(cam, x, y, 0.0f), farPoint = unprojectPixel(cam, x, y, 1.0f);
                    const float t = nearPoint.z / (nearPoint.z - farPoint.z);
                    const glm::vec3 p = nearPoint + t * (farPoint - nearPoint);
                    const float u = (p.x + 1.0f) / 2.0f, v = (p.y + 1.0f) / 2.0f;
                    if (v < 0.1f || v > 0.9f) continue;
                    const bool background = isBackground(image.at(x, y));
                    if (u > 0.65f && u < 0.85f) ++cut, cutShown += !background;
                    if (u > 0.15f && u < 0.35f) ++quadPixels, shown += !background;
                }
            REQUIRE(quadPixels > 200);
            REQUIRE(cut > 200);
            if (what == "cut-out") {
                CHECK(shown == quadPixels);  // the opaque half is drawn and lit
                CHECK(cutShown == 0);        // the cut half is the background, in every mode
            } else if (what == "one-sided from behind") {
                CHECK(shown + cutShown == 0);  // nothing of it from behind
            } else {
                CHECK(shown == quadPixels);
                CHECK(cutShown == cut);
            }
            if (mode == "lidr" || mode == "tiled" || mode == "clustered") CHECK(image.pixels == reference.pixels);
        }
        if (what == "cut-out") {  // LIDR's light lists against the reference, pixel by pixel
            LidrOptions options;
            const RenderResult result = renderAndEvaluate(scene, options);
            requireExactWithinBudget(result.evaluation, what);
        }
    }
}

TEST_CASE("material variants: a context with fewer texture units leaves out the textures that do not fit",
          "[material-textures][every-gl]") {
    testContext();
    TempDir dir;
    const Json material = {{"emissiveFactor", {1, 1, 1}}, {"emissiveTexture", {{"index", 0}}},
                           {"occlusionTexture", {{"index", 0}}},
                           {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}};
    const Scene scene = quadScene(dir, material, {twoHalves({255, 0, 0, 255}, {0, 0, 255, 255})});
    GpuScene::setTextureUnitLimitForTests(13);  // units 0..12: base colour (11) and emissive (12) fit
    const GpuScene limited(scene);
    GpuScene::setTextureUnitLimitForTests(0);
    const uint32_t features = limited.materialFeatures(size_t(scene.meshes[0].material));
    CHECK((features & material_feature::texture(TextureSlot::BaseColor)) != 0);
    CHECK((features & material_feature::texture(TextureSlot::Emissive)) != 0);
    CHECK((features & material_feature::texture(TextureSlot::Occlusion)) == 0);
    REQUIRE(limited.warnings().size() == 1);
    CHECK_THAT(limited.warnings()[0], Catch::Contains("occlusion texture is not drawn") && Catch::Contains("unit 14"));
    CHECK(textureUnitWarnings(scene, 13) == limited.warnings());  // what tools print before drawing
    // The context's own units: Mesa's (desktop GL and ES 2.0 alike) has room for every material texture.
    const int units = testGl().maxTextureUnits;
    CAPTURE(units);
    const GpuScene full(scene);
    size_t leftOut = 0;
    for (const TextureSlot slot : {TextureSlot::BaseColor, TextureSlot::Emissive, TextureSlot::Occlusion})
        leftOut += textureSlotInfo(slot).unit >= units;
    CHECK(full.warnings().size() == leftOut);
    CHECK(((full.materialFeatures(size_t(scene.meshes[0].material)) & material_feature::texture(TextureSlot::Occlusion)) != 0) ==
          (gl::kUnitOcclusion < units));
}
