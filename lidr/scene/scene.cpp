#include "lidr/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "lidr/base/error.h"
#include "lidr/scene/camera.h"

namespace lidr {

namespace {

constexpr size_t maxLights = maxSceneLights;
constexpr double kHalfPi = 1.57079632679489661923;

std::string str(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

std::string str(const glm::vec3& v) { return "(" + str(v.x) + ", " + str(v.y) + ", " + str(v.z) + ")"; }

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

[[noreturn]] void fail(const std::string& item, const std::string& problem) { throw Error(item + ": " + problem); }

void requireFinite(const std::string& item, const char* field, const glm::vec3& v) {
    if (!isFinite(v)) fail(item, std::string(field) + " must be finite, got " + str(v));
}

void requireFinite(const std::string& item, const char* field, float v) {
    if (!std::isfinite(v)) fail(item, std::string(field) + " must be finite, got " + str(v));
}

void requireColor(const std::string& item, const char* field, const glm::vec3& c) {
    if (!isFinite(c) || c.x < 0.0f || c.y < 0.0f || c.z < 0.0f)
        fail(item, std::string(field) + " must be finite and >= 0, got " + str(c));
}

void requirePositive(const std::string& item, const char* field, float v) {
    if (!std::isfinite(v) || v <= 0.0f) fail(item, std::string(field) + " must be finite and > 0, got " + str(v));
}

// Position of one axis moving at `speed` from `start`, reflected at lo and hi: a triangle wave with period
// 2 (hi - lo). Computed in double so long times keep their precision.
float bounceAxis(float start, float speed, float lo, float hi, float t) {
    const double length = double(hi) - double(lo);
    if (length <= 0.0) return lo;
    double unfolded = std::fmod(double(start) - lo + double(speed) * t, 2.0 * length);
    if (unfolded < 0.0) unfolded += 2.0 * length;
    return float(lo + (unfolded <= length ? unfolded : 2.0 * length - unfolded));
}

void validateMaterial(const Material& material, size_t index) {
    const std::string item = "material " + std::to_string(index) + " '" + material.name + "'";
    requireColor(item, "diffuse", material.diffuse);
    requireColor(item, "specular", material.specular);
    requirePositive(item, "shininess", material.shininess);
    requireColor(item, "emissive", material.emissive);
    if (!(material.metallic >= 0.0f && material.metallic <= 1.0f))
        fail(item, "metallic must be in [0, 1], got " + str(material.metallic));
    if (!(material.roughness >= 0.0f && material.roughness <= 1.0f))
        fail(item, "roughness must be in [0, 1], got " + str(material.roughness));
    if (!(material.opacity >= 0.0f && material.opacity <= 1.0f))
        fail(item, "opacity must be in [0, 1], got " + str(material.opacity));
    if (material.diffuseImage) {
        const ImageRGBA8& image = *material.diffuseImage;
        if (image.width <= 0 || image.height <= 0 || image.pixels.size() != size_t(image.width) * size_t(image.height) * 4)
            fail(item, "texture image is " + std::to_string(image.width) + "x" + std::to_string(image.height) + " with " +
                           std::to_string(image.pixels.size()) + " bytes");
    }
    const std::pair<const char*, const MaterialTexture*> textures[] = {
        {"emissive", &material.emissiveTexture}, {"metallic-roughness", &material.metallicRoughnessTexture},
        {"occlusion", &material.occlusionTexture}, {"normal", &material.normalTexture}};
    for (const auto& [what, texture] : textures) {
        if (texture->image) {
            const ImageRGBA8& image = *texture->image;
            if (image.width <= 0 || image.height <= 0 || image.pixels.size() != size_t(image.width) * size_t(image.height) * 4)
                fail(item, std::string(what) + " texture image is " + std::to_string(image.width) + "x" +
                               std::to_string(image.height) + " with " + std::to_string(image.pixels.size()) + " bytes");
        }
        if (texture->mapping.texCoord != 0 && texture->mapping.texCoord != 1)
            fail(item, std::string(what) + " texture reads texture coordinate set " +
                           std::to_string(texture->mapping.texCoord) + "; lidr has sets 0 and 1");
        if (!std::isfinite(texture->scale)) fail(item, std::string(what) + " texture scale is not finite");
    }
    if (!(material.alphaCutoff >= 0.0f && std::isfinite(material.alphaCutoff)))
        fail(item, "alphaCutoff must be finite and >= 0, got " + str(material.alphaCutoff));
    const DielectricSpecular& d = material.dielectric;
    if (!(std::isfinite(d.ior) && (d.ior == 0.0f || d.ior >= 1.0f)))
        fail(item, "ior must be finite and >= 1, or 0, got " + str(d.ior));
    if (!(d.weight >= 0.0f && d.weight <= 1.0f)) fail(item, "specular weight must be in [0, 1], got " + str(d.weight));
    requireColor(item, "specular colour", d.color);
}

void validateMesh(const Mesh& mesh, size_t index, size_t materialCount) {
    const std::string item = "mesh " + std::to_string(index) + " '" + mesh.name + "'";
    if (mesh.material < 0 || size_t(mesh.material) >= materialCount)
        fail(item, "material " + std::to_string(mesh.material) + " out of range (the scene has " +
                       std::to_string(materialCount) + " materials)");
    if (mesh.normals.size() != mesh.positions.size())
        fail(item, std::to_string(mesh.normals.size()) + " normals for " + std::to_string(mesh.positions.size()) +
                       " positions; need one per position");
    if (!mesh.texCoords.empty() && mesh.texCoords.size() != mesh.positions.size())
        fail(item, std::to_string(mesh.texCoords.size()) + " texCoords for " +
                       std::to_string(mesh.positions.size()) + " positions; need none or one per position");
    if (!mesh.texCoords1.empty() && mesh.texCoords1.size() != mesh.positions.size())
        fail(item, std::to_string(mesh.texCoords1.size()) + " texCoords1 for " +
                       std::to_string(mesh.positions.size()) + " positions; need none or one per position");
    if (!mesh.tangents.empty() && mesh.tangents.size() != mesh.positions.size())
        fail(item, std::to_string(mesh.tangents.size()) + " tangents for " + std::to_string(mesh.positions.size()) +
                       " positions; need none or one per position");
    if (mesh.indices.size() % 3 != 0)
        fail(item, "index count " + std::to_string(mesh.indices.size()) + " is not a multiple of 3");
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        if (!isFinite(mesh.positions[i])) fail(item, "position " + std::to_string(i) + " is not finite: " + str(mesh.positions[i]));
        if (!isFinite(mesh.normals[i])) fail(item, "normal " + std::to_string(i) + " is not finite: " + str(mesh.normals[i]));
    }
    for (size_t i = 0; i < mesh.texCoords.size(); ++i)
        if (!std::isfinite(mesh.texCoords[i].x) || !std::isfinite(mesh.texCoords[i].y))
            fail(item, "texCoord " + std::to_string(i) + " is not finite");
    for (size_t i = 0; i < mesh.indices.size(); ++i)
        if (mesh.indices[i] >= mesh.positions.size())
            fail(item, "index " + std::to_string(i) + " is " + std::to_string(mesh.indices[i]) + ", out of range (" +
                           std::to_string(mesh.positions.size()) + " positions)");
}

void validateLight(const PointLight& light, size_t index) {
    const std::string item = "light " + std::to_string(index);
    requireFinite(item, "position", light.position);
    requirePositive(item, "radius", light.radius);
    if (light.radius > maxLightRadius)
        fail(item, "radius " + str(light.radius) + " is too large (limit " + str(maxLightRadius) + ")");
    if (!isFinite(light.position + glm::vec3(light.radius)) || !isFinite(light.position - glm::vec3(light.radius)))
        fail(item, "bounds position " + str(light.position) + " +- radius " + str(light.radius) + " overflow float");
    requireColor(item, "color", light.color);
    requireFinite(item, "priority", light.priority);
    if (!(light.outerConeAngle >= 0.0f && light.outerConeAngle <= float(kHalfPi)))
        fail(item, "outer cone angle " + str(light.outerConeAngle) + " must be in [0, pi/2] (0: a point light)");
    if (light.isSpot()) {
        if (!(light.innerConeAngle >= 0.0f && light.innerConeAngle < light.outerConeAngle))
            fail(item, "inner cone angle " + str(light.innerConeAngle) + " must be in [0, outer cone angle " +
                           str(light.outerConeAngle) + ")");
        requireFinite(item, "direction", light.direction);
        if (!isUsableDirection(light.direction))
            fail(item, "spot direction " + str(light.direction) + " has length " + str(glm::length(light.direction)) +
                           "; it must be between 1e-18 and 1e18");
    }
}

}  // namespace

bool isUsableDirection(const glm::vec3& direction) {
    const float length = glm::length(direction);  // NaN or infinite for a direction not finite
    return length >= 1e-18f && length <= 1e18f;
}

void validateDirectionalLights(const std::vector<DirectionalLight>& lights) {
    if (lights.size() > maxDirectionalLights)
        fail("directional lights", std::to_string(lights.size()) + " directional lights; at most " +
                                       std::to_string(maxDirectionalLights) +
                                       " are supported (uniforms of every forward shader)");
    for (size_t i = 0; i < lights.size(); ++i) {
        const std::string item = "directional light " + std::to_string(i);
        requireFinite(item, "direction", lights[i].direction);
        if (!isUsableDirection(lights[i].direction))
            fail(item, "direction " + str(lights[i].direction) + " has length " + str(glm::length(lights[i].direction)) +
                           "; it must be between 1e-18 and 1e18 (the way the light travels)");
        requireColor(item, "color", lights[i].color);
    }
}

namespace {

void validatePath(const LightPath& path, size_t index) {
    const std::string item = "light path " + std::to_string(index);
    requireFinite(item, "center", path.center);
    requireFinite(item, "orbitRadius", path.orbitRadius);
    requireFinite(item, "angularSpeed", path.angularSpeed);
    requireFinite(item, "phase", path.phase);
    requireFinite(item, "bobAmplitude", path.bobAmplitude);
    requireFinite(item, "velocity", path.velocity);
    requireFinite(item, "boxMin", path.boxMin);
    requireFinite(item, "boxMax", path.boxMax);
    if (path.kind == LightPath::Kind::Bounce &&
        (path.boxMin.x > path.boxMax.x || path.boxMin.y > path.boxMax.y || path.boxMin.z > path.boxMax.z))
        fail(item, "bounce box min " + str(path.boxMin) + " exceeds max " + str(path.boxMax));
}

void validateCamera(const Camera& camera) {
    const std::string item = "camera";
    requireFinite(item, "position", camera.position);
    requireFinite(item, "target", camera.target);
    requireFinite(item, "up", camera.up);
    requireFinite(item, "fov", camera.fovYDegrees);
    requireFinite(item, "near", camera.nearPlane);
    requireFinite(item, "far", camera.farPlane);
    if (!(camera.fovYDegrees > 0.0f && camera.fovYDegrees < 180.0f))
        fail(item, "fov must be in (0, 180) degrees, got " + str(camera.fovYDegrees));
    if (!(camera.nearPlane > 0.0f)) fail(item, "near must be > 0, got " + str(camera.nearPlane));
    if (!(camera.farPlane > camera.nearPlane))
        fail(item, "far (" + str(camera.farPlane) + ") must be > near (" + str(camera.nearPlane) + ")");
    const glm::vec3 view = camera.target - camera.position;
    if (glm::length(view) == 0.0f) fail(item, "position and target are the same point " + str(camera.position));
    // Before the parallel test: an overflowing view direction normalises to NaN or zero, which is not "parallel".
    // glm::normalize squares the components: a direction longer than about 1.8e19 overflows to a zero vector.
    if (!isFinite(view) || !std::isfinite(glm::length(view)))
        fail(item, "target - position overflows float (position " + str(camera.position) + ", target " +
                       str(camera.target) + "; its length must stay below about 1.8e19): the view basis is not finite");
    if (glm::length(glm::cross(glm::normalize(view), camera.up)) < 1e-6f)
        fail(item, "up " + str(camera.up) + " is zero or parallel to the view direction");
    // The view matrix holds -dot(axis, position): finite inputs near the float range can still overflow it.
    const CameraMatrices m = cameraMatrices(camera, 1, 1);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m.view[c][r]))
                fail(item, "position " + str(camera.position) + " and target " + str(camera.target) +
                               " overflow float in the view basis (the view matrix is not finite)");
}

}  // namespace

