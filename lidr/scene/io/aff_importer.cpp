#include "lidr/scene/io/aff_importer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>

#include "lidr/base/colour.h"
#include "lidr/base/error.h"
#include "lidr/scene/camera.h"
#include "lidr/scene/io/aff_tokenizer.h"
#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/io/mesh_split.h"
#include "lidr/scene/io/ppm_image.h"
#include "lidr/scene/kochanek_bartels.h"

namespace lidr {

namespace {

namespace fs = std::filesystem;

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

glm::vec3 faceNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    return length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
}

class AffReader {
public:
    AffReader(const std::string& path, const AffImportOptions& options) : root_(path), detail_(options.detailLevel) {}

    Scene read() {
        parseFile(root_, {});
        Scene scene;
        scene.warnings = warnings_;
        scene.name = fs::path(root_).stem().string();
        attachKeyFrames(scene);
        addCamera(scene);
        poseGeometry(scene);
        placeLights(scene);
        finishCamera(scene);
        return scene;
    }

private:
    // ---- files -------------------------------------------------------------------------------------------
    void parseFile(const std::string& path, const std::string& includedFrom) {
        if (std::find(includeStack_.begin(), includeStack_.end(), path) != includeStack_.end())
            throw Error(includedFrom + ": '" + path + "' includes itself (through the files that include it)");
        if (int(includeStack_.size()) >= maxAffIncludeDepth)
            throw Error(includedFrom + ": includes nested deeper than " + std::to_string(maxAffIncludeDepth) + " files");
        auto& text = files_[path];
        if (!text) text = AffTokens::readFile(path);
        includeStack_.push_back(path);
        AffTokens in(path, text);
        std::vector<int> openLines;  // the line of each `{` of this file still open
        const size_t stackDepth = nodeStack_.size();
        while (!in.atEnd()) command(in, openLines);
        if (!openLines.empty()) in.failAt(openLines.back(), "this '{' is never closed (the file ends first)");
        nodeStack_.resize(stackDepth);
        includeStack_.pop_back();
    }

    void command(AffTokens& in, std::vector<int>& openLines) {
        const std::string c = in.word("a command");
        if (c == "}") {
            if (openLines.empty()) in.fail("'}' closes nothing (no '{' of this file is open)");
            openLines.pop_back();
            nodeStack_.pop_back();
        } else if (c == "{") {
            in.fail("'{' without a transform before it (xs or x NAME)");
        } else if (c == "v") {
            viewpoint(in);
        } else if (c == "l" || c == "la") {
            light(in, c == "la");
        } else if (c == "b") {
            background_ = colour(in, "background");
        } else if (c == "am") {
            ambient_ = colour(in, "ambient light (am)");
        } else if (c == "a") {
            animationRange(in);
        } else if (c == "f" || c == "fm") {
            fill(in, c == "fm");
        } else if (c == "m") {
            mesh(in);
        } else if (c == "p" || c == "pp") {
            polygon(in, c == "pp");
        } else if (c == "tt" || c == "ttp") {
            texturedTriangle(in, c == "ttp");
        } else if (c == "i") {
            include(in);
        } else if (c == "d") {
            detail_ = int(in.integer("detail level (d)", -1000000, 1000000));
        } else if (c == "xs" || c == "x") {
            transform(in, c == "xs");
            openLines.push_back(in.line());
        } else if (c == "k") {
            keyFrames(in);
        } else if (c == "s" || c == "c" || c == "tpa") {
            in.fail(refusal(c));
        } else {
            in.fail("unknown AFF command '" + clipped(c, 40) +
                    "' (lidr reads v, l, la, b, am, a, f, fm, m, p, pp, tt, ttp, i, d, xs, x, k and comments)");
        }
    }

    static std::string refusal(const std::string& c) {
        if (c == "s") return "spheres (s) are not read: lidr draws triangles; give the sphere as a mesh (m)";
        if (c == "c") return "cones and cylinders (c) are not read: lidr draws triangles; give them as a mesh (m)";
        return "animated triangles (tpa) are not read: lidr moves whole meshes by their transforms, not single "
               "triangles by their own keys";
    }

