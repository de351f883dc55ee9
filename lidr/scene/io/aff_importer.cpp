// The AFF importer's entry point and its reading of the files: includes, the commands, the view, lights and
// globals; the rest of the reader by concern in aff_import_*.cpp (aff_importer_internal.h lists them).
#include "lidr/scene/io/aff_importer.h"
#include "lidr/scene/io/aff_importer_internal.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "lidr/base/error.h"
#include "lidr/scene/io/aff_tokenizer.h"
#include "lidr/scene/io/file_checks.h"

namespace lidr {

namespace aff_import {

namespace fs = std::filesystem;

Scene AffReader::read() {
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


void AffReader::parseFile(const std::string& path, const std::string& includedFrom) {
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

void AffReader::command(AffTokens& in, std::vector<int>& openLines) {
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

std::string AffReader::refusal(const std::string& c) {
    if (c == "s") return "spheres (s) are not read: lidr draws triangles; give the sphere as a mesh (m)";
    if (c == "c") return "cones and cylinders (c) are not read: lidr draws triangles; give them as a mesh (m)";
    return "animated triangles (tpa) are not read: lidr moves whole meshes by their transforms, not single "
           "triangles by their own keys";
}

void AffReader::include(AffTokens& in) {
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

glm::vec3 AffReader::vector3(AffTokens& in, const std::string& what) {
    const float x = in.number(what + " x"), y = in.number(what + " y"), z = in.number(what + " z");
    return {x, y, z};
}

glm::vec3 AffReader::colour(AffTokens& in, const std::string& what) {
    const glm::vec3 c{in.number(what + " red"), in.number(what + " green"), in.number(what + " blue")};
    if (c.x < 0.0f || c.y < 0.0f || c.z < 0.0f) in.fail(what + " " + str(c) + " must not be negative");
    return c;
}

void AffReader::viewpoint(AffTokens& in) {
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

void AffReader::light(AffTokens& in, bool animated) {
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

void AffReader::animationRange(AffTokens& in) {
    const float start = in.number("animation start time (a START END FRAMES)");
    const float end = in.number("animation end time (a START END FRAMES)");
    const long frames = in.integer("animation frame count (a START END FRAMES)", 1, 100000000);
    if (end < start) in.fail("animation end " + str(end) + " is before its start " + str(start));
    start_ = start, end_ = end, frames_ = int(frames), rangeGiven_ = true;
}

void AffReader::fill(AffTokens& in, bool extended) {
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

}  // namespace aff_import

Scene loadAff(const std::string& path, const AffImportOptions& options) {
    return aff_import::AffReader(path, options).read();
}

}  // namespace lidr
