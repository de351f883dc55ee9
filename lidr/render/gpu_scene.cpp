#include "lidr/render/gpu_scene.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cstring>
#include <memory>

#include <stb_image.h>

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"

namespace lidr {

namespace {
struct Vertex {
    float position[3];
    float normal[3];
    float texCoord[2];
};
}  // namespace

GpuScene::GpuScene(const Scene& scene, DrawOrder order) : materials_(scene.materials) {
    for (const Mesh& mesh : scene.meshes) {
        if (mesh.indices.empty()) continue;
        std::vector<Vertex> vertices(mesh.positions.size());
        glm::vec3 sum(0.0f);
        for (size_t i = 0; i < vertices.size(); ++i) {
            std::memcpy(vertices[i].position, &mesh.positions[i], sizeof(float) * 3);
            std::memcpy(vertices[i].normal, &mesh.normals[i], sizeof(float) * 3);
            if (!mesh.texCoords.empty())
                std::memcpy(vertices[i].texCoord, &mesh.texCoords[i], sizeof(float) * 2);
            else
                vertices[i].texCoord[0] = vertices[i].texCoord[1] = 0.0f;
            sum += mesh.positions[i];
        }
        Batch b;
        b.vertices = gl::Buffer::create(GL_ARRAY_BUFFER, vertices.data(), vertices.size() * sizeof(Vertex));
        std::vector<uint32_t> reversed;
        if (order == DrawOrder::Reversed) {  // triangles last to first, each keeping its winding
            reversed.reserve(mesh.indices.size());
            for (size_t t = mesh.triangleCount(); t-- > 0;)
                reversed.insert(reversed.end(), mesh.indices.begin() + 3 * t, mesh.indices.begin() + 3 * t + 3);
        }
        const std::vector<uint32_t>& indices = order == DrawOrder::Reversed ? reversed : mesh.indices;
        b.indices = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, indices.data(), indices.size() * sizeof(uint32_t));
        b.indexCount = static_cast<GLsizei>(indices.size());
        b.material = mesh.material;
        b.centroid = sum / float(std::max<size_t>(vertices.size(), 1));
        b.boundsMin = b.boundsMax = mesh.positions.empty() ? glm::vec3(0.0f) : mesh.positions[0];
        for (const glm::vec3& p : mesh.positions) b.boundsMin = glm::min(b.boundsMin, p), b.boundsMax = glm::max(b.boundsMax, p);
        triangles_ += mesh.triangleCount();
        batches_.push_back(std::move(b));
    }
    if (order == DrawOrder::Reversed) std::reverse(batches_.begin(), batches_.end());
    for (const Material& m : materials_) {
        if (m.diffuseTexture.empty()) {
            textures_.emplace_back();
            continue;
        }
        int w = 0, h = 0, n = 0;
        std::unique_ptr<stbi_uc, void (*)(void*)> data(stbi_load(m.diffuseTexture.c_str(), &w, &h, &n, 4),
                                                       stbi_image_free);
        if (!data)
            throw Error("material '" + m.name + "': cannot load texture '" + m.diffuseTexture +
                        "': " + stbi_failure_reason());
        // stb_image rows run top to bottom; OBJ texture coordinates have v up, so flip rows on upload.
        std::vector<uint8_t> flipped(static_cast<size_t>(w) * h * 4);
        for (int y = 0; y < h; ++y)
            std::memcpy(&flipped[static_cast<size_t>(y) * w * 4], data.get() + static_cast<size_t>(h - 1 - y) * w * 4,
                        static_cast<size_t>(w) * 4);
        textures_.push_back(gl::Texture::create2D(GL_RGBA8, w, h, GL_RGBA, GL_UNSIGNED_BYTE, flipped.data(),
                                                  GL_LINEAR_MIPMAP_LINEAR));
    }
    checkGl("GpuScene upload");
}

bool GpuScene::hasTransparent() const {
    return std::any_of(batches_.begin(), batches_.end(),
                       [&](const Batch& b) { return materials_[b.material].opacity < 1.0f; });
}

void GpuScene::drawBatch(const gl::Program& program, const Batch& b, bool setMaterials) const {
    if (setMaterials) {
        const Material& m = materials_[b.material];
        // shading.glsl's material uniforms: a program's own material shader may leave any of them out.
        program.setIfDeclared("uMaterialDiffuse", m.diffuse);
        program.setIfDeclared("uMaterialSpecular", m.specular);
        program.setIfDeclared("uMaterialShininess", m.shininess);
        program.setIfDeclared("uMaterialOpacity", m.opacity);
        const gl::Texture& tex = textures_[b.material];
        program.setIfDeclared("uMaterialHasTexture", tex ? 1.0f : 0.0f);
        if (tex) {
            tex.bind(gl::kUnitMaterial);
            program.setIfDeclared("uMaterialTexture", int(gl::kUnitMaterial));
        }
    }
    glBindBuffer(GL_ARRAY_BUFFER, b.vertices.id());
    glEnableVertexAttribArray(gl::kPosition);
    glVertexAttribPointer(gl::kPosition, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, position)));
    glEnableVertexAttribArray(gl::kNormal);
    glVertexAttribPointer(gl::kNormal, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, normal)));
    glEnableVertexAttribArray(gl::kTexCoord);
    glVertexAttribPointer(gl::kTexCoord, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, texCoord)));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.indices.id());
    StateCache::current().drawElements(GL_TRIANGLES, b.indexCount, GL_UNSIGNED_INT, nullptr);
}

void GpuScene::unbindGeometry() const {
    glDisableVertexAttribArray(gl::kPosition);
    glDisableVertexAttribArray(gl::kNormal);
    glDisableVertexAttribArray(gl::kTexCoord);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

void GpuScene::draw(const gl::Program& program, DrawFilter filter, bool setMaterials) const {
    drawSelected(program, filter, [](size_t, const glm::vec3&, const glm::vec3&) { return true; }, setMaterials);
}

void GpuScene::drawTransparentSorted(const gl::Program& program, const glm::vec3& eye) const {
    std::vector<const Batch*> order;
    for (const Batch& b : batches_)
        if (materials_[b.material].opacity < 1.0f) order.push_back(&b);
    std::stable_sort(order.begin(), order.end(), [&](const Batch* a, const Batch* b) {
        return glm::length(a->centroid - eye) > glm::length(b->centroid - eye);
    });
    for (const Batch* b : order) drawBatch(program, *b, true);
    unbindGeometry();
}

bool sphereTouchesBox(const glm::vec3& center, float radius, const glm::vec3& boxMin, const glm::vec3& boxMax) {
    const glm::vec3 nearest = glm::clamp(center, boxMin, boxMax);
    return glm::dot(nearest - center, nearest - center) <= radius * radius;
}

int GpuScene::drawSelected(const gl::Program& program, DrawFilter filter,
                           const std::function<bool(size_t, const glm::vec3&, const glm::vec3&)>& select,
                           bool setMaterials) const {
    int drawn = 0;
    for (size_t i = 0; i < batches_.size(); ++i) {
        const Batch& b = batches_[i];
        const bool transparent = materials_[b.material].opacity < 1.0f;
        if ((filter == DrawFilter::Opaque && transparent) || (filter == DrawFilter::Transparent && !transparent))
            continue;
        if (!select(i, b.boundsMin, b.boundsMax)) continue;
        drawBatch(program, b, setMaterials);
        ++drawn;
    }
    unbindGeometry();
    return drawn;
}

}  // namespace lidr