size_t Scene::triangleCount() const {
    size_t count = 0;
    for (const Mesh& mesh : meshes) count += mesh.triangleCount();
    return count;
}

// Both bounds are (0, 0, 0) for a scene without geometry.
glm::vec3 Scene::boundsMin() const {
    if (triangleCount() == 0) return glm::vec3(0.0f);
    glm::vec3 result(std::numeric_limits<float>::max());
    for (const Mesh& mesh : meshes)
        for (const glm::vec3& p : mesh.positions) result = glm::min(result, p);
    return result;
}

glm::vec3 Scene::boundsMax() const {
    if (triangleCount() == 0) return glm::vec3(0.0f);
    glm::vec3 result(std::numeric_limits<float>::lowest());
    for (const Mesh& mesh : meshes)
        for (const glm::vec3& p : mesh.positions) result = glm::max(result, p);
    return result;
}

std::vector<PointLight> Scene::lightsAt(float t) const {
    std::vector<PointLight> result = lights;
    if (!lightPaths.empty()) {
        if (lightPaths.size() != lights.size())
            throw Error("Scene::lightsAt: " + std::to_string(lightPaths.size()) + " light paths for " +
                        std::to_string(lights.size()) + " lights");
        for (size_t i = 0; i < result.size(); ++i) result[i].position = evaluatePath(lightPaths[i], lights[i].position, t);
    }
    // Lights carried by animation nodes: placed, turned and scaled by the node's transform at t.
    const SceneAnimation& a = animation;
    if (std::none_of(a.lightBindings.begin(), a.lightBindings.end(), [](const LightBinding& b) { return b.node >= 0; }))
        return result;
    const std::vector<glm::mat4> world = a.worldAt(t);
    for (size_t i = 0; i < a.lightBindings.size() && i < result.size(); ++i) {
        const LightBinding& b = a.lightBindings[i];
        if (b.node < 0) continue;
        const glm::mat4& w = world[size_t(b.node)];
        result[i].position = glm::vec3(w * glm::vec4(b.position, 1.0f));
        const glm::vec3 direction = glm::mat3(w) * b.direction;
        if (isUsableDirection(direction)) result[i].direction = glm::normalize(direction);
        const float scale = std::max({glm::length(glm::vec3(w[0])), glm::length(glm::vec3(w[1])), glm::length(glm::vec3(w[2]))});
        result[i].radius = std::min(maxLightRadius, b.radius * scale);
    }
    return result;
}

