#pragma once
// What the light-volume pass draws for the steps of its plan (volume_draw_plan.h). VolumeGeometry is the
// strategy; LightVolumeGeometry, the pass's own, draws the lights' volumes (one mesh per light for the stencil
// tests, batches of them for the shader tests). A test substitutes its own geometry (tests/pixel_list_geometry.h
// draws exact per-pixel light lists) and gets the scheme's real draw state without a branch in the pass.
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/render/depth_prepass.h"
#include "lidr/render/shadow_maps.h"
#include "lidr/technique/volume_tiles.h"
#include "lidr/scene/camera.h"
#include "lidr/technique/depth_span_pass.h"
#include "lidr/technique/draw_target_programs.h"
#include "lidr/technique/light_volume_mesh.h"
#include "lidr/technique/volume_draw_plan.h"

namespace lidr {

using IndexColors = std::array<glm::vec4, kMaxIndexTargets>;
// The value a light's index writes to each target of a draw.
using IndexColorsFor = std::function<IndexColors(uint32_t index)>;

// A light as the volume pass sees it: its 1-based index and where it is.
struct VolumeLight {
    uint32_t index = 0;
    glm::vec4 posRadius{0.0f};
    int region = -1;  // tile-culled volumes with IndexRegions: the only region whose tiles this entry marks
    // A spot light's cone as the shading takes it (lidr::spotCone: world axis x scale, offset); a point light's
    // (0, 0, 0, 1) passes everywhere. The sphere test keeps a spot only where this ramp is >= 0 (the shading's 0).
    glm::vec4 cone{0.0f, 0.0f, 0.0f, 1.0f};
    // The first shadow-atlas tile of the light's maps where the sphere test discards what they shadow (the
    // paper's first way, ShadowLookup::VolumePass; LightVolumeGeometry::setShadows); -1: no shadow test.
    int shadowTile = -1;
};

class VolumeGeometry {
public:
    virtual ~VolumeGeometry() = default;
    // What the plan needs to know about a light seen from `camera`.
    virtual VolumeLightFacts factsFor(const VolumeLight& light, const CameraMatrices& camera) const = 0;
    // False where a light may mark pixels outside its sphere's screen footprint (any two lights may then share
    // a pixel: CPU sorting cannot group them).
    virtual bool marksWithinLightFootprints() const { return true; }
    // Lights per draw of a batched plan (VolumeProgram::Batch) writing this many targets.
    virtual int batchFor(int /*targetCount*/) const { return 1; }
    // True where the shader tests draw screen quads over depth-culled tiles instead of volume meshes (no depth
    // pre-test then).
    virtual bool drawsScreenTiles() const { return false; }
    // The pass's begin() and end(): vertex buffers and attributes. targetSize: the index targets' in pixels;
    // depth: the pre-pass depth copy (the shader tests read it).
    virtual void begin(const CameraMatrices& camera, glm::ivec2 targetSize, const gl::Texture* depth) = 0;
    virtual void end() = 0;
    // Before a plan's steps: its program and the uniforms of the whole draw.
    virtual void beginSteps(const VolumeDraw& d, const VolumeDrawPlan& plan, const IndexColorsFor& colors) = 0;
    // One step (its state is applied): the lights' uniforms where step.loadLights, then the draw call.
    virtual void drawStep(const VolumeStep& step, const std::vector<VolumeLight>& lights,
                          const IndexColorsFor& colors) = 0;
};

class LightVolumeGeometry final : public VolumeGeometry {
public:
    LightVolumeGeometry() = default;
    // volumeDetail, depth, depthSpans: see LightVolumePass.
    LightVolumeGeometry(const GlInfo& info, VolumeTest test, bool volumeDetail, DepthEmulation depth = {},
                        bool depthSpans = false, int spanSamples = 0);

    VolumeLightFacts factsFor(const VolumeLight& light, const CameraMatrices& camera) const override;
    void begin(const CameraMatrices& camera, glm::ivec2 targetSize, const gl::Texture* depth) override;
    void end() override;
    void beginSteps(const VolumeDraw& d, const VolumeDrawPlan& plan, const IndexColorsFor& colors) override;
    void drawStep(const VolumeStep& step, const std::vector<VolumeLight>& lights,
                  const IndexColorsFor& colors) override;

    // The mesh drawn for a light (0 = 20 faces, 1 = 80, 2 = 320; kSpotDetail: a spot light's cone mesh in the
    // stencil and front-face tests) and its relative vertex distance; the shader tests' outsideRadiusFor is
    // kSphereRadiusScale, what they mark, whatever mesh they draw.
    int detailFor(const VolumeLight& light, const CameraMatrices& camera) const;
    static constexpr int kSpotDetail = 3;  // the cone mesh, after the sphere's levels
    float outsideRadiusFor(const VolumeLight& light, const CameraMatrices& camera) const;
    float volumeOutsideRadius() const { return meshes_[size_t(coarsest_)].outsideRadius; }
    int batchSize() const { return batch_; }
    int batchFor(int targetCount) const override;
    // The precision of the depth the shader tests read (the pre-pass's depth buffer, copied): 24 or 16 bits;
    // kSphereDepthSteps are steps of it.
    void setDepthBits(int bits) { depthUnits_ = float((1u << bits) - 1u); }
    // sphere-span, and sphere-ray built with depthSpans: the frame's MSAA depth spans (with side moments;
    // outliving the pass), read after each frame's run.
    void setDepthSpans(const DepthSpanPass* spans) { depthSpans_ = spans; }

