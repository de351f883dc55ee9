#pragma once
// The scene's geometry and material textures in GL buffers, drawn the same way by every pass and mode.
#include <functional>
#include <vector>

#include "lidr/gl/gl_resources.h"
#include "lidr/scene/scene.h"

namespace lidr {

enum class DrawFilter { Opaque, Transparent, All };

// True where the sphere touches the box [boxMin, boxMax] (an infinite radius touches every box).
bool sphereTouchesBox(const glm::vec3& center, float radius, const glm::vec3& boxMin, const glm::vec3& boxMax);

// The order meshes and their triangles are drawn in. Where fragments tie at the pre-pass depth (a back
// face meeting the front face at a silhouette, coplanar copies) a depth-EQUAL shading pass keeps the last
// one drawn; a pass that keeps the first one instead (multi-pass forward, whose additive passes must add
// one fragment per pixel) draws in Reversed order to shade the same surface.
enum class DrawOrder { AsGiven, Reversed };

class GpuScene {
public:
    GpuScene() = default;
    // Uploads geometry; loads material textures (stb_image) relative to nothing: paths are as in the Scene.
    explicit GpuScene(const Scene& scene, DrawOrder order = DrawOrder::AsGiven);
    // Draws meshes passing `filter`, setting the shading.glsl material uniforms on `program` when
    // `setMaterials` (a depth-only pass does not need them). The program must be in use.
    void draw(const gl::Program& program, DrawFilter filter, bool setMaterials) const;
    // Transparent meshes sorted back to front for `eye` (by mesh centroid distance).
    void drawTransparentSorted(const gl::Program& program, const glm::vec3& eye) const;
    // Draws the meshes passing `filter` for which select(batch, boundsMin, boundsMax) is true (batch: 0 ..
    // batchCount() - 1, in draw order); returns how many.
    int drawSelected(const gl::Program& program, DrawFilter filter,
                     const std::function<bool(size_t, const glm::vec3&, const glm::vec3&)>& select,
                     bool setMaterials) const;
    size_t batchCount() const { return batches_.size(); }
    void batchBounds(size_t batch, glm::vec3& boundsMin, glm::vec3& boundsMax) const {
        boundsMin = batches_.at(batch).boundsMin, boundsMax = batches_.at(batch).boundsMax;
    }
    bool hasTransparent() const;
    bool batchTransparent(size_t batch) const { return materials_[size_t(batches_.at(batch).material)].opacity < 1.0f; }
    size_t triangleCount() const { return triangles_; }

private:
    struct Batch {
        gl::Buffer vertices, indices;
        GLsizei indexCount = 0;
        int material = 0;
        glm::vec3 centroid{0.0f};
        glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
    };
    void drawBatch(const gl::Program& program, const Batch& b, bool setMaterials) const;
    void unbindGeometry() const;
    std::vector<Batch> batches_;
    std::vector<Material> materials_;
    std::vector<gl::Texture> textures_;  // one per material; empty texture when none
    size_t triangles_ = 0;
};

}  // namespace lidr
