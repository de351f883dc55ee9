#pragma once
// The renderer's settings as one table of descriptors (renderOptions()): name, type, choices or range, default, help
// and the modes that use each. lidr-demo's and lidr-bench's command lines, the viewer's panel and the web page's URL
// query are made from it, and its checks (setRenderOption, renderModeOptionsFrom) are the only ones: a tool adds
// none of its own. A new option is one row in render_options.cpp and, where it sets a field, one line in
// renderModeOptionsFrom.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "lidr/modes/render_mode.h"
#include "lidr/render/output_transform.h"

namespace lidr {

enum class RenderOptionType {
    Flag,    // on or off ("--no-depth-bounds" on a command line; "on"/"off" elsewhere)
    Int,     // a whole number in [min, max]
    Number,  // a finite number in [min, max]
    Choice,  // one of choices
    Text,    // checked where it is read (the shadow settings' forms: "off", "scene", K; SIZE[:TILE])
};

struct RenderOption {
    std::string name;  // "tile-size": --tile-size on a command line, tile-size=16 in a URL query, a viewer setting
    RenderOptionType type = RenderOptionType::Text;
    std::vector<std::string> choices;  // Choice: the valid values; Int/Flag: suggested values for a menu (viewer)
    double min = 0.0, max = 0.0;       // Int, Number
    std::string defaultValue;  // what leaving it out means; "" where that is the scene's or the library's default
    std::string help;          // one paragraph for --help and tooltips
    std::vector<std::string> modes;  // the modes that read it; empty: every mode
    std::string unit;                // Int: after the range in messages (" pixels")
    bool usedBy(const std::string& mode) const;
    std::string typeName() const;  // "INT", "FLOAT", "TEXT" (command-line help)
};

// Every renderer setting, in the order tools show them.
const std::vector<RenderOption>& renderOptions();
// The descriptor named `name`; null where there is none.
const RenderOption* findRenderOption(const std::string& name);

// The settings given, by name, as text ("on"/"off" for flags); a name left out takes its default.
using RenderOptionValues = std::map<std::string, std::string>;

// Checks `value` against `option`'s type, range and choices; throws lidr::Error naming --NAME, what it takes and
// the value given.
void checkRenderOption(const RenderOption& option, const std::string& value);
// Checks and sets one setting; throws lidr::Error for an unknown name (listing the names) or a bad value.
void setRenderOption(RenderOptionValues& values, const std::string& name, const std::string& value);
// The value of `name`: the one given, else its default ("" where there is none).
std::string renderOptionValue(const RenderOptionValues& values, const std::string& name);

// A URL query ("mode=tiled&tile-size=16&model=x.glb", an optional leading '?', %XX and '+' decoded): the renderer
// settings in it are checked and set in `values` as setRenderOption does (a flag given without a value is "on");
// the other pairs are returned, in order, for the caller (a page's model, size, bench run).
std::vector<std::pair<std::string, std::string>> setRenderOptionsFromQuery(RenderOptionValues& values,
                                                                           const std::string& query);

// Every mode's settings from `values`, the mode from "mode" (else the scene's), MSAA and transparency from the scene
// where not given. Throws lidr::Error for settings that contradict each other or the mode (e.g. --budget with
// --scheme auto, --cluster-* with a mode that has no clusters), before any GL work.
RenderModeOptions renderModeOptionsFrom(const RenderOptionValues& values, const Scene& scene);
// LIDR's settings alone (part of renderModeOptionsFrom).
LidrOptions lidrOptionsFrom(const RenderOptionValues& values, const Scene& scene);
// "tone-map" and "exposure".
OutputTransform outputTransformFrom(const RenderOptionValues& values);

}  // namespace lidr
