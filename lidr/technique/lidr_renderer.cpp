#include "lidr/technique/lidr_renderer.h"
#include "lidr/base/gl.h"
#include "lidr/gl/saved_gl_state.h"

#include <algorithm>
#include <numeric>

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr {

namespace {
std::unique_ptr<PackingScheme> checkedScheme(const GlInfo& info, const Scene& scene, const LidrOptions& o) {
    if (!o.depthPrepass && o.volumeTest != VolumeTest::FrontFace)
        throw Error(std::string("the ") + volumeTestName(o.volumeTest) +
                    " volume test needs the depth pre-pass; only frontface may skip it");
    if (o.perSampleIndices) {
        if (o.msaaSamples < 2) throw Error("per-sample index targets need MSAA (2 or more samples)");
        if (!info.multisampleTexture || !info.sampleShading)
            throw UnsupportedError("per-sample index targets need multisample textures (GL 3.2 / "
                                   "ARB_texture_multisample) and sample shading (GL 4.0 / ARB_sample_shading); this "
                                   "context (GL " + info.version + ") lacks them: use the single-sample front-face "
                                   "index texture instead");
        if (o.msaaSamples > info.maxColorTextureSamples)
            throw UnsupportedError("per-sample index targets: " + std::to_string(o.msaaSamples) +
                                   " samples asked for, multisample textures allow at most " +
                                   std::to_string(info.maxColorTextureSamples));
    } else if (o.msaaSamples > 0 && !isFrontFaceVolumeTest(o.volumeTest)) {
        throw Error("MSAA takes each edge sample's lights from a front-face index texture: use the sphere-ray or "
                    "frontface volume test with MSAA (or per-sample index targets where the context has them)");
    }
    if (o.perSampleIndices && isShaderVolumeTest(o.volumeTest))
        throw Error(std::string("the ") + volumeTestName(o.volumeTest) + " volume test reads single-sample depth; "
                    "per-sample index targets take backface, exact or frontface");
    if (o.perSampleIndices && !o.depthPrepass)
        throw Error("per-sample index targets are built against the MSAA pre-pass depth: keep the pre-pass");
    checkSamples(info, o.msaaSamples);
    auto scheme = createPackingScheme(o.packing, info);
    if (scene.lights.size() > scheme->maxLights())
        throw Error("scene has " + std::to_string(scene.lights.size()) + " lights but " +
                    std::to_string(o.packing.indexBits) + "-bit indices hold at most " +
                    std::to_string(scheme->maxLights()) + " (choose a wider index)");
    return scheme;
}
}  // namespace

LidrRenderer::LidrRenderer(const GlInfo& info, const Scene& scene, const LidrOptions& options, int width, int height)
    : options_(options),
      scheme_(checkedScheme(info, scene, options)),
      scene_(scene),
      targets_(info, width, height, options.msaaSamples),
      indexTargets_(scheme_->targetCount(), width, height,
                    options.perSampleIndices ? targets_.multisampleDepthStencil() : targets_.depthStencil(),
                    options.perSampleIndices ? options.msaaSamples : 0),
      lightTable_(info, static_cast<int>(scheme_->maxLights()), options.forceFixedLightTable),
      volumePass_(info, options.volumeTest, options.volumeDetail),
      forwardPass_(*scheme_, lightTable_, options.perSampleIndices, options.materialShader),
      timer_(info, options.timingMethod) {
    timer_.setEnabled(options.timing);
    drawTransparent_ = options.transparency && scene_.hasTransparent();
    bool needsDepthTexture = isShaderVolumeTest(options.volumeTest);
    if (drawTransparent_ && !isFrontFaceVolumeTest(options.volumeTest)) {
        transparentIndexTargets_ =
            IndexTargets(scheme_->targetCount(), width, height,
                         options.perSampleIndices ? targets_.multisampleDepthStencil() : targets_.depthStencil(),
                         options.perSampleIndices ? options.msaaSamples : 0);
        // The exact front-face lists in batches go with the sphere test; the stencil tests keep front faces.
        const VolumeTest front = options.volumeTest == VolumeTest::Sphere ? VolumeTest::SphereRay : VolumeTest::FrontFace;
        transparentVolumePass_ = LightVolumePass(info, front, options.volumeDetail);
        needsDepthTexture = needsDepthTexture || isShaderVolumeTest(front);
    }
    if (needsDepthTexture)
        depthTexture_ = gl::Texture::create2D(GL_DEPTH_COMPONENT24, width, height, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT);
}

const IndexTargets& LidrRenderer::transparentIndexTargets() const {
    return transparentIndexTargets_.count() > 0 ? transparentIndexTargets_ : indexTargets_;
}

std::vector<uint32_t> LidrRenderer::drawOrder(const std::vector<PointLight>& lights) {
    std::vector<uint32_t> order(lights.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return lights[a].priority > lights[b].priority; });
    for (uint32_t& i : order) ++i;  // 1-based light indices
    return order;
}

