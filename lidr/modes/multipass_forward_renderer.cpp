#include "lidr/modes/multipass_forward_renderer.h"
#include "lidr/base/gl.h"
#include "lidr/gl/saved_gl_state.h"

#include <algorithm>

#include "lidr/base/error.h"
#include "lidr/render/shading_pass.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr {

namespace {
// Depth EQUAL, and only where the stencil does not hold `stamp` yet; a fragment that passes writes it.
RenderState onceAtPrepassDepth(GLint stamp) {
    RenderState s;
    s.depthTest = true;
    s.depthFunc = GL_EQUAL;
    s.stencilTest = true;
    s.stencil.func = GL_NOTEQUAL;
    s.stencil.ref = stamp;
    s.stencil.depthPass = GL_REPLACE;
    return s;
}
}  // namespace

MultipassForwardRenderer::MultipassForwardRenderer(const GlInfo& info, const Scene& scene,
                                                   const MultipassOptions& options, int width, int height)
    // The scene drawn in reverse: the stamps keep the first fragment (see render()).
    : frame_(info, scene, FrameSetup::of(options, scene, width, height, DrawOrder::Reversed)),
      options_(options) {
    const ShaderDefines defines = frame_.lightTable.defines();
    ambient_ = gl::Program::create("forward-ambient", buildShaderSource("geometry.vert"),
                                   buildShaderSource("forward_ambient.frag", defines), geometryAttributes());
    light_ = gl::Program::create("forward-light", buildShaderSource("geometry.vert"),
                                 buildShaderSource("forward_light.frag", defines), geometryAttributes());
    lightDefines_ = defines;
    if (!options.halfFloatAccumulation) {
        accumulationNote_ = "forced (MultipassOptions::halfFloatAccumulation false)";
    } else {
        try {
            halfFloat_ = HalfFloatTarget(info, frame_.targets);
        } catch (const UnsupportedError& e) {
            accumulationNote_ = e.what();
        }
        if (halfFloat_ && frame_.targets.samples() > 0)
            accumulationNote_ = halfFloat_.multisampleTexture()
                                    ? "MSAA samples encoded one by one, then averaged"
                                    : "MSAA samples averaged in linear light, then encoded (no multisample textures "
                                      "with sample shading, GL 3.2 + ARB_sample_shading)";
    }
}

namespace {
// Multi-pass forward's own passes, between FrameResources' (passes(), render()). The sum is the half-float target
// where there is one, else the 8-bit colour target; the stencil stamps let one fragment a pixel through each pass.
constexpr GLint kAmbientStamp = 1;  // the ambient pass's; the light passes count on from it
constexpr FramePass kAmbient{"ambient", "scene, depth, [environment]", "sum (linear light), stencil stamps"};
constexpr FramePass kLightPasses{"light-passes", "scene, depth, lights, light table, [shadow atlas]",
                                 "sum (linear light), stencil stamps"};
constexpr FramePass kEncodeSamples{"output-encode", "sum (MSAA, each sample)", "colour (MSAA)"};
constexpr FramePass kResolveSum{"msaa-resolve", "sum (MSAA)", "sum", "MSAA"};
constexpr FramePass kEncodeSum{"output-encode", "sum", "colour"};
constexpr FramePass kEncodeColour{"output-encode", "colour", "colour", "a tone map, exposure or sRGB encoding"};
}  // namespace

std::vector<FramePass> MultipassForwardRenderer::passes() const {
    std::vector<FramePass> p{pass::kShadowMaps, pass::kLightTable, pass::kDepthPrepass, kAmbient, kLightPasses};
    const bool msaa = frame_.targets.samples() > 0;
    if (halfFloat_ && halfFloat_.multisampleTexture()) {
        p.insert(p.end(), {kEncodeSamples, pass::kMsaaResolve});
    } else if (halfFloat_) {
        if (msaa) p.push_back(kResolveSum);
        p.push_back(kEncodeSum);
    } else {
        if (msaa) p.push_back(pass::kMsaaResolve);
        p.push_back(kEncodeColour);
    }
    return p;
}

