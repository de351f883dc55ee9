#pragma once
// Shared by the libFuzzer harnesses (tests/fuzz).
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include <nlohmann/json.hpp>

#include "lidr/scene/scene.h"

namespace lidr::fuzz {

// True for a scene that parses as JSON and asks for far more geometry or lights than a fuzzing iteration should
// build (the limits allow 20 M triangles and 65,535 lights, which take seconds and gigabytes): such inputs are
// skipped so the fuzzer explores parsing and validation instead of timing out. The limits themselves are tested
// by test_scene.cpp.
inline bool asksForHugeWork(const std::string& text) {
    const nlohmann::json doc = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (doc.is_discarded()) return false;
    bool huge = false;
    auto walk = [&](const nlohmann::json& node, const auto& self) -> void {
        if (huge) return;
        if (node.is_object()) {
            for (const auto& [key, value] : node.items()) {
                if (value.is_number() && (key == "subdivisions" || key == "segments" || key == "major_segments" ||
                                          key == "minor_segments" || key == "count")) {
                    const double v = value.get<double>();
                    if (v > (key == "count" ? 2048.0 : 64.0)) huge = true;
                }
                self(value, self);
            }
        } else if (node.is_array()) {
            if (node.size() > 4096) huge = true;
            for (const auto& value : node) self(value, self);
        }
    };
    walk(doc, walk);
    return huge;
}

// What a loaded scene must satisfy (else abort: a finding): Scene::validate passes (the loader promises a
// validated scene), every mesh has a material, one normal per position, no or one texture coordinate per
// position, and every index in range.
inline void checkScene(const Scene& scene) {
    try {
        scene.validate(16384);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "loaded scene fails validation: %s\n", error.what());
        std::abort();
    }
    for (const Mesh& mesh : scene.meshes) {
        const bool ok = mesh.material >= 0 && mesh.material < int(scene.materials.size()) &&
                        mesh.normals.size() == mesh.positions.size() &&
                        (mesh.texCoords.empty() || mesh.texCoords.size() == mesh.positions.size()) &&
                        mesh.indices.size() % 3 == 0;
        if (!ok) {
            std::fprintf(stderr, "mesh '%s' is inconsistent\n", mesh.name.c_str());
            std::abort();
        }
        for (uint32_t index : mesh.indices)
            if (index >= mesh.positions.size()) {
                std::fprintf(stderr, "mesh '%s': index %u out of range\n", mesh.name.c_str(), index);
                std::abort();
            }
    }
}

}  // namespace lidr::fuzz
