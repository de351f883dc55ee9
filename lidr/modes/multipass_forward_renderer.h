#pragma once
// Multi-pass forward ("forward-multipass"): the classic forward renderer the LIDR paper compares with
// (Trebilco 2007). After a depth pre-pass, an ambient pass, then per light one additive pass (blend ONE, ONE,
// depth EQUAL) over the meshes that light's sphere touches, scissored to the light's screen rectangle
// (lidr/scene/sphere_bounds.h). Same scene, camera, light table and shading function as every other mode.
// Each pass shades one fragment per pixel (sample): stencil stamps let the first through, and the scene is
// drawn in reverse so that it is the fragment single-pass modes keep (doc/tiled.md, "One fragment per pixel
// and pass"). Under MSAA meshes are culled by screen rectangles (exactMsaaCulling).
//
// Accuracy: the passes sum linear light in a half-float target (HalfFloatTarget) where the context renders to
// one (GlInfo::halfFloatColorBuffer), and an encode pass runs the output transform over the float sum once, as
// the single-pass modes do in their shader: within 1 step of the reference, like them (doc/tiled.md). Where the
// context has none (or MultipassOptions::halfFloatAccumulation is false) they blend into the 8-bit colour
// target: each term rounded on its own, the sum clamped at 1 before the tone map; at a pixel lit by n lights the
// linear image can differ from the reference by up to floor(n / 2) + 1 steps (doc/colour.md).
// Transparent meshes are not drawn: additive light passes cannot alpha-blend a surface over what is behind it.
#include <string>
#include <vector>

#include "lidr/render/frame_resources.h"
#include "lidr/render/present.h"
#include "lidr/gl/half_float_target.h"

namespace lidr {

struct MultipassOptions {
    bool scissor = true;                // scissor each light pass to the light's screen rectangle
    bool cullMeshes = true;             // draw only the meshes whose bounds the light's sphere touches
    // Under MSAA, cull by screen rectangles instead (exact; see render()). false: by mesh bounds as without
    // MSAA, faster, but a sample shaded off its triangle (at the pixel centre) can miss a light.
    bool exactMsaaCulling = true;
    bool forceFixedLightTable = false;
    int msaaSamples = 0;                // 0, or 2..GL_MAX_SAMPLES: shading multisampled, then resolved
    // Sum the passes in a half-float target where the context can render to one; false: in the 8-bit colour
    // target, as where it cannot (the tests of that path; its cost, lidr-bench --multipass-accumulation).
    bool halfFloatAccumulation = true;
    bool timing = false;  // as LidrOptions::timing
    TimingMethod timingMethod = TimingMethod::Auto;
};

class MultipassForwardRenderer final : public Renderer {
public:
    MultipassForwardRenderer(const GlInfo& info, const Scene& scene, const MultipassOptions& options, int width,
                             int height);
    std::string modeName() const override { return "forward-multipass"; }
    const FrameStats& render(const Camera& camera, const std::vector<PointLight>& lights,
                             const ShadingParameters& shading) override;
    const FrameResources& frame() const override { return frame_; }
    long meshDrawCalls() const { return meshDraws_; }  // light-pass mesh draws of the last frame
    // Where the passes sum their light: "half-float" or "8-bit", chosen when the renderer was made.
    const char* accumulation() const { return halfFloat_ ? "half-float" : "8-bit"; }
    // Why the 8-bit target (forced, or what the context lacks); with half float and MSAA, how the samples are
    // resolved; else empty.
    const std::string& accumulationNote() const { return accumulationNote_; }
    ModeStatistics modeStatistics() const override;  // "multipass": accumulation and its note

    std::vector<FramePass> passes() const override;

private:
    // The passes of render() after the pre-pass, in its order (passes() says what each reads and writes).
    void drawAmbient(const CameraMatrices& cam, const PassDescription& sumPass, const ShadingParameters& linearShading);
    void drawLightPasses(const CameraMatrices& cam, const std::vector<PointLight>& lights,
                         const ShadingParameters& linearShading);
    std::vector<glm::ivec4> meshScreenRects(const CameraMatrices& cam) const;  // per batch; exactMsaaCulling
    void encodeOutput(const OutputTransform& output);

    FrameResources frame_;
    MultipassOptions options_;
    HalfFloatTarget halfFloat_;  // empty: the passes blend into frame_.targets' 8-bit colour
    std::string accumulationNote_;
    gl::Program ambient_, light_;
    ShaderDefines lightDefines_;  // light_'s, for its shadowed twin (ShadowMaps::program)
    OutputEncodePass outputEncode_;  // its passes sum linear light; the output transform runs over the sum
    long meshDraws_ = 0;
};

}  // namespace lidr
