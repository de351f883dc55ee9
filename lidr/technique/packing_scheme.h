#pragma once
// A packing scheme turns "these lights touch this pixel" into bytes of RGBA8 index targets using only the
// fixed-function blender (and stencil), and says how a GLSL 1.20 shader reads them back. Every scheme has
// a bit-exact CPU model (encodePixel / decodePixel) that the GPU results are tested against.
//
// A scheme is a plan of volume draws (lidr/technique/light_volume_pass.h): which lights, which targets and channels,
// which blend state, which stencil rank window. The GPU runs the plan through LightVolumePass; the CPU model
// runs the same plan through a model of the blender and the stencil (one pixel that every light marks).
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "lidr/gl/gl_info.h"
#include "lidr/technique/light_volume_pass.h"
#include "lidr/base/shader_float.h"
#include "lidr/gl/shader_source.h"

namespace lidr {

// The packing schemes (doc/packing.md). Their names ("auto", "bitshift", "max-stencil", "cpu-sorted") are for
// the command line, scene and bench files and reports only: packingSchemeName / parsePackingScheme convert.
enum class PackingSchemeKind {
    Auto,        // bit-shift with the budget and the index width chosen per frame (LidrRenderer, doc/auto.md)
    BitShift,    // CONSTANT_COLOR bit-shift (bitshift_scheme.h)
    MaxStencil,  // MAX blend + stencil (max_stencil_scheme.h)
    CpuSorted,   // CPU overlap sorting (cpu_sorted_scheme.h)
};
const char* packingSchemeName(PackingSchemeKind kind);
// "auto", "bitshift", "max-stencil" (or "max"), "cpu-sorted" (or "sorted"); throws UnsupportedError listing
// the valid names for anything else.
PackingSchemeKind parsePackingScheme(const std::string& name);
// The concrete schemes (not Auto), and their names.
std::vector<PackingSchemeKind> packingSchemes();
std::vector<std::string> packingSchemeNames();

struct PackingConfig {
    static constexpr int kAuto = 0;
    PackingSchemeKind scheme = PackingSchemeKind::Auto;
    int budget = kAuto;     // light slots per pixel: 1, 2, 4, 8, 16, or kAuto (measured per frame; bitshift)
    int indexBits = kAuto;  // 4 (15 lights), 8 (255), 16 (65,535), or kAuto (the narrowest for the visible lights)
    bool autoScheme() const { return scheme == PackingSchemeKind::Auto; }
    bool autoBudget() const { return autoScheme() || budget == kAuto; }
    bool autoIndexBits() const { return autoScheme() || indexBits == kAuto; }
};

// How a kind of hardware blends into an RGBA8 target (the CPU model's knobs).
struct BlendModel {
    bool quantisedConstant = false;  // the blend constant is first stored as an 8-bit value (k / 255)
    bool truncate = false;           // results are truncated instead of rounded to nearest
};

// One draw of a scheme's plan: the VolumeDraw state, its lights in draw order, and their colours.
struct SchemeDraw {
    VolumeDraw draw;
    std::vector<VolumeLight> lights;
    std::function<IndexColors(uint32_t index)> colors;
};

// Draw `window` of `windows` of a scheme that splits its budget into stencil rank windows of `windowSlots`
// lights: ranks window * windowSlots .. + windowSlots - 1. Schemes draw the windows last to first: the count
// is restarted for every window after the first drawn, so the last drawn, ranks 0.., leaves every pixel's
// whole count in the stencil (the overlap probe and readLightCounts read it), and the earlier windows need
// touch only pixels with more lights than their first rank (tile-culled volumes skip the rest). The scheme
// sets targets, masks and blending.
SchemeDraw rankWindowDraw(PackingSchemeKind scheme, int window, int windowSlots, int windows,
                          const std::vector<VolumeLight>& lights, std::function<IndexColors(uint32_t index)> colors);

class PackingScheme {
public:
    virtual ~PackingScheme() = default;
    const PackingConfig& config() const { return config_; }  // config().scheme: which scheme this is
    std::string describe() const;  // "bitshift budget 4, 8-bit indices, 1 target, ..."
    uint32_t maxLights() const { return (1u << config_.indexBits) - 1u; }
    virtual int targetCount() const = 0;
    size_t indexBytes(int width, int height) const { return size_t(targetCount()) * width * height * 4; }
    // Stencil bits the scheme relies on beyond the light count (always 8 bits of DEPTH24_STENCIL8 are held).
    virtual std::string stencilUse() const = 0;
    // Passes of light-volume geometry (each light is drawn this many times, before the volume test's own
    // multiplier: 4 draws per light and pass with the exact stencil test).
    virtual int geometryPasses() const = 0;

