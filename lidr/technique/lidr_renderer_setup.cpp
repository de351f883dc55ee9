// LidrRenderer's construction: the options checked against the context and the scene, the packing chosen, the
// frame's resources and passes made (lidr_renderer.cpp draws the frames).
#include "lidr/technique/lidr_renderer.h"
#include "lidr/base/gl.h"
#include "lidr/gl/saved_gl_state.h"

#include <algorithm>

#include "lidr/base/error.h"
#include "lidr/gl/early_depth_probe.h"
#include "lidr/gl/gl_state.h"
#include "lidr/render/shading_pass.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr {

namespace {
// The options a context without occlusion queries (OpenGL ES 2.0) can run: an automatic budget is measured by
// occlusion queries over the stencil count, so there it becomes the fixed kBudgetWithoutOcclusionQueries
// (bit-shift; the automatic width stays). FrameStats::autoDecision.budgetFallback says so each frame.
LidrOptions withContextFallbacks(const GlInfo& info, LidrOptions o) {
    // The default test lists the lights of the pixel centre's surface; under MSAA that is sphere-span, which
    // lists those of every sample's surface (interior pixels: the same lists; doc/msaa-transparency.md).
    if (o.msaaSamples > 0 && !o.perSampleIndices && o.volumeTest == VolumeTest::Sphere) o.volumeTest = VolumeTest::SphereSpan;
    // sphere-span reads each sample's distance where the context has multisample textures (GL 3.2), else the
    // GL 2.1 moments (doc/msaa-transparency.md, "Edge pixels").
    if (o.volumeTest == VolumeTest::SphereSpan) o.msaaSpans = resolveDepthSpanStorage(o.msaaSpans, info, o.msaaSamples);
    if (info.occlusionQuery || !o.packing.autoBudget()) return o;
    if (o.packing.autoScheme()) o.packing.scheme = PackingSchemeKind::BitShift;
    o.packing.budget = LidrRenderer::kBudgetWithoutOcclusionQueries;
    return o;
}

// The MSAA options: per-sample index targets where the context has them, a volume test whose single-sample lists
// cover every sample's surface.
void checkMsaaOptions(const GlInfo& info, const LidrOptions& o) {
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
    } else if (o.msaaSamples > 0 && !isFrontFaceVolumeTest(o.volumeTest) && o.volumeTest != VolumeTest::SphereSpan) {
        throw Error("MSAA takes each edge sample's lights from a single-sample index texture that must cover every "
                    "sample's surface: use the sphere-span (the default), sphere-ray or frontface volume test with MSAA "
                    "(or per-sample index targets where the context has them)");
    }
    if (o.volumeTest == VolumeTest::SphereSpan && (o.msaaSamples == 0 || o.perSampleIndices))
        throw Error("the sphere-span volume test lists the surfaces of a pixel's MSAA samples: it needs MSAA on the "
                    "single-sample index path (without MSAA use sphere, which lists the same lights)");
    if (o.perSampleIndices && isShaderVolumeTest(o.volumeTest))
        throw Error(std::string("the ") + volumeTestName(o.volumeTest) + " volume test reads single-sample depth; "
                    "per-sample index targets take backface, exact or frontface");
    if (o.perSampleIndices && !o.depthPrepass)
        throw Error("per-sample index targets are built against the MSAA pre-pass depth: keep the pre-pass");
}