    // Tile-culled volumes (the sphere test only): with the frame's pre-pass depth per tile (volume_tiles.h; it
    // must outlive the pass), the pass draws each light as screen quads over the tiles of its sphere's screen
    // rectangle that may hold a surface within its depth span, and a rank window from rank k > 0 only over tiles
    // with more than k such lights. The fragment shader's test is unchanged, so the lists are the same; hidden
    // lights and empty tiles cost no fragment. nullptr: volume meshes.
    void setTiles(const VolumeTiles* tiles, const CameraMatrices& camera);
    // Whether the next draw's lights include a spot light (the shader tests' cone test; on by default).
    void setSpotCones(bool on) { spotCones_ = on; }
    // The sphere test's shadow test (opaque lists): a draw with a light whose VolumeLight::shadowTile >= 0 takes
    // the LIDR_SHADOWS program, which discards surface points `maps` shadows (bound with `settings`). Both must
    // outlive the pass's draws; nullptr: no shadow test.
    void setShadows(const ShadowMaps* maps, const ShadowSettings& settings) {
        shadowMaps_ = maps;
        shadowSettings_ = settings;
    }
    // Whether a draw of `lights` takes the shadowed program (setShadows, the sphere test, a light with a tile).
    bool shadowedDraw(const std::vector<VolumeLight>& lights) const;
    void setShadowDraw(bool on) { shadowDraw_ = on; }  // the next draw's (shadowedDraw)
    // Lights per draw: the shadowed program gives a quarter of a uniform vector per light to its tile.
    int batchFor(int targetCount, bool shadowed) const;
    bool drawsScreenTiles() const override { return tiles_ != nullptr; }
    // With tiles: whether the sphere (centre, radius) may mark any pixel of this frame (some tile may hold a
    // surface inside it). Its tiles are kept for the frame's draws.
    bool sphereReachesTiles(const glm::vec4& posRadius);
    // With tiles: the regions of `regions` whose tiles the sphere reaches (bit r: region r; at most 32 regions).
    uint32_t sphereRegions(const glm::vec4& posRadius, const IndexRegions& regions);
    // The frame's regions (VolumeLight::region refers to them); off: every light marks all its tiles.
    void setRegions(const IndexRegions& regions) { regions_ = regions; }
    // The depth margin of the sphere test, in window depth: what VolumeTiles::build takes.
    float depthMargin() const { return kSphereDepthSteps / depthUnits_; }
    // Rasterised area of the last frame's tile quads, in pixels (0 without tiles): what the culling kept.
    long tileQuadPixels() const { return tileQuadPixels_; }
    // After this frame's tile-culled draws: the pixel box (x, y, width, height) of the tiles where more than
    // `count` lights may mark a pixel (the candidate bound); every pixel whose count exceeds `count` lies in it.
    // Width 0: no such tile; width -1: unknown (no tile-culled draw this frame).
    glm::ivec4 candidateArea(int count) const;
    // Lights the tile quads' draws were asked for since begin(), one per light and draw (each rank window draws them all).
    long tileStepLights() const { return tileStepLights_; }

    // The shader tests keep a light up to this many times its radius: a hair over 1, so rounding in the
    // rebuilt surface point never loses a pixel the forward pass lights (the CPU truth's band lies inside).
    static constexpr float kSphereRadiusScale = 1.0005f;
    // The sphere tests treat the pixel's surface as anywhere within this many steps of the depth copy (24 or 16 bits, setDepthBits)
    // (light_volume_sphere.frag): the stored depth is the true depth within half a step, and rebuilding distance
    // from it in fp32 costs about one more. Negligible at ordinary near/far ratios (about 1 mm at 20 m for near
    // 0.1 m), it keeps a light whose sphere the true surface reaches from being lost where depth precision is
    // coarse (far/near 1e5 and up: doc/stability.md).
    static constexpr float kSphereDepthSteps = 3.0f;

private:
    struct TileReach {
        int tile;
        uint32_t slices;  // VolumeTiles::slicesReached
    };
    struct SphereTiles {
        glm::ivec4 rect{0};  // the sphere's pixel rectangle (spherePixelRect): quads are clipped to it
        std::vector<TileReach> tiles;
    };
    // The constructor's parts: the volume meshes (each detail level and the spot cone) in one vertex and one index
    // buffer; for the shader tests, the batches of mesh copies and their programs.
    void uploadMeshes();
    void setUpBatches(const GlInfo& info, VolumeTest test, DepthEmulation depth);
    bool reachesFarPlane(const VolumeLight& light, const CameraMatrices& camera) const;
    // A spot light's cone mesh shape (spotVolumeShape, cached by cone), its unit axis in `axis`; nullptr for a
    // point light.
    const SpotVolumeShape* spotShapeOf(const VolumeLight& light, glm::vec3* axis = nullptr) const;
    mutable std::unordered_map<float, SpotVolumeShape> spotShapes_;  // by the cosine of the outer cone angle
    const SphereTiles& tilesOf(const glm::vec4& posRadius);  // the sphere's tiles this frame (cached)
    void cullToTiles(const std::vector<VolumeLight>& lights);     // lightTiles_, tileCandidates_ for a draw
    bool tileInRegion(int tile, int region) const {
        return region < 0 || !regions_.on() || regions_.regionOfTile(tile) == region;
    }
    void drawTileQuads(const VolumeStep& step);
    static int batchFor(int batch, int maxVertexUniformVectors, int targetCount, bool shadowed = false);
    static constexpr int kMaxBatch = 256, kReservedVertexUniforms = 12;
    static constexpr int kDetailLevels = 3;

