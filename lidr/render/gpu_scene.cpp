#include "lidr/render/gpu_scene.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

#include <stb_image.h>

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/render/shading_variants.h"
#include "lidr/scene/sphere_bounds.h"
#include "lidr/scene/tangents.h"

namespace lidr {

namespace {
struct Vertex {
    float position[3];
    float normal[3];
    float texCoord[2];
};

constexpr GLint kSrgb8Alpha8 = 0x8C43;  // GL_SRGB8_ALPHA8, core since GL 2.1

// Base-colour texels are sRGB-encoded. Desktop GL decodes them in the texture unit (before filtering, as it
// should be); an OpenGL ES 2.0 / WebGL 1 context gets RGBA8 and shading.glsl decodes under GL_ES.
GLint colorTextureFormat() {
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    const bool gles = version && std::strncmp(version, "OpenGL ES", 9) == 0;
    return gles ? GLint(GL_RGBA8) : kSrgb8Alpha8;
}

int textureUnitLimitForTests = 0;  // 0: the context's own

int materialTextureUnits() {
    GLint units = 0;
    glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
    return textureUnitLimitForTests > 0 ? std::min(int(units), textureUnitLimitForTests) : int(units);
}
}  // namespace

void GpuScene::setTextureUnitLimitForTests(int units) { textureUnitLimitForTests = units; }

GpuScene::Batch GpuScene::upload(const Mesh& mesh, const Material& material, uint32_t features, DrawOrder order) const {
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
    if (!mesh.texCoords1.empty())
        b.texCoords1 = gl::Buffer::create(GL_ARRAY_BUFFER, mesh.texCoords1.data(), mesh.texCoords1.size() * sizeof(glm::vec2));
    if (features & material_feature::texture(TextureSlot::Normal)) {  // the file's tangents, or made here
        const std::vector<glm::vec4> tangents =
            mesh.tangents.empty() ? generateTangents(mesh, material.normalTexture.mapping.texCoord) : mesh.tangents;
        b.tangents = gl::Buffer::create(GL_ARRAY_BUFFER, tangents.data(), tangents.size() * sizeof(glm::vec4));
    }
    b.indices = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, indices.data(), indices.size() * sizeof(uint32_t));
    b.indexCount = static_cast<GLsizei>(indices.size());
    b.triangles = mesh.triangleCount();
    b.material = mesh.material;
    b.outer = closedMeshOuterWinding(mesh.positions, mesh.indices);  // the reversed order keeps each winding
    b.objectCentroid = sum / float(std::max<size_t>(vertices.size(), 1));
    b.objectMin = b.objectMax = mesh.positions.empty() ? glm::vec3(0.0f) : mesh.positions[0];
    for (const glm::vec3& p : mesh.positions) b.objectMin = glm::min(b.objectMin, p), b.objectMax = glm::max(b.objectMax, p);
    placeBatch(b);
    return b;
}

gl::Texture GpuScene::loadTexture(const Material& m, TextureSlot slot) const {
    const MaterialTexture* texture = materialTexture(m, slot);
    const std::shared_ptr<const ImageRGBA8>& image = texture ? texture->image : m.diffuseImage;
    const std::string& path = texture ? texture->name : m.diffuseTexture;
    if (!image && (texture || path.empty())) return {};
    int w = 0, h = 0, n = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> data(nullptr, stbi_image_free);
    if (image) {  // decoded by the importer (glTF)
        w = image->width;
        h = image->height;
    } else {
        data.reset(stbi_load(path.c_str(), &w, &h, &n, 4));
        if (!data)
            throw Error("material '" + m.name + "': cannot load texture '" + path + "': " + stbi_failure_reason());
    }
    const uint8_t* pixels = image ? image->pixels.data() : data.get();
    // Image rows run top to bottom; OBJ texture coordinates (and glTF's, flipped on import) have v up, so flip
    // rows on upload.
    std::vector<uint8_t> flipped(static_cast<size_t>(w) * h * 4);
    for (int y = 0; y < h; ++y)
        std::memcpy(&flipped[static_cast<size_t>(y) * w * 4], pixels + static_cast<size_t>(h - 1 - y) * w * 4,
                    static_cast<size_t>(w) * 4);
    return gl::Texture::create2D(textureSlotInfo(slot).srgb ? colorTextureFormat() : GLint(GL_RGBA8), w, h, GL_RGBA,
                                 GL_UNSIGNED_BYTE, flipped.data(), GL_LINEAR_MIPMAP_LINEAR);
}

