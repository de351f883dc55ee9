#pragma once
// Scene data: what every render mode (LIDR, tiled, forward) draws. Geometry is stored in world space (model
// transforms are applied when a scene is built), lights are evaluated for a time with Scene::lightsAt().
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "lidr/base/image.h"
#include "lidr/scene/animation.h"
#include "lidr/scene/environment.h"

namespace lidr {

// Where a texture is sampled: texture coordinate set 0 or 1 (glTF TEXCOORD_n), moved by a 3x3 transform
// (KHR_texture_transform, already in lidr's texture space, v up: uv' = (transform * (uv, 1)).xy).
struct TextureMapping {
    int texCoord = 0;
    glm::mat3 transform{1.0f};
    bool operator==(const TextureMapping& o) const { return texCoord == o.texCoord && transform == o.transform; }
};

// A material texture besides the base colour (glTF's emissive, metallic-roughness, occlusion and normal textures):
// the decoded image, the name it had (a path, or file#imageN for an embedded one), where it is sampled, and a
// `scale`: the normal texture's scale, the occlusion texture's strength (unused by the others).
struct MaterialTexture {
    std::string name;
    std::shared_ptr<const ImageRGBA8> image{};
    TextureMapping mapping;
    float scale = 1.0f;
    bool present() const { return bool(image); }
    bool operator==(const MaterialTexture& o) const {
        return name == o.name && image == o.image && mapping == o.mapping && scale == o.scale;
    }
};

enum class AlphaMode { Opaque, Mask };  // glTF's OPAQUE and MASK (BLEND is opacity < 1)

// The dielectric part's specular reflection (glTF's KHR_materials_ior and KHR_materials_specular): at normal
// incidence F0 = min(((ior - 1) / (ior + 1))^2 x color, 1) x weight, at grazing angles F90 = weight; a metal's stay
// its base colour and 1. The defaults are glTF 2.0's core model: ior 1.5 (F0 0.04), weight 1, white. A material
// with other values is drawn by the shader variant that reads them (lidr/render/material_variants.h).
struct DielectricSpecular {
    float ior = 1.5f;        // >= 1, or 0 (F0 1: the extension's conversion of specular-glossiness materials)
    float weight = 1.0f;     // KHR_materials_specular's specularFactor, [0, 1]
    glm::vec3 color{1.0f};   // its specularColorFactor (linear), >= 0
    glm::vec3 f0() const;
    float f90() const { return weight; }
    // glTF's core model (F0 0.04, F90 1): drawn by the code every material without the extensions runs.
    bool isDefault() const { return ior == 1.5f && weight == 1.0f && color == glm::vec3(1.0f); }
    bool operator==(const DielectricSpecular& o) const { return ior == o.ior && weight == o.weight && color == o.color; }
};

// Colours are linear (importers decode display-value colours: doc/colour.md); textures are sRGB-encoded.
struct Material {
    std::string name;
    glm::vec3 diffuse{0.8f};
    std::string diffuseTexture;  // path (resolved against the scene file's folder); empty: none
    glm::vec3 specular{0.25f};
    float shininess = 32.0f;
    float opacity = 1.0f;        // < 1: transparent, drawn after opaque geometry
    glm::vec3 emissive{0.0f};    // light the surface gives off itself, added to the ambient term (MTL Ke, glTF emissive)
    // The texture's pixels when the importer decoded them (glTF images, embedded ones included; rows top to
    // bottom like a file): used instead of reading diffuseTexture, which then only names the image.
    std::shared_ptr<const ImageRGBA8> diffuseImage{};
    // glTF metallic-roughness (the one shading model, shaders/common/shading.glsl): with metallicRoughness
    // true, `diffuse` is the base colour and these two are used as they are; false (OBJ/MTL, scene files, code
    // written for Blinn-Phong) maps specular and shininess onto them (metallicRoughnessOf).
    bool metallicRoughness = false;
    float metallic = 0.0f;   // [0, 1]
    float roughness = 1.0f;  // [0, 1], perceptual (alpha = roughness^2)
    // Per-pixel textures (glTF), each drawn by the shader variant that has it (lidr/render/material_variants.h).
    TextureMapping diffuseMapping{};     // of the base colour texture (sRGB)
    MaterialTexture emissiveTexture{};   // sRGB, times `emissive`
    MaterialTexture metallicRoughnessTexture{};  // linear: G x roughness, B x metallic
    MaterialTexture occlusionTexture{};  // linear: R, mixed in by `scale` (glTF's strength); ambient light only
    MaterialTexture normalTexture{};     // linear, tangent space; `scale` scales its x and y
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;            // MASK: texture alpha below it is cut out (glTF's cutoff / factor alpha)
    bool doubleSided = true;             // false: the back of each triangle is culled (glTF's default is false)
    DielectricSpecular dielectric{};     // KHR_materials_ior and KHR_materials_specular (their factors)
};

// The material as the BRDF takes it. Blinn-Phong materials map (doc/colour.md, "Materials"): roughness from
// the exponent by matching the lobe, alpha^2 = 2 / (shininess + 2); a chromatic, strong specular colour
// (largest channel above 0.25, (max - min) / max above 0.2: gold, copper) makes a metal whose base colour is
// that specular colour; otherwise a dielectric (F0 0.04) with the diffuse colour as base.
struct MetallicRoughness {
    glm::vec3 baseColor{0.8f};
    float metallic = 0.0f, roughness = 1.0f;
};
MetallicRoughness metallicRoughnessOf(const Material& material);

// One draw batch: triangles of one material, world space.
struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> texCoords;  // empty or one per position
    std::vector<uint32_t> indices;     // triangles
    int material = 0;
    std::vector<glm::vec2> texCoords1{};  // the second set (glTF TEXCOORD_1): empty or one per position
    std::vector<glm::vec4> tangents{};    // empty or one per position: xyz unit tangent along +u, w = +-1 handedness
    size_t triangleCount() const { return indices.size() / 3; }
};