// Checks the options and returns the concrete packing the first frame uses: "auto" resolved to bit-shift,
// an automatic budget to its initial value, an automatic width to the narrowest for the scene's lights.
PackingConfig checkedPacking(const GlInfo& info, const Scene& scene, const LidrOptions& o) {
    if (o.emulatedDepthBits != 0) {
        if (o.emulatedDepthBits != 16)
            throw Error("emulatedDepthBits is 0 (off) or 16, got " + std::to_string(o.emulatedDepthBits));
        if (o.depthBits != 24)
            throw Error("emulatedDepthBits rounds depth to 16 bits inside the 24-bit buffer: keep depthBits 24 "
                        "(depthBits 16 is the real 16-bit buffer)");
        if (o.msaaSamples > 0)
            throw Error("emulatedDepthBits writes one depth per fragment, which would replace MSAA's per-sample "
                        "depth: use it without MSAA");
        if (!o.materialShader.empty())
            throw Error("emulatedDepthBits needs lidr's own forward shader: a material shader does not write the "
                        "rounded depth the pre-pass wrote");
        if (info.gles)
            throw UnsupportedError("emulatedDepthBits writes gl_FragDepth, which OpenGL ES 2.0 has only with "
                                   "EXT_frag_depth: use a desktop GL context");
    }
    checkDepthBits(info, o.depthBits);
    if (!o.depthPrepass && o.volumeTest != VolumeTest::FrontFace)
        throw Error(std::string("the ") + volumeTestName(o.volumeTest) +
                    " volume test needs the depth pre-pass; only frontface may skip it");
    checkMsaaOptions(info, o);
    checkSamples(info, o.msaaSamples);
    // The shader tests read a depth texture; transparent layers under `sphere` take `sphere-ray`.
    if (isShaderVolumeTest(o.volumeTest) && !info.depthTexture)
        throw UnsupportedError(std::string("the ") + volumeTestName(o.volumeTest) + " volume test reads a copy of the "
                               "pre-pass depth, and this context has no depth textures (OpenGL ES 2.0 needs "
                               "OES_depth_texture): use --volume-test backface or exact");

    PackingConfig c = o.packing;
    if (c.autoScheme()) {
        if (c.budget != PackingConfig::kAuto || c.indexBits != PackingConfig::kAuto)
            throw Error("the auto scheme chooses the budget and the index width itself (got budget " +
                        std::to_string(c.budget) + ", " + std::to_string(c.indexBits) +
                        "-bit): leave both automatic, or name a scheme (bitshift, max-stencil, cpu-sorted) to fix them");
        c.scheme = PackingSchemeKind::BitShift;
    }
    if (c.budget == PackingConfig::kAuto && c.scheme != PackingSchemeKind::BitShift)
        throw Error(std::string("an automatic budget is measured from the stencil count of bit-shift packing; ") +
                    packingSchemeName(c.scheme) + " needs a fixed budget (1, 2, 4, 8 or 16)");
    if (o.autoHoldFrames < 0 || o.autoHoldFrames > 100000)
        throw Error("autoHoldFrames must be in [0, 100000], got " + std::to_string(o.autoHoldFrames));
    if (o.autoNarrowingInterval < 1 || o.autoNarrowingInterval > 100000)
        throw Error("autoNarrowingInterval must be in [1, 100000], got " + std::to_string(o.autoNarrowingInterval));
    const int sceneLights = static_cast<int>(scene.lights.size());
    if (c.indexBits == PackingConfig::kAuto) {
        if (sceneLights > 65535)
            throw Error("scene has " + std::to_string(sceneLights) + " lights; lidr indexes at most 65,535");
        c.indexBits = AutoConfiguration::indexBitsFor(sceneLights);
    }
    if (c.budget == PackingConfig::kAuto) c.budget = AutoConfiguration::kInitialBudget;
    const auto scheme = createPackingScheme(c, info);  // names what the context or the config lacks
    if (!o.packing.autoIndexBits() && scene.lights.size() > scheme->maxLights())
        throw Error("scene has " + std::to_string(scene.lights.size()) + " lights but " +
                    std::to_string(c.indexBits) + "-bit indices hold at most " +
                    std::to_string(scheme->maxLights()) + " (choose a wider index, or an automatic one)");
    return c;
}

// The largest budget an automatic configuration may use at an index width: 32 where the context can bind its
// targets (4- and 8-bit indices, bit-shift), 16 at 16 bits.
int largestBudget(const GlInfo& info, const PackingConfig& c, int widestBits) {
    for (int b : {32, 16, 8, 4, 2, 1}) {
        try {
            createPackingScheme({c.scheme, b, widestBits}, info);
            return b;
        } catch (const UnsupportedError&) {
        }
    }
    throw UnsupportedError("no budget of bit-shift packing fits this context at " + std::to_string(widestBits) + "-bit");
}

int lightTableCapacity(const Scene& scene, const LidrOptions& o, const PackingConfig& first, int width, int height) {
    if (!o.packing.autoIndexBits()) return static_cast<int>((1u << first.indexBits) - 1u);
    // Compact numbering: never more than the scene's lights (the 8-bit table's one row at least); with more
    // than 255, region-local indices may need a row per region (LidrOptions::regionalIndices).
    const int lights = static_cast<int>(scene.lights.size());
    if (lights > 255 && o.regionalIndices && o.tileCulledVolumes) {  // a row per region, then the tile map's rows
        const long tiles = long((width + o.volumeTileSize - 1) / o.volumeTileSize) * ((height + o.volumeTileSize - 1) / o.volumeTileSize);
        const long capacity = (LidrRenderer::kMaxIndexRegions + (tiles + 255) / 256) * 256 - 1;
        if (capacity <= 65535) return std::max<int>(lights, int(capacity));  // else too many tiles: global numbering
    }
    return std::max<int>(255, lights);
}

// The frame's resources as LIDR sets them up: its depth precision, a light table sized for the index width.
FrameSetup frameSetup(const Scene& scene, const LidrOptions& o, const PackingConfig& first, int width, int height) {
    FrameSetup setup = FrameSetup::of(o, scene, width, height);
    setup.depthBits = o.depthBits;
    setup.prepassDepth = DepthEmulation{o.emulatedDepthBits};
    setup.lightCapacity = lightTableCapacity(scene, o, first, width, height);
    return setup;
}

}  // namespace