    void include(AffTokens& in) {
        const long level = in.integer("include detail level (i LEVEL FILE)", -1000000, 1000000);
        const std::string name = in.word("the included file's name (i LEVEL FILE)");
        if (level > detail_) return;  // BART: skipped where its detail exceeds the scene's
        if (++includes_ > maxAffIncludes)
            in.fail("more than " + std::to_string(maxAffIncludes) + " files included in all (files including each other over and over?)");
        const std::string where = in.path() + ":" + std::to_string(in.line());
        // Relative to the including file's folder, else (BART's own rule) to the scene file's.
        std::string path = (fs::path(in.path()).parent_path() / name).lexically_normal().string();
        if (fileProblem(path) == "not found") {
            const std::string fromRoot = (fs::path(root_).parent_path() / name).lexically_normal().string();
            if (fileProblem(fromRoot).empty()) path = fromRoot;
        }
        const std::string problem = fileProblem(path);
        if (!problem.empty()) in.fail("included file '" + path + "' " + problem);
        parseFile(path, where);
    }

    // ---- view, lights, globals ---------------------------------------------------------------------------
    glm::vec3 vector3(AffTokens& in, const std::string& what) {
        const float x = in.number(what + " x"), y = in.number(what + " y"), z = in.number(what + " z");
        return {x, y, z};
    }

    glm::vec3 colour(AffTokens& in, const std::string& what) {
        const glm::vec3 c{in.number(what + " red"), in.number(what + " green"), in.number(what + " blue")};
        if (c.x < 0.0f || c.y < 0.0f || c.z < 0.0f) in.fail(what + " " + str(c) + " must not be negative");
        return c;
    }

    void viewpoint(AffTokens& in) {
        in.expect("from", "the view (v) gives from, at, up, angle, hither, resolution in that order");
        view_.from = vector3(in, "from");
        in.expect("at", "the view (v)");
        view_.at = vector3(in, "at");
        in.expect("up", "the view (v)");
        view_.up = vector3(in, "up");
        in.expect("angle", "the view (v)");
        view_.angle = in.number("angle");
        if (!(view_.angle > 0.0f && view_.angle < 180.0f)) in.fail("angle " + str(view_.angle) + " must be in (0, 180) degrees");
        in.expect("hither", "the view (v)");
        view_.hither = in.number("hither");
        if (view_.hither < 0.0001f) view_.hither = 1.0f;  // BART's rule for a hither of (about) 0
        in.expect("resolution", "the view (v)");
        view_.width = int(in.integer("resolution width", 1, 16384));
        view_.height = int(in.integer("resolution height", 1, 16384));
        view_.given = true;
    }

    void light(AffTokens& in, bool animated) {
        AffLight l;
        l.where = in.path() + ":" + std::to_string(in.line());
        l.node = currentNode();
        if (animated) {
            const std::string name = in.word("the animated light's name (la NAME X Y Z)");
            l.node = addNode(in, name, l.node, glm::mat4(1.0f));
        }
        l.light.position = vector3(in, "light position");
        if (in.nextIsNumber()) l.light.color = colour(in, "light colour");
        lights_.push_back(l);
    }

    void animationRange(AffTokens& in) {
        const float start = in.number("animation start time (a START END FRAMES)");
        const float end = in.number("animation end time (a START END FRAMES)");
        const long frames = in.integer("animation frame count (a START END FRAMES)", 1, 100000000);
        if (end < start) in.fail("animation end " + str(end) + " is before its start " + str(start));
        start_ = start, end_ = end, frames_ = int(frames), rangeGiven_ = true;
    }

    void fill(AffTokens& in, bool extended) {
        AffMaterial m;
        m.where = fs::path(in.path()).filename().string() + ":" + std::to_string(in.line());
        if (extended) {
            m.ambient = colour(in, "fm ambient");
            m.diffuse = colour(in, "fm diffuse");
            m.specular = colour(in, "fm specular");
        } else {
            const glm::vec3 c = colour(in, "f colour");
            const float kd = in.number("f Kd"), ks = in.number("f Ks");
            if (kd < 0.0f || ks < 0.0f) in.fail("f: Kd and Ks must not be negative");
            m.ambient = m.diffuse = c * kd;
            m.specular = glm::vec3(ks);
        }
        m.shine = in.number("Phong exponent (Shine)");
        m.transmittance = in.number("transmittance (T)");
        m.ior = in.number("index of refraction");
        if (m.shine < 0.0f) in.fail("Phong exponent " + str(m.shine) + " must not be negative");
        if (m.transmittance < 0.0f || m.transmittance > 1.0f) in.fail("transmittance " + str(m.transmittance) + " must be in [0, 1]");
        if (m.ior < 0.0f) in.fail("index of refraction " + str(m.ior) + " must not be negative");
        material_ = m;
    }

