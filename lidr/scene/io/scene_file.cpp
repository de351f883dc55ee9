#include "lidr/scene/io/scene_file.h"
#include "lidr/scene/light_scatter.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "lidr/base/colour.h"
#include "lidr/base/error.h"
#include "lidr/scene/default_scene.h"
#include "lidr/scene/primitives.h"
#include "lidr/scene/render_mode_names.h"
#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/io/gltf_importer.h"
#include "lidr/scene/io/environment_file.h"
#include "lidr/scene/io/json_fields.h"
#include "lidr/scene/io/obj_importer.h"

namespace lidr {

namespace {

namespace fs = std::filesystem;

constexpr int maxResolution = 16384;
constexpr int maxLights = int(maxSceneLights);
constexpr int maxSegments = maxPrimitiveSegments;
constexpr int maxSubdivisions = maxPrimitiveSubdivisions;
// Longest error message a scene file gives; longer ones (a huge key or string echoed back) keep their start
// and end.
constexpr size_t maxMessageLength = 2000;

// Reads one scene document into a Scene; the sections are applied in a fixed order (base, materials,
// models, primitives, lights, generate), whatever their order in the file.
class SceneReader {
public:
    SceneReader(const std::string& file, const std::string& baseDir, const ObjImportOptions& objDefaults)
        : file_(file), baseDir_(baseDir), objDefaults_(objDefaults) {}

    Scene read(const Json& document) {
        const Field root(document, "", file_);
        root.expectObject({"name", "description", "base", "seed", "base_lights", "resolution", "time", "camera",
                           "ambient", "background", "materials", "models", "primitives", "lights", "generate",
                           "directional_lights", "scatter_lights", "msaa", "transparency", "mode", "environment"});
        readBase(root);
        if (root.has("name")) scene_.name = root["name"].text();
        if (root.has("description")) root["description"].text();  // free text for people; only its type is checked
        if (root.has("resolution")) readResolution(root["resolution"]);
        if (root.has("time")) scene_.time = root["time"].number();
        if (root.has("mode")) {
            scene_.renderMode = root["mode"].text();
            if (!isRenderModeName(scene_.renderMode))
                root["mode"].fail("unknown render mode '" + scene_.renderMode + "' (valid: " + renderModeList() + ")");
        }
        if (root.has("camera")) readCamera(root["camera"]);
        if (root.has("ambient")) scene_.ambient = color(root["ambient"]);
        if (root.has("background")) scene_.backgroundColor = color(root["background"]);
        if (root.has("environment")) readEnvironment(root["environment"]);
        if (root.has("msaa")) {
            scene_.msaaSamples = int(root["msaa"].integer(0, 64));
            if (scene_.msaaSamples != 0 && (scene_.msaaSamples < 2 || (scene_.msaaSamples & (scene_.msaaSamples - 1)) != 0))
                root["msaa"].fail("must be 0 (off) or a power of two 2, 4, 8, ... 64, got " +
                                  std::to_string(scene_.msaaSamples));
        }
        if (root.has("transparency")) scene_.transparency = root["transparency"].boolean();
        if (root.has("materials"))
            for (const Field& material : root["materials"].items()) readMaterial(material);
        if (root.has("models"))
            for (const Field& model : root["models"].items()) readModel(model);
        if (root.has("primitives"))
            for (const Field& primitive : root["primitives"].items()) readPrimitive(primitive);
        // Paths stay one per light while reading; all-static scenes drop them at the end.
        scene_.lightPaths.resize(scene_.lights.size());
        if (root.has("lights"))
            for (const Field& light : root["lights"].items()) readLight(light);
        if (root.has("generate")) readGenerators(root["generate"]);
        if (root.has("directional_lights")) readDirectionalLights(root["directional_lights"]);
        if (root.has("scatter_lights")) readScatter(root["scatter_lights"]);
        bool anyMoves = false;
        for (const LightPath& path : scene_.lightPaths) anyMoves = anyMoves || path.kind != LightPath::Kind::Static;
        if (!anyMoves) scene_.lightPaths.clear();
        // The glTF models' cameras: the first one met is the view unless the file gives "camera".
        finishGltfViews(scene_);
        if (!root.has("camera") && firstModelView_ >= 0) {
            scene_.view = firstModelView_;
            scene_.camera = scene_.views[size_t(firstModelView_)].camera;
            if (size_t(firstModelView_) < scene_.animation.viewNodes.size())
                scene_.animation.cameraNode = scene_.animation.viewNodes[size_t(firstModelView_)];
        }
        if (!scene_.animation.empty()) poseScene(scene_, scene_.time);  // the models were built in their rest pose

        try {
            scene_.validate(maxResolution);
        } catch (const Error& error) {
            throw Error(file_ + ": " + error.what());
        }
        return std::move(scene_);
    }

private:
    void readBase(const Field& root) {
        if (!root.has("base")) {
            if (root.has("seed")) root["seed"].fail("only used with \"base\"");
            if (root.has("base_lights")) root["base_lights"].fail("only used with \"base\"");
            return;
        }
        const std::string base = root["base"].text();
        if (base != "default-room") root["base"].fail("unknown base scene '" + base + "' (known: default-room)");
        DefaultSceneOptions options;
        if (root.has("seed")) options.seed = uint32_t(root["seed"].integer(0, std::numeric_limits<uint32_t>::max()));
        scene_ = makeDefaultScene(options);
        if (!(root.has("base_lights") && root["base_lights"].boolean())) {
            scene_.lights.clear();
            scene_.lightPaths.clear();
            scene_.directionalLights.clear();
        }
    }

