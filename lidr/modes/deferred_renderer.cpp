#include "lidr/modes/deferred_renderer.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <sstream>

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"
#include "lidr/render/shading_pass.h"
#include "lidr/render/shading_variants.h"
#include "lidr/technique/light_volume_mesh.h"

namespace lidr {

namespace {
const GlInfo& checkedContext(const GlInfo& info, const DeferredOptions& o) {
    const std::string msaaRefusal = deferredMsaaRefusal(info, o.msaaSamples, "deferred");
    if (!msaaRefusal.empty()) throw UnsupportedError(msaaRefusal);
    return info;
}

// Deferred shading's own passes, between FrameResources' (passes(), render()).
constexpr FramePass kGBuffer{"g-buffer", "scene, depth", "G-buffer (4 targets; RGBA8: 5)"};
constexpr FramePass kLightVolumes{"light-volumes", "lights, G-buffer, depth, light table, [shadow atlas]",
                                  "light sum"};
constexpr FramePass kLightVolumesStencil{"light-volumes",
                                         "lights, G-buffer, depth, stencil marks, light table, [shadow atlas]",
                                         "light sum, stencil marks"};
constexpr FramePass kComposite{"deferred-composite", "G-buffer, light sum, [environment]", "colour"};
constexpr FramePass kTransparent{"deferred-transparent",
                                 "transparent meshes, depth, light table, [shadow atlas], [environment]", "colour",
                                 "transparent meshes in the scene"};
// The light volumes' states: without the stencil test, back faces shade where the surface lies in front of the
// volume's far side; with it, back faces mark 1 there (no colour), then front faces shade where marked in front of
// the near side and clear the mark (depth pass or fail: every marked pixel lies under a front face).
struct VolumeStates {
    RenderState backFaces, mark, frontFaces;
};
VolumeStates volumeStates(bool perSample) {
    VolumeStates v;
    RenderState& backFaces = v.backFaces;  // shade (or mark) where the surface lies in front of the volume's far side
    backFaces.depthTest = true;
    backFaces.depthFunc = GL_GEQUAL;
    backFaces.cull = true;
    backFaces.cullFace = GL_FRONT;
    backFaces.blend = true;
    backFaces.blendSrcRgb = backFaces.blendDstRgb = backFaces.blendSrcAlpha = backFaces.blendDstAlpha = GL_ONE;
    RenderState& mark = v.mark;
    mark = backFaces;  // the stencil way: mark 1 there, no colour
    mark.blend = false;
    mark.colorMask = glm::bvec4(false);
    mark.stencilTest = true;
    mark.stencil.ref = 1;
    mark.stencil.depthPass = GL_REPLACE;
    RenderState& frontFaces = v.frontFaces;
    frontFaces = backFaces;  // ... then shade where marked in front of the near side; clear the mark
    frontFaces.depthFunc = GL_LEQUAL;
    frontFaces.cullFace = GL_BACK;
    frontFaces.stencilTest = true;
    frontFaces.stencil.func = GL_EQUAL;
    frontFaces.stencil.ref = 1;
    frontFaces.stencil.depthFail = frontFaces.stencil.depthPass = GL_ZERO;
    backFaces.sampleShading = frontFaces.sampleShading = perSample;  // MSAA: each sample's surface (the mark needs none)
    return v;
}
}  // namespace

DeferredRenderer::DeferredRenderer(const GlInfo& info, const Scene& scene, const DeferredOptions& options, int width,
                                   int height)
    : frame_(checkedContext(info, options), scene, FrameSetup::of(options, scene, width, height)),
      options_(options),
      gBuffer_(makeDeferredGBuffer(info, frame_.targets, options.format, true)),
      lightShader_(perSample() ? "deferred_light_multisample.frag" : "deferred_light.frag") {
    lightDefines_ = frame_.lightTable.defines();
    lightDefines_.push_back({"LIDR_DIELECTRIC_SPECULAR", "1"});  // F90 comes from the G-buffer
    for (const auto& d : gBuffer_->shaderDefines()) lightDefines_.push_back(d);  // the RGBA8 layout's decoding
    light_ = gl::Program::create("deferred-light", buildShaderSource("deferred_volume.vert"),
                                 buildShaderSource(lightShader_, lightDefines_), geometryAttributes());
    mark_ = gl::Program::create("deferred-stencil-mark", buildShaderSource("deferred_volume.vert"),
                                buildShaderSource("deferred_stencil_mark.frag"), geometryAttributes());
    const char* compositeShader = perSample() ? "deferred_composite_multisample.frag" : "deferred_composite.frag";
    composite_ = gl::Program::create("deferred-composite", buildShaderSource("deferred_fullscreen.vert"),
                                     buildShaderSource(compositeShader, lightDefines_), geometryAttributes());
    sphere_ = upload(makeLightVolumeMesh(2));
    cone_ = upload(makeSpotVolumeMesh());
    cone_.outsideRadius = 1.0f;  // its vertices lie on the cap's sphere (radius: the range x the cap's scale)
    checkGl("DeferredRenderer");
}

DeferredRenderer::VolumeMesh DeferredRenderer::upload(const LightVolumeMesh& mesh) {
    VolumeMesh m;
    m.vertices = gl::Buffer::create(GL_ARRAY_BUFFER, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
    m.indices = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, mesh.indices.data(), mesh.indices.size() * sizeof(uint16_t));
    m.indexCount = int(mesh.indices.size());
    m.outsideRadius = mesh.outsideRadius;
    return m;
}

void DeferredRenderer::bindVolumeMesh(const VolumeMesh& mesh) const {
    glBindBuffer(GL_ARRAY_BUFFER, mesh.vertices.id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh.indices.id());
    glVertexAttribPointer(gl::kPosition, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
}

std::vector<FramePass> DeferredRenderer::passes() const {
    std::vector<FramePass> p{pass::kShadowMaps, pass::kLightTable, pass::kDepthPrepass, kGBuffer,
                             options_.stencil ? kLightVolumesStencil : kLightVolumes, kComposite};
    if (options_.transparency) p.push_back(kTransparent);
    if (perSample()) p.push_back(pass::kMsaaResolve);
    return p;
}

const FrameStats& DeferredRenderer::render(const Camera& camera, const std::vector<PointLight>& lights,
                                           const ShadingParameters& shading) {
    const CameraMatrices cam = frame_.checkFrame(camera, lights, shading, "deferred");
    const FrameScope scope(stats_, frame_.timer, lights.size());
    frame_.prepareLights(lights, shading, stats_);  // shadow-maps, light-table
    frame_.drawDepthPrepass(cam);
    {
        TimedPass gBufferTime(frame_.timer, kGBuffer.name);
        gBuffer_->draw(frame_.scene, cam);
    }
    drawLightVolumes(cam, lights, shading);
    composite(cam, shading);
    if (options_.transparency && frame_.scene.hasTransparent()) shadeTransparent(cam, lights, shading);
    frame_.resolve();
    gBuffer_->unbind();
    frame_.finishFrame(stats_, "DeferredRenderer::render");
    return stats_;
}

bool DeferredRenderer::volumeNearEye(const CameraMatrices& cam, const glm::vec3& centre, float r) const {
    float nearReach = 0.0f;  // the farthest near-plane corner from the eye
    for (int corner = 0; corner < 4; ++corner) {
        const glm::vec4 p = cam.inverseViewProjection *
                            glm::vec4(corner & 1 ? 1.0f : -1.0f, corner & 2 ? 1.0f : -1.0f, -1.0f, 1.0f);
        nearReach = std::max(nearReach, glm::length(glm::vec3(p) / p.w - cam.eye));
    }
    return glm::length(centre - cam.eye) <= r * 1.01f + nearReach * 1.01f;
}

DeferredRenderer::PlacedVolume DeferredRenderer::placeVolume(const CameraMatrices& cam, const PointLight& l,
                                                            float r) const {
    PlacedVolume v{&sphere_, glm::vec4(l.position, r), glm::vec4(0.0f), r * sphere_.outsideRadius};
    if (perSample()) {
        // MSAA: a sample shades the point on its pixel centre's ray, up to 0.71 pixels from the sample's own ray;
        // the sphere grown by a pixel's width at its far side covers the sample, and passes the depth test against
        // the stored depths (GBufferMultisample::beginAccumulation), wherever the light reaches that point. Spot
        // lights take the grown sphere too (the cone mesh does not grow evenly).
        const float pixelPerDistance =
            2.0f / std::min(cam.projection[0][0] * float(cam.width), cam.projection[1][1] * float(cam.height));
        v.posRadius.w = r + (glm::length(l.position - cam.eye) + r) * pixelPerDistance;
        v.reach = v.posRadius.w * sphere_.outsideRadius;
        return v;
    }
    // A spot light: LIDR's cone mesh around the cone as the light table holds it (lidr::spotCone).
    const glm::vec4 cone = spotCone(l);
    const float coneScale = glm::length(glm::vec3(cone));
    if (!l.isSpot() || coneScale <= 0.0f) return v;
    const SpotVolumeShape shape = spotVolumeShape(std::acos(std::clamp(-cone.w / coneScale, 0.0f, 1.0f)));
    v.mesh = &cone_;
    v.posRadius.w = v.reach = r * shape.capScale;
    v.spot = glm::vec4(glm::vec3(cone) / coneScale, shape.rimAngle);
    return v;
}

void DeferredRenderer::drawLightVolumes(const CameraMatrices& cam, const std::vector<PointLight>& lights,
                                        const ShadingParameters& shading) {
    TimedPass lightVolumesTime(frame_.timer, kLightVolumes.name);
    StateCache& cache = StateCache::current();
    gBuffer_->beginAccumulation();  // MSAA: with the shaded surfaces' depths
    const gl::Program& program =
        frame_.shadows.active()
            ? frame_.shadows.program(light_.name(), "deferred_volume.vert", lightShader_, lightDefines_,
                                     shading.shadows)
            : light_;
    useShadingProgram(program, cam, shading, frame_.lightTable, frame_.environment);
    frame_.shadows.bind(program, shading.shadows);
    gBuffer_->bind(program, cam);
    if (options_.stencil) {
        mark_.use();
        mark_.set("uViewProj", cam.viewProjection);
        program.use();
    }
    glEnableVertexAttribArray(gl::kPosition);
    const VolumeMesh* bound = nullptr;

    const VolumeStates states = volumeStates(perSample());

    const float reach = frame_.lightTable.reachError();
    stencilLights_ = backFaceLights_ = 0;
    for (size_t i = 0; i < lights.size(); ++i) {
        const PointLight& l = lights[i];
        const float r = l.radius + reach;
        if (!sphereMayBeVisible(cam, l.position, r * sphere_.outsideRadius)) continue;
        // Lights that touch no opaque mesh's bounds shade nothing, except under MSAA: a sample of an edge pixel
        // shades its fragment's surface extrapolated to the pixel centre, which may lie outside every mesh's bounds.
        if (!perSample() && !frame_.scene.batchesTouchSphere(glm::vec4(l.position, r), DrawFilter::Opaque)) continue;
        const PlacedVolume placed = placeVolume(cam, l, r);
        const VolumeMesh& mesh = *placed.mesh;
        const glm::vec4 volume = placed.posRadius, spot = placed.spot;
        if (&mesh != bound) bindVolumeMesh(*(bound = &mesh));
        const float reachOfVolume = placed.reach;
        const bool stenciled = options_.stencil && !volumeNearEye(cam, l.position, reachOfVolume);
        if (stenciled) {
            mark_.use();
            mark_.set("uVolumePosRadius", volume);
            mark_.set("uSpotVolume", spot);
            cache.apply(states.mark);
            cache.drawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_SHORT, nullptr);
            program.use();
            cache.apply(states.frontFaces);
            ++stencilLights_;
        } else {
            cache.apply(states.backFaces);
            ++backFaceLights_;
        }
        program.set("uVolumePosRadius", volume);
        program.set("uSpotVolume", spot);
        program.set("uLightIndex", float(i + 1));
        cache.drawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_SHORT, nullptr);
        stats_.volumeDrawCalls += stenciled ? 2 : 1;
        ++stats_.drawnLights;
    }
    glDisableVertexAttribArray(gl::kPosition);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    cache.apply(RenderState{});
}