const FrameStats& MultipassForwardRenderer::render(const Camera& camera, const std::vector<PointLight>& lights,
                                                   const ShadingParameters& shading) {
    const CameraMatrices cam = frame_.checkFrame(camera, lights, shading, "forward-multipass");
    const FrameScope scope(stats_, frame_.timer, lights.size());
    frame_.prepareLights(lights, shading, stats_);  // shadow-maps, light-table
    meshDraws_ = 0;
    // Every pass draws into the half-float target where there is one, else into the 8-bit colour target; both
    // share the one depth-stencil.
    const PassDescription sumPass = halfFloat_ ? halfFloat_.pass() : frame_.targets.colorPass();
    frame_.drawDepthPrepass(cam, &sumPass);
    // The passes write linear light, the background too; outputEncode_ transforms the finished sum.
    ShadingParameters linearShading = shading;
    linearShading.output = OutputTransform::linear();
    drawAmbient(cam, sumPass, linearShading);
    drawLightPasses(cam, lights, linearShading);
    encodeOutput(shading.output);  // output-encode and msaa-resolve, in the order the sum's target takes them
    frame_.finishFrame(stats_, "MultipassForwardRenderer::render");
    return stats_;
}

void MultipassForwardRenderer::drawAmbient(const CameraMatrices& cam, const PassDescription& sumPass,
                                           const ShadingParameters& linearShading) {
    TimedPass ambientTime(frame_.timer, kAmbient.name);
    beginOpaqueShading(sumPass, linearShading, true);
    // Depth EQUAL passes every fragment at the pre-pass depth, and where fragments tie (a back face meeting
    // the front face at a silhouette) additive passes would add each one's term. A stencil stamp per pass
    // (1 for the ambient pass, then 2, 3, ... per light; cleared when they run out) lets one fragment per
    // pixel through: the first drawn. The scene is drawn in reverse order, so that is the fragment the
    // single-pass modes keep, the last drawn in scene order (lidr/render/gpu_scene.h).
    StateCache::current().apply(onceAtPrepassDepth(kAmbientStamp));  // the pre-pass left stencil 0
    ambient_.use();
    setShadingUniforms(ambient_, cam, linearShading, frame_.environment);
    frame_.scene.draw(ambient_, DrawFilter::Opaque, true, &cam,
                      shadingVariantKey(ambient_, linearShading, frame_.environment));
}

void MultipassForwardRenderer::drawLightPasses(const CameraMatrices& cam, const std::vector<PointLight>& lights,
                                               const ShadingParameters& linearShading) {
    TimedPass lightPassesTime(frame_.timer, kLightPasses.name);
    StateCache& cache = StateCache::current();
    RenderState s = onceAtPrepassDepth(kAmbientStamp);
    s.blend = true;
    s.blendSrcRgb = s.blendDstRgb = GL_ONE;  // add this light's term
    s.blendSrcAlpha = GL_ZERO, s.blendDstAlpha = GL_ONE;
    s.scissor = options_.scissor;
    s.scissorBox = glm::ivec4(0, 0, frame_.targets.width(), frame_.targets.height());
    cache.apply(s);  // per light only the scissor box and the stamp change below (the cache sets only those)
    // Shadows: each light's term with its lookup compiled in (shadow_lookup.glsl), as the reference does.
    const gl::Program& lightProgram =
        frame_.shadows.shadingProgram(light_, "forward_light.frag", lightDefines_, linearShading.shadows);
    lightProgram.use();
    setShadingUniforms(lightProgram, cam, linearShading, frame_.environment);
    frame_.lightTable.bind(lightProgram);
    frame_.shadows.bind(lightProgram, linearShading.shadows);
    const float reach = frame_.lightTable.reachError();
    // Culling a mesh whose bounds the sphere misses is exact only where every shaded point lies on its
    // triangle. Under MSAA a fragment that covers samples but not the pixel centre is shaded at the centre,
    // extrapolated along the triangle's plane, possibly outside the mesh's bounds and inside a light's sphere
    // the bounds miss (seen: 4 steps darker at an edge of the room). There a mesh is skipped only when its
    // screen rectangle misses the light's: that point still lies on the pixel's centre ray. It costs: 3.3x
    // the frame on the room at 320x240 with 4x MSAA on llvmpipe (doc/tiled.md); exactMsaaCulling = false
    // keeps the mesh bounds test.
    const bool screenCull = frame_.targets.samples() > 0 && options_.exactMsaaCulling;
    const std::vector<glm::ivec4> meshRects = screenCull ? meshScreenRects(cam) : std::vector<glm::ivec4>{};
    GLint stamp = kAmbientStamp;
    for (size_t i = 0; i < lights.size(); ++i) {
        const PointLight& l = lights[i];
        const float radius = l.radius + reach;
        glm::vec3 coneMin, coneMax;  // a spot light's cone's box (the sphere's for a point light)
        spotLightBox(l, radius, coneMin, coneMax);
        glm::ivec4 rect;
        if (!spherePixelRect(cam, l.position, radius, rect)) continue;  // touches no pixel
        if (options_.scissor) s.scissorBox = glm::ivec4(rect.x, rect.y, rect.z - rect.x + 1, rect.w - rect.y + 1);
        if (++stamp > 255) {  // every stamp used since the last clear: start again from a clear stencil
            ClearAction clearStamps;
            clearStamps.stencil = true;
            cache.clear(clearStamps);
            stamp = 1;
        }
        s.stencil.ref = stamp;
        cache.apply(s);
        lightProgram.set("uLightIndex", float(i + 1));
        const int drawn = frame_.scene.drawSelected(lightProgram, DrawFilter::Opaque, [&](size_t i, const glm::vec3& bmin, const glm::vec3& bmax) {
            if (!options_.cullMeshes) return true;
            if (!screenCull)
                return sphereTouchesBox(l.position, radius, bmin, bmax) &&
                       glm::all(glm::lessThanEqual(coneMin, bmax)) && glm::all(glm::lessThanEqual(bmin, coneMax));
            const glm::ivec4& box = meshRects[i];  // empty (z < x) when off screen
            return box.x <= box.z && box.x <= rect.z && rect.x <= box.z && box.y <= rect.w && rect.y <= box.w;
        }, true, &cam);
        if (drawn == 0) continue;
        meshDraws_ += drawn;
        ++stats_.drawnLights;
    }
    stats_.volumeDrawCalls = meshDraws_;
    cache.apply(RenderState{});
}

