#pragma once
// Deferred shading ("deferred"; the technique Trebilco 2007 and Olsson & Assarsson 2011 measure LIDR and tiled
// shading against) on the same footing as every mode: the same scene, camera, light table and shading function.
//
// Frame: shadow maps, light table -> depth pre-pass -> G-buffer (lidr/modes/g_buffer.h: the opaque meshes' surfaces
// in four targets, depth EQUAL) -> light volumes: each point or spot light's circumscribed sphere mesh shading the
// G-buffer's surfaces inside it, added (ONE, ONE) into the accumulation target (the G-buffer's float format) ->
// composite, full screen: ambient, environment, emission and directional lights plus the sum, through the output
// transform -> transparent meshes by the brute-force forward shading every light (the reference's program: exact,
// no light list to reuse) -> passes() lists them (lidr-demo --list-passes deferred).
//
// Volumes: without the stencil test (the default, by measurement), back faces with depth GEQUAL (every surface in front of the volume's far side,
// lit or not, runs the light's shader; the shading's falloff gives 0 outside). With it (DeferredOptions::stencil,
// Olsson & Assarsson's Deferred-Stencil), back faces first mark in the stencil where the surface lies in front of
// them, then front faces shade where marked (depth LEQUAL) and clear the mark: only surfaces inside the volume's
// depth span run the shader. A spot light draws LIDR's cone mesh around its cone. A light whose volume reaches the near plane (the eye inside or close) is drawn the
// first way, its front faces being clipped. MSAA: the multisampled G-buffer (lidr/modes/g_buffer_multisample.h), the
// light volumes, composite and transparent meshes drawn into the MSAA targets and shaded once a sample, then resolved;
// refused where the context has no multisample textures or per-sample shading (GL 2.1, ES 2.0, WebGL 1).
#include <string>
#include <vector>

#include <memory>

#include "lidr/modes/g_buffer.h"
#include "lidr/modes/g_buffer_multisample.h"
#include "lidr/render/frame_resources.h"
#include "lidr/technique/light_volume_mesh.h"

namespace lidr {

struct DeferredOptions {
    // The stencil test on the light volumes (--deferred-stencil on|off). Off by measurement: on llvmpipe the marking
    // pass costs more than the shading it saves (light-volumes 0.5-0.8x with it off on hall-255 and many-1024-fp at
    // 320x240, doc/deferred.md); a GPU's early stencil test may decide otherwise (not measured here).
    bool stencil = false;
    GBufferFormat format = GBufferFormat::Auto;  // rgba16f where the context renders to it, else rgba8
    bool transparency = true;  // draw transparent meshes (opacity < 1) after the opaque ones, forward
    int msaaSamples = 0;       // 0, or 2..: the multisampled G-buffer (refused without deferredMsaaRefusal's features)
    bool forceFixedLightTable = false;
    bool timing = false;  // as LidrOptions::timing
    TimingMethod timingMethod = TimingMethod::Auto;
};

class DeferredRenderer final : public Renderer {
public:
    // Throws UnsupportedError where the context cannot hold the G-buffer (GBuffer, GBufferMultisample; MSAA:
    // deferredMsaaRefusal), before drawing.
    DeferredRenderer(const GlInfo& info, const Scene& scene, const DeferredOptions& options, int width, int height);
    std::string modeName() const override { return "deferred"; }
    const FrameStats& render(const Camera& camera, const std::vector<PointLight>& lights,
                             const ShadingParameters& shading) override;
    const FrameResources& frame() const override { return frame_; }
    std::vector<FramePass> passes() const override;
    // The G-buffer and the accumulation target.
    size_t lightDataBytes() const override { return gBuffer_->bytes(); }
    // "deferred": the G-buffer's format, samples and bytes a pixel (all samples), the light sum's, the stencil test,
    // the lights drawn each way.
    ModeStatistics modeStatistics() const override;
    const DeferredGBuffer& gBuffer() const { return *gBuffer_; }
    const DeferredOptions& options() const { return options_; }
    // The last frame's lights drawn the stencil way and the back-face way (near-plane lights, or stencil off).
    int stencilLights() const { return stencilLights_; }
    int backFaceLights() const { return backFaceLights_; }

private:
    bool perSample() const { return frame_.targets.samples() > 0; }
    void drawLightVolumes(const CameraMatrices& cam, const std::vector<PointLight>& lights,
                          const ShadingParameters& shading);
    // Whether a light's volume (within r of `centre`) may reach the near plane: its front faces may be clipped.
    bool volumeNearEye(const CameraMatrices& cam, const glm::vec3& centre, float r) const;
    void composite(const CameraMatrices& cam, const ShadingParameters& shading);
    void shadeTransparent(const CameraMatrices& cam, const std::vector<PointLight>& lights,
                          const ShadingParameters& shading);

    FrameResources frame_;
    DeferredOptions options_;
    std::unique_ptr<DeferredGBuffer> gBuffer_;
    std::string lightShader_;  // the light pass's fragment shader file (the multisample one under MSAA)
    gl::Program light_, mark_, composite_, transparent_;
    ShaderDefines lightDefines_, transparentDefines_;
    int transparentBound_ = 0;  // transparent_'s LIDR_MAX_LIGHTS (rebuilt when a frame has more lights)
    struct VolumeMesh {  // a light volume mesh on the GPU
        gl::Buffer vertices, indices;
        int indexCount = 0;
        float outsideRadius = 1.0f;  // of the unit mesh (the sphere's; the cone's cap lies within its scale)
    };
    static VolumeMesh upload(const LightVolumeMesh& mesh);
    struct PlacedVolume {  // a light's volume as drawn: deferred_volume.vert's uniforms
        const VolumeMesh* mesh = nullptr;
        glm::vec4 posRadius{0.0f}, spot{0.0f};  // uVolumePosRadius, uSpotVolume
        float reach = 0.0f;                     // how far from the centre the mesh reaches
    };
    // The sphere mesh or a spot light's cone mesh around light `l` of reach r; under MSAA the sphere, grown.
    PlacedVolume placeVolume(const CameraMatrices& cam, const PointLight& l, float r) const;
    void bindVolumeMesh(const VolumeMesh& mesh) const;
    VolumeMesh sphere_, cone_;
    int stencilLights_ = 0, backFaceLights_ = 0;
};

}  // namespace lidr
