#include "lidr/technique/light_volume_pass.h"
#include "lidr/base/gl.h"

#include <algorithm>

#include "lidr/base/error.h"

namespace lidr {

IndexTargets::IndexTargets(int count, int width, int height, const gl::Renderbuffer& depthStencil, int samples,
                           const gl::Renderbuffer* separateStencil)
    : width_(width), height_(height), samples_(samples) {
    if (count < 1 || count > kMaxIndexTargets)
        throw Error("index target count must be 1.." + std::to_string(kMaxIndexTargets));
    fbo_ = gl::Framebuffer::create();
    for (int i = 0; i < count; ++i) {
        textures_.push_back(samples > 0 ? gl::Texture::create2DMultisample(GL_RGBA8, width, height, samples)
                                        : gl::Texture::create2D(GL_RGBA8, width, height, GL_RGBA, GL_UNSIGNED_BYTE));
        fbo_.attachTexture(GL_COLOR_ATTACHMENT0 + i, textures_.back());
    }
    fbo_.attachDepthStencil(depthStencil, separateStencil);
    fbo_.checkComplete("light-index targets");
    if (currentContextIsGles()) {
        for (int first = 1; first < count; ++first) {
            gl::Framebuffer f = gl::Framebuffer::create();
            for (int i = first; i < count; ++i) f.attachTexture(GL_COLOR_ATTACHMENT0 + (i - first), textures_[size_t(i)]);
            f.attachDepthStencil(depthStencil, separateStencil);
            f.checkComplete("light-index targets from a later one (OpenGL ES)");
            fromFbos_.push_back(std::move(f));
        }
    }
    StateCache::current().bindFramebuffer(0);
}

const gl::Framebuffer& IndexTargets::framebufferFrom(int first) const {
    if (first == 0 || fromFbos_.empty()) return fbo_;
    return fromFbos_.at(size_t(first - 1));
}

size_t IndexTargets::bytes() const { return size_t(count()) * width_ * height_ * 4 * std::max(samples_, 1); }

LightVolumePass::LightVolumePass(const GlInfo& info, VolumeTest test, bool volumeDetail, DepthEmulation depth,
                                 bool depthSpans, int spanSamples)
    : test_(test), depthClamp_(info.depthClamp), gles_(info.gles),
      maxDrawTargets_(maxDrawTargets(info)),
      volumes_(info, test, volumeDetail, depth, depthSpans, spanSamples) {}

void LightVolumePass::begin(const IndexTargets& targets, const CameraMatrices& camera, const gl::Texture* depth) {
    activeGeometry().begin(camera, glm::ivec2(targets.width(), targets.height()), depth);
    targets_ = &targets;
    camera_ = camera;
    drawCalls_ = 0;
    PassDescription pass{targets.framebuffer().id(), glm::ivec4(0, 0, targets.width(), targets.height()), {}, {}};
    // OpenGL ES without EXT_draw_buffers draws to COLOR_ATTACHMENT0 only: its draw buffers are left as they are.
    if (!gles_ || maxDrawTargets_ > 1)
        for (int i = 0; i < targets.count(); ++i) pass.drawBuffers.push_back(GL_COLOR_ATTACHMENT0 + i);
    pass.clear.color = pass.clear.stencil = true;  // index 0 (the null light) everywhere, no light counted
    StateCache::current().beginPass(pass);
    checkGl("light-volume pass begin");
}

bool LightVolumePass::marksWholeFootprint(const VolumeLight& l) const {
    return volumeMarksWholeFootprint(test_, depthClamp_, geometry().factsFor(l, camera_).reachesFarPlane);
}

VolumeDrawPlan LightVolumePass::planFor(const VolumeDraw& d, const std::vector<VolumeLight>& lights) const {
    const VolumeGeometry& geometry = this->geometry();
    std::vector<VolumeLightFacts> facts;
    facts.reserve(lights.size());
    for (const VolumeLight& l : lights) facts.push_back(geometry.factsFor(l, camera_));
    VolumePlanContext context;
    context.test = test_;
    context.depthClamp = depthClamp_;
    context.gles = gles_;
    context.drawBuffers = maxDrawTargets_ > 1;
    context.batchSize = geometry_ ? geometry.batchFor(d.targetCount)
                                  : volumes_.batchFor(d.targetCount, volumes_.shadowedDraw(lights));
    context.screenTiles = geometry.drawsScreenTiles();
    context.scissor = scissor_;
    return planVolumeDraw(d, context, facts);
}

void LightVolumePass::draw(const VolumeDraw& d, const std::vector<VolumeLight>& lights, const IndexColorsFor& colors) {
    if (!targets_) throw Error("LightVolumePass::draw outside begin/end");
    if (d.firstTarget < 0 || d.firstTarget + d.targetCount > targets_->count())
        throw Error("volume draw '" + d.name + "' addresses index targets outside the frame's set");
    const VolumeDrawPlan plan = planFor(d, lights);
    volumes_.setShadowDraw(!geometry_ && volumes_.shadowedDraw(lights));
    VolumeGeometry& geometry = activeGeometry();
    // A point light's cone is (0, 0, 0, 1): draws of point lights alone use the shader tests' program without
    // the cone test.
    volumes_.setSpotCones(std::any_of(lights.begin(), lights.end(),
                                      [](const VolumeLight& l) { return l.cone != glm::vec4(0.0f, 0.0f, 0.0f, 1.0f); }));
    StateCache& cache = StateCache::current();  // sets per step only what differs from the last
    if (plan.restartCount) {
        ClearAction clear;
        clear.stencil = true;
        cache.clear(clear);
    }
    if (plan.framebufferFrom >= 0) targets_->framebufferFrom(plan.framebufferFrom).bind();
    if (!plan.drawBuffers.empty()) cache.setDrawBuffers(plan.drawBuffers);
    geometry.beginSteps(d, plan, colors);
    for (const VolumeStep& step : plan.steps) {
        cache.apply(plan.stateOf(step));
        geometry.drawStep(step, lights, colors);
        ++drawCalls_;
    }
    countBits_ = plan.countBits;
    checkGl(("light-volume draw '" + d.name + "'").c_str());
}

void LightVolumePass::end() {
    activeGeometry().end();
    StateCache::current().apply(RenderState{});
    targets_ = nullptr;
    checkGl("light-volume pass end");
}

}  // namespace lidr
