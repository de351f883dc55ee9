#pragma once
// What every mode does with shadows each frame (issue 30): the lights that cast (PointLight::castsShadow, when
// ShadingParameters::shadows is enabled) get their maps in a ShadowAtlas, made on first use and again when its
// options change; each light's first atlas tile goes into the light table (LightTable::update), and the shading
// programs compiled with defines() read the atlas bound by bind() (shaders/common/shadow_lookup.glsl).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "lidr/gl/gl_info.h"
#include "lidr/gl/shader_source.h"
#include "lidr/render/light_table.h"
#include "lidr/render/shadow_atlas.h"

namespace lidr {

class ShadowMaps {
public:
    explicit ShadowMaps(const GlInfo& info) : info_(info) {}
    // Draws the maps this frame needs (ShadowAtlas::update: only those whose light or range changed). Returns
    // the lights' first tiles for LightTable::update: empty when no light casts (shadows off, or no caster),
    // else one entry per light, -1 for those that cast none. Throws lidr::Error (before drawing) where the
    // casters need more maps than the atlas holds, or a spot's cone is wider than one map covers.
    const std::vector<int>& update(const GpuScene& scene, const std::vector<PointLight>& lights,
                                   const ShadowSettings& settings);
    bool active() const { return !firstTiles_.empty(); }  // the last update() had casters
    int casters() const { return casters_; }
    int mapsDrawn() const { return mapsDrawn_; }  // by the last update()
    const ShadowAtlas* atlas() const { return atlas_.get(); }
    // LIDR_SHADOWS, with LIDR_SHADOW_PCF (settings.filtered) and LIDR_SHADOW_PACKED (an RGBA8 atlas).
    ShaderDefines defines(const ShadowSettings& settings) const;
    // The atlas to its texture unit and shadow_lookup.glsl's uniforms, where the program declares them.
    void bind(const gl::Program& program, const ShadowSettings& settings) const;
    // The lights of `lights` reordered or subset as `sourceIndex` says (entry k: 1-based index into the lights
    // given to update()), with their tiles: for tables built from a selection of the lights.
    // The atlas's texture unit: gl::kUnitShadowAtlas, or on a context with 16 units the fixed light table's
    // (renderers refuse shadows with a fixed-point table there: checkUnits).
    int unit() const;
    // Throws lidr::UnsupportedError where shadows cannot be bound next to `table` (16 texture units and a
    // fixed-point light table).
    void checkUnits(LightTableFormat table) const;
    // The shadowed twin of a shading program: the same shader files compiled with `defines` plus
    // defines(settings) (with geometryAttributes()), made on first use and kept per name and shadow defines.
    const gl::Program& program(const std::string& name, const std::string& vertexFile, const std::string& fragmentFile,
                               const ShaderDefines& defines, const ShadowSettings& settings);
    // The program a shading pass draws with this frame: `plain` (built from geometry.vert and `fragmentFile` with
    // `defines`) where no light casts, else its shadowed twin (program(), under plain's name).
    const gl::Program& shadingProgram(const gl::Program& plain, const std::string& fragmentFile,
                                      const ShaderDefines& defines, const ShadowSettings& settings);
    std::vector<int> tilesFor(const std::vector<uint32_t>& sourceIndex) const;

private:
    GlInfo info_;
    std::unique_ptr<ShadowAtlas> atlas_;
    ShadowAtlasOptions atlasOptions_{};
    std::vector<int> firstTiles_;
    int casters_ = 0, mapsDrawn_ = 0;
    std::map<std::string, gl::Program> programs_;
};

}  // namespace lidr