// How a point or spot light fades with distance d; either way it gives exactly nothing from d = radius on, so
// the radius is its light volume (LIDR's lists, the tiles, the CPU truth in lidr/eval/light_coverage.h).
enum class LightFalloff {
    Smooth,         // lidr's own: colour x saturate(1 - d^2 / r^2) (scene files, built-in scenes)
    InverseSquare,  // KHR_lights_punctual: colour x saturate(1 - (d / r)^4) / max(d^2, 1e-4) (glTF lights)
};

// A point light, or, with outerConeAngle > 0, a spot light (KHR_lights_punctual): light leaves `position` only
// inside the cone around `direction`, full between the axis and innerConeAngle, falling smoothly to nothing at
// outerConeAngle (KHR_lights_punctual's falloff, squared linear in the cosine: spotCone()). Both are indexed;
// `radius` (the range) bounds both. A spot light is indexed by its cone: the sphere volume test tests the cone,
// the stencil and front-face tests draw a closed cone mesh, tiled forward assigns it to tiles by its cone; the
// volume tiles and the sphere-ray front-face lists use its bounding sphere (doc/architecture.md, "Light types"):
// the shading's cone term is exactly 0 outside the cone, so lists that hold more only cost slots.
struct PointLight {
    glm::vec3 position{0.0f};
    float radius = 1.0f;
    glm::vec3 color{1.0f};
    float priority = 0.0f;  // higher is kept first when a pixel has more lights than the budget
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // spot lights: the cone's axis, the way the light shines
    float innerConeAngle = 0.0f;             // radians, [0, outerConeAngle)
    float outerConeAngle = 0.0f;             // radians, (0, pi/2] for a spot light; 0: a point light
    LightFalloff falloff = LightFalloff::Smooth;  // InverseSquare: colour is (lux at 1 m) / pi (doc/colour.md)
    bool castsShadow = false;  // drawn into the shadow atlas when the frame's ShadowSettings are enabled
    bool isSpot() const { return outerConeAngle > 0.0f; }
};