    // ---- transforms and keyframes --------------------------------------------------------------------------
    int currentNode() const { return nodeStack_.empty() ? -1 : nodeStack_.back(); }

    int addNode(AffTokens& in, const std::string& name, int parent, const glm::mat4& rest) {
        if (nodes_.size() >= maxAffNodes) in.fail("more than " + std::to_string(maxAffNodes) + " transforms in all");
        AnimationNode node;
        node.name = name;
        node.parent = parent;
        node.rest = rest;
        nodes_.push_back(std::move(node));
        nodeWhere_.push_back(in.path() + ":" + std::to_string(in.line()));
        return int(nodes_.size() - 1);
    }

    void transform(AffTokens& in, bool isStatic) {
        int node = currentNode();
        if (isStatic) {
            const glm::vec3 scale = vector3(in, "xs scale");
            const glm::vec3 axis = vector3(in, "xs rotation axis");
            const float degrees = in.number("xs rotation angle");
            const glm::vec3 translation = vector3(in, "xs translation");
            const float axisLength = glm::length(axis);
            if (degrees != 0.0f && !(axisLength > 0.0f))
                in.fail("xs rotates " + str(degrees) + " degrees about a zero axis");
            glm::mat4 m = glm::translate(glm::mat4(1.0f), translation);
            if (degrees != 0.0f) m = glm::rotate(m, glm::radians(degrees), axis / axisLength);
            m = glm::scale(m, scale);
            if (glm::determinant(glm::mat3(m)) == 0.0f) in.fail("xs scale " + str(scale) + " flattens everything in it");
            // The identity (xs 1 1 1 0 0 1 0 0 0 0, as every BART part file opens) adds no node.
            if (m != glm::mat4(1.0f)) node = addNode(in, "", node, m);
        } else {
            node = addNode(in, in.word("the transform's name (x NAME)"), node, glm::mat4(1.0f));
        }
        in.expect("{", isStatic ? "a static transform (xs) opens a block" : "a transform (x NAME) opens a block");
        nodeStack_.push_back(node);
    }

    void keyFrames(AffTokens& in) {
        const std::string name = in.word("the keyframes' name (k NAME)");
        const int line = in.line();
        const std::string where = in.path() + ":" + std::to_string(line);
        KeyFrames keys;
        keys.where = where;
        in.expect("{", "keyframes (k " + clipped(name, 40) + ") open a block");
        while (in.peek() != "}") {
            const std::string kind = in.word("keyframes (transl, rot, scale) or '}'");
            const int kindLine = in.line();
            const long count = in.integer(kind + " key count", 0, long(maxAffKeys));
            if (kind == "transl" || kind == "scale") {
                if ((kind == "transl" ? keys.translation : keys.scale)) in.fail(kind + " keys given twice for '" + name + "'");
                std::vector<KochanekBartelsKey> list;
                for (long i = 0; i < count; ++i) {
                    KochanekBartelsKey k;
                    k.time = in.number(kind + " key time");
                    k.value = vector3(in, kind + " key");
                    k.tension = in.number("tension"), k.continuity = in.number("continuity"), k.bias = in.number("bias");
                    list.push_back(k);
                }
                if (!keysInTimeOrder(list)) outOfOrder(in, kindLine, name, kind);
                try {
                    (kind == "transl" ? keys.translation : keys.scale) = kochanekBartelsTrack(list);
                } catch (const Error& e) {
                    in.failAt(kindLine, "keyframes '" + clipped(name, 40) + "', " + kind + ": " + e.what());
                }
            } else if (kind == "rot") {
                if (keys.rotation) in.fail("rot keys given twice for '" + name + "'");
                std::vector<KochanekBartelsRotationKey> list;
                for (long i = 0; i < count; ++i) {
                    KochanekBartelsRotationKey k;
                    k.time = in.number("rot key time");
                    k.axis = vector3(in, "rot key axis");
                    k.angleRadians = glm::radians(in.number("rot key angle (degrees)"));
                    k.tension = in.number("tension"), k.continuity = in.number("continuity"), k.bias = in.number("bias");
                    list.push_back(k);
                }
                if (!keysInTimeOrder(list)) outOfOrder(in, kindLine, name, kind);
                try {
                    keys.rotation = kochanekBartelsRotationTrack(list);
                } catch (const Error& e) {
                    in.failAt(kindLine, "keyframes '" + clipped(name, 40) + "', rot: " + e.what());
                }
            } else if (kind == "visibility") {
                in.fail("visibility keyframes are not read: lidr draws every object at every time");
            } else {
                in.fail("unknown keyframe kind '" + clipped(kind, 40) + "' (transl, rot or scale)");
            }
        }
        in.expect("}", "the keyframes' block closes");
        const auto [found, added] = keys_.emplace(name, keys);
        if (!added) in.failAt(line, "keyframes '" + clipped(name, 40) + "' given twice (first at " + found->second.where + ")");
    }

