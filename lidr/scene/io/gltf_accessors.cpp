#include "lidr/scene/io/gltf_accessors.h"

#include <algorithm>
#include <cstring>

// The declarations only: tinygltf's implementation is compiled in gltf_importer.cpp.
#include <nlohmann/json.hpp>
#define TINYGLTF_NO_INCLUDE_JSON
#define TINYGLTF_NO_INCLUDE_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>

#include "lidr/base/error.h"

namespace lidr {

GltfAccessorView gltfAccessorView(const tinygltf::Model& model, const std::string& path, int accessorIndex,
                                  const std::string& what, std::initializer_list<int> types,
                                  std::initializer_list<int> componentTypes) {
    const auto fail = [&](const std::string& problem) { throw Error(path + ": " + problem); };
    const std::string name = what + " accessor " + std::to_string(accessorIndex);
    if (accessorIndex < 0 || size_t(accessorIndex) >= model.accessors.size())
        fail(what + " accessor " + std::to_string(accessorIndex) + " out of range (" +
             std::to_string(model.accessors.size()) + " accessors)");
    const tinygltf::Accessor& accessor = model.accessors[size_t(accessorIndex)];
    if (std::find(types.begin(), types.end(), accessor.type) == types.end())
        fail(name + ": type " + std::to_string(accessor.type) + " is not the type " + what + " needs");
    if (std::find(componentTypes.begin(), componentTypes.end(), accessor.componentType) == componentTypes.end())
        fail(name + ": component type " + std::to_string(accessor.componentType) + " is not allowed for " + what);
    if (accessor.sparse.isSparse) fail(name + ": sparse accessors are not supported");
    GltfAccessorView v;
    v.count = accessor.count;
    v.componentType = accessor.componentType;
    v.components = tinygltf::GetNumComponentsInType(uint32_t(accessor.type));
    v.normalized = accessor.normalized;
    if (accessor.bufferView < 0) return v;
    if (size_t(accessor.bufferView) >= model.bufferViews.size())
        fail(name + ": buffer view " + std::to_string(accessor.bufferView) + " out of range (" +
             std::to_string(model.bufferViews.size()) + " buffer views)");
    const tinygltf::BufferView& bufferView = model.bufferViews[size_t(accessor.bufferView)];
    if (bufferView.buffer < 0 || size_t(bufferView.buffer) >= model.buffers.size())
        fail(name + ": buffer " + std::to_string(bufferView.buffer) + " out of range (" +
             std::to_string(model.buffers.size()) + " buffers)");
    const tinygltf::Buffer& buffer = model.buffers[size_t(bufferView.buffer)];
    const size_t elementSize = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(accessor.componentType))) * size_t(v.components);
    v.stride = bufferView.byteStride ? bufferView.byteStride : elementSize;
    if (bufferView.byteOffset > buffer.data.size() || bufferView.byteLength > buffer.data.size() - bufferView.byteOffset)
        fail(name + ": buffer view " + std::to_string(accessor.bufferView) + " (bytes " +
             std::to_string(bufferView.byteOffset) + " + " + std::to_string(bufferView.byteLength) +
             ") lies outside buffer " + std::to_string(bufferView.buffer) + " (" + std::to_string(buffer.data.size()) +
             " bytes)");
    // Overflow-safe: count and stride come from the file.
    const size_t needed = v.count == 0 ? 0 : accessor.byteOffset + elementSize;
    const bool fits = v.count == 0 ||
                      (needed <= bufferView.byteLength && (v.count - 1) <= (bufferView.byteLength - needed) / v.stride);
    if (!fits)
        fail(name + ": " + std::to_string(v.count) + " elements from byte " + std::to_string(accessor.byteOffset) +
             " do not fit buffer view " + std::to_string(accessor.bufferView) + " (" +
             std::to_string(bufferView.byteLength) + " bytes)");
    v.data = buffer.data.data() + bufferView.byteOffset + accessor.byteOffset;
    return v;
}

float gltfComponent(const GltfAccessorView& v, size_t element, int c) {
    if (!v.data) return 0.0f;
    const unsigned char* p = v.data + element * v.stride;
    switch (v.componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float f;
        std::memcpy(&f, p + 4 * c, 4);
        return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return float(p[c]) / (v.normalized ? 255.0f : 1.0f);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t s;
        std::memcpy(&s, p + 2 * c, 2);
        return float(s) / (v.normalized ? 65535.0f : 1.0f);
    }
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const float b = float(int8_t(p[c]));
        return v.normalized ? std::max(b / 127.0f, -1.0f) : b;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        int16_t s;
        std::memcpy(&s, p + 2 * c, 2);
        return v.normalized ? std::max(float(s) / 32767.0f, -1.0f) : float(s);
    }
    default: return 0.0f;
    }
}

uint32_t gltfIndex(const GltfAccessorView& v, size_t element) {
    if (!v.data) return 0;
    const unsigned char* p = v.data + element * v.stride;
    if (v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) return p[0];
    if (v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        uint16_t s;
        std::memcpy(&s, p, 2);
        return s;
    }
    uint32_t i;
    std::memcpy(&i, p, 4);
    return i;
}

}  // namespace lidr