void GpuScene::loadMaterial(const Material& m) {
    std::array<gl::Texture, kTextureSlots> textures;
    uint32_t loaded = 0;
    const int units = materialTextureUnits();
    for (int i = 0; i < kTextureSlots; ++i) {
        const TextureSlot slot = TextureSlot(i);
        gl::Texture t = loadTexture(m, slot);
        if (!t) continue;
        if (!textureSlotFits(slot, units)) {  // OpenGL ES 2.0 guarantees 8 (doc/colour.md)
            warnings_.push_back(textureUnitWarning(m, slot, units));
            continue;
        }
        textures[size_t(i)] = std::move(t);
        loaded |= 1u << i;
    }
    materials_.push_back(m);
    textures_.push_back(std::move(textures));
    features_.push_back(lidr::materialFeatures(m, loaded));
}

GpuScene::GpuScene(const Scene& scene, DrawOrder order) : order_(order) {
    for (const Material& m : scene.materials) loadMaterial(m);
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        const Mesh& mesh = scene.meshes[i];
        if (mesh.indices.empty()) continue;
        Batch b = upload(mesh, materials_.at(size_t(mesh.material)), features_.at(size_t(mesh.material)), order);
        b.id = i;
        triangles_ += b.triangles;
        batches_.push_back(std::move(b));
    }
    nextId_ = scene.meshes.size();
    if (order == DrawOrder::Reversed) std::reverse(batches_.begin(), batches_.end());
    checkGl("GpuScene upload");
}

void GpuScene::placeBatch(Batch& b) const {
    b.centroid = glm::vec3(b.transform * glm::vec4(b.objectCentroid, 1.0f));
    // The world box of the object's box: its eight corners transformed.
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? b.objectMax.x : b.objectMin.x, (c & 2) ? b.objectMax.y : b.objectMin.y,
                               (c & 4) ? b.objectMax.z : b.objectMin.z);
        const glm::vec3 w(b.transform * glm::vec4(corner, 1.0f));
        b.boundsMin = c ? glm::min(b.boundsMin, w) : w;
        b.boundsMax = c ? glm::max(b.boundsMax, w) : w;
    }
}

size_t GpuScene::batchIndex(ObjectId id) const {
    for (size_t i = 0; i < batches_.size(); ++i)
        if (batches_[i].id == id) return i;
    throw Error("no object " + std::to_string(id) + " in the scene (ids: the Scene's mesh indices, then those addObject " +
                "returned; removed ones and meshes without triangles do not exist)");
}

void GpuScene::setTransform(ObjectId id, const glm::mat4& objectToWorld) {
    Batch& b = batches_[batchIndex(id)];
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(objectToWorld[c][r]))
                throw Error("object " + std::to_string(id) + ": the transform is not finite");
    if (objectToWorld[0][3] != 0.0f || objectToWorld[1][3] != 0.0f || objectToWorld[2][3] != 0.0f || objectToWorld[3][3] != 1.0f)
        throw Error("object " + std::to_string(id) + ": the transform must be affine (bottom row 0 0 0 1)");
    const glm::mat3 linear(objectToWorld);
    const float det = glm::determinant(linear);
    if (!std::isfinite(det) || std::abs(det) < 1e-30f)
        throw Error("object " + std::to_string(id) + ": the transform is not invertible (determinant " + std::to_string(det) + ")");
    const glm::vec3 beforeMin = b.boundsMin, beforeMax = b.boundsMax;
    b.transform = objectToWorld;
    b.normalMatrix = glm::transpose(glm::inverse(linear));
    placeBatch(b);
    recordChange(glm::min(beforeMin, b.boundsMin), glm::max(beforeMax, b.boundsMax));
}

void GpuScene::recordChange(const glm::vec3& boundsMin, const glm::vec3& boundsMax) {
    if (changes_.size() >= kKeptChanges) changes_.erase(changes_.begin(), changes_.begin() + long(kKeptChanges / 2));
    changes_.push_back({++version_, boundsMin, boundsMax});
}