glm::vec3 evaluatePath(const LightPath& path, const glm::vec3& restPosition, float t) {
    switch (path.kind) {
    case LightPath::Kind::Static:
        return restPosition;
    case LightPath::Kind::Orbit: {
        const float angle = path.phase + path.angularSpeed * t;
        return path.center + glm::vec3(path.orbitRadius * std::cos(angle), path.bobAmplitude * std::sin(0.7f * angle),
                                       path.orbitRadius * std::sin(angle));
    }
    case LightPath::Kind::Bounce:
        return {bounceAxis(restPosition.x, path.velocity.x, path.boxMin.x, path.boxMax.x, t),
                bounceAxis(restPosition.y, path.velocity.y, path.boxMin.y, path.boxMax.y, t),
                bounceAxis(restPosition.z, path.velocity.z, path.boxMin.z, path.boxMax.z, t)};
    }
    return restPosition;
}

void Scene::validate(int maxResolution) const {
    if (width <= 0 || height <= 0 || width > maxResolution || height > maxResolution)
        fail("resolution", std::to_string(width) + "x" + std::to_string(height) + " must be within 1.." +
                               std::to_string(maxResolution) + " per side");
    validateCamera(camera);
    requireFinite("scene", "time", time);
    requireColor("scene", "ambient", ambient);
    requireColor("scene", "background", backgroundColor);
    for (size_t i = 0; i < materials.size(); ++i) validateMaterial(materials[i], i);
    for (size_t i = 0; i < meshes.size(); ++i) validateMesh(meshes[i], i, materials.size());
    if (triangleCount() > maxSceneTriangles)
        fail("meshes", std::to_string(triangleCount()) + " triangles; at most " + std::to_string(maxSceneTriangles) +
                           " are supported");
    if (lights.size() > maxLights)
        fail("lights", std::to_string(lights.size()) + " lights; at most " + std::to_string(maxLights) +
                           " are supported (16-bit light indices)");
    for (size_t i = 0; i < lights.size(); ++i) validateLight(lights[i], i);
    if (!lightPaths.empty() && lightPaths.size() != lights.size())
        fail("lightPaths", std::to_string(lightPaths.size()) + " paths for " + std::to_string(lights.size()) +
                               " lights; need none or one per light");
    for (size_t i = 0; i < lightPaths.size(); ++i) validatePath(lightPaths[i], i);
    validateDirectionalLights(directionalLights);
    validateEnvironmentIntensity(environmentIntensity, "environment: intensity");
    validateAnimation(animation, meshes.size(), lights.size(), views.size());
}

