#pragma once
// The scene's geometry and material textures in GL buffers, drawn the same way by every pass and mode.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "lidr/gl/gl_resources.h"
#include "lidr/render/material_variants.h"
#include "lidr/scene/camera.h"
#include "lidr/scene/closed_mesh.h"
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

// An object is one of the Scene's meshes, named by its index in Scene::meshes, or one added later (the ids
// continue from there and are never reused). Its geometry stays as uploaded; a transform places it in the world.
using ObjectId = size_t;

class GpuScene {
public:
    GpuScene() = default;
    // Uploads geometry; loads material textures (stb_image) relative to nothing: paths are as in the Scene.
    explicit GpuScene(const Scene& scene, DrawOrder order = DrawOrder::AsGiven);
    // Draws meshes passing `filter`, setting the shading.glsl material uniforms on `program` when
    // `setMaterials` (a depth-only pass does not need them). The program must be in use. A material with
    // textures or alpha MASK is drawn with the program's variant for its features (material_variants.h; a
    // depth-only pass: its MASK variant), compiled on first use, given the program's uniforms; `program` is in
    // use again after. With `camera`, opaque
    // closed meshes that the eye and the near plane are outside of are drawn with their inner side culled
    // (cullsInnerSide); the pass's own state is restored after.
    // `shadingKey` (shading_variants.h, a shading pass's frame features: suns, tone map, encoding) is ORed into
    // every material's key, so each combination is a variant of its own.
    void draw(const gl::Program& program, DrawFilter filter, bool setMaterials,
              const CameraMatrices* camera = nullptr, uint32_t shadingKey = 0) const;
    // Transparent meshes sorted back to front for `eye` (by mesh centroid distance).
    void drawTransparentSorted(const gl::Program& program, const glm::vec3& eye, uint32_t shadingKey = 0) const;
    // Draws the meshes passing `filter` for which select(batch, boundsMin, boundsMax) is true (batch: 0 ..
    // batchCount() - 1, in draw order); returns how many.
    int drawSelected(const gl::Program& program, DrawFilter filter,
                     const std::function<bool(size_t, const glm::vec3&, const glm::vec3&)>& select,
                     bool setMaterials, const CameraMatrices* camera = nullptr, uint32_t shadingKey = 0) const;
    // The GL face (GL_BACK or GL_FRONT) that draw() culls for this batch seen from `camera`, 0 for none: the inner
    // side of an opaque closed mesh (closedMeshOuterWinding, after the object's transform) whose bounds neither the
    // eye nor any point of the near plane reaches. From outside, that side always lies behind the outer one.
    GLenum culledSide(size_t batch, const CameraMatrices& camera) const;
    // false: every mesh drawn with both sides (the image is the same; tests compare the two).
    void setCullClosedMeshes(bool on) { cullClosedMeshes_ = on; }
    size_t batchCount() const { return batches_.size(); }
    void batchBounds(size_t batch, glm::vec3& boundsMin, glm::vec3& boundsMax) const {
        boundsMin = batches_.at(batch).boundsMin, boundsMax = batches_.at(batch).boundsMax;
    }
    bool hasTransparent() const;
    bool batchTransparent(size_t batch) const { return materials_[size_t(batches_.at(batch).material)].opacity < 1.0f; }
    // Whether the bounds of a batch `filter` draws touch the sphere (centre, radius).
    bool batchesTouchSphere(const glm::vec4& posRadius, DrawFilter filter) const;
    // The pixel rectangle (x0, y0, x1, y1, inclusive, GL window coordinates) covering the on-screen bounds of the
    // batches `filter` draws; false where none is on screen.
    bool batchesPixelRect(const CameraMatrices& camera, DrawFilter filter, glm::ivec4& rect) const;
    size_t triangleCount() const { return triangles_; }
    // The shader-variant key each material is drawn with (material_variants.h), by material index.
    uint32_t materialFeatures(size_t material) const { return features_.at(material); }
    // What the scene could not draw as its materials ask (a texture left out for want of texture units), one
    // line each; tools print them with the scene's warnings.
    const std::vector<std::string>& warnings() const { return warnings_; }
    // For tests: the texture units material textures may use (the context's own count by default); textures on
    // units at or above it are left out as on a context that has fewer. Applies to materials loaded after.
    static void setTextureUnitLimitForTests(int units);

