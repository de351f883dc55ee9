#pragma once
// What the files of the AFF importer share (not installed; the API is aff_importer.h): the AffReader and what it
// collects while the files are read. Its members are defined by concern, one file each:
//   aff_importer.cpp          the entry point, the files (includes, commands), the view, lights and globals
//   aff_import_animation.cpp  transforms (x, xs) and keyframes (k): the node tree as AnimationNodes
//   aff_import_geometry.cpp   the geometry commands (m, p, pp, tt, ttp) and their textures
//   aff_import_scene.cpp      the Scene made of what was read: keyframes on nodes, camera, geometry posed and
//                             merged, materials, lights placed, far plane
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "lidr/scene/animation.h"
#include "lidr/scene/io/aff_importer.h"
#include "lidr/scene/io/aff_tokenizer.h"
#include "lidr/scene/scene.h"

namespace lidr::aff_import {

// BART's material: `fm` (ambient, diffuse, specular colours, Phong exponent, transmittance, index of refraction)
// or NFF's `f` (one colour times Kd, grey Ks). Where: the file and line that set it (the lidr material's name).
struct AffMaterial {
    glm::vec3 ambient{0.2f}, diffuse{0.8f}, specular{0.0f};
    float shine = 1.0f, transmittance = 0.0f, ior = 1.0f;
    std::string where = "default";
    bool operator==(const AffMaterial& o) const {
        return ambient == o.ambient && diffuse == o.diffuse && specular == o.specular && shine == o.shine &&
               transmittance == o.transmittance && ior == o.ior && where == o.where;
    }
};

// Geometry as a command made it, in the space of the node it sits under (-1: world).
struct Piece {
    int node = -1;
    size_t look = 0;  // index into AffReader::looks_
    Mesh mesh;
};

// A material with its texture: one lidr material each.
struct Look {
    AffMaterial material;
    std::string texture;  // resolved path; empty: none
};

struct KeyFrames {
    std::string where;  // file:line of the `k`
    std::optional<Vec3Track> translation, scale;
    std::optional<RotationTrack> rotation;
    bool used = false;
};

struct AffLight {
    PointLight light;   // position in its node's space
    int node = -1;
    std::string where;
};

struct AffView {
    bool given = false;
    glm::vec3 from{0.0f, 0.0f, 1.0f}, at{0.0f}, up{0.0f, 1.0f, 0.0f};
    float angle = 45.0f, hither = 1.0f;
    int width = 0, height = 0;
};

class AffReader {
public:
    AffReader(const std::string& path, const AffImportOptions& options) : root_(path), detail_(options.detailLevel) {}

    Scene read();

private:
    // ---- files, view, lights, globals (aff_importer.cpp) -----------------------------------------------------
    void parseFile(const std::string& path, const std::string& includedFrom);
    void command(AffTokens& in, std::vector<int>& openLines);
    static std::string refusal(const std::string& c);
    void include(AffTokens& in);
    glm::vec3 vector3(AffTokens& in, const std::string& what);
    glm::vec3 colour(AffTokens& in, const std::string& what);
    void viewpoint(AffTokens& in);
    void light(AffTokens& in, bool animated);
    void animationRange(AffTokens& in);
    void fill(AffTokens& in, bool extended);

    // ---- transforms and keyframes (aff_import_animation.cpp) -------------------------------------------------
    int currentNode() const { return nodeStack_.empty() ? -1 : nodeStack_.back(); }
    int addNode(AffTokens& in, const std::string& name, int parent, const glm::mat4& rest);
    void transform(AffTokens& in, bool isStatic);
    void keyFrames(AffTokens& in);
    void outOfOrder(AffTokens& in, int line, const std::string& name, const std::string& kind);

    // ---- geometry (aff_import_geometry.cpp) ------------------------------------------------------------------
    size_t look(const std::string& texture);
    std::string texturePath(AffTokens& in, const std::string& name);
    void loadTexture(AffTokens& in, const std::string& path);
    void addTriangles(AffTokens& in, size_t count);
    std::vector<glm::vec3> vectors(AffTokens& in, const std::string& what, long count);
    void mesh(AffTokens& in);
    long index(AffTokens& in, const char* what, size_t count);
    void polygon(AffTokens& in, bool patch);
    void texturedTriangle(AffTokens& in, bool patch);

    // ---- the scene (aff_import_scene.cpp) --------------------------------------------------------------------
    void attachKeyFrames(Scene& scene);
    void addCamera(Scene& scene);
    void poseGeometry(Scene& scene);
    static void keyRange(SceneAnimation& a);
    static void bake(Mesh& mesh, const glm::mat4& w);
    static void append(Mesh& to, const Mesh& from);
    Material material(const Look& look, const Scene&);
    void placeLights(Scene& scene);
    void finishCamera(Scene& scene);

    std::string root_;
    int detail_ = 0;
    std::map<std::string, std::shared_ptr<const std::string>> files_;
    std::map<std::string, std::shared_ptr<const ImageRGBA8>> textures_;
    std::vector<std::string> includeStack_;
    size_t includes_ = 0, triangles_ = 0;
    std::vector<AnimationNode> nodes_;
    std::vector<std::string> nodeWhere_;
    std::vector<int> nodeStack_;
    std::vector<Piece> pieces_;
    std::vector<Look> looks_;
    AffMaterial material_;
    std::map<std::string, KeyFrames> keys_;
    std::vector<AffLight> lights_;
    AffView view_;
    glm::vec3 background_{0.0f}, ambient_{1.0f};  // BART's defaults: black, am 1 1 1
    float start_ = 0.0f, end_ = 0.0f;
    int frames_ = 0;
    bool rangeGiven_ = false;
    int cameraNode_ = -1;
    std::vector<glm::mat4> world_;
    int transmissive_ = 0;
    std::vector<std::string> warnings_;
};

}  // namespace lidr::aff_import
