#include "lidr/render/shadow_maps.h"
#include "lidr/base/gl.h"

#include <string>

#include "lidr/base/error.h"
#include "lidr/gl/bindings.h"
#include "lidr/render/depth_prepass.h"

namespace lidr {

const std::vector<int>& ShadowMaps::update(const GpuScene& scene, const std::vector<PointLight>& lights,
                                           const ShadowSettings& settings) {
    firstTiles_.clear();
    casters_ = mapsDrawn_ = 0;
    if (!settings.enabled) return firstTiles_;
    std::vector<int> casters;
    for (size_t i = 0; i < lights.size(); ++i)
        if (lights[i].castsShadow) casters.push_back(int(i));
    if (casters.empty()) return firstTiles_;
    if (!atlas_ || atlasOptions_.size != settings.atlas.size || atlasOptions_.tileSize != settings.atlas.tileSize ||
        atlasOptions_.slopeBias != settings.atlas.slopeBias) {
        atlas_ = std::make_unique<ShadowAtlas>(info_, settings.atlas);
        atlasOptions_ = settings.atlas;
    }
    mapsDrawn_ = atlas_->update(scene, lights, casters);
    casters_ = int(casters.size());
    firstTiles_.assign(lights.size(), -1);
    const auto& slots = atlas_->slots();
    for (size_t s = slots.size(); s-- > 0;) firstTiles_[size_t(slots[s].light)] = int(s);  // the lowest slot wins
    return firstTiles_;
}

std::vector<int> ShadowMaps::tilesFor(const std::vector<uint32_t>& sourceIndex) const {
    if (firstTiles_.empty()) return {};
    std::vector<int> tiles(sourceIndex.size(), -1);
    for (size_t k = 0; k < sourceIndex.size(); ++k)
        if (sourceIndex[k] >= 1 && sourceIndex[k] <= firstTiles_.size()) tiles[k] = firstTiles_[sourceIndex[k] - 1];
    return tiles;
}

int ShadowMaps::unit() const {
    return info_.maxTextureUnits > gl::kUnitShadowAtlas ? int(gl::kUnitShadowAtlas) : int(gl::kUnitShadowAtlasOn16);
}

void ShadowMaps::checkUnits(LightTableFormat table) const {
    if (unit() == int(gl::kUnitShadowAtlasOn16) && table == LightTableFormat::Fixed16)
        throw UnsupportedError("shadows: this context has " + std::to_string(info_.maxTextureUnits) +
                               " texture units and no float textures: the shadow atlas needs a 17th unit, or the "
                               "fixed-point light table's third unit");
}

ShaderDefines ShadowMaps::defines(const ShadowSettings& settings) const {
    ShaderDefines d = {{"LIDR_SHADOWS", "1"}};
    if (settings.filtered) d.push_back({"LIDR_SHADOW_PCF", "1"});
    if (atlas_ && atlas_->packed()) d.push_back({"LIDR_SHADOW_PACKED", "1"});
    return d;
}

const gl::Program& ShadowMaps::program(const std::string& name, const std::string& vertexFile,
                                      const std::string& fragmentFile, const ShaderDefines& defines,
                                      const ShadowSettings& settings) {
    ShaderDefines all = defines;
    for (const auto& d : this->defines(settings)) all.push_back(d);
    std::string key = name;
    for (const auto& d : all) key += " " + d.first + "=" + d.second;
    auto found = programs_.find(key);
    if (found != programs_.end()) return found->second;
    gl::Program p = gl::Program::create(name + "-shadowed", buildShaderSource(vertexFile, defines),
                                        buildShaderSource(fragmentFile, all), geometryAttributes());
    return programs_.emplace(key, std::move(p)).first->second;
}

const gl::Program& ShadowMaps::shadingProgram(const gl::Program& plain, const std::string& fragmentFile,
                                             const ShaderDefines& defines, const ShadowSettings& settings) {
    return active() ? program(plain.name(), "geometry.vert", fragmentFile, defines, settings) : plain;
}

void ShadowMaps::bind(const gl::Program& program, const ShadowSettings& settings) const {
    if (!atlas_ || !program.declares("uShadowAtlas")) return;
    atlas_->texture().bind(unit());
    program.set("uShadowAtlas", unit());
    const float tilesPerRow = float(atlas_->size() / atlas_->tileSize());
    program.setIfDeclared("uShadowAtlasLayout", glm::vec4(tilesPerRow, 1.0f / tilesPerRow, float(atlas_->tileSize()),
                                                          1.0f / float(atlas_->size())));
    program.setIfDeclared("uShadowBias", glm::vec2(settings.biasTexels, settings.biasRange));
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace lidr
