#pragma once
// Checks a glTF 2.0 file (.gltf or .glb) against the specification and lidr's limits from its raw bytes, before
// tinygltf parses it or allocates anything it describes: the GLB container, the JSON nesting depth, every index,
// the JSON type of every property lidr or the specification relies on, accessor and buffer-view bounds and
// alignment, the node graph (a forest), transforms, required extensions, data: URIs, the file kind and the header
// of every external buffer and image. The rules and limits are listed in doc/scene-format.md ("glTF validation").
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "lidr/scene/scene.h"

namespace lidr {

constexpr int maxGltfJsonDepth = 128;                            // arrays and objects; glTF itself needs about 10
constexpr uint64_t maxGltfJsonBytes = uint64_t(256) << 20;       // the JSON text (a .gltf, or a GLB's JSON chunk)
constexpr uint64_t maxGltfBufferBytes = uint64_t(1) << 30;       // one buffer's byteLength
constexpr uint64_t maxGltfTotalBufferBytes = uint64_t(2) << 30;  // all buffers of a file together
constexpr uint64_t maxGltfJsonValues = 2000000;   // numbers, strings, arrays, objects: up to ~300 B each once parsed
constexpr uint64_t maxGltfArrayEntries = 200000;   // nodes, meshes, accessors, ... per top-level array (~600 B each)
constexpr uint64_t maxGltfAccessorCount = 3 * uint64_t(maxSceneTriangles);  // elements of one accessor

// Throws lidr::Error "<path>: <JSON pointer>: <rule>" (or "<path>: GLB header: <rule>") at the first violation;
// appends to `warnings` one "<path>: <feature> ..." line per thing the specification allows but lidr does not draw.
void validateGltfFile(const std::string& path, std::vector<std::string>& warnings);

}  // namespace lidr