    void outOfOrder(AffTokens& in, int line, const std::string& name, const std::string& kind) {
        warnings_.push_back(in.path() + ":" + std::to_string(line) + ": keyframes '" + name + "', " + kind +
                            ": times go back; read as BART reads them (at each time the first segment in key order "
                            "that ends after it)");
    }

    // ---- geometry ------------------------------------------------------------------------------------------
    size_t look(const std::string& texture) {
        for (size_t i = 0; i < looks_.size(); ++i)
            if (looks_[i].material == material_ && looks_[i].texture == texture) return i;
        looks_.push_back({material_, texture});
        return looks_.size() - 1;
    }

    // A texture named by a mesh: beside the file naming it, in a TextureFiles folder beside that file's folder
    // (BART's layout: aff/ and TextureFiles/), or in a TextureFiles folder inside it.
    std::string texturePath(AffTokens& in, const std::string& name) {
        const fs::path folder = fs::path(in.path()).parent_path();
        const fs::path candidates[] = {folder / name, folder.parent_path() / "TextureFiles" / name,
                                       folder / "TextureFiles" / name};
        std::string looked;
        for (const fs::path& candidate : candidates) {
            const std::string path = candidate.lexically_normal().string();
            if (fileProblem(path).empty()) {
                loadTexture(in, path);
                return path;
            }
            looked += (looked.empty() ? "" : ", ") + path;
        }
        in.fail("texture '" + clipped(name, 80) + "' not found (looked for " + looked + ")");
    }

    void loadTexture(AffTokens& in, const std::string& path) {
        auto& image = textures_[path];
        if (image) return;
        const std::string extension = lowerCaseExtension(path);
        if (extension != ".ppm" && extension != ".pgm" && extension != ".pnm")
            in.fail("texture '" + path + "': lidr reads BART's PPM textures (.ppm, .pgm), not " + extension + " files");
        try {
            image = std::make_shared<const ImageRGBA8>(readPpm(path));
        } catch (const Error& e) {
            in.fail(std::string("texture: ") + e.what());
        }
    }

    void addTriangles(AffTokens& in, size_t count) {
        triangles_ += count;
        if (triangles_ > maxSceneTriangles)
            in.fail("the scene so far has " + std::to_string(triangles_) + " triangles; at most " +
                    std::to_string(maxSceneTriangles) + " are supported");
    }

    std::vector<glm::vec3> vectors(AffTokens& in, const std::string& what, long count) {
        std::vector<glm::vec3> result;
        result.reserve(size_t(std::min<long>(count, 65536)));  // grows with what the file really holds
        for (long i = 0; i < count; ++i) result.push_back(vector3(in, what + " " + std::to_string(i)));
        return result;
    }