void DeferredRenderer::composite(const CameraMatrices& cam, const ShadingParameters& shading) {
    TimedPass compositeTime(frame_.timer, kComposite.name);
    beginOpaqueShading(frame_.targets, shading, true);  // cleared to the background
    RenderState fullScreen;  // no depth test; MSAA: once a sample
    fullScreen.sampleShading = perSample();
    StateCache::current().apply(fullScreen);
    const uint32_t key = shadingVariantKey(composite_, shading, frame_.environment);
    const gl::Program& program = composite_.variant(key, [&] { return shadingVariantDefines(key); });
    program.use();
    setShadingUniforms(program, cam, shading, frame_.environment);
    gBuffer_->bind(program, cam);
    gBuffer_->drawFullScreen();
}

void DeferredRenderer::shadeTransparent(const CameraMatrices& cam, const std::vector<PointLight>& lights,
                                        const ShadingParameters& shading) {
    TimedPass transparentTime(frame_.timer, kTransparent.name);
    const int bound = std::max<int>(1, int(lights.size()));
    if (bound > transparentBound_) {  // its loop bound is compiled in: rebuilt for more lights
        transparentDefines_ = frame_.lightTable.defines();
        transparentDefines_.push_back({"LIDR_MAX_LIGHTS", std::to_string(bound)});
        transparent_ = gl::Program::create("deferred-transparent-" + std::to_string(bound),
                                           buildShaderSource("geometry.vert"),
                                           buildShaderSource("reference_forward.frag", transparentDefines_),
                                           geometryAttributes());
        transparentBound_ = bound;
    }
    frame_.targets.bindColor();
    beginTransparentShading();
    const gl::Program& program =
        frame_.shadows.shadingProgram(transparent_, "reference_forward.frag", transparentDefines_, shading.shadows);
    useShadingProgram(program, cam, shading, frame_.lightTable, frame_.environment);
    frame_.shadows.bind(program, shading.shadows);
    program.set("uLightCount", float(lights.size()));
    frame_.scene.drawTransparentSorted(program, cam.eye, shadingVariantKey(program, shading, frame_.environment));
}