// A light's cone term as the shaders take it (shading.glsl, lidrShadeLight): (unit direction x scale, offset)
// with scale = 1 / max(1e-3, cos inner - cos outer) and offset = -cos outer x scale, so the term is
// saturate(dot(-L, xyz) + w)^2 for L towards the light; (0, 0, 0, 1) for a point light (the term is 1).
glm::vec4 spotCone(const PointLight& light);

// A light infinitely far away (the sun): the same direction and colour at every point, so it touches every
// pixel and is not indexed. Every mode adds up to maxDirectionalLights of them in its forward pass, as uniforms,
// through the one shading function (shaders/common/shading.glsl, lidrDirectionalLights), so the modes stay equal
// to the reference (doc/architecture.md, "Light types").
struct DirectionalLight {
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // the way the light travels (need not be unit length; not zero)
    glm::vec3 color{1.0f};                   // linear; what a white Lambert surface facing the light gives
};

// How a light moves. Closed-form in time, so a frame is the same for the same (seed, time).
struct LightPath {
    enum class Kind { Static, Orbit, Bounce };
    Kind kind = Kind::Static;
    // Static: the rest position.
    // Orbit: position = center + orbitRadius * (cos, 0, sin)(a) + (0, bobAmplitude * sin(0.7 a), 0) with
    // a = phase + angularSpeed * t; the rest position is not used (the light is there at t = 0).
    glm::vec3 center{0.0f};
    float orbitRadius = 0.0f, angularSpeed = 0.0f, phase = 0.0f, bobAmplitude = 0.0f;
    // Bounce: starts at the rest position, moves with velocity, reflected by the box [boxMin, boxMax]
    // (a triangle wave per axis; an axis where boxMin == boxMax stays at boxMin).
    glm::vec3 velocity{0.0f}, boxMin{0.0f}, boxMax{0.0f};
};