    void mesh(AffTokens& in) {
        const long limit = long(3 * maxSceneTriangles);
        in.expect("vertices", "a mesh (m) starts with its vertices");
        const std::vector<glm::vec3> vertices = vectors(in, "vertex", in.integer("vertex count", 0, limit));
        std::vector<glm::vec3> normals;
        std::vector<glm::vec2> texCoords;
        std::string texture;
        if (in.peek() == "normals") {
            in.word("normals");
            normals = vectors(in, "normal", in.integer("normal count", 0, limit));
        }
        if (in.peek() == "texturecoords") {
            in.word("texturecoords");
            const long count = in.integer("texture coordinate count", 0, limit);
            texture = texturePath(in, in.word("the texture's file name (texturecoords N FILE)"));
            texCoords.reserve(size_t(std::min<long>(count, 65536)));
            for (long i = 0; i < count; ++i) {
                const float u = in.number("texture coordinate u"), v = in.number("texture coordinate v");
                texCoords.emplace_back(u, 1.0f - v);  // BART's v runs down the image from its first row; lidr's up
            }
        }
        in.expect("triangles", "a mesh (m) ends with its triangles");
        const long count = in.integer("triangle count", 0, long(maxSceneTriangles));
        addTriangles(in, size_t(count));
        Piece piece;
        piece.node = currentNode();
        piece.look = look(texture);
        piece.mesh.name = fs::path(in.path()).stem().string() + ":" + std::to_string(in.line());
        std::map<std::array<long, 4>, uint32_t> vertexOf;  // (position, normal, texcoord, flat triangle) -> vertex
        for (long t = 0; t < count; ++t) {
            long v[3], n[3] = {-1, -1, -1}, c[3] = {-1, -1, -1};
            for (long& i : v) i = index(in, "vertex", vertices.size());
            if (!normals.empty()) for (long& i : n) i = index(in, "normal", normals.size());
            if (!texCoords.empty()) for (long& i : c) i = index(in, "texture coordinate", texCoords.size());
            const glm::vec3 flat = faceNormal(vertices[size_t(v[0])], vertices[size_t(v[1])], vertices[size_t(v[2])]);
            for (int k = 0; k < 3; ++k) {
                const std::array<long, 4> key{v[k], n[k], c[k], normals.empty() ? t : -1};
                const auto [found, added] = vertexOf.emplace(key, uint32_t(piece.mesh.positions.size()));
                if (added) {
                    piece.mesh.positions.push_back(vertices[size_t(v[k])]);
                    glm::vec3 normal = n[k] >= 0 ? normals[size_t(n[k])] : flat;
                    const float length = glm::length(normal);
                    normal = length > 0.0f ? normal / length : flat;
                    piece.mesh.normals.push_back(normal);
                    if (!texCoords.empty()) piece.mesh.texCoords.push_back(texCoords[size_t(c[k])]);
                }
                piece.mesh.indices.push_back(found->second);
            }
        }
        if (count > 0) pieces_.push_back(std::move(piece));
    }

    long index(AffTokens& in, const char* what, size_t count) {
        const long i = in.integer(std::string("triangle ") + what + " index", 0, long(maxSceneTriangles) * 3);
        if (size_t(i) >= count)
            in.fail(std::string("triangle ") + what + " index " + std::to_string(i) + " out of range (the mesh has " +
                    std::to_string(count) + ")");
        return i;
    }

    // p / pp: a convex polygon, fanned into triangles; pp gives a normal per vertex.
    void polygon(AffTokens& in, bool patch) {
        const long count = in.integer("polygon vertex count", 3, long(maxSceneTriangles));
        addTriangles(in, size_t(count - 2));
        Piece piece;
        piece.node = currentNode();
        piece.look = look("");
        piece.mesh.name = fs::path(in.path()).stem().string() + ":" + std::to_string(in.line());
        for (long i = 0; i < count; ++i) {
            piece.mesh.positions.push_back(vector3(in, "polygon vertex"));
            if (patch) piece.mesh.normals.push_back(vector3(in, "polygon normal"));
        }
        const glm::vec3 flat = faceNormal(piece.mesh.positions[0], piece.mesh.positions[1], piece.mesh.positions[2]);
        if (!patch) piece.mesh.normals.assign(piece.mesh.positions.size(), flat);
        for (glm::vec3& n : piece.mesh.normals) n = glm::length(n) > 0.0f ? glm::normalize(n) : flat;
        for (long i = 1; i + 1 < count; ++i)
            piece.mesh.indices.insert(piece.mesh.indices.end(), {0u, uint32_t(i), uint32_t(i + 1)});
        pieces_.push_back(std::move(piece));
    }