    void readResolution(const Field& field) {
        const std::vector<Field> size = field.items(2);
        scene_.width = int(size[0].integer(1, maxResolution));
        scene_.height = int(size[1].integer(1, maxResolution));
    }

    void readCamera(const Field& field) {
        field.expectObject({"position", "target", "up", "fov", "near", "far"});
        Camera& camera = scene_.camera;
        if (field.has("position")) camera.position = field["position"].vec3();
        if (field.has("target")) camera.target = field["target"].vec3();
        if (field.has("up")) camera.up = field["up"].vec3();
        if (field.has("fov")) camera.fovYDegrees = field["fov"].number();
        if (field.has("near")) camera.nearPlane = field["near"].number();
        if (field.has("far")) camera.farPlane = field["far"].number();
        // Ranges and consistency are checked with the whole scene (Scene::validate names "camera").
    }

    void readMaterial(const Field& field) {
        field.expectObject({"name", "diffuse", "texture", "specular", "shininess", "opacity", "emissive", "metallic",
                            "roughness"});
        Material material;
        material.name = field["name"].text();
        if (material.name.empty()) field["name"].fail("must not be empty");
        if (findMaterial(material.name) >= 0) field["name"].fail("material '" + material.name + "' already exists");
        if (field.has("diffuse")) material.diffuse = color(field["diffuse"]);
        if (field.has("texture")) {
            material.diffuseTexture = resolve(field["texture"].text());
            const std::string problem = imageProblem(material.diffuseTexture);
            if (!problem.empty()) field["texture"].fail(problem);
        }
        if (field.has("specular")) material.specular = color(field["specular"]);
        if (field.has("emissive")) material.emissive = color(field["emissive"]);
        // Material colours are display values (sRGB-encoded, defaults included); lidr shades in linear light.
        // Lights and the ambient are linear light already (doc/scene-format.md).
        material.diffuse = displayColourToLinear(material.diffuse);
        material.specular = displayColourToLinear(material.specular);
        material.emissive = displayColourToLinear(material.emissive);
        if (field.has("shininess")) material.shininess = positive(field["shininess"]);
        if (field.has("opacity")) {
            material.opacity = field["opacity"].number();
            if (!(material.opacity >= 0.0f && material.opacity <= 1.0f))
                field["opacity"].fail("must be in [0, 1], got " + str(material.opacity));
        }
        // metallic / roughness: the material is given in the BRDF's own terms (diffuse = base colour);
        // specular and shininess then have nothing to say (doc/colour.md, "Materials").
        if (field.has("metallic") || field.has("roughness")) {
            if (field.has("specular") || field.has("shininess"))
                field.fail("give either metallic / roughness or specular / shininess, not both");
            material.metallicRoughness = true;
            material.roughness = 0.5f;
            for (const char* key : {"metallic", "roughness"}) {
                if (!field.has(key)) continue;
                const float v = field[key].number();
                if (!(v >= 0.0f && v <= 1.0f)) field[key].fail("must be in [0, 1], got " + str(v));
                (std::string(key) == "metallic" ? material.metallic : material.roughness) = v;
            }
        }
        scene_.materials.push_back(material);
    }

