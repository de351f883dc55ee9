#pragma once
// The shadow settings of the option table (lidr/modes/render_options.h: shadows, shadow-lookup, shadow-filter,
// shadow-atlas) read and checked once, here, for every tool: which lights cast, the atlas, the look-up and the
// filter, applied to each frame's lights and shading.
#include <string>
#include <vector>

#include "lidr/modes/render_options.h"
#include "lidr/render/shadow_settings.h"
#include "lidr/scene/camera.h"
#include "lidr/scene/scene.h"

namespace lidr {

// --shadows and its settings (shadows, shadow-lookup, shadow-filter, shadow-atlas of the option table), checked
// against each other and the mode by shadowChoiceFrom, applied to each frame's lights and shading.
struct ShadowChoice {
    enum class Casters { Off, Scene, Brightest };
    Casters casters = Casters::Off;
    int brightest = 0;             // Casters::Brightest: K (chooseShadowCasters)
    ShadowSettings settings{};     // enabled unless Off
    bool automaticTile = true;     // --shadow-atlas without :TILE: the largest tile (<= 512) the casters' maps fit
    bool lidrMode = false;         // the lookup setting applies (describe() names it)
    // Sets the lights' castsShadow (Scene: left as the scene says; Brightest: the rule, with the scene's camera)
    // and shading.shadows. Throws lidr::Error where the casters' maps cannot fit the atlas.
    void apply(const Scene& scene, std::vector<PointLight>& lights, ShadingParameters& shading) const;
    // The same with the rule's view given (the viewer's and the page's moving camera).
    void apply(const CameraMatrices& view, std::vector<PointLight>& lights, ShadingParameters& shading) const;
    // "8 brightest, atlas 4096 (512-texel tiles, chosen to fit), lookup volume, filter nearest"; `used`: apply()'s.
    std::string describe(const ShadowSettings& used) const;
};

// The shadow settings in `values`, checked against each other and `mode` (the look-up is LIDR's); throws
// lidr::Error naming the option ("--shadows must be off, scene or a number of lights K ...").
ShadowChoice shadowChoiceFrom(const RenderOptionValues& values, const std::string& mode);

}  // namespace lidr