    // tt / ttp TEXTURE: one triangle with texture coordinates (ttp: and normals).
    void texturedTriangle(AffTokens& in, bool patch) {
        const std::string texture = texturePath(in, in.word("the texture's file name (tt FILE)"));
        addTriangles(in, 1);
        Piece piece;
        piece.node = currentNode();
        piece.look = look(texture);
        piece.mesh.name = fs::path(in.path()).stem().string() + ":" + std::to_string(in.line());
        for (int i = 0; i < 3; ++i) {
            piece.mesh.positions.push_back(vector3(in, "triangle vertex"));
            if (patch) piece.mesh.normals.push_back(vector3(in, "triangle normal"));
            const float u = in.number("texture coordinate u"), v = in.number("texture coordinate v");
            piece.mesh.texCoords.emplace_back(u, 1.0f - v);
        }
        const glm::vec3 flat = faceNormal(piece.mesh.positions[0], piece.mesh.positions[1], piece.mesh.positions[2]);
        if (!patch) piece.mesh.normals.assign(3, flat);
        for (glm::vec3& n : piece.mesh.normals) n = glm::length(n) > 0.0f ? glm::normalize(n) : flat;
        piece.mesh.indices = {0, 1, 2};
        pieces_.push_back(std::move(piece));
    }

    // ---- the scene -------------------------------------------------------------------------------------------
    // Nodes named like a `k` are animated by it (the keys' translation, rotation, scale; each missing one identity).
    void attachKeyFrames(Scene& scene) {
        std::map<std::string, std::vector<std::string>> unkeyed;  // file -> names
        for (size_t i = 0; i < nodes_.size(); ++i) {
            AnimationNode& node = nodes_[i];
            if (node.name.empty()) continue;
            const auto found = keys_.find(node.name);
            if (found == keys_.end()) {
                auto& names = unkeyed[nodeWhere_[i].substr(0, nodeWhere_[i].rfind(':'))];
                if (std::find(names.begin(), names.end(), node.name) == names.end()) names.push_back(node.name);
                continue;
            }
            found->second.used = true;
            node.animated = true;
            node.translationTrack = found->second.translation;
            node.rotationTrack = found->second.rotation;
            node.scaleTrack = found->second.scale;
        }
        for (const auto& [file, names] : unkeyed) {
            std::string list;
            for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
            scene.warnings.push_back(file + ": transforms without keyframes (k NAME) stay as they are: " + list);
        }
        for (const auto& [name, keys] : keys_)
            if (!keys.used && name != "camera")
                scene.warnings.push_back(keys.where + ": keyframes '" + name +
                                         "' move nothing (no transform x or light la has that name)");
    }

    // The view: `v`, on a node that `k camera` animates (its translation the eye, its rotation turning the view
    // that looks down -z with +y up; the one it lacks stays as `v` gives it).
    void addCamera(Scene& scene) {
        Camera& camera = scene.camera;
        if (view_.given) {
            camera.position = view_.from;
            camera.target = view_.at;
            camera.up = view_.up;
            camera.fovYDegrees = view_.angle;  // BART: the angle is the vertical field of view where width != height
            camera.nearPlane = view_.hither;
            scene.width = view_.width;
            scene.height = view_.height;
        }
        const auto keys = keys_.find("camera");
        if (keys == keys_.end()) return;
        keys->second.used = true;
        AnimationNode node;
        node.name = "camera";
        node.animated = true;
        node.translation = camera.position;
        const glm::vec3 forward = camera.target - camera.position;
        if (glm::length(forward) > 0.0f && glm::length(glm::cross(forward, camera.up)) > 0.0f)
            node.rotation = glm::quat_cast(glm::inverse(glm::lookAt(glm::vec3(0.0f), forward, camera.up)));
        node.translationTrack = keys->second.translation;
        node.rotationTrack = keys->second.rotation;
        node.scaleTrack = keys->second.scale;
        nodes_.push_back(std::move(node));
        nodeWhere_.push_back(keys->second.where);
        cameraNode_ = int(nodes_.size() - 1);
    }