struct Camera {
    glm::vec3 position{0.0f, 2.0f, 8.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDegrees = 60.0f;
    float nearPlane = 0.1f;
    float farPlane = 100.0f;
};

// A camera a model file brings: a glTF camera, by its index in the file's `cameras`, seen from the first node of the
// default scene (in node order) that places it, looking down the node's -z with its +y up. `camera` is set where
// lidr can draw it, a perspective camera placed by a node; otherwise `unusable` says why (orthographic: lidr's
// light volumes and tiles assume a perspective projection; placed by no node: there is nothing to view from).
struct SceneView {
    std::string name;      // "camera 1 'Top'"
    Camera camera;         // yfov, znear, zfar of the file (no zfar: a far plane past the scene's bounds)
    std::string unusable;  // empty: lidr draws it
};

// Limits every scene is checked against before any work (doc/scene-format.md, "Limits").
constexpr size_t maxSceneLights = 65535;           // the light index is 16 bits; 0 is the null light
constexpr float maxLightRadius = 1e18f;            // radius^2 and position +- radius stay finite floats
constexpr size_t maxDirectionalLights = 4;         // uniforms of every forward shader (a fixed loop bound)
constexpr size_t maxSceneTriangles = 20000000;     // 20 M: about 1.4 GB of vertex data on the CPU side alone
constexpr int maxPrimitiveSubdivisions = 256;      // box: 6 x 256^2 x 2 = 786,432 triangles
constexpr int maxPrimitiveSegments = 1024;         // torus: 1024 x 1024 x 2 = 2 M triangles

struct Scene {
    std::string name = "unnamed";
    std::vector<Material> materials;
    std::vector<Mesh> meshes;
    // Light i has index i + 1 in the index texture; 0 is the null light. Positions are REST positions
    // (t = 0): paths start from them, so draw lightsAt(time), not `lights`, for the current frame.
    std::vector<PointLight> lights;
    std::vector<LightPath> lightPaths;   // empty (all static), or one per light
    std::vector<DirectionalLight> directionalLights;  // at most maxDirectionalLights; not indexed, not moved
    Camera camera;
    // A glTF model's cameras, by their index in the file's `cameras`; a scene file's glTF models' cameras, in
    // model order (empty for OBJ and built-in scenes). `camera` is the first usable one met in node order (in a
    // scene file: unless it gives "camera"), else the default view framing the bounds; chooseView
    // (lidr/scene/io/scene_loader.h) picks another. `view`: the index of the one `camera` was set from, -1: none.
    std::vector<SceneView> views;
    int view = -1;
    int width = 1024, height = 768;
    float time = 0.0f;                   // the time this scene is shown at: lightsAt(time); its geometry is posed there
    // Keyframe animation (lidr/scene/animation.h): nodes moving meshes, lights and the camera over time. Empty for a
    // scene without one. poseScene(scene, t) moves the scene to t; meshTransformsAt / lightsAt / cameraAt give a
    // frame at t without changing it.
    SceneAnimation animation;
    std::string renderMode = "lidr";     // the mode tools render it with (lidr/modes/render_mode.h names them)
    glm::vec3 ambient{0.04f};
    glm::vec3 backgroundColor{0.0f};
    // The image-based environment light (issue 39, lidr/scene/environment.h): none unless asked for (scene files'
    // "environment"; tools give glTF and OBJ models the default one, doc/colour.md). Added to the ambient.
    std::shared_ptr<const Environment> environment{};
    float environmentIntensity = 1.0f;  // finite, >= 0 (validate)
    // How the scene asks to be rendered (tools may override): MSAA samples (0 = off) and whether
    // transparent materials are drawn (after the opaque geometry, back to front).
    int msaaSamples = 0;
    bool transparency = true;
    // What the importers read but could not honour as asked (a missing .mtl, a spot light, ...), one line
    // each naming the file; tools print them (lidr-demo's summary).
    std::vector<std::string> warnings;

    size_t triangleCount() const;
    glm::vec3 boundsMin() const;  // of the geometry
    glm::vec3 boundsMax() const;
    // The lights at time t (paths applied, lights carried by animation nodes placed). Same t, same result.
    std::vector<PointLight> lightsAt(float t) const;
    // Throws lidr::Error describing the first problem: non-finite or negative values, bad indices,
    // zero or oversized resolution, bad camera (including a position or target so far out that the view
    // basis overflows float), more than maxSceneLights lights (the widest light index), a light radius above
    // maxLightRadius, a bad directional light (validateDirectionalLights), more than maxSceneTriangles triangles.
    void validate(int maxResolution = 16384) const;
};

// A direction a light may have: finite, of length in [1e-18, 1e18], so its square is a normal float and it
// normalises (spot axes, directional lights).
bool isUsableDirection(const glm::vec3& direction);

// Throws lidr::Error naming the first bad directional light: more than maxDirectionalLights, a direction not
// finite or zero (or too long to normalise in float), a colour not finite or negative. Scene::validate and
// every mode's render() (through ShadingParameters) call it.
void validateDirectionalLights(const std::vector<DirectionalLight>& lights);

// The index of a material equal to `material` (name and every value), adding it if there is none: loading
// the same model twice reuses its materials instead of adding copies.
int findOrAddMaterial(Scene& scene, const Material& material);
// Geometry without a material gets the scene's "default" material, which a scene file may define itself;
// one with Material's defaults is added if the scene has none.
int findOrAddDefaultMaterial(Scene& scene);

glm::vec3 evaluatePath(const LightPath& path, const glm::vec3& restPosition, float t);

// Checks an object added to a renderer after construction (Renderer::addObject): the mesh as Scene::validate
// checks a scene's meshes (its `material` index is ignored: the object brings its material) and the material.
// Throws lidr::Error naming the problem.
void validateObject(const Mesh& mesh, const Material& material);

}  // namespace lidr