    // The draws for these lights (highest priority first). `pass` supplies the camera and the volume test
    // (CPU sorting groups by them); nullptr plans one pixel that every light marks (the CPU model).
    virtual std::vector<SchemeDraw> plan(const std::vector<VolumeLight>& lightsInPriorityOrder,
                                         const LightVolumePass* pass) const = 0;
    // Draws the plan into the index targets of the pass.
    void encode(LightVolumePass& pass, const std::vector<VolumeLight>& lightsInPriorityOrder) const;

    // The unpack file that replaces "lidr_unpack.glsl" in forward shaders, and its defines.
    virtual std::string unpackShaderFile() const = 0;
    virtual ShaderDefines unpackDefines() const = 0;
    // True when the unpack lists lights in order with empty slots last (LIDR_NULL_ENDS_LIST).
    virtual bool nullEndsList() const = 0;
    // True when a pixel keeps exactly the first `budget` lights (in draw order) that mark it. CPU sorting
    // instead keeps whole lights: a light that fits no group is dropped at every pixel.
    virtual bool keepsFirstMarks() const { return true; }

    // CPU model. encodePixel: the bytes (targetCount * 4, target-major) that drawing `drawOrder` at one pixel
    // leaves behind, blender and stencil included (every light marks the pixel). stencilCount (optional)
    // receives the count the stencil holds afterwards.
    std::vector<uint8_t> encodePixel(const std::vector<uint32_t>& drawOrder, const BlendModel& model = {},
                                     int* stencilCount = nullptr) const;
    // The indices the unpack shader returns slot by slot (0 = empty slot), in its order, for texel reads
    // (targetCount * 4 values, ideally byte / 255) computed in precision p, step for step as the shader does.
    std::vector<uint32_t> decodeReads(const float* reads, FloatPrecision p) const;
    // Same for exact texel bytes in fp32.
    std::vector<uint32_t> decodePixel(const uint8_t* texels) const;
    // What a pixel whose lights are `drawOrder` (all marking it) must decode to, as a set: the lights kept.
    std::vector<uint32_t> keptLights(const std::vector<uint32_t>& drawOrder) const;

protected:
    PackingScheme(PackingSchemeKind kind, PackingConfig c) : config_(c) { config_.scheme = kind; }
    // The unpack arithmetic after lidrBytes(): `bytes` are exact integers (as shader floats) per channel.
    virtual std::vector<uint32_t> decodeBytes(const std::vector<ShaderFloat>& bytes) const = 0;
    PackingConfig config_;
};

// Throws UnsupportedError (before any drawing) for a budget or width the scheme cannot do, or a context
// without what the scheme needs; the message lists what is valid. The config must be concrete (no Auto scheme,
// no kAuto): LidrRenderer resolves those per frame.
std::unique_ptr<PackingScheme> createPackingScheme(const PackingConfig& config, const GlInfo& info);

// Common checks: budget in {1,2,4,8,16} (and 32 for bit-shift), width in {4,8,16}; and that the context can bind `targets` index
// textures (colour attachments, texture units next to the light table) and draw `drawTargets` at once.
void checkPackingConfig(const PackingConfig& config);
void checkContextFor(const std::string& what, const GlInfo& info, int targets, int drawTargets);

// A slot's index from the unpack shader's (low byte, high byte) pair, the two coordinates of its light-table texel
// (column, row): low + 256 * high, computed here in integers as the lookup never forms it in one shader float;
// 0xFFFFFFFF (an invalid slot) where either is not an integer in 0..255.
uint32_t indexFromHalves(ShaderFloat low, ShaderFloat high);

// Bytes of an index as colours: byte / 255 exactly.
inline float byteColor(uint32_t byte) { return float(byte) / 255.0f; }

}  // namespace lidr