    // Dynamic scenes. setTransform places an object (object -> world; the Scene's meshes start at identity, their
    // positions being world space); its bounds, used for light culling, follow. add uploads a mesh with its own
    // material and returns its id; remove deletes one. Each throws lidr::Error (unknown id, a transform that is
    // not finite or not invertible, a bad mesh or material) before changing anything.
    void setTransform(ObjectId id, const glm::mat4& objectToWorld);
    ObjectId add(const Mesh& mesh, const Material& material);
    void remove(ObjectId id);
    // Changes, for passes that keep what they drew (shadow maps): version() counts setTransform, add and remove
    // calls; changedNear says whether one after `since` touched the sphere (the object's bounds before or after
    // it). Conservative: true where the record of that change was not kept (the last kKeptChanges are).
    uint64_t version() const { return version_; }
    bool changedNear(const glm::vec3& center, float radius, uint64_t since) const;
    static constexpr size_t kKeptChanges = 4096;

private:
    struct Batch {
        ObjectId id = 0;
        gl::Buffer vertices, indices;
        gl::Buffer texCoords1, tangents;  // only where the mesh has a second set / its material a normal texture
        GLsizei indexCount = 0;
        size_t triangles = 0;
        int material = 0;
        glm::mat4 transform{1.0f};
        glm::mat3 normalMatrix{1.0f};
        glm::vec3 objectCentroid{0.0f}, objectMin{0.0f}, objectMax{0.0f};  // as uploaded
        glm::vec3 centroid{0.0f};                                           // world, after the transform
        glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
        OuterWinding outer = OuterWinding::Open;  // of the mesh as uploaded
    };
    Batch upload(const Mesh& mesh, const Material& material, uint32_t features, DrawOrder order) const;
    void loadMaterial(const Material& m);  // its textures, its features, warnings
    gl::Texture loadTexture(const Material& m, TextureSlot slot) const;
    // The program in use while a draw call draws its batches: the caller's, or a variant of it.
    struct DrawState {
        const gl::Program& base;
        const gl::Program* current;
        std::vector<const gl::Program*> prepared;  // variants given base's uniforms in this draw call
        uint32_t shadingKey = 0;                   // shading_variants.h
    };
    const gl::Program& useVariant(DrawState& state, uint32_t features) const;
    void setMaterialUniforms(const gl::Program& program, const Material& m, size_t material) const;
    void placeBatch(Batch& b) const;  // world centroid and bounds from the transform
    size_t batchIndex(ObjectId id) const;  // throws lidr::Error for an id that is not (or no longer) there
    void drawBatch(DrawState& state, const Batch& b, bool setMaterials) const;
    GLenum culledSide(const Batch& b, const glm::vec3& eye, float nearReach) const;
    void unbindGeometry() const;
    std::vector<Batch> batches_;
    std::vector<Material> materials_;
    std::vector<std::array<gl::Texture, kTextureSlots>> textures_;  // per material, by TextureSlot; empty: none
    std::vector<uint32_t> features_;                                // per material
    std::vector<std::string> warnings_;
    size_t triangles_ = 0;
    DrawOrder order_ = DrawOrder::AsGiven;
    bool cullClosedMeshes_ = true;
    ObjectId nextId_ = 0;
    struct Change {
        uint64_t version;
        glm::vec3 boundsMin, boundsMax;  // what the object covered before and after
    };
    void recordChange(const glm::vec3& boundsMin, const glm::vec3& boundsMax);
    uint64_t version_ = 0;
    std::vector<Change> changes_;  // the last kKeptChanges, oldest first
};

}  // namespace lidr