LidrRenderer::LidrRenderer(const GlInfo& info, const Scene& scene, const LidrOptions& requested, int width, int height)
    : options_(withContextFallbacks(info, requested)),
      firstPacking_(checkedPacking(info, scene, options_)),
      frame_(info, scene, frameSetup(scene, options_, firstPacking_, width, height)),
      volumePass_(info, options_.volumeTest, options_.volumeDetail, DepthEmulation{options_.emulatedDepthBits}) {
    requestedAutoBudget_ = requested.packing.autoBudget();
    if (options_.volumeTest == VolumeTest::SphereSpan) {
        try {
            depthSpans_ = DepthSpanPass(info, frame_.targets, options_.msaaSpans);
        } catch (const UnsupportedError&) {
            if (requested.msaaSpans != DepthSpanStorage::Auto) throw;
            // The driver refused the multisample texture beside its depth-stencil: GL 2.1's moments.
            options_.msaaSpans = DepthSpanStorage::Moments;
            depthSpans_ = DepthSpanPass(info, frame_.targets, options_.msaaSpans);
        }
        // The samples' distances: programs that loop over the sample count the driver gave.
        if (depthSpans_.storesSamples()) {
            volumePass_ = LightVolumePass(info, options_.volumeTest, options_.volumeDetail,
                                          DepthEmulation{options_.emulatedDepthBits}, false, depthSpans_.samples());
            shadesRejectedFragments_ = shadesRejectedMultisampleFragments(info, depthSpans_.samples());
        }
    }
    const PackingConfig& first = firstPacking_;
    if (options_.packing.autoBudget()) {
        const int widest = options_.packing.autoIndexBits()
                               ? AutoConfiguration::indexBitsFor(std::max<int>(1, int(scene.lights.size())))
                               : first.indexBits;
        // Per width up to the widest (a frame's width, and so its largest budget, is chosen per frame).
        for (int bits : {4, 8, 16})
            largestAutoBudget_[widthSlot(bits)] = bits <= widest ? largestBudget(info, first, bits) : 0;
        auto_ = AutoConfiguration(largestAutoBudget_[widthSlot(widest)], options_.autoHoldFrames,
                                  options_.autoNarrowingInterval);
        autoTransparent_ = auto_;
        probe_ = OverlapProbe(info, DepthEmulation{options_.emulatedDepthBits});
    } else {
        auto_ = autoTransparent_ = AutoConfiguration(16, options_.autoHoldFrames, options_.autoNarrowingInterval);
    }
    drawTransparent_ = options_.transparency && frame_.scene.hasTransparent();
    bool needsDepthTexture = isShaderVolumeTest(options_.volumeTest);
    if (drawTransparent_ && !isFrontFaceVolumeTest(options_.volumeTest)) {
        // The exact front-face lists in batches go with the sphere test; the stencil tests keep front faces.
        const bool spans = options_.volumeTest == VolumeTest::SphereSpan;
        const VolumeTest front =
            options_.volumeTest == VolumeTest::Sphere || spans ? VolumeTest::SphereRay : VolumeTest::FrontFace;
        transparentVolumePass_ = LightVolumePass(info, front, options_.volumeDetail,
                                                 DepthEmulation{options_.emulatedDepthBits}, spans,
                                                 spans && depthSpans_.storesSamples() ? depthSpans_.samples() : 0);
        needsDepthTexture = needsDepthTexture || isShaderVolumeTest(front);
    }
    const int depthPrecision = options_.emulatedDepthBits != 0 ? options_.emulatedDepthBits : options_.depthBits;
    volumePass_.setDepthBits(depthPrecision);
    transparentVolumePass_.setDepthBits(depthPrecision);
    if (needsDepthTexture) {
        depthTexture_ = gl::Texture::create2D(GL_DEPTH_COMPONENT24, width, height, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT);
        if (info.gles) {
            // OpenGL ES 2.0 cannot copy depth (glCopyTexSubImage2D takes colour formats only; Mesa accepts the
            // call and leaves the texture wrong): the pre-pass is drawn a second time into the depth texture
            // (OES_depth_texture) as the only attachment of a framebuffer of its own.
            depthTextureFbo_ = gl::Framebuffer::create();
            depthTextureFbo_.attachTexture(GL_DEPTH_ATTACHMENT, depthTexture_);
            depthTextureFbo_.checkComplete("pre-pass depth texture (OpenGL ES)");
            StateCache::current().bindFramebuffer(0);
        }
    }
    if (options_.volumeTest == VolumeTest::SphereSpan) {
        volumePass_.setDepthSpans(&depthSpans_);
        transparentVolumePass_.setDepthSpans(&depthSpans_);
    }
    // sphere-span culls by tiles of each pixel's range of its samples' points (their distances, or on GL 2.1 the
    // centre's depth and the resolved spans).
    const bool spanTiles = options_.volumeTest == VolumeTest::SphereSpan && bool(depthSpans_);
    if (options_.tileCulledVolumes && (options_.volumeTest == VolumeTest::Sphere || spanTiles) && !info.gles) {
        // OpenGL ES 2.0 keeps the volume meshes: it cannot read depth back (glReadPixels takes colour only).
        volumeTiles_ = std::make_unique<VolumeTiles>(width, height, options_.volumeTileSize);
    }
    selectVariant(first.budget, first.indexBits);
    selectTransparentVariant(first.budget, first.indexBits);
}

}  // namespace lidr
