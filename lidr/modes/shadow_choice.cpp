#include "lidr/modes/shadow_choice.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include <glm/glm.hpp>

#include "lidr/base/error.h"
#include "lidr/render/shadow_atlas.h"
#include "lidr/render/shadow_casters.h"

namespace lidr {

namespace {
bool powerOfTwo(long v) { return v > 0 && (v & (v - 1)) == 0; }

long atlasNumber(const std::string& text, const std::string& whole) {
    if (text.empty() || text.size() > 6 || !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
        throw Error("--shadow-atlas must be SIZE or SIZE:TILE (whole numbers of texels, e.g. 4096:256), got '" + whole + "'");
    return std::stol(text);
}
}  // namespace

ShadowChoice shadowChoiceFrom(const RenderOptionValues& values, const std::string& mode) {
    const auto get = [&](const std::string& name) { return renderOptionValue(values, name); };
    const auto given = [&](const std::string& name) { return values.count(name) != 0; };
    ShadowChoice c;
    const std::string shadows = get("shadows");
    const std::optional<std::string> shadowLookup =
        given("shadow-lookup") ? std::optional<std::string>(get("shadow-lookup")) : std::nullopt;
    const std::optional<std::string> shadowFilter =
        given("shadow-filter") ? std::optional<std::string>(get("shadow-filter")) : std::nullopt;
    const std::optional<std::string> shadowAtlas =
        given("shadow-atlas") ? std::optional<std::string>(get("shadow-atlas")) : std::nullopt;
    if (shadows == "off") {
        for (const auto* given : {&shadowLookup, &shadowFilter, &shadowAtlas})
            if (*given)
                throw Error("--shadow-lookup, --shadow-filter and --shadow-atlas set up shadows: add --shadows scene or "
                            "--shadows K");
        return c;
    }
    if (shadows == "scene") {
        c.casters = ShadowChoice::Casters::Scene;
    } else {
        const bool digits = !shadows.empty() && shadows.size() <= 5 &&
                            std::all_of(shadows.begin(), shadows.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
        if (!digits || std::stoi(shadows) > 65535)
            throw Error("--shadows must be off, scene or a number of lights K in 0..65535, got '" + shadows + "'");
        c.casters = ShadowChoice::Casters::Brightest;
        c.brightest = std::stoi(shadows);
    }
    c.settings.enabled = true;
    c.lidrMode = mode == "lidr";
    const std::string lookup = shadowLookup.value_or("forward");
    if (lookup != "volume" && lookup != "forward")
        throw Error("--shadow-lookup must be volume or forward, got '" + lookup + "'");
    if (shadowLookup && mode != "lidr")
        throw Error("--shadow-lookup says where LIDR applies shadows; the " + mode +
                    " mode looks them up as it shades (use --mode lidr, or leave it out)");
    c.settings.lidrLookup = lookup == "volume" ? ShadowLookup::VolumePass : ShadowLookup::ForwardPass;
    const std::string filter = shadowFilter.value_or("nearest");
    if (filter != "nearest" && filter != "pcf")
        throw Error("--shadow-filter must be nearest or pcf, got '" + filter + "'");
    c.settings.filtered = filter == "pcf";
    c.settings.atlas.size = 4096;
    if (shadowAtlas) {
        const size_t colon = shadowAtlas->find(':');
        const long size = atlasNumber(shadowAtlas->substr(0, colon), *shadowAtlas);
        if (!powerOfTwo(size) || size < 16 || size > 8192)
            throw Error("--shadow-atlas: SIZE must be a power of two from 16 to 8192 texels, got " + std::to_string(size));
        c.settings.atlas.size = int(size);
        if (colon != std::string::npos) {
            const long tile = atlasNumber(shadowAtlas->substr(colon + 1), *shadowAtlas);
            if (!powerOfTwo(tile) || tile < 16 || tile > size)
                throw Error("--shadow-atlas: TILE must be a power of two from 16 to SIZE (" + std::to_string(size) +
                            "), got " + std::to_string(tile));
            c.settings.atlas.tileSize = int(tile);
            c.automaticTile = false;
        }
    }
    if (c.automaticTile) c.settings.atlas.tileSize = std::min(512, c.settings.atlas.size);
    return c;
}

void ShadowChoice::apply(const Scene& scene, std::vector<PointLight>& lights, ShadingParameters& shading) const {
    apply(cameraMatrices(scene.camera, scene.width, scene.height), lights, shading);
}

void ShadowChoice::apply(const CameraMatrices& view, std::vector<PointLight>& lights, ShadingParameters& shading) const {
    shading.shadows = settings;
    if (casters == Casters::Off) return;
    if (casters == Casters::Brightest) chooseShadowCasters(lights, view, brightest);
    for (size_t i = 0; i < lights.size(); ++i)  // the scene's own flags: a cone one map cannot cover
        if (lights[i].castsShadow && lights[i].isSpot() && !(lights[i].outerConeAngle <= kMaxShadowConeAngle))
            throw Error("--shadows scene: light " + std::to_string(i) + " is a spot light of " +
                        std::to_string(int(std::lround(glm::degrees(lights[i].outerConeAngle)))) +
                        " degrees marked to cast; one shadow map covers cones up to " +
                        std::to_string(int(std::lround(glm::degrees(kMaxShadowConeAngle)))) +
                        " degrees (the K brightest leave such lights out)");
    if (!automaticTile) return;  // the atlas refuses casters it cannot hold, naming the count
    try {
        shading.shadows.atlas.tileSize = shadowTileToFit(lights, settings.atlas.size);
    } catch (const Error& e) {
        throw Error(std::string("--") + e.what() + " (--shadow-atlas)");  // the library's "shadows: the casters ..."
    }
}

std::string ShadowChoice::describe(const ShadowSettings& used) const {
    if (casters == Casters::Off) return "off";
    std::ostringstream s;
    s << (casters == Casters::Scene ? std::string("the scene's flags") : std::to_string(brightest) + " brightest")
      << ", atlas " << used.atlas.size << " (" << used.atlas.tileSize << "-texel tiles"
      << (automaticTile ? ", chosen to fit" : "") << ")";
    if (lidrMode) s << ", lookup " << (settings.lidrLookup == ShadowLookup::VolumePass ? "volume" : "forward");
    s << ", filter "
      << (settings.filtered ? "pcf" : "nearest");
    return s.str();
}

}  // namespace lidr