    // Geometry baked at the start time into world space, merged per (node, look): one mesh per material and moving
    // part; the static parts by material in 64-unit cells, so per-mesh light culling still has pieces to skip.
    void poseGeometry(Scene& scene) {
        SceneAnimation& a = scene.animation;
        a.nodes = std::move(nodes_);
        a.cameraNode = cameraNode_;
        a.start = rangeGiven_ ? start_ : 0.0f;
        a.end = rangeGiven_ ? end_ : 0.0f;
        a.frames = rangeGiven_ ? frames_ : 0;
        if (!rangeGiven_) keyRange(a);  // without `a`: the keyframes' own range, no frame count
        scene.time = rangeGiven_ ? a.start : 0.0f;
        world_ = a.worldAt(a.start);
        a.posedWorld = world_;
        const std::vector<bool> moving = a.movingNodes();
        std::vector<int> lookMaterial(looks_.size(), -1);
        std::map<std::tuple<int, size_t, int, int, int>, size_t> meshOf;
        std::vector<Mesh> meshes;
        std::vector<int> meshNodes;
        for (Piece& piece : pieces_) {
            const glm::mat4 w = piece.node >= 0 ? world_[size_t(piece.node)] : glm::mat4(1.0f);
            bake(piece.mesh, w);
            const bool moves = piece.node >= 0 && moving[size_t(piece.node)];
            glm::ivec3 cell(0);
            if (!moves) {
                glm::vec3 centroid(0.0f);
                for (const glm::vec3& p : piece.mesh.positions) centroid += p;
                cell = glm::ivec3(glm::clamp(glm::floor(centroid / float(piece.mesh.positions.size()) / 64.0f),
                                             glm::vec3(-1e6f), glm::vec3(1e6f)));
            }
            const auto key = std::make_tuple(moves ? piece.node : -1, piece.look, cell.x, cell.y, cell.z);
            const auto [found, added] = meshOf.emplace(key, meshes.size());
            if (added) {
                if (lookMaterial[piece.look] < 0) lookMaterial[piece.look] = findOrAddMaterial(scene, material(looks_[piece.look], scene));
                Mesh m;
                m.name = piece.mesh.name;
                m.material = lookMaterial[piece.look];
                meshes.push_back(std::move(m));
                meshNodes.push_back(moves ? piece.node : -1);
            }
            append(meshes[found->second], piece.mesh);
        }
        pieces_.clear();
        for (size_t i = 0; i < meshes.size(); ++i)
            for (Mesh& part : splitMeshSpatially(std::move(meshes[i]))) {
                scene.meshes.push_back(std::move(part));
                a.meshNodes.push_back(meshNodes[i]);
            }
        if (std::all_of(a.meshNodes.begin(), a.meshNodes.end(), [](int n) { return n < 0; })) a.meshNodes.clear();
        if (transmissive_ > 0)
            scene.warnings.push_back(root_ + ": " + std::to_string(transmissive_) +
                                     " materials transmit light (fm T > 0): drawn transparent with opacity 1 - T; "
                                     "their refraction (index of refraction) is not drawn");
    }

    // From the earliest to the latest key of every track (0 .. 0 without any).
    static void keyRange(SceneAnimation& a) {
        bool any = false;
        const auto cover = [&](const std::vector<float>& times) {
            if (times.empty()) return;
            a.start = any ? std::min(a.start, times.front()) : times.front();
            a.end = any ? std::max(a.end, times.back()) : times.back();
            any = true;
        };
        for (const AnimationNode& n : a.nodes) {
            if (n.translationTrack) cover(n.translationTrack->times);
            if (n.rotationTrack) cover(n.rotationTrack->times);
            if (n.scaleTrack) cover(n.scaleTrack->times);
        }
    }