bool GpuScene::changedNear(const glm::vec3& center, float radius, uint64_t since) const {
    if (since >= version_) return false;
    if (changes_.empty() || changes_.front().version > since + 1) return true;  // not all kept: assume it did
    for (auto it = changes_.rbegin(); it != changes_.rend() && it->version > since; ++it)
        if (sphereTouchesBox(center, radius, it->boundsMin, it->boundsMax)) return true;
    return false;
}

ObjectId GpuScene::add(const Mesh& mesh, const Material& material) {
    validateObject(mesh, material);
    Mesh m = mesh;
    m.material = int(materials_.size());
    loadMaterial(material);
    Batch b = upload(m, material, features_.back(), order_);
    b.id = nextId_;
    triangles_ += b.triangles;
    // Drawn after the objects already there (or before them, in reversed order): depth-EQUAL ties resolve as
    // if the object had been the scene's last mesh.
    if (order_ == DrawOrder::Reversed) batches_.insert(batches_.begin(), std::move(b));
    else batches_.push_back(std::move(b));
    checkGl("GpuScene::add");
    const Batch& added = batches_[batchIndex(nextId_)];
    recordChange(added.boundsMin, added.boundsMax);
    return nextId_++;
}

void GpuScene::remove(ObjectId id) {
    const auto it = batches_.begin() + long(batchIndex(id));
    triangles_ -= it->triangles;
    recordChange(it->boundsMin, it->boundsMax);
    batches_.erase(it);  // its material stays (other objects may share it)
}

bool GpuScene::hasTransparent() const {
    return std::any_of(batches_.begin(), batches_.end(),
                       [&](const Batch& b) { return materials_[b.material].opacity < 1.0f; });
}

const gl::Program& GpuScene::useVariant(DrawState& state, uint32_t features) const {
    const gl::Program& program = state.base.variant(features | state.shadingKey, [&] {
        ShaderDefines defines = materialDefines(features);
        const ShaderDefines shading = shadingVariantDefines(state.shadingKey);
        defines.insert(defines.end(), shading.begin(), shading.end());
        return defines;
    });
    if (&program == state.current) return program;
    program.use();
    state.current = &program;
    if (&program != &state.base &&
        std::find(state.prepared.begin(), state.prepared.end(), &program) == state.prepared.end()) {
        program.copyUniformsFrom(state.base);  // this frame's camera, lights, units... as the caller set them
        state.prepared.push_back(&program);
    }
    return program;
}

void GpuScene::setMaterialUniforms(const gl::Program& program, const Material& m, size_t material) const {
    // shading.glsl's material uniforms: a program's own material shader may leave any of them out.
    const MetallicRoughness pbr = metallicRoughnessOf(m);
    program.setIfDeclared("uMaterialDiffuse", pbr.baseColor);
    program.setIfDeclared("uMaterialMetallic", pbr.metallic);
    program.setIfDeclared("uMaterialRoughness", pbr.roughness);
    // Blinn-Phong's inputs, for user material shaders written against them (doc/embedding.md)
    program.setIfDeclared("uMaterialSpecular", m.specular);
    program.setIfDeclared("uMaterialShininess", m.shininess);
    program.setIfDeclared("uMaterialOpacity", m.opacity);
    program.setIfDeclared("uMaterialEmissive", m.emissive);
    const std::array<gl::Texture, kTextureSlots>& textures = textures_[material];
    program.setIfDeclared("uMaterialHasTexture", textures[0] ? 1.0f : 0.0f);
    for (int i = 0; i < kTextureSlots; ++i) {
        if (!textures[size_t(i)]) continue;
        const TextureSlotInfo& slot = textureSlotInfo(TextureSlot(i));
        textures[size_t(i)].bind(slot.unit);
        program.setIfDeclared(slot.sampler, slot.unit);
        program.setIfDeclared(slot.transform, textureMapping(m, TextureSlot(i)).transform);
    }
    program.setIfDeclared("uOcclusionStrength", m.occlusionTexture.scale);
    program.setIfDeclared("uNormalScale", m.normalTexture.scale);
    program.setIfDeclared("uAlphaCutoff", m.alphaCutoff);
    if (!m.dielectric.isDefault()) {  // only its variant declares them (material_variants.h)
        program.setIfDeclared("uMaterialDielectricF0", m.dielectric.f0());
        program.setIfDeclared("uMaterialDielectricF90", m.dielectric.f90());
    }
}