    void readModel(const Field& field) {
        field.expectObject({"file", "translate", "rotate", "rotate_y", "scale", "material", "smooth_normals"});
        ObjImportOptions objOptions = objDefaults_;
        if (field.has("smooth_normals")) objOptions.smoothNormals = field["smooth_normals"].boolean();
        glm::mat4 transform(1.0f);
        if (field.has("translate")) transform = glm::translate(transform, field["translate"].vec3());
        if (field.has("rotate") && field.has("rotate_y")) field.fail("give either \"rotate\" or \"rotate_y\", not both");
        if (field.has("rotate")) {
            const std::vector<Field> values = field["rotate"].items(4);
            const float angle = values[0].number();
            const glm::vec3 axis(values[1].number(), values[2].number(), values[3].number());
            if (glm::length(axis) == 0.0f) field["rotate"].fail("the axis must not be zero");
            transform = glm::rotate(transform, glm::radians(angle), glm::normalize(axis));
        }
        if (field.has("rotate_y"))
            transform = glm::rotate(transform, glm::radians(field["rotate_y"].number()), glm::vec3(0, 1, 0));
        if (field.has("scale")) transform = glm::scale(transform, positiveVec3(field["scale"]));
        const int material = field.has("material") ? materialIndex(field["material"]) : -1;
        const Field file = field["file"];
        try {
            const std::string path = resolve(file.text());
            const std::string extension = lowerCaseExtension(path);
            if (extension == ".gltf" || extension == ".glb") {
                // Its cameras are numbered after those of the models before it, named with the file.
                const GltfContents contents = appendGltf(scene_, path, transform, material);
                if (firstModelView_ < 0 && contents.firstView >= 0)
                    firstModelView_ = int(scene_.views.size()) + contents.firstView;
                if (!contents.viewNodes.empty()) {  // its cameras on animated nodes ride on them
                    scene_.animation.viewNodes.resize(scene_.views.size(), -1);
                    scene_.animation.viewNodes.insert(scene_.animation.viewNodes.end(), contents.viewNodes.begin(),
                                                      contents.viewNodes.end());
                }
                for (SceneView view : contents.views) {
                    view.name = file.text() + " " + view.name;
                    scene_.views.push_back(view);
                }
            } else
                appendObj(scene_, path, transform, material, objOptions);
        } catch (const Error& error) {
            file.fail(error.what());
        }
        checkTriangleCount(field);
    }

    void readPrimitive(const Field& field) {
        const std::string shape = field["shape"].text();
        const int material = field.has("material") ? materialIndex(field["material"]) : findOrAddDefaultMaterial(scene_);
        const auto segments = [&](const char* key, int fallback) {
            return field.has(key) ? int(field[key].integer(3, maxSegments)) : fallback;
        };
        const auto subdivisions = [&] {
            return field.has("subdivisions") ? int(field["subdivisions"].integer(1, maxSubdivisions)) : 1;
        };
        if (shape == "box") {
            field.expectObject({"shape", "material", "min", "max", "subdivisions"});
            const glm::vec3 min = field["min"].vec3(), max = field["max"].vec3();
            if (!(min.x < max.x && min.y < max.y && min.z < max.z))
                field["max"].fail("must be greater than min " + str(min) + " on every axis, got " + str(max));
            addBox(scene_, min, max, material, subdivisions());
        } else if (shape == "plane") {
            field.expectObject({"shape", "material", "center", "size", "subdivisions"});
            const std::vector<Field> size = field["size"].items(2);
            addPlane(scene_, field["center"].vec3(), {positive(size[0]), positive(size[1])}, material, subdivisions());
        } else if (shape == "sphere") {
            field.expectObject({"shape", "material", "center", "radius", "segments"});
            addSphere(scene_, field["center"].vec3(), positive(field["radius"]), material, segments("segments", 16));
        } else if (shape == "cylinder") {
            field.expectObject({"shape", "material", "base", "radius", "height", "segments"});
            addCylinder(scene_, field["base"].vec3(), positive(field["radius"]), positive(field["height"]), material,
                        segments("segments", 16));
        } else if (shape == "torus") {
            field.expectObject(
                {"shape", "material", "center", "major_radius", "minor_radius", "major_segments", "minor_segments"});
            addTorus(scene_, field["center"].vec3(), positive(field["major_radius"]), positive(field["minor_radius"]),
                     material, segments("major_segments", 24), segments("minor_segments", 12));
        } else {
            field["shape"].fail("unknown shape '" + shape + "' (known: box, plane, sphere, cylinder, torus)");
        }
        checkTriangleCount(field);
    }