const FrameStats& LidrRenderer::render(const Camera& camera, const std::vector<PointLight>& lights,
                                       const ShadingParameters& shading) {
    const SavedGlState callerState;  // the caller's GL state comes back on return (doc/embedding.md)
    if (lights.size() > scheme_->maxLights())
        throw Error(std::to_string(lights.size()) + " lights exceed the " + std::to_string(scheme_->maxLights()) +
                    " that " + std::to_string(options_.packing.indexBits) + "-bit indices hold");
    const CameraMatrices cam = cameraMatrices(camera, targets_.width(), targets_.height());
    stats_ = FrameStats{};
    stats_.timingMethod = timer_.method();
    stats_.sceneLights = static_cast<int>(lights.size());

    timer_.begin("light-table");
    lightTable_.update(lights);
    std::vector<VolumeLight> volumes;
    for (uint32_t index : drawOrder(lights)) {
        const PointLight& l = lights[index - 1];
        if (options_.cullLights && !sphereMayBeVisible(cam, l.position, l.radius)) continue;
        volumes.push_back({index, glm::vec4(l.position, l.radius)});
    }
    stats_.drawnLights = static_cast<int>(volumes.size());
    timer_.end();

    // The pre-pass the volume tests compare against: the MSAA one on the per-sample path.
    if (options_.perSampleIndices)
        targets_.bindColor();
    else
        targets_.bindSingleSample();
    if (options_.depthPrepass) {
        timer_.begin("depth-prepass");
        depthPrepass_.run(scene_, cam);
        if (depthTexture_) {
            // The shader volume tests read the pre-pass depth from a texture that is not attached to the
            // framebuffer they draw into (reading an attached one is a feedback loop).
            depthTexture_.bind(0);
            glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, targets_.width(), targets_.height());
            checkGl("depth copy for the volume tests");
        }
        timer_.end();
    } else {
        RenderState clearable;
        clearable.depthWrite = true;
        applyRenderState(clearable);
        glClearDepth(1.0);
        glClear(GL_DEPTH_BUFFER_BIT);
    }

    if (transparentIndexTargets_.count() > 0) {
        // First, so that the main pass's per-pixel light counts stay in the shared stencil. Only where
        // transparent geometry can be on screen, and only lights that reach a transparent mesh's bounds: the
        // lists outside stay empty, and no transparent surface reads them.
        glm::ivec4 area(0);
        std::vector<VolumeLight> reaching;
        if (transparentScreenArea(cam, area))
            for (const VolumeLight& v : volumes)
                if (reachesTransparentMesh(v)) reaching.push_back(v);
        stats_.transparentVolumeLights = static_cast<int>(reaching.size());
        timer_.begin("light-volumes-transparent");
        transparentVolumePass_.begin(transparentIndexTargets_, cam, &depthTexture_);
        if (!reaching.empty()) {
            const glm::ivec4 box(area.x, area.y, area.z - area.x + 1, area.w - area.y + 1);
            transparentVolumePass_.setScissor(&box);
            scheme_->encode(transparentVolumePass_, reaching);
            transparentVolumePass_.setScissor(nullptr);
        }
        transparentVolumePass_.end();
        timer_.end();
    }

    timer_.begin("light-volumes");
    volumePass_.begin(indexTargets_, cam, &depthTexture_);
    scheme_->encode(volumePass_, volumes);
    volumePass_.end();
    stats_.volumeDrawCalls = volumePass_.drawCalls() + transparentVolumePass_.drawCalls();
    timer_.end();

    const bool multisampled = targets_.samples() > 0;
    if (multisampled && options_.depthPrepass && !options_.perSampleIndices) {
        timer_.begin("msaa-depth-prepass");
        targets_.bindColor();
        depthPrepass_.run(scene_, cam);
        timer_.end();
    }

    timer_.begin("forward");
    forwardPass_.run(targets_, indexTargets_, scene_, lightTable_, cam, shading, options_.depthPrepass);
    timer_.end();

    if (drawTransparent_) {
        timer_.begin("forward-transparent");
        forwardPass_.runTransparent(targets_, transparentIndexTargets(), scene_, lightTable_, cam, shading);
        timer_.end();
    }
    targets_.resolve(timer_);

    stats_.passes = timer_.collect();
    stats_.timingLag = timer_.lag();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGl("LidrRenderer::render");
    return stats_;
}