    static void bake(Mesh& mesh, const glm::mat4& w) {
        if (w == glm::mat4(1.0f)) return;
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(w)));
        for (glm::vec3& p : mesh.positions) p = glm::vec3(w * glm::vec4(p, 1.0f));
        for (glm::vec3& n : mesh.normals) {
            const glm::vec3 moved = normalMatrix * n;
            const float length = glm::length(moved);
            if (length > 0.0f && std::isfinite(length)) n = moved / length;
        }
        if (glm::determinant(glm::mat3(w)) < 0.0f)
            for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    }

    static void append(Mesh& to, const Mesh& from) {
        const uint32_t base = uint32_t(to.positions.size());
        const bool textured = !from.texCoords.empty();
        if (textured && to.texCoords.size() < to.positions.size()) to.texCoords.resize(to.positions.size(), glm::vec2(0.0f));
        to.positions.insert(to.positions.end(), from.positions.begin(), from.positions.end());
        to.normals.insert(to.normals.end(), from.normals.begin(), from.normals.end());
        if (textured) to.texCoords.insert(to.texCoords.end(), from.texCoords.begin(), from.texCoords.end());
        else if (!to.texCoords.empty()) to.texCoords.resize(to.positions.size(), glm::vec2(0.0f));
        for (uint32_t i : from.indices) to.indices.push_back(base + i);
    }

    // BART's Phong material as lidr's (doc/scene-format.md, "AFF"): diffuse and specular colours as display values,
    // the exponent x 4 as Blinn-Phong's (metallicRoughnessOf turns them into the BRDF's base colour, metallic,
    // roughness), the texture modulating the diffuse colour; the ambient colour times `am` becomes the emission
    // (textured like the diffuse), BART's ambient term; transmittance T makes it transparent (opacity 1 - T).
    Material material(const Look& look, const Scene&) {
        const AffMaterial& m = look.material;
        Material out;
        out.name = m.where + (look.texture.empty() ? "" : " " + fs::path(look.texture).filename().string());
        out.diffuse = displayColourToLinear(m.diffuse);
        out.specular = displayColourToLinear(m.specular);
        out.shininess = std::max(1.0f, 4.0f * m.shine);
        out.emissive = displayColourToLinear(m.ambient * ambient_);
        if (m.transmittance > 0.0f) {
            out.opacity = std::max(0.05f, 1.0f - m.transmittance);
            ++transmissive_;
        }
        if (!look.texture.empty()) {
            out.diffuseTexture = look.texture;
            out.diffuseImage = textures_.at(look.texture);
            if (out.emissive != glm::vec3(0.0f)) {
                out.emissiveTexture.name = look.texture;
                out.emissiveTexture.image = out.diffuseImage;
            }
        }
        return out;
    }

    // `l` lights: lidr's lights fade to nothing at their radius, BART's do not fade: the radius reaches twice as
    // far as the farthest corner of the scene's bounds, so the falloff (1 - d^2 / r^2) stays within [0.75, 1] over
    // the scene. Lights under a moving transform (or `la`) ride on their node.
    void placeLights(Scene& scene) {
        const glm::vec3 lo = scene.boundsMin(), hi = scene.boundsMax();
        const std::vector<bool> moving = scene.animation.movingNodes();
        bool carried = false;
        for (const AffLight& l : lights_) {
            PointLight light = l.light;
            light.color = displayColourToLinear(light.color);
            const glm::mat4 w = l.node >= 0 ? world_[size_t(l.node)] : glm::mat4(1.0f);
            const glm::vec3 local = light.position;
            light.position = glm::vec3(w * glm::vec4(local, 1.0f));
            float farthest = 0.0f;
            for (int corner = 0; corner < 8; ++corner) {
                const glm::vec3 c(corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z);
                farthest = std::max(farthest, glm::length(c - light.position));
            }
            light.radius = std::max(1.0f, 2.0f * farthest);
            LightBinding binding;
            if (l.node >= 0 && moving[size_t(l.node)]) {
                binding.node = l.node;
                binding.position = local;
                const glm::mat4& wl = world_[size_t(l.node)];
                const float scale = std::max({glm::length(glm::vec3(wl[0])), glm::length(glm::vec3(wl[1])), glm::length(glm::vec3(wl[2]))});
                binding.radius = light.radius / std::max(scale, 1e-6f);
                carried = true;
            }
            scene.lights.push_back(light);
            scene.animation.lightBindings.push_back(binding);
        }
        if (!carried) scene.animation.lightBindings.clear();
        scene.backgroundColor = displayColourToLinear(background_);
        scene.ambient = glm::vec3(0.0f);  // BART's ambient is each material's emission (above)
    }

    // Far enough for the whole scene from wherever the camera goes (sampled over the animation).
    void finishCamera(Scene& scene) {
        if (!view_.given && cameraNode_ < 0) {
            scene.camera = cameraFramingBounds(scene.boundsMin(), scene.boundsMax(), scene.camera.fovYDegrees);
            return;
        }
        const glm::vec3 lo = scene.boundsMin(), hi = scene.boundsMax();
        const glm::vec3 center = 0.5f * (lo + hi);
        const float radius = 0.5f * glm::length(hi - lo);
        float farthest = 0.0f;
        const SceneAnimation& a = scene.animation;
        for (int i = 0; i <= 64; ++i) {
            const float t = a.start + (a.end - a.start) * float(i) / 64.0f;
            farthest = std::max(farthest, glm::length(cameraAt(scene, t).position - center));
        }
        scene.camera.farPlane = std::max(scene.camera.nearPlane * 2.0f, 1.01f * (farthest + radius));
        scene.camera = cameraAt(scene, scene.time);
    }

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

}  // namespace

Scene loadAff(const std::string& path, const AffImportOptions& options) {
    return AffReader(path, options).read();
}

}  // namespace lidr
