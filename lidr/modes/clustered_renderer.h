#pragma once
// Clustered forward shading ("clustered"; Olsson, Billeter & Assarsson 2012, with the CPU-built dense grid of
// Doom 2016 and Filament's froxels) on the same GL 2.1-class footing as LIDR and tiled forward: the same scene,
// camera, light table, shading function and shader variants.
//
// Frame: light table -> pre-Z -> (optionally the pre-Z depth read back: which clusters hold a surface) -> lights
// assigned to clusters on the CPU (screen tiles x exponential view-depth slices; an exact sphere-cell test, the
// spot cone) -> opaque geometry shaded with its cluster's lights (depth EQUAL; each fragment finds its slice from
// its own view depth) -> transparent geometry back to front, alpha blended, each fragment in its own cluster.
// doc/clustered.md describes the grid, the assignment and its memory.
#include <memory>
#include <string>
#include <vector>

#include "lidr/base/image.h"
#include "lidr/modes/cluster_grid.h"
#include "lidr/render/frame_resources.h"

namespace lidr {

struct ClusteredOptions {
    // The defaults: the fastest grid of the sweep on the bench scenes at 1024x768 (doc/clustered.md, "Sweep").
    int tileSize = 16;   // screen tile edge in pixels, ClusterGrid::kMinTileSize..kMaxTileSize
    int slices = 32;     // view-depth slices, 1..ClusterGrid::kMaxSlices
    ClusterSlicing slicing = ClusterSlicing::NearSlice;
    // NearSlice: the first slice's far end (view depth, scene units; Filament's 5 m). Measured against the far plane /
    // 20 (the room's 3 m): many-4096-top's extra pairs per true pair 1.11 at 5 against 3.29 at 3 (doc/clustered.md).
    float lightNear = 5.0f;
    // Olsson's occupied-cluster step: the pre-Z depth read back, the slices fitted to the frame's nearest and
    // farthest surface (clusterSlices' fit), and only clusters holding a surface (and, with transparent meshes,
    // those in front of a tile's farthest surface) get lists. Off: every cluster (the dense grid) over the camera's
    // depth range. Needs a depth read-back (GlInfo::readDepthStencil); not used under MSAA (frameInfo says so).
    bool occupiedClusters = false;
    bool preZ = true;                  // depth pre-pass, then shading with depth EQUAL (no overdraw shading)
    bool transparency = true;          // draw transparent meshes (opacity < 1) after the opaque ones
    int msaaSamples = 0;               // 0, or 2..GL_MAX_SAMPLES; shading goes to the multisampled targets
    bool forceFixedLightTable = false; // the RGBA8 fixed-point light table even with float textures
    int initialLoopBound = 16;         // first LIDR_MAX_CLUSTER_LIGHTS; grows (power of two) with the lists
    bool timing = false;               // as LidrOptions::timing
    TimingMethod timingMethod = TimingMethod::Auto;
};

struct ClusteredFrameInfo {
    ClusterGridStats grid;
    ClusterSlices slicing;        // the frame's slices (their count: 1 where fragments have no highp floats)
    int loopBound = 0;            // LIDR_MAX_CLUSTER_LIGHTS the frame's shader ran with (>= every list's length)
    int shaderRebuilds = 0;       // programs built since construction (the first, then each loop-bound growth or
                                  // index-width change)
    int listTextureRows = 0;      // rows of the index list texture (it grows too)
    int indexBits = 0;            // of the list texture: 8 (at most 255 lights) or 16
    bool occupancyUsed = false;   // the occupied-cluster step ran (asked for, a depth read-back, no MSAA)
    double assignMilliseconds = 0.0;     // CPU: light assignment, list layout and upload
    double occupancyMilliseconds = 0.0;  // CPU: depth read-back and occupied slices (0 without)
};

// The scene, targets, light table, pre-Z, shadow maps, environment maps and timer, and the frame steps every mode
// takes alike, are its FrameResources.
class ClusteredRenderer final : public Renderer {
public:
    // Checks everything before any drawing: FBOs, resolution, the grid (tile size, slices), occupancy where no
    // depth can be read back, occupancy without pre-Z (lidr::Error / UnsupportedError naming the cause).
    ClusteredRenderer(const GlInfo& info, const Scene& scene, const ClusteredOptions& options, int width, int height);