    // After each primitive or model (each adds at most a few million triangles, see the limits), so a scene
    // that asks for too many stops before the rest is built.
    void checkTriangleCount(const Field& field) const {
        const size_t count = scene_.triangleCount();
        if (count > maxSceneTriangles)
            field.fail("the scene now has " + std::to_string(count) + " triangles; at most " +
                       std::to_string(maxSceneTriangles) + " are supported");
    }

    void readLight(const Field& field) {
        field.expectObject({"position", "radius", "color", "priority", "path", "type", "direction", "inner_cone_angle",
                            "outer_cone_angle", "falloff", "shadow"});
        PointLight light;
        LightPath path;
        if (field.has("path")) path = readPath(field["path"]);
        if (path.kind == LightPath::Kind::Orbit) {
            if (field.has("position"))
                field["position"].fail("not used by orbit lights: they start on their orbit (see path)");
            light.position = evaluatePath(path, glm::vec3(0.0f), 0.0f);
        } else {
            light.position = field["position"].vec3();
        }
        light.radius = positive(field["radius"]);
        if (light.radius > maxLightRadius)
            field["radius"].fail("radius " + str(light.radius) + " is too large (limit " + str(maxLightRadius) + ")");
        if (field.has("color")) light.color = color(field["color"]);
        if (field.has("priority")) light.priority = field["priority"].number();
        if (field.has("falloff")) {
            const std::string falloff = field["falloff"].text();
            if (falloff == "inverse_square") light.falloff = LightFalloff::InverseSquare;
            else if (falloff != "smooth")
                field["falloff"].fail("unknown falloff '" + falloff + "' (smooth: 1 - d^2/r^2, the default; "
                                      "inverse_square: glTF's, with the range window)");
        }
        readSpotCone(field, light);
        // Whether it casts shadows where a frame turns them on (ShadingParameters::shadows; doc/shadows.md).
        if (field.has("shadow")) light.castsShadow = field["shadow"].boolean();
        scene_.lights.push_back(light);
        scene_.lightPaths.push_back(path);
    }

    // "type": "point" (the default) or "spot" with its cone, in degrees (KHR_lights_punctual's defaults: inner 0,
    // outer 45); a point light takes none of the spot keys.
    void readSpotCone(const Field& field, PointLight& light) {
        const std::string type = field.has("type") ? field["type"].text() : "point";
        if (type == "point") {
            for (const char* key : {"direction", "inner_cone_angle", "outer_cone_angle"})
                if (field.has(key)) field[key].fail("only for spot lights (\"type\": \"spot\")");
            return;
        }
        if (type != "spot") field["type"].fail("unknown light type '" + type + "' (point or spot; directional "
                                               "lights are \"directional_lights\")");
        light.direction = field["direction"].vec3();
        if (!isUsableDirection(light.direction))
            field["direction"].fail("length " + str(glm::length(light.direction)) + "; it must be between 1e-18 and 1e18");
        const float outer = field.has("outer_cone_angle") ? field["outer_cone_angle"].number() : 45.0f;
        const float inner = field.has("inner_cone_angle") ? field["inner_cone_angle"].number() : 0.0f;
        if (!(outer > 0.0f && outer <= 90.0f))  // the default, 45, is in range
            field["outer_cone_angle"].fail("must be in (0, 90] degrees, got " + str(outer));
        if (!(inner >= 0.0f && inner < outer))
            field["inner_cone_angle"].fail("must be in [0, outer_cone_angle " + str(outer) + ") degrees, got " + str(inner));
        light.outerConeAngle = glm::radians(outer);
        light.innerConeAngle = std::min(glm::radians(inner), std::nextafter(light.outerConeAngle, 0.0f));
    }

    // Not indexed (every mode adds them in its forward pass), so they have their own key, after the models'.
    // "default", "none", a file (an .hdr panorama or a folder of six faces, relative to the scene file), or
    // {"source": one of those, "intensity": scale}.
    void readEnvironment(const Field& field) {
        const bool object = field.has("source") || field.has("intensity");
        if (object) field.expectObject({"source", "intensity"});
        const Field source = object ? field["source"] : field;
        const std::string text = source.text();
        try {
            scene_.environment = loadEnvironment(text == "default" || text == "none" ? text : resolve(text));
        } catch (const Error& e) {
            source.fail(e.what());
        }
        if (object && field.has("intensity")) scene_.environmentIntensity = nonNegative(field["intensity"]);
    }

