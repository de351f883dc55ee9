#pragma once
// A glTF accessor's elements as the readers take them (gltf_importer, gltf_animation): checked against its buffer
// view and buffer before anything is read, every problem an lidr::Error naming the file and the accessor.
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>

namespace tinygltf {
class Model;
}

namespace lidr {

struct GltfAccessorView {
    const unsigned char* data = nullptr;  // null: the accessor has no buffer view (all zeros)
    size_t stride = 0, count = 0;
    int componentType = 0, components = 0;
    bool normalized = false;
};

// The accessor, of one of `types` (TINYGLTF_TYPE_*) and `componentTypes`; not sparse; every element inside its
// buffer view, the view inside its buffer. `what` says what it is for ("mesh 0 POSITION", "animation 1 sampler 0
// input"). Throws lidr::Error "<path>: <what> accessor N: <problem>".
GltfAccessorView gltfAccessorView(const tinygltf::Model& model, const std::string& path, int accessorIndex,
                                  const std::string& what, std::initializer_list<int> types,
                                  std::initializer_list<int> componentTypes);
// Component c of element i as a float: floats as they are, integers as they are or, normalized, as glTF maps them
// (unsigned: / max; signed: max(value / max, -1)).
float gltfComponent(const GltfAccessorView& view, size_t element, int c);
// An index (unsigned byte, short or int).
uint32_t gltfIndex(const GltfAccessorView& view, size_t element);

}  // namespace lidr