glm::vec4 spotCone(const PointLight& light) {
    if (!light.isSpot()) return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    const float cosOuter = std::cos(light.outerConeAngle), cosInner = std::cos(light.innerConeAngle);
    const float scale = 1.0f / std::max(1e-3f, cosInner - cosOuter);
    return glm::vec4(glm::normalize(light.direction) * scale, -cosOuter * scale);
}

glm::vec3 DielectricSpecular::f0() const {
    const float r = (ior - 1.0f) / (ior + 1.0f);  // ior 0: r = -1, F0 = 1
    return glm::min(r * r * color, glm::vec3(1.0f)) * weight;
}

MetallicRoughness metallicRoughnessOf(const Material& m) {
    if (m.metallicRoughness) return {m.diffuse, m.metallic, m.roughness};
    MetallicRoughness out;
    out.roughness = float(std::pow(2.0 / (double(m.shininess) + 2.0), 0.25));
    const float high = std::max(m.specular.r, std::max(m.specular.g, m.specular.b));
    const float low = std::min(m.specular.r, std::min(m.specular.g, m.specular.b));
    const bool metal = high > 0.25f && (high - low) > 0.2f * high;
    out.metallic = metal ? 1.0f : 0.0f;
    out.baseColor = metal ? m.specular : m.diffuse;
    return out;
}

