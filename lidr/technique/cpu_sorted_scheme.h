#pragma once
// CPU overlap sorting (Trebilco 2007). Each frame the lights (highest priority first) are put greedily into
// the first of `budget` groups that holds no light able to mark a pixel they could mark; each group is drawn
// into its own slot with colour masks and no blending (a slot is written at most once per pixel), so there
// is nothing to unpack. Lights that fit no group are dropped (not drawn into the index targets, only into
// the stencil count, so their marks are counted per pixel).
//
// "Able to mark the same pixel" depends on the volume test. The exact stencil test marks only surfaces inside
// the volume mesh, so two lights whose enclosing spheres are disjoint never share a pixel (unless a light is
// drawn without its depth test, see LightVolumePass::marksWholeFootprint). The back-face test marks every
// surface IN FRONT of the volume's back faces inside its screen footprint: a light hidden behind a wall marks
// the wall where another light, in front of the wall, marks it too, although the two spheres are far apart.
// Under it (and under the front-face test, which marks every volume the eye ray crosses in front of the
// surface) two lights conflict when their conservative screen footprints overlap.
//
// Slots: 8-bit one channel, 16-bit two channels (low, high byte), 4-bit one nibble (two groups share a
// channel, written with ADD blending, which is exact because each nibble is written at most once).
#include "lidr/technique/packing_scheme.h"

namespace lidr {

// A light's conservative pixel rectangle (the projected bounding box of its volume mesh); the whole target
// when the box reaches behind the near plane.
struct ScreenFootprint {
    int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    bool overlaps(const ScreenFootprint& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};
ScreenFootprint screenFootprint(const CameraMatrices& camera, const glm::vec4& posRadius, float meshOutsideRadius);

class CpuSortedScheme final : public PackingScheme {
public:
    CpuSortedScheme(const PackingConfig& config, const GlInfo& info);
    int targetCount() const override { return (config_.budget * config_.indexBits + 31) / 32; }
    std::string stencilUse() const override { return "light count only (no rank windows)"; }
    int geometryPasses() const override { return 1; }
    std::vector<SchemeDraw> plan(const std::vector<VolumeLight>& lights, const LightVolumePass* pass) const override;
    std::string unpackShaderFile() const override { return "unpack_cpu_sorted.glsl"; }
    ShaderDefines unpackDefines() const override;
    bool nullEndsList() const override { return false; }
    bool keepsFirstMarks() const override { return false; }

    // The groups for these lights: group of each light (-1: dropped), in input order. `pass` nullptr: every
    // pair conflicts (one pixel marked by all).
    std::vector<int> assignGroups(const std::vector<VolumeLight>& lights, const LightVolumePass* pass) const;
    // Whether lights a and b can mark a common pixel under the pass's volume test and camera.
    static bool mayShareAPixel(const VolumeLight& a, const VolumeLight& b, const LightVolumePass& pass);
    IndexColors colorsFor(uint32_t index, int group) const;

protected:
    std::vector<uint32_t> decodeBytes(const std::vector<ShaderFloat>& bytes) const override;
};

}  // namespace lidr