bool LidrRenderer::transparentScreenArea(const CameraMatrices& cam, glm::ivec4& area) const {
    bool any = false;
    for (size_t b = 0; b < scene_.batchCount(); ++b) {
        if (!scene_.batchTransparent(b)) continue;
        glm::vec3 lo, hi;
        scene_.batchBounds(b, lo, hi);
        glm::ivec4 r;
        if (!boxPixelRect(cam, lo, hi, r)) continue;
        area = any ? glm::ivec4(glm::min(glm::ivec2(area), glm::ivec2(r)), glm::max(glm::ivec2(area.z, area.w), glm::ivec2(r.z, r.w)))
                   : r;
        any = true;
    }
    return any;
}

bool LidrRenderer::reachesTransparentMesh(const VolumeLight& light) const {
    for (size_t b = 0; b < scene_.batchCount(); ++b) {
        if (!scene_.batchTransparent(b)) continue;
        glm::vec3 lo, hi;
        scene_.batchBounds(b, lo, hi);
        if (sphereTouchesBox(glm::vec3(light.posRadius), light.posRadius.w, lo, hi)) return true;
    }
    return false;
}

std::vector<ImageRGBA8> LidrRenderer::readIndexTargets() const {
    std::vector<ImageRGBA8> out;
    indexTargets_.framebuffer().bind();
    for (int i = 0; i < indexTargets_.count(); ++i) {
        glReadBuffer(GL_COLOR_ATTACHMENT0 + i);
        out.push_back(readPixelsRGBA8(indexTargets_.width(), indexTargets_.height()));
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return out;
}

std::vector<float> LidrRenderer::volumeOutsideRadii(const std::vector<PointLight>& lights) const {
    std::vector<float> radii;
    radii.reserve(lights.size());
    for (size_t i = 0; i < lights.size(); ++i)
        radii.push_back(volumePass_.outsideRadiusFor({uint32_t(i + 1), glm::vec4(lights[i].position, lights[i].radius)}));
    return radii;
}

std::vector<uint8_t> LidrRenderer::readLightCounts() const {
    const int bits = volumePass_.stencilCountBits();
    if (bits == 0) return {};
    std::vector<uint8_t> s = targets_.readStencil();
    const uint8_t mask = static_cast<uint8_t>((1u << bits) - 1u);
    for (uint8_t& v : s) v &= mask;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return s;
}

}  // namespace lidr