int findOrAddMaterial(Scene& scene, const Material& material) {
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& existing = scene.materials[i];
        if (existing.name == material.name && existing.diffuse == material.diffuse &&
            existing.diffuseTexture == material.diffuseTexture && existing.specular == material.specular &&
            existing.shininess == material.shininess && existing.opacity == material.opacity &&
            existing.diffuseImage == material.diffuseImage && existing.emissive == material.emissive &&
            existing.metallicRoughness == material.metallicRoughness && existing.metallic == material.metallic &&
            existing.roughness == material.roughness && existing.diffuseMapping == material.diffuseMapping &&
            existing.emissiveTexture == material.emissiveTexture &&
            existing.metallicRoughnessTexture == material.metallicRoughnessTexture &&
            existing.occlusionTexture == material.occlusionTexture && existing.normalTexture == material.normalTexture &&
            existing.alphaMode == material.alphaMode && existing.alphaCutoff == material.alphaCutoff &&
            existing.doubleSided == material.doubleSided && existing.dielectric == material.dielectric)
            return int(i);
    }
    scene.materials.push_back(material);
    return int(scene.materials.size() - 1);
}

int findOrAddDefaultMaterial(Scene& scene) {
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name == "default") return int(i);
    Material material;
    material.name = "default";
    scene.materials.push_back(material);
    return int(scene.materials.size() - 1);
}

void validateObject(const Mesh& mesh, const Material& material) {
    validateMaterial(material, 0);
    Mesh m = mesh;
    m.material = 0;
    validateMesh(m, 0, 1);
    if (mesh.indices.empty()) fail("mesh '" + mesh.name + "'", "has no triangles");
}

}  // namespace lidr
