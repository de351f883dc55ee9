#include "lidr/modes/render_options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "lidr/base/error.h"
#include "lidr/gl/render_targets.h"
#include "lidr/modes/cluster_grid.h"
#include "lidr/technique/packing_scheme.h"
#include "lidr/technique/volume_draw_plan.h"

namespace lidr {

namespace {
using T = RenderOptionType;
const std::vector<std::string> kOnOff = {"on", "off"};
const std::vector<std::string> kLidr = {"lidr"}, kTiled = {"tiled"}, kClustered = {"clustered", "auto"};
const std::vector<std::string> kDeferred = {"deferred", "tiled-deferred"}, kTileGrid = {"tiled", "tiled-deferred"};

std::vector<std::string> withAuto(std::vector<std::string> names) {
    names.insert(names.begin(), "auto");
    return names;
}

std::string joinOr(const std::vector<std::string>& names) {
    std::string s;
    for (size_t i = 0; i < names.size(); ++i)
        s += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return s;
}

std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

// The rows for the per-mode settings of tiled, clustered and multi-pass forward.
void addModeRows(std::vector<RenderOption>& o) {
    const ClusteredOptions clustered;
    o.push_back({"tile-size", T::Int, {"8", "16", "32", "64"}, 0, 0, "32", "Tiled and tiled-deferred modes: tile edge in pixels", kTileGrid});
    o.push_back({"no-depth-bounds", T::Flag, {}, 0, 0, "", "Tiled and tiled-deferred modes: no per-tile min/max depth pruning", kTileGrid});
    o.push_back({"half-z", T::Flag, {}, 0, 0, "", "Tiled mode: split each tile's depth range in two (half-Z)", kTiled});
    o.push_back({"packed-depth", T::Flag, {}, 0, 0, "",
                 "Tiled mode: reduce depth in packed RGBA8 even with float targets", kTiled});
    o.push_back({"cluster-tile-size", T::Int, {"16", "32", "64", "128"}, double(ClusterGrid::kMinTileSize),
                 double(ClusterGrid::kMaxTileSize), "",
                 "Clustered mode: screen tile edge in pixels, " + std::to_string(ClusterGrid::kMinTileSize) + ".." +
                     std::to_string(ClusterGrid::kMaxTileSize) + " (default " + std::to_string(clustered.tileSize) + ")",
                 kClustered, " pixels"});
    o.push_back({"cluster-slices", T::Int, {"1", "8", "16", "32", "64"}, 1, double(ClusterGrid::kMaxSlices), "",
                 "Clustered mode: view-depth slices, 1.." + std::to_string(ClusterGrid::kMaxSlices) + " (default " +
                     std::to_string(clustered.slices) + ")",
                 kClustered});
    o.push_back({"cluster-slicing", T::Choice, {"exponential", "near-slice"}, 0, 0, "",
                 std::string("Clustered mode: exponential (Doom's: near to far plane) or near-slice (Filament's: one "
                             "slice to --cluster-light-near, exponential beyond) (default ") +
                     clusterSlicingName(clustered.slicing) + ")",
                 kClustered});
    o.push_back({"cluster-light-near", T::Text, {}, 0, 0, "",
                 "Clustered mode, near-slice: the first slice's far end, view depth in scene units (default " +
                     std::to_string(int(clustered.lightNear)) + ")",
                 kClustered});
    o.push_back({"cluster-occupancy", T::Choice, kOnOff, 0, 0, "",
                 std::string("Clustered mode: on (the pre-Z depth read back, lists only for clusters holding a "
                             "surface; not on ES 2.0/WebGL) or off (every cluster) (default ") +
                     (clustered.occupiedClusters ? "on" : "off") + ")",
                 kClustered});
    o.push_back({"deferred-stencil", T::Choice, kOnOff, 0, 0, "off",
                 "Deferred mode: on (light volumes' back faces mark the stencil, front faces shade where marked) or "
                 "off (default, faster on llvmpipe: back faces shade every surface in front of them; doc/deferred.md)",
                 {"deferred"}});
    o.push_back({"g-buffer", T::Choice, gBufferFormatNames(), 0, 0, "auto",
                 "Deferred and tiled-deferred modes: the G-buffer's format, " + joinOr(gBufferFormatNames()) +
                     " (default auto: rgba16f where the context renders to half floats, else rgba8, five 8-bit "
                     "targets; doc/deferred.md)",
                 kDeferred});
    o.push_back({"multipass-accumulation", T::Choice, {"auto", "8-bit"}, 0, 0, "auto",
                 "Multi-pass forward sums its passes in: auto (half float where the context renders to it, else the "
                 "8-bit colour target), 8-bit (the 8-bit target, to compare)",
                 {"forward-multipass", "auto"}});
}

// LIDR's rows: packing, volume test and its tiles, index numbering, depth precision.
void addLidrRows(std::vector<RenderOption>& o) {
    std::string schemes;
    for (const std::string& n : packingSchemeNames()) schemes += (schemes.empty() ? "" : ", ") + n;
    o.push_back({"scheme", T::Choice, withAuto(packingSchemeNames()), 0, 0, "auto",
                 "Packing scheme: auto (default: bit-shift with the budget and index width chosen per frame, "
                 "doc/auto.md), " + schemes +
                     " (bitshift: CONSTANT_COLOR bit shifting; max-stencil: MAX blend + stencil rank windows; "
                     "cpu-sorted: CPU overlap sorting into colour-masked groups; see doc/packing.md)",
                 kLidr});
    o.push_back({"budget", T::Choice, {"auto", "1", "2", "4", "8", "16", "32"}, 0, 0, "auto",
                 "Light slots per pixel: auto (measured per frame; bitshift, up to 32) or 1, 2, 4, 8, 16 (with a named "
                 "scheme), 32 (bitshift at 4- or 8-bit indices)",
                 kLidr});
    o.push_back({"index-bits", T::Choice, {"auto", "4", "8", "16"}, 0, 0, "auto",
                 "Light index width: auto (the narrowest for the visible lights) or 4, 8, 16 (with a named scheme)",
                 kLidr});
    o.push_back({"volume-test", T::Choice, {"auto", "sphere", "sphere-span", "sphere-ray", "backface", "exact", "frontface"}, 0,
                 0, "auto",
                 "Light volume test: auto (sphere; sphere-span with MSAA; backface with --msaa-per-sample), sphere "
                 "(exact, in the shader, batched), sphere-span (MSAA: every sample's surface), sphere-ray, backface, "
                 "exact (stencil), frontface",
                 kLidr});
    o.push_back({"msaa-spans", T::Choice, {"auto", "samples", "moments"}, 0, 0, "auto",
                 "sphere-span under MSAA, how the volume pass learns each pixel's sample surfaces: auto (samples "
                 "where the context has multisample textures, GL 3.2; else moments), samples (each sample's shaded "
                 "distance in a multisample texture, read per sample: exact lists), moments (GL 2.1: per-side moments "
                 "resolved into two float targets; doc/msaa-transparency.md)",
                 kLidr});
    o.push_back({"msaa-skip-hidden", T::Choice, {"auto", "on", "off"}, 0, 0, "auto",
                 "Under MSAA with samples spans, LIDR's opaque pass skips the light lists of fragments that keep no "
                 "sample (the same image): auto (where the context shades fragments its depth test rejected, counted "
                 "once, and the frame's budget is 8 or more), on, off",
                 kLidr});
    o.push_back({"msaa-per-sample", T::Flag, {}, 0, 0, "",
                 "MSAA with multisample index targets read per sample (GL 3.2 + sample shading; optional path)", kLidr});
    o.push_back({"volume-detail", T::Flag, {}, 0, 0, "",
                 "Coarser light volumes (20 / 80 faces) for lights small on screen (LidrOptions::volumeDetail)", kLidr});
    o.push_back({"volume-tiles", T::Choice, kOnOff, 0, 0, "on",
                 "Sphere test over depth-culled screen tiles: on (default; desktop GL) or off (volume meshes) "
                 "(LidrOptions::tileCulledVolumes, doc/architecture.md)",
                 kLidr});
    o.push_back({"volume-tile-size", T::Int, {}, 4, 256, "16", "Tile size of --volume-tiles in pixels, 4..256", kLidr});
    o.push_back({"regional-indices", T::Choice, kOnOff, 0, 0, "on",
                 "Over 255 lights with --volume-tiles: 8-bit indices numbered per screen region (on, default) or "
                 "16-bit global ones (off) (LidrOptions::regionalIndices, doc/architecture.md)",
                 kLidr});
    o.push_back({"depth-bits", T::Choice, {"24", "16", "16-emulated"}, 0, 0, "24",
                 "LIDR depth precision: 24 (default), 16 (a 16-bit depth buffer with a separate stencil, where the "
                 "driver holds it) or 16-emulated (16-bit levels inside the 24-bit buffer; doc/stability.md)",
                 kLidr});
}

// What every mode shares: samples, transparency, light table, timing, output transform, shadows.
void addSharedRows(std::vector<RenderOption>& o) {
    o.push_back({"msaa", T::Int, {"0", "2", "4", "8", "16"}, 0, 0, "",
                 "MSAA samples: 0 (off), 2, 4, ... up to GL_MAX_SAMPLES (default: the scene's)"});
    o.push_back({"transparency", T::Choice, {"on", "off", "scene"}, 0, 0, "scene",
                 "Draw transparent materials: on, off, scene (default)"});
    o.push_back({"timer", T::Choice, {"auto", "gpu", "cpu"}, 0, 0, "auto",
                 "Pass timing: auto, gpu (timer queries), cpu (glFinish around each pass)"});
    o.push_back({"fixed-light-table", T::Flag, {}, 0, 0, "", "Use the RGBA8 fixed-point light table (no float textures)"});
    o.push_back({"tone-map", T::Text, {"none", "pbr-neutral", "aces"}, 0, 0, "pbr-neutral",
                 std::string("Tone map of the linear frame before its sRGB encoding: ") + toneMapNames() +
                     " (doc/colour.md)"});
    o.push_back({"exposure", T::Number, {}, -20, 20, "0", "Exposure in stops: linear light x 2^stops before the tone map"});
    o.push_back({"shadows", T::Text, {"off", "scene", "1", "8", "32", "128"}, 0, 0, "off",
                 "Shadow-casting lights: off (default), scene (the lights' own \"shadow\" flags: scene files, glTF "
                 "extras.lidr.shadow) or K (the K brightest lights that can touch the view: colour luminance x "
                 "range^2; doc/shadows.md)"});
    o.push_back({"shadow-lookup", T::Text, {"forward", "volume"}, 0, 0, "forward",
                 "Where LIDR applies shadows: forward (default: the forward pass looks each listed light up by index, "
                 "the paper's second way; faster on llvmpipe) or volume (the volume pass also discards shadowed "
                 "points, the paper's first way: shorter lists, for fixed budgets); the other modes look up as they "
                 "shade",
                 kLidr});
    o.push_back({"shadow-filter", T::Text, {"nearest", "pcf"}, 0, 0, "nearest",
                 "Shadow-map lookups: nearest (default: one texel decides) or pcf (the four nearest texels, bilinear)"});
    o.push_back({"shadow-atlas", T::Text, {}, 0, 0, "",
                 "Shadow atlas SIZE[:TILE] in texels, powers of two, TILE 16..SIZE, SIZE at most 8192 (default 4096 "
                 "with the largest TILE up to 512 that holds every caster's maps: a spot light takes one tile, a "
                 "point light six)"});
}

std::vector<RenderOption> makeRenderOptions() {
    std::vector<RenderOption> o;
    o.push_back({"mode", T::Choice, renderModeNames(), 0, 0, "",
                 "Render mode: " + renderModeList() + " (default: the scene's, else lidr)"});
    addModeRows(o);
    addLidrRows(o);
    addSharedRows(o);
    return o;
}

bool isWholeNumber(const std::string& v) {
    if (v.empty() || v.size() > 10) return false;
    const size_t start = v[0] == '-' ? 1 : 0;
    return start < v.size() && std::all_of(v.begin() + long(start), v.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool flagValue(const std::string& v) { return v == "on" || v == "true" || v == "1" || v.empty(); }
}  // namespace

bool RenderOption::usedBy(const std::string& mode) const {
    return modes.empty() || std::find(modes.begin(), modes.end(), mode) != modes.end();
}

std::string RenderOption::typeName() const {
    switch (type) {
        case RenderOptionType::Int: return "INT";
        case RenderOptionType::Number: return "FLOAT";
        default: return "TEXT";
    }
}

const std::vector<RenderOption>& renderOptions() {
    static const std::vector<RenderOption> options = makeRenderOptions();
    return options;
}

const RenderOption* findRenderOption(const std::string& name) {
    for (const RenderOption& o : renderOptions())
        if (o.name == name) return &o;
    return nullptr;
}

void checkRenderOption(const RenderOption& option, const std::string& value) {
    const std::string what = "--" + option.name;
    switch (option.type) {
        case RenderOptionType::Flag:
            if (!flagValue(value) && value != "off" && value != "false" && value != "0")
                throw Error(what + " must be on or off, got '" + value + "'");
            return;
        case RenderOptionType::Int: {
            if (!isWholeNumber(value)) throw Error(what + " must be a whole number, got '" + value + "'");
            const long v = std::strtol(value.c_str(), nullptr, 10);
            if (option.max > option.min && (v < option.min || v > option.max))
                throw Error(what + " must be " + number(option.min) + ".." + number(option.max) + option.unit +
                            ", got " + value);
            return;
        }
        case RenderOptionType::Number: {
            char* end = nullptr;
            const double v = std::strtod(value.c_str(), &end);
            if (value.empty() || *end != '\0' || !std::isfinite(v) || v < option.min || v > option.max)
                throw Error(what + " must be a finite number from " + number(option.min) + " to " + number(option.max) +
                            ", got '" + value + "'");
            return;
        }
        case RenderOptionType::Choice:
            if (std::find(option.choices.begin(), option.choices.end(), value) == option.choices.end())
                throw Error(what + " must be " + joinOr(option.choices) + ", got '" + value + "'");
            return;
        case RenderOptionType::Text: return;  // checked where it is read (renderModeOptionsFrom, the shadow settings)
    }
}

void setRenderOption(RenderOptionValues& values, const std::string& name, const std::string& value) {
    const RenderOption* option = findRenderOption(name);
    if (!option) {
        std::string names;
        for (const RenderOption& o : renderOptions()) names += (names.empty() ? "" : ", ") + o.name;
        throw Error("unknown renderer setting '" + name + "' (valid: " + names + ")");
    }
    checkRenderOption(*option, value);
    values[name] = option->type == RenderOptionType::Flag ? (flagValue(value) ? "on" : "off") : value;
}

std::string renderOptionValue(const RenderOptionValues& values, const std::string& name) {
    const auto it = values.find(name);
    if (it != values.end()) return it->second;
    const RenderOption* option = findRenderOption(name);
    return option ? option->defaultValue : std::string();
}

namespace {
std::string urlDecode(const std::string& s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '+') {
            out += ' ';
        } else if (s[i] == '%' && i + 2 < s.size() && std::isxdigit(static_cast<unsigned char>(s[i + 1])) &&
                   std::isxdigit(static_cast<unsigned char>(s[i + 2]))) {
            out += char(std::strtol(s.substr(i + 1, 2).c_str(), nullptr, 16));
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

// "auto" (PackingConfig::kAuto) or a number the row's choices hold (they are checked by setRenderOption).
int autoOrNumber(const std::string& text) { return text == "auto" ? PackingConfig::kAuto : std::stoi(text); }

bool given(const RenderOptionValues& values, const std::string& name) { return values.count(name) != 0; }
bool on(const RenderOptionValues& values, const std::string& name) { return renderOptionValue(values, name) == "on"; }

void checkPacking(const PackingConfig& p, const std::string& scheme) {
    if (p.autoScheme() && (p.budget != PackingConfig::kAuto || p.indexBits != PackingConfig::kAuto))
        throw Error("--scheme auto chooses the budget and the index width itself: leave out --budget and --index-bits, "
                    "or name a scheme (--scheme bitshift) to fix them");
    if (!p.autoScheme() && p.scheme != PackingSchemeKind::BitShift && p.budget == PackingConfig::kAuto)
        throw Error("--budget auto is measured from bit-shift packing's stencil count; --scheme " + scheme +
                    " needs --budget 1, 2, 4, 8 or 16");
}

// The clustered grid's settings; refused with a mode that has no clusters.
void setClusterOptions(const RenderOptionValues& v, const std::string& mode, ClusteredOptions& c) {
    const bool set = given(v, "cluster-tile-size") || given(v, "cluster-slices") || given(v, "cluster-slicing") ||
                     given(v, "cluster-occupancy") || given(v, "cluster-light-near");
    if (set && mode != "clustered" && mode != "auto")
        throw Error("--cluster-* options set the clustered mode's grid; the " + mode +
                    " mode has none (use --mode clustered, or auto)");
    if (given(v, "cluster-tile-size")) c.tileSize = std::stoi(v.at("cluster-tile-size"));
    if (given(v, "cluster-slices")) c.slices = std::stoi(v.at("cluster-slices"));
    if (given(v, "cluster-slicing")) c.slicing = parseClusterSlicing(v.at("cluster-slicing"));
    if (given(v, "cluster-light-near")) {
        if (c.slicing != ClusterSlicing::NearSlice)
            throw Error("--cluster-light-near ends the first slice of --cluster-slicing near-slice; the slicing is " +
                        std::string(clusterSlicingName(c.slicing)));
        const std::string& text = v.at("cluster-light-near");
        char* end = nullptr;
        const float nearDepth = std::strtof(text.c_str(), &end);
        if (text.empty() || *end != '\0' || !(nearDepth > 0.0f) || !std::isfinite(nearDepth))
            throw Error("--cluster-light-near must be a positive view depth, got " + text);
        c.lightNear = nearDepth;
    }
    if (given(v, "cluster-occupancy")) c.occupiedClusters = v.at("cluster-occupancy") == "on";
}
}  // namespace

std::vector<std::pair<std::string, std::string>> setRenderOptionsFromQuery(RenderOptionValues& values,
                                                                           const std::string& query) {
    std::vector<std::pair<std::string, std::string>> others;
    std::istringstream in(!query.empty() && query[0] == '?' ? query.substr(1) : query);
    std::string pair;
    while (std::getline(in, pair, '&')) {
        if (pair.empty()) continue;
        const size_t eq = pair.find('=');
        const std::string name = urlDecode(pair.substr(0, eq));
        const std::string value = eq == std::string::npos ? std::string() : urlDecode(pair.substr(eq + 1));
        const RenderOption* option = findRenderOption(name);
        if (!option) {
            others.emplace_back(name, value);
            continue;
        }
        setRenderOption(values, name, value.empty() && option->type == RenderOptionType::Flag ? "on" : value);
    }
    return others;
}

OutputTransform outputTransformFrom(const RenderOptionValues& values) {
    OutputTransform o;
    o.toneMap = parseToneMap(renderOptionValue(values, "tone-map"), "--tone-map");
    o.exposureStops = std::strtof(renderOptionValue(values, "exposure").c_str(), nullptr);  // checked: -20..20
    return o;
}

LidrOptions lidrOptionsFrom(const RenderOptionValues& v, const Scene& scene) {
    LidrOptions o;
    if (given(v, "msaa")) checkSampleCount(std::stoi(v.at("msaa")), "--msaa");
    o.msaaSamples = given(v, "msaa") ? std::stoi(v.at("msaa")) : scene.msaaSamples;
    const std::string transparency = renderOptionValue(v, "transparency");
    o.transparency = transparency == "on" || (transparency != "off" && scene.transparency);
    const std::string scheme = renderOptionValue(v, "scheme");
    o.packing.scheme = parsePackingScheme(scheme);
    o.packing.budget = autoOrNumber(renderOptionValue(v, "budget"));
    o.packing.indexBits = autoOrNumber(renderOptionValue(v, "index-bits"));
    checkPacking(o.packing, scheme);
    o.perSampleIndices = on(v, "msaa-per-sample");
    o.hiddenFragmentSkip = parseHiddenFragmentSkip(renderOptionValue(v, "msaa-skip-hidden"));
    o.msaaSpans = parseDepthSpanStorage(renderOptionValue(v, "msaa-spans"));
    o.volumeDetail = on(v, "volume-detail");
    o.tileCulledVolumes = on(v, "volume-tiles");
    o.regionalIndices = on(v, "regional-indices");
    o.volumeTileSize = std::stoi(renderOptionValue(v, "volume-tile-size"));
    const std::string depthBits = renderOptionValue(v, "depth-bits");
    if (depthBits == "16") o.depthBits = 16;
    if (depthBits == "16-emulated") o.emulatedDepthBits = 16;
    const std::string volumeTest = renderOptionValue(v, "volume-test");
    o.volumeTest = volumeTest == "auto"
                       ? (o.perSampleIndices ? VolumeTest::BackFace
                          : o.msaaSamples > 0 ? VolumeTest::SphereSpan
                                              : VolumeTest::Sphere)
                       : parseVolumeTest(volumeTest);
    o.forceFixedLightTable = on(v, "fixed-light-table");
    o.timingMethod = parseTimingMethod(renderOptionValue(v, "timer"));
    return o;
}

RenderModeOptions renderModeOptionsFrom(const RenderOptionValues& v, const Scene& scene) {
    RenderModeOptions o;
    o.mode = given(v, "mode") ? v.at("mode") : scene.renderMode;
    if (!isRenderModeName(o.mode)) throw Error("unknown render mode '" + o.mode + "' (valid: " + renderModeList() + ")");
    o.lidr = lidrOptionsFrom(v, scene);
    if (given(v, "depth-bits") && o.mode != "lidr")
        throw Error("--depth-bits sets LIDR's depth precision; the " + o.mode + " mode keeps 24-bit depth (use --mode lidr)");
    o.msaaSamples = o.lidr.msaaSamples;
    o.transparency = o.lidr.transparency;
    o.timingMethod = o.lidr.timingMethod;
    o.tiled.tileSize = std::stoi(renderOptionValue(v, "tile-size"));
    o.tiled.depthBounds = !on(v, "no-depth-bounds");
    o.tiled.forcePackedDepth = on(v, "packed-depth");
    o.tiled.halfZ = on(v, "half-z");
    o.tiledDeferred.tileSize = o.tiled.tileSize;  // tiled deferred builds the same grid
    o.tiledDeferred.depthBounds = o.tiled.depthBounds;
    o.deferred.stencil = on(v, "deferred-stencil");
    o.deferred.format = o.tiledDeferred.format = parseGBufferFormat(renderOptionValue(v, "g-buffer"));
    setClusterOptions(v, o.mode, o.clustered);
    o.multipass.halfFloatAccumulation = renderOptionValue(v, "multipass-accumulation") == "auto";
    o.forceFixedLightTable = on(v, "fixed-light-table");
    outputTransformFrom(v);  // checked with the rest, before any context
    return o;
}

}  // namespace lidr