std::vector<glm::ivec4> MultipassForwardRenderer::meshScreenRects(const CameraMatrices& cam) const {
    // Per batch, this frame: (0, 0, -1, -1) when off screen.
    std::vector<glm::ivec4> rects(frame_.scene.batchCount(), glm::ivec4(0, 0, -1, -1));
    for (size_t i = 0; i < rects.size(); ++i) {
        glm::vec3 bmin, bmax;
        frame_.scene.batchBounds(i, bmin, bmax);
        if (!boxPixelRect(cam, bmin, bmax, rects[i])) rects[i] = glm::ivec4(0, 0, -1, -1);
    }
    return rects;
}

void MultipassForwardRenderer::encodeOutput(const OutputTransform& output) {
    if (halfFloat_ && halfFloat_.multisampleTexture()) {
        // Each sample encoded, then the encoded samples averaged, as the single-pass modes resolve.
        TimedPass encodeTime(frame_.timer, kEncodeSamples.name);
        outputEncode_.run(frame_.targets, output, halfFloat_.multisampleTexture());
        encodeTime.end();
        frame_.targets.resolve(frame_.timer);
    } else if (halfFloat_) {
        if (frame_.targets.samples() > 0) {  // averaged in linear light, then encoded (doc/colour.md)
            TimedPass msaaResolveTime(frame_.timer, kResolveSum.name);
            halfFloat_.resolve();
        }
        TimedPass encodeTime(frame_.timer, kEncodeSum.name);  // always: it also writes the 8-bit colour target
        outputEncode_.run(frame_.targets, output, halfFloat_.texture());
    } else {
        frame_.targets.resolve(frame_.timer);
        if (output.srgb || output.toneMap != ToneMap::None || output.exposureStops != 0.0f) {
            TimedPass encodeTime(frame_.timer, kEncodeColour.name);
            outputEncode_.run(frame_.targets, output);
        }
    }
}

ModeStatistics MultipassForwardRenderer::modeStatistics() const {
    // Where its passes summed their light (doc/colour.md): half float, or the 8-bit target and why.
    return {"multipass",
            {modeStatistic("accumulation", std::string(accumulation())),
             modeStatistic("accumulation_note", accumulationNote_)},
            std::string("multi-pass accumulation: ") + accumulation() +
                (accumulationNote_.empty() ? "" : " (" + accumulationNote_ + ")")};
}

}  // namespace lidr
