#pragma once
// Keyframe animation (issue 46): a tree of nodes whose local transforms follow keyframed tracks (glTF's STEP,
// LINEAR and CUBICSPLINE samplers, BART's Kochanek-Bartels splines), and what hangs on them: meshes, lights, the
// camera. Scene::animation holds it. The scene's geometry stays world space, posed at Scene::time (posedWorld
// records the node transforms it was posed with), so everything that reads a Scene sees one valid frame;
// meshTransformsAt gives each mesh's move to another time (Renderer::setObjectTransform), poseScene moves the
// geometry itself. doc/scene-format.md, "Animation".
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace lidr {

struct Scene;
struct Camera;

enum class Interpolation {
    Step,             // glTF STEP: a key's value holds until the next key
    Linear,           // glTF LINEAR: component-wise; rotations along the shorter arc (slerp)
    CubicSpline,      // glTF CUBICSPLINE: cubic Hermite from each key's value and in/out tangents
    KochanekBartels,  // BART: Hermite cubics whose tangents come from tension, continuity and bias
};
const char* interpolationName(Interpolation interpolation);  // "STEP", "LINEAR", "CUBICSPLINE", "Kochanek-Bartels"

// Where a Kochanek-Bartels track's pieces come from: piece i (times[i] .. times[i + 1]) evaluates its spline
// segment at u = (t - start[i]) / length[i] (kochanek_bartels.h: a segment may be cut short, BART's rule for keys
// out of time order).
struct SegmentSpans {
    std::vector<float> start, length;  // one per piece; length != 0
};

// A keyed vector (translation or scale). Times increase. Before the first time the track holds its first value,
// after the last its last.
struct Vec3Track {
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;  // KochanekBartels: the piece boundaries, one more than the pieces
    // One per time; CubicSpline: three per time, as glTF stores them: in-tangent, value, out-tangent.
    // KochanekBartels: two, the values before the first time and after the last.
    std::vector<glm::vec3> values;
    // KochanekBartels: four per piece, the cubic's coefficients c0 .. c3 in u: c0 + u (c1 + u (c2 + u c3)).
    std::vector<glm::vec3> segments;
    SegmentSpans spans;  // KochanekBartels
    glm::vec3 at(float t) const;
};

// A keyed rotation, unit quaternions. CubicSpline values: in-tangent, value, out-tangent per time (the result is
// normalised, as glTF asks). KochanekBartels: values and pieces as Vec3Track's, four quaternions per piece (p, a,
// b, q of Shoemake's squad).
struct RotationTrack {
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;
    std::vector<glm::quat> values;
    std::vector<glm::quat> segments;
    SegmentSpans spans;
    glm::quat at(float t) const;
};

// A node of the animation tree. Static: its local transform is `rest`. Animated: T(t) R(t) S(t), each from its
// track or, where it has none, from the rest translation, rotation and scale (glTF's rule; BART's keys leave the
// others at identity, which its importer gives as the rest values).
struct AnimationNode {
    std::string name;
    int parent = -1;  // an earlier node, or -1 (world)
    glm::mat4 rest{1.0f};
    bool animated = false;
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    std::optional<Vec3Track> translationTrack, scaleTrack;
    std::optional<RotationTrack> rotationTrack;
    glm::mat4 localAt(float t) const;
};

// A light carried by a node: its position, direction (spot lights) and radius in the node's space. At time t it
// is at W(t) x position, shines along W(t) x direction, and its radius is scaled by W(t)'s largest axis scale.
struct LightBinding {
    int node = -1;  // -1: not carried (the scene's light as it is, or on its LightPath)
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
    float radius = 1.0f;
};

struct SceneAnimation {
    std::vector<AnimationNode> nodes;  // parents before children
    // Per Scene::meshes entry, the node that carries it (-1: static). Shorter than the meshes: the rest are static.
    std::vector<int> meshNodes;
    // Per node, the world transform the scene's geometry (and its camera) was posed with.
    std::vector<glm::mat4> posedWorld;
    std::vector<LightBinding> lightBindings;  // per Scene::lights entry; shorter: the rest are not carried
    // The node the scene's camera rides on (-1: the camera stays where Scene::camera puts it): its eye at the
    // node's origin, looking down the node's -z with its +y up; fov, near and far stay the camera's.
    int cameraNode = -1;
    std::vector<int> viewNodes;  // per Scene::views entry, the node that places it (-1: none)
    float start = 0.0f, end = 0.0f;  // the time range the animation is defined over (seconds)
    int frames = 0;                  // frames over it (AFF's `a start end frames`); 0: the file gives none (glTF)
    std::vector<std::string> clips;  // what plays, for the summaries ("glTF animation 0 'Walk'", ...)

    bool empty() const { return nodes.empty(); }
    // True where some node is animated (a track on it or on an ancestor moves what it carries).
    bool moves() const;
    // Per node: true where it or an ancestor is animated.
    std::vector<bool> movingNodes() const;
    // Per node, its world transform at t.
    std::vector<glm::mat4> worldAt(float t) const;
    // The time of frame `frame` (0-based): start + frame (end - start) / (frames - 1); frames must be >= 1.
    float frameTime(int frame) const;
};

// Throws lidr::Error naming the first problem: a parent that is not an earlier node, a track with no keys, times
// that do not increase or are not finite, a value count that does not match,
// values not finite, a mesh, light or view bound to a node out of range, more bindings than meshes / lights /
// views, a camera node out of range, a bad time range or frame count.
void validateAnimation(const SceneAnimation& animation, size_t meshes, size_t lights, size_t views);

// Per Scene::meshes entry: the transform from its geometry as stored (posed at Scene::time) to its place at t;
// identity for a static mesh. Renderer::setObjectTransform takes it.
std::vector<glm::mat4> meshTransformsAt(const Scene& scene, float t);
// Indices of the meshes that move (carried by an animated node or one below it): the ones to re-place per frame.
std::vector<size_t> movingMeshes(const Scene& scene);
// The scene's camera at t: Scene::camera, or where its camera node puts it.
Camera cameraAt(const Scene& scene, float t);
// Moves the scene to t: its geometry (positions, normals, tangents of the moving meshes), its camera and
// Scene::time. Lights need nothing: Scene::lightsAt(t) places them.
void poseScene(Scene& scene, float t);

}  // namespace lidr