    VolumeTest test_ = VolumeTest::BackFace;
    LightVolumeMesh meshes_[kDetailLevels];  // subdivisions 0, 1, 2, in one vertex and one index buffer
    GLsizei firstIndex_[kDetailLevels + 1] = {}, indexCount_[kDetailLevels + 1] = {};  // + the cone mesh
    int coarsest_ = kDetailLevels - 1;  // 0 with volumeDetail, else the finest only
    gl::Buffer vertices_, indices_;
    DrawTargetPrograms programs_;  // the stencil tests' one-light program
    // Shader tests: batch_ copies of the batchLevel_ volume mesh, each vertex (x, y, z, slot).
    int batch_ = 1, batchLevel_ = 0, maxVertexUniformVectors_ = 128;
    GLsizei batchCopyIndices_ = 0;
    gl::Buffer batchVertices_, batchIndices_;
    DrawTargetPrograms batchPrograms_[2];  // the shader tests' batch program, without and with the cone test
    bool spotCones_ = true;  // setSpotCones: the next draw's lights include spot lights
    // setShadows: the shadowed programs, by screen tiles, cones and shadow defines (built on first use).
    const ShadowMaps* shadowMaps_ = nullptr;
    ShadowSettings shadowSettings_;
    bool shadowDraw_ = false;
    std::function<DrawTargetPrograms(bool screenTiles, bool cones, const ShaderDefines& shadow)> makePrograms_;
    std::map<std::string, DrawTargetPrograms> shadowPrograms_;
    gl::Uniform<glm::vec4> shadowTilesUniform_;
    std::vector<glm::vec4> shadowTileData_;
    // The frame (begin()) and the current plan's program and per-step uniforms (one light, or a batch's arrays).
    CameraMatrices camera_;
    glm::ivec2 targetSize_{1};
    const gl::Texture* depth_ = nullptr;
    bool readsSpans_ = false;  // the batch programs read the depth spans (LIDR_DEPTH_SPAN)
    int spanSamples_ = 0;  // ... as each of this many samples' distance (LIDR_SPAN_SAMPLES); 0: moments
    const DepthSpanPass* depthSpans_ = nullptr;
    VolumeProgram program_ = VolumeProgram::PerLight;
    int targets_ = 1;
    float depthUnits_ = 16777215.0f;  // 2^depthBits - 1
    gl::Uniform<glm::vec4> lightsUniform_, colorsUniform_, conesUniform_;
    gl::Uniform<glm::vec4> spotUniform_;  // the stencil tests' uSpotVolume
    gl::Uniform<float> clampUniform_;
    std::vector<glm::vec4> lightData_, colorData_, coneData_;
    // Tile-culled volumes (setTileDepth): the frame's tile ranges, each light's tiles (by its place in the
    // pass's light list) and each tile's candidate count, the stream buffer of quads and its program.
    const VolumeTiles* tiles_ = nullptr;
    struct SphereKey {
        glm::vec4 posRadius;
        bool operator==(const SphereKey& o) const { return posRadius == o.posRadius; }
    };
    struct SphereHash {
        size_t operator()(const SphereKey& k) const;
    };
    std::unordered_map<SphereKey, SphereTiles, SphereHash> sphereTiles_;  // this frame's, by sphere
    std::vector<glm::vec4> tiledLights_;           // the spheres lightTiles_ was gathered for
    std::vector<int> tiledRegions_;                // and their regions
    std::vector<const SphereTiles*> lightTiles_;
    IndexRegions regions_;
    // Per tile: at most this many lights mark one of its pixels (the most spheres reaching one run of slices a
    // pixel's depth span may cover, VolumeTiles::candidateWindows).
    std::vector<int> tileCandidates_;
    std::vector<uint8_t> sliceCounts_;  // per tile and run start, saturating at 255 (a bound above 32 is as good)
    int skipTilesUpTo_ = 0;  // the current draw's tiles with at most this many candidates are skipped
    long tileQuadPixels_ = 0;
    long tileStepLights_ = 0;
    gl::Buffer tileQuads_;
    std::vector<glm::vec4> tileVertices_;
    DrawTargetPrograms tilePrograms_[2];
};

}  // namespace lidr