    std::string modeName() const override { return "clustered"; }
    // Light i has index i + 1; at most 65535 lights (the light table grows to hold them).
    const FrameStats& render(const Camera& camera, const std::vector<PointLight>& lights,
                             const ShadingParameters& shading) override;
    size_t lightDataBytes() const override { return gridTextures_.bytes(); }
    ModeStatistics modeStatistics() const override;  // "clustered": the grid and its lists
    const FrameResources& frame() const override { return frame_; }

    const ClusteredOptions& options() const { return options_; }
    const ClusterGrid& grid() const { return grid_; }  // the last frame's cluster lists
    const ClusteredFrameInfo& frameInfo() const { return frameInfo_; }
    size_t gridBytes() const { return gridTextures_.gridBytes(); }
    size_t listBytes() const { return gridTextures_.listBytes(); }
    // The slice every opaque pixel of the last frame read its lights from, found by the GPU with the shading
    // pass's own code (clustered_forward.frag with LIDR_CLUSTER_SLICE_OUTPUT, drawn over the frame's depth), rows
    // top to bottom; -1 where no surface. Without MSAA only (lidr::Error otherwise): an evaluation aid, not part
    // of a frame.
    std::vector<int> pixelSlices() const;
    // Per pixel (rows top to bottom) the cluster its opaque surface read, from pixelSlices(); -1 where none.
    std::vector<int> pixelClusters() const;

    // Lights in each pixel's cluster as an image (width x height, rows top to bottom), coloured like
    // overlapHeatMap: blue -> yellow up to `budget`, red past it; background pixels show slice 0's count.
    ImageRGBA8 clusterHeatMap(int budget = 16) const;

    std::vector<FramePass> passes() const override;

private:
    void buildProgram(int loopBound, int indexBits);
    std::string programName() const;
    bool usesOccupancy() const;  // asked for, and no MSAA (one depth per pixel to read back)
    // The passes of render(), in its order (passes() says what each reads and writes). markOccupiedClusters: the
    // occupied clusters (empty without the step), `slicing` fitted to the frame's surfaces.
    std::vector<uint64_t> markOccupiedClusters(const CameraMatrices& cam, bool transparent, ClusterSlices& slicing);
    void readPackedDepth();  // packedDepth_: the pre-Z depth-stencil as stored
    ClusterSlices slicesOverSurfaces(const CameraMatrices& cam, const ClusterSlices& camera) const;
    void buildLightGrid(const CameraMatrices& cam, const std::vector<PointLight>& lights, const ClusterSlices& slicing,
                        const std::vector<uint64_t>& occupied);
    const gl::Program& shadeOpaque(const CameraMatrices& cam, const ShadingParameters& shading,
                                   const ClusterSlices& slicing);
    void shadeTransparent(const CameraMatrices& cam, const ShadingParameters& shading, const gl::Program& program);

    FrameResources frame_;  // first: the options and the context are checked before any GL object
    ClusteredOptions options_;
    ClusterGrid grid_;
    ClusterGridTextures gridTextures_;
    gl::Program program_;
    ShaderDefines programDefines_;  // program_'s, for its shadowed twin (ShadowMaps::program)
    int slices_ = 1;  // options_.slices, or 1 without highp fragment floats
    CameraMatrices lastCamera_;
    ClusteredFrameInfo frameInfo_;
    std::vector<uint32_t> packedDepth_;  // the occupied-cluster step's depth read-back
    // pixelSlices(): the slice-output program and its target, made on first use.
    mutable gl::Program sliceProgram_;
    mutable gl::Texture sliceTexture_;
    mutable gl::Framebuffer sliceFbo_;
};

}  // namespace lidr