void GpuScene::drawBatch(DrawState& state, const Batch& b, bool setMaterials) const {
    const uint32_t all = features_[size_t(b.material)];
    const uint32_t features = setMaterials ? all : depthFeatures(all);
    const gl::Program& program = useVariant(state, features);
    if (setMaterials || features) setMaterialUniforms(program, materials_[size_t(b.material)], size_t(b.material));
    program.set("uModel", b.transform);
    program.set("uNormalMatrix", b.normalMatrix);
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
    bool secondSet = false;
    for (int i = 0; i < kTextureSlots; ++i) secondSet = secondSet || (features & material_feature::secondSet(TextureSlot(i)));
    if (secondSet) {  // a mesh without a second set reads its first (the importer warned)
        if (b.texCoords1) {
            glBindBuffer(GL_ARRAY_BUFFER, b.texCoords1.id());
            glVertexAttribPointer(gl::kTexCoord1, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
        } else {
            glVertexAttribPointer(gl::kTexCoord1, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                                  reinterpret_cast<const void*>(offsetof(Vertex, texCoord)));
        }
        glEnableVertexAttribArray(gl::kTexCoord1);
    } else {
        glDisableVertexAttribArray(gl::kTexCoord1);
    }
    if (features & material_feature::texture(TextureSlot::Normal)) {
        glBindBuffer(GL_ARRAY_BUFFER, b.tangents.id());
        glVertexAttribPointer(gl::kTangent, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
        glEnableVertexAttribArray(gl::kTangent);
    } else {
        glDisableVertexAttribArray(gl::kTangent);
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.indices.id());
    StateCache::current().drawElements(GL_TRIANGLES, b.indexCount, GL_UNSIGNED_INT, nullptr);
}

void GpuScene::unbindGeometry() const {
    glDisableVertexAttribArray(gl::kPosition);
    glDisableVertexAttribArray(gl::kNormal);
    glDisableVertexAttribArray(gl::kTexCoord);
    glDisableVertexAttribArray(gl::kTexCoord1);
    glDisableVertexAttribArray(gl::kTangent);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

void GpuScene::draw(const gl::Program& program, DrawFilter filter, bool setMaterials,
                    const CameraMatrices* camera, uint32_t shadingKey) const {
    drawSelected(program, filter, [](size_t, const glm::vec3&, const glm::vec3&) { return true; }, setMaterials,
                 camera, shadingKey);
}

namespace {
// How far from the eye the near plane reaches (its farthest corner), with a margin: within that distance of a
// mesh's bounds the near plane may cut the mesh open, or the eye be inside it, and its inner side be seen.
float nearPlaneReach(const CameraMatrices& camera) {
    float reach = 0.0f;
    for (int c = 0; c < 4; ++c) {
        const glm::vec4 p = camera.inverseViewProjection *
                            glm::vec4((c & 1) ? 1.0f : -1.0f, (c & 2) ? 1.0f : -1.0f, -1.0f, 1.0f);
        reach = std::max(reach, glm::length(glm::vec3(p) / p.w - camera.eye));
    }
    return std::isfinite(reach) ? reach * 1.01f + camera.nearPlane : std::numeric_limits<float>::infinity();
}
}  // namespace

GLenum GpuScene::culledSide(size_t batch, const CameraMatrices& camera) const {
    return culledSide(batches_.at(batch), camera.eye, nearPlaneReach(camera));
}

GLenum GpuScene::culledSide(const Batch& b, const glm::vec3& eye, float reach) const {
    if (!cullClosedMeshes_ || b.outer == OuterWinding::Open || materials_[b.material].opacity < 1.0f) return 0;
    if (sphereTouchesBox(eye, reach, b.boundsMin, b.boundsMax)) return 0;
    // A mirroring transform turns the winding over.
    const bool mirrored = glm::determinant(glm::mat3(b.transform)) < 0.0f;
    return (b.outer == OuterWinding::CounterClockwise) != mirrored ? GL_BACK : GL_FRONT;
}

void GpuScene::drawTransparentSorted(const gl::Program& program, const glm::vec3& eye, uint32_t shadingKey) const {
    std::vector<const Batch*> order;
    for (const Batch& b : batches_)
        if (materials_[b.material].opacity < 1.0f) order.push_back(&b);
    std::stable_sort(order.begin(), order.end(), [&](const Batch* a, const Batch* b) {
        return glm::length(a->centroid - eye) > glm::length(b->centroid - eye);
    });
    DrawState state{program, &program, {}, shadingKey};
    for (const Batch* b : order) drawBatch(state, *b, true);
    if (state.current != &program) program.use();
    unbindGeometry();
}

bool sphereTouchesBox(const glm::vec3& center, float radius, const glm::vec3& boxMin, const glm::vec3& boxMax) {
    const glm::vec3 nearest = glm::clamp(center, boxMin, boxMax);
    return glm::dot(nearest - center, nearest - center) <= radius * radius;
}

namespace {
bool drawsBatch(DrawFilter filter, bool transparent) {
    return !((filter == DrawFilter::Opaque && transparent) || (filter == DrawFilter::Transparent && !transparent));
}
// The same, asking the batch's material only where the filter needs it (the frame plan asks All per light).
bool drawsBatch(const GpuScene& scene, DrawFilter filter, size_t batch) {
    return filter == DrawFilter::All || drawsBatch(filter, scene.batchTransparent(batch));
}
}  // namespace

bool GpuScene::batchesTouchSphere(const glm::vec4& posRadius, DrawFilter filter) const {
    for (size_t b = 0; b < batchCount(); ++b) {
        if (!drawsBatch(*this, filter, b)) continue;
        glm::vec3 lo, hi;
        batchBounds(b, lo, hi);
        if (sphereTouchesBox(glm::vec3(posRadius), posRadius.w, lo, hi)) return true;
    }
    return false;
}

bool GpuScene::batchesPixelRect(const CameraMatrices& camera, DrawFilter filter, glm::ivec4& rect) const {
    bool any = false;
    for (size_t b = 0; b < batchCount(); ++b) {
        if (!drawsBatch(*this, filter, b)) continue;
        glm::vec3 lo, hi;
        batchBounds(b, lo, hi);
        glm::ivec4 r;
        if (!boxPixelRect(camera, lo, hi, r)) continue;
        rect = any ? glm::ivec4(glm::min(glm::ivec2(rect), glm::ivec2(r)), glm::max(glm::ivec2(rect.z, rect.w), glm::ivec2(r.z, r.w)))
                   : r;
        any = true;
    }
    return any;
}

int GpuScene::drawSelected(const gl::Program& program, DrawFilter filter,
                           const std::function<bool(size_t, const glm::vec3&, const glm::vec3&)>& select,
                           bool setMaterials, const CameraMatrices* camera, uint32_t shadingKey) const {
    StateCache& cache = StateCache::current();
    // Culling goes through the cache on top of the pass's state, which is applied again after; a pass that culls
    // itself, or state the cache does not know, is left alone.
    const bool mayCull = cache.valid() && !cache.known().cull;
    const bool cullInner = mayCull && camera && cullClosedMeshes_;
    const RenderState pass = mayCull ? cache.known() : RenderState{};
    const float reach = cullInner ? nearPlaneReach(*camera) : 0.0f;
    int drawn = 0;
    DrawState state{program, &program, {}, shadingKey};
    for (size_t i = 0; i < batches_.size(); ++i) {
        const Batch& b = batches_[i];
        const bool transparent = materials_[b.material].opacity < 1.0f;
        if (!drawsBatch(filter, transparent))
            continue;
        if (!select(i, b.boundsMin, b.boundsMax)) continue;
        if (mayCull) {
            RenderState s = pass;
            GLenum side = cullInner ? culledSide(b, camera->eye, reach) : 0;
            // A one-sided material (glTF's doubleSided false) has no back: its back faces are culled in every
            // pass, so nothing is lit or drawn from behind. Mesh fronts are counter-clockwise.
            if (!materials_[size_t(b.material)].doubleSided)
                side = glm::determinant(glm::mat3(b.transform)) < 0.0f ? GL_FRONT : GL_BACK;
            s.cull = side != 0;
            if (side) s.cullFace = side;
            cache.apply(s);
        }
        drawBatch(state, b, setMaterials);
        ++drawn;
    }
    if (state.current != &program) program.use();
    if (mayCull) cache.apply(pass);
    unbindGeometry();
    return drawn;
}

}  // namespace lidr