    void readDirectionalLights(const Field& field) {
        const std::vector<Field> items = field.items();
        if (scene_.directionalLights.size() + items.size() > maxDirectionalLights)
            field.fail(std::to_string(scene_.directionalLights.size() + items.size()) + " directional lights" +
                       (scene_.directionalLights.empty() ? std::string() : " with the models'") + "; at most " +
                       std::to_string(maxDirectionalLights) + " are supported (uniforms of every forward shader)");
        for (const Field& item : items) {
            item.expectObject({"direction", "color"});
            DirectionalLight light;
            light.direction = item["direction"].vec3();
            if (!isUsableDirection(light.direction))
                item["direction"].fail("length " + str(glm::length(light.direction)) + "; it must be between 1e-18 and "
                                       "1e18 (the way the light travels, e.g. [0, -1, 0] straight down)");
            if (item.has("color")) light.color = color(item["color"]);
            scene_.directionalLights.push_back(light);
        }
    }

    LightPath readPath(const Field& field) {
        LightPath path;
        const std::string kind = field["kind"].text();
        if (kind == "static") {
            field.expectObject({"kind"});
        } else if (kind == "orbit") {
            field.expectObject({"kind", "center", "radius", "angular_speed", "phase", "bob"});
            path.kind = LightPath::Kind::Orbit;
            path.center = field["center"].vec3();
            path.orbitRadius = nonNegative(field["radius"]);
            path.angularSpeed = field["angular_speed"].number();
            if (field.has("phase")) path.phase = field["phase"].number();
            if (field.has("bob")) path.bobAmplitude = field["bob"].number();
        } else if (kind == "bounce") {
            field.expectObject({"kind", "velocity", "box_min", "box_max"});
            path.kind = LightPath::Kind::Bounce;
            path.velocity = field["velocity"].vec3();
            path.boxMin = field["box_min"].vec3();
            path.boxMax = field["box_max"].vec3();
            if (!glm::all(glm::lessThanEqual(path.boxMin, path.boxMax)))
                field["box_max"].fail("must be >= box_min " + str(path.boxMin) + " on every axis, got " + str(path.boxMax));
        } else {
            field["kind"].fail("unknown path kind '" + kind + "' (known: static, orbit, bounce)");
        }
        return path;
    }

    // A count of lights to add (at least `least`), checked against the scene's total limit.
    int addedLightCount(const Field& count, int least) const {
        const int n = int(count.integer(least, maxLights));
        if (scene_.lights.size() + size_t(n) > size_t(maxLights))
            count.fail(std::to_string(n) + " more lights would make " + std::to_string(scene_.lights.size() + size_t(n)) +
                       "; at most " + std::to_string(maxLights) + " are supported");
        return n;
    }

    // "scatter_lights": N seeded static lights over the surfaces read so far (lidr::scatterLights, as
    // lidr-demo --lights N); radius <= 0 or absent: chosen from the scene's size and N.
    void readScatter(const Field& field) {
        field.expectObject({"count", "radius", "seed", "spot_share"});
        LightScatterOptions options;
        options.count = addedLightCount(field["count"], 1);
        if (field.has("radius")) {
            options.radius = positive(field["radius"]);
            if (options.radius > maxLightRadius)
                field["radius"].fail("radius " + str(options.radius) + " is too large (limit " + str(maxLightRadius) + ")");
        }
        if (field.has("seed")) options.seed = uint32_t(field["seed"].integer(0, std::numeric_limits<uint32_t>::max()));
        if (field.has("spot_share")) {
            options.spotShare = nonNegative(field["spot_share"]);
            if (options.spotShare > 1.0f) field["spot_share"].fail("must be in [0, 1], got " + str(options.spotShare));
        }
        if (scene_.triangleCount() == 0) field.fail("needs surfaces to scatter over: the scene has no triangles");
        addScatteredLights(scene_, options);
        scene_.lightPaths.resize(scene_.lights.size());  // static, one per light as while reading
    }

    // "generate" is one generator object or an array of them.
    void readGenerators(const Field& field) {
        if (field.isArray())
            for (const Field& generator : field.items()) readGenerator(generator);
        else
            readGenerator(field);
    }