ModeStatistics DeferredRenderer::modeStatistics() const {
    ModeStatistics m;
    m.section = "deferred";
    const std::string format = gBufferFormatName(gBuffer_->format());
    m.values = {modeStatistic("g_buffer_format", format), modeStatistic("g_buffer_samples", gBuffer_->samples()),
                modeStatistic("g_buffer_bytes_per_pixel", gBuffer_->bytesPerPixel()),
                modeStatistic("light_sum_bytes_per_pixel", gBuffer_->accumulationBytesPerPixel()),
                modeStatistic("light_sum_format", std::string(gBuffer_->accumulationFormatName())),
                modeStatistic("geometry_passes", gBuffer_->geometryPasses()),
                modeStatistic("stencil", options_.stencil), modeStatistic("stencil_lights", stencilLights_),
                modeStatistic("back_face_lights", backFaceLights_)};
    std::ostringstream s;
    s << "g-buffer   " << gBufferDescription(*gBuffer_) << " + " << gBuffer_->accumulationBytesPerPixel()
      << " for the light sum (" << gBuffer_->accumulationFormatName()
      << (gBuffer_->eightBitAccumulation() ? ", clamped at 1" : "") << "), "
      << (gBuffer_->geometryPasses() > 1 ? std::to_string(gBuffer_->geometryPasses()) + " geometry passes, " : "")
      << "stencil " << (options_.stencil ? "on" : "off") << " (" << stencilLights_ << " lights the stencil way, "
      << backFaceLights_ << " the back-face way)";
    m.line = s.str();
    return m;
}

}  // namespace lidr
