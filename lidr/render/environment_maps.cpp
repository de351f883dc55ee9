#include "lidr/render/environment_maps.h"
#include "lidr/base/gl.h"

#include <sstream>

#include <glm/gtc/packing.hpp>

#include "lidr/base/error.h"
#include "lidr/gl/bindings.h"

namespace lidr {

namespace {
constexpr GLenum kHalfFloatOes = 0x8D61;  // OES_texture_half_float's HALF_FLOAT_OES (not GL 3.0's HALF_FLOAT)
}  // namespace

EnvironmentMaps::EnvironmentMaps(const GlInfo& info, bool floatTextures) : info_(info) {
    storage_ = floatTextures && info.halfFloatLinear ? EnvironmentStorage::HalfFloat : EnvironmentStorage::Rgbm8;
    const bool above = info.maxTextureUnits > int(gl::kUnitEnvironmentSplitSum);
    specularUnit_ = above ? int(gl::kUnitEnvironmentSpecular) : int(gl::kUnitEnvironmentSpecularLow);
    splitSumUnit_ = above ? int(gl::kUnitEnvironmentSplitSum) : int(gl::kUnitEnvironmentSplitSumLow);
}

EnvironmentLookup EnvironmentMaps::lookupFor(const GlInfo& info, EnvironmentLight::Lookup choice, std::string* reason) {
    if (choice == EnvironmentLight::Lookup::DiffuseOnly) {
        if (reason) *reason = "diffuse only as asked";
        return EnvironmentLookup::DiffuseOnly;
    }
    if (choice == EnvironmentLight::Lookup::Bias) {
        if (reason) *reason = "mip bias as asked";
        return EnvironmentLookup::Bias;
    }
    if (info.textureLod) return EnvironmentLookup::Lod;
    if (reason)
        *reason = std::string("no ") + (info.gles ? "EXT_shader_texture_lod" : "ARB_shader_texture_lod") +
                  ": roughness as a mip bias over the implicit LOD";
    return EnvironmentLookup::Bias;
}

void EnvironmentMaps::prepare(const EnvironmentLight& light, int indexTargets) {
    reason_.clear();
    if (!light.on()) {
        lookup_ = EnvironmentLookup::None;
        intensity_ = 0.0f;
        return;
    }
    if (light.map != uploaded_) {
        upload(*light.map);
        uploaded_ = light.map;
    }
    intensity_ = light.intensity;
    lookup_ = lookupFor(info_, light.lookup, &reason_);
    if (lookup_ != EnvironmentLookup::DiffuseOnly && specularUnit_ == int(gl::kUnitEnvironmentSpecularLow) &&
        indexTargets > specularUnit_) {
        lookup_ = EnvironmentLookup::DiffuseOnly;
        reason_ = std::to_string(info_.maxTextureUnits) + " texture units and " + std::to_string(indexTargets) +
                  " index targets: the specular cube's units (6, 7) are the index targets'";
    }
}

namespace {
// The stored values (StoredEnvironment: half floats as floats, RGBM bytes as 0..255) converted per component to
// the pixel type GL takes: each level's texels, and the table's.
template <typename T, typename Convert>
void converted(const StoredEnvironment& s, const Convert& convert, std::vector<std::vector<T>>& levels, std::vector<T>& table) {
    levels.assign(s.levels.size(), {});
    for (size_t l = 0; l < s.levels.size(); ++l)
        for (const glm::vec4& t : s.levels[l].texels)
            for (int k = 0; k < 4; ++k) levels[l].push_back(convert(t[k]));
    for (const glm::vec4& t : s.table)
        for (int k = 0; k < 4; ++k) table.push_back(convert(t[k]));
}

template <typename T>
void uploadAs(const StoredEnvironment& s, GLint cubeFormat, GLint tableFormat, GLenum type,
              const std::vector<std::vector<T>>& levels, const std::vector<T>& table, gl::Texture& cube,
              gl::Texture& splitSum) {
    cube = gl::Texture::createCube(cubeFormat, s.levels[0].size, int(levels.size()), GL_RGBA, type,
                                   [&](int level, int face) {
                                       const size_t side = size_t(s.levels[size_t(level)].size);
                                       return static_cast<const void*>(&levels[size_t(level)][size_t(face) * 4 * side * side]);
                                   },
                                   float(s.roughnessLevels - 1));
    splitSum = gl::Texture::create2D(tableFormat, s.tableSize, s.tableSize, GL_RGBA, type, table.data(), GL_LINEAR);
}
}  // namespace

void EnvironmentMaps::upload(const Environment& environment) {
    stored_ = std::make_unique<StoredEnvironment>(storeEnvironment(environment, storage_));
    const StoredEnvironment& s = *stored_;
    if (storage_ == EnvironmentStorage::HalfFloat && info_.gles) {
        // OES_texture_half_float: the halves themselves (the values are half floats already).
        std::vector<std::vector<uint16_t>> levels;
        std::vector<uint16_t> table;
        converted(s, [](float v) { return uint16_t(glm::packHalf1x16(v)); }, levels, table);
        uploadAs(s, GL_RGBA, GL_RGBA, kHalfFloatOes, levels, table, cube_, splitSum_);
    } else if (storage_ == EnvironmentStorage::HalfFloat) {
        // Floats already rounded to halves: GL's conversion keeps them exactly.
        std::vector<std::vector<float>> levels;
        std::vector<float> table;
        converted(s, [](float v) { return v; }, levels, table);
        uploadAs(s, GL_RGB16F_ARB, GL_RGBA16F_ARB, GL_FLOAT, levels, table, cube_, splitSum_);
    } else {
        std::vector<std::vector<uint8_t>> levels;
        std::vector<uint8_t> table;
        converted(s, [](float v) { return uint8_t(v); }, levels, table);
        uploadAs(s, GL_RGBA8, GL_RGBA8, GL_UNSIGNED_BYTE, levels, table, cube_, splitSum_);
    }
    checkGl("environment upload");
}

uint32_t EnvironmentMaps::variantKey(const gl::Program& program) const {
    return environmentVariantKey(program, lookup_, rgbm());
}

void EnvironmentMaps::bind(const gl::Program& program) const {
    program.setIfDeclared("uEnvironmentSpecular", specularUnit_);
    program.setIfDeclared("uEnvironmentSplitSum", splitSumUnit_);
    if (!program.declares("uEnvironmentSh")) return;
    glm::vec3 sh[9] = {};
    glm::vec4 params(0.0f, 0.0f, 0.0f, 2.0f);
    if (lookup_ != EnvironmentLookup::None && stored_) {
        for (int i = 0; i < 9; ++i) sh[i] = glm::vec3(uploaded_->sh[size_t(i)] * double(intensity_));
        params = glm::vec4(intensity_, rgbm() ? stored_->range : 0.0f, float(stored_->roughnessLevels - 1),
                           float(stored_->tableSize));
        if (lookup_ != EnvironmentLookup::DiffuseOnly) {
            cube_.bind(specularUnit_);
            splitSum_.bind(splitSumUnit_);
            glActiveTexture(GL_TEXTURE0);
        }
    }
    program.uniform<glm::vec3>("uEnvironmentSh").setArray(sh, 9);
    program.set("uEnvironment", params);
    program.setIfDeclared("uEnvironmentSize", stored_ ? float(stored_->levels[0].size) : 1.0f);
}

std::string EnvironmentMaps::describe() const {
    if (lookup_ == EnvironmentLookup::None || !stored_) return "none";
    std::ostringstream s;
    s << uploaded_->name << ", intensity " << intensity_ << ", " << environmentLookupName(lookup_);
    if (!reason_.empty()) s << " (" << reason_ << ")";
    s << ", " << (rgbm() ? "RGBM8" : "half-float") << " cube " << stored_->levels[0].size << " x "
      << stored_->levels[0].size << " x 6, " << stored_->roughnessLevels << " roughness levels, units " << specularUnit_
      << " and " << splitSumUnit_;
    return s.str();
}

}  // namespace lidr