    void readGenerator(const Field& field) {
        field.expectObject({"seed", "count", "bounds_min", "bounds_max", "radius_min", "radius_max", "intensity", "speed"});
        LightGeneratorOptions options;
        if (field.has("seed")) options.seed = uint32_t(field["seed"].integer(0, std::numeric_limits<uint32_t>::max()));
        options.count = addedLightCount(field["count"], 0);
        options.boundsMin = field["bounds_min"].vec3();
        options.boundsMax = field["bounds_max"].vec3();
        if (!glm::all(glm::lessThanEqual(options.boundsMin, options.boundsMax)))
            field["bounds_max"].fail("must be >= bounds_min " + str(options.boundsMin) + " on every axis, got " +
                                     str(options.boundsMax));
        if (field.has("radius_min")) options.radiusMin = positive(field["radius_min"]);
        if (field.has("radius_max")) options.radiusMax = positive(field["radius_max"]);
        if (options.radiusMax > maxLightRadius)
            field["radius_max"].fail("radius " + str(options.radiusMax) + " is too large (limit " + str(maxLightRadius) + ")");
        if (!isFinite(options.boundsMax - options.boundsMin) || !isFinite(options.boundsMin - glm::vec3(options.radiusMax)) ||
            !isFinite(options.boundsMax + glm::vec3(options.radiusMax)))
            field.fail("light generator bounds " + str(options.boundsMin) + " .. " + str(options.boundsMax) +
                       " overflow float (their extent, or the bounds +- radius_max, is not finite)");
        if (options.radiusMin > options.radiusMax)
            field.fail("radius_min (" + str(options.radiusMin) + ") must be <= radius_max (" + str(options.radiusMax) + ")");
        if (field.has("intensity")) options.intensity = nonNegative(field["intensity"]);
        if (field.has("speed")) options.speed = nonNegative(field["speed"]);
        generateLights(scene_, options);
    }

    int findMaterial(const std::string& name) const {
        for (size_t i = 0; i < scene_.materials.size(); ++i)
            if (scene_.materials[i].name == name) return int(i);
        return -1;
    }

    int materialIndex(const Field& field) const {
        const std::string name = field.text();
        const int index = findMaterial(name);
        if (index < 0) field.fail("unknown material '" + name + "'");
        return index;
    }

    std::string resolve(const std::string& path) const {
        if (path.empty() || fs::path(path).is_absolute() || baseDir_.empty()) return path;
        return (fs::path(baseDir_) / path).lexically_normal().string();
    }

    const std::string& file_;
    const std::string baseDir_;
    const ObjImportOptions objDefaults_;
    Scene scene_;
    int firstModelView_ = -1;  // scene_.views' index of the first usable glTF camera met, -1: none
};

}  // namespace

Scene parseSceneJson(const std::string& jsonText, const std::string& baseDir, const std::string& nameForErrors,
                     const ObjImportOptions& objDefaults) {
    try {
        return SceneReader(nameForErrors, baseDir, objDefaults).read(parseJsonWithPaths(jsonText, nameForErrors));
    } catch (const Error& error) {
        const std::string message = error.what();
        if (message.size() <= maxMessageLength) throw;
        const size_t keep = maxMessageLength / 2;
        throw Error(message.substr(0, keep) + " ...(" + std::to_string(message.size() - 2 * keep) +
                    " characters left out)... " + message.substr(message.size() - keep));
    }
}

Scene loadSceneFile(const std::string& path, const ObjImportOptions& objDefaults) {
    std::error_code error;
    if (!fs::exists(path, error) && !error) throw Error(path + ": scene file not found");
    const std::string problem = fileProblem(path);
    if (!problem.empty()) throw Error(path + ": scene file " + problem);
    // Read whole and parsed into a tree of several times its size: the size is bounded first.
    constexpr uintmax_t maxSceneFileBytes = uintmax_t(64) << 20;
    const uintmax_t size = fs::file_size(path, error);
    if (!error && size > maxSceneFileBytes)
        throw Error(path + ": scene file of " + std::to_string(size) + " bytes; at most " +
                    std::to_string(maxSceneFileBytes) + " (64 MiB) are read");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open the scene file");
    std::ostringstream text;
    text << in.rdbuf();  // an empty file sets failbit on `text`; the parser then reports it
    if (in.bad()) throw Error(path + ": cannot read the scene file");
    return parseSceneJson(text.str(), fs::path(path).parent_path().string(), path, objDefaults);
}

}  // namespace lidr
